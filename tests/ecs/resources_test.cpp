#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "engine/ecs/registry.h"

namespace qlight::ecs {
namespace {

struct MeshTable {
  std::vector<std::string> names;
};
struct FrameSettings {
  int samplesPerPixel;
};

TEST(Resources, SetGetReplaceErase) {
  Registry registry;
  EXPECT_FALSE(registry.hasResource<MeshTable>());
  EXPECT_EQ(registry.tryResource<MeshTable>(), nullptr);
  registry.setResource<MeshTable>(std::vector<std::string>{"cube"});
  registry.setResource<FrameSettings>(4);
  registry.resource<MeshTable>().names.push_back("sphere");
  EXPECT_EQ(registry.resource<MeshTable>().names.size(), 2u);
  EXPECT_EQ(registry.resource<FrameSettings>().samplesPerPixel, 4);
  registry.setResource<FrameSettings>(8);  // replaces
  EXPECT_EQ(registry.ctx().get<FrameSettings>().samplesPerPixel, 8);
  EXPECT_TRUE(registry.ctx().erase<FrameSettings>());
  EXPECT_FALSE(registry.hasResource<FrameSettings>());
  EXPECT_TRUE(registry.hasResource<MeshTable>());
}

TEST(Resources, MissingResourceErrorNamesTheType) {
  Registry registry;
  try {
    registry.resource<FrameSettings>();
    FAIL() << "a missing resource must throw";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("FrameSettings"), std::string::npos) << error.what();
  }
}

TEST(TypeId, ConstnessIsTheSameTypeAndNamesAreReadable) {
  EXPECT_EQ(typeId<const MeshTable>(), typeId<MeshTable>());
  EXPECT_NE(typeId<MeshTable>(), typeId<FrameSettings>());
  EXPECT_NE(typeName<MeshTable>().find("MeshTable"), std::string_view::npos);
}

}  // namespace
}  // namespace qlight::ecs

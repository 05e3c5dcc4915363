// The extension rays traced in the shade pass, which also starts the camera paths (fused),
// or in a trace pass of their own after a begin pass (separate) are the same rays with the
// same hits: with one seed the two renders are equal
// bit for bit, the counters too, guided and learning across frames or not, and on a
// textured, skinned (a moving instance beside the merged tree) and sky-lit scene.
#include <cstring>

#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

struct KernelCase {
  const char* name;
  std::string scene;
  bool guided;
};

void PrintTo(const KernelCase& c, std::ostream* os) { *os << c.name; }

class TraceKernel : public GpuTest, public ::testing::WithParamInterface<KernelCase> {};

TEST_P(TraceKernel, FusedAndSeparateRenderTheSameImage) {
  const KernelCase c = GetParam();
  scene::SceneAsset asset = gltf::loadGltf(c.scene);
  auto render = [&](render::TraceKernel kernel) {
    render::RenderSettings s = smallSettings(48, 32, 7);
    s.samplesPerFrame = 2;  // several frames: the guide learns between them
    s.traceKernel = kernel;
    guiding::GuidingSettings g;
    g.enabled = c.guided;
    g.pointBudget = 2048;
    g.dartPaths = 4096;
    g.seed = 7;
    return session::renderScene(ctx(), asset, s, 8, 0.0f, g);
  };
  session::OfflineRender fused = render(render::TraceKernel::Fused);
  session::OfflineRender separate = render(render::TraceKernel::Separate);
  EXPECT_TRUE(fused.stats.traceInShade);
  EXPECT_FALSE(separate.stats.traceInShade);
  EXPECT_EQ(fused.stats.gpuMs.count("path.trace"), 0u) << "fused: no trace pass";
  EXPECT_EQ(fused.stats.gpuMs.count("path.begin"), 0u) << "fused: the shade starts the paths";
  EXPECT_GT(separate.stats.gpuMs.count("path.trace"), 0u);
  ASSERT_EQ(fused.image.rgba.size(), separate.image.rgba.size());
  EXPECT_EQ(std::memcmp(fused.image.rgba.data(), separate.image.rgba.data(),
                        fused.image.rgba.size() * sizeof(float)),
            0);
  EXPECT_EQ(fused.stats.counters.rays, separate.stats.counters.rays);
  EXPECT_EQ(fused.stats.counters.shadowRays, separate.stats.counters.shadowRays);
  EXPECT_EQ(fused.stats.counters.pathVertices, separate.stats.counters.pathVertices);
  EXPECT_GT(fused.stats.counters.rays, fused.stats.counters.paths) << "the paths bounced";
  // Not a black image: the comparison above would hold for two empty ones.
  double sum = 0;
  for (float v : fused.image.rgba) sum += v;
  EXPECT_GT(sum, 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, TraceKernel,
    ::testing::Values(KernelCase{"DoorGuided", assetPath("door_ajar.gltf"), true},
                      KernelCase{"DoorUnguided", assetPath("door_ajar.gltf"), false},
                      KernelCase{"TexturedSkinnedGuided",
                                 std::string(QLIGHT_SAMPLES_DIR) +
                                     "/features/CesiumMan/glTF/CesiumMan.gltf",
                                 true}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace qlight::test

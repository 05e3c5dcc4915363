// bvh_traverse.h must stay valid GLSL: compile a compute shader that binds the
// three texel buffers the way the renderer will and calls both queries.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace {

constexpr const char* kShader = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform samplerBuffer uBvhNodes;
layout(set = 0, binding = 1) uniform samplerBuffer uBvhTriangles;
layout(set = 0, binding = 2) uniform samplerBuffer uBvhInstances;
#define QL_BVH_NODE(i) texelFetch(uBvhNodes, int(i))
#define QL_BVH_TRI(i) texelFetch(uBvhTriangles, int(i))
#define QL_BVH_INST(i) texelFetch(uBvhInstances, int(i))
#include "shared/bvh_traverse.h"
layout(set = 0, binding = 3, scalar) readonly buffer Rays { vec4 rays[]; };
layout(set = 0, binding = 4, scalar) writeonly buffer Hits { BvhHit hits[]; };
layout(set = 0, binding = 5, scalar) writeonly buffer Shadow { uint shadow[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 o = rays[2 * i];
  vec4 d = rays[2 * i + 1];
  BvhHit h;
  traceClosest(o.xyz, d.xyz, o.w, h);
  hits[i] = h;
  shadow[i] = traceAny(o.xyz, d.xyz, d.w) ? 1u : 0u;
}
)";

TEST(BvhGlsl, TraversalCompilesAsGlsl) {
  if (std::system("command -v glslangValidator > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "glslangValidator not on PATH";
  }
  auto dir =
      std::filesystem::temp_directory_path() /
      ("qlight_bvh_glsl_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
       "_" + std::to_string(std::hash<std::string>{}(std::filesystem::current_path())));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "trace.comp") << kShader;
  std::string cmd = "glslangValidator -V --target-env vulkan1.2 -I" QLIGHT_SOURCE_DIR
                    "/shaders -o " +
                    (dir / "trace.spv").string() + " " + (dir / "trace.comp").string() + " > " +
                    (dir / "log.txt").string() + " 2>&1";
  int rc = std::system(cmd.c_str());
  std::ifstream logFile(dir / "log.txt");
  std::string log((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(dir);
  EXPECT_EQ(rc, 0) << log;
}

}  // namespace

#include "engine/gpu/pipeline_library.h"

#include <stdexcept>

#include "engine/gpu/compute_pipeline.h"
#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {
namespace {

using PipelineLibraryTest = GpuTest;

TEST_F(PipelineLibraryTest, TheSameShaderAndSpecializationIsBuiltOnce) {
  gpu::ComputePipeline first(ctx(), "trace_rays", {0, 0, 0, 1});
  const size_t built = ctx().pipelines().size();
  gpu::ComputePipeline second(ctx(), "trace_rays", {0, 0, 0, 1});
  EXPECT_EQ(second.handle(), first.handle());
  EXPECT_EQ(second.layout(), first.layout());
  EXPECT_EQ(ctx().pipelines().size(), built);
}

TEST_F(PipelineLibraryTest, OtherSpecializationsAreOtherPipelines) {
  gpu::ComputePipeline anyHit(ctx(), "trace_rays", {0, 0, 0, 1});
  gpu::ComputePipeline closest(ctx(), "trace_rays", {0, 0, 0, 0});
  gpu::ComputePipeline plain(ctx(), "trace_rays");
  EXPECT_NE(anyHit.handle(), closest.handle());
  EXPECT_NE(closest.handle(), plain.handle());  // no specialization is its own key
  EXPECT_EQ(plain.localSize(0), 64u);
}

TEST_F(PipelineLibraryTest, APipelineOutlivesTheOwnerThatBuiltIt) {
  VkPipeline handle = VK_NULL_HANDLE;
  {
    gpu::ComputePipeline owner(ctx(), "prefix_sum_add");
    handle = owner.handle();
  }
  const size_t built = ctx().pipelines().size();
  gpu::ComputePipeline later(ctx(), "prefix_sum_add");
  EXPECT_EQ(later.handle(), handle);
  EXPECT_EQ(later.name(), "prefix_sum_add");
  EXPECT_EQ(ctx().pipelines().size(), built);
}

TEST_F(PipelineLibraryTest, AnUnknownShaderThrowsAndLeavesNoEntry) {
  const size_t built = ctx().pipelines().size();
  EXPECT_THROW(gpu::ComputePipeline(ctx(), "no_such_shader"), std::runtime_error);
  EXPECT_EQ(ctx().pipelines().size(), built);
  EXPECT_THROW(gpu::ComputePipeline(ctx(), "no_such_shader"), std::runtime_error);
}

TEST_F(PipelineLibraryTest, ADefaultPipelineHasNoHandles) {
  gpu::ComputePipeline none;
  EXPECT_EQ(none.handle(), VkPipeline(VK_NULL_HANDLE));
  EXPECT_EQ(none.layout(), VkPipelineLayout(VK_NULL_HANDLE));
  EXPECT_TRUE(none.name().empty());
}

}  // namespace
}  // namespace qlight::test

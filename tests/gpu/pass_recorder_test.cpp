#include "engine/gpu/pass_recorder.h"

#include <algorithm>
#include <chrono>

#include "engine/gpu/image.h"
#include "shaders/shared/prefix_sum.h"
#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {
namespace {

using shared::PrefixSumPush;

class PassRecorderTest : public GpuTest {};

// The tile pass writes the tile sums; the add pass reads them. Nothing in the
// calling code places a barrier: it must come from the declarations.
TEST_F(PassRecorderTest, ReadAfterWriteGetsABarrierFromTheDeclarations) {
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  gpu::ComputePipeline add(ctx(), "prefix_sum_add");
  const uint32_t n = 2048;
  std::vector<float> ones(n, 1.0f);
  gpu::Buffer values(ctx(), n * 4, "values");
  gpu::Buffer sums(ctx(), 2 * 4, "sums");
  gpu::Buffer untouched(ctx(), 16, "untouched");
  values.upload<float>(ctx(), ones);
  std::vector<gpu::BarrierRecord> barriers;
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    PrefixSumPush push{n, 0, 1024, 0};
    rec.pass("tiles", tiles).write(0, values).write(1, sums).push(push).dispatch(2);
    rec.pass("add", add).write(0, values).read(1, sums).push(push).dispatchThreads(n);
    rec.finish();
    barriers = rec.barriers();
  });
  ASSERT_EQ(barriers.size(), 1u);
  EXPECT_EQ(barriers[0].pass, "add");
  auto& res = barriers[0].resources;
  auto it = std::find(res.begin(), res.end(), "sums");
  ASSERT_NE(it, res.end());
  EXPECT_EQ(barriers[0].hazards[it - res.begin()], "RAW");
  auto out = values.read<float>(ctx());
  for (uint32_t i = 0; i < n; ++i) ASSERT_FLOAT_EQ(out[i], float(i + 1)) << i;
}

TEST_F(PassRecorderTest, IndependentPassesGetNoBarrier) {
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  gpu::Buffer a(ctx(), 1024 * 4, "a"), b(ctx(), 1024 * 4, "b");
  gpu::Buffer sa(ctx(), 4, "sa"), sb(ctx(), 4, "sb");
  std::vector<gpu::BarrierRecord> barriers;
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    PrefixSumPush push{1024, 0, 1024, 0};
    rec.pass("scan a", tiles).write(0, a).write(1, sa).push(push).dispatch(1);
    rec.pass("scan b", tiles).write(0, b).write(1, sb).push(push).dispatch(1);
    rec.finish();
    barriers = rec.barriers();
  });
  EXPECT_TRUE(barriers.empty());
}

TEST_F(PassRecorderTest, WriteAfterReadIsOrdered) {
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  gpu::ComputePipeline add(ctx(), "prefix_sum_add");
  gpu::Buffer values(ctx(), 2048 * 4, "values"), sums(ctx(), 8, "sums");
  gpu::Buffer other(ctx(), 2048 * 4, "other");
  std::vector<gpu::BarrierRecord> barriers;
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    PrefixSumPush push{2048, 0, 1024, 0};
    rec.pass("produce", tiles).write(0, values).write(1, sums).push(push).dispatch(2);
    rec.pass("consume", add).write(0, values).read(1, sums).push(push).dispatchThreads(2048);
    rec.pass("overwrite", tiles).write(0, other).write(1, sums).push(push).dispatch(2);
    rec.finish();
    barriers = rec.barriers();
  });
  ASSERT_EQ(barriers.size(), 2u);
  EXPECT_EQ(barriers[1].pass, "overwrite");
  EXPECT_EQ(barriers[1].resources.front(), "sums");
  EXPECT_EQ(barriers[1].hazards.front(), "WAR");
}

// Without the derived barrier the synchronization validation layer reports the
// hazard: proof that the barrier above is what makes the frame correct.
TEST_F(PassRecorderTest, WithoutTheBarrierValidationReportsAHazard) {
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  gpu::ComputePipeline add(ctx(), "prefix_sum_add");
  gpu::Buffer values(ctx(), 2048 * 4, "values"), sums(ctx(), 8, "sums");
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    rec.setAutomaticBarriers(false);
    PrefixSumPush push{2048, 0, 1024, 0};
    rec.pass("tiles", tiles).write(0, values).write(1, sums).push(push).dispatch(2);
    rec.pass("add", add).write(0, values).read(1, sums).push(push).dispatchThreads(2048);
  });
  auto messages = ctx().validationMessages();
  ctx().clearValidationMessages();
  bool hazard = std::any_of(messages.begin(), messages.end(), [](const std::string& m) {
    return m.find("HAZARD") != std::string::npos;
  });
  EXPECT_TRUE(hazard) << "expected a synchronization hazard report, got " << messages.size()
                      << " messages";
}

TEST_F(PassRecorderTest, MisdeclaredBindingsAreRejected) {
  gpu::ComputePipeline add(ctx(), "prefix_sum_add");
  gpu::Buffer values(ctx(), 64, "values"), sums(ctx(), 64, "sums");
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    PrefixSumPush push{16, 0, 1024, 0};
    // binding 1 is missing
    EXPECT_THROW(rec.pass("p", add).write(0, values).push(push).dispatch(1), std::logic_error);
    // binding 1 is readonly in the shader
    EXPECT_THROW(rec.pass("p", add).write(0, values).write(1, sums).push(push).dispatch(1),
                 std::logic_error);
    // binding 7 does not exist
    EXPECT_THROW(
        rec.pass("p", add).write(0, values).read(1, sums).read(7, sums).push(push).dispatch(1),
        std::logic_error);
    // push constants missing
    EXPECT_THROW(rec.pass("p", add).write(0, values).read(1, sums).dispatch(1), std::logic_error);
  });
}

TEST_F(PassRecorderTest, ReflectionReadsBindingsFromSpirv) {
  gpu::ComputePipeline add(ctx(), "prefix_sum_add");
  auto& b = add.reflection().bindings;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_FALSE(b[0].readOnly);
  EXPECT_TRUE(b[1].readOnly);
  EXPECT_EQ(add.localSize(0), uint32_t(QL_SCAN_GROUP_SIZE));
  EXPECT_TRUE(add.reflection().hasPushConstants);
}

// A queue without timestamps (timestampPeriod 0) leaves timing off, a documented fallback:
// the timer tests skip there. lavapipe, the device CI runs on, has them, so there they must run.
bool timingAvailable(const gpu::Context& ctx, const gpu::GpuTimer& timer) {
  if (!timer.enabled()) {
    EXPECT_EQ(ctx.deviceName().find("llvmpipe"), std::string::npos)
        << "lavapipe's queue has timestamps: the timer must be on";
  }
  return timer.enabled();
}

TEST_F(PassRecorderTest, TimestampsNamePasses) {
  gpu::GpuTimer timer(ctx());
  if (!timingAvailable(ctx(), timer)) GTEST_SKIP() << "queue has no timestamps";
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  gpu::Buffer values(ctx(), 1024 * 1024 * 4, "values"), sums(ctx(), 4096, "sums");
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    gpu::PassRecorder rec(ctx(), cmd, &timer);
    PrefixSumPush push{1024 * 1024, 0, 1024, 0};
    rec.pass("big scan", tiles).write(0, values).write(1, sums).push(push).dispatch(1024);
    rec.finish();
  });
  auto ms = timer.collect(ctx());
  ASSERT_EQ(ms.count("big scan"), 1u);
  EXPECT_GT(ms["big scan"], 0.0);
  EXPECT_LT(ms["big scan"], 10000.0);
}

// A render pass that clears a small image, run once on the queue (as the window's ImGui pass).
void runARenderPass(const gpu::Context& ctx) {
  VkDevice device = ctx.device();
  gpu::Image target(ctx, 16, 16, VK_FORMAT_R32G32B32A32_SFLOAT, "target",
                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  VkAttachmentDescription colour{};
  colour.format = target.format();
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_GENERAL;
  colour.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_GENERAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkRenderPassCreateInfo rpInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rpInfo.attachmentCount = 1;
  rpInfo.pAttachments = &colour;
  rpInfo.subpassCount = 1;
  rpInfo.pSubpasses = &subpass;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateRenderPass(device, &rpInfo, nullptr, &renderPass), VK_SUCCESS);
  gpu::Unique<VkRenderPass> renderPassOwner(
      renderPass, [device](VkRenderPass r) { vkDestroyRenderPass(device, r, nullptr); });
  VkImageView view = target.view();
  VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fbInfo.renderPass = renderPass;
  fbInfo.attachmentCount = 1;
  fbInfo.pAttachments = &view;
  fbInfo.width = target.width();
  fbInfo.height = target.height();
  fbInfo.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffer), VK_SUCCESS);
  gpu::Unique<VkFramebuffer> framebufferOwner(
      framebuffer, [device](VkFramebuffer f) { vkDestroyFramebuffer(device, f, nullptr); });
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    VkClearValue clear{};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass;
    begin.framebuffer = framebuffer;
    begin.renderArea.extent = {target.width(), target.height()};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdEndRenderPass(cmd);
  });
}

// Once a render pass has run on its queue, lavapipe takes a timestamp's time when the next
// timestamp command flushes: without GpuTimer's follower stamps every pass here read about
// 0 ms (the window's pass times did). The passes must hold most of the submission's time.
TEST_F(PassRecorderTest, TimestampsMeasureThePassesAfterARenderPass) {
  gpu::GpuTimer timer(ctx());
  if (!timingAvailable(ctx(), timer)) GTEST_SKIP() << "queue has no timestamps";
  runARenderPass(ctx());
  gpu::ComputePipeline tiles(ctx(), "prefix_sum_tiles");
  constexpr uint32_t kValues = 4 * 1024 * 1024;
  gpu::Buffer values(ctx(), kValues * 4ull, "values"), sums(ctx(), kValues / 256, "sums");
  auto start = std::chrono::steady_clock::now();
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    gpu::PassRecorder rec(ctx(), cmd, &timer);
    PrefixSumPush push{kValues, 0, 1024, 0};
    for (int i = 0; i < 4; ++i)
      rec.pass("big scan", tiles)
          .write(0, values)
          .write(1, sums)
          .push(push)
          .dispatch(kValues / 1024);
    rec.finish();
  });
  double wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto ms = timer.collect(ctx());
  ASSERT_EQ(ms.count("big scan"), 1u);
  EXPECT_GT(ms["big scan"], 0.5 * wallMs) << "submission took " << wallMs << " ms";
  EXPECT_LE(ms["big scan"], 1.01 * wallMs + 0.1);
}

}  // namespace
}  // namespace qlight::test

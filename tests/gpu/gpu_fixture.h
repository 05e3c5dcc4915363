// A Vulkan context for GPU tests, with validation on (QLIGHT_VALIDATION=1 from
// CTest, forced here too): any validation message fails the test.
#pragma once
#include <gtest/gtest.h>

#include <memory>

#include "engine/gpu/context.h"

namespace qlight::test {

class GpuTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    gpu::ContextOptions options = gpu::defaultContextOptions();
    options.validation = true;
    options.quiet = true;
    context_ = std::make_unique<gpu::Context>(options);
  }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { context_->clearValidationMessages(); }
  void TearDown() override {
    for (const std::string& m : context_->validationMessages()) ADD_FAILURE() << m;
  }
  gpu::Context& ctx() { return *context_; }

  static inline std::unique_ptr<gpu::Context> context_;
};

}  // namespace qlight::test

// The progress bar on a pipe (as under CTest): a line per 10%, and nothing from a short run.
#include "game/progress_bar.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace qlight::test {
namespace {

TEST(ProgressBar, OnAPipeItPrintsALinePerTenPercent) {
  testing::internal::CaptureStderr();  // before the bar: it looks at stderr when made
  {
    game::ProgressBar bar(200.0, "qlight test", 0.0);
    for (int i = 1; i <= 200; ++i) bar.update(i, "step " + std::to_string(i));
  }
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 11) << out;  // 0%, 10%, ... 100%
  EXPECT_NE(out.find("qlight test:  50% step 100\n"), std::string::npos) << out;
  EXPECT_NE(out.find("qlight test: 100% step 200\n"), std::string::npos) << out;
}

TEST(ProgressBar, ARunShorterThanTheQuietTimePrintsNothing) {
  testing::internal::CaptureStderr();
  {
    game::ProgressBar bar(10.0, "qlight test");
    for (int i = 1; i <= 10; ++i) bar.update(i, "step");
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace qlight::test

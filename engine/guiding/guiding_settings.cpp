#include "engine/guiding/guiding_settings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shaders/shared/direction_tree.h"
#include "shaders/shared/dqn.h"
#include "shaders/shared/strata.h"

namespace qlight::guiding {
namespace {

// The deep Q network's settings (GuideMethod::Dqn), each with its own message.
void validateDqn(const GuidingSettings& s) {
  if (s.dqnWidth < 4 || s.dqnWidth > shared::kDqnMaxWidth || s.dqnWidth % 4 != 0)
    throw std::invalid_argument("network width must be a multiple of 4 in 4.." +
                                std::to_string(shared::kDqnMaxWidth));
  if (s.dqnHidden < 1 || s.dqnHidden > shared::kDqnMaxHidden)
    throw std::invalid_argument("hidden layers must be 1.." +
                                std::to_string(shared::kDqnMaxHidden));
  if (s.dqnBins < 1 || s.dqnBins > shared::kDqnMaxBins)
    throw std::invalid_argument("one-blob bins must be 1.." + std::to_string(shared::kDqnMaxBins));
  if (s.dqnBatch < 1 || s.dqnBatch > 65536) throw std::invalid_argument("batch must be 1..65536");
  if (s.dqnStepsPerFrame > 64)
    throw std::invalid_argument("training steps per frame must be 0..64");
  if (!std::isfinite(s.dqnLearningRate) || s.dqnLearningRate <= 0 || s.dqnLearningRate > 1)
    throw std::invalid_argument("network learning rate must be in (0, 1]");
  if (s.dqnTargetInterval < 1 || s.dqnTargetInterval > 10000)
    throw std::invalid_argument("target network interval must be 1..10000 frames");
  if (s.dqnReplayFrames < 1 || s.dqnReplayFrames > 64)
    throw std::invalid_argument("replay frames must be 1..64");
  if (s.dqnWarmupSteps > 100000) throw std::invalid_argument("warm-up steps must be 0..100000");
  if (!std::isfinite(s.dqnFloorShare) || s.dqnFloorShare <= 0 || s.dqnFloorShare > 10)
    throw std::invalid_argument("network floor share must be in (0, 10]");
  if (s.dqnGrid == 1 || s.dqnGrid > shared::kDqnMaxGrid)
    throw std::invalid_argument("network grid must be 0 (no grid) or 2.." +
                                std::to_string(shared::kDqnMaxGrid) + " cells per axis");
}

}  // namespace

void validate(const GuidingSettings& s) {
  auto finite = [](float v) { return std::isfinite(v); };
  if (s.rows == 0 || s.cols == 0 || s.strata() > shared::kMaxStrata)
    throw std::invalid_argument("strata must be RxC with 1 <= R*C <= " +
                                std::to_string(shared::kMaxStrata));
  if (s.treeNodes < 5 || s.treeNodes > shared::kTreeMaxNodes)
    throw std::invalid_argument("tree nodes must be 5.." + std::to_string(shared::kTreeMaxNodes));
  if (!finite(s.treeSplitShare) || s.treeSplitShare <= 0 || s.treeSplitShare >= 1)
    throw std::invalid_argument("tree split share must be in (0, 1)");
  if (s.treeMaxDepth < 1 || s.treeMaxDepth > shared::kTreeMaxDepth)
    throw std::invalid_argument("tree depth must be 1.." + std::to_string(shared::kTreeMaxDepth));
  if (s.treeSplitVisits > (1u << 20))
    throw std::invalid_argument("tree split visits must be 0..1048576");
  if (!finite(s.alphaMin) || !finite(s.alphaMax) || s.alphaMin <= 0 || s.alphaMax > 1 ||
      s.alphaMin > s.alphaMax)
    throw std::invalid_argument(
        "learning rate bounds must satisfy 0 < alpha-min <= alpha-max <= 1");
  if (!finite(s.halfLifeFrames) || s.halfLifeFrames < 0 || s.halfLifeFrames > 1e6f)
    throw std::invalid_argument("half-life must be 0 (never forget) to 1e6 frames");
  if (!finite(s.forgetOnLightMove) || s.forgetOnLightMove < 0 || s.forgetOnLightMove > 1e3f)
    throw std::invalid_argument("forgetting on light moves must be 0 (off) to 1000 halvings");
  if (!finite(s.selectProbability) || s.selectProbability < 0 || s.selectProbability > 0.95f)
    throw std::invalid_argument(
        "guided selection probability must be in [0, 0.95] (BSDF sampling keeps the rest)");
  if (!finite(s.qFloor) || s.qFloor <= 0) throw std::invalid_argument("Q floor must be positive");
  if (s.pointBudget > (1u << 20))
    throw std::invalid_argument("point budget must be 1..1048576 (0: from the frame's paths)");
  if (!finite(s.rejectionMin) || !finite(s.rejectionMax) || s.rejectionMin < 0 ||
      s.rejectionMax < 0 || (s.rejectionMax > 0 && s.rejectionMax < s.rejectionMin))
    throw std::invalid_argument("rejection distances must be >= 0 with max >= min");
  if (!finite(s.lightMix) || s.lightMix < 0 || s.lightMix > 0.95f)
    throw std::invalid_argument(
        "light mix must be in [0, 0.95] (power-based choice keeps the rest)");
  if (!finite(s.confidenceUpdates) || s.confidenceUpdates < 0 || s.confidenceUpdates > 1e6f)
    throw std::invalid_argument("confidence updates must be in [0, 1e6]");
  if (!finite(s.neeMinProbability) || s.neeMinProbability < 0.01f || s.neeMinProbability > 1)
    throw std::invalid_argument(
        "NEE's minimum probability must be in [0.01, 1] (1: NEE at every vertex)");
  if (s.dartBounces == 0 || s.dartBounces > 64)
    throw std::invalid_argument("dart bounces must be 1..64");
  validateDqn(s);
  if (s.method == GuideMethod::Dqn && s.strata() > shared::kDqnMaxOutputs)
    throw std::invalid_argument("deep Q guiding takes at most " +
                                std::to_string(shared::kDqnMaxOutputs) + " strata");
}

uint32_t resolvedPointBudget(const GuidingSettings& s, uint64_t pathsPerFrame) {
  if (s.pointBudget > 0) return s.pointBudget;
  return uint32_t(
      std::clamp<uint64_t>(pathsPerFrame / kPathsPerPoint, kMinAutoPoints, kMaxAutoPoints));
}

void parseStrata(const std::string& text, GuidingSettings& s) {
  size_t x = text.find_first_of("xX");
  try {
    if (x == std::string::npos) throw std::invalid_argument("");
    size_t used = 0;
    int r = std::stoi(text.substr(0, x), &used);
    if (used != x) throw std::invalid_argument("");
    int c = std::stoi(text.substr(x + 1), &used);
    if (used != text.size() - x - 1) throw std::invalid_argument("");
    if (r <= 0 || c <= 0)
      throw std::domain_error("strata '" + text + "': rows and columns must be at least 1");
    s.rows = uint32_t(r);
    s.cols = uint32_t(c);
  } catch (const std::domain_error& e) {
    throw std::invalid_argument(e.what());
  } catch (const std::exception&) {
    throw std::invalid_argument("strata '" + text + "' is not of the form RxC, e.g. 8x8");
  }
}

}  // namespace qlight::guiding

// What the path tracing passes need from a guide (engine/guiding holds them all,
// the null guide too): its bindings, the guide block of shaders/shared/
// bindings.h, and which guiding features the frame uses. The shade pass is
// specialized on those features: lavapipe runs both sides of every branch, so
// code for an unused feature must not be in the pipeline.
#pragma once
#include "engine/gpu/pass_recorder.h"

namespace qlight::render {

struct GuideFeatures {
  bool points = false;          // cache points are searched (guided sampling, learning, spawns)
  bool lightLearning = false;   // learned light selection for NEE
  bool dqn = false;             // the deep Q network guides instead of the points' tables
  bool directionTrees = false;  // the points' directions are trees, not strata
  bool tdTarget = false;        // Q learns D&K's one-step target, not returns
  bool learns = false;          // the samples record learning targets (else frozen: that code
                                // is left out of the pipelines)
  // With dqn: the network's shape (shaders/shared/dqn.h DqnShape), a specialization too.
  uint32_t dqnBins = 0, dqnWidth = 0, dqnHidden = 0, dqnOutputs = 0;
  uint32_t dqnGrid = 0;  // cells per axis of its baked grid (0: evaluated at every vertex)
};

class Guide {
 public:
  virtual ~Guide() = default;
  // Binds every guide binding of a path tracing pass.
  virtual void bind(gpu::PassBuilder& pass) const = 0;
  virtual GuideFeatures features() const = 0;
};

}  // namespace qlight::render

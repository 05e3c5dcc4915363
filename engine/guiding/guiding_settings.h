// User settings of Q-learned importance sampling (CLI and UI).
#pragma once
#include <cstdint>
#include <string>

namespace qlight::guiding {

enum class PointSet : uint32_t {
  PhotonMap,  // fixed rejection distance (van Mastrigt's best)
  PoissonAo,  // rejection distance from ambient occlusion, between min and max
};

// What Q learns from (issue 9, docs/guiding_log.md).
enum class LearningTarget : uint32_t {
  Returns,  // the radiance each direction brought back, NEE included, once the path is done
  TdStep,   // D&K's one-step target: emission at the next vertex + what its Q says it scatters
};

// How a point's Q resolves directions (issue 9, docs/guiding_log.md).
enum class DirectionModel : uint32_t {
  Tree,    // a quadtree per point that refines where Q is (shaders/shared/direction_tree.h)
  Strata,  // D&K's fixed rows x cols strata of equal solid angle
};

// Where guided directions come from (--guiding q|dqn).
enum class GuideMethod : uint32_t {
  Q,    // Q tables in cache points (D&K, van Mastrigt)
  Dqn,  // a network of the continuous state, trained on the GPU (Comi's deep Q, issue 14)
};

struct GuidingSettings {
  bool enabled = true;  // --guiding q|dqn|off
  GuideMethod method = GuideMethod::Q;
  // The deep Q network and its training (GuideMethod::Dqn; shaders/shared/dqn.h). The
  // shape by measurement (quick bench, door ajar and corridor): 16 x 1 reached unguided's
  // error in 2.6x and 2.0x its time, 32 x 2 in 3.8x and 1.8x, 64 x 2 in 6.5x and 3.2x; the
  // equal-sample errors were alike, the network's cost per vertex is not.
  uint32_t dqnWidth = 16;    // neurons per hidden layer (4..128, a multiple of 4)
  uint32_t dqnHidden = 1;    // hidden layers (1..4)
  uint32_t dqnBins = 16;     // one-blob bins per position axis (1..32)
  uint32_t dqnBatch = 2048;  // records per training step
  uint32_t dqnStepsPerFrame = 1;
  float dqnLearningRate = 3e-3f;  // Adam's
  // Frames between copies of the trained network to the one the paths sample from (the
  // target network).
  uint32_t dqnTargetInterval = 4;
  uint32_t dqnReplayFrames = 8;  // frames of records the replay ring holds
  uint32_t dqnWarmupSteps = 16;  // training steps before the network guides at the full share
  float dqnFloorShare = 0.1f;    // each stratum's weight gets this share of the mean
  // Cells per axis of the grid the target network is baked into at each refresh (the paths
  // read a cell's row as they read a point's); 0: the paths evaluate it at every vertex. By
  // measurement (quick bench, 8 s, door / corridor / Cornell box, time to unguided's error):
  // per vertex 1.45 / 2.62 / 1.18, grid 8 1.18 / 1.61 / 1.13, 16 1.25 / 1.23 / 1.17, 32
  // 1.38 / 1.40 / 1.31 (its bake is 8x dearer; 8 is too coarse for the corridor's walls).
  uint32_t dqnGrid = 16;
  DirectionModel directions = DirectionModel::Strata;  // --directions (tree: being measured)
  uint32_t rows = 8;  // strata: rows x cols, equal solid angle (trees: the nominal resolution
  uint32_t cols = 8;  // of the confidence, rows x cols leaves' worth of updates)
  // Trees: nodes per point, the share of a point's weight above which a leaf splits (once it
  // has had treeSplitVisits visits), and the deepest level (root = 1). With 0.02 a uniform Q
  // stops at 64 leaves (21 nodes), leaving the rest for where the light comes from.
  uint32_t treeNodes = 64;
  float treeSplitShare = 0.02f;
  uint32_t treeSplitVisits = 8;
  uint32_t treeMaxDepth = 8;
  float alphaMin = 1e-4f;  // learning rate clamp(1/(1+visits), min, max), vM's bounds
  // 1: Q is the running mean of its targets from the first one. Returns are unbiased, so
  // there is nothing to wait out (van Mastrigt's 0.05 suits bootstrapped TD targets; with
  // returns it left Q near its initial value for the first ~20 updates of each stratum).
  float alphaMax = 1.0f;
  // Tracking (issue 12): every learning pass ages what a point has learned, so the visit
  // counts behind the learning rate and the point's confidence halve after this many frames
  // without more data and Q follows a light that moves. 0 remembers everything (the
  // right choice where nothing moves: the offline render and the bench).
  float halfLifeFrames = 0.0f;
  // Tracking by how far lights move: what was learned halves this many times per scene radius
  // a light moves (a jump forgets almost all at once; lights that stand still, nothing).
  float forgetOnLightMove = 0.0f;
  // Guided vs BSDF sampling (times the diffuse share and the point's confidence). On the
  // door scene without NEE, 0.5 gives relMSE 5.95 vs 10.2 unguided (3 seeds); 0.8 finds the
  // light more often but lets fireflies through (BSDF-sampled paths in low-Q directions).
  float selectProbability = 0.5f;
  float qFloor = 1e-4f;  // Q stays above this: every direction stays possible
  // Updates per stratum before a point guides at the full share (fewer: BSDF
  // sampling takes over in proportion); 0 trusts every point at once.
  float confidenceUpdates = 4.0f;
  float initialQ = 1e-2f;
  // --points; 0: from the frame's paths (resolvedPointBudget). Points must each receive
  // enough targets to learn: on the door scene a budget of one point per 8 paths per frame
  // reached unguided's error in 0.8x its time where 16384 fixed points needed 1.1x.
  uint32_t pointBudget = 0;
  float rejectionMin = 0.0f;  // 0: from the budget and the scene's surface area
  float rejectionMax = 0.0f;  // 0: 3 x min (Poisson-AO variant)
  PointSet pointSet = PointSet::PhotonMap;
  float normalCosine = 0.7f;   // compatible point normals (about 45 degrees)
  uint32_t dartPaths = 65536;  // light paths that drop candidate points
  uint32_t dartBounces = 4;
  bool spawnFromCamera = true;  // add points where camera paths land uncovered
  bool learn = true;            // update Q every frame (off: keep what was learned)
  LearningTarget target = LearningTarget::Returns;  // --learning-target
  bool lightLearning = true;  // D&K section 4: learned light selection for NEE
  float lightMix = 0.5f;      // share of the learned light choice
  // Learned NEE: a point whose shadow rays are (nearly) all blocked samples a light with this
  // probability only, and its NEE counts 1 / p (shared::neeProbabilityOf). 1 turns it off.
  float neeMinProbability = 0.1f;
  // Russian roulette by the path's expected contribution (throughput x Q in the direction
  // taken, over what its first vertex expected) instead of its throughput alone. A throughput
  // roulette ends the paths guiding sent toward the light, whose pdf is large: on the door
  // scene it raised guided's equal-spp relMSE ratio from 0.27 (roulette off) to 0.82.
  bool guidedRoulette = true;
  uint32_t seed = 1;

  uint32_t strata() const { return rows * cols; }
  bool learnsNee() const { return neeMinProbability < 1.0f; }
  // Q entries per point: strata, or a tree's 4 slots a node.
  uint32_t entriesPerPoint() const {
    return directions == DirectionModel::Tree ? 4 * treeNodes : strata();
  }
};

// The point budget: the setting, or for 0 one point per kPathsPerPoint paths traced per
// frame, within [kMinAutoPoints, kMaxAutoPoints].
constexpr uint32_t kPathsPerPoint = 8, kMinAutoPoints = 256, kMaxAutoPoints = 16384;
uint32_t resolvedPointBudget(const GuidingSettings& s, uint64_t pathsPerFrame);

// Throws std::invalid_argument with a message naming the setting.
void validate(const GuidingSettings& s);

// Parses "RxC" (e.g. 8x8, 16x8) into rows and cols.
void parseStrata(const std::string& text, GuidingSettings& s);

}  // namespace qlight::guiding

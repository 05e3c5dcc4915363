#include "engine/guiding/direction_tree_cpu.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

// The shaders' tree code, compiled for the CPU: its reads go through this per-thread tree.
namespace qlight::guiding::cpu {
thread_local const DirectionTree* tTree = nullptr;
inline glm::vec4 treeWeights(uint32_t node) {
  const float* w = &tTree->weights.at(4 * node);
  return {w[0], w[1], w[2], w[3]};
}
inline glm::uvec4 treeChildren(uint32_t node) {
  const uint32_t* c = &tTree->children.at(4 * node);
  return {c[0], c[1], c[2], c[3]};
}
}  // namespace qlight::guiding::cpu
#define QL_TREE_WEIGHTS(node) (::qlight::guiding::cpu::treeWeights(node))
#define QL_TREE_CHILDREN(node) (::qlight::guiding::cpu::treeChildren(node))
#include "shaders/shared/direction_tree.h"

namespace qlight::guiding {
namespace {

// Points the shared code at `tree` for one call.
struct Using {
  explicit Using(const DirectionTree& tree) {
    if (tree.weights.size() < 4 || tree.children.size() != tree.weights.size())
      throw std::invalid_argument("direction tree: 4 weights and children a node");
    cpu::tTree = &tree;
  }
  ~Using() { cpu::tTree = nullptr; }
};

}  // namespace

float treeDensity(const DirectionTree& tree, glm::vec3 local) {
  Using use(tree);
  float pdfU = 0.0f;
  shared::treeLeafOf(0, shared::treeCoordsOfDirection(local), pdfU);
  return shared::treeSolidAnglePdf(pdfU, local.z);
}

glm::vec3 sampleTreeDirection(const DirectionTree& tree, glm::vec3 xi, float& pdf) {
  Using use(tree);
  glm::vec2 u;
  float pdfU = 0.0f;
  shared::sampleTree(0, xi, u, pdfU);
  glm::vec3 d = shared::directionOfTreeCoords(u);
  pdf = shared::treeSolidAnglePdf(pdfU, d.z);
  return d;
}

float treeIrradiance(const DirectionTree& tree) {
  Using use(tree);
  glm::vec4 w = cpu::treeWeights(0);
  return shared::kPi * 0.25f * (w.x + w.y + w.z + w.w);
}

float treeQ(const DirectionTree& tree, glm::vec3 local) {
  const float mean = treeIrradiance(tree) / shared::kPi;
  Using use(tree);
  float pdfU = 0.0f;
  shared::treeLeafOf(0, shared::treeCoordsOfDirection(local), pdfU);
  return pdfU * mean;
}

std::vector<float> treeOnStrata(const DirectionTree& tree, uint32_t rows, uint32_t cols) {
  std::vector<float> q(size_t(rows) * cols);
  for (uint32_t r = 0; r < rows; ++r)
    for (uint32_t c = 0; c < cols; ++c) {
      float z = 1.0f - (float(r) + 0.5f) / float(rows);
      float phi = shared::kTwoPi * (float(c) + 0.5f) / float(cols);
      float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
      q[size_t(r) * cols + c] = treeQ(tree, {s * std::cos(phi), s * std::sin(phi), z});
    }
  return q;
}

TreeShape treeShape(const DirectionTree& tree) {
  TreeShape shape;
  const uint32_t nodes = uint32_t(tree.children.size() / 4);
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 1}};
  std::vector<bool> seen(nodes, false);
  while (!stack.empty()) {
    auto [node, depth] = stack.back();
    stack.pop_back();
    if (node >= nodes || seen[node]) continue;
    seen[node] = true;
    shape.depth = std::max(shape.depth, depth);
    for (uint32_t c = 0; c < 4; ++c) {
      uint32_t child = tree.children[4 * node + c];
      if (child == 0)
        ++shape.leaves;
      else
        stack.push_back({child, depth + 1});
    }
  }
  return shape;
}

}  // namespace qlight::guiding

// The direction tree of one cache point on the CPU (shaders/shared/direction_tree.h, the
// shaders' code compiled here): its density, samples and Q, for tests and the window's
// hemisphere view.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace qlight::guiding {

// One point's slots (4 a node, node 0 the root): sampling weights and child nodes.
struct DirectionTree {
  std::vector<float> weights;
  std::vector<uint32_t> children;
};

// Density over solid angle of a local direction (z up), as the path passes evaluate it.
float treeDensity(const DirectionTree& tree, glm::vec3 local);
// A direction drawn from the tree with xi in [0,1)^3, and its density.
glm::vec3 sampleTreeDirection(const DirectionTree& tree, glm::vec3 xi, float& pdf);
// Q of the leaf holding a local direction (its sampling weight).
float treeQ(const DirectionTree& tree, glm::vec3 local);
// int Q cos(theta) dw: pi times the mean weight of the root's slots.
float treeIrradiance(const DirectionTree& tree);
// Q at the centre of each of rows x cols strata (row-major), for the hemisphere view.
std::vector<float> treeOnStrata(const DirectionTree& tree, uint32_t rows, uint32_t cols);
// Leaves in use, and the deepest node level (root = 1).
struct TreeShape {
  uint32_t leaves = 0, depth = 0;
};
TreeShape treeShape(const DirectionTree& tree);

}  // namespace qlight::guiding

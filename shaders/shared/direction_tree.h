// A cache point's directions as a quadtree that refines where Q is (issue 9: 8x8 strata
// spread the light through a 10 cm gap over a whole 45-degree stratum). Shared by GLSL
// and C++; the learning pass that grows it is shaders/q_tree_update.comp.
//
// The tree lives on the unit square u = (1 - cos^2 theta, phi / 2 pi) of the point's
// hemisphere: equal areas there are equal cosine-weighted solid angles, so a uniform u is a
// cosine-distributed direction and the density over solid angle is p_u(u) cos(theta) / pi
// (the same parameterisation as practical path guiding's quadtrees, Mueller et al. 2017,
// restricted to the hemisphere).
//
// Each point owns `nodes` nodes; node 0 is the root. A node has 4 child slots (child
// c = x + 2 y covers its x and y halves); a slot is a leaf (children = 0) or holds the
// index of the child node. Per slot the learning pass keeps Q (leaves), and writes the
// sampling weight: a leaf's Q (shrunk toward the point's mean), an inner slot's the mean
// of its children's. Siblings have equal areas, so the chance of child c is w_c / sum(w).
// Slot s of node n of point p has the global index 4 (p nodes + n) + c: the Q entry
// the path passes record targets in.
//
// The includer defines, before including this header:
//   QL_TREE_WEIGHTS(node):  vec4 of the node's 4 slot weights (node: global index)
//   QL_TREE_CHILDREN(node): uvec4 of the node's 4 slot children (local node indices)
#ifndef QLIGHT_SHARED_DIRECTION_TREE_H
#define QLIGHT_SHARED_DIRECTION_TREE_H

#include "common.h"

QL_BEGIN

QL_CONST uint kTreeMaxNodes = 128u;  // per point (the learning pass keeps one list of them)
QL_CONST uint kTreeMaxDepth = 10u;   // levels of nodes below and with the root

QL_FN vec2 treeCoordsOfDirection(vec3 local) {
  float z = clamp(local.z, 0.0f, 1.0f);
  // atan(0, 0) is undefined in GLSL: the pole belongs to phi 0.
  float phi = (local.x != 0.0f || local.y != 0.0f) ? atan(local.y, local.x) : 0.0f;
  if (phi < 0.0f) phi += kTwoPi;
  return vec2(clamp(1.0f - z * z, 0.0f, 1.0f), clamp(phi / kTwoPi, 0.0f, 0.99999994f));
}

QL_FN vec3 directionOfTreeCoords(vec2 u) {
  float sinTheta = sqrt(clamp(u.x, 0.0f, 1.0f));
  float cosTheta = sqrt(clamp(1.0f - u.x, 0.0f, 1.0f));
  float phi = kTwoPi * u.y;
  return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Density over solid angle of a direction with cos(theta) = cosTheta whose leaf has density
// pdfU over the unit square.
QL_FN float treeSolidAnglePdf(float pdfU, float cosTheta) {
  return cosTheta > 0.0f ? pdfU * cosTheta * kInvPi : 0.0f;
}

// Area of a slot of a node at `depth` (the root's slots: 1/4).
QL_FN float treeSlotArea(uint depth) { return exp2(-2.0f * float(depth + 1u)); }

#if defined(QL_TREE_WEIGHTS) && defined(QL_TREE_CHILDREN)
QL_FN float treeWeightOf(vec4 w, uint c) {
  return c == 0u ? w.x : (c == 1u ? w.y : (c == 2u ? w.z : w.w));
}
QL_FN uint treeChildOf(uvec4 ch, uint c) {
  return c == 0u ? ch.x : (c == 1u ? ch.y : (c == 2u ? ch.z : ch.w));
}

// The leaf slot (global index) holding u, and its density over the unit square. firstNode:
// the point's root, p * nodes. A corrupt tree (deeper than kTreeMaxDepth) gives density 0.
QL_FN uint treeLeafOf(uint firstNode, vec2 u, QL_OUT(float) pdfU) {
  uint node = 0u;
  vec2 p = u;
  pdfU = 1.0f;
  for (uint depth = 0u; depth < kTreeMaxDepth; ++depth) {
    vec4 w = QL_TREE_WEIGHTS(firstNode + node);
    uvec4 ch = QL_TREE_CHILDREN(firstNode + node);
    uint cx = p.x >= 0.5f ? 1u : 0u;
    uint cy = p.y >= 0.5f ? 1u : 0u;
    uint c = cx + 2u * cy;
    pdfU *= 4.0f * treeWeightOf(w, c) / (w.x + w.y + w.z + w.w);
    p = 2.0f * p - vec2(float(cx), float(cy));
    uint child = treeChildOf(ch, c);
    if (child == 0u) return 4u * (firstNode + node) + c;
    node = child;
  }
  pdfU = 0.0f;
  return 4u * firstNode;
}

// A point of the unit square drawn from the tree: xi.z descends (rescaled at each level),
// xi.xy places it uniformly in the leaf. Returns the leaf slot; pdfU its density.
QL_FN uint sampleTree(uint firstNode, vec3 xi, QL_OUT(vec2) u, QL_OUT(float) pdfU) {
  uint node = 0u;
  vec2 origin = vec2(0.0f);
  float size = 1.0f;
  float s = xi.z;
  pdfU = 1.0f;
  for (uint depth = 0u; depth < kTreeMaxDepth; ++depth) {
    vec4 w = QL_TREE_WEIGHTS(firstNode + node);
    uvec4 ch = QL_TREE_CHILDREN(firstNode + node);
    float sum = w.x + w.y + w.z + w.w;
    float t = s * sum;
    uint c = 0u;
    float below = 0.0f;
    // The first child whose running sum exceeds t (weights are positive: Q has a floor).
    while (c < 3u && below + treeWeightOf(w, c) <= t) {
      below += treeWeightOf(w, c);
      ++c;
    }
    float wc = treeWeightOf(w, c);
    s = clamp((t - below) / wc, 0.0f, 0.99999994f);
    pdfU *= 4.0f * wc / sum;
    size *= 0.5f;
    origin += size * vec2(float(c & 1u), float(c >> 1u));
    uint child = treeChildOf(ch, c);
    if (child == 0u) {
      u = origin + size * vec2(xi.x, xi.y);
      return 4u * (firstNode + node) + c;
    }
    node = child;
  }
  u = vec2(0.5f);
  pdfU = 0.0f;
  return 4u * firstNode;
}
#endif

QL_END

#endif

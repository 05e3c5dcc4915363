#version 460
// The learning pass of the direction trees (shared/direction_tree.h), one thread per point:
// applies the frame's targets to the leaves (as q_update.comp does to strata), writes the
// sampling weights (leaves' Q shrunk toward the point's mean, inner slots the mean of
// their children), then reshapes the tree where Q is: a leaf holding more than splitShare
// of the point's weight splits into 4 (children start from its Q, so the distribution is
// the same the moment it splits), and a node whose leaves together hold under a quarter of
// that merges back into one leaf. Points without targets cost a walk of their tree.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/guiding_types.h"
#include "shared/direction_tree.h"

layout(local_size_x = QL_Q_UPDATE_GROUP_SIZE) in;
layout(binding = QL_Q_UPDATE_BIND_VALUES, scalar) buffer Values { float values[]; };
layout(binding = QL_Q_UPDATE_BIND_VISITS, scalar) buffer Visits { uint visits[]; };
layout(binding = QL_Q_UPDATE_BIND_CDF, scalar) buffer Weights { float weights[]; };
layout(binding = QL_Q_UPDATE_BIND_SUMS, scalar) buffer Sums { uint sums[]; };
layout(binding = QL_Q_UPDATE_BIND_COUNTS, scalar) buffer Counts { uint counts[]; };
layout(binding = QL_Q_UPDATE_BIND_POINT_UPDATES, scalar) buffer PointUpdates { uint pointUpdates[]; };
layout(binding = QL_Q_UPDATE_BIND_ROW_CLOCKS, scalar) buffer RowClocks { float rowClocks[]; };
layout(binding = QL_Q_UPDATE_BIND_CHILDREN, scalar) buffer Children { uint children[]; };
layout(push_constant, scalar) uniform Push { TreeUpdatePush pc; };

const float kShrink = 4.0;  // pseudo-visits toward the point's mean, as q_update.comp

void main() {
  uint row = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
             gl_LocalInvocationID.x;
  if (row >= pc.rowCount) return;
  uint first = row * pc.nodes;  // the point's root (global node index)

  // The tree breadth first (parents before children), each node's depth and parent slot.
  uint order[kTreeMaxNodes];
  uint depthOf[kTreeMaxNodes];
  uint parentSlot[kTreeMaxNodes];
  bool used[kTreeMaxNodes];
  for (uint n = 0u; n < pc.nodes; ++n) used[n] = false;
  uint count = 1u;
  order[0] = 0u;
  depthOf[0] = 0u;
  used[0] = true;
  uint targets = 0u;
  for (uint i = 0u; i < count; ++i) {
    uint node = order[i];
    for (uint c = 0u; c < 4u; ++c) {
      uint slot = 4u * (first + node) + c;
      uint child = children[slot];
      if (child != 0u && child < pc.nodes && !used[child] && count < pc.nodes) {
        used[child] = true;
        order[count++] = child;
        depthOf[child] = depthOf[node] + 1u;
        parentSlot[child] = slot;
      } else {
        targets += counts[slot];
      }
    }
  }
  if (targets == 0u && pc.everyRow == 0u) return;
  float kept = keptAfter(pc.clock - rowClocks[row]);
  float visitsKept = visitsKeptOf(kept);
  rowClocks[row] = pc.clock;
  pointUpdates[row] = cappedUpdates(agedCount(pointUpdates[row], kept), targets, pc.confidenceCap);

  // The update of each leaf, and the area-weighted mean of the visited ones.
  float visitedSum = 0.0, visitedArea = 0.0;
  for (uint i = 0u; i < count; ++i) {
    uint node = order[i];
    float area = treeSlotArea(depthOf[node]);
    for (uint c = 0u; c < 4u; ++c) {
      uint e = 4u * (first + node) + c;
      if (children[e] != 0u) continue;
      uint m = counts[e];
      uint n = agedCount(visits[e], visitsKept);
      float q = values[e];
      if (m == 0u && n != visits[e]) visits[e] = n;
      if (m > 0u) {
        float sum = fixedSumToFloat(sums[2u * e], sums[2u * e + 1u]);
        q = updatedQ(q, sum, m, n, pc.alphaMin, pc.alphaMax, pc.floorValue);
        values[e] = q;
        visits[e] = n + m;
        sums[2u * e] = 0u;
        sums[2u * e + 1u] = 0u;
        counts[e] = 0u;
      }
      if (n + m > 0u) {
        visitedSum += max(q, pc.floorValue) * area;
        visitedArea += area;
      }
    }
  }
  float prior = visitedArea > 0.0 ? visitedSum / visitedArea : 0.0;

  // Sampling weights, children before parents.
  float nodeMean[kTreeMaxNodes];
  for (uint i = count; i-- > 0u;) {
    uint node = order[i];
    float sum = 0.0;
    for (uint c = 0u; c < 4u; ++c) {
      uint e = 4u * (first + node) + c;
      uint child = children[e];
      float w;
      if (child != 0u) {
        w = nodeMean[child];
      } else {
        float n = float(visits[e]);
        float q = max(values[e], pc.floorValue);
        w = visitedArea > 0.0 ? (n * q + kShrink * prior) / (n + kShrink) : q;
      }
      weights[e] = w;
      sum += w;
    }
    nodeMean[node] = 0.25 * sum;
  }
  float total = nodeMean[0];  // the weights' integral over the unit square
  if (!(total > 0.0)) return;

  // Merges, deepest first: a node of leaves that holds little goes back to one leaf.
  for (uint i = count; i-- > 1u;) {
    uint node = order[i];
    uint s0 = 4u * (first + node);
    if ((children[s0] | children[s0 + 1u] | children[s0 + 2u] | children[s0 + 3u]) != 0u) continue;
    float share = nodeMean[node] * exp2(-2.0 * float(depthOf[node])) / total;
    if (share >= 0.25 * pc.splitShare) continue;
    uint p = parentSlot[node];
    float q = 0.0;
    uint n = 0u;
    for (uint c = 0u; c < 4u; ++c) {
      q += 0.25 * max(values[s0 + c], pc.floorValue);
      n += visits[s0 + c];
    }
    values[p] = q;
    visits[p] = n;
    children[p] = 0u;  // its weight already is the node's mean
    used[node] = false;
  }

  // Splits, in breadth-first order while free nodes last.
  uint nextFree = 1u;
  for (uint i = 0u; i < count; ++i) {
    uint node = order[i];
    if (!used[node] || depthOf[node] + 1u >= pc.maxDepth) continue;
    float area = treeSlotArea(depthOf[node]);
    for (uint c = 0u; c < 4u; ++c) {
      uint e = 4u * (first + node) + c;
      if (children[e] != 0u || visits[e] < pc.splitVisits) continue;
      if (weights[e] * area <= pc.splitShare * total) continue;
      while (nextFree < pc.nodes && used[nextFree]) ++nextFree;
      if (nextFree >= pc.nodes) return;
      uint child = nextFree;
      used[child] = true;
      for (uint k = 0u; k < 4u; ++k) {
        uint s = 4u * (first + child) + k;
        values[s] = values[e];
        visits[s] = visits[e] / 4u;
        weights[s] = weights[e];
        children[s] = 0u;
        sums[2u * s] = 0u;
        sums[2u * s + 1u] = 0u;
        counts[s] = 0u;
      }
      children[e] = child;
    }
  }
}

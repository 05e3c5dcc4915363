#version 460
// Between wavefront passes: the queue just filled becomes the current one
// (its dispatch size computed here, on the GPU, so the CPU never waits), and
// the queue just consumed is emptied to be filled next.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_types.h"

layout(local_size_x = 1) in;
layout(binding = QL_BIND_QUEUE_STATE, scalar) buffer Queues { QueueState queues[2]; };
layout(push_constant, scalar) uniform Push { TracePush pc; };

void main() {
  uint next = pc.bounce & 1u;  // the queue the coming passes read
  if (pc.extend != 0u) queues[next].count = pc.pathCount;  // start of a sample: every path
  queues[next].groupsX = (queues[next].count + kPathGroupSize - 1u) / kPathGroupSize;
  queues[next].groupsY = 1u;
  queues[next].groupsZ = 1u;
  queues[next ^ 1u].count = 0u;
}

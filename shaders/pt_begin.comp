#version 460
// Wavefront pass 1: one camera ray per pixel (jittered), fresh path state. Not run when the
// camera-hit shade pass starts the paths itself (kTraceInShade: include/camera_path.glsl).
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/camera_path.glsl"
layout(binding = QL_BIND_QUEUE_OUT, scalar) writeonly buffer QueueOut { uint queueOut[]; };

void main() {
  uint path = gl_GlobalInvocationID.x;
  if (path >= pc.pathCount) return;
  storePath(path, cameraPath(path));
  queueOut[path] = path;  // every path starts in queue 0 (its count is set by pt_queue)
}

#version 460
// Wavefront pass 2: the extension ray of each queued (live) path; its hit is
// all this pass writes. Small kernel, little live state: traversal runs at
// full speed. (Shadow rays are traced where they are made, in pt_shade.)
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/path_queue.glsl"

void main() {
  uint path = queuedPath(gl_GlobalInvocationID.x);
  if (path == kNoPath) return;
  vec4 o = pathTexel(path, kPathTexelOrigin), d = pathTexel(path, kPathTexelDir);
  BvhHit hit;
  bool found = traceClosest(o.xyz, d.xyz, kInfinity, hit);
  setHit(path, found ? hit.t : -1.0, hit.u, hit.v, hit.instance, hit.primitive);
}

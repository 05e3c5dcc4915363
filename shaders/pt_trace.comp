#version 460
// Wavefront pass 2: the pending shadow ray (NEE) of each path, then its
// extension ray. Small kernel, little live state: traversal runs at full speed.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/path_queue.glsl"

void main() {
  uint path = queuedPath(gl_GlobalInvocationID.x);
  if (path == 0xffffffffu) return;
  vec4 t3 = pathTexel(path, 3u);
  uint flags = floatBitsToUint(t3.w);
  bool shadow = (flags & kPathShadowPending) != 0u;
  bool extend = pc.extend != 0u && (flags & kPathAlive) != 0u;
  if (!shadow && !extend) return;
  uvec4 counters = floatBitsToUint(pathTexel(path, 9u));
  if (shadow) {
    vec4 o = pathTexel(path, 4u), d = pathTexel(path, 5u), c = pathTexel(path, 6u), l = pathTexel(path, 8u);
    counters.z++;
    counters.w++;
    bool blocked = traceAny(o.xyz, d.xyz, o.w);
    if (!blocked) t3.xyz += c.xyz;
    uint point = floatBitsToUint(l.z);
    if (point != kNoCachePoint) recordVTarget(point, floatBitsToUint(l.w), blocked ? 0.0 : l.y);
    flags &= ~kPathShadowPending;
  }
  if (extend) {
    vec4 o = pathTexel(path, 0u), d = pathTexel(path, 1u);
    counters.z++;
    BvhHit hit;
    bool found = traceClosest(o.xyz, d.xyz, kInfinity, hit);
    setPathTexel(path, 7u, vec4(found ? hit.t : -1.0, hit.u, hit.v, uintBitsToFloat(hit.instance)));
    vec4 t8 = pathTexel(path, 8u);
    t8.x = uintBitsToFloat(hit.primitive);
    setPathTexel(path, 8u, t8);
  }
  setPathTexel(path, 3u, vec4(t3.xyz, uintBitsToFloat(flags)));
  setPathTexel(path, 9u, uintBitsToFloat(counters));
}

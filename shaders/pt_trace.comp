#version 460
// Wavefront pass 2: the pending shadow ray (NEE) of each queued path, then its
// extension ray. Small kernel, little live state: traversal runs at full speed.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/path_queue.glsl"

void main() {
  uint path = queuedPath(gl_GlobalInvocationID.x);
  if (path == kNoPath) return;
  vec4 radianceFlags = pathTexel(path, kPathTexelRadianceFlags);
  uint flags = floatBitsToUint(radianceFlags.w);
  bool shadow = (flags & kPathShadowPending) != 0u;
  bool extend = pc.extend != 0u && (flags & kPathAlive) != 0u;
  if (!shadow && !extend) return;
  uvec4 counters = floatBitsToUint(pathTexel(path, kPathTexelCounters));
  if (shadow) {
    vec4 o = pathTexel(path, kPathTexelShadowOrigin), d = pathTexel(path, kPathTexelShadowDir);
    vec4 c = pathTexel(path, kPathTexelShadowContribution);
    vec4 l = pathTexel(path, kPathTexelShadowLearning);
    counters.z++;
    counters.w++;
    bool blocked = traceAny(o.xyz, d.xyz, o.w);
    if (!blocked) radianceFlags.xyz += c.xyz;
    uint point = floatBitsToUint(l.z);
    if (lightLearningOn(point)) recordVTarget(point, floatBitsToUint(l.w), blocked ? 0.0 : l.y);
    recordShadowRay(point, !blocked);
    flags &= ~kPathShadowPending;
  }
  if (extend) {
    vec4 o = pathTexel(path, kPathTexelOrigin), d = pathTexel(path, kPathTexelDir);
    counters.z++;
    BvhHit hit;
    bool found = traceClosest(o.xyz, d.xyz, kInfinity, hit);
    setPathTexel(path, kPathTexelHit,
                 vec4(found ? hit.t : -1.0, hit.u, hit.v, uintBitsToFloat(hit.instance)));
    vec4 t = pathTexel(path, kPathTexelShadowLearning);  // x: the hit primitive
    t.x = uintBitsToFloat(hit.primitive);
    setPathTexel(path, kPathTexelShadowLearning, t);
  }
  setPathTexel(path, kPathTexelRadianceFlags, vec4(radianceFlags.xyz, uintBitsToFloat(flags)));
  setPathTexel(path, kPathTexelCounters, uintBitsToFloat(counters));
}

// Spawning secondary rays without self-intersection: Waechter & Binder,
// "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing Gems,
// ch. 6). Moves the point along the geometric normal by a few ulps, scaled to
// the magnitude of its coordinates, so it works at any scene scale.
#ifndef QLIGHT_SHARED_RAY_OFFSET_H
#define QLIGHT_SHARED_RAY_OFFSET_H
#include "common.h"

QL_BEGIN
QL_FN vec3 offsetRayOrigin(vec3 p, vec3 n) {
  const float kOrigin = 1.0f / 32.0f;
  const float kFloatScale = 1.0f / 65536.0f;
  const float kIntScale = 256.0f;
  ivec3 ofi = ivec3(kIntScale * n.x, kIntScale * n.y, kIntScale * n.z);
  vec3 pi = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0f ? -ofi.x : ofi.x)),
                 intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0f ? -ofi.y : ofi.y)),
                 intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0f ? -ofi.z : ofi.z)));
  return vec3(abs(p.x) < kOrigin ? p.x + kFloatScale * n.x : pi.x,
              abs(p.y) < kOrigin ? p.y + kFloatScale * n.y : pi.y,
              abs(p.z) < kOrigin ? p.z + kFloatScale * n.z : pi.z);
}

// A hit point computed from numbers as large as `extent` (the triangle's vertices,
// the ray's origin) carries a rounding error that scales with them, not with the
// point: a point near the origin on a 1 km triangle is off by ~1e-4 m, far more
// than its own ulps. The point moves kExtentOffset * extent further out: 16 ulps of
// the extent (1 mm on a 1 km triangle, 10 um in a 5 m room); 1 ulp already passes
// tests/render/ray_offset_test.cpp, none fails it (8% of its floor self-shadowed).
QL_CONST float kExtentOffset = 2e-6f;

QL_FN vec3 offsetRayOriginFrom(vec3 p, vec3 n, float extent) {
  return offsetRayOrigin(p, n) + n * (kExtentOffset * extent);
}
QL_END

#endif

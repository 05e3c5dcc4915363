// Two-level BVH traversal shared by GLSL and C++ (the C++ tests run this very
// code). Layout: bvh_types.h. The includer defines how texels are read:
//   QL_BVH_NODE(i), QL_BVH_TRI(i), QL_BVH_INST(i) -> vec4 texel i
// GLSL:  #define QL_BVH_NODE(i) imageLoad(uBvhNodes, int(i))   (readonly imageBuffer)
// C++:   engine/bvh/cpu_traversal.h
//
// traceClosest / traceAny take a world-space ray (direction need not be unit
// length; t is measured along it) and report hits with 0 < t < tMax. Every
// step pops or descends, so any input (NaN included) ends; the builder caps
// tree depths so the fixed stack cannot overflow.
// Shape of the loop (Aila & Laine 2009, "while-while"): descend inner nodes
// until the current ref is a leaf, then work through pending leaves. A TLAS
// leaf is an instance: the ray moves to object space (not renormalized, so t
// stays comparable) and the BLAS root becomes the current ref; when the stack
// drains back to the depth it had there, the world ray is restored.
// Triangles: watertight test of Woop, Benthin & Wald 2013 (JCGT 2(1)).
#ifndef QLIGHT_SHARED_BVH_TRAVERSE_H
#define QLIGHT_SHARED_BVH_TRAVERSE_H

#include "bvh_types.h"

#if !defined(QL_BVH_NODE) || !defined(QL_BVH_TRI) || !defined(QL_BVH_INST)
#error "define QL_BVH_NODE(i), QL_BVH_TRI(i) and QL_BVH_INST(i) before including bvh_traverse.h"
#endif

QL_BEGIN

// Box far distances are scaled by this before comparing with near distances,
// so rounding in the slab test never culls a box the ray touches (Ize 2013,
// "Robust BVH Ray Traversal", needs 1 + 2 gamma_3 ~ 1 + 3.6e-7; the margin
// also covers near-ties between the box distance and the current hit's t).
QL_CONST float kBvhBoxFarScale = 1.000002f;

// 1/x without infinities, so the slab test never computes 0 * inf = NaN.
QL_FN float bvhSafeRcp(float x) {
  return abs(x) > 1e-20f ? 1.0f / x : (x >= 0.0f ? 1e20f : -1e20f);
}

QL_FN vec3 bvhSafeInverse(vec3 d) {
  return vec3(bvhSafeRcp(d.x), bvhSafeRcp(d.y), bvhSafeRcp(d.z));
}

// A ray in one BLAS's object space, with what the watertight test needs: the
// rows of the shear that maps the ray onto +z (kz = the dominant axis of dir;
// x' = p[kx] - Sx p[kz], y' = p[ky] - Sy p[kz], z' = Sz p[kz]).
struct BvhLocalRay {
  vec3 origin;
  vec3 invDir;
  vec3 shearX;
  vec3 shearY;
  vec3 shearZ;
};

QL_FN BvhLocalRay bvhMakeLocalRay(vec3 origin, vec3 dir) {
  vec3 ad = abs(dir);
  vec3 ex;
  vec3 ey;
  vec3 ez;
  if (ad.x >= ad.y && ad.x >= ad.z) {
    ex = vec3(0.0f, 1.0f, 0.0f);
    ey = vec3(0.0f, 0.0f, 1.0f);
    ez = vec3(1.0f, 0.0f, 0.0f);
  } else if (ad.y >= ad.z) {
    ex = vec3(0.0f, 0.0f, 1.0f);
    ey = vec3(1.0f, 0.0f, 0.0f);
    ez = vec3(0.0f, 1.0f, 0.0f);
  } else {
    ex = vec3(1.0f, 0.0f, 0.0f);
    ey = vec3(0.0f, 1.0f, 0.0f);
    ez = vec3(0.0f, 0.0f, 1.0f);
  }
  float dz = dot(ez, dir);
  if (dz < 0.0f) {  // keep the winding: the sign of det tells the facing
    vec3 swapped = ex;
    ex = ey;
    ey = swapped;
  }
  BvhLocalRay ray;
  ray.origin = origin;
  ray.invDir = bvhSafeInverse(dir);
  float rcpDz = dot(ez, ray.invDir);  // dz is the largest component, so never below 1e-20
  ray.shearX = ex - (dot(ex, dir) * rcpDz) * ez;
  ray.shearY = ey - (dot(ey, dir) * rcpDz) * ez;
  ray.shearZ = rcpDz * ez;
  return ray;
}

// The world ray in instance `instance`'s object space.
QL_FN BvhLocalRay bvhInstanceRay(uint instance, vec3 origin, vec3 dir) {
  uint base = instance * kBvhInstanceTexels + kBvhInstanceObjectFromWorld;
  vec4 r0 = QL_BVH_INST(base);
  vec4 r1 = QL_BVH_INST(base + 1u);
  vec4 r2 = QL_BVH_INST(base + 2u);
  vec3 o = vec3(dot(vec3(r0), origin) + r0.w, dot(vec3(r1), origin) + r1.w,
                dot(vec3(r2), origin) + r2.w);
  vec3 d = vec3(dot(vec3(r0), dir), dot(vec3(r1), dir), dot(vec3(r2), dir));
  return bvhMakeLocalRay(o, d);
}

QL_FN uint bvhInstanceBlasRoot(uint instance) {
  return floatBitsToUint(QL_BVH_INST(instance * kBvhInstanceTexels + kBvhInstanceInfo).x);
}

// Watertight ray/triangle test. A hit needs 0 < t < tLimit; on a hit tuv gets
// (t, u, v) with u, v the barycentrics of p1, p2. Edges and vertices count as
// inside for both neighbours (a shared edge may report either triangle, never
// neither). Degenerate triangles give det = 0 and t = NaN or inf: a miss.
QL_FN bool bvhIntersectTriangle(BvhLocalRay ray, vec3 p0, vec3 p1, vec3 p2, float tLimit,
                                QL_INOUT(vec3) tuv) {
  QL_BVH_PRECISE vec3 a = p0 - ray.origin;
  QL_BVH_PRECISE vec3 b = p1 - ray.origin;
  QL_BVH_PRECISE vec3 c = p2 - ray.origin;
  QL_BVH_PRECISE float ax = dot(ray.shearX, a);
  QL_BVH_PRECISE float ay = dot(ray.shearY, a);
  QL_BVH_PRECISE float bx = dot(ray.shearX, b);
  QL_BVH_PRECISE float by = dot(ray.shearY, b);
  QL_BVH_PRECISE float cx = dot(ray.shearX, c);
  QL_BVH_PRECISE float cy = dot(ray.shearY, c);
  QL_BVH_PRECISE float eu = cx * by - cy * bx;
  QL_BVH_PRECISE float ev = ax * cy - ay * cx;
  QL_BVH_PRECISE float ew = bx * ay - by * ax;
  if ((eu < 0.0f || ev < 0.0f || ew < 0.0f) && (eu > 0.0f || ev > 0.0f || ew > 0.0f)) {
    return false;
  }
  float det = eu + ev + ew;
  float scaledT = eu * dot(ray.shearZ, a) + ev * dot(ray.shearZ, b) + ew * dot(ray.shearZ, c);
  float t = scaledT / det;
  if (!(t > 0.0f && t < tLimit)) return false;  // also rejects NaN and inf
  float invDet = 1.0f / det;
  tuv = vec3(t, ev * invDet, ew * invDet);
  return true;
}

// A candidate hit counts when QL_BVH_ACCEPT_HIT(instance, primitive, u, v) holds: the GLSL
// includer (include/scene_access.glsl) tests alpha there; by default every hit counts.
#ifndef QL_BVH_ACCEPT_HIT
#define QL_BVH_ACCEPT_HIT(instance, primitive, u, v) true
#endif

// Both entry points: anyHit stops at the first hit (the compiler folds the
// constant after inlining).
QL_FN bool bvhTrace(vec3 origin, vec3 dir, float tMax, bool anyHit, QL_OUT(BvhHit) hit) {
  hit.t = tMax;
  hit.u = 0.0f;
  hit.v = 0.0f;
  hit.instance = kBvhInvalidIndex;
  hit.primitive = kBvhInvalidIndex;

  vec3 worldInvDir = bvhSafeInverse(dir);
  vec3 rayOrigin = origin;  // of the level being traversed
  vec3 rayInvDir = worldInvDir;
  BvhLocalRay local;
  local.origin = origin;
  local.invDir = worldInvDir;
  local.shearX = vec3(0.0f);
  local.shearY = vec3(0.0f);
  local.shearZ = vec3(0.0f);
  uint instance = kBvhInvalidIndex;

  uint stack[kBvhStackSize + 1u];  // + 1: the inner loop's unconditional store
  stack[0] = 0u;                   // ref 0 (the header node) ends the traversal
  uint sp = 1u;
  uint blasBase = 0u;  // stack depth when the current instance was entered; 0 in the TLAS
  uint node = floatBitsToUint(QL_BVH_NODE(kBvhHeaderNode).x);
  bool found = false;

  while (node != 0u) {
    // Inner nodes: test both children, go to the nearer, push the farther.
    while (int(node) > 0) {
      uint base = node * kBvhNodeTexels;
      vec4 leftMin = QL_BVH_NODE(base + kBvhNodeLeftMin);
      vec4 leftMax = QL_BVH_NODE(base + kBvhNodeLeftMax);
      vec4 rightMin = QL_BVH_NODE(base + kBvhNodeRightMin);
      vec4 rightMax = QL_BVH_NODE(base + kBvhNodeRightMax);
      vec3 l0 = (vec3(leftMin) - rayOrigin) * rayInvDir;
      vec3 l1 = (vec3(leftMax) - rayOrigin) * rayInvDir;
      vec3 r0 = (vec3(rightMin) - rayOrigin) * rayInvDir;
      vec3 r1 = (vec3(rightMax) - rayOrigin) * rayInvDir;
      vec3 lNear = min(l0, l1);
      vec3 lFar = max(l0, l1);
      vec3 rNear = min(r0, r1);
      vec3 rFar = max(r0, r1);
      float leftEnter = max(max(lNear.x, lNear.y), max(lNear.z, 0.0f));
      float leftExit = min(min(lFar.x, lFar.y), min(lFar.z, hit.t)) * kBvhBoxFarScale;
      float rightEnter = max(max(rNear.x, rNear.y), max(rNear.z, 0.0f));
      float rightExit = min(min(rFar.x, rFar.y), min(rFar.z, hit.t)) * kBvhBoxFarScale;
      bool leftHit = leftEnter <= leftExit;
      bool rightHit = rightEnter <= rightExit;
      uint leftRef = floatBitsToUint(leftMin.w);
      uint rightRef = floatBitsToUint(rightMin.w);
      // Branch-free step (on lavapipe every branch side runs anyway): push the
      // farther child when both are hit, pop when neither is. The store
      // always happens; it lands above the top when nothing is pushed.
      bool both = leftHit && rightHit;
      bool none = !(leftHit || rightHit);
      bool rightFirst = rightHit && (!leftHit || rightEnter < leftEnter);
      uint top = stack[sp - 1u];
      stack[sp] = rightFirst ? leftRef : rightRef;
      bool leaveBlas = none && sp == blasBase;  // the pop returns to the TLAS
      rayOrigin = leaveBlas ? origin : rayOrigin;
      rayInvDir = leaveBlas ? worldInvDir : rayInvDir;
      blasBase = leaveBlas ? 0u : blasBase;
      sp = none ? sp - 1u : (both ? sp + 1u : sp);
      node = none ? top : (rightFirst ? rightRef : leftRef);
    }
    // A TLAS leaf: enter its instance. Its own loop of at most one step, not an
    // if inside the triangle loop: lavapipe runs an if's body under a mask
    // whatever the lanes, so there it ran at every leaf step; here it runs once
    // per visit of the outer loop.
    while (int(node) < 0 && blasBase == 0u) {
      instance = bvhTlasLeafInstance(node);
      local = bvhInstanceRay(instance, origin, dir);
      rayOrigin = local.origin;
      rayInvDir = local.invDir;
      blasBase = sp;
      node = bvhInstanceBlasRoot(instance);
    }
    // BLAS leaves: test up to 8 triangles, pop, and go on while the popped ref
    // is another BLAS leaf.
    while (int(node) < 0 && blasBase != 0u) {
      uint first = bvhLeafFirst(node);
      uint last = first + (node & kBvhLeafCountMask);
      for (uint i = first; i <= last; i++) {
        uint texel = i * kBvhTriangleTexels;
        vec4 t0 = QL_BVH_TRI(texel);
        vec4 t1 = QL_BVH_TRI(texel + 1u);
        vec4 t2 = QL_BVH_TRI(texel + 2u);
        vec3 tuv = vec3(0.0f);
        uint owner = floatBitsToUint(t1.w);  // instance + 1 in the merged BLAS, else 0
        owner = owner == 0u ? instance : owner - 1u;
        if (bvhIntersectTriangle(local, vec3(t0), vec3(t1), vec3(t2), hit.t, tuv) &&
            QL_BVH_ACCEPT_HIT(owner, floatBitsToUint(t0.w), tuv.y, tuv.z)) {
          found = true;
          hit.t = tuv.x;
          hit.u = tuv.y;
          hit.v = tuv.z;
          hit.instance = owner;
          hit.primitive = floatBitsToUint(t0.w);
          if (anyHit) return true;
        }
      }
      // Pop; when the BLAS part of the stack is empty the next entry belongs
      // to the TLAS, so the world ray comes back.
      bool leaveBlas = sp == blasBase;
      rayOrigin = leaveBlas ? origin : rayOrigin;
      rayInvDir = leaveBlas ? worldInvDir : rayInvDir;
      blasBase = leaveBlas ? 0u : blasBase;
      sp -= 1u;
      node = stack[sp];
    }
  }
  return found;
}

// Nearest hit with 0 < t < tMax; on a miss hit.t = tMax and the indices are
// kBvhInvalidIndex.
QL_FN bool traceClosest(vec3 origin, vec3 dir, float tMax, QL_OUT(BvhHit) hit) {
  return bvhTrace(origin, dir, tMax, false, hit);
}

// Whether anything lies at 0 < t < tMax (shadow rays).
QL_FN bool traceAny(vec3 origin, vec3 dir, float tMax) {
  BvhHit ignored;
  return bvhTrace(origin, dir, tMax, true, ignored);
}

QL_END

#endif

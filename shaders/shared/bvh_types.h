// GPU layout of qlight's two-level BVH, shared by GLSL and C++. Everything is
// an RGBA32F texel so the shader reads it with texelFetch on a samplerBuffer
// (on lavapipe texel loads are 1.6-2x faster than storage-buffer loads).
// Integers live in the float lanes as raw bits (floatBitsToUint).
//
// Three arrays, all BLASes concatenated and the TLAS appended:
//
// nodes: 4 texels per node; node i starts at texel 4*i.
//   node 0 is the header (never a child, so ref 0 doubles as "stack empty"):
//     texel 0: (tlasRootRef, instanceCount, tlasNodeOffset, nodeCount)  bits
//     texel 1: (sceneMin.xyz, blasCount bits)
//     texel 2: (sceneMax.xyz, triangleCount bits)
//     texel 3: 0 (reserved)
//   other nodes store BOTH children's boxes, so one node visit tests two:
//     texel 0: (left.min.xyz,  leftRef bits)
//     texel 1: (left.max.xyz,  0)
//     texel 2: (right.min.xyz, rightRef bits)
//     texel 3: (right.max.xyz, 0)
//   A child ref is an inner node index (1 .. 2^31-1), or a leaf with bit 31:
//     BLAS leaf: kBvhLeafBit | firstTriangle << 3 | (triangleCount - 1)
//                (firstTriangle indexes the concatenated triangle array)
//     TLAS leaf: kBvhLeafBit | instanceIndex (one instance per leaf)
// triangles: 3 texels per triangle, in leaf order, object space:
//     (v0.xyz, originalTriangleIndex bits), (v1.xyz, owner bits), (v2.xyz, 0)
//   originalTriangleIndex is the triangle's index within its mesh's index
//   buffer (FlatBvh::triangleIndices holds the same numbers as a uint array).
//   owner is 0 in a mesh's own BLAS (a hit belongs to the instance the ray
//   entered). The fixed instances' triangles are also copied, in world space,
//   into one merged BLAS after the meshes' (fewer, tighter boxes than a top
//   level over overlapping instances: Embree's flat build); there owner is 1 +
//   the instance each triangle came from.
// instances: 8 texels per instance (in the order given to rebuildTopLevel,
//   then one identity instance whose BLAS is the merged one, when there is one):
//     texels 0-2: objectFromWorld rows (3x4: dot(row.xyz, p) + row.w)
//     texels 3-5: worldFromObject rows
//     texel 6:    (blasRootRef, blasTriangleOffset, customIndex, blasIndex) bits
//                 blasRootRef is 0 for an instance that cannot be hit (empty
//                 mesh or singular transform); the TLAS leaves it out.
//     texel 7:    0 (reserved)
#ifndef QLIGHT_SHARED_BVH_TYPES_H
#define QLIGHT_SHARED_BVH_TYPES_H

#include "common.h"

// The watertight triangle test needs each product rounded on its own (no fused
// multiply-add) so that a shared edge gives bit-opposite edge functions in its
// two triangles. GLSL spells that `precise`; C++ does not contract on x86-64
// unless built with FMA (-march=haswell and later): keep -ffp-contract=off then.
#ifdef __cplusplus
#define QL_BVH_PRECISE
#else
#define QL_BVH_PRECISE precise
#endif

QL_BEGIN

QL_CONST uint kBvhNodeTexels = 4u;
QL_CONST uint kBvhTriangleTexels = 3u;
QL_CONST uint kBvhInstanceTexels = 8u;

// Texel offsets inside one node.
QL_CONST uint kBvhNodeLeftMin = 0u;
QL_CONST uint kBvhNodeLeftMax = 1u;
QL_CONST uint kBvhNodeRightMin = 2u;
QL_CONST uint kBvhNodeRightMax = 3u;

// Texel offsets inside one instance.
QL_CONST uint kBvhInstanceObjectFromWorld = 0u;
QL_CONST uint kBvhInstanceWorldFromObject = 3u;
QL_CONST uint kBvhInstanceInfo = 6u;

// Header texel (node 0, texel 0) lanes, and the header's bounds texels.
QL_CONST uint kBvhHeaderNode = 0u;
QL_CONST uint kBvhHeaderSceneMin = 1u;
QL_CONST uint kBvhHeaderSceneMax = 2u;

QL_CONST uint kBvhLeafBit = 0x80000000u;
QL_CONST uint kBvhLeafCountBits = 3u;
QL_CONST uint kBvhLeafCountMask = 7u;
QL_CONST uint kBvhMaxLeafTriangles = 8u;
QL_CONST uint kBvhMaxTriangles = 1u << 28u;  // firstTriangle must fit in 28 bits
QL_CONST uint kBvhInvalidIndex = 0xffffffffu;

// One stack for both levels: the empty-marker, up to kBvhMaxTlasDepth TLAS
// entries and up to kBvhMaxBlasDepth BLAS entries (near-first traversal
// pushes at most one entry per inner node on the current root-to-leaf path,
// and the builder caps those path lengths).
QL_CONST uint kBvhStackSize = 48u;
QL_CONST uint kBvhMaxTlasDepth = 18u;
QL_CONST uint kBvhMaxBlasDepth = 29u;

// Closest hit: t along the caller's (unnormalized) direction, barycentrics of
// v1 and v2 (p = (1-u-v) v0 + u v1 + v v2), the instance's index in the
// instance array and the triangle's index within its mesh.
struct BvhHit {
  float t;
  float u;
  float v;
  uint instance;
  uint primitive;
};
QL_CHECK_SIZE(BvhHit, 20);

// The texel groups as structs, for C++ code that fills or reads them and to
// pin their sizes; the shader reads single texels.
struct BvhNodeTexels {
  vec4 leftMin;
  vec4 leftMax;
  vec4 rightMin;
  vec4 rightMax;
};
QL_CHECK_SIZE(BvhNodeTexels, 64);

struct BvhTriangleTexels {
  vec4 v0;
  vec4 v1;
  vec4 v2;
};
QL_CHECK_SIZE(BvhTriangleTexels, 48);

struct BvhInstanceTexels {
  vec4 objectFromWorld0;
  vec4 objectFromWorld1;
  vec4 objectFromWorld2;
  vec4 worldFromObject0;
  vec4 worldFromObject1;
  vec4 worldFromObject2;
  vec4 info;
  vec4 reserved;
};
QL_CHECK_SIZE(BvhInstanceTexels, 128);

QL_FN bool bvhIsLeaf(uint ref) { return (ref & kBvhLeafBit) != 0u; }
QL_FN uint bvhLeafFirst(uint ref) { return (ref & ~kBvhLeafBit) >> kBvhLeafCountBits; }
QL_FN uint bvhLeafCount(uint ref) { return (ref & kBvhLeafCountMask) + 1u; }
QL_FN uint bvhTlasLeafInstance(uint ref) { return ref & ~kBvhLeafBit; }

QL_END

#endif

// Internal to the glTF loader: reads accessors into plain arrays after checking every byte
// they touch lies inside its buffer view and buffer (sparse accessors included), that the
// element type is the expected one, and that float values are finite.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/gltf/gltf_context.h"
#include "engine/scene/scene_asset.h"

namespace qlight::gltf::detail {
using namespace ::qlight::scene;

// Element type: 1 = SCALAR, 2..4 = VEC2..VEC4.
struct FloatAccessorRule {
  int components = 3;
  bool allowNormalizedIntegers = false;  // UNSIGNED_BYTE/SHORT etc. with normalized: true
};

// Returns count * components floats. `use` names the reader in errors ("mesh 0 primitive 1
// POSITION"); failures throw through ctx.
std::vector<float> readFloatAccessor(const tinygltf::Model& model, int accessor,
                                     FloatAccessorRule rule, const std::string& use,
                                     LoadContext& ctx);

// SCALAR UNSIGNED_BYTE/SHORT/INT accessor as uint32 values (not range-checked here).
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessor,
                                        const std::string& use, LoadContext& ctx);

// VECn UNSIGNED_BYTE/SHORT accessor, not normalized (JOINTS_0), as count * n uint32 values.
std::vector<uint32_t> readUnsignedAccessor(const tinygltf::Model& model, int accessor,
                                           int components, const std::string& use,
                                           LoadContext& ctx);

// MAT4 FLOAT accessor (inverseBindMatrices) as count * 16 floats, column-major.
std::vector<float> readMat4Accessor(const tinygltf::Model& model, int accessor,
                                    const std::string& use, LoadContext& ctx);

// Checks an accessor this loader does not read (e.g. COLOR_0) stays inside its buffers.
void checkAccessorBounds(const tinygltf::Model& model, int accessor, const std::string& use,
                         LoadContext& ctx);

// The accessor's element count after checking the index exists.
size_t accessorCount(const tinygltf::Model& model, int accessor, const std::string& use,
                     LoadContext& ctx);

}  // namespace qlight::gltf::detail

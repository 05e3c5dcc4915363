#include "engine/gpu/spirv_reflect.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace qlight::gpu {
namespace {

// The few SPIR-V opcodes, decorations and storage classes the reflection needs.
enum : uint32_t {
  OpName = 5,
  OpExecutionMode = 16,
  OpTypeImage = 25,
  OpTypeSampler = 26,
  OpTypeSampledImage = 27,
  OpTypeArray = 28,
  OpTypeRuntimeArray = 29,
  OpTypeStruct = 30,
  OpTypePointer = 32,
  OpConstant = 43,
  OpVariable = 59,
  OpDecorate = 71,
  OpMemberDecorate = 72,
};
enum : uint32_t {
  DecBlock = 2,
  DecBufferBlock = 3,
  DecNonWritable = 24,
  DecBinding = 33,
  DecSet = 34
};
enum : uint32_t { ScUniformConstant = 0, ScUniform = 2, ScPushConstant = 9, ScStorageBuffer = 12 };
constexpr uint32_t kExecutionModeLocalSize = 17;
constexpr uint32_t kDimBuffer = 5;

struct TypeInfo {
  uint32_t op = 0;
  std::vector<uint32_t> operands;  // words after the result id
};

}  // namespace

const char* descriptorTypeName(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
      return "storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return "storage image";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
      return "sampled image";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
      return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
      return "uniform texel buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
      return "storage texel buffer";
    case VK_DESCRIPTOR_TYPE_SAMPLER:
      return "sampler";
    default:
      return "unknown descriptor";
  }
}

ReflectedShader reflectSpirv(std::span<const uint32_t> words) {
  if (words.size() < 5 || words[0] != 0x07230203u)
    throw std::runtime_error("not a SPIR-V module (bad magic number)");
  ReflectedShader out;
  std::unordered_map<uint32_t, TypeInfo> types;
  std::unordered_map<uint32_t, uint32_t> constants;
  std::unordered_map<uint32_t, std::string> names;
  std::unordered_map<uint32_t, uint32_t> bindingOf, setOf;
  std::unordered_map<uint32_t, bool> isBlock, isBufferBlock, nonWritable;
  std::unordered_map<uint32_t, bool> memberNonWritable, memberWritable;
  struct Var {
    uint32_t id, pointerType, storage;
  };
  std::vector<Var> vars;

  for (size_t i = 5; i < words.size();) {
    uint32_t count = words[i] >> 16, op = words[i] & 0xffffu;
    if (count == 0 || i + count > words.size()) throw std::runtime_error("truncated SPIR-V module");
    const uint32_t* w = &words[i];
    switch (op) {
      case OpName:
        names[w[1]] = reinterpret_cast<const char*>(&w[2]);
        break;
      case OpExecutionMode:
        if (count >= 6 && w[2] == kExecutionModeLocalSize)
          out.localSize[0] = w[3], out.localSize[1] = w[4], out.localSize[2] = w[5];
        break;
      case OpDecorate:
        if (w[2] == DecBinding) bindingOf[w[1]] = w[3];
        if (w[2] == DecSet) setOf[w[1]] = w[3];
        if (w[2] == DecBlock) isBlock[w[1]] = true;
        if (w[2] == DecBufferBlock) isBufferBlock[w[1]] = true;
        if (w[2] == DecNonWritable) nonWritable[w[1]] = true;
        break;
      case OpMemberDecorate:
        if (w[3] == DecNonWritable) memberNonWritable[w[1]] = true;
        break;
      case OpConstant:
        if (count >= 4) constants[w[2]] = w[3];
        break;
      case OpTypeImage:
      case OpTypeSampler:
      case OpTypeSampledImage:
      case OpTypeArray:
      case OpTypeRuntimeArray:
      case OpTypeStruct:
      case OpTypePointer:
        types[w[1]] = TypeInfo{op, std::vector<uint32_t>(w + 2, w + count)};
        break;
      case OpVariable:
        vars.push_back({w[2], w[1], w[3]});
        break;
      default:
        break;
    }
    i += count;
  }

  for (const Var& v : vars) {
    if (v.storage == ScPushConstant) out.hasPushConstants = true;
    if (!bindingOf.count(v.id)) continue;
    ReflectedBinding b;
    b.binding = bindingOf[v.id];
    b.set = setOf.count(v.id) ? setOf[v.id] : 0;
    b.name = names.count(v.id) ? names[v.id] : "";
    b.readOnly = nonWritable.count(v.id) > 0;
    auto pointer = types.find(v.pointerType);
    if (pointer == types.end() || pointer->second.op != OpTypePointer)
      throw std::runtime_error("SPIR-V variable " + b.name + " is not a pointer");
    uint32_t typeId = pointer->second.operands[1];
    // Unwrap arrays of descriptors.
    while (types.count(typeId) &&
           (types[typeId].op == OpTypeArray || types[typeId].op == OpTypeRuntimeArray)) {
      if (types[typeId].op == OpTypeArray) b.count *= constants[types[typeId].operands[1]];
      typeId = types[typeId].operands[0];
    }
    const TypeInfo& t = types[typeId];
    if (v.storage == ScStorageBuffer) {
      b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      b.readOnly = b.readOnly || memberNonWritable.count(typeId);
    } else if (v.storage == ScUniform) {
      b.type = isBufferBlock.count(typeId) ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                           : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      b.readOnly = b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || b.readOnly ||
                   memberNonWritable.count(typeId);
    } else if (t.op == OpTypeSampler) {
      b.type = VK_DESCRIPTOR_TYPE_SAMPLER;
      b.readOnly = true;
    } else if (t.op == OpTypeSampledImage) {
      const TypeInfo& image = types[t.operands[0]];
      b.type = image.operands[1] == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                               : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      b.readOnly = true;
    } else if (t.op == OpTypeImage) {
      // operands: sampled type, dim, depth, arrayed, ms, sampled(1 = sampled, 2 = storage), format
      bool storage = t.operands[5] == 2;
      bool buffer = t.operands[1] == kDimBuffer;
      b.type =
          buffer ? (storage ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                            : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
                 : (storage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
      if (!storage) b.readOnly = true;
    } else {
      throw std::runtime_error("SPIR-V binding " + std::to_string(b.binding) + " (" + b.name +
                               ") has a descriptor type qlight does not handle");
    }
    out.bindings.push_back(b);
  }
  std::sort(out.bindings.begin(), out.bindings.end(), [](auto& a, auto& b) {
    return a.set != b.set ? a.set < b.set : a.binding < b.binding;
  });
  // Aliased views of one buffer (e.g. uint and uint64_t) share a binding: one descriptor.
  std::vector<ReflectedBinding> merged;
  for (const ReflectedBinding& b : out.bindings) {
    if (!merged.empty() && merged.back().set == b.set && merged.back().binding == b.binding) {
      ReflectedBinding& m = merged.back();
      if (m.type != b.type || m.count != b.count)
        throw std::runtime_error("SPIR-V binding " + std::to_string(b.binding) + " (" + m.name +
                                 ", " + b.name +
                                 ") is declared with two descriptor types or counts");
      m.readOnly = m.readOnly && b.readOnly;
      continue;
    }
    merged.push_back(b);
  }
  out.bindings = std::move(merged);
  return out;
}

}  // namespace qlight::gpu

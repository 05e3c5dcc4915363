#include "engine/gltf/gltf_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace qlight::gltf::detail {
namespace {

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;  // INT and DOUBLE are not glTF 2.0 accessor types
  }
}

int componentsInType(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;  // matrices: never read by this loader
  }
}

const char* typeName(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    default:
      return "VEC4";
  }
}

double readComponent(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? v / 4294967295.0 : v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// Where an accessor's (or a sparse block's) elements lie, after the bounds checks.
struct ElementRange {
  const uint8_t* base = nullptr;  // null: no buffer view, elements are zero
  size_t stride = 0;
};

ElementRange locateElements(const tinygltf::Model& model, int viewIndex, uint64_t byteOffset,
                            uint64_t elementSize, uint64_t count, bool allowStride,
                            const std::string& owner, LoadContext& ctx) {
  if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
    ctx.fail(owner + " refers to buffer view " + std::to_string(viewIndex) +
             ", which does not exist (" + std::to_string(model.bufferViews.size()) +
             " buffer views)");
  const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    ctx.fail("buffer view " + std::to_string(viewIndex) + " refers to buffer " +
             std::to_string(view.buffer) + ", which does not exist");
  const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
  const uint64_t bufferSize = buffer.data.size();
  if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset)
    ctx.fail("buffer view " + std::to_string(viewIndex) + " reads past the end of buffer " +
             std::to_string(view.buffer));

  uint64_t stride = elementSize;
  if (allowStride && view.byteStride != 0) {
    if (view.byteStride < elementSize)
      ctx.fail(owner + " elements (" + std::to_string(elementSize) +
               " bytes) are larger than the byteStride " + std::to_string(view.byteStride) +
               " of buffer view " + std::to_string(viewIndex));
    stride = view.byteStride;
  }
  // Every quantity is below 2^32 * 2^8 or checked first, so 128-bit arithmetic cannot wrap.
  const unsigned __int128 end =
      (unsigned __int128)byteOffset + (unsigned __int128)stride * (count - 1) + elementSize;
  if (end > view.byteLength)
    ctx.fail(owner + " reads past the end of buffer view " + std::to_string(viewIndex) +
             " of buffer " + std::to_string(view.buffer) + " (needs " +
             std::to_string(uint64_t(std::min<unsigned __int128>(end, UINT64_MAX))) +
             " bytes, the view has " + std::to_string(view.byteLength) + ")");
  return {buffer.data.data() + view.byteOffset + byteOffset, size_t(stride)};
}

const tinygltf::Accessor& checkedAccessor(const tinygltf::Model& model, int index,
                                          const std::string& use, LoadContext& ctx) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    ctx.fail(use + ": accessor " + std::to_string(index) + " does not exist (" +
             std::to_string(model.accessors.size()) + " accessors)");
  return model.accessors[size_t(index)];
}

// Reads all components as doubles into `out` (count * components), with sparse substitution.
// `convert` turns each raw component into the stored value and may reject it.
template <typename T, typename Convert>
std::vector<T> readElements(const tinygltf::Model& model, int index, int components,
                            Convert convert, LoadContext& ctx) {
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const std::string owner = "accessor " + std::to_string(index);
  const int compSize = componentSize(a.componentType);
  const uint64_t elementSize = uint64_t(compSize) * components;
  // Bounds first: the output is only allocated once the data is known to be there.
  ElementRange range;
  if (a.bufferView >= 0) {
    range =
        locateElements(model, a.bufferView, a.byteOffset, elementSize, a.count, true, owner, ctx);
  } else if (!a.sparse.isSparse) {
    ctx.fail(owner + " has neither a buffer view nor sparse values");
  } else if (a.count > (size_t(1) << 24)) {
    ctx.fail(owner + " has no buffer view and count " + std::to_string(a.count) +
             " (too large for zeros)");
  }
  std::vector<T> out(a.count * components, T(0));

  auto readElement = [&](const uint8_t* p, size_t element) {
    for (int c = 0; c < components; ++c) {
      const double raw = readComponent(p + size_t(c) * compSize, a.componentType, a.normalized);
      out[element * components + c] = convert(raw, element);
    }
  };

  if (range.base != nullptr) {
    for (size_t i = 0; i < a.count; ++i) readElement(range.base + i * range.stride, i);
  }

  if (a.sparse.isSparse) {
    const std::string sparse = owner + " sparse";
    if (a.sparse.count < 1 || size_t(a.sparse.count) > a.count)
      ctx.fail(sparse + " count " + std::to_string(a.sparse.count) + " is not in [1, " +
               std::to_string(a.count) + "]");
    const int indexType = a.sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      ctx.fail(sparse + " indices have component type " + std::to_string(indexType));
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
      ctx.fail(sparse + " has a negative byteOffset");
    const uint64_t n = uint64_t(a.sparse.count);
    const ElementRange indices =
        locateElements(model, a.sparse.indices.bufferView, uint64_t(a.sparse.indices.byteOffset),
                       uint64_t(componentSize(indexType)), n, false, sparse + " indices", ctx);
    const ElementRange values =
        locateElements(model, a.sparse.values.bufferView, uint64_t(a.sparse.values.byteOffset),
                       elementSize, n, false, sparse + " values", ctx);
    int64_t previous = -1;
    for (size_t i = 0; i < n; ++i) {
      const auto target =
          int64_t(readComponent(indices.base + i * indices.stride, indexType, false));
      if (target <= previous || uint64_t(target) >= a.count)
        ctx.fail(sparse + " index " + std::to_string(target) +
                 " is out of range or not increasing (count " + std::to_string(a.count) + ")");
      previous = target;
      readElement(values.base + i * values.stride, size_t(target));
    }
  }
  return out;
}

void checkCount(const tinygltf::Accessor& a, int index, LoadContext& ctx) {
  if (a.count == 0) ctx.fail("accessor " + std::to_string(index) + " has count 0");
  if (a.count > (size_t(1) << 31))
    ctx.fail("accessor " + std::to_string(index) + " count " + std::to_string(a.count) +
             " is too large");
}

}  // namespace

void checkAccessorBounds(const tinygltf::Model& model, int index, const std::string& use,
                         LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, index, use, ctx);
  checkCount(a, index, ctx);
  const int compSize = componentSize(a.componentType);
  int columns = 0, rows = 0;  // matrix columns start on 4-byte boundaries
  if (a.type == TINYGLTF_TYPE_MAT2) columns = rows = 2;
  if (a.type == TINYGLTF_TYPE_MAT3) columns = rows = 3;
  if (a.type == TINYGLTF_TYPE_MAT4) columns = rows = 4;
  const uint64_t elementSize = columns > 0
                                   ? uint64_t(columns) * ((uint64_t(rows) * compSize + 3) / 4 * 4)
                                   : uint64_t(componentsInType(a.type)) * compSize;
  if (elementSize == 0)
    ctx.fail(use + ": accessor " + std::to_string(index) + " has an invalid type");
  if (a.bufferView >= 0)
    locateElements(model, a.bufferView, a.byteOffset, elementSize, a.count, true,
                   "accessor " + std::to_string(index), ctx);
}

size_t accessorCount(const tinygltf::Model& model, int accessor, const std::string& use,
                     LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, accessor, use, ctx);
  checkCount(a, accessor, ctx);
  return a.count;
}

namespace {
// The element converter of float accessors: a value that is not finite fails the load.
auto finiteFloats(int index, LoadContext& ctx) {
  return [index, &ctx](double v, size_t element) {
    if (!std::isfinite(v))
      ctx.fail("accessor " + std::to_string(index) +
               " holds a non-finite value (NaN or Inf) at element " + std::to_string(element));
    return float(v);
  };
}
}  // namespace

std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index,
                                     FloatAccessorRule rule, const std::string& use,
                                     LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, index, use, ctx);
  const std::string owner = use + ": accessor " + std::to_string(index);
  checkCount(a, index, ctx);
  if (componentsInType(a.type) != rule.components)
    ctx.fail(owner + " must be " + typeName(rule.components));
  if (componentSize(a.componentType) == 0)
    ctx.fail(owner + " has invalid component type " + std::to_string(a.componentType));
  const bool isFloat = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (!isFloat && !(rule.allowNormalizedIntegers && a.normalized))
    ctx.fail(owner + (rule.allowNormalizedIntegers ? " must be FLOAT or a normalized integer"
                                                   : " must be FLOAT"));
  return readElements<float>(model, index, rule.components, finiteFloats(index, ctx), ctx);
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                        const std::string& use, LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, index, use, ctx);
  const std::string owner = use + ": accessor " + std::to_string(index);
  checkCount(a, index, ctx);
  if (a.type != TINYGLTF_TYPE_SCALAR) ctx.fail(owner + " (indices) must be SCALAR");
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    ctx.fail(owner + " (indices) must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  if (a.normalized) ctx.fail(owner + " (indices) must not be normalized");
  return readElements<uint32_t>(
      model, index, 1, [](double v, size_t) { return uint32_t(v); }, ctx);
}

std::vector<uint32_t> readUnsignedAccessor(const tinygltf::Model& model, int index, int components,
                                           const std::string& use, LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, index, use, ctx);
  const std::string owner = use + ": accessor " + std::to_string(index);
  checkCount(a, index, ctx);
  if (componentsInType(a.type) != components) ctx.fail(owner + " must be " + typeName(components));
  if ((a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
       a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
      a.normalized)
    ctx.fail(owner + " must be UNSIGNED_BYTE or UNSIGNED_SHORT, not normalized");
  return readElements<uint32_t>(
      model, index, components, [](double v, size_t) { return uint32_t(v); }, ctx);
}

std::vector<float> readMat4Accessor(const tinygltf::Model& model, int index, const std::string& use,
                                    LoadContext& ctx) {
  const tinygltf::Accessor& a = checkedAccessor(model, index, use, ctx);
  const std::string owner = use + ": accessor " + std::to_string(index);
  checkCount(a, index, ctx);
  if (a.type != TINYGLTF_TYPE_MAT4 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    ctx.fail(owner + " must be a MAT4 of FLOAT");
  return readElements<float>(model, index, 16, finiteFloats(index, ctx), ctx);
}

}  // namespace qlight::gltf::detail

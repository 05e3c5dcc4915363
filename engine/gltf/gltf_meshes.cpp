// glTF meshes into MeshAsset: triangle primitives concatenated, strips and fans turned into
// lists, flat normals where the file has none, morph targets applied at the default weights
// (and kept, with the skin attributes, for animation: gltf_mesh_deform.cpp).
#include <cmath>
#include <map>
#include <numeric>

#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_convert.h"
#include "engine/gltf/gltf_primitive.h"

namespace qlight::gltf::detail {
namespace {

std::vector<glm::vec3> toVec3(const std::vector<float>& f) {
  std::vector<glm::vec3> out(f.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
  return out;
}

// The accessor's floats, checked to hold vertexCount elements (0: any count, for POSITION).
std::vector<float> readSized(const tinygltf::Model& model, int accessor, FloatAccessorRule rule,
                             size_t vertexCount, const std::string& use, LoadContext& ctx) {
  std::vector<float> values = readFloatAccessor(model, accessor, rule, use, ctx);
  if (vertexCount != 0 && values.size() / size_t(rule.components) != vertexCount)
    ctx.fail(use + " has " + std::to_string(values.size() / size_t(rule.components)) +
             " elements but POSITION has " + std::to_string(vertexCount));
  return values;
}

std::vector<glm::vec3> readVec3Attribute(const tinygltf::Model& model, int accessor,
                                         size_t vertexCount, const std::string& use,
                                         LoadContext& ctx) {
  return toVec3(readSized(model, accessor, {3, false}, vertexCount, use, ctx));
}

std::vector<glm::vec2> readUvAttribute(const tinygltf::Model& model, int accessor,
                                       size_t vertexCount, const std::string& use,
                                       LoadContext& ctx) {
  const std::vector<float> f = readSized(model, accessor, {2, true}, vertexCount, use, ctx);
  std::vector<glm::vec2> out(vertexCount);
  for (size_t i = 0; i < vertexCount; ++i) out[i] = {f[2 * i], f[2 * i + 1]};
  return out;
}

// COLOR_0: VEC3 or VEC4, float or normalized integers; RGB gets alpha 1.
std::vector<glm::vec4> readColorAttribute(const tinygltf::Model& model, int accessor,
                                          size_t vertexCount, const std::string& use,
                                          LoadContext& ctx) {
  accessorCount(model, accessor, use, ctx);
  const int n = model.accessors[size_t(accessor)].type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  const std::vector<float> f = readSized(model, accessor, {n, true}, vertexCount, use, ctx);
  std::vector<glm::vec4> out(vertexCount, glm::vec4(1.0f));
  for (size_t i = 0; i < vertexCount; ++i)
    for (int c = 0; c < n; ++c) out[i][c] = f[size_t(n) * i + size_t(c)];
  return out;
}

// TANGENT: VEC4 floats, xyz the tangent, w the bitangent's sign.
std::vector<glm::vec4> readTangentAttribute(const tinygltf::Model& model, int accessor,
                                            size_t vertexCount, const std::string& use,
                                            LoadContext& ctx) {
  const std::vector<float> f = readSized(model, accessor, {4, false}, vertexCount, use, ctx);
  std::vector<glm::vec4> out(vertexCount);
  for (size_t i = 0; i < vertexCount; ++i)
    out[i] = {f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3] < 0.0f ? -1.0f : 1.0f};
  return out;
}

// Appends a primitive's optional attribute to the mesh's, keeping it either empty or one
// per vertex: the side that lacks it gets `fill`.
template <class T>
void appendOptional(std::vector<T>& mesh, size_t meshVertices, const std::vector<T>& prim,
                    size_t primVertices, T fill) {
  if (mesh.empty() && prim.empty()) return;
  mesh.resize(meshVertices, fill);
  if (prim.empty())
    mesh.insert(mesh.end(), primVertices, fill);
  else
    mesh.insert(mesh.end(), prim.begin(), prim.end());
}

glm::vec3 faceNormal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float len = glm::length(n);
  return len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Vertex order of each triangle for the primitive's mode (glTF spec 3.7.2.1).
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& v, int mode,
                                  const std::string& owner, LoadContext& ctx) {
  std::vector<uint32_t> out;
  const size_t n = v.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (n % 3 != 0)
      ctx.warn(owner + " has " + std::to_string(n) +
               " indices, not a multiple of 3; the rest is dropped");
    out.assign(v.begin(), v.begin() + long(n / 3 * 3));
  } else if (n >= 3) {
    out.reserve((n - 2) * 3);
    for (size_t i = 0; i + 2 < n; ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        const size_t odd = i % 2;
        out.insert(out.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
      } else {  // fan
        out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
      }
    }
  }
  return out;
}

// Unit normals; a zero-length one is replaced by the area-weighted normal of its faces.
void normalizeNormals(PrimitiveData& data) {
  std::vector<glm::vec3> faceSum;
  for (size_t i = 0; i < data.normals.size(); ++i) {
    const float len = glm::length(data.normals[i]);
    if (len > 1e-12f && std::isfinite(len)) {
      data.normals[i] /= len;
      continue;
    }
    if (faceSum.empty()) {
      faceSum.assign(data.positions.size(), glm::vec3(0.0f));
      for (size_t t = 0; t + 2 < data.triangles.size(); t += 3) {
        const uint32_t a = data.triangles[t], b = data.triangles[t + 1], c = data.triangles[t + 2];
        const glm::vec3 n = glm::cross(data.positions[b] - data.positions[a],
                                       data.positions[c] - data.positions[a]);
        faceSum[a] += n;
        faceSum[b] += n;
        faceSum[c] += n;
      }
    }
    const float sumLen = glm::length(faceSum[i]);
    data.normals[i] = sumLen > 0.0f ? faceSum[i] / sumLen : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

// Without normals in the file, each triangle gets its own three vertices and its face normal.
void makeFlat(PrimitiveData& data) {
  PrimitiveData flat;
  const size_t count = data.triangles.size();
  flat.deform = std::move(data.deform);
  reorderDeform(flat.deform, data.triangles);
  flat.positions.reserve(count);
  flat.normals.reserve(count);
  flat.uv0.reserve(count);
  for (size_t t = 0; t < count; t += 3) {
    const uint32_t v[3] = {data.triangles[t], data.triangles[t + 1], data.triangles[t + 2]};
    const glm::vec3 n =
        faceNormal(data.positions[v[0]], data.positions[v[1]], data.positions[v[2]]);
    for (uint32_t k : v) {
      flat.triangles.push_back(uint32_t(flat.positions.size()));
      flat.positions.push_back(data.positions[k]);
      flat.normals.push_back(n);
      flat.uv0.push_back(data.uv0[k]);
      if (!data.uv1.empty()) flat.uv1.push_back(data.uv1[k]);
      if (!data.colors.empty()) flat.colors.push_back(data.colors[k]);
      if (!data.tangents.empty()) flat.tangents.push_back(data.tangents[k]);
    }
  }
  data = std::move(flat);
}

struct VertexKey {
  int position, normal, uv, uv1, color, tangent, joints, weights;
  friend auto operator<=>(const VertexKey&, const VertexKey&) = default;
};

int attributeOf(const tinygltf::Primitive& prim, const char* name) {
  auto it = prim.attributes.find(name);
  return it == prim.attributes.end() ? -1 : it->second;
}

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    default:
      return "an unknown mode";
  }
}

}  // namespace

void convertMeshes(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  const uint32_t defaultMaterial = uint32_t(model.materials.size());
  bool defaultUsed = false;

  for (size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& mesh = model.meshes[m];
    MeshAsset out;
    out.name = mesh.name;
    std::map<VertexKey, uint32_t> sharedVertices;  // first vertex of each loaded vertex set
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      const std::string owner = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ctx.warn(owner + " is " + modeName(mode) + ", not triangles; skipped");
        continue;
      }
      auto positionIt = prim.attributes.find("POSITION");
      if (positionIt == prim.attributes.end()) {
        ctx.warn(owner + " has no POSITION; skipped");
        continue;
      }

      PrimitiveData data;
      data.positions = readVec3Attribute(model, positionIt->second, 0, owner + " POSITION", ctx);
      const size_t vertexCount = data.positions.size();
      for (const auto& [name, accessor] : prim.attributes) {
        const std::string use = owner + " " + name;
        if (name == "NORMAL") {
          data.normals = readVec3Attribute(model, accessor, vertexCount, use, ctx);
        } else if (name == "TEXCOORD_0") {
          data.uv0 = readUvAttribute(model, accessor, vertexCount, use, ctx);
        } else if (name == "TEXCOORD_1") {
          data.uv1 = readUvAttribute(model, accessor, vertexCount, use, ctx);
        } else if (name == "COLOR_0") {
          data.colors = readColorAttribute(model, accessor, vertexCount, use, ctx);
        } else if (name == "TANGENT") {
          data.tangents = readTangentAttribute(model, accessor, vertexCount, use, ctx);
        } else if (name != "POSITION" && !isSkinAttribute(name)) {
          checkAccessorBounds(model, accessor, use, ctx);
        }
      }
      if (data.uv0.empty()) data.uv0.assign(vertexCount, glm::vec2(0.0f));
      readSkinAttributes(model, prim, owner, data, ctx);
      readMorphTargets(model, mesh, prim, owner, data, ctx);

      std::vector<uint32_t> order;
      if (prim.indices >= 0) {
        order = readIndexAccessor(model, prim.indices, owner + " indices", ctx);
        for (size_t i = 0; i < order.size(); ++i)
          if (order[i] >= vertexCount)
            ctx.fail(owner + " index " + std::to_string(order[i]) + " at position " +
                     std::to_string(i) + " is out of range (" + std::to_string(vertexCount) +
                     " vertices)");
      } else {
        order.resize(vertexCount);
        std::iota(order.begin(), order.end(), 0u);
      }
      data.triangles = triangulate(order, mode, owner, ctx);
      if (data.triangles.empty()) {
        ctx.warn(owner + " has no triangles; skipped");
        continue;
      }

      uint32_t material = defaultMaterial;
      if (prim.material >= 0) {
        if (size_t(prim.material) >= model.materials.size())
          ctx.fail(owner + " uses material " + std::to_string(prim.material) +
                   ", which does not exist (" + std::to_string(model.materials.size()) +
                   " materials)");
        material = uint32_t(prim.material);
      } else {
        defaultUsed = true;
      }

      // Primitives that share their vertex accessors (a common exporter layout: one vertex
      // set, one index range per material) share their vertices here too.
      const VertexKey key{attributeOf(prim, "POSITION"),   attributeOf(prim, "NORMAL"),
                          attributeOf(prim, "TEXCOORD_0"), attributeOf(prim, "TEXCOORD_1"),
                          attributeOf(prim, "COLOR_0"),    attributeOf(prim, "TANGENT"),
                          attributeOf(prim, "JOINTS_0"),   attributeOf(prim, "WEIGHTS_0")};
      const bool shareable = key.normal >= 0 && prim.targets.empty();
      auto shared = shareable ? sharedVertices.find(key) : sharedVertices.end();
      uint32_t base;
      if (shared != sharedVertices.end()) {
        base = shared->second;
      } else {
        if (data.normals.empty()) {
          makeFlat(data);
          for (size_t t = 0; t < data.triangles.size() / 3; ++t)
            out.deform.flatTriangles.push_back(uint32_t(out.indices.size() / 3 + t));
        } else {
          normalizeNormals(data);
        }
        base = uint32_t(out.positions.size());
        const size_t added = data.positions.size();
        appendOptional(out.uv1, base, data.uv1, added, glm::vec2(0.0f));
        appendOptional(out.colors, base, data.colors, added, glm::vec4(1.0f));
        appendOptional(out.tangents, base, data.tangents, added, glm::vec4(0.0f));
        out.positions.insert(out.positions.end(), data.positions.begin(), data.positions.end());
        out.normals.insert(out.normals.end(), data.normals.begin(), data.normals.end());
        out.uv0.insert(out.uv0.end(), data.uv0.begin(), data.uv0.end());
        appendDeform(out, data.deform, base);
        if (shareable) sharedVertices.emplace(key, base);
      }
      for (uint32_t v : data.triangles) out.indices.push_back(base + v);
      out.triangleMaterials.insert(out.triangleMaterials.end(), data.triangles.size() / 3,
                                   material);
    }
    finishDeform(out, mesh, "mesh " + std::to_string(m), ctx);
    if (out.positions.empty()) {
      ctx.warn("mesh " + std::to_string(m) + " has no triangle primitives");
    } else {
      out.boundsMin = out.boundsMax = out.positions[0];
      for (const glm::vec3& p : out.positions) {
        out.boundsMin = glm::min(out.boundsMin, p);
        out.boundsMax = glm::max(out.boundsMax, p);
      }
    }
    scene.meshes.push_back(std::move(out));
  }

  if (defaultUsed) {
    scene.defaultMaterial = int32_t(defaultMaterial);
    MaterialAsset fallback;  // glTF's defaults: baseColor 1, metallic 1, roughness 1
    fallback.name = "glTF default material";
    scene.materials.push_back(fallback);
  }
}

}  // namespace qlight::gltf::detail

// What deforms a glTF mesh: skin attributes and morph targets, read per primitive and joined
// per mesh (engine/scene/deform.h applies them).
#include <algorithm>

#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_primitive.h"

namespace qlight::gltf::detail {
namespace {

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor, size_t vertexCount,
                                const std::string& use, LoadContext& ctx) {
  const std::vector<float> f = readFloatAccessor(model, accessor, {3, false}, use, ctx);
  if (f.size() / 3 != vertexCount)
    ctx.fail(use + " has " + std::to_string(f.size() / 3) + " elements but POSITION has " +
             std::to_string(vertexCount));
  std::vector<glm::vec3> out(vertexCount);
  for (size_t i = 0; i < vertexCount; ++i) out[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
  return out;
}

template <typename T>
void reorder(std::vector<T>& values, const std::vector<uint32_t>& order) {
  if (values.empty()) return;
  std::vector<T> out(order.size());
  for (size_t i = 0; i < order.size(); ++i) out[i] = values[order[i]];
  values = std::move(out);
}

// Pads `values` up to `count` with `fill(i)` for each missing index i.
template <typename T, typename Fill>
void padTo(std::vector<T>& values, size_t count, Fill fill) {
  values.reserve(count);
  for (size_t i = values.size(); i < count; ++i) values.push_back(fill(i));
}

template <typename T>
void padTo(std::vector<T>& values, size_t count) {
  padTo(values, count, [](size_t) { return T(0); });
}

}  // namespace

bool isSkinAttribute(const std::string& name) {
  return name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0;
}

void readSkinAttributes(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                        const std::string& owner, PrimitiveData& data, LoadContext& ctx) {
  int joints = -1, weights = -1;
  for (const auto& [name, accessor] : prim.attributes) {
    if (!isSkinAttribute(name)) continue;
    if (name == "JOINTS_0") {
      joints = accessor;
    } else if (name == "WEIGHTS_0") {
      weights = accessor;
    } else {
      checkAccessorBounds(model, accessor, owner + " " + name, ctx);
      ctx.warn(owner + " has more than 4 joint influences (" + name +
               "); only JOINTS_0/WEIGHTS_0 are used, renormalized");
    }
  }
  if (joints < 0 && weights < 0) return;
  if (joints < 0 || weights < 0)
    ctx.fail(owner + " has " +
             (joints < 0 ? "WEIGHTS_0 without JOINTS_0" : "JOINTS_0 without WEIGHTS_0"));
  const size_t n = data.positions.size();
  const std::vector<uint32_t> j = readUnsignedAccessor(model, joints, 4, owner + " JOINTS_0", ctx);
  const std::vector<float> w =
      readFloatAccessor(model, weights, {4, true}, owner + " WEIGHTS_0", ctx);
  if (j.size() / 4 != n || w.size() / 4 != n)
    ctx.fail(owner + " JOINTS_0/WEIGHTS_0 have " + std::to_string(j.size() / 4) + "/" +
             std::to_string(w.size() / 4) + " elements but POSITION has " + std::to_string(n));
  data.deform.joints.resize(n);
  data.deform.weights.resize(n);
  for (size_t i = 0; i < n; ++i) {
    data.deform.joints[i] = {j[4 * i], j[4 * i + 1], j[4 * i + 2], j[4 * i + 3]};
    data.deform.weights[i] = {w[4 * i], w[4 * i + 1], w[4 * i + 2], w[4 * i + 3]};
  }
}

void readMorphTargets(const tinygltf::Model& model, const tinygltf::Mesh& mesh,
                      const tinygltf::Primitive& prim, const std::string& owner,
                      PrimitiveData& data, LoadContext& ctx) {
  if (prim.targets.empty()) return;
  if (!mesh.weights.empty() && mesh.weights.size() != prim.targets.size())
    ctx.fail(owner + " has " + std::to_string(prim.targets.size()) +
             " morph targets but the mesh has " + std::to_string(mesh.weights.size()) + " weights");
  PrimitiveDeform& d = data.deform;
  d.basePositions = data.positions;
  d.baseNormals = data.normals;
  d.targetPositions.assign(prim.targets.size(), {});
  d.targetNormals.assign(prim.targets.size(), {});
  const size_t n = data.positions.size();
  for (size_t t = 0; t < prim.targets.size(); ++t) {
    const double weight = mesh.weights.empty() ? 0.0 : mesh.weights[t];
    ctx.requireFinite(weight, owner + " morph weight");
    const std::string use = owner + " target " + std::to_string(t);
    for (const auto& [name, accessor] : prim.targets[t]) {
      if (name != "POSITION" && name != "NORMAL") {
        checkAccessorBounds(model, accessor, use + " " + name, ctx);
        // TANGENT targets follow tangents, which meshes do not carry yet: nothing to move.
        if (name != "TANGENT")
          ctx.warn(use + " moves " + name + ", which morphing does not support; ignored");
        continue;
      }
      std::vector<glm::vec3> deltas = readVec3(model, accessor, n, use + " " + name, ctx);
      const bool position = name == "POSITION";
      std::vector<glm::vec3>& pose = position ? data.positions : data.normals;
      if (!position && pose.empty()) continue;  // normals are generated flat later
      for (size_t i = 0; i < n; ++i) pose[i] += float(weight) * deltas[i];
      (position ? d.targetPositions : d.targetNormals)[t] = std::move(deltas);
    }
    if (d.targetPositions[t].empty()) d.targetPositions[t].assign(n, glm::vec3(0.0f));
  }
}

void reorderDeform(PrimitiveDeform& d, const std::vector<uint32_t>& order) {
  reorder(d.joints, order);
  reorder(d.weights, order);
  reorder(d.basePositions, order);
  reorder(d.baseNormals, order);
  for (auto& t : d.targetPositions) reorder(t, order);
  for (auto& t : d.targetNormals) reorder(t, order);
}

void appendDeform(MeshAsset& mesh, const PrimitiveDeform& p, size_t firstVertex) {
  MeshDeformation& d = mesh.deform;
  if (!p.joints.empty()) {
    padTo(d.joints, firstVertex);
    padTo(d.weights, firstVertex);
    d.joints.insert(d.joints.end(), p.joints.begin(), p.joints.end());
    d.weights.insert(d.weights.end(), p.weights.begin(), p.weights.end());
  }
  if (p.targetPositions.empty()) return;
  padTo(d.basePositions, firstVertex, [&](size_t i) { return mesh.positions[i]; });
  padTo(d.baseNormals, firstVertex, [&](size_t i) { return mesh.normals[i]; });
  d.basePositions.insert(d.basePositions.end(), p.basePositions.begin(), p.basePositions.end());
  d.baseNormals.insert(d.baseNormals.end(), p.baseNormals.begin(), p.baseNormals.end());
  if (d.targets.size() < p.targetPositions.size()) d.targets.resize(p.targetPositions.size());
  for (size_t t = 0; t < p.targetPositions.size(); ++t) {
    MorphTarget& target = d.targets[t];
    padTo(target.positions, firstVertex);
    target.positions.insert(target.positions.end(), p.targetPositions[t].begin(),
                            p.targetPositions[t].end());
    if (!p.targetNormals[t].empty()) {
      padTo(target.normals, firstVertex);
      target.normals.insert(target.normals.end(), p.targetNormals[t].begin(),
                            p.targetNormals[t].end());
    }
  }
}

void finishDeform(MeshAsset& mesh, const tinygltf::Mesh& source, const std::string& owner,
                  LoadContext& ctx) {
  MeshDeformation& d = mesh.deform;
  const size_t n = mesh.positions.size();
  if (d.morphed()) {
    padTo(d.basePositions, n, [&](size_t i) { return mesh.positions[i]; });
    padTo(d.baseNormals, n, [&](size_t i) { return mesh.normals[i]; });
    for (MorphTarget& t : d.targets) {
      padTo(t.positions, n);
      if (!t.normals.empty()) padTo(t.normals, n);
    }
    d.defaultWeights.assign(d.targets.size(), 0.0f);
    for (size_t t = 0; t < d.targets.size() && t < source.weights.size(); ++t)
      d.defaultWeights[t] = float(source.weights[t]);
  }
  if (d.skinnable()) {
    padTo(d.joints, n);
    padTo(d.weights, n);
    bool unweighted = false;
    for (glm::vec4& w : d.weights) {
      w = glm::max(w, glm::vec4(0.0f));
      const float sum = w.x + w.y + w.z + w.w;
      unweighted = unweighted || !(sum > 0.0f);
      w = sum > 0.0f ? w / sum : glm::vec4(0.0f);
    }
    if (unweighted)
      ctx.warn(owner + " has vertices whose joint weights are all 0; the skin leaves them unmoved");
  }
  if (!d.morphed() && !d.skinnable()) d.flatTriangles.clear();
}

}  // namespace qlight::gltf::detail

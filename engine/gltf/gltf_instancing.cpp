// EXT_mesh_gpu_instancing: a node's TRANSLATION/ROTATION/SCALE accessors become the node's
// instance transforms (each one an instance of the mesh's one bottom-level BVH).
#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_convert.h"

namespace qlight::gltf::detail {
namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

int attributeAccessor(const tinygltf::Value& attributes, const char* name, const std::string& owner,
                      LoadContext& ctx) {
  if (!attributes.Has(name)) return -1;
  const tinygltf::Value& v = attributes.Get(name);
  if (!v.IsNumber()) ctx.fail(owner + " " + kExtension + " " + name + " is not an accessor index");
  const double index = v.GetNumberAsDouble();
  if (!(index >= 0.0 && index < double(1u << 30)) || index != double(int(index)))
    ctx.fail(owner + " " + kExtension + " " + name + " is not an accessor index");
  return int(index);
}

}  // namespace

void convertMeshInstancing(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    auto it = model.nodes[i].extensions.find(kExtension);
    if (it == model.nodes[i].extensions.end()) continue;
    const std::string owner = "node " + std::to_string(i);
    NodeAsset& node = scene.nodes[i];
    if (!it->second.IsObject() || !it->second.Has("attributes") ||
        !it->second.Get("attributes").IsObject())
      ctx.fail(owner + " " + kExtension + " has no attributes object");
    const tinygltf::Value& attributes = it->second.Get("attributes");
    const int translation = attributeAccessor(attributes, "TRANSLATION", owner, ctx);
    const int rotation = attributeAccessor(attributes, "ROTATION", owner, ctx);
    const int scale = attributeAccessor(attributes, "SCALE", owner, ctx);
    if (node.mesh < 0) {
      ctx.warn(owner + " has " + kExtension + " but no mesh; ignored");
      continue;
    }
    if (node.skin >= 0) {
      ctx.warn(owner + " is skinned; its " + kExtension + " instances are ignored");
      continue;
    }
    size_t count = 0;
    for (int a : {translation, rotation, scale}) {
      if (a < 0) continue;
      const size_t n = accessorCount(model, a, owner + " " + kExtension, ctx);
      if (count != 0 && n != count)
        ctx.fail(owner + " " + kExtension + " attributes have different counts (" +
                 std::to_string(count) + " and " + std::to_string(n) + ")");
      count = n;
    }
    if (count == 0) {
      ctx.warn(owner + " " + kExtension + " has no TRANSLATION, ROTATION or SCALE; ignored");
      continue;
    }
    node.instances.assign(count, LocalTransform{});
    const std::string use = owner + " " + kExtension;
    if (translation >= 0) {
      const std::vector<float> t =
          readFloatAccessor(model, translation, {3, false}, use + " TRANSLATION", ctx);
      for (size_t k = 0; k < count; ++k)
        node.instances[k].translation = {t[3 * k], t[3 * k + 1], t[3 * k + 2]};
    }
    if (rotation >= 0) {
      const std::vector<float> r =
          readFloatAccessor(model, rotation, {4, true}, use + " ROTATION", ctx);
      for (size_t k = 0; k < count; ++k) {
        const glm::quat q(r[4 * k + 3], r[4 * k], r[4 * k + 1], r[4 * k + 2]);
        node.instances[k].rotation =
            glm::length(q) > 1e-6f ? glm::normalize(q) : glm::quat(1, 0, 0, 0);
      }
    }
    if (scale >= 0) {
      const std::vector<float> s = readFloatAccessor(model, scale, {3, false}, use + " SCALE", ctx);
      for (size_t k = 0; k < count; ++k)
        node.instances[k].scale = {s[3 * k], s[3 * k + 1], s[3 * k + 2]};
    }
  }
}

}  // namespace qlight::gltf::detail

// glTF nodes (hierarchy, transforms), the shown scene's roots, cameras and punctual lights.
#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "engine/gltf/gltf_convert.h"
#include "engine/scene/transforms.h"

namespace qlight::gltf::detail {
namespace {

constexpr float kHalfPi = 1.57079632679f;

LocalTransform nodeTransform(const tinygltf::Node& node, const std::string& owner,
                             LoadContext& ctx) {
  ctx.requireFiniteAll(node.matrix, owner + " matrix");
  ctx.requireFiniteAll(node.translation, owner + " translation");
  ctx.requireFiniteAll(node.rotation, owner + " rotation");
  ctx.requireFiniteAll(node.scale, owner + " scale");
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) ctx.fail(owner + " matrix needs 16 numbers");
    if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
      ctx.warn(owner + " has both a matrix and TRS; the matrix is used");
    glm::dmat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));  // column-major
    return decompose(glm::mat4(m));
  }
  LocalTransform local;
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) ctx.fail(owner + " translation needs 3 numbers");
    local.translation = {node.translation[0], node.translation[1], node.translation[2]};
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) ctx.fail(owner + " rotation needs 4 numbers");
    const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                      float(node.rotation[2]));
    if (glm::length(q) < 1e-6f) {
      ctx.warn(owner + " rotation is a zero quaternion; identity used");
    } else {
      local.rotation = glm::normalize(q);
    }
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) ctx.fail(owner + " scale needs 3 numbers");
    local.scale = {node.scale[0], node.scale[1], node.scale[2]};
  }
  return local;
}

int32_t checkedIndex(int index, size_t count, const std::string& owner, const char* what,
                     LoadContext& ctx) {
  if (index < 0) return -1;
  if (size_t(index) >= count)
    ctx.fail(owner + " uses " + what + " " + std::to_string(index) + ", which does not exist (" +
             std::to_string(count) + ")");
  return index;
}

int nodeLight(const tinygltf::Node& node, const std::string& owner, LoadContext& ctx) {
  auto it = node.extensions.find("KHR_lights_punctual");
  if (it == node.extensions.end()) return -1;
  if (!it->second.IsObject() || !it->second.Has("light") || !it->second.Get("light").IsNumber())
    ctx.fail(owner + " KHR_lights_punctual has no light index");
  const double light = it->second.Get("light").GetNumberAsDouble();
  if (!(light >= 0.0 && light < 1e9)) ctx.fail(owner + " light index is invalid");
  return int(light);
}

// Roots of the scene shown: `scene`, else scenes[0], else every parentless node.
void chooseRoots(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  int shown = model.defaultScene;
  if (shown >= 0 && size_t(shown) >= model.scenes.size())
    ctx.fail("scene " + std::to_string(shown) + " does not exist (" +
             std::to_string(model.scenes.size()) + " scenes)");
  if (shown < 0 && !model.scenes.empty()) shown = 0;
  if (shown < 0) {
    // glTF lets a file without scenes be a library of nodes; viewers differ on what to show.
    // qlight shows every node without a parent, and says so.
    for (uint32_t i = 0; i < scene.nodes.size(); ++i)
      if (scene.nodes[i].parent < 0) scene.rootNodes.push_back(i);
    if (!scene.nodes.empty())
      ctx.warn("the file defines no scene: showing all " + std::to_string(scene.rootNodes.size()) +
               " root nodes");
    return;
  }
  std::vector<bool> listed(scene.nodes.size(), false);
  for (int node : model.scenes[size_t(shown)].nodes) {
    const std::string owner = "scene " + std::to_string(shown);
    checkedIndex(node, scene.nodes.size(), owner, "node", ctx);
    if (node < 0) ctx.fail(owner + " lists node " + std::to_string(node));
    if (scene.nodes[size_t(node)].parent >= 0) {
      ctx.warn(owner + " lists node " + std::to_string(node) + ", which has a parent; ignored");
      continue;
    }
    if (listed[size_t(node)]) continue;
    listed[size_t(node)] = true;
    scene.rootNodes.push_back(uint32_t(node));
  }
}

}  // namespace

void convertNodes(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  const size_t count = model.nodes.size();
  scene.nodes.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const tinygltf::Node& node = model.nodes[i];
    const std::string owner = "node " + std::to_string(i);
    NodeAsset& out = scene.nodes[i];
    out.name = node.name;
    out.local = nodeTransform(node, owner, ctx);
    out.mesh = checkedIndex(node.mesh, model.meshes.size(), owner, "mesh", ctx);
    out.camera = checkedIndex(node.camera, model.cameras.size(), owner, "camera", ctx);
    out.light = checkedIndex(nodeLight(node, owner, ctx), model.lights.size(), owner, "light", ctx);
  }
  for (size_t i = 0; i < count; ++i) {
    for (int child : model.nodes[i].children) {
      const std::string owner = "node " + std::to_string(i);
      if (child < 0 || size_t(child) >= count)
        ctx.fail(owner + " has child " + std::to_string(child) + ", which does not exist (" +
                 std::to_string(count) + " nodes)");
      NodeAsset& c = scene.nodes[size_t(child)];
      if (c.parent >= 0)
        ctx.fail("node " + std::to_string(child) + " has two parents (" + std::to_string(c.parent) +
                 " and " + std::to_string(i) + ")");
      c.parent = int32_t(i);
      scene.nodes[i].children.push_back(uint32_t(child));
    }
  }
  // With one parent each, a node unreachable from the parentless nodes sits on a cycle.
  const std::vector<uint32_t> reached = nodesParentFirst(scene, true);
  if (reached.size() != count) {
    std::vector<bool> seen(count, false);
    for (uint32_t i : reached) seen[i] = true;
    const size_t onCycle = size_t(std::find(seen.begin(), seen.end(), false) - seen.begin());
    ctx.fail("node hierarchy has a cycle through node " + std::to_string(onCycle));
  }
  chooseRoots(model, scene, ctx);
}

void convertCameras(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t i = 0; i < model.cameras.size(); ++i) {
    const tinygltf::Camera& c = model.cameras[i];
    const std::string owner = "camera " + std::to_string(i);
    CameraAsset out;
    out.name = c.name;
    if (c.type == "perspective") {
      const tinygltf::PerspectiveCamera& p = c.perspective;
      for (double v : {p.yfov, p.znear, p.zfar, p.aspectRatio}) ctx.requireFinite(v, owner);
      if (!(p.yfov > 0.0 && p.yfov < 3.14159)) ctx.fail(owner + " yfov must be in (0, pi)");
      if (!(p.znear > 0.0)) ctx.fail(owner + " znear must be positive");
      if (p.zfar != 0.0 && !(p.zfar > p.znear)) ctx.fail(owner + " zfar must exceed znear");
      if (p.aspectRatio < 0.0) ctx.fail(owner + " aspectRatio must be positive");
      out.yfov = float(p.yfov);
      out.znear = float(p.znear);
      if (p.zfar > 0.0) out.zfar = float(p.zfar);
      out.aspectRatio = float(p.aspectRatio);
    } else if (c.type == "orthographic") {
      const tinygltf::OrthographicCamera& o = c.orthographic;
      for (double v : {o.xmag, o.ymag, o.znear, o.zfar}) ctx.requireFinite(v, owner);
      if (o.xmag == 0.0 || o.ymag == 0.0) ctx.fail(owner + " xmag and ymag must not be zero");
      if (o.znear < 0.0 || !(o.zfar > o.znear)) ctx.fail(owner + " needs 0 <= znear < zfar");
      out.fromOrthographic = true;  // yfov is set by replaceOrthographicCameras
      out.aspectRatio = float(std::abs(o.xmag / o.ymag));
      out.znear = float(o.znear);
      out.zfar = float(o.zfar);
    } else {
      ctx.fail(owner + " type '" + c.type + "' is neither perspective nor orthographic");
    }
    scene.cameras.push_back(out);
  }
}

void replaceOrthographicCameras(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  const glm::vec3 center = scene.bounds.center();
  const float radius = std::max(scene.bounds.radius(), 1e-3f);
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    CameraAsset& camera = scene.cameras[i];
    if (!camera.fromOrthographic) continue;
    // The distance, along the view axis, from the camera's first node to the scene's center.
    float distance = 0.0f;
    for (uint32_t n : nodesParentFirst(scene)) {
      if (scene.nodes[n].camera != int32_t(i)) continue;
      const glm::vec3 forward = -glm::normalize(glm::vec3(world[n][2]));
      distance = glm::dot(center - glm::vec3(world[n][3]), forward);
      break;
    }
    if (!(distance > 1e-3f * radius)) distance = 2.0f * radius;
    const double ymag = std::abs(model.cameras[i].orthographic.ymag);
    camera.yfov = float(2.0 * std::atan(ymag / distance));
    if (camera.znear <= 0.0f) camera.znear = 1e-3f * distance;
    ctx.warn("camera " + std::to_string(i) +
             " is orthographic; loaded as a perspective camera (yfov " +
             std::to_string(camera.yfov) + ") framing its extent at the scene center's distance " +
             std::to_string(distance));
  }
}

void convertLights(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t i = 0; i < model.lights.size(); ++i) {
    const tinygltf::Light& l = model.lights[i];
    const std::string owner = "light " + std::to_string(i);
    LightAsset out;
    out.name = l.name;
    if (l.type == "directional") {
      out.type = LightType::Directional;
    } else if (l.type == "point") {
      out.type = LightType::Point;
    } else if (l.type == "spot") {
      out.type = LightType::Spot;
    } else {
      ctx.fail(owner + " type '" + l.type + "' is not directional, point or spot");
    }
    if (!l.color.empty()) {
      if (l.color.size() != 3) ctx.fail(owner + " color needs 3 numbers");
      ctx.requireFiniteAll(l.color, owner + " color");
      out.color = {l.color[0], l.color[1], l.color[2]};
      if (glm::any(glm::lessThan(out.color, glm::vec3(0.0f))))
        ctx.fail(owner + " color is negative");
    }
    ctx.requireFinite(l.intensity, owner + " intensity");
    ctx.requireFinite(l.range, owner + " range");
    if (l.intensity < 0.0) ctx.fail(owner + " intensity is negative");
    if (l.range < 0.0) ctx.fail(owner + " range is negative");
    out.intensity = float(l.intensity);
    out.range = float(l.range);
    if (out.type == LightType::Spot) {
      ctx.requireFinite(l.spot.innerConeAngle, owner + " innerConeAngle");
      ctx.requireFinite(l.spot.outerConeAngle, owner + " outerConeAngle");
      out.outerConeAngle = std::clamp(float(l.spot.outerConeAngle), 1e-4f, kHalfPi);
      out.innerConeAngle = std::clamp(float(l.spot.innerConeAngle), 0.0f, out.outerConeAngle);
      if (out.outerConeAngle != float(l.spot.outerConeAngle) ||
          out.innerConeAngle != float(l.spot.innerConeAngle))
        ctx.warn(owner + " cone angles clamped to 0 <= inner <= outer <= pi/2");
    }
    scene.lights.push_back(out);
  }
}

}  // namespace qlight::gltf::detail

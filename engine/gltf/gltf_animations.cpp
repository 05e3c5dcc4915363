// glTF animations into AnimationAsset: node translation/rotation/scale channels with their
// sampler's keys copied in, and morph-target `weights` channels (their node's mesh must have
// targets).
#include <algorithm>

#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_convert.h"

namespace qlight::gltf::detail {
namespace {

Interpolation interpolationOf(const std::string& name, const std::string& owner, LoadContext& ctx) {
  if (name == "LINEAR" || name.empty()) return Interpolation::Linear;
  if (name == "STEP") return Interpolation::Step;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  ctx.warn(owner + " interpolation '" + name + "' is unknown; LINEAR used");
  return Interpolation::Linear;
}

bool pathOf(const std::string& name, AnimationPath& path) {
  if (name == "translation")
    path = AnimationPath::Translation;
  else if (name == "rotation")
    path = AnimationPath::Rotation;
  else if (name == "scale")
    path = AnimationPath::Scale;
  else if (name == "weights")
    path = AnimationPath::Weights;
  else
    return false;
  return true;
}

}  // namespace

void convertAnimations(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& anim = model.animations[a];
    AnimationAsset out;
    out.name = anim.name;
    for (size_t c = 0; c < anim.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = anim.channels[c];
      const std::string owner = "animation " + std::to_string(a) + " channel " + std::to_string(c);
      if (ch.sampler < 0 || size_t(ch.sampler) >= anim.samplers.size())
        ctx.fail(owner + " uses sampler " + std::to_string(ch.sampler) +
                 ", which does not exist (" + std::to_string(anim.samplers.size()) + " samplers)");
      if (ch.target_node < 0) {
        ctx.warn(owner + " targets no node; skipped");
        continue;
      }
      if (size_t(ch.target_node) >= model.nodes.size())
        ctx.fail(owner + " targets node " + std::to_string(ch.target_node) +
                 ", which does not exist (" + std::to_string(model.nodes.size()) + " nodes)");
      AnimationChannel channel;
      channel.node = uint32_t(ch.target_node);
      if (!pathOf(ch.target_path, channel.path)) {
        ctx.warn(owner + " animates '" + ch.target_path + "', which is not supported; skipped");
        continue;
      }

      const tinygltf::AnimationSampler& sampler = anim.samplers[size_t(ch.sampler)];
      const std::string samplerName =
          "animation " + std::to_string(a) + " sampler " + std::to_string(ch.sampler);
      channel.interpolation = interpolationOf(sampler.interpolation, samplerName, ctx);
      channel.times =
          readFloatAccessor(model, sampler.input, {1, false}, samplerName + " input", ctx);
      for (size_t k = 1; k < channel.times.size(); ++k)
        if (!(channel.times[k] > channel.times[k - 1]))
          ctx.fail(samplerName + " key times are not strictly increasing (key " +
                   std::to_string(k) + ")");

      if (channel.path == AnimationPath::Weights) {
        const int mesh = scene.nodes[channel.node].mesh;
        channel.weightCount =
            mesh >= 0 ? uint32_t(scene.meshes[size_t(mesh)].deform.targets.size()) : 0u;
        if (channel.weightCount == 0) {
          ctx.warn(owner + " animates the weights of node " + std::to_string(channel.node) +
                   ", whose mesh has no morph targets; skipped");
          continue;
        }
      }

      const bool rotation = channel.path == AnimationPath::Rotation;
      const size_t perKey = channel.interpolation == Interpolation::CubicSpline ? 3 : 1;
      if (channel.path == AnimationPath::Weights) {
        channel.weights =
            readFloatAccessor(model, sampler.output, {1, true}, samplerName + " output", ctx);
        const size_t expected = channel.times.size() * perKey * channel.weightCount;
        if (channel.weights.size() != expected)
          ctx.fail(samplerName + " output has " + std::to_string(channel.weights.size()) +
                   " weights for " + std::to_string(channel.times.size()) + " keys of " +
                   std::to_string(channel.weightCount) + " morph targets (expected " +
                   std::to_string(expected) + ")");
        out.duration = std::max(out.duration, channel.times.back());
        out.channels.push_back(std::move(channel));
        continue;
      }
      const int components = rotation ? 4 : 3;
      const std::vector<float> values = readFloatAccessor(
          model, sampler.output, {components, rotation}, samplerName + " output", ctx);
      const size_t expected = channel.times.size() * perKey;
      if (values.size() / components != expected)
        ctx.fail(samplerName + " output has " + std::to_string(values.size() / components) +
                 " values for " + std::to_string(channel.times.size()) + " keys (expected " +
                 std::to_string(expected) + ")");
      channel.values.resize(expected);
      for (size_t v = 0; v < expected; ++v) {
        glm::vec4 value(0.0f);
        for (int k = 0; k < components; ++k) value[k] = values[v * components + k];
        // Key values of a rotation are unit quaternions; tangents are not.
        const bool isKeyValue = perKey == 1 || v % 3 == 1;
        if (rotation && isKeyValue) {
          const float len = glm::length(value);
          if (!(len > 1e-6f)) ctx.fail(samplerName + " output holds a zero quaternion");
          value /= len;
        }
        channel.values[v] = value;
      }
      out.duration = std::max(out.duration, channel.times.back());
      out.channels.push_back(std::move(channel));
    }
    scene.animations.push_back(std::move(out));
  }
}

}  // namespace qlight::gltf::detail

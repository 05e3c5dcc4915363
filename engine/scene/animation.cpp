#include "engine/scene/animation.h"

#include <algorithm>
#include <cmath>

#include "engine/scene/transforms.h"

namespace qlight::scene {
namespace {

// Quaternions as (x, y, z, w) vectors, shorter arc, as in the glTF spec's appendix.
glm::vec4 slerp(glm::vec4 a, glm::vec4 b, float u) {
  float d = glm::dot(a, b);
  if (d < 0.0f) {
    b = -b;
    d = -d;
  }
  if (d > 0.9995f) return glm::normalize(glm::mix(a, b, u));  // nearly equal: lerp is exact enough
  const float theta = std::acos(std::min(d, 1.0f));
  const float s = std::sin(theta);
  return (std::sin((1.0f - u) * theta) / s) * a + (std::sin(u * theta) / s) * b;
}

glm::vec4 keyValue(const AnimationChannel& channel, size_t key) {
  return channel.interpolation == Interpolation::CubicSpline ? channel.values[3 * key + 1]
                                                             : channel.values[key];
}

glm::vec4 normalizedIfRotation(const AnimationChannel& channel, glm::vec4 v) {
  if (channel.path != AnimationPath::Rotation) return v;
  const float len = glm::length(v);
  return len > 0.0f ? v / len : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
}

}  // namespace

glm::vec4 sampleChannel(const AnimationChannel& channel, float t) {
  const std::vector<float>& times = channel.times;
  if (times.empty())
    return channel.path == AnimationPath::Rotation ? glm::vec4(0, 0, 0, 1)
           : channel.path == AnimationPath::Scale  ? glm::vec4(1, 1, 1, 0)
                                                   : glm::vec4(0.0f);
  if (!(t > times.front())) return normalizedIfRotation(channel, keyValue(channel, 0));
  if (t >= times.back()) return normalizedIfRotation(channel, keyValue(channel, times.size() - 1));

  // times[k] <= t < times[k + 1]
  const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const float t0 = times[k], t1 = times[k + 1];
  const float dt = t1 - t0;
  const float u = std::clamp((t - t0) / dt, 0.0f, 1.0f);

  switch (channel.interpolation) {
    case Interpolation::Step:
      return keyValue(channel, k);
    case Interpolation::Linear:
      if (channel.path == AnimationPath::Rotation)
        return slerp(channel.values[k], channel.values[k + 1], u);
      return glm::mix(channel.values[k], channel.values[k + 1], u);
    case Interpolation::CubicSpline: {
      const glm::vec4 p0 = channel.values[3 * k + 1];
      const glm::vec4 m0 = dt * channel.values[3 * k + 2];  // out-tangent of key k
      const glm::vec4 p1 = channel.values[3 * (k + 1) + 1];
      const glm::vec4 m1 = dt * channel.values[3 * (k + 1)];  // in-tangent of key k + 1
      const float u2 = u * u, u3 = u2 * u;
      const glm::vec4 p = (2.0f * u3 - 3.0f * u2 + 1.0f) * p0 + (u3 - 2.0f * u2 + u) * m0 +
                          (-2.0f * u3 + 3.0f * u2) * p1 + (u3 - u2) * m1;
      return normalizedIfRotation(channel, p);
    }
  }
  return keyValue(channel, k);
}

std::vector<float> sampleWeights(const AnimationChannel& channel, float t) {
  const size_t n = channel.weightCount;
  std::vector<float> out(n, 0.0f);
  const std::vector<float>& times = channel.times;
  const bool cubic = channel.interpolation == Interpolation::CubicSpline;
  const size_t perKey = cubic ? 3 : 1;
  if (times.empty() || channel.weights.size() < times.size() * perKey * n) return out;
  auto value = [&](size_t key, size_t which) {  // which: 0 in-tangent, 1 value, 2 out-tangent
    return &channel.weights[(key * perKey + (cubic ? which : 0)) * n];
  };
  auto copyKey = [&](size_t key) {
    const float* v = value(key, 1);
    out.assign(v, v + n);
    return out;
  };
  if (!(t > times.front())) return copyKey(0);
  if (t >= times.back()) return copyKey(times.size() - 1);
  const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const float dt = times[k + 1] - times[k];
  const float u = std::clamp((t - times[k]) / dt, 0.0f, 1.0f);
  switch (channel.interpolation) {
    case Interpolation::Step:
      return copyKey(k);
    case Interpolation::Linear:
      for (size_t i = 0; i < n; ++i) out[i] = glm::mix(value(k, 1)[i], value(k + 1, 1)[i], u);
      return out;
    case Interpolation::CubicSpline: {
      const float u2 = u * u, u3 = u2 * u;
      for (size_t i = 0; i < n; ++i)
        out[i] = (2.0f * u3 - 3.0f * u2 + 1.0f) * value(k, 1)[i] +
                 (u3 - 2.0f * u2 + u) * dt * value(k, 2)[i] +
                 (-2.0f * u3 + 3.0f * u2) * value(k + 1, 1)[i] +
                 (u3 - u2) * dt * value(k + 1, 0)[i];
      return out;
    }
  }
  return out;
}

void applyChannel(const AnimationChannel& channel, float t, LocalTransform& local) {
  if (channel.path == AnimationPath::Weights) return;
  const glm::vec4 v = sampleChannel(channel, t);
  switch (channel.path) {
    case AnimationPath::Translation:
      local.translation = glm::vec3(v);
      break;
    case AnimationPath::Rotation:
      local.rotation = glm::quat(v.w, v.x, v.y, v.z);
      break;
    case AnimationPath::Scale:
      local.scale = glm::vec3(v);
      break;
    case AnimationPath::Weights:
      break;
  }
}

float animationTime(const AnimationAsset& animation, float t, bool loop) {
  if (!std::isfinite(t)) return 0.0f;
  if (!loop || !(animation.duration > 0.0f)) return t;
  const float wrapped = std::fmod(t, animation.duration);
  return wrapped < 0.0f ? wrapped + animation.duration : wrapped;
}

std::vector<LocalTransform> animate(const SceneAsset& scene, float timeSeconds, bool loop) {
  std::vector<LocalTransform> locals = restPose(scene);
  for (const AnimationAsset& animation : scene.animations) {
    const float t = animationTime(animation, timeSeconds, loop);
    for (const AnimationChannel& channel : animation.channels)
      applyChannel(channel, t, locals[channel.node]);
  }
  return locals;
}

}  // namespace qlight::scene

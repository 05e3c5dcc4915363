// Pure evaluation of glTF animation channels (no ECS): sampling one channel at a time and
// posing every node of a SceneAsset. Times outside a channel's keys clamp to its first or
// last key, as glTF says; looping is the caller's choice (animationTime).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

// The channel's value at time t: (x, y, z, 0) for translation and scale, a unit quaternion
// (x, y, z, w) for rotation. LINEAR rotations slerp along the shorter arc; CUBICSPLINE is the
// glTF Hermite spline with the keys' in/out tangents (scaled by the key interval), rotations
// renormalized; STEP holds each key until the next.
glm::vec4 sampleChannel(const AnimationChannel& channel, float t);

// A Weights channel's morph weights at time t (weightCount of them), interpolated as
// sampleChannel interpolates (LINEAR lerps, STEP holds, CUBICSPLINE is the Hermite spline).
std::vector<float> sampleWeights(const AnimationChannel& channel, float t);

// Writes the channel's value at t into the transform component it targets (Weights channels
// are left to sampleWeights).
void applyChannel(const AnimationChannel& channel, float t, LocalTransform& local);

// The time at which to sample `animation` for a clock reading t: t itself, or t wrapped into
// [0, duration) when looping.
float animationTime(const AnimationAsset& animation, float t, bool loop);

// Every node's local transform at time t: the rest pose with the channels of every animation
// applied in order (a later animation overrides an earlier one on the same target).
std::vector<LocalTransform> animate(const SceneAsset& scene, float timeSeconds, bool loop = false);

}  // namespace qlight::scene

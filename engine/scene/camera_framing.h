// A default camera for scenes that have none: it looks at the bounds' center from the front
// (+Z), a little above and to the right, far enough that the whole bounding sphere is inside
// the view for the given aspect ratio.
#pragma once

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

struct FramedCamera {
  LocalTransform worldFromCamera;  // the camera looks down its -Z, +Y up (glTF)
  CameraAsset camera;              // perspective; aspectRatio is the one asked for
};

inline constexpr float kDefaultYfov = 0.8f;  // radians (about 46 degrees)

// aspect = width / height (> 0). Empty bounds frame the unit sphere at the origin.
FramedCamera frameBounds(const Bounds& bounds, float aspect, float yfov = kDefaultYfov);

}  // namespace qlight::scene

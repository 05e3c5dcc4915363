// The default camera sees the whole scene: every corner of the bounds projects inside the
// view frustum, for boxes of different shapes and viewports of different aspect ratios.
#include "engine/scene/camera_framing.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/transforms.h"

namespace qlight::scene {
namespace {

void expectCornersInside(const Bounds& bounds, float aspect) {
  const FramedCamera framed = frameBounds(bounds, aspect);
  EXPECT_EQ(framed.camera.aspectRatio, aspect);
  const glm::mat4 cameraFromWorld = glm::inverse(toMatrix(framed.worldFromCamera));
  const glm::mat4 clipFromCamera =
      glm::perspective(framed.camera.yfov, aspect, framed.camera.znear, framed.camera.zfar);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? bounds.max.x : bounds.min.x, i & 2 ? bounds.max.y : bounds.min.y,
                           i & 4 ? bounds.max.z : bounds.min.z);
    const glm::vec4 clip = clipFromCamera * cameraFromWorld * glm::vec4(corner, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    EXPECT_LT(std::abs(ndc.x), 1.0f) << "corner " << i << " aspect " << aspect;
    EXPECT_LT(std::abs(ndc.y), 1.0f) << "corner " << i << " aspect " << aspect;
    EXPECT_LT(std::abs(ndc.z), 1.0f) << "corner " << i << " aspect " << aspect;
  }
  // It looks at the center: the center projects to the middle of the image.
  const glm::vec4 center = clipFromCamera * cameraFromWorld * glm::vec4(bounds.center(), 1.0f);
  EXPECT_NEAR(center.x / center.w, 0.0f, 1e-5f);
  EXPECT_NEAR(center.y / center.w, 0.0f, 1e-5f);
}

TEST(CameraFraming, AllCornersOfTheBoundsAreInView) {
  const Bounds boxes[] = {{{-1, -1, -1}, {1, 1, 1}},       // cube at the origin
                          {{10, 0, -3}, {12, 0.5f, 40}},   // long and off-center
                          {{-5, 0, -5}, {5, 0, 5}},        // flat floor
                          {{0, 0, 0}, {0.01f, 3, 0.01f}},  // thin pole
                          {{-1000, -2, -1000}, {1000, 2, 1000}}};
  for (const Bounds& b : boxes)
    for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f, 3.0f}) expectCornersInside(b, aspect);
}

TEST(CameraFraming, EmptyBoundsFrameTheUnitSphere) {
  const FramedCamera framed = frameBounds(Bounds{}, 1.0f);
  const float distance = glm::length(framed.worldFromCamera.translation);
  EXPECT_GT(distance, 1.0f);
  EXPECT_GT(framed.camera.znear, 0.0f);
  EXPECT_LT(framed.camera.znear, distance - 1.0f);
  EXPECT_GT(framed.camera.zfar, distance + 1.0f);
}

}  // namespace
}  // namespace qlight::scene

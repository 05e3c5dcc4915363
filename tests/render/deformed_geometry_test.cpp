// Instanced, skinned and morphed geometry end to end: EXT_mesh_gpu_instancing instances are
// top-level BVH instances hit where their transforms put them, a skinned character's refitted
// BVH traces like brute force over its posed triangles, deformed scenes render and move on the
// GPU, and guided renders stay unbiased while geometry moves under the cache points.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/bvh/cpu_traversal.h"
#include "engine/bvh/scene_bvh.h"
#include "engine/scene/procedural.h"
#include "engine/scene/transforms.h"
#include "engine/session/renderer.h"
#include "engine/session/scene_world.h"
#include "tests/render/agreement.h"

namespace qlight::test {
namespace {

const std::string kFeatures = std::string(QLIGHT_SAMPLES_DIR) + "/features/";

// Brute force over every drawn triangle (world space), for the CPU traversal's answer.
struct Closest {
  float t = 1e30f;
  int draw = -1;
};
Closest bruteForce(const scene::SceneAsset& asset, const render::SceneDraw& draw,
                   const std::vector<std::vector<glm::vec3>>& positions, glm::vec3 o, glm::vec3 d) {
  Closest best;
  for (size_t i = 0; i < draw.meshes.size(); ++i) {
    const render::MeshDraw& m = draw.meshes[i];
    const scene::MeshAsset& mesh = asset.meshes[m.mesh];
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = glm::vec3(m.worldFromObject *
                         glm::vec4(positions[m.mesh][mesh.indices[3 * t + k]], 1.0f));
      // Moller-Trumbore in double: a reference independent of the traversal's test.
      const glm::dvec3 e1 = glm::dvec3(p[1] - p[0]), e2 = glm::dvec3(p[2] - p[0]);
      const glm::dvec3 q = glm::cross(glm::dvec3(d), e2);
      const double det = glm::dot(e1, q);
      if (std::abs(det) < 1e-30) continue;
      const glm::dvec3 s = glm::dvec3(o) - glm::dvec3(p[0]);
      const double u = glm::dot(s, q) / det;
      const glm::dvec3 r = glm::cross(s, e1);
      const double v = glm::dot(glm::dvec3(d), r) / det;
      const double h = glm::dot(e2, r) / det;
      if (u < 0 || v < 0 || u + v > 1 || h <= 0 || h >= best.t) continue;
      best = {float(h), int(i)};
    }
  }
  return best;
}

bvh::SceneBvh bvhOf(const scene::SceneAsset& asset, const render::SceneDraw& draw,
                    std::vector<std::vector<glm::vec3>>& positions) {
  bvh::SceneBvh out;
  positions.clear();
  for (const scene::MeshAsset& m : asset.meshes) {
    out.addMesh(m.positions, m.indices);  // the rest pose, as GpuScene builds it
    positions.push_back(m.positions);
  }
  for (const render::DeformedDraw& d : draw.deformed) {
    positions[d.mesh].assign(d.positions.begin(), d.positions.end());
    out.refitMesh(d.mesh, d.positions, asset.meshes[d.mesh].indices);
  }
  std::vector<bvh::Instance> instances;
  for (uint32_t i = 0; i < draw.meshes.size(); ++i)
    instances.push_back(
        {draw.meshes[i].worldFromObject, draw.meshes[i].mesh, i, draw.meshes[i].fixed});
  out.rebuildTopLevel(instances);
  return out;
}

TEST(DeformedGeometry, SimpleInstancingHasOneTopLevelInstancePerInstanceOfOneMesh) {
  const scene::SceneAsset asset =
      gltf::loadGltf(kFeatures + "SimpleInstancing/glTF/SimpleInstancing.gltf");
  for (const std::string& w : asset.warnings)
    EXPECT_EQ(w.find("EXT_mesh_gpu_instancing"), std::string::npos) << w;
  ASSERT_EQ(asset.meshes.size(), 1u);  // shared, not copied
  session::SceneWorld world(asset, 1.0f);
  const render::SceneDraw& draw = world.draw();
  ASSERT_EQ(draw.meshes.size(), 125u);
  std::vector<std::vector<glm::vec3>> positions;
  const bvh::SceneBvh bvh = bvhOf(asset, draw, positions);
  EXPECT_EQ(bvh.blasCount(), 1u);
  EXPECT_EQ(bvh.topLevel().hittableInstances, 125u);
  EXPECT_EQ(bvh.merged().instances, 125u);  // none moves: all copied into the merged BLAS
  // README: the first instance is the unit cube, the last one sits at (10, 10, 10), scaled 2.
  EXPECT_EQ(glm::vec3(draw.meshes.front().worldFromObject[3]), glm::vec3(0.0f));
  EXPECT_NEAR(glm::length(glm::vec3(draw.meshes.back().worldFromObject[3]) - glm::vec3(10)), 0,
              1e-4f);
  EXPECT_NEAR(glm::length(glm::vec3(draw.meshes.back().worldFromObject[0])), 2.0f, 1e-4f);

  // A ray from outside the grid at each instance's centre hits what brute force hits, and
  // from each centre outwards, that instance itself first (its own faces are nearest).
  bvh::CpuBvhBinding binding(bvh.flat());
  const glm::vec3 cubeCentre = 0.5f * (asset.meshes[0].boundsMin + asset.meshes[0].boundsMax);
  uint32_t own = 0;
  for (uint32_t i = 0; i < draw.meshes.size(); ++i) {
    const glm::vec3 centre(draw.meshes[i].worldFromObject * glm::vec4(cubeCentre, 1));
    for (glm::vec3 origin : {centre + glm::vec3(0.1f, 0.2f, 30.0f), centre}) {
      const glm::vec3 dir = origin == centre ? glm::vec3(0.3f, 0.2f, 1.0f) : centre - origin;
      shared::BvhHit hit;
      const bool found = shared::traceClosest(origin, dir, 1e30f, hit);
      const Closest ref = bruteForce(asset, draw, positions, origin, dir);
      ASSERT_EQ(found, ref.draw >= 0) << "instance " << i;
      ASSERT_EQ(int(hit.instance), ref.draw) << "instance " << i;
      ASSERT_NEAR(hit.t, ref.t, 1e-4f * ref.t) << "instance " << i;
      if (origin == centre) own += hit.instance == i;
    }
  }
  EXPECT_EQ(own, 125u);
}

TEST(DeformedGeometry, CesiumManRefittedAfterSkinningTracesLikeBruteForce) {
  const scene::SceneAsset asset = gltf::loadGltf(kFeatures + "CesiumMan/glTF/CesiumMan.gltf");
  for (const std::string& w : asset.warnings) EXPECT_EQ(w.find("skin"), std::string::npos) << w;
  session::SceneWorld world(asset, 1.0f);
  for (float t : {0.0f, 0.7f, 1.4f}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    world.advance(t);
    const render::SceneDraw& draw = world.draw();
    ASSERT_EQ(draw.deformed.size(), 1u);
    std::vector<std::vector<glm::vec3>> positions;
    const bvh::SceneBvh bvh = bvhOf(asset, draw, positions);
    for (const render::MeshDraw& d : draw.meshes) EXPECT_FALSE(d.fixed);  // skinned
    EXPECT_EQ(bvh.merged().rootRef, 0u);
    bvh::CpuBvhBinding binding(bvh.flat());
    // Rays from a ring around the character towards random points of its (posed) bounds.
    scene::Bounds box;
    for (const glm::vec3& p : draw.deformed[0].positions) box.include(p);
    uint32_t hits = 0;
    for (int r = 0; r < 400; ++r) {
      const float a = 0.157f * float(r), h = float(r % 17) / 16.0f;
      const glm::vec3 target = glm::mix(
          box.min, box.max,
          glm::vec3(0.5f + 0.4f * std::sin(3.1f * a), h, 0.5f + 0.4f * std::cos(1.7f * a)));
      const glm::vec3 origin =
          box.center() + 3.0f * box.radius() * glm::vec3(std::cos(a), 0.2f, std::sin(a));
      shared::BvhHit hit;
      const bool found = shared::traceClosest(origin, target - origin, 1e30f, hit);
      const Closest ref = bruteForce(asset, draw, positions, origin, target - origin);
      ASSERT_EQ(found, ref.draw >= 0) << "ray " << r;
      if (found) {
        ASSERT_NEAR(hit.t, ref.t, 1e-4f * ref.t) << "ray " << r;
      }
      hits += found;
    }
    EXPECT_GT(hits, 100u);
  }
}

TEST(DeformedGeometry, OnlyNodesThatNoAnimationMovesAreFixed) {
  // animated_light.gltf: the room and the blocks stand still, node 3's translation is animated.
  const scene::SceneAsset asset =
      gltf::loadGltf(std::string(QLIGHT_SOURCE_DIR) + "/assets/animated_light.gltf");
  session::SceneWorld world(asset, 1.0f);
  world.advance(0.5f);
  const render::SceneDraw& draw = world.draw();
  ASSERT_EQ(draw.meshes.size(), 3u);
  for (const render::MeshDraw& d : draw.meshes) EXPECT_EQ(d.fixed, d.mesh != 2u) << d.mesh;
  // The moving light stays an instance of its own BLAS; a ray at it still finds it.
  std::vector<std::vector<glm::vec3>> positions;
  const bvh::SceneBvh bvh = bvhOf(asset, draw, positions);
  EXPECT_EQ(bvh.merged().instances, 2u);
  bvh::CpuBvhBinding binding(bvh.flat());
  for (uint32_t i = 0; i < draw.meshes.size(); ++i) {
    const scene::MeshAsset& mesh = asset.meshes[draw.meshes[i].mesh];
    const glm::vec3 centre(draw.meshes[i].worldFromObject *
                           glm::vec4(0.5f * (mesh.boundsMin + mesh.boundsMax), 1));
    for (glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(0.3f, 1, 0.2f), glm::vec3(1, 0.1f, 0)}) {
      const glm::vec3 origin = centre + 0.25f * dir;
      shared::BvhHit hit;
      const bool found = shared::traceClosest(origin, dir, 1e30f, hit);
      const Closest ref = bruteForce(asset, draw, positions, origin, dir);
      ASSERT_EQ(found, ref.draw >= 0) << "draw " << i;
      if (!found) continue;
      EXPECT_EQ(int(hit.instance), ref.draw) << "draw " << i;
      EXPECT_NEAR(hit.t, ref.t, 1e-4f * ref.t) << "draw " << i;
    }
  }
}

class DeformedRender : public GpuTest {};

double meanOf(const image::LinearImage& img) {
  double sum = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    sum += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2];
  return sum / double(img.rgba.size() / 4);
}

TEST_F(DeformedRender, SkinnedMorphedAndInstancedSamplesRenderAndMove) {
  for (const char* file : {"CesiumMan/glTF/CesiumMan.gltf", "Fox/glTF/Fox.gltf",
                           "AnimatedMorphCube/glTF/AnimatedMorphCube.gltf",
                           "SimpleInstancing/glTF/SimpleInstancing.gltf"}) {
    SCOPED_TRACE(file);
    const scene::SceneAsset asset = gltf::loadGltf(kFeatures + file);
    render::RenderSettings s = smallSettings(24, 24, 3);
    s.samplesPerFrame = 4;
    session::Renderer renderer(ctx(), asset, s, session::disabledGuiding(), 1.0f);
    const render::CameraView camera = renderer.world().camera();  // the framing at t = 0
    std::vector<image::LinearImage> images;
    for (float t : {0.0f, 0.9f}) {
      const session::FrameResult r = renderer.renderFrame(t, camera);
      EXPECT_EQ(r.counters.invalidSamples, 0u);
      images.push_back(renderer.tracer().readImage());
    }
    EXPECT_GT(meanOf(images[0]), 0.0);
    if (std::string(file).find("Instancing") == std::string::npos) {  // the others animate
      EXPECT_NE(images[0].rgba, images[1].rgba);
    }
  }
}

// The Cornell box with a box that a morph target carries across the room in 1 s: guided
// renders learn while it moves (the cache points stay where the box was) and must still
// converge to what unguided renders show at the end.
scene::SceneAsset cornellWithMovingBox() {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("cornell_box.gltf"));
  scene::MeshAsset box;
  scene::addBox(box,
                glm::translate(glm::mat4(1.0f), asset.bounds.center() - glm::vec3(0.6f, 0.5f, 0)),
                glm::vec3(0.15f * asset.bounds.radius()), 0);
  scene::MorphTarget move;
  move.positions.assign(box.positions.size(), glm::vec3(0.4f * asset.bounds.radius(), 0, 0));
  box.deform.targets = {move};
  box.deform.defaultWeights = {0.0f};
  box.deform.basePositions = box.positions;
  box.deform.baseNormals = box.normals;
  asset.meshes.push_back(box);
  scene::NodeAsset node;
  node.mesh = int32_t(asset.meshes.size() - 1);
  const uint32_t n = scene::addNode(asset, node);
  scene::AnimationChannel weights;
  weights.node = n;
  weights.path = scene::AnimationPath::Weights;
  weights.times = {0.0f, 1.0f};
  weights.weights = {0.0f, 1.0f};
  weights.weightCount = 1;
  scene::AnimationAsset animation;
  animation.channels.push_back(weights);
  animation.duration = 2.0f;  // holds the end pose from 1 s to 2 s (the clock loops at 2)
  asset.animations.push_back(animation);
  return asset;
}

TEST_F(DeformedRender, GuidedRendersStayUnbiasedWhileGeometryMoves) {
  const scene::SceneAsset asset = cornellWithMovingBox();
  AgreementSetup setup{24, 3, 16};
  auto with = [&](bool guided) {
    return [&, guided](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.samplesPerFrame = 4;
      s.maxDepth = 4;
      guiding::GuidingSettings g = guided ? guiding::GuidingSettings{} : session::disabledGuiding();
      g.pointBudget = 512;
      g.dartPaths = 2048;
      session::Renderer renderer(ctx(), asset, s, g, 1.0f);
      for (float t : {0.0f, 0.3f, 0.6f}) renderer.renderFrame(t);  // learning as the box moves
      for (int f = 0; f < 4; ++f) renderer.renderFrame(1.5f);      // the end pose, accumulated
      return renderer.tracer().readImage();
    };
  };
  expectAgree(regionMeans(setup, with(true), 100), regionMeans(setup, with(false), 200),
              "guided vs unguided after motion");
}

}  // namespace
}  // namespace qlight::test

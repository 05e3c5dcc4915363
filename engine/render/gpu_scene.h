// The scene on the GPU: geometry, materials and textures uploaded once; the
// two-level BVH, instance table and world-space light list refreshed when
// instances or lights move; a deformed mesh's vertices re-uploaded and its
// bottom-level BVH refitted when its pose changes.
#pragma once
#include <memory>

#include "engine/gpu/buffer.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/render/scene_accel.h"
#include "engine/render/scene_draw.h"
#include "engine/scene/scene_asset.h"
#include "shaders/shared/scene_types.h"

namespace qlight::render {

struct SceneLightingOptions {
  // Radiance of the uniform sky added when the scene has no light, or no emitter but emissive
  // textures (glow maps: a model made to be seen under the viewer's light), and the user chose
  // no environment (SceneAsset::environment), so that such a glTF renders visibly instead of
  // black (documented fallback).
  float fallbackSkyRadiance = 1.0f;
};

class GpuScene {
 public:
  GpuScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
           SceneLightingOptions options = {});

  // Takes the new poses of deformed meshes (vertices and BLAS refit), rebuilds the
  // top-level BVH, the instance table and the light list. Replaces and writes
  // buffers, so no recorded frame that uses them may still be in flight.
  void update(const SceneDraw& draw);

  // Binds every scene buffer of the path tracing passes (shaders/pt_*.comp).
  void bind(gpu::PassBuilder& pass) const;
  // Binds the geometry and materials only (include/scene_access.glsl, without the lights).
  void bindSurfaces(gpu::PassBuilder& pass) const;

  uint32_t lightCount() const { return lightCount_; }
  bool usesFallbackSky() const { return fallbackSky_; }
  // Every emitter of the scene is an emissive texture (a glow map, usesFallbackSky() says
  // whether the fallback sky lights it as well).
  bool glowMapsOnly() const { return glowMapsOnly_; }
  // The user's environment is the last light (it has power: a black one is left out).
  bool hasEnvironment() const { return environmentLit_; }
  uint32_t triangleCount() const { return triangleCount_; }
  // Device memory of every scene buffer (geometry, BVH, materials, textures, lights).
  uint64_t memoryBytes() const;
  // Wall time of building the bottom-level BVHs, and of the whole construction (uploads
  // included), in seconds.
  double blasBuildSeconds() const { return blasBuildSeconds_; }
  double buildSeconds() const { return buildSeconds_; }
  float surfaceArea() const { return surfaceArea_; }
  // Features the path tracing passes are specialized on.
  bool hasTextures() const { return hasTextures_; }
  bool hasVertexExtras() const { return hasVertexExtras_; }  // TEXCOORD_1, COLOR_0, tangents
  bool hasAlphaTest() const { return hasAlphaTest_; }        // some material is MASK or BLEND
  // Some scattering material is not exactly Lambertian (metal, a specular layer, transmission).
  bool hasMicrofacet() const { return hasMicrofacet_; }
  // The specialization constants of shaders/include/features.glsl that the scene decides
  // (guiding's stay 0), indexed by constant id.
  std::vector<uint32_t> specializationFeatures() const;
  bool hasNonTriangleLights() const {
    return hasNonTriangleLights_;
  }  // world space, of the last update
  bool hasEnvironmentMap() const { return environmentLit_ && asset_.environment->hasMap(); }
  const glm::vec3& boundsCenter() const { return center_; }
  float boundsRadius() const { return radius_; }
  const scene::Bounds& bounds() const { return asset_.bounds; }  // world space, at t = 0
  const std::vector<shared::GpuLight>& lights() const { return lights_; }
  // Nearest surface along a ray (CPU traversal of the same BVH; for picking).
  std::optional<float> closestHit(glm::vec3 origin, glm::vec3 direction) const {
    return accel_.closestHit(origin, direction);
  }

 private:
  void requireGeometryFits() const;
  void uploadStatic();
  void uploadEnvironment();
  void uploadLights(const SceneDraw& draw);
  // The sky of the user's environment, or of the fallback, as lights: one per tile of a map
  // (shaders/shared/environment.h), else one; powers 0 when black.
  std::vector<shared::GpuLight> skyLights(const scene::EnvironmentAsset& env) const;
  bool applyDeformations(const std::vector<DeformedDraw>& deformed);
  // The mesh's positions as last posed (its file positions until it deforms).
  const std::vector<glm::vec3>& positionsOf(uint32_t mesh) const;

  const gpu::Context& ctx_;
  const scene::SceneAsset& asset_;
  SceneLightingOptions options_;
  std::vector<uint32_t> meshFirstTriangle_;  // into the GpuTriangle array
  std::vector<uint32_t> meshFirstVertex_;
  std::vector<shared::GpuTriangle> triangles_;
  std::vector<uint64_t> poseVersions_;  // per mesh: the DeformedDraw version uploaded
  std::vector<std::vector<glm::vec3>> posedPositions_;  // per mesh; empty until it deforms
  SceneAccel accel_;
  uint64_t uploadedTriangles_ = 0;  // accel_.trianglesVersion() of bvhTris_
  std::vector<shared::GpuLight> lights_;
  uint32_t lightCount_ = 0;
  uint32_t triangleCount_ = 0;
  bool fallbackSky_ = false;
  bool glowMapsOnly_ = false;
  std::vector<std::vector<glm::vec3>> triangleEmissions_;  // emitter_power.h, per mesh
  bool environmentLit_ = false;
  std::vector<double> environmentTileIntegrals_;  // of the map's tiles (environment_tables.h)
  glm::vec3 center_{0.0f};
  float radius_ = 1.0f;
  float surfaceArea_ = 0.0f;
  double blasBuildSeconds_ = 0.0, buildSeconds_ = 0.0;
  bool hasTextures_ = false;
  bool hasVertexExtras_ = false;
  bool hasAlphaTest_ = false;
  bool hasMicrofacet_ = false;
  bool hasNonTriangleLights_ = false;

  std::unique_ptr<gpu::Buffer> vertices_, triangleBuffer_, materials_, textures_, texels_;
  std::unique_ptr<gpu::BufferView> texelView_, verticesView_, materialsView_, triangleView_,
      lightCdfView_, texturesView_, lightView_, instancesView_;
  std::unique_ptr<gpu::Buffer> bvhNodes_, bvhTris_, bvhInstances_, instances_, lightBuffer_,
      lightCdf_;
  std::unique_ptr<gpu::BufferView> bvhNodesView_, bvhTrisView_, bvhInstancesView_;
  std::unique_ptr<gpu::Buffer> envTexels_, envCdf_;  // placeholders without a map
  std::unique_ptr<gpu::BufferView> envTexelsView_, envCdfView_;
};

}  // namespace qlight::render

#include "engine/render/gpu_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "engine/bvh/scene_bvh.h"
#include "engine/render/emitter_power.h"
#include "engine/render/environment_tables.h"
#include "engine/render/scene_packing.h"
#include "engine/render/texture_mips.h"
#include "shaders/shared/bvh_types.h"
#include "shaders/shared/environment.h"
#include "shaders/shared/sampling.h"
#include "shaders/shared/specialization.h"

namespace qlight::render {
namespace {

// The shaders read these tables as RGBA32UI texels (instanceAt, lightAt, textureAt).
static_assert(sizeof(shared::GpuInstance) == 16 * shared::kInstanceTexels);
static_assert(sizeof(shared::GpuLight) == 16 * shared::kLightTexels);
static_assert(sizeof(shared::GpuTexture) == 16);

using shared::GpuLight;
using shared::GpuMaterial;
using shared::GpuTexture;
using shared::GpuTriangle;

constexpr float kPi = 3.14159265358979f;

float luminance(glm::vec3 c) { return glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

uint32_t textureFlags(const scene::TextureAsset& t) {
  uint32_t f = t.srgb ? shared::kTextureSrgb : 0u;
  if (t.nearestFilter) f |= shared::kTextureNearest;
  if (t.wrapS == scene::TextureWrap::ClampToEdge) f |= shared::kTextureClampS;
  if (t.wrapT == scene::TextureWrap::ClampToEdge) f |= shared::kTextureClampT;
  if (t.wrapS == scene::TextureWrap::MirroredRepeat) f |= shared::kTextureMirrorS;
  if (t.wrapT == scene::TextureWrap::MirroredRepeat) f |= shared::kTextureMirrorT;
  return f;
}

template <class T>
std::unique_ptr<gpu::Buffer> makeBuffer(const gpu::Context& ctx, const std::vector<T>& data,
                                        const std::string& name, VkBufferUsageFlags usage = 0) {
  auto buffer = std::make_unique<gpu::Buffer>(ctx, std::max<size_t>(data.size() * sizeof(T), 16),
                                              name, usage);
  if (!data.empty()) buffer->upload(ctx, data.data(), data.size() * sizeof(T));
  return buffer;
}

}  // namespace

GpuScene::GpuScene(const gpu::Context& ctx, const scene::SceneAsset& asset,
                   SceneLightingOptions options)
    : ctx_(ctx), asset_(asset), options_(options) {
  center_ = asset.bounds.center();
  radius_ = std::max(asset.bounds.radius(), 1e-3f);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  requireGeometryFits();
  uploadStatic();
  uploadEnvironment();
  triangleEmissions_ = triangleEmissions(asset);
  const auto blasStart = Clock::now();
  accel_.buildMeshes(asset.meshes);
  {
    // The merged copy of the fixed instances' triangles shares the BVH's triangle buffer:
    // keep it within what one texel buffer holds (requireGeometryFits counted the meshes').
    uint64_t triangles = 0;
    for (const scene::MeshAsset& m : asset.meshes) triangles += m.triangleCount();
    const uint64_t texels = ctx.properties().limits.maxTexelBufferElements;
    const uint64_t room = texels / 3 > triangles ? texels / 3 - triangles : 0;
    accel_.setMaxMergedTriangles(
        uint32_t(std::min<uint64_t>(room, bvh::SceneBvh::kDefaultMaxMergedTriangles)));
  }
  blasBuildSeconds_ = std::chrono::duration<double>(Clock::now() - blasStart).count();
  buildSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  poseVersions_.assign(asset.meshes.size(), 0);
  posedPositions_.resize(asset.meshes.size());
}

// Refused before anything is built or allocated, in one line naming the geometry and the
// limit: the largest texel buffers are the BVH's triangles (3 texels each) and the vertices
// (2 each); the BVH's node layout addresses 2^28 triangles.
void GpuScene::requireGeometryFits() const {
  uint64_t vertices = 0, triangles = 0;
  for (const scene::MeshAsset& m : asset_.meshes) {
    vertices += m.positions.size();
    triangles += m.triangleCount();
  }
  const std::string what = "the scene's geometry (" + std::to_string(triangles) + " triangles, " +
                           std::to_string(vertices) + " vertices in " +
                           std::to_string(asset_.meshes.size()) +
                           " meshes; use fewer or simpler meshes)";
  if (triangles > shared::kBvhMaxTriangles)
    throw std::runtime_error(what + " is larger than qlight's BVH allows: " +
                             std::to_string(shared::kBvhMaxTriangles) + " triangles");
  // Bytes: vertices, triangle table, BVH triangles and at most one node per triangle.
  const uint64_t bytes =
      vertices * sizeof(shared::GpuVertex) + triangles * (sizeof(GpuTriangle) + 3 * 16 + 4 * 16);
  ctx_.requireBufferFits(what, bytes, false, std::max(3 * triangles, 2 * vertices));
}

void GpuScene::uploadEnvironment() {
  EnvironmentTables tables;
  const std::optional<scene::EnvironmentAsset>& env = asset_.environment;
  if (env && env->hasMap()) {
    // Refused before anything is allocated: the texels and the CDFs are one buffer each.
    const uint64_t texels = shared::kEnvironmentHeaderTexels + uint64_t(env->width) * env->height;
    ctx_.requireBufferFits("the environment map " + env->name + " (" + std::to_string(env->width) +
                               "x" + std::to_string(env->height) + " texels; use a smaller map)",
                           texels * 16, false, texels);
    tables = buildEnvironmentTables(*env);
    environmentTileIntegrals_ = tables.tileLuminanceIntegrals;
  } else {
    tables.texels.assign(shared::kEnvironmentHeaderTexels, glm::vec4(0.0f));  // never read
    tables.cdf.assign(1, 0.0f);
  }
  envTexels_ = makeBuffer(ctx_, tables.texels, "scene.environmentTexels", gpu::kTexelTableUsage);
  envCdf_ = makeBuffer(ctx_, tables.cdf, "scene.environmentCdf", gpu::kTexelTableUsage);
  envTexelsView_ =
      std::make_unique<gpu::BufferView>(ctx_, *envTexels_, VK_FORMAT_R32G32B32A32_SFLOAT);
  envCdfView_ = std::make_unique<gpu::BufferView>(ctx_, *envCdf_, VK_FORMAT_R32_SFLOAT);
}

std::vector<GpuLight> GpuScene::skyLights(const scene::EnvironmentAsset& env) const {
  GpuLight sky{};
  sky.type = shared::kLightSky;  // the sky's lights come last (the shader looks there on a miss)
  sky.emission = env.scale();
  // Selection weight: the power entering the scene's bounding sphere, pi r^2 times the
  // luminance integrated over the directions (a uniform sky: 4 pi L).
  const double crossSection = kPi * double(radius_) * radius_ * luminance(sky.emission);
  auto weight = [&](double integral) {
    const float power = float(crossSection * integral);
    return power > 0.0f && std::isfinite(power) ? power : 0.0f;
  };
  if (!env.hasMap()) {
    sky.power = weight(4.0 * kPi);
    return {sky};
  }
  // A light per tile, `triangle` naming the tile; all of them, so that tile t is light
  // first + t, even where a tile is black.
  std::vector<GpuLight> tiles;
  sky.flags = shared::kLightEnvironmentMap;
  for (size_t t = 0; t < environmentTileIntegrals_.size(); ++t) {
    sky.triangle = uint32_t(t);
    sky.power = weight(environmentTileIntegrals_[t]);
    tiles.push_back(sky);
  }
  return tiles;
}

void GpuScene::uploadStatic() {
  PackedVertices vertices = packVertices(asset_.meshes);
  meshFirstVertex_ = vertices.firstVertex;
  hasVertexExtras_ = vertices.anyExtras;
  for (size_t m = 0; m < asset_.meshes.size(); ++m) {
    const scene::MeshAsset& mesh = asset_.meshes[m];
    meshFirstTriangle_.push_back(uint32_t(triangles_.size()));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      GpuTriangle tri{};
      tri.v0 = meshFirstVertex_[m] + mesh.indices[t * 3];
      tri.v1 = meshFirstVertex_[m] + mesh.indices[t * 3 + 1];
      tri.v2 = meshFirstVertex_[m] + mesh.indices[t * 3 + 2];
      tri.material = mesh.triangleMaterials[t];
      tri.light = shared::kNoLight;
      tri.vertexExtras = vertices.extrasTexel[m];
      triangles_.push_back(tri);
    }
  }
  triangleCount_ = uint32_t(triangles_.size());
  std::vector<GpuMaterial> materials;
  for (auto& m : asset_.materials) {
    materials.push_back(packMaterial(m));
    hasTextures_ |= usesTextures(m);
    hasAlphaTest_ |= m.alphaMode != scene::AlphaMode::Opaque;
    hasMicrofacet_ |= !m.unlit && !exactlyLambertian(m);
  }
  if (materials.empty()) materials.push_back(packMaterial(scene::MaterialAsset{}));

  // Refused before anything is allocated: all textures share one texel buffer, mipmaps
  // included.
  uint64_t texelCount = 0;
  for (const scene::TextureAsset& t : asset_.textures)
    texelCount += mipChainTexels(t.width, t.height);
  ctx_.requireBufferFits("the scene's textures (" + std::to_string(asset_.textures.size()) +
                             " images, " + std::to_string(texelCount) +
                             " texels with their mipmaps; use smaller or fewer images)",
                         texelCount * 4, false, texelCount);
  std::vector<GpuTexture> textures;
  std::vector<uint32_t> texels;
  for (const scene::TextureAsset& t : asset_.textures) {
    const uint32_t levels = mipLevelCount(t.width, t.height);
    textures.push_back({uint32_t(texels.size()), t.width, t.height,
                        textureFlags(t) | (levels << shared::kTextureLevelShift)});
    const std::vector<uint32_t> chain = buildMipChain(t);
    texels.insert(texels.end(), chain.begin(), chain.end());
  }
  if (texels.empty()) texels.push_back(0xffffffffu);
  if (textures.empty()) textures.push_back({0, 1, 1, 0});

  vertices_ = makeBuffer(ctx_, vertices.texels, "scene.vertices", gpu::kTexelTableUsage);
  materials_ = makeBuffer(ctx_, materials, "scene.materials", gpu::kTexelTableUsage);
  verticesView_ =
      std::make_unique<gpu::BufferView>(ctx_, *vertices_, VK_FORMAT_R32G32B32A32_SFLOAT);
  materialsView_ =
      std::make_unique<gpu::BufferView>(ctx_, *materials_, VK_FORMAT_R32G32B32A32_SFLOAT);
  textures_ = makeBuffer(ctx_, textures, "scene.textures", gpu::kTexelTableUsage);
  texturesView_ = std::make_unique<gpu::BufferView>(ctx_, *textures_, VK_FORMAT_R32G32B32A32_UINT);
  texels_ = makeBuffer(ctx_, texels, "scene.texels", gpu::kTexelTableUsage);
  texelView_ = std::make_unique<gpu::BufferView>(ctx_, *texels_, VK_FORMAT_R32_UINT);
}

void GpuScene::uploadLights(const SceneDraw& draw) {
  lights_.clear();
  for (GpuTriangle& t : triangles_) t.light = shared::kNoLight;
  // A scene whose emitters are all glow maps (emissive textures) and nothing else is a model
  // made to be seen under the viewer's light: it gets the fallback sky as well.
  bool glowOnly = true, anyEmitter = false;
  // Emissive triangles, in world space at this frame.
  for (const MeshDraw& d : draw.meshes) {
    const scene::MeshAsset& mesh = asset_.meshes[d.mesh];
    const std::vector<glm::vec3>& positions = positionsOf(d.mesh);
    bool mirrored = glm::determinant(glm::mat3(d.worldFromObject)) < 0.0f;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      const scene::MaterialAsset& m = asset_.materials[mesh.triangleMaterials[t]];
      if (!m.isEmissive()) continue;
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = glm::vec3(d.worldFromObject * glm::vec4(positions[mesh.indices[t * 3 + k]], 1.0f));
      GpuLight l{};
      l.type = shared::kLightTriangle;
      l.position = p[0];
      l.edge1 = p[1] - p[0];
      l.edge2 = p[2] - p[0];
      l.area = 0.5f * glm::length(glm::cross(l.edge1, l.edge2));
      if (!(l.area > 0.0f)) continue;  // degenerate: cannot be sampled or hit
      l.triangle = meshFirstTriangle_[d.mesh] + uint32_t(t);
      l.emission = m.emissive;
      l.flags = (m.doubleSided ? shared::kLightDoubleSided : 0u) |
                (mirrored ? shared::kLightMirrored : 0u);
      glowOnly &= m.emissiveTexture.present();
      anyEmitter = true;
      l.power =
          luminance(triangleEmissions_[d.mesh][t]) * l.area * kPi * (m.doubleSided ? 2.0f : 1.0f);
      if (!(l.power > 0.0f)) continue;  // black texels only: found by scattered rays alone
      // A triangle instanced twice is one light per instance; the hit maps to the last.
      triangles_[l.triangle].light = uint32_t(lights_.size());
      lights_.push_back(l);
    }
  }
  for (const PunctualDraw& d : draw.lights) {
    GpuLight l{};
    const scene::LightAsset& a = d.light;
    l.emission = a.color * a.intensity;
    l.position = glm::vec3(d.worldFromLight[3]);
    l.edge1 = glm::normalize(glm::vec3(d.worldFromLight * glm::vec4(0, 0, -1, 0)));
    l.range = a.range;
    l.cosInner = std::cos(a.innerConeAngle);
    l.cosOuter = std::cos(a.outerConeAngle);
    float lum = luminance(l.emission);
    if (a.type == scene::LightType::Point) {
      l.type = shared::kLightPoint;
      l.power = 4.0f * kPi * lum;
    } else if (a.type == scene::LightType::Spot) {
      l.type = shared::kLightSpot;
      l.power = 2.0f * kPi * (1.0f - 0.5f * (l.cosInner + l.cosOuter)) * lum;
    } else {
      l.type = shared::kLightDirectional;
      l.power = kPi * radius_ * radius_ * lum;
    }
    if (l.power > 0.0f && std::isfinite(l.power)) lights_.push_back(l);
    glowOnly = false;
    anyEmitter = true;
  }
  // The user's environment lights the scene whatever else does; without one, a scene with no
  // light gets the fallback sky.
  const std::optional<scene::EnvironmentAsset>& env = asset_.environment;
  glowMapsOnly_ = anyEmitter && glowOnly;
  fallbackSky_ = !env && (lights_.empty() || glowMapsOnly_) && options_.fallbackSkyRadiance > 0.0f;
  std::vector<GpuLight> sky;
  if (env) {
    sky = skyLights(*env);
  } else if (fallbackSky_) {
    scene::EnvironmentAsset fallback;
    fallback.color = glm::vec3(options_.fallbackSkyRadiance);
    sky = skyLights(fallback);
    if (lights_.empty()) sky[0].power = 1.0f;  // the only light
  }
  float skyPower = 0.0f;
  for (const GpuLight& l : sky) skyPower += l.power;
  environmentLit_ = env && skyPower > 0.0f;
  if (skyPower > 0.0f) lights_.insert(lights_.end(), sky.begin(), sky.end());
  lightCount_ = uint32_t(lights_.size());
  hasNonTriangleLights_ = std::any_of(lights_.begin(), lights_.end(), [](const GpuLight& l) {
    return l.type != shared::kLightTriangle;
  });
  std::vector<float> cdf;
  float running = 0.0f;
  for (const GpuLight& l : lights_) cdf.push_back(running += l.power);
  if (cdf.empty()) cdf.push_back(0.0f);

  lightCdfView_.reset();
  triangleView_.reset();
  lightView_.reset();
  lightBuffer_ = makeBuffer(ctx_, lights_, "scene.lights", gpu::kTexelTableUsage);
  lightView_ = std::make_unique<gpu::BufferView>(ctx_, *lightBuffer_, VK_FORMAT_R32G32B32A32_UINT);
  lightCdf_ = makeBuffer(ctx_, cdf, "scene.lightCdf", gpu::kTexelTableUsage);
  triangleBuffer_ = makeBuffer(ctx_, triangles_, "scene.triangles", gpu::kTexelTableUsage);
  lightCdfView_ = std::make_unique<gpu::BufferView>(ctx_, *lightCdf_, VK_FORMAT_R32_SFLOAT);
  triangleView_ =
      std::make_unique<gpu::BufferView>(ctx_, *triangleBuffer_, VK_FORMAT_R32G32B32A32_UINT);
}

const std::vector<glm::vec3>& GpuScene::positionsOf(uint32_t mesh) const {
  return posedPositions_[mesh].empty() ? asset_.meshes[mesh].positions : posedPositions_[mesh];
}

bool GpuScene::applyDeformations(const std::vector<DeformedDraw>& deformed) {
  bool changed = false;
  for (const DeformedDraw& d : deformed) {
    if (d.mesh >= asset_.meshes.size()) throw std::out_of_range("deformed draw names no mesh");
    const scene::MeshAsset& mesh = asset_.meshes[d.mesh];
    if (d.positions.size() != mesh.positions.size() || d.normals.size() != mesh.positions.size())
      throw std::invalid_argument("deformed draw of mesh " + std::to_string(d.mesh) +
                                  " has another vertex count than the mesh");
    if (poseVersions_[d.mesh] == d.version) continue;
    poseVersions_[d.mesh] = d.version;
    posedPositions_[d.mesh].assign(d.positions.begin(), d.positions.end());
    std::vector<shared::GpuVertex> vertices;
    vertices.reserve(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      vertices.push_back(packVertex(mesh, i, d.positions[i], d.normals[i]));
    vertices_->upload(ctx_, std::span<const shared::GpuVertex>(vertices),
                      VkDeviceSize(meshFirstVertex_[d.mesh]) * sizeof(shared::GpuVertex));
    accel_.refitMesh(d.mesh, d.positions, mesh.indices);
    changed = true;
  }
  return changed;
}

void GpuScene::update(const SceneDraw& draw) {
  for (const MeshDraw& d : draw.meshes)
    if (d.mesh >= asset_.meshes.size()) throw std::out_of_range("mesh draw names no mesh");
  applyDeformations(draw.deformed);
  accel_.buildInstances(draw.meshes);
  const bool trianglesMoved = !bvhTris_ || accel_.trianglesVersion() != uploadedTriangles_;
  uploadedTriangles_ = accel_.trianglesVersion();
  surfaceArea_ = 0.0f;
  for (const MeshDraw& d : draw.meshes) {
    const scene::MeshAsset& mesh = asset_.meshes[d.mesh];
    const std::vector<glm::vec3>& positions = positionsOf(d.mesh);
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = glm::vec3(d.worldFromObject * glm::vec4(positions[mesh.indices[t * 3 + k]], 1.0f));
      surfaceArea_ += 0.5f * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    }
  }
  std::vector<shared::GpuInstance> instances;
  for (const MeshDraw& d : draw.meshes) {
    shared::GpuInstance inst{};
    glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(d.worldFromObject)));
    for (int r = 0; r < 3; ++r)
      inst.normalFromObject[r] = glm::vec4(n[0][r], n[1][r], n[2][r], 0.0f);
    const glm::mat3 m(d.worldFromObject);
    for (int r = 0; r < 3; ++r)
      inst.tangentFromObject[r] = glm::vec4(m[0][r], m[1][r], m[2][r], 0.0f);
    inst.worldScale = std::max(std::max(glm::length(m[0]), glm::length(m[1])), glm::length(m[2]));
    inst.firstTriangle = meshFirstTriangle_[d.mesh];
    inst.mesh = d.mesh;
    instances.push_back(inst);
  }
  instancesView_.reset();
  instances_ = makeBuffer(ctx_, instances, "scene.instances", gpu::kTexelTableUsage);
  instancesView_ =
      std::make_unique<gpu::BufferView>(ctx_, *instances_, VK_FORMAT_R32G32B32A32_UINT);
  bvhNodesView_.reset();
  bvhInstancesView_.reset();
  bvhNodes_ = makeBuffer(ctx_, accel_.nodeTexels(), "bvh.nodes", gpu::kTexelTableUsage);
  bvhInstances_ = makeBuffer(ctx_, accel_.instanceTexels(), "bvh.instances", gpu::kTexelTableUsage);
  bvhNodesView_ =
      std::make_unique<gpu::BufferView>(ctx_, *bvhNodes_, VK_FORMAT_R32G32B32A32_SFLOAT);
  bvhInstancesView_ =
      std::make_unique<gpu::BufferView>(ctx_, *bvhInstances_, VK_FORMAT_R32G32B32A32_SFLOAT);
  if (trianglesMoved) {  // rigid motion of unmerged instances leaves the triangles as they are
    bvhTrisView_.reset();
    bvhTris_ = makeBuffer(ctx_, accel_.triangleTexels(), "bvh.triangles", gpu::kTexelTableUsage);
    bvhTrisView_ =
        std::make_unique<gpu::BufferView>(ctx_, *bvhTris_, VK_FORMAT_R32G32B32A32_SFLOAT);
  }
  uploadLights(draw);
}

uint64_t GpuScene::memoryBytes() const {
  uint64_t bytes = 0;
  for (const auto* b : {&vertices_, &triangleBuffer_, &materials_, &textures_, &texels_, &bvhNodes_,
                        &bvhTris_, &bvhInstances_, &instances_, &lightBuffer_, &lightCdf_})
    if (*b) bytes += (*b)->size();
  return bytes;
}

std::vector<uint32_t> GpuScene::specializationFeatures() const {
  std::vector<uint32_t> features(shared::kSpecPathFeatureCount, 0);
  features[shared::kSpecUseTextures] = hasTextures();
  features[shared::kSpecUseNonTriangleLights] = hasNonTriangleLights();
  features[shared::kSpecUseVertexExtras] = hasVertexExtras();
  features[shared::kSpecUseEnvironmentMap] = hasEnvironmentMap();
  features[shared::kSpecUseAlphaTest] = hasAlphaTest();
  features[shared::kSpecUseMicrofacet] = hasMicrofacet();
  return features;
}

void GpuScene::bind(gpu::PassBuilder& pass) const {
  bindSurfaces(pass);
  pass.read(QL_BIND_LIGHTS, *lightView_)
      .read(QL_BIND_LIGHT_CDF, *lightCdfView_)
      .read(QL_BIND_ENV_TEXELS, *envTexelsView_)
      .read(QL_BIND_ENV_CDF, *envCdfView_);
}

void GpuScene::bindSurfaces(gpu::PassBuilder& pass) const {
  if (!instances_) throw std::logic_error("GpuScene::update must run before the first frame");
  pass.read(QL_BIND_BVH_NODES, *bvhNodesView_)
      .read(QL_BIND_BVH_TRIS, *bvhTrisView_)
      .read(QL_BIND_BVH_INSTANCES, *bvhInstancesView_)
      .read(QL_BIND_TRIANGLES, *triangleView_)
      .read(QL_BIND_VERTICES, *verticesView_)
      .read(QL_BIND_INSTANCES, *instancesView_)
      .read(QL_BIND_MATERIALS, *materialsView_)
      .read(QL_BIND_TEXTURES, *texturesView_)
      .read(QL_BIND_TEXELS, *texelView_);
}

}  // namespace qlight::render

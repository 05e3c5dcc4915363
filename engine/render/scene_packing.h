// Scene data in the GPU layouts of shaders/shared/scene_types.h: materials with their
// texture views, and vertices with the optional attributes of the meshes that have them.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/scene_asset.h"
#include "shaders/shared/scene_types.h"

namespace qlight::render {

// One place that turns a mesh's vertex into the GPU's (static and deformed meshes alike).
shared::GpuVertex packVertex(const scene::MeshAsset& mesh, size_t i, glm::vec3 position,
                             glm::vec3 normal);

shared::GpuMaterial packMaterial(const scene::MaterialAsset& m);
// A binding's KHR_texture_transform as the shader applies it: uv' = (dot(u.xy, uv) + u.z,
// dot(v.xy, uv) + v.z).
struct TextureTransformRows {
  glm::vec3 u, v;
  glm::vec2 apply(glm::vec2 uv) const {
    return {u.x * uv.x + u.y * uv.y + u.z, v.x * uv.x + v.y * uv.y + v.z};
  }
};
TextureTransformRows textureTransformRows(const scene::TextureBinding& b);
bool usesTextures(const scene::MaterialAsset& m);
// Metallic 0, specular layer 0, no transmission: the BSDF is baseColor / pi.
bool exactlyLambertian(const scene::MaterialAsset& m);

// The vertex texel buffer: every mesh's GpuVertex entries, then the GpuVertexExtras of the
// meshes with TEXCOORD_1, COLOR_0 or tangents. firstVertex[i] is mesh i's first vertex,
// extrasTexel[i] the GpuTriangle::vertexExtras value of its triangles.
struct PackedVertices {
  std::vector<glm::vec4> texels;
  std::vector<uint32_t> firstVertex;
  std::vector<uint32_t> extrasTexel;
  bool anyExtras = false;
};
PackedVertices packVertices(const std::vector<scene::MeshAsset>& meshes);

}  // namespace qlight::render

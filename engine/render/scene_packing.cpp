#include "engine/render/scene_packing.h"

#include <cmath>

namespace qlight::render {
namespace {

shared::GpuTextureView packView(const scene::TextureBinding& b) {
  const TextureTransformRows rows = textureTransformRows(b);
  shared::GpuTextureView v{};
  v.uRow = glm::vec4(rows.u, float(b.texCoord));
  v.vRow = glm::vec4(rows.v, float(b.index));
  return v;
}

bool hasExtras(const scene::MeshAsset& mesh) {
  return !mesh.uv1.empty() || !mesh.colors.empty() || !mesh.tangents.empty();
}

}  // namespace

TextureTransformRows textureTransformRows(const scene::TextureBinding& b) {
  const float c = std::cos(b.rotation), s = std::sin(b.rotation);
  // KHR_texture_transform: T * R * S with R = [[cos, sin], [-sin, cos]].
  return {{c * b.scale.x, s * b.scale.y, b.offset.x}, {-s * b.scale.x, c * b.scale.y, b.offset.y}};
}

shared::GpuVertex packVertex(const scene::MeshAsset& mesh, size_t i, glm::vec3 position,
                             glm::vec3 normal) {
  return {position, mesh.uv0[i].x, normal, mesh.uv0[i].y};
}

shared::GpuMaterial packMaterial(const scene::MaterialAsset& m) {
  shared::GpuMaterial g{};
  g.baseColor = m.baseColorFactor;
  g.emissive = m.emissive;
  g.metallic = m.metallicFactor;
  g.roughness = m.roughnessFactor;
  g.specular = m.specularFactor;
  uint32_t flags = m.doubleSided ? shared::kMaterialDoubleSided : 0u;
  if (m.unlit) flags |= shared::kMaterialUnlit;
  if (m.alphaMode == scene::AlphaMode::Mask) flags |= shared::kMaterialAlphaMask;
  if (m.alphaMode == scene::AlphaMode::Blend) flags |= shared::kMaterialAlphaBlend;
  if (m.volume) flags |= shared::kMaterialVolume;
  g.alphaCutoff = m.alphaCutoff;
  g.transmission = m.transmissionFactor;
  g.ior = m.ior;
  g.flags = float(flags);
  g.normalScale = m.normalScale;
  g.textures[shared::kTextureSlotBaseColor] = packView(m.baseColorTexture);
  g.textures[shared::kTextureSlotMetallicRoughness] = packView(m.metallicRoughnessTexture);
  g.textures[shared::kTextureSlotEmissive] = packView(m.emissiveTexture);
  g.textures[shared::kTextureSlotNormal] = packView(m.normalTexture);
  return g;
}

bool exactlyLambertian(const scene::MaterialAsset& m) {
  // The metallic texture only scales the factor; a specular layer of weight 0 is none.
  return m.metallicFactor == 0.0f && m.specularFactor == 0.0f && m.transmissionFactor == 0.0f;
}

bool usesTextures(const scene::MaterialAsset& m) {
  return m.baseColorTexture.present() || m.metallicRoughnessTexture.present() ||
         m.emissiveTexture.present() || m.normalTexture.present();
}

PackedVertices packVertices(const std::vector<scene::MeshAsset>& meshes) {
  PackedVertices out;
  size_t vertexCount = 0;
  for (const scene::MeshAsset& mesh : meshes) {
    out.firstVertex.push_back(uint32_t(vertexCount));
    vertexCount += mesh.positions.size();
  }
  out.texels.reserve(2 * vertexCount);
  for (const scene::MeshAsset& mesh : meshes)
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      const shared::GpuVertex v = packVertex(mesh, i, mesh.positions[i], mesh.normals[i]);
      out.texels.emplace_back(v.position, v.u);
      out.texels.emplace_back(v.normal, v.v);
    }
  for (size_t m = 0; m < meshes.size(); ++m) {
    const scene::MeshAsset& mesh = meshes[m];
    if (!hasExtras(mesh)) {
      out.extrasTexel.push_back(shared::kNoVertexExtras);
      continue;
    }
    out.anyExtras = true;
    // Unsigned wrap-around: the shader adds 3 x the global vertex index back.
    out.extrasTexel.push_back(uint32_t(out.texels.size()) -
                              shared::kVertexExtrasTexels * out.firstVertex[m]);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      out.texels.push_back(mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[i]);
      out.texels.push_back(mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i]);
      out.texels.emplace_back(mesh.uv1.empty() ? glm::vec2(0.0f) : mesh.uv1[i], 0.0f, 0.0f);
    }
  }
  return out;
}

}  // namespace qlight::render

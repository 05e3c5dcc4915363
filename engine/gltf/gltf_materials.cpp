// glTF materials and textures into MaterialAsset / TextureAsset.
#include <algorithm>

#include "engine/gltf/gltf_convert.h"

namespace qlight::gltf::detail {
namespace {

double numberOr(const tinygltf::Value& object, const char* key, double fallback,
                const std::string& what, LoadContext& ctx) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber()) ctx.fail(what + " " + key + " is not a number");
  const double x = v.GetNumberAsDouble();
  ctx.requireFinite(x, what + " " + key);
  return x;
}

glm::vec2 vec2Or(const tinygltf::Value& object, const char* key, glm::vec2 fallback,
                 const std::string& what, LoadContext& ctx) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
    ctx.fail(what + " " + key + " needs 2 numbers");
  glm::vec2 out(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
  ctx.requireFinite(out.x, what + " " + key);
  ctx.requireFinite(out.y, what + " " + key);
  return out;
}

// A texture reference with its UV set and KHR_texture_transform (whose texCoord, when
// given, overrides the reference's).
TextureBinding textureBinding(const tinygltf::Model& model, int index, int texCoord,
                              const tinygltf::ExtensionMap& extensions, const std::string& owner,
                              LoadContext& ctx) {
  TextureBinding b;
  if (index < 0) return b;
  if (size_t(index) >= model.textures.size())
    ctx.fail(owner + " uses texture " + std::to_string(index) + ", which does not exist (" +
             std::to_string(model.textures.size()) + " textures)");
  b.index = index;
  auto it = extensions.find("KHR_texture_transform");
  if (it != extensions.end() && it->second.IsObject()) {
    const tinygltf::Value& t = it->second;
    const std::string what = owner + " KHR_texture_transform";
    b.offset = vec2Or(t, "offset", b.offset, what, ctx);
    b.rotation = float(numberOr(t, "rotation", 0.0, what, ctx));
    b.scale = vec2Or(t, "scale", b.scale, what, ctx);
    texCoord = int(numberOr(t, "texCoord", texCoord, what, ctx));
  }
  if (texCoord == 0 || texCoord == 1) {
    b.texCoord = uint32_t(texCoord);
  } else {
    ctx.warn(owner + " reads TEXCOORD_" + std::to_string(texCoord) +
             "; only TEXCOORD_0 and TEXCOORD_1 are loaded, so TEXCOORD_0 is used");
  }
  return b;
}

TextureBinding textureBinding(const tinygltf::Model& model, const tinygltf::TextureInfo& info,
                              const std::string& owner, LoadContext& ctx) {
  return textureBinding(model, info.index, info.texCoord, info.extensions, owner, ctx);
}

float unitFactor(double value, const std::string& what, LoadContext& ctx) {
  ctx.requireFinite(value, what);
  if (value < 0.0 || value > 1.0) {
    ctx.warn(what + " " + std::to_string(value) + " is outside [0, 1]; clamped");
    value = std::clamp(value, 0.0, 1.0);
  }
  return float(value);
}

float emissiveStrength(const tinygltf::Material& material, const std::string& owner,
                       LoadContext& ctx) {
  auto it = material.extensions.find("KHR_materials_emissive_strength");
  if (it == material.extensions.end()) return 1.0f;
  const tinygltf::Value& ext = it->second;
  if (!ext.IsObject() || !ext.Has("emissiveStrength")) return 1.0f;
  const tinygltf::Value& strength = ext.Get("emissiveStrength");
  if (!strength.IsNumber()) ctx.fail(owner + " emissiveStrength is not a number");
  const double value = strength.GetNumberAsDouble();
  ctx.requireFinite(value, owner + " emissiveStrength");
  if (value < 0.0) ctx.fail(owner + " emissiveStrength is negative");
  return float(value);
}

// KHR_materials_specular: only specularFactor (specularColorFactor is ignored, with a warning
// when it is not white).
float specularFactorOf(const tinygltf::Material& material, const std::string& owner,
                       LoadContext& ctx) {
  auto it = material.extensions.find("KHR_materials_specular");
  if (it == material.extensions.end() || !it->second.IsObject()) return 1.0f;
  const tinygltf::Value& ext = it->second;
  if (ext.Has("specularTexture") || ext.Has("specularColorTexture"))
    ctx.warn(owner + " KHR_materials_specular textures are ignored");
  if (ext.Has("specularColorFactor"))
    ctx.warn(owner + " KHR_materials_specular specularColorFactor is ignored");
  if (!ext.Has("specularFactor")) return 1.0f;
  const tinygltf::Value& factor = ext.Get("specularFactor");
  if (!factor.IsNumber()) ctx.fail(owner + " specularFactor is not a number");
  return unitFactor(factor.GetNumberAsDouble(), owner + " specularFactor", ctx);
}

// KHR_materials_transmission (the factor; its texture is ignored with a warning).
float transmissionOf(const tinygltf::Material& material, const std::string& owner,
                     LoadContext& ctx) {
  auto it = material.extensions.find("KHR_materials_transmission");
  if (it == material.extensions.end() || !it->second.IsObject()) return 0.0f;
  if (it->second.Has("transmissionTexture"))
    ctx.warn(owner + " KHR_materials_transmission transmissionTexture is ignored");
  const double t = numberOr(it->second, "transmissionFactor", 0.0, owner, ctx);
  return unitFactor(t, owner + " transmissionFactor", ctx);
}

// KHR_materials_ior: at least 1 (the extension's 0, "no refraction", is not modelled).
float iorOf(const tinygltf::Material& material, const std::string& owner, LoadContext& ctx) {
  auto it = material.extensions.find("KHR_materials_ior");
  if (it == material.extensions.end() || !it->second.IsObject()) return 1.5f;
  const double ior = numberOr(it->second, "ior", 1.5, owner, ctx);
  if (ior < 1.0) {
    ctx.warn(owner + " ior " + std::to_string(ior) + " is below 1; 1.5 used");
    return 1.5f;
  }
  return float(ior);
}

// KHR_materials_volume: a thickness above 0 makes the mesh a solid; attenuation is not
// modelled (a warning when it would tint).
bool volumeOf(const tinygltf::Material& material, const std::string& owner, LoadContext& ctx) {
  auto it = material.extensions.find("KHR_materials_volume");
  if (it == material.extensions.end() || !it->second.IsObject()) return false;
  const tinygltf::Value& v = it->second;
  if (v.Has("attenuationDistance") || v.Has("attenuationColor"))
    ctx.warn(owner + " KHR_materials_volume attenuation is ignored");
  return numberOr(v, "thicknessFactor", 0.0, owner, ctx) > 0.0;
}

AlphaMode alphaModeOf(const std::string& mode, const std::string& owner, LoadContext& ctx) {
  if (mode == "MASK") return AlphaMode::Mask;
  if (mode == "BLEND") return AlphaMode::Blend;
  if (mode != "OPAQUE" && !mode.empty())
    ctx.warn(owner + " alphaMode '" + mode + "' is unknown; OPAQUE used");
  return AlphaMode::Opaque;
}

TextureWrap wrapOf(int code, const std::string& owner, LoadContext& ctx) {
  switch (code) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT:
      return TextureWrap::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return TextureWrap::MirroredRepeat;
    default:
      ctx.warn(owner + " wrap mode " + std::to_string(code) + " is unknown; REPEAT used");
      return TextureWrap::Repeat;
  }
}

void makeWhite(TextureAsset& texture) {
  texture.width = texture.height = 1;
  texture.rgba8 = {255, 255, 255, 255};
}

// Expands the decoded image (1-4 channels, 8 or 16 bits) to RGBA8.
void copyPixels(const tinygltf::Image& image, const std::string& owner, TextureAsset& texture,
                LoadContext& ctx) {
  const int channels = image.component;
  const int bytesPerChannel = image.bits / 8;
  if (image.width < 1 || image.height < 1 || channels < 1 || channels > 4 ||
      (image.bits != 8 && image.bits != 16))
    ctx.fail(owner + " decoded to an unusable format (" + std::to_string(image.width) + "x" +
             std::to_string(image.height) + ", " + std::to_string(channels) + " channels, " +
             std::to_string(image.bits) + " bits)");
  const size_t pixels = size_t(image.width) * size_t(image.height);
  if (image.image.size() != pixels * channels * bytesPerChannel)
    ctx.fail(owner + " holds " + std::to_string(image.image.size()) +
             " bytes, not what its size says");
  texture.width = uint32_t(image.width);
  texture.height = uint32_t(image.height);
  texture.rgba8.assign(pixels * 4, 255);
  for (size_t p = 0; p < pixels; ++p) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < channels; ++k) {
      // 16-bit: the high byte (little-endian storage from stb).
      const size_t at = (p * channels + k) * bytesPerChannel + (bytesPerChannel - 1);
      c[k] = image.image[at];
    }
    if (channels <= 2) {  // grey (+ alpha)
      const uint8_t alpha = channels == 2 ? c[1] : 255;
      c[1] = c[2] = c[0];
      c[3] = alpha;
    }
    std::copy(c, c + 4, texture.rgba8.begin() + p * 4);
  }
}

}  // namespace

void convertMaterials(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const std::string owner = "material " + std::to_string(i);
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    MaterialAsset out;
    out.name = m.name;

    if (pbr.baseColorFactor.size() != 4) ctx.fail(owner + " baseColorFactor needs 4 numbers");
    for (int c = 0; c < 4; ++c)
      out.baseColorFactor[c] = unitFactor(pbr.baseColorFactor[c], owner + " baseColorFactor", ctx);
    out.metallicFactor = unitFactor(pbr.metallicFactor, owner + " metallicFactor", ctx);
    out.roughnessFactor = unitFactor(pbr.roughnessFactor, owner + " roughnessFactor", ctx);
    out.baseColorTexture =
        textureBinding(model, pbr.baseColorTexture, owner + " baseColorTexture", ctx);
    out.metallicRoughnessTexture = textureBinding(model, pbr.metallicRoughnessTexture,
                                                  owner + " metallicRoughnessTexture", ctx);

    if (!m.emissiveFactor.empty() && m.emissiveFactor.size() != 3)
      ctx.fail(owner + " emissiveFactor needs 3 numbers");
    const float strength = emissiveStrength(m, owner, ctx);
    for (size_t c = 0; c < m.emissiveFactor.size(); ++c)
      out.emissive[int(c)] =
          unitFactor(m.emissiveFactor[c], owner + " emissiveFactor", ctx) * strength;
    out.emissiveTexture = textureBinding(model, m.emissiveTexture, owner + " emissiveTexture", ctx);

    out.specularFactor = specularFactorOf(m, owner, ctx);
    out.doubleSided = m.doubleSided;
    out.alphaMode = alphaModeOf(m.alphaMode, owner, ctx);
    ctx.requireFinite(m.alphaCutoff, owner + " alphaCutoff");
    out.alphaCutoff = float(m.alphaCutoff);
    out.normalTexture = textureBinding(model, m.normalTexture.index, m.normalTexture.texCoord,
                                       m.normalTexture.extensions, owner + " normalTexture", ctx);
    ctx.requireFinite(m.normalTexture.scale, owner + " normalTexture scale");
    out.normalScale = float(m.normalTexture.scale);
    out.unlit = m.extensions.count("KHR_materials_unlit") > 0;
    out.transmissionFactor = transmissionOf(m, owner, ctx);
    out.ior = iorOf(m, owner, ctx);
    out.volume = volumeOf(m, owner, ctx);
    scene.materials.push_back(out);
  }
}

void convertTextures(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  // A texture is sRGB when some material reads it as color (baseColor, emissive).
  std::vector<int> colorUses(model.textures.size(), 0), dataUses(model.textures.size(), 0);
  for (const MaterialAsset& m : scene.materials) {
    if (m.baseColorTexture.present()) ++colorUses[size_t(m.baseColorTexture.index)];
    if (m.emissiveTexture.present()) ++colorUses[size_t(m.emissiveTexture.index)];
    if (m.metallicRoughnessTexture.present()) ++dataUses[size_t(m.metallicRoughnessTexture.index)];
    if (m.normalTexture.present()) ++dataUses[size_t(m.normalTexture.index)];
  }

  for (size_t i = 0; i < model.textures.size(); ++i) {
    const tinygltf::Texture& t = model.textures[i];
    const std::string owner = "texture " + std::to_string(i);
    TextureAsset out;
    out.name = t.name;
    out.srgb = colorUses[i] > 0;
    if (colorUses[i] > 0 && dataUses[i] > 0)
      ctx.warn(owner + " is used both as color (sRGB) and as data; treated as sRGB");

    if (t.source < 0) {
      ctx.warn(owner + " has no image source (a texture extension?); white used");
      makeWhite(out);
    } else if (size_t(t.source) >= model.images.size()) {
      ctx.fail(owner + " uses image " + std::to_string(t.source) + ", which does not exist");
    } else if (model.images[size_t(t.source)].image.empty()) {
      ctx.warn(owner + " image " + std::to_string(t.source) + " could not be loaded; white used");
      makeWhite(out);
    } else {
      copyPixels(model.images[size_t(t.source)], "image " + std::to_string(t.source), out, ctx);
    }

    if (t.sampler >= 0) {
      if (size_t(t.sampler) >= model.samplers.size())
        ctx.fail(owner + " uses sampler " + std::to_string(t.sampler) + ", which does not exist");
      const tinygltf::Sampler& s = model.samplers[size_t(t.sampler)];
      const std::string samplerName = "sampler " + std::to_string(t.sampler);
      out.wrapS = wrapOf(s.wrapS, samplerName, ctx);
      out.wrapT = wrapOf(s.wrapT, samplerName, ctx);
      out.nearestFilter = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    scene.textures.push_back(std::move(out));
  }
}

}  // namespace qlight::gltf::detail

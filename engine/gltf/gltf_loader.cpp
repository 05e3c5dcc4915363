#include "engine/gltf/gltf_loader.h"

#include <tiny_gltf.h>

#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_context.h"
#include "engine/gltf/gltf_convert.h"
#include "engine/gltf/gltf_file_check.h"
#include "engine/scene/animation.h"
#include "engine/scene/deform.h"
#include "engine/scene/tangents.h"
#include "engine/scene/transforms.h"

namespace qlight::gltf {
namespace {

// tinygltf's stb decoder, except that an image it cannot decode is a warning (the texture
// becomes white) rather than a failure of the whole file.
bool decodeImageOrWarn(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
                       int width, int height, const unsigned char* bytes, int size, void*) {
  std::string problem;
  if (tinygltf::LoadImageData(image, index, &problem, warn, width, height, bytes, size, nullptr))
    return true;
  (void)err;
  if (warn) *warn += "image " + std::to_string(index) + " could not be decoded: " + problem + "\n";
  image->image.clear();
  return true;
}

tinygltf::Model parseWithTinygltf(const detail::CheckedGltfFile& file, detail::LoadContext& ctx) {
  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(decodeImageOrWarn, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = file.binary
                      ? parser.LoadBinaryFromMemory(&model, &error, &warning, file.bytes.data(),
                                                    unsigned(file.bytes.size()), file.baseDir)
                      : parser.LoadASCIIFromString(&model, &error, &warning,
                                                   reinterpret_cast<const char*>(file.bytes.data()),
                                                   unsigned(file.bytes.size()), file.baseDir);
  if (!warning.empty()) ctx.warn("tinygltf: " + warning);
  if (!ok) ctx.fail(error.empty() ? "tinygltf could not parse the file" : error);
  return model;
}

void warnAboutUnusedExtensions(const tinygltf::Model& model, detail::LoadContext& ctx) {
  for (const std::string& name : model.extensionsUsed)
    if (!detail::isSupportedRequiredExtension(name))
      ctx.warn("extension " + name + " is not supported and is ignored");
}

SceneAsset convertCheckedFile(const detail::CheckedGltfFile& file,
                              const std::filesystem::path& source, detail::LoadContext& ctx) {
  const tinygltf::Model model = parseWithTinygltf(file, ctx);
  warnAboutUnusedExtensions(model, ctx);

  // Every accessor, used or not, is checked against its buffer view and buffer before any read.
  for (size_t i = 0; i < model.accessors.size(); ++i)
    detail::checkAccessorBounds(model, int(i), "accessor " + std::to_string(i), ctx);

  SceneAsset scene;
  scene.source = source;
  detail::convertMaterials(model, scene, ctx);
  detail::convertTextures(model, scene, ctx);
  detail::convertMeshes(model, scene, ctx);
  qlight::scene::generateMissingTangents(scene);  // for normal maps, where the file has no TANGENT
  detail::convertNodes(model, scene, ctx);
  detail::convertSkins(model, scene, ctx);
  detail::convertMeshInstancing(model, scene, ctx);
  detail::convertCameras(model, scene, ctx);
  detail::convertLights(model, scene, ctx);
  detail::convertAnimations(model, scene, ctx);

  scene.bounds = posedWorldBounds(scene, 0.0f);
  detail::replaceOrthographicCameras(model, scene, ctx);
  scene.warnings = std::move(ctx.warnings());
  return scene;
}

}  // namespace

SceneAsset loadGltf(const std::filesystem::path& path) {
  detail::LoadContext ctx(path.string());
  return convertCheckedFile(detail::readAndCheckGltfFile(path, ctx), path, ctx);
}

SceneAsset loadGltfFromMemory(std::span<const uint8_t> bytes, const std::filesystem::path& baseDir,
                              const std::string& name) {
  detail::LoadContext ctx(name);
  return convertCheckedFile(
      detail::checkGltfBytes(std::vector<uint8_t>(bytes.begin(), bytes.end()), baseDir, ctx),
      baseDir / name, ctx);
}

}  // namespace qlight::gltf

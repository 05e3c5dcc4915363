#include "engine/gltf/gltf_file_check.h"

#include <array>
#include <cctype>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

namespace qlight::gltf::detail {
namespace {

using nlohmann::json;

constexpr uint64_t kMaxFileBytes = uint64_t(1) << 31;  // tinygltf indexes with int in places
constexpr uint32_t kGlbMagic = 0x46546C67;             // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;            // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;             // "BIN\0"

// The data URI prefixes tinygltf decodes; any other data URI it would treat as a file name.
constexpr std::array<const char*, 7> kDataUriPrefixes = {"data:application/octet-stream;base64,",
                                                         "data:application/gltf-buffer;base64,",
                                                         "data:image/jpeg;base64,",
                                                         "data:image/png;base64,",
                                                         "data:image/bmp;base64,",
                                                         "data:image/gif;base64,",
                                                         "data:text/plain;base64,"};

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;  // GLB is little-endian, as is every machine qlight runs on
}

std::vector<uint8_t> readWholeFile(const std::filesystem::path& path, LoadContext& ctx) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) ctx.fail("file not found");
  if (!std::filesystem::is_regular_file(path, ec)) ctx.fail("not a regular file");
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) ctx.fail("cannot read the file size: " + ec.message());
  if (size == 0) ctx.fail("file is empty");
  if (size > kMaxFileBytes) ctx.fail("file is larger than 2 GiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) ctx.fail("cannot open the file");
  std::vector<uint8_t> bytes(size);
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
  if (!in || in.gcount() != std::streamsize(size)) ctx.fail("cannot read the file");
  return bytes;
}

// Reads a property that must be a non-negative integer; `fallback` when absent.
uint64_t unsignedProperty(const json& object, const char* key, uint64_t fallback,
                          const std::string& owner, LoadContext& ctx) {
  auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (it->is_number_unsigned()) return it->get<uint64_t>();
  if (it->is_number_float()) {
    const double d = it->get<double>();
    if (d >= 0.0 && d < 9.0e15 && d == double(uint64_t(d))) return uint64_t(d);
  }
  ctx.fail(owner + " " + key + " is not a non-negative integer");
}

// Number of bytes a base64 payload decodes to, counting up to the first non-base64 character
// (padding included), as tinygltf's decoder does.
uint64_t base64DecodedSize(const std::string& uri, size_t payloadStart) {
  uint64_t chars = 0;
  for (size_t i = payloadStart; i < uri.size(); ++i) {
    const char c = uri[i];
    const bool valid = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '+' || c == '/';
    if (!valid) break;
    ++chars;
  }
  return chars * 3 / 4;
}

std::string percentDecode(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

size_t dataUriPayloadStart(const std::string& uri) {
  for (const char* prefix : kDataUriPrefixes) {
    const size_t n = std::strlen(prefix);
    if (uri.compare(0, n, prefix) == 0) return n;
  }
  return 0;
}

struct GlbChunks {
  size_t jsonOffset = 0, jsonSize = 0;
  uint64_t binSize = 0;
  bool hasBin = false;
};

GlbChunks checkGlbContainer(const std::vector<uint8_t>& bytes, LoadContext& ctx) {
  if (bytes.size() < 20) ctx.fail("GLB file is truncated (no header and JSON chunk)");
  if (readU32(bytes, 4) != 2)
    ctx.fail("GLB version " + std::to_string(readU32(bytes, 4)) + " is not supported (only 2)");
  const uint64_t length = readU32(bytes, 8);
  if (length > bytes.size())
    ctx.fail("GLB header says " + std::to_string(length) + " bytes but the file has " +
             std::to_string(bytes.size()) + " (truncated)");
  GlbChunks chunks;
  const uint64_t jsonSize = readU32(bytes, 12);
  if (readU32(bytes, 16) != kChunkJson) ctx.fail("GLB first chunk is not JSON");
  if (20 + jsonSize > length) ctx.fail("GLB JSON chunk runs past the end of the file");
  chunks.jsonOffset = 20;
  chunks.jsonSize = size_t(jsonSize);
  const uint64_t next = (20 + jsonSize + 3) / 4 * 4;
  if (next + 8 <= length && readU32(bytes, size_t(next) + 4) == kChunkBin) {
    const uint64_t binSize = readU32(bytes, size_t(next));
    if (next + 8 + binSize > length) ctx.fail("GLB BIN chunk runs past the end of the file");
    chunks.binSize = binSize;
    chunks.hasBin = true;
  }
  return chunks;
}

void checkRequiredExtensions(const json& root, LoadContext& ctx) {
  auto it = root.find("extensionsRequired");
  if (it == root.end()) return;
  if (!it->is_array()) ctx.fail("extensionsRequired is not an array");
  for (const json& name : *it) {
    if (!name.is_string()) ctx.fail("extensionsRequired holds a non-string");
    if (!isSupportedRequiredExtension(name.get<std::string>()))
      ctx.fail("requires unsupported extension " + name.get<std::string>());
  }
}

// Returns each buffer's declared byteLength after checking that its data holds that many bytes.
std::vector<uint64_t> checkBuffers(const json& root, const GlbChunks& glb, bool binary,
                                   const std::filesystem::path& baseDir, LoadContext& ctx) {
  std::vector<uint64_t> lengths;
  auto it = root.find("buffers");
  if (it == root.end()) return lengths;
  if (!it->is_array()) ctx.fail("buffers is not an array");
  for (size_t i = 0; i < it->size(); ++i) {
    const json& buffer = (*it)[i];
    const std::string name = "buffer " + std::to_string(i);
    if (!buffer.is_object()) ctx.fail(name + " is not an object");
    if (!buffer.contains("byteLength")) ctx.fail(name + " has no byteLength");
    const uint64_t byteLength = unsignedProperty(buffer, "byteLength", 0, name, ctx);
    auto uriIt = buffer.find("uri");
    if (uriIt == buffer.end()) {
      if (!binary || i != 0) ctx.fail(name + " has no uri (only a GLB's buffer 0 may omit it)");
      if (!glb.hasBin) ctx.fail(name + " refers to the GLB BIN chunk, which is missing");
      if (glb.binSize < byteLength)
        ctx.fail(name + " is truncated: the GLB BIN chunk has " + std::to_string(glb.binSize) +
                 " of its " + std::to_string(byteLength) + " bytes");
    } else {
      if (!uriIt->is_string()) ctx.fail(name + " uri is not a string");
      const std::string uri = uriIt->get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        const size_t start = dataUriPayloadStart(uri);
        if (start == 0)
          ctx.fail(name + " has an unsupported data URI (not base64 of a known type)");
        const uint64_t decoded = base64DecodedSize(uri, start);
        if (decoded < byteLength)
          ctx.fail(name + " is truncated: its data URI decodes to " + std::to_string(decoded) +
                   " of its " + std::to_string(byteLength) + " bytes");
        if (decoded > byteLength)
          ctx.fail(name + " data URI decodes to " + std::to_string(decoded) +
                   " bytes but byteLength is " + std::to_string(byteLength));
      } else {
        const std::filesystem::path file = baseDir / percentDecode(uri);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
          ctx.fail(name + " file '" + uri + "' is missing");
        const uintmax_t size = std::filesystem::file_size(file, ec);
        if (ec) ctx.fail(name + " file '" + uri + "' cannot be read");
        if (size < byteLength)
          ctx.fail(name + " file '" + uri + "' is truncated: " + std::to_string(size) + " of " +
                   std::to_string(byteLength) + " bytes");
        if (size > byteLength)  // tinygltf insists on equality
          ctx.fail(name + " file '" + uri + "' has " + std::to_string(size) +
                   " bytes but byteLength is " + std::to_string(byteLength));
      }
    }
    lengths.push_back(byteLength);
  }
  return lengths;
}

void checkBufferViews(const json& root, const std::vector<uint64_t>& bufferLengths,
                      LoadContext& ctx) {
  auto it = root.find("bufferViews");
  if (it == root.end()) return;
  if (!it->is_array()) ctx.fail("bufferViews is not an array");
  for (size_t i = 0; i < it->size(); ++i) {
    const json& view = (*it)[i];
    const std::string name = "buffer view " + std::to_string(i);
    if (!view.is_object()) ctx.fail(name + " is not an object");
    if (!view.contains("buffer")) ctx.fail(name + " has no buffer");
    const uint64_t buffer = unsignedProperty(view, "buffer", 0, name, ctx);
    if (buffer >= bufferLengths.size())
      ctx.fail(name + " refers to buffer " + std::to_string(buffer) + ", which does not exist (" +
               std::to_string(bufferLengths.size()) + " buffers)");
    const uint64_t offset = unsignedProperty(view, "byteOffset", 0, name, ctx);
    const uint64_t length = unsignedProperty(view, "byteLength", 0, name, ctx);
    if (length == 0) ctx.fail(name + " has no byteLength (or 0)");
    if (offset > bufferLengths[buffer] || length > bufferLengths[buffer] - offset)
      ctx.fail(name + " reads past the end of buffer " + std::to_string(buffer) + " (bytes " +
               std::to_string(offset) + "+" + std::to_string(length) + " of " +
               std::to_string(bufferLengths[buffer]) + ")");
    const uint64_t stride = unsignedProperty(view, "byteStride", 0, name, ctx);
    if (view.contains("byteStride") && (stride < 4 || stride > 252 || stride % 4 != 0))
      ctx.fail(name + " byteStride " + std::to_string(stride) +
               " is not a multiple of 4 in [4, 252]");
  }
}

void checkImages(const json& root, LoadContext& ctx) {
  auto it = root.find("images");
  if (it == root.end()) return;
  if (!it->is_array()) ctx.fail("images is not an array");
  const size_t viewCount = root.contains("bufferViews") ? root["bufferViews"].size() : 0;
  for (size_t i = 0; i < it->size(); ++i) {
    const json& image = (*it)[i];
    const std::string name = "image " + std::to_string(i);
    if (!image.is_object()) ctx.fail(name + " is not an object");
    if (image.contains("bufferView")) {
      const uint64_t view = unsignedProperty(image, "bufferView", 0, name, ctx);
      if (view >= viewCount)
        ctx.fail(name + " refers to buffer view " + std::to_string(view) +
                 ", which does not exist");
    }
  }
}

}  // namespace

bool isSupportedRequiredExtension(const std::string& name) {
  return name == "KHR_lights_punctual" || name == "EXT_mesh_gpu_instancing" ||
         name == "KHR_materials_emissive_strength" || name == "KHR_materials_specular" ||
         name == "KHR_texture_transform" || name == "KHR_materials_unlit" ||
         name == "KHR_materials_transmission" || name == "KHR_materials_ior" ||
         name == "KHR_materials_volume";
}

CheckedGltfFile readAndCheckGltfFile(const std::filesystem::path& path, LoadContext& ctx) {
  return checkGltfBytes(readWholeFile(path, ctx), path.parent_path(), ctx);
}

CheckedGltfFile checkGltfBytes(std::vector<uint8_t> bytes, const std::filesystem::path& baseDir,
                               LoadContext& ctx) {
  if (bytes.empty()) ctx.fail("file is empty");
  CheckedGltfFile file;
  file.bytes = std::move(bytes);
  file.baseDir = baseDir.string();
  file.binary = file.bytes.size() >= 4 && readU32(file.bytes, 0) == kGlbMagic;

  GlbChunks glb;
  const uint8_t* jsonBegin = file.bytes.data();
  size_t jsonSize = file.bytes.size();
  if (file.binary) {
    glb = checkGlbContainer(file.bytes, ctx);
    jsonBegin += glb.jsonOffset;
    jsonSize = glb.jsonSize;
  }

  json root;
  try {
    root = json::parse(jsonBegin, jsonBegin + jsonSize);
  } catch (const json::out_of_range& e) {
    // nlohmann refuses numbers beyond double's range: the only way JSON spells "Inf".
    ctx.fail(std::string("malformed JSON: a number is not finite: ") + e.what());
  } catch (const json::exception& e) {
    ctx.fail(std::string("malformed JSON: ") + e.what());
  }
  if (!root.is_object()) ctx.fail("malformed JSON: the top level is not an object");
  if (!root.contains("asset")) ctx.fail("not glTF: no \"asset\" property");

  checkRequiredExtensions(root, ctx);
  const std::vector<uint64_t> lengths = checkBuffers(root, glb, file.binary, baseDir, ctx);
  checkBufferViews(root, lengths, ctx);
  checkImages(root, ctx);
  return file;
}

}  // namespace qlight::gltf::detail

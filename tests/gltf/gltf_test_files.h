// Test helpers: glTF documents written byte by byte into a temporary directory, so each test
// knows exactly what the loader is given.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/gltf/gltf_loader.h"
#include "engine/gltf/gltf_writer.h"

namespace qlight::gltf::testing {

using nlohmann::json;

// A fresh directory under the system temp dir, removed with its content at scope exit.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("qlight_scene_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void writeBytes(const std::filesystem::path& path, const void* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), std::streamsize(size));
}
inline void writeText(const std::filesystem::path& path, const std::string& text) {
  writeBytes(path, text.data(), text.size());
}

// Little-endian bytes of plain values, appended.
class Bytes {
 public:
  template <typename T>
  Bytes& add(std::initializer_list<T> values) {
    for (T v : values) {
      const size_t at = data.size();
      data.resize(at + sizeof(T));
      std::memcpy(data.data() + at, &v, sizeof(T));
    }
    return *this;
  }
  Bytes& pad4() {
    while (data.size() % 4 != 0) data.push_back(0);
    return *this;
  }
  std::vector<uint8_t> data;
};

inline std::string dataUri(const std::vector<uint8_t>& bytes) {
  return "data:application/octet-stream;base64," + base64Encode(bytes.data(), bytes.size());
}

// One counter-clockwise triangle in the xy plane (normal +z), indexed with UNSIGNED_SHORT:
// buffer = 3 float3 positions (36 bytes) + 3 uint16 indices (6 bytes, padded to 8).
// accessor 0: POSITION, accessor 1: indices. bufferView 0: positions, 1: indices.
inline std::vector<uint8_t> triangleBytes() {
  Bytes b;
  b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.add<uint16_t>({0, 1, 2}).pad4();
  return b.data;
}

inline json triangleDoc() {
  const std::vector<uint8_t> bytes = triangleBytes();
  return json{
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"mesh", 0}}})},
      {"meshes",
       json::array(
           {{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
      {"buffers", json::array({{{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}}})},
      {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                   {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}})},
      {"accessors",
       json::array(
           {{{"bufferView", 0},
             {"componentType", 5126},
             {"count", 3},
             {"type", "VEC3"},
             {"min", {0, 0, 0}},
             {"max", {1, 1, 0}}},
            {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})}};
}

// Replaces the document's single buffer with these bytes (as a data URI).
inline void setBuffer(json& doc, const std::vector<uint8_t>& bytes) {
  doc["buffers"] = json::array({{{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}}});
}

// The triangle of triangleDoc() with a sparse accessor replacing POSITION `index` by
// `value` (index at byte 44, value at 48, both in views of their own).
inline json sparseTriangleDoc(uint16_t index, std::initializer_list<float> value) {
  json doc = triangleDoc();
  Bytes b;
  b.data = triangleBytes();
  b.add<uint16_t>({index, 0});
  b.add<float>(value);
  setBuffer(doc, b.data);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 2}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
  doc["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                   {"values", {{"bufferView", 3}}}};
  return doc;
}

inline std::filesystem::path writeDoc(const TempDir& dir, const std::string& name,
                                      const json& doc) {
  const std::filesystem::path path = dir / name;
  writeText(path, doc.dump());
  return path;
}

// A GLB container: JSON chunk (space padded) and, when bin is not empty, a BIN chunk.
inline std::vector<uint8_t> makeGlb(json doc, const std::vector<uint8_t>& bin) {
  if (!bin.empty()) doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
  std::string text = doc.dump();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<uint8_t> padded = bin;
  while (padded.size() % 4 != 0) padded.push_back(0);
  Bytes out;
  const uint32_t total = uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + padded.size()));
  out.add<uint32_t>({0x46546C67u, 2u, total, uint32_t(text.size()), 0x4E4F534Au});
  out.data.insert(out.data.end(), text.begin(), text.end());
  if (!bin.empty()) {
    out.add<uint32_t>({uint32_t(padded.size()), 0x004E4942u});
    out.data.insert(out.data.end(), padded.begin(), padded.end());
  }
  return out.data;
}

// Loading `path` throws a one-line std::runtime_error naming the file and holding `problem`.
inline void expectLoadError(const std::filesystem::path& path, const std::string& problem) {
  try {
    loadGltf(path);
    ADD_FAILURE() << "no error loading " << path << " (expected '" << problem << "')";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace qlight::gltf::testing

// Test helper: a glTF document built accessor by accessor, its one buffer embedded, so a test
// states the file's data where it checks the loader's answer.
#pragma once

#include <string>
#include <vector>

#include "tests/gltf/gltf_test_files.h"

namespace qlight::gltf::testing {

class DocBuilder {
 public:
  // Appends the values as a new buffer view and accessor; returns the accessor's index.
  // componentType: 5126 FLOAT, 5123 UNSIGNED_SHORT, 5121 UNSIGNED_BYTE.
  template <typename T>
  int add(const std::vector<T>& values, int componentType, const std::string& type) {
    const size_t components = type == "SCALAR" ? 1
                              : type == "VEC2" ? 2
                              : type == "VEC3" ? 3
                              : type == "VEC4" ? 4
                                               : 16;
    const size_t offset = bytes_.data.size();
    for (T v : values) bytes_.add<T>({v});
    const size_t length = bytes_.data.size() - offset;
    bytes_.pad4();
    views_.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    accessors_.push_back({{"bufferView", views_.size() - 1},
                          {"componentType", componentType},
                          {"count", values.size() / components},
                          {"type", type}});
    return int(accessors_.size() - 1);
  }
  int addFloats(const std::vector<float>& v, const std::string& type) { return add(v, 5126, type); }

  // The document: `rest` (nodes, meshes, scenes, ...) with the buffer, views and accessors.
  json finish(json rest) const {
    rest["asset"] = {{"version", "2.0"}};
    rest["buffers"] =
        json::array({{{"byteLength", bytes_.data.size()}, {"uri", dataUri(bytes_.data)}}});
    rest["bufferViews"] = views_;
    rest["accessors"] = accessors_;
    return rest;
  }

 private:
  Bytes bytes_;
  json views_ = json::array();
  json accessors_ = json::array();
};

}  // namespace qlight::gltf::testing

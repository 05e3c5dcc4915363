// Internal to the glTF loader: the file name every error and warning starts with, and the
// warnings gathered while loading. Errors are one line: "<file>: <problem>".
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::gltf::detail {
using namespace ::qlight::scene;

class LoadContext {
 public:
  explicit LoadContext(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  // Throws std::runtime_error("<file>: <problem>") with line breaks folded into "; ".
  [[noreturn]] void fail(const std::string& problem) const;
  // Records "<file>: <problem>" (once per distinct text) and prints it to stderr.
  void warn(const std::string& problem);

  std::vector<std::string>& warnings() { return warnings_; }

  // Throws unless every value is finite: "<what> is not finite".
  void requireFinite(double value, const std::string& what) const {
    if (!std::isfinite(value)) fail(what + " is not finite");
  }
  template <typename Container>
  void requireFiniteAll(const Container& values, const std::string& what) const {
    for (double v : values) requireFinite(v, what);
  }

 private:
  std::string file_;
  std::vector<std::string> warnings_;
};

// Folds line breaks (tinygltf's errors have several lines) into one line.
std::string oneLine(const std::string& text);

}  // namespace qlight::gltf::detail

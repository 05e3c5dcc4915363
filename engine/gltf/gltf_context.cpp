#include "engine/gltf/gltf_context.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>

namespace qlight::gltf::detail {

std::string oneLine(const std::string& text) {
  std::string out;
  bool pendingBreak = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      pendingBreak = !out.empty();
      continue;
    }
    if (pendingBreak) out += "; ";
    pendingBreak = false;
    out += c;
  }
  return out;
}

void LoadContext::fail(const std::string& problem) const {
  throw std::runtime_error(oneLine(file_ + ": " + problem));
}

void LoadContext::warn(const std::string& problem) {
  std::string line = oneLine(file_ + ": warning: " + problem);
  if (std::find(warnings_.begin(), warnings_.end(), line) != warnings_.end()) return;
  std::cerr << line << '\n';
  warnings_.push_back(std::move(line));
}

}  // namespace qlight::gltf::detail

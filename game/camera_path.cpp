#include "game/camera_path.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace qlight::game {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Every problem in a file is this, so main prints it as one line.
[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw std::runtime_error(file.string() + ": " + problem);
}

// The shortest decimal that reads back as the same float: files and messages show 0.3, not
// 0.30000001192092896.
std::string text(float v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof(buf), v).ptr);
}
double shortest(float v) { return std::strtod(text(v).c_str(), nullptr); }

float readNumber(const fs::path& file, const json& value, const std::string& what) {
  // JSON has no NaN or infinity: a writer that had them wrote null; 1e999 parses as infinite.
  if (!value.is_number()) fail(file, what + " is not a number");
  const float v = float(value.get<double>());
  if (!std::isfinite(v)) fail(file, what + " is not a finite number");
  return v;
}

glm::vec3 readVec3(const fs::path& file, const json& key, const char* name,
                   const std::string& where) {
  const std::string what = where + ": " + name;
  if (!key.contains(name)) fail(file, what + " is missing");
  const json& v = key[name];
  if (!v.is_array() || v.size() != 3) fail(file, what + " is not [x, y, z]");
  return {readNumber(file, v[0], what + "[0]"), readNumber(file, v[1], what + "[1]"),
          readNumber(file, v[2], what + "[2]")};
}

CameraKey readKey(const fs::path& file, const json& k, size_t index) {
  const std::string where = "key " + std::to_string(index);
  if (!k.is_object()) fail(file, where + " is not an object");
  if (!k.contains("time")) fail(file, where + ": time is missing");
  CameraKey key;
  key.time = readNumber(file, k["time"], where + ": time");
  key.view.position = readVec3(file, k, "position", where);
  key.view.forward = readVec3(file, k, "forward", where);
  key.view.up = readVec3(file, k, "up", where);
  const std::optional<render::CameraView> view = orthonormal(key.view);
  if (!view) fail(file, where + ": forward is zero, or up is zero or parallel to forward");
  key.view = *view;
  if (k.contains("yfov")) {
    key.view.yfov = readNumber(file, k["yfov"], where + ": yfov");
    if (key.view.yfov <= 0.0f || key.view.yfov >= 3.14159f)
      fail(file, where + ": yfov " + text(key.view.yfov) + " is not in (0, pi) radians");
  }
  return key;
}

json parseFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, std::string("cannot open (") + std::strerror(errno) + ")");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 1, ...": the text after the tag.
    // A number beyond a double (1e999) is out_of_range.406 "number overflow parsing ...".
    const std::string message = e.what();
    const size_t tag = message.find("] ");
    const std::string what = tag == std::string::npos ? message : message.substr(tag + 2);
    fail(file, (dynamic_cast<const json::parse_error*>(&e) ? "not JSON: " : "") + what);
  }
}

nlohmann::ordered_json vec3Json(const glm::vec3& v) {
  return {shortest(v.x), shortest(v.y), shortest(v.z)};
}

// The key's rotation: camera x right, y up, looking down -z (glTF).
glm::quat rotationOf(const render::CameraView& v) {
  const glm::vec3 right = glm::cross(v.forward, v.up);
  return glm::quat_cast(glm::mat3(right, v.up, -v.forward));
}

}  // namespace

std::optional<render::CameraView> orthonormal(const render::CameraView& view) {
  const float forwardLength = glm::length(view.forward);
  if (!(forwardLength > 1e-6f)) return std::nullopt;
  render::CameraView v = view;
  v.forward = view.forward / forwardLength;
  // The up orthogonal to forward, so the key is a rotation (sampling slerps those).
  const glm::vec3 up = view.up - glm::dot(view.up, v.forward) * v.forward;
  const float upLength = glm::length(up);
  if (!(upLength > 1e-4f * glm::length(view.up))) return std::nullopt;
  v.up = up / upLength;
  return v;
}

render::CameraView CameraPath::sample(float seconds) const {
  if (seconds <= start()) return keys.front().view;
  if (seconds >= end()) return keys.back().view;
  const auto after = std::upper_bound(keys.begin(), keys.end(), seconds,
                                      [](float t, const CameraKey& k) { return t < k.time; });
  const CameraKey& a = *(after - 1);
  const CameraKey& b = *after;
  const float s = (seconds - a.time) / (b.time - a.time);
  if (s == 0.0f) return a.view;  // exactly on a key: its pose, not a round trip through a quat
  render::CameraView v;
  v.position = glm::mix(a.view.position, b.view.position, s);
  const glm::quat q = glm::slerp(rotationOf(a.view), rotationOf(b.view), s);  // the short way
  v.forward = glm::normalize(q * glm::vec3(0.0f, 0.0f, -1.0f));
  v.up = glm::normalize(q * glm::vec3(0.0f, 1.0f, 0.0f));
  v.yfov = glm::mix(a.view.yfov, b.view.yfov, s);
  return v;
}

void CameraPath::setFov(float yfov) {
  for (CameraKey& k : keys) k.view.yfov = yfov;
  hasFov = true;
}

CameraPath loadCameraPath(const fs::path& file) {
  const json j = parseFile(file);
  if (!j.is_object() || !j.contains("keys") || !j["keys"].is_array())
    fail(file, "expected {\"keys\": [...]}");
  const json& list = j["keys"];
  if (list.size() < 2)
    fail(file, "a camera path needs at least 2 keys, this one has " + std::to_string(list.size()));
  CameraPath path;
  size_t withFov = 0;
  for (size_t i = 0; i < list.size(); ++i) {
    path.keys.push_back(readKey(file, list[i], i));
    withFov += list[i].contains("yfov");
    if (i > 0 && path.keys[i].time <= path.keys[i - 1].time)
      fail(file, "key " + std::to_string(i) + ": time " + text(path.keys[i].time) +
                     " is not after the previous key's " + text(path.keys[i - 1].time));
  }
  if (withFov != 0 && withFov != list.size())
    fail(file, "yfov is on " + std::to_string(withFov) + " of " + std::to_string(list.size()) +
                   " keys: give it on every key or on none");
  path.hasFov = withFov != 0;
  return path;
}

void saveCameraPath(const fs::path& file, const CameraPath& path) {
  std::error_code ec;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
  const fs::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail(file, std::string("cannot write (") + std::strerror(errno) + ")");
    // One key a line: readable, and diffs of edited paths stay small.
    out << "{\"keys\": [\n";
    for (size_t i = 0; i < path.keys.size(); ++i) {
      const CameraKey& k = path.keys[i];
      nlohmann::ordered_json key = {{"time", shortest(k.time)},
                                    {"position", vec3Json(k.view.position)},
                                    {"forward", vec3Json(k.view.forward)},
                                    {"up", vec3Json(k.view.up)}};
      if (path.hasFov) key["yfov"] = shortest(k.view.yfov);
      out << "  " << key.dump() << (i + 1 < path.keys.size() ? ",\n" : "\n");
    }
    out << "]}\n";
    out.close();
    if (!out) fail(file, "cannot write " + temporary.string());
  }
  fs::rename(temporary, file, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(temporary, ec);
    fail(file, "cannot write (" + why + ")");
  }
}

}  // namespace qlight::game

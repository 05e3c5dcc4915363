#include "game/ui_guide_views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace qlight::game {
namespace {

// Table read-backs a second: enough to watch Q follow a light, cheap beside a frame.
constexpr double kPointsRefreshSeconds = 0.5, kDetailRefreshSeconds = 0.2;

// The camera's frame as the path tracer builds its rays (path_tracer.cpp, pt_begin.comp).
struct CameraFrame {
  glm::vec3 position, forward, right, up;
  float tanHalf, aspect;
  CameraFrame(const render::CameraView& v, float aspectRatio)
      : position(v.position),
        forward(glm::normalize(v.forward)),
        right(glm::normalize(glm::cross(forward, v.up))),
        up(glm::cross(right, forward)),
        tanHalf(std::tan(0.5f * v.yfov)),
        aspect(aspectRatio) {}
  // The ray through a window position (pixels, y down).
  glm::vec3 rayThrough(ImVec2 p, ImVec2 display) const {
    const float x = p.x / display.x * 2.0f - 1.0f, y = p.y / display.y * 2.0f - 1.0f;
    return glm::normalize(forward + x * tanHalf * aspect * right - y * tanHalf * up);
  }
  // Where a world point lands in the window, if in front of the camera.
  std::optional<ImVec2> project(glm::vec3 p, ImVec2 display) const {
    const glm::vec3 d = p - position;
    const float z = glm::dot(d, forward);
    if (z <= 1e-4f) return std::nullopt;
    const float x = glm::dot(d, right) / (z * tanHalf * aspect),
                y = -glm::dot(d, up) / (z * tanHalf);
    if (std::abs(x) > 1.0f || std::abs(y) > 1.0f) return std::nullopt;
    return ImVec2((x + 1.0f) * 0.5f * display.x, (y + 1.0f) * 0.5f * display.y);
  }
};

// A perceptually ordered ramp (dark blue -> magenta -> orange -> pale yellow), t in 0..1.
ImU32 falseColour(float t) {
  static const glm::vec3 keys[] = {{0.05f, 0.03f, 0.25f},
                                   {0.45f, 0.07f, 0.5f},
                                   {0.85f, 0.3f, 0.3f},
                                   {0.98f, 0.65f, 0.15f},
                                   {0.99f, 0.98f, 0.65f}};
  t = std::clamp(std::isfinite(t) ? t : 0.0f, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(int(t), 3);
  const glm::vec3 c = glm::mix(keys[i], keys[i + 1], t - float(i));
  return IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), 255);
}

bool elapsed(std::chrono::steady_clock::time_point& last, double seconds) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last).count() < seconds) return false;
  last = now;
  return true;
}

// The strata as a disc: row r is the ring between radii sqrt(r / rows) and sqrt((r+1) / rows)
// (equal area, as the strata have equal solid angle), column c the wedge from phi 2 pi c / cols.
void drawHemisphereDisc(const guiding::PointDetail& d, ImDrawList* draw, ImVec2 centre,
                        float radius) {
  const float qMax = *std::max_element(d.q.begin(), d.q.end());
  const int arcSteps = std::max(2, int(64 / d.cols));
  for (uint32_t r = 0; r < d.rows; ++r) {
    const float r0 = radius * std::sqrt(float(r) / d.rows);
    const float r1 = radius * std::sqrt(float(r + 1) / d.rows);
    for (uint32_t c = 0; c < d.cols; ++c) {
      const float q = d.q[r * d.cols + c];
      const ImU32 colour = falseColour(qMax > 0 ? q / qMax : 0.0f);
      for (int s = 0; s < arcSteps; ++s) {
        const float a0 = 6.2831853f * (c + float(s) / arcSteps) / d.cols;
        const float a1 = 6.2831853f * (c + float(s + 1) / arcSteps) / d.cols;
        const ImVec2 quad[4] = {{centre.x + r0 * std::cos(a0), centre.y - r0 * std::sin(a0)},
                                {centre.x + r1 * std::cos(a0), centre.y - r1 * std::sin(a0)},
                                {centre.x + r1 * std::cos(a1), centre.y - r1 * std::sin(a1)},
                                {centre.x + r0 * std::cos(a1), centre.y - r0 * std::sin(a1)}};
        draw->AddConvexPolyFilled(quad, 4, colour);
      }
    }
  }
  draw->AddCircle(centre, radius, IM_COL32(255, 255, 255, 160), 64);
}

}  // namespace

void drawGuideViewControls(GuideViewSettings& s) {
  ImGui::Checkbox("show cache points", &s.pointsOverlay);
  if (s.pointsOverlay) {
    ImGui::SameLine();
    ImGui::Checkbox("by confidence", &s.colourByConfidence);
  }
  ImGui::Checkbox("Q under the cursor", &s.hemisphere);
}

void GuideViews::refreshPoints(session::Renderer& renderer, const render::CameraView& camera) {
  visible_.clear();
  if (!renderer.guide() || renderer.dqnGuide()) return;  // deep Q has no points
  // Only the points the camera sees: one CPU ray per point, a few times a second.
  for (const guiding::PointSummary& p :
       guiding::summarizePoints(renderer.world().registry(), *renderer.guide())) {
    const glm::vec3 toPoint = p.position - camera.position;
    const float distance = glm::length(toPoint);
    if (distance <= 0.0f || glm::dot(p.normal, toPoint) >= 0.0f) continue;  // faces away
    const std::optional<float> hit = renderer.scene().closestHit(camera.position, toPoint);
    if (!hit || *hit >= distance * 0.995f - 1e-3f) visible_.push_back(p);
  }
}

void GuideViews::refreshDetail(session::Renderer& renderer, const render::CameraView& camera,
                               ImVec2 display, ImVec2 mouse) {
  detail_.reset();
  const CameraFrame frame(camera, display.x / std::max(display.y, 1.0f));
  const glm::vec3 dir = frame.rayThrough(mouse, display);
  const std::optional<float> t = renderer.scene().closestHit(camera.position, dir);
  if (!t) return;
  if (const guiding::DqnGuide* network = renderer.dqnGuide()) {
    // The surface's normal from two more hits a pixel aside (the CPU picking ray gives t only).
    const glm::vec3 p = camera.position + *t * dir;
    const glm::vec3 dx = frame.rayThrough(ImVec2(mouse.x + 1, mouse.y), display);
    const glm::vec3 dy = frame.rayThrough(ImVec2(mouse.x, mouse.y + 1), display);
    const std::optional<float> tx = renderer.scene().closestHit(camera.position, dx);
    const std::optional<float> ty = renderer.scene().closestHit(camera.position, dy);
    if (!tx || !ty) return;
    glm::vec3 n = glm::cross(camera.position + *tx * dx - p, camera.position + *ty * dy - p);
    if (!(glm::dot(n, n) > 0.0f)) return;
    if (glm::dot(n, dir) > 0.0f) n = -n;  // facing the viewer
    detail_ = guiding::inspectNetworkAt(*network, p, n);
    return;
  }
  if (!renderer.guide()) return;
  detail_ = guiding::inspectPointAt(renderer.world().registry(), *renderer.guide(),
                                    camera.position + *t * dir, -dir);
}

void GuideViews::draw(session::Renderer& renderer, const render::CameraView& camera, ImVec2 display,
                      ImVec2 mouse, bool mouseFree) {
  if (!renderer.guided() || display.x <= 0 || display.y <= 0) return;
  const CameraFrame frame(camera, display.x / display.y);
  if (settings.pointsOverlay) {
    if (elapsed(pointsAt_, kPointsRefreshSeconds)) refreshPoints(renderer, camera);
    float lo = INFINITY, hi = -INFINITY;  // the colour scale: log irradiance over what is seen
    for (const auto& p : visible_)
      if (p.irradiance > 0)
        lo = std::min(lo, std::log(p.irradiance)), hi = std::max(hi, std::log(p.irradiance));
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    drewPoints_ = true;
    pointsDrawn_ = 0;
    for (const auto& p : visible_) {
      const std::optional<ImVec2> at = frame.project(p.position, display);
      if (!at) continue;
      ++pointsDrawn_;
      const float t = settings.colourByConfidence   ? p.confidence
                      : hi > lo && p.irradiance > 0 ? (std::log(p.irradiance) - lo) / (hi - lo)
                                                    : 0.0f;
      draw->AddCircleFilled(*at, 2.0f, falseColour(t));
    }
  }
  if (!settings.hemisphere) return;
  if (mouseFree && elapsed(detailAt_, kDetailRefreshSeconds))
    refreshDetail(renderer, camera, display, mouse);
  // Top right (the auto-sized window is about 240 pixels wide; its size is unknown until drawn).
  ImGui::SetNextWindowPos(ImVec2(std::max(0.0f, display.x - 252), 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("learned Q", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (!detail_) {
      ImGui::TextWrapped("point the cursor at a surface with a cache point");
    } else {
      const guiding::PointDetail& d = *detail_;
      drewDetail_ = true;
      ImGui::Text("point at %.2f %.2f %.2f", d.point.position.x, d.point.position.y,
                  d.point.position.z);
      ImGui::Text("confidence %.2f, %ux%u strata", d.confidence, d.rows, d.cols);
      const float size = 200.0f;
      const ImVec2 corner = ImGui::GetCursorScreenPos();
      drawHemisphereDisc(d, ImGui::GetWindowDrawList(),
                         ImVec2(corner.x + size * 0.5f, corner.y + size * 0.5f), size * 0.5f - 2);
      ImGui::Dummy(ImVec2(size, size));
      ImGui::TextDisabled("centre: the normal; rim: the horizon");
      if (!d.lightValues.empty()) {
        ImGui::Text("learned light selection (%zu lights)", d.lightValues.size());
        ImGui::PlotHistogram("##lights", d.lightValues.data(), int(d.lightValues.size()), 0,
                             nullptr, 0.0f, FLT_MAX, ImVec2(size, 60));
      }
    }
  }
  ImGui::End();
}

std::string GuideViews::summary() const {
  std::string s;
  char text[160];
  if (drewPoints_) {
    std::snprintf(text, sizeof(text), "%zu cache points drawn", pointsDrawn_);
    s += text;
  }
  if (drewDetail_ && detail_) {
    std::snprintf(text, sizeof(text), "%sQ shown of the point at %.2f %.2f %.2f (%zu light values)",
                  s.empty() ? "" : ", ", detail_->point.position.x, detail_->point.position.y,
                  detail_->point.position.z, detail_->lightValues.size());
    s += text;
  }
  return s;
}

}  // namespace qlight::game

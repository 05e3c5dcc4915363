#include "game/window_script.h"

#include <charconv>
#include <stdexcept>

#include "game/setting_words.h"

namespace qlight::game {
namespace {

// The whole of `text` as a number in [lowest, highest].
bool readNumber(std::string_view text, uint32_t lowest, uint32_t highest, uint32_t& out) {
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && out >= lowest &&
         out <= highest;
}

}  // namespace

ScriptStep parseScriptStep(const std::string& text) {
  auto bad = [&](const std::string& why) {
    return std::invalid_argument("--script " + text + ": " + why);
  };
  ScriptStep step;
  const size_t colon = text.find(':'), equals = text.find('=', colon);
  if (colon == std::string::npos || equals == std::string::npos)
    throw bad("not of the form FRAME:ACTION=VALUE (e.g. 10:resize=640x360)");
  if (!readNumber(std::string_view(text).substr(0, colon), 0, 1000000, step.frame))
    throw bad("the frame must be a number in [0, 1000000]");
  const std::string action = text.substr(colon + 1, equals - colon - 1);
  const std::string value = text.substr(equals + 1);
  if (action == "resize") {
    step.action = ScriptStep::Action::Resize;
    const size_t x = value.find('x');
    const auto size = [&](std::string_view part, uint32_t& out) {
      return readNumber(part, 1, uint32_t(ranges::kImageSize.highest), out);
    };
    if (x == std::string::npos || !size(std::string_view(value).substr(0, x), step.width) ||
        !size(std::string_view(value).substr(x + 1), step.height))
      throw bad("resize takes WxH, e.g. 640x360");
  } else if (action == "vsync" || action == "points" || action == "denoise" || action == "panel") {
    step.action = action == "vsync"     ? ScriptStep::Action::Vsync
                  : action == "points"  ? ScriptStep::Action::Points
                  : action == "denoise" ? ScriptStep::Action::Denoise
                                        : ScriptStep::Action::Panel;
    auto it = onOffWords().find(value);
    if (it == onOffWords().end()) throw bad(action + " takes on or off");
    step.on = it->second;
  } else if (action == "load" || action == "save" || action == "capture") {
    step.action = action == "load"   ? ScriptStep::Action::Load
                  : action == "save" ? ScriptStep::Action::Save
                                     : ScriptStep::Action::Capture;
    if (value.empty()) throw bad(action + " takes a file");
    step.path = value;
  } else {
    throw bad("unknown action \"" + action +
              "\" (resize, vsync, load, save, points, denoise, panel or capture)");
  }
  return step;
}

}  // namespace qlight::game

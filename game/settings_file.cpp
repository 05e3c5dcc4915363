#include "game/settings_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>

#include "game/setting_words.h"

namespace qlight::game {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// Where a setting lives: a part of Settings (render, guiding, window) and a member of it.
template <class Part>
struct Section {
  const char* name;
  Part Settings::*part;
};
constexpr Section<render::RenderSettings> kRender{"render", &Settings::render};
constexpr Section<guiding::GuidingSettings> kGuiding{"guiding", &Settings::guiding};
constexpr Section<WindowSettings> kWindow{"window", &Settings::window};
constexpr Section<EnvironmentSettings> kEnvironment{"environment", &Settings::environment};

// One setting of the file: where it sits, the CLI option that overrides it, how it is read
// and written. `set` returns why the value was refused ("" when it was applied); `copy`
// takes the setting from another Settings (to undo a value).
struct Field {
  std::string section, key;
  std::string option;  // "" where the CLI has none (panel-only settings)
  std::function<ordered_json(const Settings&)> get;
  std::function<std::string(const json&, Settings&)> set;
  std::function<void(const Settings& from, Settings& to)> copy;
};

// `copy` for a setting that is one member.
template <class Part, class T>
auto copier(Section<Part> section, T Part::*member) {
  return [section, member](const Settings& from, Settings& to) {
    to.*section.part.*member = from.*section.part.*member;
  };
}

template <class Json>
std::string shown(const Json& j) {
  std::string text = j.dump(-1, ' ', false, Json::error_handler_t::replace);
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", v);
  return text;
}

// The float's shortest decimal, so that the file says 0.7 rather than 0.699999988079071
// (kept only where it reads back as the same float).
double fileValue(float f) {
  char text[32];
  auto end = std::to_chars(text, text + sizeof(text), f).ptr;
  double d = 0;
  std::from_chars(text, end, d);
  return float(d) == f ? d : double(f);
}

// A number in `range`; whole numbers for integer settings.
template <class Part, class T>
Field number(Section<Part> section, std::string key, std::string option, T Part::*member,
             Range range) {
  Field f{section.name, std::move(key), std::move(option)};
  f.get = [section, member](const Settings& s) -> ordered_json {
    if constexpr (std::is_floating_point_v<T>)
      return fileValue(s.*section.part.*member);
    else
      return s.*section.part.*member;
  };
  f.set = [section, member, range](const json& j, Settings& s) -> std::string {
    constexpr bool real = std::is_floating_point_v<T>;
    if (real ? !j.is_number() : !j.is_number_integer())
      return std::string(real ? "must be a number" : "must be a whole number") + ", not " +
             shown(j);
    double v = j.get<double>();
    if (!(v >= range.lowest && v <= range.highest))
      return "is " + shown(j) + ", not in [" + shown(range.lowest) + ", " + shown(range.highest) +
             "]";
    s.*section.part.*member = T(v);
    return "";
  };
  f.copy = copier(section, member);
  return f;
}

template <class Part>
Field boolean(Section<Part> section, std::string key, std::string option, bool Part::*member) {
  Field f{section.name, std::move(key), std::move(option)};
  f.get = [section, member](const Settings& s) -> ordered_json { return s.*section.part.*member; };
  f.set = [section, member](const json& j, Settings& s) -> std::string {
    if (!j.is_boolean()) return "must be true or false, not " + shown(j);
    s.*section.part.*member = j.get<bool>();
    return "";
  };
  f.copy = copier(section, member);
  return f;
}

// One of the CLI's words for an enum (any case, as on the command line).
template <class Part, class T>
Field word(Section<Part> section, std::string key, std::string option, T Part::*member,
           const Words<T>& words) {
  Field f{section.name, std::move(key), std::move(option)};
  f.get = [section, member, &words](const Settings& s) -> ordered_json {
    return wordOf(words, s.*section.part.*member);
  };
  f.set = [section, member, &words](const json& j, Settings& s) -> std::string {
    if (j.is_string()) {
      std::string text = j.get<std::string>();
      for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (auto it = words.find(text); it != words.end()) {
        s.*section.part.*member = it->second;
        return "";
      }
    }
    std::string list;
    for (const auto& [w, value] : words) list += (list.empty() ? "\"" : ", \"") + w + "\"";
    return "must be one of " + list + ", not " + shown(j);
  };
  f.copy = copier(section, member);
  return f;
}

// The environment map's file ("" for none).
Field environmentFile() {
  Field f{kEnvironment.name, "file", "--env"};
  f.get = [](const Settings& s) -> ordered_json { return s.environment.file; };
  f.set = [](const json& j, Settings& s) -> std::string {
    if (!j.is_string()) return "must be a file name (\"\": none), not " + shown(j);
    s.environment.file = j.get<std::string>();
    return "";
  };
  f.copy = copier(kEnvironment, &EnvironmentSettings::file);
  return f;
}

// The uniform sky's radiance [r, g, b], or null for none.
Field skyColor() {
  Field f{kEnvironment.name, "sky", "--sky"};
  f.get = [](const Settings& s) -> ordered_json {
    if (!s.environment.sky) return nullptr;
    const glm::vec3 c = *s.environment.sky;
    return ordered_json::array({fileValue(c.x), fileValue(c.y), fileValue(c.z)});
  };
  f.set = [](const json& j, Settings& s) -> std::string {
    if (j.is_null()) {
      s.environment.sky.reset();
      return "";
    }
    const Range r = ranges::kSkyRadiance;
    bool ok = j.is_array() && j.size() == 3;
    for (size_t i = 0; ok && i < 3; ++i)
      ok = j[i].is_number() && j[i].get<double>() >= r.lowest && j[i].get<double>() <= r.highest;
    if (!ok) return "must be [r, g, b] with each in [0, 1e6], or null, not " + shown(j);
    s.environment.sky = glm::vec3(j[0].get<float>(), j[1].get<float>(), j[2].get<float>());
    return "";
  };
  f.copy = copier(kEnvironment, &EnvironmentSettings::sky);
  return f;
}

Field strata() {
  Field f{"guiding", "strata", "--strata"};
  f.get = [](const Settings& s) -> ordered_json {
    return std::to_string(s.guiding.rows) + "x" + std::to_string(s.guiding.cols);
  };
  f.set = [](const json& j, Settings& s) -> std::string {
    if (!j.is_string()) return "must be a string RxC such as \"8x8\", not " + shown(j);
    try {
      guiding::parseStrata(j.get<std::string>(), s.guiding);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  f.copy = [](const Settings& from, Settings& to) {
    to.guiding.rows = from.guiding.rows;
    to.guiding.cols = from.guiding.cols;
  };
  return f;
}

// The file's settings, in its order. The CLI's ranges apply; guiding values that the CLI
// leaves to guiding::validate are only checked there.
const std::vector<Field>& fields() {
  using namespace ranges;
  constexpr Range kAnyReal{-FLT_MAX, FLT_MAX}, kAnyUint{0, 4294967295.0};
  using R = render::RenderSettings;
  using G = guiding::GuidingSettings;
  using W = WindowSettings;
  using E = EnvironmentSettings;
  static const std::vector<Field> all{
      number(kRender, "width", "--width", &R::width, kImageSize),
      number(kRender, "height", "--height", &R::height, kImageSize),
      number(kRender, "spp_per_frame", "--spp-per-frame", &R::samplesPerFrame, kSamplesPerFrame),
      number(kRender, "max_depth", "--max-depth", &R::maxDepth, kMaxDepth),
      number(kRender, "seed", "--seed", &R::seed, kAnyUint),
      word(kRender, "estimator", "--estimator", &R::estimator, estimatorWords()),
      boolean(kRender, "rr", "--rr", &R::russianRoulette),
      word(kRender, "trace_kernel", "--trace-kernel", &R::traceKernel, traceKernelWords()),
      number(kRender, "exposure", "--exposure", &R::exposure, kExposure),
      number(kRender, "temporal_blend", "--temporal-blend", &R::temporalBlend, kTemporalBlend),
      word(kRender, "tonemap", "--tonemap", &R::tonemap, tonemapWords()),
      boolean(kGuiding, "enabled", "--guiding", &G::enabled),
      word(kGuiding, "method", "--guiding", &G::method, guideMethodWords()),
      number(kGuiding, "dqn_width", "--dqn-width", &G::dqnWidth, kAnyUint),
      number(kGuiding, "dqn_layers", "--dqn-layers", &G::dqnHidden, kAnyUint),
      number(kGuiding, "dqn_bins", "--dqn-bins", &G::dqnBins, kAnyUint),
      number(kGuiding, "dqn_batch", "--dqn-batch", &G::dqnBatch, kAnyUint),
      number(kGuiding, "dqn_steps", "--dqn-steps", &G::dqnStepsPerFrame, kAnyUint),
      number(kGuiding, "dqn_learning_rate", "--dqn-learning-rate", &G::dqnLearningRate,
             kDqnLearningRate),
      number(kGuiding, "dqn_target_interval", "--dqn-target-interval", &G::dqnTargetInterval,
             kAnyUint),
      number(kGuiding, "dqn_grid", "--dqn-grid", &G::dqnGrid, kAnyUint),
      strata(),
      word(kGuiding, "directions", "--directions", &G::directions, directionModelWords()),
      number(kGuiding, "tree_nodes", "--tree-nodes", &G::treeNodes, kAnyUint),
      number(kGuiding, "tree_split", "--tree-split", &G::treeSplitShare, kAnyReal),
      number(kGuiding, "alpha_min", "--alpha-min", &G::alphaMin, kAnyReal),
      number(kGuiding, "alpha_max", "--alpha-max", &G::alphaMax, kAnyReal),
      number(kGuiding, "half_life", "--half-life", &G::halfLifeFrames, kHalfLife),
      number(kGuiding, "forget_on_light_move", "--forget-on-light-move", &G::forgetOnLightMove,
             kForgetOnLightMove),
      number(kGuiding, "select_probability", "--select-probability", &G::selectProbability,
             kAnyReal),
      number(kGuiding, "confidence_updates", "--confidence-updates", &G::confidenceUpdates,
             kAnyReal),
      number(kGuiding, "points", "--points", &G::pointBudget, kAnyUint),
      word(kGuiding, "point_set", "--point-set", &G::pointSet, pointSetWords()),
      word(kGuiding, "learning_target", "--learning-target", &G::target, learningTargetWords()),
      boolean(kGuiding, "light_learning", "--light-learning", &G::lightLearning),
      number(kGuiding, "light_mix", "", &G::lightMix, kAnyReal),
      number(kGuiding, "nee_min_probability", "--nee-min-probability", &G::neeMinProbability,
             kNeeMinProbability),
      boolean(kGuiding, "guided_roulette", "--guided-roulette", &G::guidedRoulette),
      boolean(kGuiding, "learn", "", &G::learn),
      number(kWindow, "render_scale", "--render-scale", &W::renderScale, kRenderScale),
      number(kWindow, "target_frame_ms", "--target-frame-ms", &W::targetFrameMs, kTargetFrameMs),
      boolean(kWindow, "vsync", "--vsync", &W::vsync),
      environmentFile(),
      skyColor(),
      number(kEnvironment, "strength", "--env-strength", &E::strength, kEnvStrength),
      number(kEnvironment, "rotation", "--env-rotation", &E::rotationDegrees, kEnvRotation),
  };
  return all;
}

const Field* findField(const std::string& section, const std::string& key) {
  for (const Field& f : fields())
    if (f.section == section && f.key == key) return &f;
  return nullptr;
}

bool sectionExists(const std::string& section) {
  for (const Field& f : fields())
    if (f.section == section) return true;
  return false;
}

// Why guiding::validate refuses `g` ("" when it does not).
std::string guidingProblem(const guiding::GuidingSettings& g) {
  try {
    guiding::validate(g);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

// Undoes values of `taken` (guiding ones applied to `s` over the valid `before`) until `s`
// passes guiding::validate, naming each through `refuse` before it is undone: first one
// whose removal alone makes the rest valid, else one invalid on its own, else the last.
template <class Refuse>
void undoInvalidGuiding(std::vector<const Field*> taken, const Settings& before, Settings& s,
                        const Refuse& refuse) {
  for (std::string problem = guidingProblem(s.guiding); !problem.empty() && !taken.empty();
       problem = guidingProblem(s.guiding)) {
    auto without = [&](const Field* f) {
      Settings trial = s;
      f->copy(before, trial);
      return guidingProblem(trial.guiding).empty();
    };
    auto invalidAlone = [&](const Field* f) {
      Settings trial = before;
      f->copy(s, trial);
      return !guidingProblem(trial.guiding).empty();
    };
    auto culprit = std::find_if(taken.rbegin(), taken.rend(), without);
    if (culprit == taken.rend()) culprit = std::find_if(taken.rbegin(), taken.rend(), invalidAlone);
    if (culprit == taken.rend()) culprit = taken.rbegin();
    const Field& f = **culprit;
    if (invalidAlone(&f)) {  // its own problem, not the one of the whole
      Settings alone = before;
      f.copy(s, alone);
      problem = guidingProblem(alone.guiding);
    }
    refuse(f, problem);
    f.copy(before, s);
    taken.erase(std::next(culprit).base());
  }
}

}  // namespace

ordered_json settingsToJson(const Settings& s) {
  ordered_json out = ordered_json::object();
  for (const Field& f : fields()) out[f.section][f.key] = f.get(s);
  return out;
}

std::vector<std::string> applySettingsJson(const json& in, Settings& s, const std::string& fileName,
                                           const GivenOnCommandLine& given) {
  std::vector<std::string> warnings;
  auto warn = [&](const std::string& text) { warnings.push_back(fileName + ": " + text); };
  // Keys in quotes, escaped as JSON: a newline in a key stays out of the one-line warning.
  auto quoted = [](const std::string& key) { return shown(json(key)); };
  auto name = [&](const Field& f) { return quoted(f.section + "." + f.key); };
  for (const auto& [section, keys] : in.items()) {
    if (!sectionExists(section)) {
      warn("unknown key " + quoted(section) + " ignored");
    } else if (!keys.is_object()) {
      warn(quoted(section) + " must be an object of settings, not " + shown(keys) + "; ignored");
    } else {
      for (const auto& [key, value] : keys.items())
        if (!findField(section, key))
          warn("unknown key " + quoted(section + "." + key) + " ignored");
    }
  }
  // In the table's order; the command line's options win.
  const Settings before = s;
  std::vector<const Field*> applied;
  for (const Field& f : fields()) {
    auto section = in.find(f.section);
    if (section == in.end() || !section->is_object()) continue;
    auto value = section->find(f.key);
    if (value == section->end() || (!f.option.empty() && given && given(f.option))) continue;
    const std::string refused = f.set(*value, s);
    if (refused.empty())
      applied.push_back(&f);
    else
      warn(name(f) + " " + refused + "; ignored");
  }
  // Guiding values must also pass guiding::validate, together (alpha_min <= alpha_max).
  // Settings invalid before the file are the command line's error, reported there.
  if (!guidingProblem(before.guiding).empty()) return warnings;
  std::erase_if(applied, [](const Field* f) { return f->section != kGuiding.name; });
  undoInvalidGuiding(applied, before, s, [&](const Field& f, const std::string& problem) {
    warn(name(f) + " " + shown(f.get(s)) + ": " + problem + "; ignored");
  });
  return warnings;
}

std::vector<std::string> loadSettingsFile(const std::filesystem::path& file, Settings& s,
                                          const GivenOnCommandLine& given) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(name + ": cannot open the settings file");
  json parsed;
  try {
    parsed = json::parse(in);
  } catch (const json::parse_error& e) {
    // e.what() starts with "[json.exception.parse_error.101] ": the rest says where and why.
    std::string what = e.what();
    if (size_t end = what.find("] "); what.rfind("[json.", 0) == 0 && end != std::string::npos)
      what = what.substr(end + 2);
    throw std::runtime_error(name + ": not valid JSON: " + what);
  }
  if (!parsed.is_object())
    throw std::runtime_error(name +
                             ": a settings file is a JSON object ({\"render\": {...}, ...}), not " +
                             shown(parsed));
  return applySettingsJson(parsed, s, name, given);
}

void saveSettingsFile(const std::filesystem::path& file, const Settings& s) {
  namespace fs = std::filesystem;
  const std::string name = file.string();
  // Next to the target (a rename is atomic within one file system), unique per process.
  fs::path temporary = file;
  temporary += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << settingsToJson(s).dump(2) << "\n";
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error(name + ": cannot write the settings file");
    }
  }
  std::error_code error;
  fs::rename(temporary, file, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(name + ": cannot write the settings file: " + error.message());
  }
}

}  // namespace qlight::game

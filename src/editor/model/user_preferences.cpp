#include "editor/model/user_preferences.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "editor/model/document_files.h"
#include "io/atomic_write.h"
#include "io/text_file.h"

namespace kinema {

namespace fs = std::filesystem;
using nlohmann::json;

const char* toString(UiTheme theme) {
  switch (theme) {
    case UiTheme::Dark: return "dark";
    case UiTheme::Light: return "light";
    case UiTheme::Classic: return "classic";
  }
  return "dark";
}

bool fromString(const std::string& s, UiTheme& out) {
  for (UiTheme t : {UiTheme::Dark, UiTheme::Light, UiTheme::Classic})
    if (s == toString(t)) {
      out = t;
      return true;
    }
  return false;
}

bool UserPreferences::operator==(const UserPreferences& o) const {
  return uiScale == o.uiScale && lineScale == o.lineScale && theme == o.theme && loop == o.loop &&
         keys.interpolation == o.keys.interpolation && keys.handles == o.keys.handles &&
         keys.locRotOnly == o.keys.locRotOnly && panels == o.panels && window == o.window;
}

namespace {
constexpr float kPresentationUiScale = 2.0f, kPresentationLineScale = 2.5f;
}

UserPreferences presentationPreset(UserPreferences p) {
  p.uiScale = kPresentationUiScale;
  p.lineScale = kPresentationLineScale;
  return p;
}

UserPreferences deskPreset(UserPreferences p) {
  p.uiScale = 1.0f;
  p.lineScale = 1.0f;
  return p;
}

bool isPresentation(const UserPreferences& p) {
  return p.uiScale == kPresentationUiScale && p.lineScale == kPresentationLineScale;
}

WindowPlacement initialWindowPlacement(const WindowPlacement& remembered, const ScreenArea& work) {
  WindowPlacement p;
  if (work.width <= 0 || work.height <= 0) {  // no monitor known: the remembered size, else a desk size
    p.width = remembered.width > 0 ? remembered.width : 1280;
    p.height = remembered.height > 0 ? remembered.height : 720;
    return p;
  }
  if (remembered.width > 0 && remembered.height > 0) {
    p.width = std::min(remembered.width, work.width);
    p.height = std::min(remembered.height, work.height);
  } else {
    p.width = work.width * 9 / 10;
    p.height = work.height * 9 / 10;
  }
  p.positioned = true;
  const bool fits = remembered.positioned && remembered.x >= work.x && remembered.y >= work.y &&
                    remembered.x + p.width <= work.x + work.width && remembered.y + p.height <= work.y + work.height;
  p.x = fits ? remembered.x : work.x + (work.width - p.width) / 2;
  p.y = fits ? remembered.y : work.y + (work.height - p.height) / 2;
  return p;
}

std::string preferencesJson(const UserPreferences& p) {
  json j;
  j["ui_scale"] = p.uiScale;
  j["line_scale"] = p.lineScale;
  j["theme"] = toString(p.theme);
  j["loop"] = p.loop;
  j["new_keys"] = {{"interpolation", toString(p.keys.interpolation)},
                   {"handles", toString(p.keys.handles)},
                   {"location_rotation_only", p.keys.locRotOnly}};
  j["panels"] = {{"left_width", p.panels.leftWidth},
                 {"right_width", p.panels.rightWidth},
                 {"outliner_fraction", p.panels.outlinerFraction},
                 {"properties_fraction", p.panels.propertiesFraction},
                 {"animation_editor_height", p.panels.animationEditorHeight}};
  json w = {{"width", p.window.width}, {"height", p.window.height}};
  if (p.window.positioned) {
    w["x"] = p.window.x;
    w["y"] = p.window.y;
  }
  j["window"] = w;
  return j.dump(2) + "\n";
}

namespace {

std::string shortNumber(float v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// Reads members of one JSON object, reporting wrong ones as "source: path: what".
struct Reader {
  const std::string& source;
  std::vector<std::string>& problems;
  void problem(const std::string& path, const std::string& what) { problems.push_back(source + ": " + path + ": " + what); }
  void number(const json& o, const std::string& key, const std::string& path, float lo, float hi, float& out) {
    if (!o.contains(key)) return;
    const json& v = o[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo || v.get<double>() > hi) {
      problem(path + key, "expected a number from " + shortNumber(lo) + " to " + shortNumber(hi));
      return;
    }
    out = v.get<float>();
  }
  void integer(const json& o, const std::string& key, const std::string& path, int lo, int hi, int& out) {
    if (!o.contains(key)) return;
    const json& v = o[key];
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi) {
      problem(path + key, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
      return;
    }
    out = v.get<int>();
  }
  void boolean(const json& o, const std::string& key, const std::string& path, bool& out) {
    if (!o.contains(key)) return;
    if (!o[key].is_boolean()) return problem(path + key, "expected true or false");
    out = o[key].get<bool>();
  }
  template <class E>
  void name(const json& o, const std::string& key, const std::string& path, E& out) {
    if (!o.contains(key)) return;
    E parsed{};
    if (!o[key].is_string() || !fromString(o[key].get<std::string>(), parsed))
      return problem(path + key, "unknown value " + o[key].dump());
    out = parsed;
  }
  const json* object(const json& o, const std::string& key) {
    if (!o.contains(key)) return nullptr;
    if (!o[key].is_object()) {
      problem(key, "expected an object");
      return nullptr;
    }
    return &o[key];
  }
};

}  // namespace

UserPreferences parsePreferences(const std::string& text, const std::string& source, std::vector<std::string>& problems) {
  UserPreferences p;
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    problems.push_back(source + ": not a JSON object (preferences left at their defaults)");
    return p;
  }
  Reader r{source, problems};
  r.number(j, "ui_scale", "", kMinUiScale, kMaxUiScale, p.uiScale);
  r.number(j, "line_scale", "", kMinLineScale, kMaxLineScale, p.lineScale);
  r.name(j, "theme", "", p.theme);
  r.boolean(j, "loop", "", p.loop);
  if (const json* k = r.object(j, "new_keys")) {
    r.name(*k, "interpolation", "new_keys.", p.keys.interpolation);
    r.name(*k, "handles", "new_keys.", p.keys.handles);
    r.boolean(*k, "location_rotation_only", "new_keys.", p.keys.locRotOnly);
  }
  if (const json* s = r.object(j, "panels")) {
    r.number(*s, "left_width", "panels.", 0.0f, 8192.0f, p.panels.leftWidth);
    r.number(*s, "right_width", "panels.", 0.0f, 8192.0f, p.panels.rightWidth);
    r.number(*s, "outliner_fraction", "panels.", 0.0f, 1.0f, p.panels.outlinerFraction);
    r.number(*s, "properties_fraction", "panels.", 0.0f, 1.0f, p.panels.propertiesFraction);
    r.number(*s, "animation_editor_height", "panels.", 0.0f, 8192.0f, p.panels.animationEditorHeight);
  }
  if (const json* w = r.object(j, "window")) {
    r.integer(*w, "width", "window.", 0, 16384, p.window.width);
    r.integer(*w, "height", "window.", 0, 16384, p.window.height);
    if (w->contains("x") || w->contains("y")) {
      const size_t before = problems.size();
      r.integer(*w, "x", "window.", -65536, 65536, p.window.x);
      r.integer(*w, "y", "window.", -65536, 65536, p.window.y);
      p.window.positioned = problems.size() == before && w->contains("x") && w->contains("y");
    }
    if (p.window.width == 0 || p.window.height == 0) p.window.width = p.window.height = 0;
  }
  return p;
}

std::string userPreferencesPath() {
  const std::string dir = kinemaConfigDir();
  return dir.empty() ? std::string() : dir + "/preferences.json";
}

UserPreferences loadUserPreferences(std::vector<std::string>& problems, const std::string& path) {
  if (path.empty()) return {};
  std::error_code ec;
  if (!fs::exists(path, ec)) return {};
  std::string text;
  if (const std::string error = readTextFile(path, text, 1 << 20); !error.empty()) {
    problems.push_back(error + " (preferences left at their defaults)");
    return {};
  }
  return parsePreferences(text, path, problems);
}

std::string saveUserPreferences(const UserPreferences& p, const std::string& path) {
  if (path.empty()) return "no config folder (neither XDG_CONFIG_HOME nor HOME is set): preferences are not kept";
  std::error_code ec;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) return parent.string() + ": cannot create the folder: " + ec.message();
  return writeFileAtomically(path, preferencesJson(p));
}

}  // namespace kinema

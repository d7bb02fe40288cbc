#include "editor/model/input_events.h"

#include "editor/model/key_codes.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>

#include "io/json_depth.h"
#include "io/text_file.h"

namespace kinema {

namespace {

struct KeyName {
  const char* name;
  int code;
};

// GLFW's named keys; letters and digits are handled by rule below.
const KeyName kKeys[] = {
    {"SPACE", keys::SPACE}, {"APOSTROPHE", keys::APOSTROPHE}, {"COMMA", keys::COMMA},
    {"MINUS", keys::MINUS}, {"PERIOD", keys::PERIOD}, {"SLASH", keys::SLASH},
    {"SEMICOLON", keys::SEMICOLON}, {"EQUAL", keys::EQUAL}, {"LEFT_BRACKET", keys::LEFT_BRACKET},
    {"BACKSLASH", keys::BACKSLASH}, {"RIGHT_BRACKET", keys::RIGHT_BRACKET},
    {"GRAVE_ACCENT", keys::GRAVE_ACCENT}, {"ESCAPE", keys::ESCAPE}, {"ENTER", keys::ENTER},
    {"TAB", keys::TAB}, {"BACKSPACE", keys::BACKSPACE}, {"INSERT", keys::INSERT},
    {"DELETE", keys::DELETE}, {"RIGHT", keys::RIGHT}, {"LEFT", keys::LEFT}, {"DOWN", keys::DOWN},
    {"UP", keys::UP}, {"PAGE_UP", keys::PAGE_UP}, {"PAGE_DOWN", keys::PAGE_DOWN},
    {"HOME", keys::HOME}, {"END", keys::END}, {"KP_DECIMAL", keys::KP_DECIMAL},
    {"KP_DIVIDE", keys::KP_DIVIDE}, {"KP_MULTIPLY", keys::KP_MULTIPLY},
    {"KP_SUBTRACT", keys::KP_SUBTRACT}, {"KP_ADD", keys::KP_ADD}, {"KP_ENTER", keys::KP_ENTER},
    {"KP_EQUAL", keys::KP_EQUAL}, {"LEFT_SHIFT", keys::LEFT_SHIFT},
    {"LEFT_CONTROL", keys::LEFT_CONTROL}, {"LEFT_ALT", keys::LEFT_ALT}, {"LEFT_SUPER", keys::LEFT_SUPER},
    {"RIGHT_SHIFT", keys::RIGHT_SHIFT}, {"RIGHT_CONTROL", keys::RIGHT_CONTROL},
    {"RIGHT_ALT", keys::RIGHT_ALT}, {"RIGHT_SUPER", keys::RIGHT_SUPER}, {"MENU", keys::MENU},
};

const char* kTypeNames[] = {"mouse_move", "button_down", "button_up", "key_down", "key_up", "scroll", "text", "command"};

constexpr size_t kMaxScriptBytes = size_t(64) << 20;
constexpr size_t kMaxEvents = 1000000;
constexpr int kMaxDepth = 16;

using json = nlohmann::json;

// Reads one event object; `where` names it ("event 3", "line 7") for messages. Shorthands
// "key" and "click" expand to a down and an up in the same frame (the handler spreads
// them over two frames so ImGui sees the press).
std::string readEvent(const json& j, std::vector<InputEvent>& out, const CommandIdCheck& isCommand) {
  if (!j.is_object()) return "expected an object";
  InputEvent e;
  auto number = [&](const char* field, double& v) -> std::string {
    if (!j.contains(field)) return "";
    if (!j[field].is_number()) return std::string("'") + field + "' must be a number";
    v = j[field].get<double>();
    if (!std::isfinite(v) || std::abs(v) > 1e7) return std::string("'") + field + "' must be finite and below 1e7";
    return "";
  };
  if (!j.contains("frame")) return "missing 'frame'";
  if (!j["frame"].is_number_integer() || j["frame"].get<long long>() < 0 || j["frame"].get<long long>() > 100000000)
    return "'frame' must be an integer from 0 to 1e8";
  e.frame = j["frame"].get<long long>();
  if (!j.contains("type") || !j["type"].is_string()) return "missing 'type' (a string)";
  const std::string type = j["type"].get<std::string>();
  double x = 0, y = 0;
  if (std::string m = number("x", x); !m.empty()) return m;
  if (std::string m = number("y", y); !m.empty()) return m;
  e.x = static_cast<float>(x);
  e.y = static_cast<float>(y);
  // A widget by name instead of x/y: the editor puts the pointer at the point `at` (fractions
  // of its rectangle, default the centre) where the widget was last drawn.
  if (j.contains("item")) {
    if (!j["item"].is_string() || j["item"].get<std::string>().empty() || j["item"].get<std::string>().size() > 256)
      return "'item' must be a widget name (a non-empty string of at most 256 bytes)";
    if (type != "mouse_move" && type != "button_down" && type != "button_up" && type != "click")
      return "'item' goes with mouse_move, button_down, button_up or click";
    e.item = j["item"].get<std::string>();
  }
  if (j.contains("at")) {
    const json& a = j["at"];
    if (!a.is_array() || a.size() != 2 || !a[0].is_number() || !a[1].is_number() || a[0].get<double>() < 0 ||
        a[0].get<double>() > 1 || a[1].get<double>() < 0 || a[1].get<double>() > 1)
      return "'at' must be [fx, fy] with fractions from 0 to 1 of the item's rectangle";
    if (e.item.empty()) return "'at' needs 'item'";
    e.at = glm::vec2(a[0].get<float>(), a[1].get<float>());
  }
  if (j.contains("mods")) {
    const json& m = j["mods"];
    if (!m.is_array()) return "'mods' must be an array of \"shift\", \"ctrl\", \"alt\", \"super\"";
    for (const json& s : m) {
      const std::string name = s.is_string() ? s.get<std::string>() : "";
      if (name == "shift") e.mods |= kModShift;
      else if (name == "ctrl") e.mods |= kModCtrl;
      else if (name == "alt") e.mods |= kModAlt;
      else if (name == "super") e.mods |= kModSuper;
      else return "'mods' must be an array of \"shift\", \"ctrl\", \"alt\", \"super\"";
    }
  }
  auto readButton = [&]() -> std::string {
    if (!j.contains("button")) return "";
    const json& b = j["button"];
    if (b.is_number_integer() && b.get<int>() >= 0 && b.get<int>() <= 7) e.button = b.get<int>();
    else if (b == "left") e.button = 0;
    else if (b == "right") e.button = 1;
    else if (b == "middle") e.button = 2;
    else return "'button' must be \"left\", \"right\", \"middle\" or 0..7";
    return "";
  };
  auto readKey = [&]() -> std::string {
    if (!j.contains("key") || !j["key"].is_string()) return "missing 'key' (a GLFW key name such as \"R\" or \"KP_1\")";
    e.key = keyCodeFromName(j["key"].get<std::string>());
    if (e.key < 0) return "'key' \"" + j["key"].get<std::string>() + "\" is not a GLFW key name";
    return "";
  };
  if (type == "mouse_move") {
    e.type = InputEventType::MouseMove;
  } else if (type == "button_down" || type == "button_up" || type == "click") {
    if (std::string m = readButton(); !m.empty()) return m;
    e.type = type == "button_up" ? InputEventType::ButtonUp : InputEventType::ButtonDown;
  } else if (type == "key_down" || type == "key_up" || type == "key") {
    if (std::string m = readKey(); !m.empty()) return m;
    e.type = type == "key_up" ? InputEventType::KeyUp : InputEventType::KeyDown;
  } else if (type == "scroll") {
    e.type = InputEventType::Scroll;
  } else if (type == "text") {
    if (!j.contains("text") || !j["text"].is_string()) return "missing 'text' (a string)";
    e.type = InputEventType::Text;
    e.text = j["text"].get<std::string>();
  } else if (type == "command") {
    if (!j.contains("id") || !j["id"].is_string()) return "missing 'id' (a command id such as \"file.save\")";
    e.type = InputEventType::Command;
    e.text = j["id"].get<std::string>();
    if (isCommand && !isCommand(e.text))
      return "'id' \"" + e.text + "\" is not a command (kinema edit --list-commands lists them)";
  } else {
    return "unknown 'type' \"" + type +
           "\" (expected mouse_move, button_down, button_up, click, key_down, key_up, key, scroll, text or command)";
  }
  out.push_back(e);
  if (type == "click" || type == "key") {
    e.type = type == "click" ? InputEventType::ButtonUp : InputEventType::KeyUp;
    out.push_back(e);
  }
  return "";
}

}  // namespace

const char* toString(InputEventType type) { return kTypeNames[static_cast<int>(type)]; }

bool isModifierKey(int key) {
  return key == keys::LEFT_SHIFT || key == keys::RIGHT_SHIFT || key == keys::LEFT_CONTROL ||
         key == keys::RIGHT_CONTROL || key == keys::LEFT_ALT || key == keys::RIGHT_ALT || key == keys::LEFT_SUPER ||
         key == keys::RIGHT_SUPER;
}

int HeldInput::track(const InputEvent& e) {
  int bit = 0;
  if (e.key == keys::LEFT_SHIFT || e.key == keys::RIGHT_SHIFT) bit = kModShift;
  else if (e.key == keys::LEFT_CONTROL || e.key == keys::RIGHT_CONTROL) bit = kModCtrl;
  else if (e.key == keys::LEFT_ALT || e.key == keys::RIGHT_ALT) bit = kModAlt;
  else if (e.key == keys::LEFT_SUPER || e.key == keys::RIGHT_SUPER) bit = kModSuper;
  if (bit && e.type == InputEventType::KeyDown) mods |= bit;
  if (bit && e.type == InputEventType::KeyUp) mods &= ~bit;
  if (e.type == InputEventType::MouseMove) mouse = glm::vec2(e.x, e.y);
  return mods | e.mods;
}

int keyCodeFromName(const std::string& name) {
  if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z') return keys::A + (name[0] - 'A');
  if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return keys::Num0 + (name[0] - '0');
  if (name.size() == 4 && name.compare(0, 3, "KP_") == 0 && name[3] >= '0' && name[3] <= '9')
    return keys::KP_0 + (name[3] - '0');
  if ((name.size() == 2 || name.size() == 3) && name[0] == 'F' && name[1] >= '1' && name[1] <= '9') {
    const int n = std::stoi(name.substr(1));
    if (n >= 1 && n <= 25) return keys::F1 + n - 1;
  }
  for (const KeyName& k : kKeys)
    if (name == k.name) return k.code;
  return -1;
}

std::string keyNameFromCode(int code) {
  if (code >= keys::A && code <= keys::Z) return std::string(1, char('A' + code - keys::A));
  if (code >= keys::Num0 && code <= keys::Num9) return std::string(1, char('0' + code - keys::Num0));
  if (code >= keys::KP_0 && code <= keys::KP_9) return "KP_" + std::string(1, char('0' + code - keys::KP_0));
  if (code >= keys::F1 && code <= keys::F25) return "F" + std::to_string(code - keys::F1 + 1);
  for (const KeyName& k : kKeys)
    if (code == k.code) return k.name;
  return "";
}

Result<std::vector<InputEvent>> parseInputScript(const std::string& text, const std::string& source,
                                                 const CommandIdCheck& isCommand) {
  using R = Result<std::vector<InputEvent>>;
  std::vector<InputEvent> events;
  if (jsonNestingDepth(text.data(), text.size()) > kMaxDepth)
    return R::failure(source + ": nested deeper than " + std::to_string(kMaxDepth) + " levels");
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '[') {
    json array = json::parse(text, nullptr, false);
    if (array.is_discarded()) return R::failure(source + ": not valid JSON (expected an array of events)");
    if (array.size() > kMaxEvents) return R::failure(source + ": more than 1000000 events");
    for (size_t i = 0; i < array.size(); ++i)
      if (std::string m = readEvent(array[i], events, isCommand); !m.empty())
        return R::failure(source + ": event " + std::to_string(i) + ": " + m);
  } else {
    std::vector<std::string> lines;
    splitLines(text, lines);
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string line = trim(lines[i]);
      if (line.empty() || line[0] == '#' || line.compare(0, 2, "//") == 0) continue;
      json j = json::parse(line, nullptr, false);
      if (j.is_discarded()) return R::failure(source + ": line " + std::to_string(i + 1) + ": not valid JSON");
      if (std::string m = readEvent(j, events, isCommand); !m.empty())
        return R::failure(source + ": line " + std::to_string(i + 1) + ": " + m);
      if (events.size() > kMaxEvents) return R::failure(source + ": more than 1000000 events");
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const InputEvent& a, const InputEvent& b) { return a.frame < b.frame; });
  return events;
}

Result<std::vector<InputEvent>> loadInputScript(const std::string& path, const CommandIdCheck& isCommand) {
  std::string text;
  if (std::string error = readTextFile(path, text, kMaxScriptBytes); !error.empty())
    return Result<std::vector<InputEvent>>::failure(error);
  return parseInputScript(text, path, isCommand);
}

}  // namespace kinema

#include "editor/commands/keymap.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "editor/model/document_files.h"
#include "io/text_file.h"

namespace kinema {

namespace {

constexpr size_t kMaxKeymapBytes = size_t(1) << 20;

}  // namespace

Keymap::Keymap(const CommandRegistry& registry) : registry_(&registry) {
  for (const Command& c : registry.all()) bindings_[c.id] = c.keys;
}

const Command* Keymap::holder(CommandScope scope, KeyChord chord) const {
  for (const Command& c : registry_->all()) {
    if (c.scope != scope) continue;
    const std::vector<KeyChord>& bound = chords(c.id);
    if (std::find(bound.begin(), bound.end(), chord) != bound.end()) return &c;
  }
  return nullptr;
}

std::string Keymap::bind(const std::string& id, KeyChord chord) {
  const Command* command = registry_->find(id);
  if (!command) return "unknown command '" + id + "' (kinema edit --list-commands lists them)";
  if (!chord.valid() || formatChord(chord).empty()) return "not a key chord";
  const Command* taken = holder(command->scope, chord);
  if (taken && taken->id != id)
    return formatChord(chord) + " is already bound to " + taken->id + " (" + scopeTitle(command->scope) + ")";
  std::vector<KeyChord>& bound = bindings_[id];
  if (std::find(bound.begin(), bound.end(), chord) == bound.end()) bound.push_back(chord);
  return "";
}

void Keymap::unbind(const std::string& id) {
  if (auto it = bindings_.find(id); it != bindings_.end()) it->second.clear();
}

const std::vector<KeyChord>& Keymap::chords(const std::string& id) const {
  static const std::vector<KeyChord> none;
  const auto it = bindings_.find(id);
  return it == bindings_.end() ? none : it->second;
}

std::string Keymap::shortcut(const std::string& id) const {
  const std::vector<KeyChord>& bound = chords(id);
  return bound.empty() ? std::string() : formatChord(bound.front());
}

std::string Keymap::shortcuts(const std::string& id, const std::string& separator) const {
  std::string out;
  for (const KeyChord& c : chords(id)) out += (out.empty() ? "" : separator) + formatChord(c);
  return out;
}

std::vector<std::string> Keymap::apply(const std::string& text, const std::string& source) {
  std::vector<std::string> problems;
  std::set<std::string> replaced;  // commands whose defaults this file has replaced already
  std::vector<std::string> lines;
  splitLines(text, lines);
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string where = source + ":" + std::to_string(i + 1) + ": ";
    const std::string line = trim(lines[i].substr(0, lines[i].find('#')));
    if (line.empty()) continue;
    // The first '=' ends the id; the chord may itself be "=".
    const size_t eq = line.find('=');
    const std::string id = eq == std::string::npos ? "" : trim(line.substr(0, eq));
    const std::string value = eq == std::string::npos ? "" : trim(line.substr(eq + 1));
    if (id.empty() || value.empty()) {
      problems.push_back(where + "expected 'command.id = Chord' or 'command.id = none', got '" + line + "'");
      continue;
    }
    if (!registry_->find(id)) {
      problems.push_back(where + "unknown command '" + id + "' (kinema edit --list-commands lists them)");
      continue;
    }
    std::string lowered = value;
    std::transform(lowered.begin(), lowered.end(), lowered.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lowered == "none") {
      unbind(id);
      replaced.insert(id);
      continue;
    }
    const std::optional<KeyChord> chord = parseChord(value);
    if (!chord) {
      problems.push_back(where + "'" + value + "' is not a key chord (e.g. Ctrl+Shift+Z, Alt+R, Numpad 1, F1)");
      continue;
    }
    // Replacing the defaults must not lose them when the new chord is refused.
    const std::vector<KeyChord> before = chords(id);
    if (!replaced.count(id)) unbind(id);
    if (const std::string error = bind(id, *chord); !error.empty()) {
      bindings_[id] = before;
      problems.push_back(where + error);
      continue;
    }
    replaced.insert(id);
  }
  return problems;
}

std::string userKeymapPath() {
  const std::string dir = kinemaConfigDir();
  return dir.empty() ? std::string() : dir + "/keymap.txt";
}

Keymap loadUserKeymap(const CommandRegistry& registry, std::vector<std::string>& problems) {
  Keymap keymap(registry);
  const std::string path = userKeymapPath();
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec)) return keymap;
  std::string text;
  if (const std::string error = readTextFile(path, text, kMaxKeymapBytes); !error.empty()) {
    problems.push_back(error);
    return keymap;
  }
  for (std::string& p : keymap.apply(text, path)) problems.push_back(std::move(p));
  return keymap;
}

}  // namespace kinema

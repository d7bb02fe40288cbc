#include "io/gltf_error_text.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <functional>
#include <utility>

#include "io/gltf_external_files.h"
#include "io/json_document.h"
#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

namespace {

using GltfJson = nlohmann::json;

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The objects of a glTF file in the order tinygltf reads them, each with its place name.
void eachObject(const GltfJson& root, const std::function<bool(const std::string&, const GltfJson&)>& visit) {
  static const std::pair<const char*, const char*> kArrays[] = {
      {"buffers", "buffer"},     {"bufferViews", "bufferView"}, {"accessors", "accessor"}, {"meshes", "mesh"},
      {"nodes", "node"},         {"scenes", "scene"},           {"materials", "material"},  {"images", "image"},
      {"textures", "texture"},   {"samplers", "sampler"},       {"skins", "skin"},          {"animations", "animation"},
      {"cameras", "camera"}};
  if (root.contains("asset") && root["asset"].is_object() && !visit("asset", root["asset"])) return;
  for (const auto& [key, name] : kArrays) {
    const auto it = root.find(key);
    if (it == root.end() || !it->is_array()) continue;
    for (size_t i = 0; i < it->size(); ++i) {
      const GltfJson& o = (*it)[i];
      if (!o.is_object()) continue;
      const std::string place = std::string(name) + " " + std::to_string(i);
      if (!visit(place, o)) return;
      // The parts tinygltf checks inside: primitives, animation channels and samplers.
      auto inner = [&](const char* arrayKey, const char* partName) {
        const auto part = o.find(arrayKey);
        if (part == o.end() || !part->is_array()) return true;
        for (size_t k = 0; k < part->size(); ++k) {
          if (!(*part)[k].is_object()) continue;
          const std::string where = place + " " + partName + " " + std::to_string(k);
          if (!visit(where, (*part)[k])) return false;
          const auto target = (*part)[k].find("target");
          if (target != (*part)[k].end() && target->is_object() && !visit(where + " target", *target)) return false;
        }
        return true;
      };
      if (!inner("primitives", "primitive") || !inner("channels", "channel") || !inner("samplers", "sampler")) return;
    }
  }
}

// Properties glTF requires, by the kind of object (the word before the index in a place).
bool required(const std::string& place, const std::string& property) {
  static const std::pair<const char*, const char*> kRequired[] = {
      {"accessor", "componentType"}, {"accessor", "count"},    {"accessor", "type"},      {"bufferView", "buffer"},
      {"bufferView", "byteLength"},  {"buffer", "byteLength"}, {"skin", "joints"},        {"mesh", "primitives"},
      {"primitive", "attributes"},   {"channel", "sampler"},   {"channel", "target"},     {"target", "path"},
      {"sampler", "input"},          {"sampler", "output"},    {"asset", "version"}};
  for (const auto& [kind, name] : kRequired) {
    const std::string k = kind;
    const bool kindMatches = place.rfind(k, 0) == 0 || place.find(" " + k + " ") != std::string::npos ||
                             (place.size() > k.size() && place.compare(place.size() - k.size(), k.size(), k) == 0);
    if (kindMatches && property == name) return true;
  }
  return false;
}

// Does `value` (absent when null) break the rule tinygltf's message `what` states?
bool breaks(const GltfJson* value, const std::string& property, const std::string& what, const std::string& place) {
  if (what.find("missing") != std::string::npos) return !value && required(place, property);
  if (!value) return false;
  if (property == "byteStride" && what.find("Invalid") != std::string::npos) {
    if (!value->is_number_unsigned()) return true;
    const auto s = value->get<unsigned long long>();
    return s > 252 || s % 4 != 0;
  }
  if (what.find("positive integer") != std::string::npos || what.find("integer type") != std::string::npos) {
    if (value->is_number_unsigned()) return false;
    if (value->is_number_integer()) return what.find("positive") != std::string::npos;
    return true;
  }
  if (what.find("number") != std::string::npos) return !value->is_number();
  if (what.find("string") != std::string::npos) return !value->is_string();
  if (what.find("bool") != std::string::npos) return !value->is_boolean();
  if (what.find("array") != std::string::npos) return !value->is_array();
  if (what.find("object") != std::string::npos) return !value->is_object();
  return false;
}

// The property a tinygltf message is about: 'count', `byteStride', ...
std::string propertyOf(const std::string& line) {
  const size_t a = line.find_first_of("'`");
  if (a == std::string::npos) return {};
  const size_t b = line.find_first_of("'`", a + 1);
  if (b == std::string::npos || b == a + 1 || b - a > 40) return {};
  return line.substr(a + 1, b - a - 1);
}

std::string withoutEnd(std::string s) {
  while (!s.empty() && (s.back() == '.' || s.back() == ' ' || s.back() == '\'')) s.pop_back();
  return s;
}

}  // namespace

std::string GltfErrorText::error(const std::string& err) const {
  std::string line;
  for (size_t start = 0; start < err.size();) {
    size_t end = err.find('\n', start);
    if (end == std::string::npos) end = err.size();
    line = err.substr(start, std::min<size_t>(end - start, 4096));
    if (!line.empty() && line.find_first_not_of(" \t\r") != std::string::npos) break;
    start = end + 1;
  }
  // Files tinygltf could not read: the reason recorded when the uri was resolved.
  const auto uriProblem = [&](const std::string& decoded, const std::string& fallback) {
    std::string why = files ? files->whyRefused(decoded) : std::string();
    if (why.empty()) why = fallback;
    // tinygltf takes a data URI it cannot decode for a file name.
    if (startsWith(decoded, "data:"))
      why = "is not a base64 data URI of a type glTF reads (data:application/octet-stream;base64,..., "
            "data:image/png;base64,...)";
    std::string place;
    if (json && jsonTreeBytes(json, jsonLength) <= treeBudget) {
      const GltfJson root = GltfJson::parse(json, json + jsonLength, nullptr, false);
      eachObject(root, [&](const std::string& where, const GltfJson& o) {
        const auto uri = o.find("uri");
        if (uri == o.end() || !uri->is_string() || percentDecoded(uri->get<std::string>()) != decoded) return true;
        place = where + ": ";
        return false;
      });
    }
    return place + "uri '" + cutForMessage(decoded) + "' " + why;
  };
  for (const char* prefix : {"File not found : ", "File read error : ", "File is empty : ", "File size mismatch : "}) {
    if (!startsWith(line, prefix)) continue;
    std::string rest = line.substr(std::strlen(prefix));
    if (startsWith(line, "File not found")) return uriProblem(rest, "is not there (no such file beside the glTF file)");
    // The others name the path tinygltf joined: the uri is what follows the folder.
    const std::string folder = files && !files->folder.empty() ? files->folder + "/" : "";
    if (startsWith(rest, folder.c_str())) rest = rest.substr(folder.size());
    if (startsWith(line, "File is empty")) return uriProblem(withoutEnd(rest), "is an empty file");
    if (startsWith(line, "File read error")) {
      const size_t colon = rest.find(" : ");
      return uriProblem(rest.substr(0, colon), "could not be read");
    }
    // "File size mismatch : PATH, requestedBytes N, but got M": the file's real size is not
    // repeated (it would tell a probing file the size of what it named).
    const size_t comma = rest.find(", requestedBytes ");
    const std::string wanted = comma == std::string::npos ? "" : rest.substr(comma + 17, rest.find(',', comma + 17) - comma - 17);
    return uriProblem(rest.substr(0, comma), "does not hold the buffer's byteLength of " + wanted + " bytes");
  }
  const std::string property = propertyOf(line);
  if (!property.empty() && json && jsonTreeBytes(json, jsonLength) <= treeBudget) {
    const GltfJson root = GltfJson::parse(json, json + jsonLength, nullptr, false);
    std::string found;
    eachObject(root, [&](const std::string& place, const GltfJson& o) {
      const auto it = o.find(property);
      if (!breaks(it == o.end() ? nullptr : &*it, property, line, place)) return true;
      found = place;
      return false;
    });
    if (!found.empty()) {
      std::string what = line;
      const size_t in = what.find(" in ");
      if (in != std::string::npos && what.find("property") != std::string::npos) what = what.substr(0, in);
      return found + ": " + cutForMessage(withoutEnd(what), 160);
    }
  }
  return "glTF: " + cutForMessage(withoutEnd(line), 200);
}

std::vector<std::string> GltfErrorText::warnings(const std::string& warn) const {
  std::vector<std::string> out;
  std::vector<std::string> lines;
  splitLines(warn, lines);
  std::string pendingFile;  // "File not found : X" comes before the line naming the image
  for (const std::string& raw : lines) {
    const std::string line = raw.substr(0, std::min<size_t>(raw.size(), 4096));
    if (isBlank(line)) continue;
    if (startsWith(line, "File not found : ") || startsWith(line, "File read error : ") ||
        startsWith(line, "File is empty : ")) {
      pendingFile = line;
      continue;
    }
    const size_t image = line.find("for image[");
    if (startsWith(line, "Failed to load external 'uri'") && image != std::string::npos) {
      const std::string index = line.substr(image + 10, line.find(']', image) - image - 10);
      std::string why = pendingFile.empty() ? std::string("could not be read") : error(pendingFile);
      const size_t colon = why.find(": uri '");
      if (colon != std::string::npos) why = why.substr(colon + 2);
      out.push_back("image " + index + ": " + why + ": shown without its texture");
      pendingFile.clear();
      continue;
    }
    out.push_back("glTF: " + cutForMessage(withoutEnd(line), 200));
  }
  if (!pendingFile.empty()) out.push_back(error(pendingFile));
  return out;
}

}  // namespace kinema

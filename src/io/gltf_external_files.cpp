#include "io/gltf_external_files.h"

#include <tiny_gltf.h>

#include <climits>
#include <cstdlib>
#include <vector>

#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

namespace {

std::string realPath(const std::string& path) {
  char* resolved = ::realpath(path.c_str(), nullptr);
  if (!resolved) return {};
  std::string out(resolved);
  std::free(resolved);
  return out;
}

bool isInside(const std::string& file, const std::string& folder) {
  if (folder == "/") return true;
  return file.size() > folder.size() && file.compare(0, folder.size(), folder) == 0 && file[folder.size()] == '/';
}

std::string prefixOf(const std::string& folder) { return folder.empty() || folder.back() == '/' ? folder : folder + "/"; }

// Whether a relative path climbs above its start ("a/../../b" does), judged on its text alone,
// so that refusing it says nothing about what exists outside the folder.
bool climbsOut(const std::string& uri) {
  int depth = 0;
  for (size_t begin = 0; begin <= uri.size();) {
    size_t end = uri.find('/', begin);
    if (end == std::string::npos) end = uri.size();
    const std::string part = uri.substr(begin, end - begin);
    if (part == "..") {
      if (--depth < 0) return true;
    } else if (!part.empty() && part != ".") {
      ++depth;
    }
    begin = end + 1;
  }
  return false;
}

bool fileExists(const std::string& path, void* self) { return static_cast<GltfExternalFiles*>(self)->exists(path); }

std::string expandNothing(const std::string& path, void*) { return path; }  // no shell expansion of ~ or $VAR

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
  auto* files = static_cast<GltfExternalFiles*>(self);
  out->clear();
  if (std::string e = readFileBytes(path, *out, files->maxBytes); !e.empty()) {
    if (err) *err += e;
    files->refused[path.substr(std::min(path.size(), prefixOf(files->folder).size()))] = e;
    return false;
  }
  files->bytesRead += out->size();
  return true;
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the reader does not write files";
  return false;
}

}  // namespace

void GltfExternalFiles::install(tinygltf::TinyGLTF& loader) {
  loader.SetFsCallbacks({fileExists, expandNothing, readWholeFile, writeNothing, this});
}

bool GltfExternalFiles::exists(const std::string& joined) {
  const std::string prefix = prefixOf(folder);
  // tinygltf tries the glTF file's folder, then the working folder: only the first counts.
  if (joined.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string uri = joined.substr(prefix.size());
  if (refused.count(uri)) return false;
  auto refuse = [&](const std::string& why) {
    refused[uri] = why;
    return false;
  };
  // tinygltf would look for an absolute path inside the folder: say what it is instead.
  if (!uri.empty() && uri[0] == '/') return refuse("is an absolute path; Kinema reads uris relative to the glTF file");
  if (!allowOutside && climbsOut(uri))
    return refuse("is outside the glTF file's folder (--allow-outside-paths reads it)");
  const std::string real = realPath(joined);
  if (real.empty()) return refuse("is not there (no such file beside the glTF file)");
  if (!allowOutside) {  // a link inside the folder may still lead out of it
    const std::string realFolder = realPath(folder.empty() ? "." : folder);
    if (!isInside(real, realFolder))
      return refuse("is outside the glTF file's folder (--allow-outside-paths reads it)");
  }
  if (std::string why = notARegularFile(real); !why.empty()) return refuse(why);
  return true;
}

std::string GltfExternalFiles::whyRefused(const std::string& decoded) const {
  const auto it = refused.find(decoded);
  return it == refused.end() ? std::string() : it->second;
}

std::string percentDecoded(const std::string& uri) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;
  };
  // As tinygltf decodes (form encoding: '+' is a space).
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size()) {
      out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace kinema

#pragma once
#include <cstddef>
#include <map>
#include <string>

namespace tinygltf {
class TinyGLTF;
}

namespace kinema {

// The files a .gltf names in its buffer and image uris. tinygltf resolves each uri
// (percent-decoded) against the glTF file's folder and asks these callbacks whether it
// exists and for its bytes. A uri is read only when it resolves (symbolic links and ".."
// followed) to a regular file inside that folder or one of its sub-folders; with
// `allowOutside` (--allow-outside-paths) other folders too. Devices, FIFOs, sockets and
// /proc are never read. tinygltf's fallback to the working folder is refused.
struct GltfExternalFiles {
  std::string folder;  // the glTF file's folder, as tinygltf joins uris to it
  bool allowOutside = false;
  size_t maxBytes = 0;   // per file
  size_t bytesRead = 0;  // all files read, for the image memory budget
  // Uris (percent-decoded, as tinygltf reports them) refused, and why.
  std::map<std::string, std::string> refused;

  // Installs the callbacks on `loader`; `this` must outlive the load.
  void install(tinygltf::TinyGLTF& loader);
  // Why the uri `decoded` was not read ("" when it was not refused by these callbacks).
  std::string whyRefused(const std::string& decoded) const;

  // The FileExists callback: records why a uri is refused.
  bool exists(const std::string& joined);
};

// `uri` decoded as tinygltf decodes uris before resolving them (%XX escapes, '+' a space).
std::string percentDecoded(const std::string& uri);

}  // namespace kinema

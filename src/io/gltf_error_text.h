#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace kinema {

struct GltfExternalFiles;

// tinygltf's error and warning texts as Kinema's one-line messages with a place: which
// buffer, bufferView, accessor, image, ... a message is about ("accessor 3: 'count' property
// is not a positive integer", "buffer 0: uri '../../etc/passwd' is outside the glTF file's
// folder ..."). tinygltf names no index for most of its checks; the place is found by
// looking for the object whose property breaks the rule the message states. Messages are
// returned without the file name (the caller puts it in front).
struct GltfErrorText {
  const char* json = nullptr;  // the glTF JSON text
  size_t jsonLength = 0;
  size_t treeBudget = 0;  // bytes the JSON's tree may take to be searched (else no place)
  const GltfExternalFiles* files = nullptr;

  // The first error in tinygltf's `err` text.
  std::string error(const std::string& err) const;
  // Each warning in tinygltf's `warn` text.
  std::vector<std::string> warnings(const std::string& warn) const;
};

}  // namespace kinema

#pragma once
#include <string>

#include "io/input_limits.h"
#include "scene/scene.h"

namespace kinema {

// The native project format (docs/kinema-format.md): versioned JSON.
constexpr int kKinemaFormatVersion = 1;

std::string toKinemaJson(const Scene& scene);
// `source` names the file in error messages, which also give the JSON path
// ("walk.kinema: skeleton.joints[3].parent: ...").
// `limits` caps the nesting depth, joints and keys per clip before they are read.
Result<Scene> parseKinemaJson(const std::string& text, const std::string& source, const InputLimits& limits = {});

Result<Scene> loadKinemaFile(const std::string& path, const InputLimits& limits = {});
// An IK rig file: {"limits": [...], "targets": [...]}, the schema of a .kinema file's
// "ik" key, with joints named in `skeleton`.
Result<IkRig> parseIkRigJson(const std::string& text, const std::string& source, const Skeleton& skeleton);
// Validates first, then writes a temporary file and renames it over `path`, so a failed
// save leaves the previous file intact. Returns an empty string or the error.
std::string saveKinemaFile(const std::string& path, const Scene& scene);

}  // namespace kinema

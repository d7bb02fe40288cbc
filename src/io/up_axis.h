#pragma once
#include <optional>
#include <string>

namespace kinema {

// Which axis points up in a BVH file. Kinema, like the BVH convention, is Y-up; Blender's
// BVH exporter (and some mocap tools) write Z-up files, which import lying on the ground
// unless read as Z-up (`--up z`, the editor's open dialog).
enum class UpAxis { Y, Z };

// "y" / "z" (either case), or nothing.
inline std::optional<UpAxis> upAxisFromString(const std::string& text) {
  if (text == "y" || text == "Y") return UpAxis::Y;
  if (text == "z" || text == "Z") return UpAxis::Z;
  return std::nullopt;
}

}  // namespace kinema

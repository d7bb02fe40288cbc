#include "scene/scene.h"

#include <algorithm>

namespace kinema {

Clip clipOnItsGrid(const Scene& scene, int clip) {
  Clip out = clip >= 0 && clip < static_cast<int>(scene.clips.size()) ? scene.clips[clip] : Clip{};
  out.frameTime = scene.frameGrid(clip).secondsPerFrame;
  return out;
}

bool hasUndecodedImages(const Scene& scene) {
  return std::any_of(scene.images.begin(), scene.images.end(), isUndecodedImage);
}

Scene withoutUndecodedImages(const Scene& scene, std::vector<int>* dropped) {
  Scene out = scene;
  std::vector<int> newIndex(scene.images.size(), -1);
  out.images.clear();
  for (size_t i = 0; i < scene.images.size(); ++i) {
    if (isUndecodedImage(scene.images[i])) {
      if (dropped) dropped->push_back(static_cast<int>(i));
      continue;
    }
    newIndex[i] = static_cast<int>(out.images.size());
    out.images.push_back(scene.images[i]);
  }
  for (Material& m : out.materials)
    if (m.baseColorImage >= 0 && m.baseColorImage < static_cast<int>(newIndex.size()))
      m.baseColorImage = newIndex[m.baseColorImage];
  return out;
}

}  // namespace kinema

#include "editor/model/curve_key_edits.h"

namespace kinema {

namespace {
bool hasClip(const DocumentEdit& e, int clip) { return clip >= 0 && clip < static_cast<int>(e.clips.size()); }
}  // namespace

std::string editCurveKeySettings(Document& doc, int clip, const std::vector<CurveKeyRef>& keys, const std::string& label,
                                 const std::function<void(KeySettings&)>& change, int* skipped) {
  int left = 0;
  const std::string error = doc.edit(label, [&](DocumentEdit& e) {
    if (!hasClip(e, clip)) return label + ": no clip to edit";
    left = changeKeySettings(e.clips[clip], keys, change);
    return std::string();
  });
  if (skipped) *skipped = left;
  return error;
}

std::string dragCurveKeySettings(Document& doc, int clip, const std::vector<CurveKeyRef>& keys,
                                 const std::function<void(KeySettings&)>& change) {
  return doc.updateDrag([&](DocumentEdit& e) {
    if (!hasClip(e, clip)) return std::string("no clip to edit");
    changeKeySettings(e.clips[clip], keys, change);
    return std::string();
  });
}

std::string setCurveKeyFrame(Document& doc, int clip, const CurveKeyRef& key, const FrameGrid& grid, long long frame,
                             CurveKeyRef& moved) {
  return doc.edit("Key time", [&](DocumentEdit& e) {
    if (!hasClip(e, clip) || key.channel < 0 || key.channel >= static_cast<int>(e.clips[clip].channels.size()))
      return std::string("Key time: no such key");
    Channel& c = e.clips[clip].channels[key.channel];
    if (key.key < 0 || key.key >= c.keyCount()) return std::string("Key time: no such key");
    moved = {key.channel, key.component, moveKey(c, key.key, grid.frameToTime(frame))};
    return std::string();
  });
}

std::string setCurveKeyValue(Document& doc, int clip, const CurveKeyRef& key, RotationView view, EulerOrder order,
                             float value) {
  return doc.edit("Key value", [&](DocumentEdit& e) {
    if (!hasClip(e, clip) || key.channel < 0 || key.channel >= static_cast<int>(e.clips[clip].channels.size()))
      return std::string("Key value: no such key");
    setKeyDisplayValue(e.clips[clip].channels[key.channel], key.key, key.component, view, order, value);
    return std::string();
  });
}

std::string dragCurveKeys(Document& doc, int clip, const FrameGrid& grid, const std::vector<CurveKeyRef>& startKeys,
                          const std::vector<float>& startValues, const std::vector<float>& scales, float dt, float dv,
                          RotationView view, EulerOrder order, std::vector<CurveKeyRef>& moved) {
  return doc.updateDrag([&](DocumentEdit& e) {
    if (!hasClip(e, clip)) return std::string("no clip to edit");
    moved = moveCurveKeys(e.clips[clip], grid, startKeys, startValues, scales, dt, dv, view, order);
    return std::string();
  });
}

std::string dragCurveKeyHandle(Document& doc, int clip, const CurveHandle& handle, glm::vec2 offset, RotationView view,
                               EulerOrder order, float fps) {
  return doc.updateDrag([&](DocumentEdit& e) {
    if (!hasClip(e, clip) || handle.key.channel < 0 || handle.key.channel >= static_cast<int>(e.clips[clip].channels.size()))
      return std::string("no such key");
    dragCurveHandle(e.clips[clip].channels[handle.key.channel], handle, offset, view, order, fps);
    return std::string();
  });
}

}  // namespace kinema

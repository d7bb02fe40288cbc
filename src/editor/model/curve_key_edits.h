#pragma once
// The curve editor's edits of the document (the panel calls these; each is one undo step, or
// one step of a Document drag that the panel began): key settings, a key's frame and value,
// dragging keys and handles. The clip arithmetic is curve_editor.h's.
#include <functional>
#include <string>
#include <vector>

#include "editor/model/curve_editor.h"
#include "editor/model/document.h"

namespace kinema {

// Changes the settings of `keys` in clips[clip] (one undo step `label`); `skipped` gets the
// number left alone because the change does not suit their channel.
std::string editCurveKeySettings(Document& doc, int clip, const std::vector<CurveKeyRef>& keys, const std::string& label,
                                 const std::function<void(KeySettings&)>& change, int* skipped = nullptr);
// The same as a step of the document's current drag (a slider held down).
std::string dragCurveKeySettings(Document& doc, int clip, const std::vector<CurveKeyRef>& keys,
                                 const std::function<void(KeySettings&)>& change);
// Moves key `key` to whole frame `frame` of `grid` ("Key time"); `moved` gets its new reference.
std::string setCurveKeyFrame(Document& doc, int clip, const CurveKeyRef& key, const FrameGrid& grid, long long frame,
                             CurveKeyRef& moved);
// Sets the key's value in display units ("Key value"; degrees for angles, as shown).
std::string setCurveKeyValue(Document& doc, int clip, const CurveKeyRef& key, RotationView view, EulerOrder order,
                             float value);
// Steps of a "Move keys" / "Move handle" drag (moveCurveKeys / dragCurveHandle from the
// drag's start); `moved` gets the keys' new references.
std::string dragCurveKeys(Document& doc, int clip, const FrameGrid& grid, const std::vector<CurveKeyRef>& startKeys,
                          const std::vector<float>& startValues, const std::vector<float>& scales, float dt, float dv,
                          RotationView view, EulerOrder order, std::vector<CurveKeyRef>& moved);
std::string dragCurveKeyHandle(Document& doc, int clip, const CurveHandle& handle, glm::vec2 offset, RotationView view,
                               EulerOrder order, float fps);

}  // namespace kinema

#pragma once

namespace kinema {

struct EditorState;

// How the 3D view of one frame is antialiased, as Blender's viewport does it: while the
// picture moves (a clip plays, a modal tool runs: a drag, R/G, navigation; or anything in
// the view changed since the previous frame) it is drawn with one sample per pixel, which a
// software rasteriser fills several times faster; once it holds still the same picture is
// drawn again with full multisampling and kept (the window shows that copy until something
// changes).
enum class ViewportQuality { Moving, Still };

constexpr int kMovingViewportSamples = 1;
constexpr int kStillViewportSamples = 4;  // or fewer where the driver offers fewer

// `sceneChanged`: what the 3D view shows differs from what it showed last frame (camera,
// pose, colours, overlay...). `stillPicture`: the frame is the one a --screenshot keeps,
// always drawn at full quality.
ViewportQuality viewportQuality(const EditorState& state, bool sceneChanged, bool stillPicture = false);
int viewportSamples(ViewportQuality quality);

// What the window did for the last frame's 3D view (--dump-state "viewport_render").
struct ViewportRenderInfo {
  int samples = 0;        // samples per pixel the shown picture was drawn with (0 = none drawn)
  bool fromCache = false; // nothing changed and the still picture was shown again without drawing
};

}  // namespace kinema

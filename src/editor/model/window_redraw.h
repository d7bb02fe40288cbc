#pragma once

namespace kinema {

// How the editor's window is drawn each frame (kinema edit --redraw). Whole: every pixel of
// every frame. Changed: the last frame is kept (in the window's back buffer where a swap
// keeps it, else in a framebuffer of its own copied into the window) and a frame draws only
// the rectangles where the panels or the 3D view differ from it (imgui_damage.h,
// scene_damage.h); a software rasteriser fills pixels one by one on the CPU, so this is what
// makes a drag on llvmpipe cheap. Auto: Changed on software rasterisers
// (softwareRasterizer()), Whole on a GPU.
enum class WindowRedraw { Auto, Whole, Changed };

// What the window did for its last frame (--dump-state "window_redraw").
struct WindowRedrawInfo {
  bool changedOnly = false;  // drawn by the Changed method (else the whole window)
  bool inBackBuffer = false; // Changed: the last frame kept in the window's back buffer (else in a copy)
  int rectangles = 0;        // rectangles drawn again (0: nothing changed)
  long long pixels = 0;      // pixels in them (the whole window's when drawn whole)
  // Shown by copying those rectangles to the window (WindowPresenter), not by a swap.
  bool presentedRectangles = false;
};

}  // namespace kinema

#pragma once
#include <string>

#include "editor/model/user_preferences.h"

namespace kinema {

// ImGui's fonts and style for a UI scale and theme. update() rebuilds the font atlas (and
// re-uploads its texture once the OpenGL backend made one) and rescales the style when the
// scale, the framebuffer's density or the theme changed; call it between frames.
class UiStyle {
 public:
  // `scale`: text and widgets, window pixels per pixel at scale 1 (the preference times the
  // monitor's content scale). `framebufferRatio`: framebuffer pixels per window pixel (the
  // font is rasterised that much finer so HiDPI text stays sharp). `fontPath` "" = built-in.
  void update(float scale, float framebufferRatio, UiTheme theme, const std::string& fontPath = kUiFontPath);
  float fontSize() const { return fontSize_; }        // text height in window pixels
  float framePaddingY() const { return framePaddingY_; }
  bool builtInFont() const { return builtIn_; }       // the TTF was missing or unreadable

 private:
  float scale_ = 0.0f, ratio_ = 0.0f, fontSize_ = kFallbackFontPixels, framePaddingY_ = 3.0f;
  UiTheme theme_ = UiTheme::Dark;
  std::string fontPath_;
  bool built_ = false, builtIn_ = true;
};

// The factor the UI scale preference is multiplied by on this monitor: its content scale
// (from the desktop's DPI setting) divided by the framebuffer ratio, since window pixels
// are already that much larger where the two differ (a Retina display).
float monitorUiFactor(float contentScale, float framebufferRatio);

}  // namespace kinema

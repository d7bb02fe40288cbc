#include "editor/window/ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "editor/window/imgui_backends.h"

namespace kinema {

namespace {
// Latin-1, general punctuation (the ellipsis, dashes), arrows, maths and geometric shapes.
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x206F, 0x2190, 0x21FF,
                                0x2200, 0x22FF, 0x25A0, 0x25FF, 0};
}  // namespace

float monitorUiFactor(float contentScale, float framebufferRatio) {
  if (!(contentScale > 0.0f) || !(framebufferRatio > 0.0f)) return 1.0f;
  return std::clamp(contentScale / framebufferRatio, 0.5f, 4.0f);
}

void UiStyle::update(float scale, float ratio, UiTheme theme, const std::string& fontPath) {
  if (!(ratio > 0.0f)) ratio = 1.0f;
  if (built_ && scale == scale_ && ratio == ratio_ && theme == theme_ && fontPath == fontPath_) return;
  const bool fontsChanged = !built_ || scale != scale_ || ratio != ratio_ || fontPath != fontPath_;
  scale_ = scale;
  ratio_ = ratio;
  theme_ = theme;
  fontPath_ = fontPath;

  ImGuiIO& io = ImGui::GetIO();
  if (fontsChanged) {
    io.Fonts->Clear();
    ImFont* font = nullptr;
    std::error_code ec;
    if (!fontPath.empty() && std::filesystem::is_regular_file(fontPath, ec)) {
      ImFontConfig cfg;
      cfg.OversampleH = 2;
      cfg.OversampleV = 1;
      font = io.Fonts->AddFontFromFileTTF(fontPath.c_str(), std::round(kUiFontPixels * scale * ratio), &cfg, kGlyphRanges);
    }
    builtIn_ = font == nullptr;
    float pixels = kUiFontPixels * scale;
    if (builtIn_) {
      ImFontConfig cfg;
      cfg.SizePixels = std::round(kFallbackFontPixels * scale * ratio);
      io.Fonts->AddFontDefault(&cfg);
      pixels = kFallbackFontPixels * scale;
    }
    io.Fonts->Build();
    io.FontGlobalScale = 1.0f / ratio;  // rasterised in framebuffer pixels, laid out in window pixels
    fontSize_ = std::round(pixels * ratio) / ratio;
    if (built_) imguiBackendsReloadFonts();  // the backend makes the first texture itself
  }
  ImGuiStyle style;
  switch (theme) {
    case UiTheme::Dark: ImGui::StyleColorsDark(&style); break;
    case UiTheme::Light: ImGui::StyleColorsLight(&style); break;
    case UiTheme::Classic: ImGui::StyleColorsClassic(&style); break;
  }
  // Menus, popups and floating windows opaque, as Blender's are: panel text behind them must
  // not read through (on a projector least of all). The themes leave them at 0.94.
  for (ImGuiCol c : {ImGuiCol_WindowBg, ImGuiCol_PopupBg, ImGuiCol_MenuBarBg}) style.Colors[c].w = 1.0f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  framePaddingY_ = style.FramePadding.y;
  built_ = true;
}

}  // namespace kinema

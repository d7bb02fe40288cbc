// The file dialog's window (ImGui): the path field, the folder listing and the recent files
// over FileDialogState (model/file_dialog_state.h).
#include "editor/panels/file_dialog.h"

#include <imgui.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "editor/panels/item_names.h"
#include "scene/scene.h"

namespace kinema {

namespace fs = std::filesystem;


bool drawFileDialog(FileDialogState& d, const std::vector<std::string>& recentFiles, std::string& chosen) {
  if (!d.visible) return false;
  const char* title = fileDialogTitle(d.purpose);
  if (d.justOpened) {
    ImGui::OpenPopup(title);
    d.justOpened = false;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 40.0f, ImGui::GetFontSize() * 31.0f), ImGuiCond_Appearing);  // 560 x 440 at 14 px
  bool stillOpen = true;
  if (!ImGui::BeginPopupModal(title, &stillOpen)) {
    d.visible = false;
    return false;
  }
  bool done = false;
  ImGui::TextUnformatted(d.folder.c_str());
  if (ImGui::Button("Up")) relistFileDialog(d, fs::path(d.folder).parent_path().string());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  bool accept = ImGui::InputText("##path", d.path, sizeof(d.path),
                                 ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  if (!d.listingError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", d.listingError.c_str());

  const float recentHeight = recentFiles.empty() || isSaveDialog(d.purpose) ? 0.0f : 96.0f;
  if (ImGui::BeginListBox("##folder", ImVec2(-1, -ImGui::GetFrameHeightWithSpacing() * 2 - recentHeight))) {
    for (const FolderEntry& e : d.listing.entries) {
      const std::string label = e.isFolder ? e.name + "/" : e.name;
      const bool selected = !e.isFolder && e.name == d.path;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (e.isFolder) {
          relistFileDialog(d, (fs::path(d.folder) / e.name).string());  // one click enters a folder
          break;  // the listing changed under the loop
        } else {
          setFileDialogField(d, e.name);
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) accept = true;
        }
      }
    }
    ImGui::EndListBox();
  }
  if (recentHeight > 0) {
    ImGui::TextDisabled("Recent files");
    if (ImGui::BeginListBox("##recent", ImVec2(-1, recentHeight - ImGui::GetTextLineHeightWithSpacing()))) {
      for (const std::string& r : recentFiles)
        if (ImGui::Selectable(r.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
          setFileDialogField(d, r);
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) accept = true;
        }
      ImGui::EndListBox();
    }
  }
  if (showsBvhUpAxis(d)) {  // Blender's BVH exporter writes Z-up files
    ImGui::TextUnformatted("BVH up axis:");
    ImGui::SameLine();
    if (ImGui::RadioButton("Y (BVH convention)", d.bvhUp == UpAxis::Y)) d.bvhUp = UpAxis::Y;
    recordItem(std::string(title) + "/Up Y");
    ImGui::SameLine();
    if (ImGui::RadioButton("Z (Blender export)", d.bvhUp == UpAxis::Z)) d.bvhUp = UpAxis::Z;
    recordItem(std::string(title) + "/Up Z");
  }
  if (ImGui::Button(isSaveDialog(d.purpose) ? "Save" : "Open", ImVec2(ImGui::GetFontSize() * 8.5f, 0))) accept = true;
  recordItem(std::string(title) + "/Accept");
  ImGui::SameLine();
  const bool escape = d.confirmOverwrite.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 8.5f, 0)) || escape) {
    ImGui::CloseCurrentPopup();
    d.visible = false;
  }

  if (accept && d.visible) {
    const std::string path = resolveDialogPath(d);
    std::error_code ec;
    if (path.empty()) {
      // Nothing typed: stay open.
    } else if (fs::is_directory(path, ec)) {
      relistFileDialog(d, path);
      setFileDialogField(d, "");
    } else if (isSaveDialog(d.purpose) && fs::exists(path, ec)) {
      d.confirmOverwrite = path;
      ImGui::OpenPopup("Replace file?");
    } else {
      chosen = path;
      done = true;
    }
  }
  // Nested modal: asked before a save replaces an existing file.
  if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s already exists.", d.confirmOverwrite.c_str());
    ImGui::TextUnformatted("Replace it?");
    if (ImGui::Button("Replace", ImVec2(ImGui::GetFontSize() * 8.5f, 0))) {
      chosen = d.confirmOverwrite;
      done = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 8.5f, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
      d.confirmOverwrite.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (done) {
    d.visible = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  if (!stillOpen) d.visible = false;
  return done;
}

}  // namespace kinema

#pragma once
#include <string>
#include <vector>

#include "editor/model/file_dialog_state.h"

namespace kinema {

// Draws it while visible. Returns true on the frame the user settles on a path (after
// confirming an overwrite for the save purposes); the path is then in `chosen`.
bool drawFileDialog(FileDialogState& dialog, const std::vector<std::string>& recentFiles, std::string& chosen);

}  // namespace kinema

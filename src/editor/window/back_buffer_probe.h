#pragma once

struct GLFWwindow;

namespace kinema {

// Whether the window's back buffer still holds the last frame's pixels after a swap, so a
// frame may draw only what changed straight into it (Mesa's software GLX copies the back
// buffer to the window and keeps it; a swap chain of several buffers does not). Probed by
// clearing the whole buffer to two greys one step apart (60 and 61 of 255, invisible next
// to the editor's background), swapping after each and reading every pixel back. Call with
// the window's context current, before the first frame; draws two frames.
bool backBufferSurvivesSwaps(GLFWwindow* window);

}  // namespace kinema

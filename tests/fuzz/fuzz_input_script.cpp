// Fuzzes the editor's --script parser (JSON array or JSON lines of input events): errors are
// one line naming the file; accepted events are sorted by frame and have known keys.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "editor/model/input_events.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinema::Result<std::vector<kinema::InputEvent>> r = kinema::parseInputScript(text, "fuzz.jsonl");
  if (!r.ok()) {
    if (r.error().find('\n') != std::string::npos || r.error().rfind("fuzz.jsonl", 0) != 0) std::abort();
    return 0;
  }
  long long previous = -1;
  for (const kinema::InputEvent& e : r.value()) {
    if (e.frame < previous) std::abort();  // sorted by frame
    previous = e.frame;
    const bool keyEvent = e.type == kinema::InputEventType::KeyDown || e.type == kinema::InputEventType::KeyUp;
    if (keyEvent && kinema::keyNameFromCode(e.key).empty()) std::abort();  // only known keys get through
  }
  return 0;
}

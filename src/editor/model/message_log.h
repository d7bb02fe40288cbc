#pragma once
#include <string>
#include <vector>

namespace kinema {

// View > Log: every status-bar message and error of the session, in full, with the time it
// came (the status bar shows the last one, elided to its width).
struct LogEntry {
  std::string time;  // local wall-clock time "HH:MM:SS"
  std::string text;
  bool error = false;
};

class MessageLog {
 public:
  static constexpr size_t kMaxEntries = 2000;  // the oldest go first
  // Adds `text` unless it is empty or the same text as the newest entry (an error also shown
  // in the status bar is one entry). `time` is "HH:MM:SS".
  void note(const std::string& text, const std::string& time, bool error = false);
  // Called each frame with the status bar's message: notes it (at clockTime()) when it changed.
  void observeStatus(const std::string& status);
  const std::vector<LogEntry>& entries() const { return entries_; }
  // Now as "HH:MM:SS" in local time.
  static std::string clockTime();

 private:
  std::vector<LogEntry> entries_;
  std::string lastStatus_;
};

}  // namespace kinema

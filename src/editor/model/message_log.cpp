#include "editor/model/message_log.h"

#include <ctime>

namespace kinema {

void MessageLog::note(const std::string& text, const std::string& time, bool error) {
  if (text.empty()) return;
  if (!entries_.empty() && entries_.back().text == text) return;
  if (entries_.size() >= kMaxEntries) entries_.erase(entries_.begin(), entries_.begin() + kMaxEntries / 10);
  entries_.push_back({time, text, error});
}

void MessageLog::observeStatus(const std::string& status) {
  if (status == lastStatus_) return;
  lastStatus_ = status;
  note(status, clockTime());
}

std::string MessageLog::clockTime() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buf[16];
  std::strftime(buf, sizeof buf, "%H:%M:%S", &local);
  return buf;
}

}  // namespace kinema

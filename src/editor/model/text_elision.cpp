#include "editor/model/text_elision.h"

#include <vector>

namespace kinema {

namespace {
bool continuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
}  // namespace

std::string elideText(const std::string& text, float maxWidth, const std::function<float(const std::string&)>& width,
                      const std::string& ellipsis) {
  if (width(text) <= maxWidth) return text;
  if (width(ellipsis) > maxWidth) return {};
  // Character boundaries; binary search for the longest prefix that fits (width grows with length).
  std::vector<size_t> cuts;
  for (size_t i = 0; i < text.size(); ++i)
    if (!continuationByte(text[i])) cuts.push_back(i);
  size_t lo = 0, hi = cuts.size();  // prefixes ending before cuts[k]: lo fits (k = 0 is ""), hi unknown
  auto prefix = [&](size_t k) {
    std::string p = text.substr(0, k < cuts.size() ? cuts[k] : text.size());
    while (!p.empty() && p.back() == ' ') p.pop_back();
    return p + ellipsis;
  };
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    if (width(prefix(mid)) <= maxWidth) lo = mid;
    else hi = mid;
  }
  return prefix(lo);
}

}  // namespace kinema

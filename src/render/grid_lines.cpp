#include "render/grid_lines.h"

#include <algorithm>
#include <cstdlib>

namespace kinema {

std::vector<LineVertex> makeGridLines(float cellSize, float reach) {
  std::vector<LineVertex> v;
  if (!(cellSize > 0.0f) || !std::isfinite(reach)) return v;
  // At most 100 cells each way: enough for any framing, and bounded for absurd inputs.
  // Clamped as a float first: a huge reach / cellSize does not fit an int (undefined behaviour).
  const int half = static_cast<int>(std::clamp(std::ceil(reach / cellSize), 1.0f, 100.0f));
  const float extent = static_cast<float>(half) * cellSize;
  const glm::vec4 minor(0.33f, 0.33f, 0.33f, 1.0f), major(0.40f, 0.40f, 0.40f, 1.0f);
  const glm::vec4 red(0.86f, 0.26f, 0.30f, 1.0f), blue(0.25f, 0.45f, 0.90f, 1.0f), green(0.45f, 0.75f, 0.20f, 1.0f);
  for (int i = -half; i <= half; ++i) {
    const float t = static_cast<float>(i) * cellSize;
    const glm::vec4 zLineColor = i == 0 ? blue : (std::abs(i) % 5 == 0 ? major : minor);  // line along Z at x = t
    const glm::vec4 xLineColor = i == 0 ? red : (std::abs(i) % 5 == 0 ? major : minor);   // line along X at z = t
    v.push_back({{t, 0.0f, -extent}, zLineColor});
    v.push_back({{t, 0.0f, extent}, zLineColor});
    v.push_back({{-extent, 0.0f, t}, xLineColor});
    v.push_back({{extent, 0.0f, t}, xLineColor});
  }
  v.push_back({{0.0f, 0.0f, 0.0f}, green});
  v.push_back({{0.0f, cellSize, 0.0f}, green});
  return v;
}

}  // namespace kinema

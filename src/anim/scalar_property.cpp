#include "anim/scalar_property.h"

namespace kinema {

namespace {
// The whole decimal number text[begin, end) (1 to 9 digits), or -1.
int smallIndex(const std::string& text, size_t begin, size_t end) {
  if (end <= begin || end - begin > 9) return -1;
  int k = 0;
  for (size_t i = begin; i < end; ++i) {
    if (text[i] < '0' || text[i] > '9') return -1;
    k = k * 10 + (text[i] - '0');
  }
  return k;
}
}  // namespace

ScalarProperty parseScalarProperty(const std::string& property) {
  ScalarProperty out;
  static const std::string ikTargets = "ik/targets/";
  if (property.compare(0, ikTargets.size(), ikTargets) == 0) {
    static const std::string position = "/position.";
    const size_t slash = property.find('/', ikTargets.size());
    if (slash == std::string::npos || property.compare(slash, position.size(), position) != 0 ||
        slash + position.size() + 1 != property.size())
      return out;
    const int k = smallIndex(property, ikTargets.size(), slash);
    const char c = property.back();
    if (k < 0 || c < 'x' || c > 'z') return out;
    out.kind = ScalarPropertyKind::IkTargetPosition;
    out.ikTarget = k;
    out.component = c - 'x';
    return out;
  }
  static const std::string weights = "weights/";
  static const std::string deformers = "deformers/";
  if (property.compare(0, weights.size(), weights) == 0) {
    const size_t digits = property.size() - weights.size();
    if (digits == 0 || digits > 9) return out;
    int k = 0;
    for (size_t i = weights.size(); i < property.size(); ++i) {
      if (property[i] < '0' || property[i] > '9') return out;
      k = k * 10 + (property[i] - '0');
    }
    out.kind = ScalarPropertyKind::MorphWeight;
    out.morphTarget = k;
    return out;
  }
  if (property.compare(0, deformers.size(), deformers) == 0) {
    const size_t slash = property.find('/', deformers.size());
    if (slash == std::string::npos || slash == deformers.size() || slash + 1 == property.size()) return out;
    out.kind = ScalarPropertyKind::DeformerParameter;
    out.deformer = property.substr(deformers.size(), slash - deformers.size());
    out.parameter = property.substr(slash + 1);
  }
  return out;
}

std::string morphWeightProperty(int target) { return "weights/" + std::to_string(target); }

std::string ikTargetPositionProperty(int target, int component) {
  return "ik/targets/" + std::to_string(target) + "/position." + static_cast<char>('x' + component);
}

std::string deformerParameterProperty(const std::string& deformer, const std::string& parameter) {
  return "deformers/" + deformer + "/" + parameter;
}

}  // namespace kinema

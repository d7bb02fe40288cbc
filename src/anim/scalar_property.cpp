#include "anim/scalar_property.h"

namespace kinema {

ScalarProperty parseScalarProperty(const std::string& property) {
  ScalarProperty out;
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

std::string deformerParameterProperty(const std::string& deformer, const std::string& parameter) {
  return "deformers/" + deformer + "/" + parameter;
}

}  // namespace kinema

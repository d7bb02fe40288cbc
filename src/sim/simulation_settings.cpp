#include "sim/simulation_settings.h"

namespace kinema {

std::string SimulationSettings::validate(const Skeleton& s) const {
  std::vector<int> owner(static_cast<size_t>(s.size()), -1);  // which spring chain moves each joint
  for (size_t c = 0; c < springChains.size(); ++c) {
    if (std::string e = springChains[c].validate(s); !e.empty()) return e;
    for (int j : springChains[c].joints) {
      if (owner[j] >= 0)
        return "spring chain '" + springChains[c].name + "': joint '" + s.names[j] + "' is already in chain '" +
               springChains[owner[j]].name + "'";
      owner[j] = static_cast<int>(c);
    }
  }
  for (size_t r = 0; r < ragdolls.size(); ++r) {
    if (std::string e = ragdolls[r].validate(s); !e.empty()) return e;
    for (size_t o = 0; o < r; ++o)
      if (s.isInSubtree(ragdolls[r].root, ragdolls[o].root) || s.isInSubtree(ragdolls[o].root, ragdolls[r].root))
        return "ragdoll '" + ragdolls[r].name + "': its joints overlap ragdoll '" + ragdolls[o].name + "'";
  }
  for (const CrowdSettings& c : crowds)
    if (std::string e = c.validate(); !e.empty()) return e;
  for (const ParticleSystemSettings& p : particles)
    if (std::string e = p.validate(s); !e.empty()) return e;
  return "";
}

}  // namespace kinema

#include "sim/lsystem_derivation.h"

#include "core/random.h"

namespace kinema {

std::string LSystemDerivationJob::validate() const {
  if (!grammar) return "no grammar";
  if (std::string bad = grammar->validate(); !bad.empty()) return bad;
  if (generations < 0 || generations > 10000)
    return "generations must be in 0 .. 10000, found " + std::to_string(generations);
  for (size_t k = 0; k < choices.size(); ++k)
    if (choices[k] < 0) return "choice " + std::to_string(k + 1) + " is negative";
  return "";
}

bool LSystemDerivationJob::run(std::string& error) {
  strings.clear();
  choicesMade.clear();
  if (error = validate(); !error.empty()) return false;
  // The rules of each byte value, looked up once.
  std::vector<std::vector<int>> rulesOf(256);
  for (int i = 0; i < static_cast<int>(grammar->rules.size()); ++i)
    rulesOf[static_cast<unsigned char>(grammar->rules[i].symbol)].push_back(i);
  SplitMix64 random(seed);
  strings.push_back(std::string(1, grammar->start));
  size_t forced = 0;
  for (int g = 1; g <= generations; ++g) {
    const std::string& current = strings.back();
    std::string next;
    next.reserve(current.size() * 2);
    for (char c : current) {
      const std::vector<int>& candidates = rulesOf[static_cast<unsigned char>(c)];
      if (candidates.empty()) {
        next += c;
      } else if (candidates.size() == 1) {
        next += grammar->rules[candidates[0]].replacement;
      } else {
        int pick = 0;
        if (forced < choices.size()) {
          pick = choices[forced++];
          if (pick >= static_cast<int>(candidates.size())) {
            error = "choice " + std::to_string(forced) + " is " + std::to_string(pick) + " but '" + std::string(1, c) +
                    "' has " + std::to_string(candidates.size()) + " rules (0 to " +
                    std::to_string(candidates.size() - 1) + ") at generation " + std::to_string(g);
            return false;
          }
        } else {
          const double u = random.uniform();
          double sum = 0.0;
          pick = static_cast<int>(candidates.size()) - 1;  // rounding leaves u past the last sum
          for (int k = 0; k < static_cast<int>(candidates.size()); ++k) {
            sum += grammar->rules[candidates[k]].probability;
            if (u < sum) {
              pick = k;
              break;
            }
          }
        }
        choicesMade.push_back(pick);
        next += grammar->rules[candidates[pick]].replacement;
      }
      if (next.size() > maxSymbols) {
        error = "the string grows past " + std::to_string(maxSymbols) + " symbols at generation " + std::to_string(g) +
                " (use fewer generations)";
        return false;
      }
    }
    strings.push_back(std::move(next));
  }
  return true;
}

}  // namespace kinema

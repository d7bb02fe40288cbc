#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "sim/lsystem_grammar.h"

namespace kinema {

// Rewrites an L-system's start symbol `generations` times (parallel rewriting: every
// non-terminal of the current string is replaced at once, left to right). Where a symbol has
// several rules, the rule is `choices[k]` for the k-th such rewrite (counted over all
// generations, left to right), and drawn by probability from a SplitMix64 stream seeded with
// `seed` once the forced choices are used up, so one seed always gives one plant.
struct LSystemDerivationJob {
  const LSystemGrammar* grammar = nullptr;
  int generations = 0;              // 0 .. 10000
  uint64_t seed = 1;
  std::vector<int> choices;         // forced rule indices among a symbol's rules (0-based, file order)
  size_t maxSymbols = 1u << 22;     // a string longer than this is refused (growth is exponential)

  // Outputs.
  std::vector<std::string> strings;  // generations + 1 strings; strings[0] is the start symbol
  std::vector<int> choicesMade;      // every choice made, forced or drawn, in order

  // Empty when the inputs can run: a valid grammar, generations in 0 .. 10000, choices >= 0.
  std::string validate() const;
  // False with `error` (one line) when a forced choice names a rule the symbol lacks or the
  // string outgrows maxSymbols; the outputs then hold the generations done before.
  bool run(std::string& error);
};

}  // namespace kinema

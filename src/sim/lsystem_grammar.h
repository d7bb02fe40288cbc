#pragma once
#include <string>
#include <vector>

#include "core/result.h"

namespace kinema {

// One production of an L-system: `symbol` is rewritten as `replacement` with `probability`
// (in (0, 1]; the rules of one symbol sum to 1).
struct LSystemRule {
  char symbol = 0;
  std::string replacement;  // may be empty (the symbol is erased)
  double probability = 1.0;
  bool explicitProbability = false;  // written as `(p)` in the file
  int line = 0;                      // where it came from, for messages (1-based; 0: built in code)
};

// A (stochastic, context-free) L-system (Lindenmayer; the seed's chapter 003, 16.6).
// Symbols are single characters. Every symbol with a rule is a non-terminal and is rewritten
// at each generation; every other character is a terminal kept as it is. The turtle reads
//   f  a segment forward (one joint),  +  turn by +angle about the turtle's Z axis,
//   -  turn by -angle,  [  push the turtle,  ]  pop it,  @  a leaf at the turtle.
struct LSystemGrammar {
  char start = 'S';
  double angleDegrees = 60.0;  // the seed's turn for + and -
  std::vector<LSystemRule> rules;

  // The indices into `rules` of the rules for `symbol`, in file order (empty: a terminal).
  std::vector<int> rulesOf(char symbol) const;
  // Empty when usable: a printable start symbol, a finite angle, each rule's symbol printable
  // and not one of the turtle's commands (f + - [ ] @), probabilities in (0, 1] summing to 1
  // per symbol (within 1e-9).
  std::string validate() const;
};

// Parses a grammar file's text. One directive a line; blank lines and `#` comments (to the
// end of the line) are ignored; spaces inside a replacement are ignored:
//   A -> [+B]fA          a rule
//   A -> (0.3) B         a rule with its probability; the rules of a symbol written without
//                        one share what the others leave equally
//   angle 30             the turn of + and -, degrees (default 60, the seed's)
//   start S              the start symbol (default: the first rule's symbol)
// Errors are one line, "SOURCE:LINE: what was expected".
Result<LSystemGrammar> parseLSystemGrammar(const std::string& text, const std::string& source);

}  // namespace kinema

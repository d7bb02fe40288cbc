#include "sim/lsystem_grammar.h"
#include "core/text_lines.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>


namespace kinema {

namespace {

constexpr const char* kTurtleCommands = "f+-[]@";

bool printableSymbol(char c) { return c > ' ' && c < 127; }

std::string describe(char c) {
  if (printableSymbol(c)) return std::string("'") + c + "'";
  return "character code " + std::to_string(static_cast<unsigned char>(c));
}

// The symbols' probabilities: explicit ones as written, the rest share what is left.
std::string shareProbabilities(LSystemGrammar& g, const std::string& source) {
  std::vector<char> seen;
  for (const LSystemRule& r : g.rules) {
    if (std::find(seen.begin(), seen.end(), r.symbol) != seen.end()) continue;
    seen.push_back(r.symbol);
    double given = 0.0;
    int implicitCount = 0, lastLine = 0;
    for (const LSystemRule& s : g.rules) {
      if (s.symbol != r.symbol) continue;
      lastLine = s.line;
      if (s.explicitProbability) given += s.probability;
      else ++implicitCount;
    }
    const std::string where = source + ":" + std::to_string(lastLine) + ": ";
    if (given > 1.0 + 1e-9)
      return where + "the probabilities of the rules for '" + std::string(1, r.symbol) + "' add up to " +
             std::to_string(given) + ", more than 1";
    if (implicitCount == 0 && std::abs(given - 1.0) > 1e-9)
      return where + "the probabilities of the rules for '" + std::string(1, r.symbol) + "' add up to " +
             std::to_string(given) + ", expected 1";
    if (implicitCount > 0) {
      const double share = (1.0 - given) / implicitCount;
      if (share <= 1e-12)
        return where + "the rules for '" + std::string(1, r.symbol) +
               "' without a probability get nothing: the others already add up to 1";
      for (LSystemRule& s : g.rules)
        if (s.symbol == r.symbol && !s.explicitProbability) s.probability = share;
    }
  }
  return "";
}

}  // namespace

std::vector<int> LSystemGrammar::rulesOf(char symbol) const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(rules.size()); ++i)
    if (rules[i].symbol == symbol) out.push_back(i);
  return out;
}

std::string LSystemGrammar::validate() const {
  if (!printableSymbol(start)) return "the start symbol is " + describe(start) + ", expected a printable character";
  if (!std::isfinite(angleDegrees)) return "the angle is not a finite number";
  std::vector<char> seen;
  for (const LSystemRule& r : rules) {
    if (!printableSymbol(r.symbol)) return "a rule rewrites " + describe(r.symbol) + ", expected a printable character";
    if (std::strchr(kTurtleCommands, r.symbol))
      return std::string("a rule rewrites the turtle command '") + r.symbol + "' (f + - [ ] @ are terminals)";
    for (char c : r.replacement)
      if (!printableSymbol(c)) return std::string("the rule for '") + r.symbol + "' holds " + describe(c);
    if (!(r.probability > 0.0 && r.probability <= 1.0))
      return std::string("a rule for '") + r.symbol + "' has probability " + std::to_string(r.probability) +
             ", expected one in (0, 1]";
    if (std::find(seen.begin(), seen.end(), r.symbol) != seen.end()) continue;
    seen.push_back(r.symbol);
    double sum = 0.0;
    for (const LSystemRule& s : rules)
      if (s.symbol == r.symbol) sum += s.probability;
    if (std::abs(sum - 1.0) > 1e-9)
      return std::string("the probabilities of the rules for '") + r.symbol + "' add up to " + std::to_string(sum) +
             ", expected 1";
  }
  return "";
}

Result<LSystemGrammar> parseLSystemGrammar(const std::string& text, const std::string& source) {
  using R = Result<LSystemGrammar>;
  LSystemGrammar g;
  bool startGiven = false;
  std::vector<std::string> lines;
  splitLines(text, lines);
  for (size_t n = 0; n < lines.size(); ++n) {
    const int lineNo = static_cast<int>(n) + 1;
    const std::string where = source + ":" + std::to_string(lineNo) + ": ";
    std::string line = lines[n];
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    size_t arrowLength = 2;
    size_t arrow = line.find("->");
    if (arrow == std::string::npos) {
      arrow = line.find("\xE2\x86\x92");  // the seed's own arrow, U+2192
      arrowLength = 3;
    }
    if (arrow == std::string::npos) {
      // A directive: `angle DEGREES` or `start SYMBOL`.
      const size_t space = line.find_first_of(" \t");
      const std::string word = line.substr(0, space);
      const std::string value = space == std::string::npos ? "" : trim(line.substr(space));
      if (word == "angle") {
        char* end = nullptr;
        const double a = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(a))
          return R::failure(where + "expected `angle DEGREES` with a finite number, found '" + line + "'");
        g.angleDegrees = a;
      } else if (word == "start") {
        if (value.size() != 1 || !printableSymbol(value[0]))
          return R::failure(where + "expected `start SYMBOL` with one character, found '" + line + "'");
        g.start = value[0];
        startGiven = true;
      } else {
        return R::failure(where + "expected a rule `A -> ...`, `angle DEGREES` or `start SYMBOL`, found '" + line + "'");
      }
      continue;
    }
    const std::string left = trim(line.substr(0, arrow));
    std::string right = trim(line.substr(arrow + arrowLength));
    if (left.size() != 1 || !printableSymbol(left[0]))
      return R::failure(where + "the left of '->' must be one symbol, found '" + left + "'");
    if (std::strchr(kTurtleCommands, left[0]))
      return R::failure(where + "'" + left + "' is a turtle command (f + - [ ] @) and cannot be rewritten");
    LSystemRule rule;
    rule.symbol = left[0];
    rule.line = lineNo;
    if (!right.empty() && right[0] == '(') {
      const size_t close = right.find(')');
      if (close == std::string::npos) return R::failure(where + "the probability '(' has no ')'");
      const std::string number = trim(right.substr(1, close - 1));
      char* end = nullptr;
      const double p = std::strtod(number.c_str(), &end);
      if (number.empty() || *end != '\0' || !std::isfinite(p) || p <= 0.0 || p > 1.0)
        return R::failure(where + "expected a probability in (0, 1] inside '( )', found '" + number + "'");
      rule.probability = p;
      rule.explicitProbability = true;
      right = trim(right.substr(close + 1));
    }
    for (char c : right) {
      if (c == ' ' || c == '\t') continue;
      if (!printableSymbol(c)) return R::failure(where + "the replacement holds " + describe(c) + ", expected printable ASCII");
      rule.replacement += c;
    }
    g.rules.push_back(std::move(rule));
  }
  if (g.rules.empty()) return R::failure(source + ": no rules (expected lines like `A -> [+B]fA`)");
  if (!startGiven) g.start = g.rules.front().symbol;
  if (std::string bad = shareProbabilities(g, source); !bad.empty()) return R::failure(bad);
  if (std::string bad = g.validate(); !bad.empty()) return R::failure(source + ": " + bad);
  return g;
}

}  // namespace kinema

#include "io/json_syntax.h"

#include <nlohmann/json.hpp>

namespace kinema {

namespace {

// Accepts everything and records the first syntax error (nlohmann's SAX interface).
struct FirstError : nlohmann::json_sax<nlohmann::json> {
  bool failed = false;
  size_t byte = 0;  // how many bytes were read when the parser gave up
  std::string what;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    failed = true;
    byte = position;
    what = e.what();
    return false;
  }
};

// nlohmann's "... syntax error while parsing object key - unexpected ','; expected string
// literal; last read: '...'" without its prefix and without the bytes it last read.
std::string plainReason(const std::string& what) {
  std::string reason = what;
  const size_t dash = reason.find(" - ");
  if (dash != std::string::npos) reason = reason.substr(dash + 3);
  const size_t lastRead = reason.find("; last read");
  if (lastRead != std::string::npos) reason = reason.substr(0, lastRead);
  // "[json.exception.out_of_range.406] number overflow parsing '1e400'": the library's tag off.
  if (reason.rfind("[json.exception.", 0) == 0 && reason.find("] ") != std::string::npos)
    reason = reason.substr(reason.find("] ") + 2);
  if (reason.size() > 160) reason = reason.substr(0, 157) + "...";  // the token it quotes may be huge
  for (char& c : reason)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  if (reason.rfind("invalid literal", 0) == 0) return "not JSON text here";
  return reason.empty() ? "not valid JSON" : reason;
}

}  // namespace

std::string jsonSyntaxError(const char* text, size_t size) {
  FirstError sax;
  nlohmann::json::sax_parse(text, text + size, &sax, nlohmann::json::input_format_t::json, false);
  if (!sax.failed) return {};
  // The position counts bytes read; the offending one is the last of them.
  const size_t at = sax.byte > 0 ? std::min(sax.byte - 1, size) : 0;
  size_t line = 1, column = 1;
  for (size_t i = 0; i < at && i < size; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + plainReason(sax.what);
}

}  // namespace kinema

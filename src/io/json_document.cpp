#include "io/json_document.h"

#include <algorithm>
#include <vector>

#include "io/json_depth.h"
#include "io/json_syntax.h"
#include "io/message_text.h"

namespace kinema {

namespace {

using Json = nlohmann::ordered_json;

// glibc hands out chunks of the request plus 8 bytes, rounded up to 16 (at least 32).
size_t chunk(size_t request) { return std::max<size_t>(32, (request + 8 + 15) & ~size_t(15)); }
// The heap part of a std::string (short strings live inside it).
size_t stringHeap(size_t length) { return length > 15 ? chunk(length + 1) : 0; }

// The first pass: what the tree will take, without building it.
struct TreeCost : nlohmann::json_sax<Json> {
  size_t bytes = sizeof(Json);  // the root value
  size_t largest = 0;           // the largest container's element storage
  std::vector<size_t> members;  // per open container (depth is capped before this runs)
  std::vector<bool> isObject;
  bool failed = false;

  void element() {
    if (!members.empty()) ++members.back();
  }
  bool null() override { return element(), true; }
  bool boolean(bool) override { return element(), true; }
  bool number_integer(number_integer_t) override { return element(), true; }
  bool number_unsigned(number_unsigned_t) override { return element(), true; }
  bool number_float(number_float_t, const string_t&) override { return element(), true; }
  bool string(string_t& s) override {
    element();
    bytes += chunk(sizeof(string_t)) + stringHeap(s.size());
    return true;
  }
  bool binary(binary_t&) override { return element(), true; }
  bool key(string_t& k) override {
    bytes += stringHeap(k.size());
    return true;
  }
  bool open(bool object) {
    element();
    bytes += chunk(object ? sizeof(Json::object_t) : sizeof(Json::array_t));
    members.push_back(0);
    isObject.push_back(object);
    return true;
  }
  bool close() {
    const size_t each = isObject.back() ? sizeof(Json::object_t::value_type) : sizeof(Json);
    const size_t storage = members.back() ? chunk(members.back() * each) : 0;
    bytes += storage;
    largest = std::max(largest, storage);
    members.pop_back();
    isObject.pop_back();
    return true;
  }
  bool start_object(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    failed = true;
    return false;
  }

  // The tree, plus a container's growth while it is read (old and new storage at once).
  size_t peak() const { return bytes + 2 * largest; }
};

// The second pass: builds the tree, each container trimmed to its size once closed.
struct TreeBuilder : nlohmann::json_sax<Json> {
  explicit TreeBuilder(Json& root) : root(root) {}
  Json& root;
  std::vector<Json*> open;
  Json* slot = nullptr;  // the member value a key has just made

  Json* add(Json&& v) {
    if (open.empty()) {
      root = std::move(v);
      return &root;
    }
    Json& top = *open.back();
    if (top.is_array()) {
      auto& a = top.get_ref<Json::array_t&>();
      a.push_back(std::move(v));
      return &a.back();
    }
    *slot = std::move(v);
    return slot;
  }
  bool null() override { return add(Json()), true; }
  bool boolean(bool b) override { return add(Json(b)), true; }
  bool number_integer(number_integer_t n) override { return add(Json(n)), true; }
  bool number_unsigned(number_unsigned_t n) override { return add(Json(n)), true; }
  bool number_float(number_float_t x, const string_t&) override { return add(Json(x)), true; }
  bool string(string_t& s) override { return add(Json(std::move(s))), true; }
  bool binary(binary_t&) override { return add(Json()), true; }
  bool key(string_t& k) override {
    // The members as a plain vector: ordered_map's operator[] searches every member for
    // the key, which is quadratic for a hostile object of a million keys. A repeated key
    // in a small object replaces the earlier value, as nlohmann's own parser does.
    auto& members = static_cast<std::vector<Json::object_t::value_type>&>(open.back()->get_ref<Json::object_t&>());
    if (members.size() <= 64)
      for (auto& m : members)
        if (m.first == k) return slot = &m.second, true;
    members.emplace_back(std::move(k), Json());
    slot = &members.back().second;
    return true;
  }
  bool start_object(std::size_t) override { return open.push_back(add(Json::object())), true; }
  bool start_array(std::size_t) override { return open.push_back(add(Json::array())), true; }
  bool end_object() override {
    static_cast<std::vector<Json::object_t::value_type>&>(open.back()->get_ref<Json::object_t&>()).shrink_to_fit();
    open.pop_back();
    return true;
  }
  bool end_array() override {
    open.back()->get_ref<Json::array_t&>().shrink_to_fit();
    open.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

std::string megabytes(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MB"; }

}  // namespace

size_t jsonTreeBytes(const char* text, size_t size) {
  TreeCost cost;
  Json::sax_parse(text, text + size, &cost);
  return cost.failed ? 0 : cost.peak();
}

std::string parseJsonDocument(const std::string& text, const std::string& source, const InputLimits& limits,
                              Json& out) {
  const int depth = jsonNestingDepth(text.data(), text.size());
  if (depth > limits.maxJsonDepth)
    return source + ": JSON nested " + limitExceeded(depth, limits.maxJsonDepth, "levels deep", "maxJsonDepth");
  TreeCost cost;
  Json::sax_parse(text.begin(), text.end(), &cost);
  if (cost.failed) return oneLineMessage(source + ": not valid JSON: " + jsonSyntaxError(text.data(), text.size()));
  const size_t budget = jsonTreeBudgetBytes(text.size(), limits);
  if (cost.peak() > budget)
    return source + ": the JSON would take " + megabytes(cost.peak()) + " in memory, more than the limit of " +
           megabytes(budget) + " (2 x the file's size + InputLimits::jsonTreeBytesOverFileSize)";
  out = Json();
  TreeBuilder builder(out);
  if (!Json::sax_parse(text.begin(), text.end(), &builder))
    return oneLineMessage(source + ": not valid JSON: " + jsonSyntaxError(text.data(), text.size()));
  return {};
}

}  // namespace kinema

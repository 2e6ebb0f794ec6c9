// Internal: a checked reader over one JSON object of a scene file. Every
// accessor names the field it reads; finish() rejects fields nobody asked for
// (typos). Errors: "<file>:<line>: <path>: expected ..., got <value>".
#pragma once
#include "json_lines.hpp"

#include <nlohmann/json.hpp>
#include <snell/bridge.hpp>

#include <initializer_list>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace snell::lab::detail {

using Json = nlohmann::json;

struct SourceInfo {
  std::string file;
  const JsonLines* lines = nullptr;
};

// An interval for numbers: [lo, hi] with each end open or closed.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false;
  bool hiOpen = false;
  static Range any() { return Range{}; }
  static Range positive() { return Range{0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range nonNegative() { return Range{0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return Range{a, b, false, false}; }
  static Range open(double a, double b) { return Range{a, b, true, true}; }
  bool contains(double v) const;
  // Why v, contained, is no good as the float it becomes ("" when it is): not
  // finite, rounded to 0 (or a denormal) where 0 is refused, or rounded onto
  // an open bound or outside the range.
  std::string floatProblem(double v) const;
  std::string describe() const;  // " in (0, 180)", "" for any()
};

std::string formatNumber(double v);  // "inf", "1e+39", "0.5"
[[noreturn]] void fail(const SourceInfo& src, const std::string& path, const std::string& message);
std::string preview(const Json& j);  // short JSON text of a value for messages

class ObjectReader {
 public:
  ObjectReader(const Json& node, std::string path, const SourceInfo& src);

  const std::string& path() const { return path_; }
  bool has(const std::string& key);  // also declares the key as known
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // "missing (required: <required>)", or, when a field nobody asked for is a likely misspelling of `key`,
  // "unknown field (did you mean ...)" on that field.
  [[noreturn]] void failMissing(const std::string& key, const std::string& required) const;

  double number(const std::string& key, double fallback, Range range);
  double requiredNumber(const std::string& key, Range range);
  int integer(const std::string& key, int fallback, int lo, int hi);
  std::string string(const std::string& key, const std::string& fallback);
  std::string requiredString(const std::string& key);
  // One of `options`; the message lists them.
  std::string choice(const std::string& key, std::initializer_list<const char*> options, const std::string& fallback,
                     bool required = false);
  vec3 vector3(const std::string& key, vec3 fallback, Range element = Range::any(), bool required = false);
  vec3 vector3OrScalar(const std::string& key, vec3 fallback, Range element);  // 2 or [2, 2, 2]
  vec2 vector2(const std::string& key, vec2 fallback, Range element);
  ivec2 integer2(const std::string& key, ivec2 fallback, int lo, int hi);
  std::vector<vec3> colorList(const std::string& key, std::size_t minCount, Range element);

  ObjectReader object(const std::string& key);  // required
  // Each element must be an object; more than maxCount is an error.
  std::vector<ObjectReader> objectArray(const std::string& key, std::size_t maxCount);

  // Throws for the first field that no accessor asked for.
  void finish() const;

 private:
  const Json& node_;
  std::string path_;
  SourceInfo src_;
  std::set<std::string> known_;
  std::vector<std::string> knownOrder_;

  std::string childPath(const std::string& key) const;
  const Json* get(const std::string& key);
  // One element of an array: a number in `element` that stays so as a float.
  void elementCheck(const Json& e, const std::string& path, const std::string& want, const Json& whole,
                    const Range& element) const;
};

}  // namespace snell::lab::detail

#include "json_reader.hpp"

#include "lab/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace snell::lab::detail {

std::string formatNumber(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  s << v;
  return s.str();
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (loOpen ? !(v > lo) : !(v >= lo)) return false;
  if (hiOpen ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Range::floatProblem(double v) const {
  // Every scene number is stored as a float: a double that passed the check
  // could still become inf (1e39), 0 (1e-50) or a bound of an open range.
  const float f = static_cast<float>(v);
  if (!std::isfinite(f)) return "is beyond the float range (largest " + formatNumber(std::numeric_limits<float>::max()) + ")";
  // Below the smallest normal float a GPU may flush the value to 0, so where 0
  // is refused such a value is refused too.
  if (!contains(0.0) && std::fabs(f) < std::numeric_limits<float>::min())
    return "rounds to 0 as a float (smallest normal float " + formatNumber(std::numeric_limits<float>::min()) + ")";
  if (!contains(static_cast<double>(f))) return "rounds to " + formatNumber(static_cast<double>(f)) + " as a float";
  return "";
}

std::string Range::describe() const {
  if (std::isinf(lo) && std::isinf(hi)) return "";
  if (std::isinf(hi)) return loOpen ? " > " + formatNumber(lo) : " >= " + formatNumber(lo);
  return std::string(" in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) + (hiOpen ? ")" : "]");
}

void fail(const SourceInfo& src, const std::string& path, const std::string& message) {
  std::string where = src.file.empty() ? std::string("<scene>") : src.file;
  // The line of the field, or of its nearest enclosing value.
  int line = 0;
  std::string p = path;
  while (src.lines && line == 0) {
    line = src.lines->line(p);
    if (line != 0 || p.empty()) break;
    const std::size_t cut = p.find_last_of(".[");
    p = cut == std::string::npos ? std::string() : p.substr(0, cut);
  }
  if (line > 0) where += ":" + std::to_string(line);
  throw Error(ErrorKind::Schema, where + ": " + (path.empty() ? std::string("(top level)") : path) + ": " + message);
}

namespace {
// j.dump(), but it stops once `out` is past `limit` characters: dump() recursed
// once per nesting level and overflowed the stack on a value nested 100,000
// arrays deep; here each level adds a character, so the depth is bounded too.
void previewInto(const Json& j, std::string& out, std::size_t limit) {
  if (!j.is_structured()) {
    out += j.dump();
    return;
  }
  out += j.is_array() ? '[' : '{';
  for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
    if (it != j.begin()) out += ',';
    if (j.is_object()) out += Json(it.key()).dump() + ":";
    previewInto(*it, out, limit);
  }
  out += j.is_array() ? ']' : '}';
}
}  // namespace

std::string preview(const Json& j) {
  std::string s;
  previewInto(j, s, 48);
  if (s.size() > 48) s = s.substr(0, 45) + "...";
  return s;
}

ObjectReader::ObjectReader(const Json& node, std::string path, const SourceInfo& src)
    : node_(node), path_(std::move(path)), src_(src) {
  if (!node_.is_object()) detail::fail(src_, path_, "expected an object, got " + preview(node_));
}

std::string ObjectReader::childPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void ObjectReader::fail(const std::string& key, const std::string& message) const {
  detail::fail(src_, childPath(key), message);
}

bool ObjectReader::has(const std::string& key) {
  if (known_.insert(key).second) knownOrder_.push_back(key);
  return node_.contains(key);
}

const Json* ObjectReader::get(const std::string& key) {
  if (!has(key)) return nullptr;
  return &node_.at(key);
}

double ObjectReader::number(const std::string& key, double fallback, Range range) {
  const Json* j = get(key);
  if (!j) return fallback;
  if (!j->is_number() || !range.contains(j->get<double>()))
    fail(key, "expected a number" + range.describe() + ", got " + preview(*j));
  const std::string why = range.floatProblem(j->get<double>());
  if (!why.empty()) fail(key, "expected a number" + range.describe() + ", got " + preview(*j) + ", which " + why);
  return j->get<double>();
}

double ObjectReader::requiredNumber(const std::string& key, Range range) {
  if (!has(key)) failMissing(key, "a number" + range.describe());
  return number(key, 0.0, range);
}

int ObjectReader::integer(const std::string& key, int fallback, int lo, int hi) {
  const Json* j = get(key);
  if (!j) return fallback;
  const std::string want = "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
  if (!j->is_number_integer()) {
    // 3.0 is accepted as 3; 3.5 is not.
    if (j->is_number_float() && std::floor(j->get<double>()) == j->get<double>() &&
        j->get<double>() >= lo && j->get<double>() <= hi)
      return static_cast<int>(j->get<double>());
    fail(key, want + preview(*j));
  }
  const long long v = j->is_number_unsigned() ? static_cast<long long>(std::min<std::uint64_t>(j->get<std::uint64_t>(), 1ull << 62))
                                              : j->get<long long>();
  if (v < lo || v > hi) fail(key, want + preview(*j));
  return static_cast<int>(v);
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
  const Json* j = get(key);
  if (!j) return fallback;
  if (!j->is_string()) fail(key, "expected a string, got " + preview(*j));
  return j->get<std::string>();
}

std::string ObjectReader::requiredString(const std::string& key) {
  if (!has(key)) failMissing(key, "a string");
  const std::string s = string(key, "");
  if (s.empty()) fail(key, "expected a non-empty string, got \"\"");
  return s;
}

std::string ObjectReader::choice(const std::string& key, std::initializer_list<const char*> options,
                                 const std::string& fallback, bool required) {
  std::string list;
  for (const char* o : options) list += (list.empty() ? "\"" : ", \"") + std::string(o) + "\"";
  if (required && !has(key)) failMissing(key, "one of " + list);
  const Json* j = get(key);
  if (!j) return fallback;
  if (j->is_string())
    for (const char* o : options)
      if (j->get<std::string>() == o) return o;
  fail(key, "expected one of " + list + ", got " + preview(*j));
}

vec3 ObjectReader::vector3(const std::string& key, vec3 fallback, Range element, bool required) {
  if (required && !has(key)) failMissing(key, "an array of 3 numbers");
  const Json* j = get(key);
  if (!j) return fallback;
  const std::string want = "expected an array of 3 numbers" + (element.describe().empty() ? std::string() : " each" + element.describe());
  if (!j->is_array() || j->size() != 3) fail(key, want + ", got " + preview(*j));
  vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    const Json& e = (*j)[i];
    elementCheck(e, childPath(key) + "[" + std::to_string(i) + "]", want, *j, element);
    v[static_cast<int>(i)] = e.get<float>();
  }
  return v;
}

void ObjectReader::elementCheck(const Json& e, const std::string& path, const std::string& want, const Json& whole,
                                const Range& element) const {
  if (!e.is_number() || !element.contains(e.get<double>())) detail::fail(src_, path, want + ", got " + preview(whole));
  const std::string why = element.floatProblem(e.get<double>());
  if (!why.empty()) detail::fail(src_, path, want + ", got " + preview(whole) + ": " + preview(e) + " " + why);
}

vec3 ObjectReader::vector3OrScalar(const std::string& key, vec3 fallback, Range element) {
  const Json* j = get(key);
  if (!j) return fallback;
  if (j->is_number()) {
    const std::string want = "expected a number" + element.describe() + " or an array of 3 such numbers";
    if (!element.contains(j->get<double>())) fail(key, want + ", got " + preview(*j));
    const std::string why = element.floatProblem(j->get<double>());
    if (!why.empty()) fail(key, want + ", got " + preview(*j) + ", which " + why);
    return vec3(j->get<float>());
  }
  return vector3(key, fallback, element);
}

vec2 ObjectReader::vector2(const std::string& key, vec2 fallback, Range element) {
  const Json* j = get(key);
  if (!j) return fallback;
  const std::string want = "expected an array of 2 numbers" + (element.describe().empty() ? std::string() : " each" + element.describe());
  if (!j->is_array() || j->size() != 2) fail(key, want + ", got " + preview(*j));
  vec2 v;
  for (std::size_t i = 0; i < 2; ++i) {
    const Json& e = (*j)[i];
    elementCheck(e, childPath(key) + "[" + std::to_string(i) + "]", want, *j, element);
    v[static_cast<int>(i)] = e.get<float>();
  }
  return v;
}

ivec2 ObjectReader::integer2(const std::string& key, ivec2 fallback, int lo, int hi) {
  const Json* j = get(key);
  if (!j) return fallback;
  const std::string want = "expected an array of 2 integers each in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!j->is_array() || j->size() != 2) fail(key, want + ", got " + preview(*j));
  ivec2 v;
  for (std::size_t i = 0; i < 2; ++i) {
    const Json& e = (*j)[i];
    const bool integral = e.is_number_integer() || (e.is_number_float() && std::floor(e.get<double>()) == e.get<double>());
    if (!integral || e.get<double>() < lo || e.get<double>() > hi)
      detail::fail(src_, childPath(key) + "[" + std::to_string(i) + "]", want + ", got " + preview(*j));
    v[static_cast<int>(i)] = static_cast<int>(e.get<double>());
  }
  return v;
}

std::vector<vec3> ObjectReader::colorList(const std::string& key, std::size_t minCount, Range element) {
  const Json* j = get(key);
  std::vector<vec3> out;
  if (!j) return out;
  const std::string want = "expected an array of at least " + std::to_string(minCount) + " colours [r, g, b]";
  if (!j->is_array() || j->size() < minCount) fail(key, want + ", got " + preview(*j));
  for (std::size_t i = 0; i < j->size(); ++i) {
    const Json& c = (*j)[i];
    const std::string p = childPath(key) + "[" + std::to_string(i) + "]";
    if (!c.is_array() || c.size() != 3) detail::fail(src_, p, "expected a colour [r, g, b], got " + preview(c));
    vec3 v;
    for (std::size_t k = 0; k < 3; ++k) {
      elementCheck(c[k], p, "expected 3 numbers each" + element.describe(), c, element);
      v[static_cast<int>(k)] = c[k].get<float>();
    }
    out.push_back(v);
  }
  return out;
}

ObjectReader ObjectReader::object(const std::string& key) {
  const Json* j = get(key);
  if (!j) failMissing(key, "an object");
  return ObjectReader(*j, childPath(key), src_);
}

std::vector<ObjectReader> ObjectReader::objectArray(const std::string& key, std::size_t maxCount) {
  const Json* j = get(key);
  std::vector<ObjectReader> out;
  if (!j) return out;
  if (!j->is_array()) fail(key, "expected an array of objects, got " + preview(*j));
  if (j->size() > maxCount)
    fail(key, "expected at most " + std::to_string(maxCount) + " objects, got " + std::to_string(j->size()));
  for (std::size_t i = 0; i < j->size(); ++i)
    out.emplace_back((*j)[i], childPath(key) + "[" + std::to_string(i) + "]", src_);
  return out;
}

namespace {
// Edit distance (insertions, deletions, substitutions, adjacent swaps) of two short keys.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
}  // namespace

// A required field is missing. When the object holds a field nobody asked for that is a likely misspelling
// of it ("objet" for "object"), that field is the error: the user wrote it, and "missing" would send them
// looking for the wrong thing.
void ObjectReader::failMissing(const std::string& key, const std::string& required) const {
  const std::size_t limit = std::max<std::size_t>(1, key.size() / 3);
  std::string best;
  std::size_t bestDistance = limit + 1;
  if (node_.is_object())
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      if (known_.count(it.key()) || it.key().size() > key.size() + limit) continue;
      const std::size_t d = editDistance(it.key(), key);
      if (d < bestDistance) {
        bestDistance = d;
        best = it.key();
      }
    }
  if (!best.empty())
    detail::fail(src_, childPath(best), "unknown field (did you mean \"" + key + "\"? it is required: " + required + ")");
  fail(key, "missing (required: " + required + ")");
}

void ObjectReader::finish() const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (known_.count(it.key())) continue;
    std::string list;
    for (const std::string& k : knownOrder_) list += (list.empty() ? "" : ", ") + k;
    detail::fail(src_, childPath(it.key()), "unknown field (expected one of: " + list + ")");
  }
}

}  // namespace snell::lab::detail

// One description per public function: the parity case (GPU vs C++), the
// property case (hostile inputs vs the contract) and the GPU property run are
// all generated from it. Adding a function is one SNELL_PARITY_CASE plus its
// input generator and an independent unit test.
//
//   SNELL_PARITY_CASE(snellRefract, refractInputs,
//       /* inputs:  (type, name, first float)                 */
//       (vec3, incident, 0)(float, eta, 3)(vec3, normal, 4)(int, policy, 7),
//       /* outputs: (type, name, first float, exact | within(abs, rel)) */
//       (vec3, direction, 0, within(1e-5f, 1e-5f))(bool, tir, 4, exact)(bool, valid, 5, exact),
//       /* extras: textures, setup, contract exceptions by name, or {} */
//       {},
//       /* the body, in the common subset (GLSL, C++ with GLM, HLSL) */
//       SnellRefraction r = snellRefract(incident, normal, eta, policy);
//       direction = r.direction;
//       tir = r.tir;
//       valid = r.valid;)
//
// The inputs arrive as locals of their type, the outputs are locals set to
// zero before the body runs; the body sets the outputs it computes. The same
// body text is compiled as C++ here (in the namespace that includes the family's
// helper file, cases/<family>.glsl, named by SNELL_PARITY_FILE) and sent to the
// GPU inside a generated entry `case<Function>(vec4, vec4, vec4, vec4)`. Both
// sides unpack and pack the 16 input and 16 output floats the same way
// (int(x); x > 0.5f for a bool; 1.0f / 0.0f for a bool out; float(i) for an
// int out), so a case means the same on each.
//
// A case without inputs leaves the inputs empty (`/* no inputs */,`); its
// generator still gives the number of runs. Inputs and outputs share one scope,
// so their names differ (a constructor's case names what it is given `given*`).
//
// Types: float, int, bool, vec2, vec3, vec4, ivec2. Each name covers as many
// consecutive floats as its type has components, from the given first float
// (float k is v[k / 4][k % 4]); inputs may not overlap, nor may outputs.
// Outputs: `exact` (bools, ints, texel indices, flags: equal, NaN == NaN) or
// `within(abs, rel)` (|gpu - cpu| <= abs + rel |cpu|; NaN and inf matched
// exactly), or `within(abs, rel, scaled, first)`: plus scaled times the C++
// value of the output floats from `first` (component by component), for an
// ill-conditioned output whose condition the case also outputs; that term is
// the allowance for a runtime that folds constants (snell::gpu::Runtime::foldsConstants) and applies
// only there, on the inputs CaseExtras::scaledWhere names. The body may not contain preprocessor lines (it is one macro
// argument); helpers, textures and macros shared by a family's cases live in
// its cases/<family>.glsl (a macro defined only in the .cpp compiles in C++
// and fails on the GPU, which sees the body unexpanded, on one line). Names
// starting with `parity` belong to the generated entry; commas in `extras`
// must sit inside parentheses. describeCase checks the layout
// (ParityManifest.EveryCaseDescriptionIsWellFormed).
#pragma once

#include "parity_registry.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cctype>
#include <functional>
#include <string>
#include <vector>

namespace snell_parity {

// A named input or output of a case: its type name (as the common subset
// spells it) and its first float.
struct CaseVar {
  const char* type;
  const char* name;
  int first;
  Check check = checks::exact;  // outputs only
};

// What a case needs beyond its inputs and body: the textures it samples (and
// the setup that fills them), and the documented exceptions to "every output
// is finite", by name.
struct CaseExtras {
  std::vector<snell::gpu::ParityTexture> textures;
  std::function<void()> setup;
  struct NamedException {
    std::vector<std::string> passThroughInputs, outputs;
    bool always = false;
    std::string reason;
  };
  std::vector<NamedException> exceptions;

  CaseExtras& sampling(std::vector<snell::gpu::ParityTexture> t, std::function<void()> s) {
    textures = std::move(t);
    setup = std::move(s);
    return *this;
  }
  // A non-finite value in any of `inputs` excuses `outputs` (a value used "as
  // given" by contract, a constructor that stores what it is given).
  CaseExtras& passThrough(std::vector<std::string> inputs, std::vector<std::string> outs, std::string why) {
    exceptions.push_back({std::move(inputs), std::move(outs), false, std::move(why)});
    return *this;
  }
  // `outputs` are never checked (the contract lets them overflow).
  CaseExtras& unchecked(std::vector<std::string> outs, std::string why) {
    exceptions.push_back({{}, std::move(outs), true, std::move(why)});
    return *this;
  }
  // The outputs' condition-scaled tolerances apply only on the inputs `where` accepts.
  std::function<bool(const ParityIO&)> scaledInputs;
  CaseExtras& scaledWhere(std::function<bool(const ParityIO&)> where) {
    scaledInputs = std::move(where);
    return *this;
  }
};

// Components of a case type (0: not a case type).
inline int caseTypeWidth(const std::string& type) {
  if (type == "float" || type == "int" || type == "bool") return 1;
  if (type == "vec2" || type == "ivec2") return 2;
  if (type == "vec3") return 3;
  if (type == "vec4") return 4;
  return 0;
}

namespace detail {
inline std::string caseComponent(int k) {
  static const char* const vecs[] = {"parityA", "parityB", "parityC", "parityD"};
  return std::string(vecs[k / 4]) + "." + "xyzw"[k % 4];
}
inline std::string caseUnpack(const CaseVar& v) {
  const std::string t = v.type;
  auto f = [&](int c) { return caseComponent(v.first + c); };
  if (t == "float") return f(0);
  if (t == "int") return "int(" + f(0) + ")";
  if (t == "bool") return "(" + f(0) + " > 0.5f)";
  if (t == "ivec2") return "ivec2(int(" + f(0) + "), int(" + f(1) + "))";
  std::string s = t + "(";
  for (int c = 0; c < caseTypeWidth(t); ++c) s += (c ? ", " : "") + f(c);
  return s + ")";
}
inline std::string caseZero(const std::string& t) {
  if (t == "float") return "0.0f";
  if (t == "int") return "0";
  if (t == "bool") return "false";
  if (t == "ivec2") return "ivec2(0, 0)";
  std::string s = t + "(";
  for (int c = 0; c < caseTypeWidth(t); ++c) s += c ? ", 0.0f" : "0.0f";
  return s + ")";
}
// Output float `c` of `v` as a float expression.
inline std::string casePacked(const CaseVar& v, int c) {
  const std::string t = v.type, n = v.name;
  if (t == "float") return n;
  if (t == "int") return "float(" + n + ")";
  if (t == "bool") return "(" + n + " ? 1.0f : 0.0f)";
  const std::string comp = n + "." + "xyzw"[c];
  return t == "ivec2" ? "float(" + comp + ")" : comp;
}
}  // namespace detail

// The generated GLSL entry of a case (also compiled as HLSL through the bridge).
inline std::string caseEntrySource(const std::string& entry, const std::vector<CaseVar>& inputs,
                                   const std::vector<CaseVar>& outputs, const std::string& body) {
  std::string s = "SNELL_FN SnellParityOut " + entry + "(vec4 parityA, vec4 parityB, vec4 parityC, vec4 parityD) {\n";
  for (const CaseVar& v : inputs) s += std::string("  ") + v.type + " " + v.name + " = " + detail::caseUnpack(v) + ";\n";
  for (const CaseVar& v : outputs) s += std::string("  ") + v.type + " " + v.name + " = " + detail::caseZero(v.type) + ";\n";
  s += "  {\n    " + body + "\n  }\n";
  std::string packed[16];
  for (std::string& p : packed) p = "0.0f";
  for (const CaseVar& v : outputs)
    for (int c = 0; c < caseTypeWidth(v.type); ++c) packed[v.first + c] = detail::casePacked(v, c);
  s += "  SnellParityOut parityOut;\n";
  for (int q = 0; q < 4; ++q)
    s += std::string("  parityOut.") + "abcd"[q] + " = vec4(" + packed[4 * q] + ", " + packed[4 * q + 1] + ", " +
         packed[4 * q + 2] + ", " + packed[4 * q + 3] + ");\n";
  s += "  return parityOut;\n}\n";
  return s;
}

// Builds the registry entry of a described case. Layout errors (an unknown
// type, a float out of 0..15, two names on one float, an exception naming
// nothing) are kept in CaseSpec::layoutError: the manifest test reports them.
inline CaseSpec describeCase(const char* function, const char* caseFile,
                             std::function<std::vector<ParityIO>()> inputs, ParityIO (*cpu)(const ParityIO&),
                             std::vector<CaseVar> ins, std::vector<CaseVar> outs, const char* body,
                             CaseExtras extras) {
  CaseSpec c;
  c.function = function;
  c.glslFile = caseFile;
  c.entry = std::string("case") + function;
  c.entry[4] = static_cast<char>(std::toupper(static_cast<unsigned char>(c.entry[4])));
  c.inputs = std::move(inputs);
  c.cpu = cpu;
  c.textures = std::move(extras.textures);
  c.setup = std::move(extras.setup);
  c.scaledWhere = std::move(extras.scaledInputs);
  std::string error;
  auto place = [&](const std::vector<CaseVar>& vars, std::string (&names)[16], const char* what) {
    for (const CaseVar& v : vars) {
      const int w = caseTypeWidth(v.type);
      if (w == 0) error += std::string(what) + " " + v.name + ": unknown type " + v.type + "; ";
      for (int k = v.first; k < v.first + std::max(w, 1); ++k) {
        if (k < 0 || k > 15) {
          error += std::string(what) + " " + v.name + " reaches float " + std::to_string(k) + "; ";
          continue;
        }
        if (!names[k].empty()) error += std::string(what) + "s " + names[k] + " and " + v.name + " share float " + std::to_string(k) + "; ";
        names[k] = w > 1 ? std::string(v.name) + "." + "xyzw"[k - v.first] : std::string(v.name);
      }
    }
  };
  std::string inNames[16], outNames[16];
  place(ins, inNames, "input");
  place(outs, outNames, "output");
  for (const CaseVar& v : outs)
    for (int k = v.first; k < v.first + caseTypeWidth(v.type) && k < 16; ++k)
      if (k >= 0)
        c.outputs.push_back({k, outNames[k], v.check.exact, v.check.abs, v.check.rel, v.check.scaled,
                             v.check.scaleFirst < 0 ? -1 : v.check.scaleFirst + (k - v.first)});
  // A name selects all its floats, name.x (.y, .z, .w) one of them.
  auto mask = [&](const std::vector<std::string>& names, const std::string (&slots)[16]) {
    std::uint16_t m = 0;
    for (const std::string& n : names) {
      std::uint16_t one = 0;
      for (int k = 0; k < 16; ++k)
        if (slots[k] == n || slots[k].rfind(n + ".", 0) == 0) one = static_cast<std::uint16_t>(one | 1u << k);
      if (!one) error += "exception names " + n + ", which the case does not have; ";
      m = static_cast<std::uint16_t>(m | one);
    }
    return m;
  };
  for (const CaseExtras::NamedException& e : extras.exceptions)
    c.exceptions.push_back({mask(e.passThroughInputs, inNames), mask(e.outputs, outNames), e.always, e.reason});
  for (const CaseVar& v : outs) {
    const std::string t = v.type;
    if (!v.check.exact && (t == "bool" || t == "int" || t == "ivec2"))
      error += std::string("output ") + v.name + ": a " + t + " is compared exactly, not within a tolerance; ";
    if (!v.check.exact && !(v.check.abs >= 0.0f && v.check.rel >= 0.0f && v.check.scaled >= 0.0f))
      error += std::string("output ") + v.name + ": tolerances must be >= 0; ";
    if (v.check.scaleFirst >= 0 && (v.check.scaleFirst + caseTypeWidth(v.type) > 16 || outNames[v.check.scaleFirst].empty()))
      error += std::string("output ") + v.name + ": its scale reads floats no output covers; ";
  }
  for (const std::vector<CaseVar>* vars : {&ins, &outs})
    for (const CaseVar& v : *vars)
      if (std::string(v.name).rfind("parity", 0) == 0)
        error += std::string(v.name) + ": names starting with 'parity' belong to the generated entry; ";
  for (const CaseExtras::NamedException& e : extras.exceptions)
    if (!e.always && e.passThroughInputs.empty()) error += "a pass-through exception names no input; ";
  c.layoutError = error;
  if (!error.empty()) {
    // Nothing is generated from a wrong layout (it could index past the 16
    // floats): the case runs as all zeros and the manifest test names the error.
    c.cpu = [](const ParityIO&) { return ParityIO{}; };
    c.outputs.clear();
    return c;
  }
  c.entrySource = caseEntrySource(c.entry, ins, outs, body);
  return c;
}

// Unpacking and packing, the C++ side of the generated GLSL.
template <class T>
T unpack(const ParityIO& io, int k);
template <>
inline float unpack<float>(const ParityIO& io, int k) {
  return comp(io, k);
}
template <>
inline int unpack<int>(const ParityIO& io, int k) {
  return int(comp(io, k));
}
template <>
inline bool unpack<bool>(const ParityIO& io, int k) {
  return comp(io, k) > 0.5f;
}
template <>
inline glm::vec2 unpack<glm::vec2>(const ParityIO& io, int k) {
  return glm::vec2(unpack<float>(io, k), unpack<float>(io, k + 1));
}
template <>
inline glm::vec3 unpack<glm::vec3>(const ParityIO& io, int k) {
  return glm::vec3(unpack<float>(io, k), unpack<float>(io, k + 1), unpack<float>(io, k + 2));
}
template <>
inline glm::vec4 unpack<glm::vec4>(const ParityIO& io, int k) {
  return glm::vec4(unpack<float>(io, k), unpack<float>(io, k + 1), unpack<float>(io, k + 2), unpack<float>(io, k + 3));
}
template <>
inline glm::ivec2 unpack<glm::ivec2>(const ParityIO& io, int k) {
  return glm::ivec2(unpack<int>(io, k), unpack<int>(io, k + 1));
}

template <class T>
T zero() {
  return T(0);
}
template <>
inline bool zero<bool>() {
  return false;
}

inline void pack(ParityIO& io, int k, float x) { comp(io, k) = x; }
inline void pack(ParityIO& io, int k, int x) { pack(io, k, float(x)); }
inline void pack(ParityIO& io, int k, bool x) { pack(io, k, x ? 1.0f : 0.0f); }
inline void pack(ParityIO& io, int k, const glm::vec2& x) {
  for (int c = 0; c < 2; ++c) pack(io, k + c, x[c]);
}
inline void pack(ParityIO& io, int k, const glm::vec3& x) {
  for (int c = 0; c < 3; ++c) pack(io, k + c, x[c]);
}
inline void pack(ParityIO& io, int k, const glm::vec4& x) {
  for (int c = 0; c < 4; ++c) pack(io, k + c, x[c]);
}
inline void pack(ParityIO& io, int k, const glm::ivec2& x) {
  for (int c = 0; c < 2; ++c) pack(io, k + c, x[c]);
}

}  // namespace snell_parity

// A preprocessor sequence (a)(b)(c) is walked by two macros that call each
// other: each expands one element and leaves the other's name for the next; the
// name left after the last element is pasted with _END into an empty macro.
// (Variadic, because the expanded elements hold commas.)
#define SNELL_PARITY_CAT_(a, b) a##b
#define SNELL_PARITY_CAT(a, b) SNELL_PARITY_CAT_(a, b)
#define SNELL_PARITY_END_(...) __VA_ARGS__##_END
#define SNELL_PARITY_END(...) SNELL_PARITY_END_(__VA_ARGS__)
#define SNELL_PARITY_EACH(first, seq) SNELL_PARITY_END(first seq)

#define SNELL_PARITY_IN_DECL(t, n, k) [[maybe_unused]] t n = ::snell_parity::unpack<t>(parityIn, k);
#define SNELL_PARITY_IN_DECL_A(t, n, k) SNELL_PARITY_IN_DECL(t, n, k) SNELL_PARITY_IN_DECL_B
#define SNELL_PARITY_IN_DECL_B(t, n, k) SNELL_PARITY_IN_DECL(t, n, k) SNELL_PARITY_IN_DECL_A
#define SNELL_PARITY_IN_DECL_A_END
#define SNELL_PARITY_IN_DECL_B_END

#define SNELL_PARITY_IN_META(t, n, k) ::snell_parity::CaseVar{#t, #n, k},
#define SNELL_PARITY_IN_META_A(t, n, k) SNELL_PARITY_IN_META(t, n, k) SNELL_PARITY_IN_META_B
#define SNELL_PARITY_IN_META_B(t, n, k) SNELL_PARITY_IN_META(t, n, k) SNELL_PARITY_IN_META_A
#define SNELL_PARITY_IN_META_A_END
#define SNELL_PARITY_IN_META_B_END

#define SNELL_PARITY_OUT_DECL(t, n, k, c) t n = ::snell_parity::zero<t>();
#define SNELL_PARITY_OUT_DECL_A(t, n, k, c) SNELL_PARITY_OUT_DECL(t, n, k, c) SNELL_PARITY_OUT_DECL_B
#define SNELL_PARITY_OUT_DECL_B(t, n, k, c) SNELL_PARITY_OUT_DECL(t, n, k, c) SNELL_PARITY_OUT_DECL_A
#define SNELL_PARITY_OUT_DECL_A_END
#define SNELL_PARITY_OUT_DECL_B_END

#define SNELL_PARITY_OUT_PACK(t, n, k, c) ::snell_parity::pack(parityOut, k, n);
#define SNELL_PARITY_OUT_PACK_A(t, n, k, c) SNELL_PARITY_OUT_PACK(t, n, k, c) SNELL_PARITY_OUT_PACK_B
#define SNELL_PARITY_OUT_PACK_B(t, n, k, c) SNELL_PARITY_OUT_PACK(t, n, k, c) SNELL_PARITY_OUT_PACK_A
#define SNELL_PARITY_OUT_PACK_A_END
#define SNELL_PARITY_OUT_PACK_B_END

#define SNELL_PARITY_OUT_META(t, n, k, c) ::snell_parity::CaseVar{#t, #n, k, ::snell_parity::checks::c},
#define SNELL_PARITY_OUT_META_A(t, n, k, c) SNELL_PARITY_OUT_META(t, n, k, c) SNELL_PARITY_OUT_META_B
#define SNELL_PARITY_OUT_META_B(t, n, k, c) SNELL_PARITY_OUT_META(t, n, k, c) SNELL_PARITY_OUT_META_A
#define SNELL_PARITY_OUT_META_A_END
#define SNELL_PARITY_OUT_META_B_END

// SNELL_PARITY_CASE(function, generator, inputs, outputs, extras, body...): see
// the top of this file. Expands, at namespace scope of a *_cases.cpp that
// defines SNELL_PARITY_FILE and includes that helper file, to the C++ build of
// the case and its registration.
#define SNELL_PARITY_CASE(FUNCTION, GENERATOR, INPUTS, OUTPUTS, EXTRAS, ...)                                      \
  inline ::snell_parity::ParityIO SNELL_PARITY_CAT(parityCpu_, FUNCTION)(                                       \
      [[maybe_unused]] const ::snell_parity::ParityIO& parityIn) {                                                 \
    SNELL_PARITY_EACH(SNELL_PARITY_IN_DECL_A, INPUTS)                                                               \
    SNELL_PARITY_EACH(SNELL_PARITY_OUT_DECL_A, OUTPUTS) {                                                           \
      __VA_ARGS__                                                                                                  \
    }                                                                                                              \
    ::snell_parity::ParityIO parityOut{};                                                                          \
    SNELL_PARITY_EACH(SNELL_PARITY_OUT_PACK_A, OUTPUTS)                                                             \
    return parityOut;                                                                                              \
  }                                                                                                                \
  static const ::snell_parity::Registrar SNELL_PARITY_CAT(parityRegistrar_, FUNCTION)(::snell_parity::describeCase( \
      #FUNCTION, SNELL_PARITY_FILE, GENERATOR, SNELL_PARITY_CAT(parityCpu_, FUNCTION),                            \
      {SNELL_PARITY_EACH(SNELL_PARITY_IN_META_A, INPUTS)}, {SNELL_PARITY_EACH(SNELL_PARITY_OUT_META_A, OUTPUTS)},    \
      #__VA_ARGS__, EXTRAS));

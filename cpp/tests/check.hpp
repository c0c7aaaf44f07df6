// A tiny test harness for the C++ tests: CHECK records failures, finish() prints the
// "N passed, N failed" line and returns the exit code.
//
// Every test file is one suite: its code lives in a namespace named for the file, its entry point
// is that namespace's main(), and CHECK_SUITE(name) registers it with the runner (runner.cpp),
// which runs the suite named by its first argument. The files of a family are compiled as one
// translation unit (cpp/tests/CMakeLists.txt), so the header templates they share compile once;
// each file still builds on its own with runner.cpp.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <vector>

namespace check {
inline int passed = 0, failed = 0;

inline void record(bool ok, const char* expr, const char* file, int line) {
  if (ok) {
    ++passed;
  } else {
    ++failed;
    std::printf("FAILED %s:%d: %s\n", file, line, expr);
  }
}

inline int finish(const char* name) {
  std::printf("%s: %d passed, %d failed\n", name, passed, failed);
  return failed == 0 ? 0 : 1;
}
// The bar of a closed-form case in precision Real: 1e-12 in double, rounding-limited (64 eps)
// in float.
template <class Real> Real closed_form_bar() {
  return std::max(Real(1e-12), Real(64) * std::numeric_limits<Real>::epsilon());
}

// The multiplier of the random draws' counts (scaled()): CIRCLEDIST_TEST_SCALE when it is set
// (a longer run: 10), else 1. Every fixed and hard case runs at any scale.
inline double scale() {
  static const double value = [] {
    if (const char* text = std::getenv("CIRCLEDIST_TEST_SCALE")) {
      char* end = nullptr;
      const double given = std::strtod(text, &end);
      if (end != text && *end == '\0' && given > 0) return given;
      std::fprintf(stderr, "CIRCLEDIST_TEST_SCALE must be a positive number, not '%s'\n", text);
      std::exit(2);
    }
    return 1.0;
  }();
  return value;
}
// n random draws times scale(), rounded down.
inline int scaled(double n) { return int(n * scale()); }

// The registered suites (CHECK_SUITE) and their entry points.
struct Suite {
  const char* name;
  std::function<int(int, char**)> main;
};
inline std::vector<Suite>& suites() {
  static std::vector<Suite> all;
  return all;
}
struct Registration {
  Registration(const char* name, int (*main)(int, char**)) { suites().push_back({name, main}); }
  Registration(const char* name, int (*main)()) {
    suites().push_back({name, [main](int, char**) { return main(); }});
  }
};
}  // namespace check

#define CHECK(expr) ::check::record(static_cast<bool>(expr), #expr, __FILE__, __LINE__)
#define CHECK_NEAR(a, b, tol) \
  ::check::record(std::abs(double((a) - (b))) <= double(tol), #a " ~= " #b " within " #tol, __FILE__, __LINE__)
// Registers namespace `name`'s main() as the suite `name` (after that namespace's closing brace).
#define CHECK_SUITE(name) static const ::check::Registration check_suite_##name(#name, &name::main)

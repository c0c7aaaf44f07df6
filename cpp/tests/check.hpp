// A tiny test harness for the C++ tests: CHECK records failures, finish() prints the
// "N passed, N failed" line and returns the exit code.
#pragma once

#include <algorithm>
#include <cstdio>
#include <limits>

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
}  // namespace check

#define CHECK(expr) ::check::record(static_cast<bool>(expr), #expr, __FILE__, __LINE__)
#define CHECK_NEAR(a, b, tol) \
  ::check::record(std::abs(double((a) - (b))) <= double(tol), #a " ~= " #b " within " #tol, __FILE__, __LINE__)

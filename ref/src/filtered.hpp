// Filtered values of exact numbers, to pick the least or largest of exact margins. A margin is
// reported, never decided on: picking on a filtered value costs no exactness, while an exact
// comparison of two equal deep margins costs CORE a root-bound evaluation (campaign case 836274
// of seed 20261231 spent 5.7 s of its 5.7 s comparing equal margins exactly).
#pragma once

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "kernel.hpp"

namespace cutcom::ref {

// The floating-point filter's value of an exact number, computed when it was built: enough to
// pick the least or largest of exact margins. CGAL::to_double would evaluate the expression to 53
// bits, which costs CORE a root-bound evaluation wherever an inner difference is exactly zero.
// The value counts only within its error bound (1e-6 relative or 2^-30 units): a square root of an
// uncertain or NaN value leaves 0 with an infinite bound (campaign case 215678: a chord of 3.5 mm
// read 0). Otherwise an evaluation to 2^-64 units absolute (not to_double's 53 relative bits,
// which an exact zero pushes to 2^-1024).
inline double rough(const FT& x) {
  const CORE::filteredFp& f = x.Rep()->ffVal;
  double v = f.getValue();
  if (std::isfinite(v)) {
    // The bound is private: it is within delta when v and v + delta have told signs apart.
    double delta = std::max(std::fabs(v) * 1e-6, std::ldexp(1.0, -30));
    if ((f - CORE::filteredFp(v + delta)).isOK()) return v;
  }
  return x.approx(CORE::extLong(53), CORE::extLong(64)).doubleValue();
}

// Double bounds lo < x < hi, certified by the floating-point filter (the sign of x - d is the
// filter's where it is sure of it: CORE's own first test of a sign): a few millionths of a unit
// around the filter's value. Empty where the filter is not sure; the caller then decides exactly.
struct CertifiedBounds {
  double lo, hi;
};
inline std::optional<CertifiedBounds> certified_bounds(const FT& x) {
  const CORE::filteredFp& f = x.Rep()->ffVal;
  double v = f.getValue();
  if (!std::isfinite(v)) return std::nullopt;
  double delta = std::fabs(v) * 0x1p-30 + 0x1p-20;
  CertifiedBounds b{v - delta, v + delta};
  CORE::filteredFp below = f - CORE::filteredFp(b.lo), above = f - CORE::filteredFp(b.hi);
  if (!below.isOK() || below.sign() <= 0 || !above.isOK() || above.sign() >= 0) return std::nullopt;
  return b;
}

// Whether margin a is less than margin b, to report the least of several exact margins. The
// filtered values pick where both are clearly of one sign (beyond twice the filter's absolute
// bound); otherwise the exact signs decide first, so the margin reported always has the sign of
// the least one. Values of one sign within the filter's error may be picked either way: the
// margin reported is then one of them, exactly.
inline bool margin_less(const FT& a, const FT& b) {
  double x = rough(a), y = rough(b);
  constexpr double kClear = 0x1p-29;
  if (std::fabs(x) > kClear && std::fabs(y) > kClear && (x < 0) == (y < 0)) return x < y;
  CGAL::Sign sa = CGAL::sign(a), sb = CGAL::sign(b);
  if (sa != sb) return sa < sb;
  return x < y;
}

}  // namespace cutcom::ref

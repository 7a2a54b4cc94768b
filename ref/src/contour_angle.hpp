// TRC-CORNER-2 (used by TRC-CORNER-3/4): the exact comparison of a corner's contour angle with a threshold in degrees
// (MD20210, MD20230), with no double anywhere (decision 29).
#pragma once

#include <gmpxx.h>

#include <string>

#include "cutcom/decimal.hpp"
#include "kernel.hpp"

namespace cutcom::ref {

struct AngleComparison {
  int sign = 0;             // sign(theta - threshold)
  std::string margin_text;  // theta - threshold in degrees; its sign is exact
};

// theta = deflection angle between two directions with integer cross product `cross`, dot
// product `dot` and |d1|^2 |d2|^2 = `squared_lengths_product`; threshold in [0, 180] degrees.
//
// Why this is exact: cos(theta) = dot / sqrt(L2) has a rational square. If cos(theta) = cos(T)
// then cos^2(T) is rational, and by Niven's theorem (T a rational number of degrees) that happens
// only for T mod 180 in {0, 30, 45, 60, 90, 120, 135, 150}; those are compared with rationals.
// For any other T the two values differ, so MPFR evaluation with a proven error bound and
// increasing precision always reaches a decision.
// `with_margin` false: the sign only (margin_text empty), where no trace keeps the margin.
AngleComparison compare_contour_angle(const mpz_class& cross, const mpz_class& dot,
                                      const mpz_class& squared_lengths_product, const Decimal& threshold_degrees,
                                      bool with_margin = true);

// The same for directions with square roots (CR= circles), given as exact numbers. cos T is
// bracketed by rationals (MPFR, growing precision) and compared exactly with cos(theta); the
// special thresholds are compared exactly as above. Equal to 2^-4096 counts as equal: possible
// only when cos T is itself a nest of square roots (a constructible T such as 36 or 22.5).
AngleComparison compare_contour_angle_exact(const FT& cross, const FT& dot, const FT& squared_lengths_product,
                                            const Decimal& threshold_degrees, bool with_margin = true);

}  // namespace cutcom::ref

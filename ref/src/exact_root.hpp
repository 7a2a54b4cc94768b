// The square root of a number known to be >= 0, taken as 0 when it is exactly 0, and divisors
// known not to be 0, kept clear of CORE's diagnostics file.
//
// CORE keeps beside every expression a floating-point filter (a double and a bound on its error)
// and decides signs by it where the bound allows. A root's filter is taken from its argument's
// when the root is built; where that double came out negative (or 0, and the root is later a
// divisor) although the exact value is positive, which near-tangent circles give, CORE appends a
// warning to a file "Core_Diagnostics" in the working directory, and where that file cannot be
// written it ends the process (exit 1, no output): `cutcom run --engine ref` in a read-only
// directory did so on two corpus programs. The argument's exact sign is known here, so its filter
// is settled first (settle_filter). The result stays exact either way.
//
// Settled with the value's nearest double and a bound of two of its ulps, the filter decides the
// signs built on it again (issue "Performance"): a bound of infinity sent every sign downstream of
// a line-circle corner to CORE's exact evaluation (a sixth of ref's time under CDON).
#pragma once

#include <CGAL/CORE_Expr.h>
#include <CGAL/number_utils.h>

namespace cutcom::ref {

// Where `v`'s filter does not prove its sign (CORE's isOK(): a filter that does proves the exact
// one), it is replaced by one that does: its nearest double's (kernel.hpp, filter_by_nearest), so
// no operation finds a negative root argument or a zero divisor in it. Where no nearest double is
// found, the bound is infinite instead: the filter claims nothing and CORE decides every later
// sign exactly (kernel.cpp).
void settle_filter(const CORE::Expr& v, CGAL::Sign exact);

// A divisor known not to be 0, with a filter fit to divide by: one whose double may be 0 (a sum of
// nearly opposite terms) has CORE warn of a possible zero divisor as above. Its exact sign is
// computed only where the filter cannot tell it.
inline const CORE::Expr& settled_divisor(const CORE::Expr& d) {
  if (!d.Rep()->ffVal.isOK()) settle_filter(d, CGAL::sign(d));
  return d;
}

inline CORE::Expr exact_root(const CORE::Expr& v) {
  CGAL::Sign sign = CGAL::sign(v);
  if (sign == CGAL::ZERO) return CORE::Expr(0);
  settle_filter(v, sign);
  return CGAL::sqrt(v);
}

}  // namespace cutcom::ref

// ref's number model. Coordinates are exact: the kernel's FT is CORE::Expr (exact square roots),
// built from integer leaves (program values in units of 10^-9, NC-NUM-1), and
// decisions that can be phrased on the programmed data use GMP integers instead.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>
#include <gmpxx.h>

#include <string>

#include "cutcom/block.hpp"
#include "cutcom/path.hpp"
#include "cutcom/units_mpz.hpp"  // to_mpz: a decimal's units exactly
#include "exact_root.hpp"

namespace cutcom::ref {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt;
using FT = Kernel::FT;
using Point = Kernel::Point_2;
using Vector = Kernel::Vector_2;

// An integer Expr leaf holding a decimal's units (fresh per call: no shared, polluted leaves).
FT leaf(const Decimal& d);

// The in-plane point (abscissa, ordinate) of a programmed position, in units.
Point plane_point(const Point3& p, PlaneAxes axes);

// The unit normal to the left of d (one square root).
inline Vector unit_left_normal(const Vector& d) {
  FT l = exact_root(d.squared_length());
  return Vector(-d.y() / l, d.x() / l);
}

// PATH-ELEMENT-2: the double nearest to an exact value, ties to even: ref's output boundary. CORE's own
// conversion is good to about an ulp, so two expressions of one value could print as two doubles
// (a full circle's end a rounding away from its start, a turn nobody can read back).
double nearest_double(const FT& value);
// The same of units (10^-9 mm) in mm: the double nearest to units / 10^9.
double nearest_mm(const FT& units);

// `v`'s floating-point filter replaced by one of its nearest double and a bound of two of that
// double's ulps, where one approximation of v finds that double in the normal range (kernel.cpp,
// with the soundness argument); false, the filter unchanged, where it does not. Never an exact
// comparison, so never a zero test.
bool filter_by_nearest(const FT& v);

// A point computed through square roots and divisions from coordinates far larger than the
// differences that matter has a floating-point filter (exact_root.hpp) orders of magnitude looser
// than its value, so that every sign built on it (where a later piece crosses it, whether it lies
// before an element's end) is taken exactly. Its coordinates' filters are made their nearest
// doubles' (filter_by_nearest), where one approximation finds them: the point itself is unchanged.
inline void tighten_filters(const Point& p) {
  filter_by_nearest(p.x());
  filter_by_nearest(p.y());
}

// A margin for the decision trace: the sign is exact, the digits are a 20-digit rendering.
std::string exact_text(const FT& value);
// A length margin: units (10^-9 mm) rendered in mm.
std::string exact_mm(const FT& units);

}  // namespace cutcom::ref

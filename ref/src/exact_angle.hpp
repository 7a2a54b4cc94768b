// Exact angles for arcs: theta = 2 pi turns + arg(v), with arg(v) in [0, 2 pi) and v an exact
// vector. Sums are complex products with a carry; signs and comparisons are exact predicates,
// so no angle is ever rounded (TRC-ARC-ELEMENT-1 needs "sweep - trims >= 0" exactly).
#pragma once

#include <string>

#include "kernel.hpp"

namespace cutcom::ref {

struct ExactAngle {
  long turns = 0;
  FT x{1}, y{0};  // direction; arg in [0, 2 pi)

  static ExactAngle of(const Vector& v) { return {0, v.x(), v.y()}; }
  static ExactAngle full_turn() { return {1, FT(1), FT(0)}; }
  // The signed rotation in (-pi, pi] from `from` to `to` in the sense `sense` (+1 ccw).
  static ExactAngle signed_rotation(const Vector& from, const Vector& to, int sense);
  // The rotation in [0, 2 pi) from `from` to `to` in the sense `sense`.
  static ExactAngle rotation(const Vector& from, const Vector& to, int sense);

  friend ExactAngle operator+(const ExactAngle& a, const ExactAngle& b);
  friend ExactAngle operator-(const ExactAngle& a);
  CGAL::Sign sign() const;
};

// Radians times a length, as margin text (sign exact, digits from MPFR).
std::string arc_length_text(const ExactAngle& angle, const FT& radius);

}  // namespace cutcom::ref

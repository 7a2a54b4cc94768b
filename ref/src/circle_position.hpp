// Exact positions on one circle, for arcs (TRC-ARC-ELEMENT-1 needs "sweep - trims >= 0" exactly).
// A position is `turns` whole turns plus the rotation, in [0, 2 pi), from the circle's reference
// ray u to a vector v, in the circle's sense. Positions compare by half-plane and cross-product
// signs of the raw vectors (degree 2): no rotations are multiplied, so the exact zero test of a
// point lying exactly at an end stays cheap (CORE's cost grows with the expression's degree).
#pragma once

#include <string>

#include "kernel.hpp"

namespace cutcom::ref {

struct CirclePosition {
  long turns = 0;
  Vector v;  // the direction from the centre
};

class CircleFrame {
 public:
  CircleFrame(const Vector& u, int sense) : u_(u), sense_(sense) {}

  CirclePosition start() const { return {0, u_}; }
  // The end of an arc from the reference ray to `to`: a full turn when `full`.
  CirclePosition end(const Vector& to, bool full) const { return full ? CirclePosition{1, u_} : CirclePosition{0, to}; }
  // Where v lies in the first turn, [0, 2 pi).
  CirclePosition at(const Vector& v) const { return {0, v}; }
  // From p by the signed rotation to v, in (-pi, pi].
  CirclePosition signed_from(const CirclePosition& p, const Vector& v) const;
  // From p by the rotation to v in [0, 2 pi).
  CirclePosition forward_from(const CirclePosition& p, const Vector& v) const;

  CGAL::Sign compare(const CirclePosition& a, const CirclePosition& b) const;
  // to - from in radians, for margins only (the exact sign is compare's).
  double radians(const CirclePosition& from, const CirclePosition& to) const;
  // (to - from) as an arc length on `radius` (units), in mm: sign exact, digits from MPFR.
  std::string length_text(const CirclePosition& from, const CirclePosition& to, const FT& radius) const;

 private:
  int half(const Vector& v) const;                                     // 0: [0, pi), 1: [pi, 2 pi)
  CGAL::Sign compare_in_turn(const Vector& a, const Vector& b) const;  // rotations from u in [0, 2 pi)
  CGAL::Sign turn_sign(const Vector& a, const Vector& b) const;        // sense of the rotation from a to b

  Vector u_;
  int sense_;
};

}  // namespace cutcom::ref

// Exact contour elements (straight or circular) and the rational predicates decided on them.
// Lines and I/J/K circles have rational data: end points, centre, squared radius and tangent
// directions. Square roots enter only through lengths, radii and unit normals.
#pragma once

#include <optional>

#include "kernel.hpp"

namespace cutcom::ref {

// A rational in-plane vector (exact tangent directions, not normalised).
struct RationalVector {
  mpq_class a, b;
};

struct ContourElement {
  enum class Kind { kLine, kArc } kind = Kind::kLine;
  int line = 0;                               // source line
  std::optional<std::int64_t> number;         // N number
  Point3 start3, end3;                        // programmed positions (exact decimals)
  Point a, b;                                 // start and end in the plane (units of 10^-9 mm)
  RationalVector start_tangent, end_tangent;  // valid when `rational`
  bool rational = true;                       // false for CR= circles (centre with a square root)
  Vector start_dir, end_dir;                  // tangent directions, always (exact)

  // Lines.
  Vector d;       // b - a
  FT length;      // |d|
  Vector normal;  // left unit normal

  // Arcs (ARC-CENTRE-1): centre on the bisector of the chord, sense +1 ccw (G3), -1 cw (G2).
  mpq_class cx, cy, radius_squared;
  Point centre;
  FT radius;
  int sense = 1;
  bool full_circle = false;

  static ContourElement of_line(const Block& block, PlaneAxes axes);
  static ContourElement of_arc(const Block& block, PlaneAxes axes);  // I/J/K or CR=
  bool is_arc() const { return kind == Kind::kArc; }

  // Unit left normal of the tangent at the start / end (exact, with one square root).
  Vector start_normal() const;
  Vector end_normal() const;
};

// TRC-CORNER-1: the kind of the corner between two elements, from the exact tangents.
enum class CornerKind { kTangent, kInner, kOuter, kReversal };
struct CornerClass {
  CornerKind kind;
  mpq_class cross, dot;
  // Integer directions with the same angles (scaled tangents), for the contour angle.
  mpz_class a1, b1, a2, b2;
};
CornerClass classify_corner(const RationalVector& end_tangent, const RationalVector& start_tangent, int side);
// The same from exact (possibly irrational) directions.
CornerKind classify_corner(const Vector& end_tangent, const Vector& start_tangent, int side);

FT to_ft(const mpq_class& q);
// The square root of a rational q >= 0, rational where it is one (contour_element.cpp).
FT rational_root(const mpq_class& q);

}  // namespace cutcom::ref

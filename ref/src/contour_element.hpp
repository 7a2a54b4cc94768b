// Exact straight contour elements and the rational predicates decided on programmed data.
#pragma once

#include <optional>

#include "kernel.hpp"

namespace cutcom::ref {

// A programmed straight block in the active plane. The integer direction (dx, dy) in units
// carries every rational predicate; the Expr objects carry constructions.
struct ContourLine {
  int line = 0;                        // source line
  std::optional<std::int64_t> number;  // N number
  Point3 start3, end3;                 // programmed positions (exact decimals)
  mpz_class dx, dy;                    // end - start in plane units
  Point a, b;                          // start, end in the plane
  Vector d;                            // b - a
  FT length;                           // |d| = sqrt(dx^2 + dy^2)
  Vector normal;                       // left unit normal perp(d)/|d|

  static ContourLine of(const Block& block, PlaneAxes axes);
};

// TRC-CORNER-1: the kind of the corner between two straight elements, from the sign of the
// cross product of their integer directions (an exact rational predicate).
enum class CornerKind { kTangent, kInner, kOuter, kReversal };
struct CornerClass {
  CornerKind kind;
  mpz_class cross, dot;               // of the integer directions
  mpz_class squared_lengths_product;  // |d1|^2 |d2|^2
};
CornerClass classify_corner(const ContourLine& first, const ContourLine& second, int side);

}  // namespace cutcom::ref

// TRC-CORNER-1 exactly where ref decides it in rationals: at lines and at circles with a centre
// (I/J/K, and the centres the reader puts on the grid). A corner's kind is the sign of the cross
// and dot products of two tangents; each tangent is an integer vector (units of 1e-9 mm) times a
// positive factor, and the products are taken in 256 bits (two lines' in 128: their components
// fit in 64). Private to fast.
#pragma once

#include <array>
#include <optional>

#include "block_copy.hpp"

namespace cutcom::fast {

struct IntVec {
  Int128 a = 0, b = 0;
};

// The cross and dot products of two lines' displacements in the plane `axes`, exactly (TRC-CORNER-1
// between lines, TRC-LOOK-2's parallel lines): each component below 2^62 units fits in 64 bits and
// each product is one 64 x 64-bit multiply into 128 bits; nullopt from 2^62 on.
struct LineProducts {
  Int128 cross = 0, dot = 0;
};
std::optional<LineProducts> line_products(const std::array<Int128, 3>& t, const std::array<Int128, 3>& u,
                                          PlaneAxes axes);

// The sign of p·q − r·t, exactly (each product in 256 bits).
int sign_of_difference(Int128 p, Int128 q, Int128 r, Int128 t);

// The tangent of `c` at its start (or end) in the plane `axes`, exactly, times a positive factor:
// a line's displacement d; a circle's σ·perp(P − c') times 2|d|², c' the programmed centre moved
// onto the chord's bisector as ref does (ARC-CENTRE-1):
//   start: σ·(2 n d − |d|² perp d),  end: σ·(2 n d + |d|² perp d),  n = (c − start)·perp d;
// a full circle's (d = 0) σ·perp(start − c). nullopt where it is not exact: a CR= circle, a SAR
// block, components of d or c − start from 2^40 units (1,099 mm) on (the products would not fit).
std::optional<IntVec> exact_tangent(const BlockCopy& c, PlaneAxes axes, bool at_end);

// The signs of the cross and the dot product of `first`'s exact tangent at its end and `second`'s
// at its start (TRC-CORNER-1), false where either is not exact. The last pair's answer is kept:
// under CDON the entry (collision.cpp) and then the corner step take the same corner, and at
// nearly tangent corners (a CAM program's tiny segments) every corner comes here. An exact copy's
// tangent is its block's (`delta` and `to_centre` are the block's decimals while `exact`), so the
// key is the two blocks' identities (the reader's index, and the traversing ordinal for blocks
// given to the engine without one) and the plane: the answer is the function's either way.
class CornerSignsMemo {
 public:
  bool signs(const BlockCopy& first, const BlockCopy& second, PlaneAxes axes, int& cross, int& dot);

 private:
  int first_ = -1, second_ = -1, first_seq_ = -1, second_seq_ = -1, abscissa_ = -1, ordinate_ = -1;
  bool found_ = false;
  int cross_ = 0, dot_ = 0;
};

}  // namespace cutcom::fast

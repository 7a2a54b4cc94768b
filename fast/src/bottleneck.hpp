// TRC-CD-2/3 (CDON) in double precision: pieces of the tool-centre path and where a block's entry
// crosses a held-back piece (see ref/src/bottleneck.hpp for the rule; no code is shared).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "plane_geometry.hpp"

namespace cutcom::fast {

// A segment from a to b, or a circle about `centre` from a through `sweep` in the sense `sense`
// (a pseudo-angle: a quarter turn is 1, a full turn 4; see bottleneck.cpp).
struct PathPiece {
  bool arc = false;
  Vec2 a, b, centre;
  double radius = 0;
  int sense = 1;
  double sweep = 0;  // [0, 4]

  static PathPiece segment(Vec2 from, Vec2 to) {
    PathPiece p;
    p.a = from, p.b = to;
    return p;
  }
  static PathPiece circle(Vec2 from, Vec2 to, Vec2 centre, double radius, int sense, bool full_turn = false);
};

// An axis-aligned box around pieces; a circle piece's holds its ends and the extreme points of
// its circle that it passes. `size`: the largest magnitude of its bounds, kept with them (apart()
// asks for it of every pair).
struct PieceBox {
  double lo_a = 0, lo_b = 0, hi_a = 0, hi_b = 0, size = 0;
  static PieceBox of(const PathPiece& p) {
    if (p.arc) return arc(p.a, p.b, p.centre, p.radius, p.sense, p.sweep);
    return sized(std::min(p.a.a, p.b.a), std::min(p.a.b, p.b.b), std::max(p.a.a, p.b.a), std::max(p.a.b, p.b.b));
  }
  // A circle piece's, from a to b in the sense `sense` with PathPiece's `sweep`.
  static PieceBox arc(Vec2 a, Vec2 b, Vec2 centre, double radius, int sense, double sweep);
  static PieceBox around(const PathPiece* pieces, int count);  // count >= 1
  static PieceBox circle(Vec2 centre, double radius) {         // a whole circle's
    return sized(centre.a - radius, centre.b - radius, centre.a + radius, centre.b + radius);
  }
  // The bounds of u and v together; `size` is left to sized(), which the caller takes once.
  static PieceBox join(const PieceBox& u, const PieceBox& v) {
    return {std::min(u.lo_a, v.lo_a), std::min(u.lo_b, v.lo_b), std::max(u.hi_a, v.hi_a), std::max(u.hi_b, v.hi_b), 0};
  }
  static PieceBox sized(double lo_a, double lo_b, double hi_a, double hi_b) {
    return {lo_a, lo_b, hi_a, hi_b, std::max({std::fabs(lo_a), std::fabs(lo_b), std::fabs(hi_a), std::fabs(hi_b)})};
  }
  // Apart by more than 1e-9 of the coordinates' size (a point's rounding off its carriers is a
  // few ulps of that size): no point piece_crossing computes lies on a piece in each. Apart from
  // a box around pieces is apart from each of them (its pad is no smaller).
  static bool apart(const PieceBox& u, const PieceBox& v) {
    double pad = 1e-9 * (1 + std::max(u.size, v.size));
    return u.hi_a + pad < v.lo_a || v.hi_a + pad < u.lo_a || u.hi_b + pad < v.lo_b || v.hi_b + pad < u.lo_b;
  }
};

// The earliest point along `held` on one of the entry's `count` pieces: `entry_piece` its index
// (-1: none), `slack` its least slack; `near_miss` (-inf: none) the largest slack of the
// carriers' common points off a piece.
struct PieceCrossing {
  Vec2 point;
  int entry_piece = -1;
  double slack = 0;
  double along = 0;  // how far along the held piece (length; rotation times radius at a circle)
  double near_miss = -std::numeric_limits<double>::infinity();
  bool overlap = false;  // two collinear segments overlap or touch: a near miss of 0 (TRC-CD-3)
};
// `from`: the first entry piece compared (see ref). Without `margins` (no decision is kept) the
// near miss and the overlap are left out where the pieces are plainly apart.
PieceCrossing piece_crossing(const PathPiece& held, const PathPiece* entry, int count, int from = 0,
                             bool margins = true);

}  // namespace cutcom::fast

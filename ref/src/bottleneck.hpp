// TRC-CD-2/3 (CDON) in exact arithmetic: pieces of the tool-centre path and where a block's entry
// crosses a held-back piece. The engine decides which pieces are compared; this file holds the
// geometry.
#pragma once

#include <cmath>
#include <deque>
#include <optional>
#include <vector>

#include "circle_position.hpp"
#include "equidistant.hpp"
#include "filtered.hpp"

namespace cutcom::ref {

// A piece of the tool-centre path in the plane: a segment from a to b, or a circle about `centre`
// from a to b in the sense `sense` (a full turn when `full_turn`).
struct PathPiece {
  bool arc = false;
  Point a, b, centre;
  FT radius;
  int sense = 1;
  bool full_turn = false;
  // The line a segment lies on, as its element defines it (the equidistant of the programmed
  // block), where known: shallower than one through its ends, which may be cut points of nested
  // radicals whose zero tests cost CORE minutes (campaign 20261224, case 663362: 100 s).
  std::optional<Carrier<Kernel>> support;

  static PathPiece segment(const Point& from, const Point& to);
  static PathPiece segment(const Point& from, const Point& to, const Carrier<Kernel>& line);
  static PathPiece circle(const Point& from, const Point& to, const Point& centre, const FT& radius, int sense,
                          bool full_turn = false);
  Carrier<Kernel> carrier() const;
  CircleFrame frame() const { return {a - centre, sense}; }
};

// Where the entry meets a held piece: the earliest point along the held piece on both, which
// entry piece it lies on, and its least slack (mm units) to the pieces' ends (and, with a circle,
// the depth of the carriers' overlap). `near_miss`: the largest (negative) slack of the carriers'
// common points that lie off a piece, for the decision's margin.
struct PieceCrossing {
  std::optional<Point> point;
  int entry_piece = -1;
  FT slack;
  std::optional<FT> near_miss;
  bool overlap = false;  // two collinear segments overlap or touch: a near miss of exactly 0
};
// `from`: the first entry piece compared (a lead piece of the predecessor is not compared with its
// neighbour's pieces).
// The largest near miss so far; a crossing's margin, lowered to a nearer miss before it.
inline void keep_largest(std::optional<FT>& near, const std::optional<FT>& miss) {
  if (miss && (!near || rough(*near) < rough(*miss))) near = miss;
}
inline FT lowered(const FT& slack, const std::optional<FT>& near) {
  return near && rough(-*near) < rough(slack) ? -*near : slack;
}

// Points known to lie on a carrier because they were built there (an intersection, a cut): the
// same numbers met again are on it without the exact zero test, which for nested radicals costs
// CORE seconds to minutes (campaign 20261226, case 597: 8 s for a SAR element's end on the circle
// it had been cut at). Holds the last kKeep facts: the collision window's reach, never the program.
class OnCarrierFacts {
 public:
  void add(const Point& p, const Carrier<Kernel>& k);
  // q is one of the points added (the very same numbers) on a carrier equal to c.
  bool known(const Point& q, const Carrier<Kernel>& c) const;

 private:
  static constexpr std::size_t kKeep = 256;
  std::deque<std::pair<Point, Carrier<Kernel>>> facts_;
};

// `margins`: the crossing's slack and the near misses too (margins only; without them the same
// crossing is found, the collinear overlap included).
PieceCrossing piece_crossing(const PathPiece& held, const std::vector<PathPiece>& entry, std::size_t from = 0,
                             bool margins = true, const OnCarrierFacts* facts = nullptr);

}  // namespace cutcom::ref

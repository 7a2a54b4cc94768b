#include "bottleneck.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcom::fast {

namespace {
// The rotation in [0, 2 pi) from `from` to `to` in the sense `sense`.
double rotation(Vec2 from, Vec2 to, int sense) {
  double a = sense * std::atan2(cross(from, to), dot(from, to));
  return a < 0 ? a + 2 * std::numbers::pi : a;
}

// Positions on a circle are only compared with each other, so a pseudo-angle in [0, 4) that grows
// with the rotation (a quarter turn is 1) stands in for it: atan2 was a tenth of a CDON run.
constexpr double kPseudoTurn = 4;
double pseudo_rotation(Vec2 from, Vec2 to, int sense) {
  double x = dot(from, to), y = sense * cross(from, to);
  double size = std::fabs(x) + std::fabs(y);
  if (size == 0) return 0;  // from or to of no length: the start, as atan2(0, 0)
  double p = y / size;      // [-1, 1]
  if (x < 0) return 2 - p;
  return p < 0 ? kPseudoTurn + p : p;
}

Carrier carrier(const PathPiece& p) {
  Carrier c;
  c.circle = p.arc;
  c.point = p.arc ? p.centre : p.a;
  if (p.arc)
    c.radius = p.radius;
  else
    c.direction = p.b - p.a;
  return c;
}

struct OnPiece {
  bool on = false;
  double slack = 0, position = 0;
};
OnPiece locate(const PathPiece& piece, Vec2 p) {
  OnPiece o;
  if (!piece.arc) {
    Vec2 d = piece.b - piece.a;
    double length = norm(d);
    double along = dot(p - piece.a, d) / length, left = length - along;
    o.position = along, o.slack = std::min(along, left), o.on = o.slack >= 0;
    return o;
  }
  o.position = pseudo_rotation(piece.a - piece.centre, p - piece.centre, piece.sense);
  o.on = piece.sweep - o.position >= 0;
  double nearer = std::min(norm(p - piece.a), norm(p - piece.b));
  o.slack = o.on ? nearer : -nearer;
  return o;
}
}  // namespace

// The piece passes its circle's extreme point in direction d where the rotation from its start to
// d (as locate() measures it) is within its sweep. Pseudo-angles of directions a quarter turn
// apart differ by exactly 1, so the four rotations are the first one plus 0, 1, 2, 3 (one
// division); their rounding moves a bound near an extreme by a second-order amount only, well
// inside apart()'s pad.
PieceBox PieceBox::arc(Vec2 a, Vec2 b, Vec2 centre, double radius, int sense, double sweep) {
  const Vec2 c = centre;
  const double rho = radius;
  if (sweep >= kPseudoTurn) return circle(c, rho);
  // The bounds in sized()'s order: lo a, lo b, hi a, hi b.
  double box[4] = {std::min(a.a, b.a), std::min(a.b, b.b), std::max(a.a, b.a), std::max(a.b, b.b)};
  // The extremes in the order the sense meets them from +a (+a, +b, -a, -b counterclockwise;
  // +a, -b, -a, +b clockwise): the bound each sets and its value.
  const int bound[4] = {2, sense > 0 ? 3 : 1, 0, sense > 0 ? 1 : 3};
  const double extreme[4] = {c.a + rho, c.b + sense * rho, c.a - rho, c.b - sense * rho};
  const double first = pseudo_rotation(a - c, {1, 0}, sense);
  for (int quarter = 0; quarter < 4; ++quarter) {
    double t = first + quarter;
    if (t >= kPseudoTurn) t -= kPseudoTurn;
    if (t <= sweep) box[bound[quarter]] = extreme[quarter];
  }
  return sized(box[0], box[1], box[2], box[3]);
}

PieceBox PieceBox::around(const PathPiece* pieces, int count) {
  PieceBox u = of(pieces[0]);
  for (int i = 1; i < count; ++i) u = join(u, of(pieces[i]));
  return count == 1 ? u : sized(u.lo_a, u.lo_b, u.hi_a, u.hi_b);  // the size of the union, once
}

PathPiece PathPiece::circle(Vec2 from, Vec2 to, Vec2 centre, double radius, int sense, bool full_turn) {
  PathPiece p;
  p.arc = true, p.a = from, p.b = to, p.centre = centre, p.radius = radius, p.sense = sense;
  p.sweep = full_turn ? kPseudoTurn : pseudo_rotation(from - centre, to - centre, sense);
  return p;
}

// TRC-CD-3: the earliest point along `held` that lies on one of the entry's pieces.
PieceCrossing piece_crossing(const PathPiece& held, const PathPiece* entry, int count, int from, bool margins) {
  PieceCrossing out;
  if (!held.arc && held.a.a == held.b.a && held.a.b == held.b.b) return out;
  Carrier h = carrier(held);
  const PieceBox held_box = PieceBox::of(held);
  bool found = false;
  double best = 0;
  for (int i = from; i < count; ++i) {
    const PathPiece& e = entry[i];
    if (!e.arc && e.a.a == e.b.a && e.a.b == e.b.b) continue;
    Carrier c = carrier(e);
    // Pieces of one circle: no crossing, as ref (and as concentric ones); in double a centre off
    // by a rounding would cross it anywhere (TRC-LOOK-2's case of campaign 20261241).
    if (on_one_circle(h, c)) continue;
    // TRACE-1: pieces whose boxes are apart have no common point; only the near miss (a margin) needs
    // their carriers' intersections then (the same path either way: PROP-TRACE-1).
    if (!margins && PieceBox::apart(held_box, PieceBox::of(e))) continue;
    bool has_depth = h.circle || c.circle;
    double depth = 0;  // -carrier_gap, taken once a point lies on both pieces (the only use)
    bool depth_known = false;
    Vec2 xs[2];
    int n = carrier_intersections(h, c, xs);
    if (!h.circle && !c.circle && n == 0) {  // parallel: no crossing; the near miss is their distance
      double length = norm(h.direction);
      double gap = std::fabs(cross(h.direction, c.point - h.point)) / length;
      if (gap == 0) {  // collinear: apart along the line, or overlapping (the knife edge of crossing)
        double ta = dot(e.a - held.a, h.direction) / length, tb = dot(e.b - held.a, h.direction) / length;
        gap = std::max({std::min(ta, tb) - length, -std::max(ta, tb), 0.0});
        out.overlap = out.overlap || gap == 0;
      }
      out.near_miss = std::max(out.near_miss, -gap);
    }
    for (int k = 0; k < n; ++k) {
      OnPiece on_held = locate(held, xs[k]), on_entry = locate(e, xs[k]);
      double slack = std::min(on_held.slack, on_entry.slack);
      bool on = on_held.on && on_entry.on;
      if (on && has_depth) {
        if (!depth_known) depth = -carrier_gap(h, c), depth_known = true;
        slack = std::min(slack, depth);
      }
      if (!on) {
        out.near_miss = std::max(out.near_miss, slack);
        continue;
      }
      if (found && on_held.position >= best) continue;
      found = true, best = on_held.position;
      out.point = xs[k], out.entry_piece = i, out.slack = slack;
    }
  }
  // The length along the held circle: its rotation, only for the point taken.
  if (found)
    out.along = held.arc ? rotation(held.a - held.centre, out.point - held.centre, held.sense) * held.radius : best;
  return out;
}

}  // namespace cutcom::fast

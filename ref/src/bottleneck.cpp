#include "bottleneck.hpp"

#include "exact_root.hpp"

namespace cutcom::ref {

PathPiece PathPiece::segment(const Point& from, const Point& to) {
  PathPiece p;
  p.a = from, p.b = to;
  return p;
}

PathPiece PathPiece::circle(const Point& from, const Point& to, const Point& centre, const FT& radius, int sense,
                            bool full_turn) {
  PathPiece p;
  p.arc = true, p.a = from, p.b = to, p.centre = centre, p.radius = radius, p.sense = sense;
  p.sweep = full_turn ? ExactAngle::full_turn() : ExactAngle::rotation(from - centre, to - centre, sense);
  return p;
}

Carrier<Kernel> PathPiece::carrier() const {
  Carrier<Kernel> c;
  c.circle = arc;
  c.point = arc ? centre : a;
  if (arc)
    c.radius = radius;
  else
    c.direction = b - a;
  return c;
}

namespace {
// Where a point of the carrier lies on the piece: `position` orders points along it, `slack` is
// the distance to the nearer end (along a segment, the chord at a circle), negative off it.
struct OnPiece {
  bool on = false;
  FT slack, line_position;
  ExactAngle arc_position;
};
OnPiece locate(const PathPiece& piece, const Point& p) {
  OnPiece o;
  if (!piece.arc) {
    Vector d = piece.b - piece.a;
    FT length = exact_root(d.squared_length());
    FT along = (p - piece.a) * d / length, left = length - along;
    o.line_position = along;
    o.slack = CGAL::compare(along, left) == CGAL::SMALLER ? along : left;
    o.on = CGAL::sign(o.slack) != CGAL::NEGATIVE;
    return o;
  }
  o.arc_position = ExactAngle::rotation(piece.a - piece.centre, p - piece.centre, piece.sense);
  o.on = (piece.sweep + -o.arc_position).sign() != CGAL::NEGATIVE;
  FT to_a = exact_root(CGAL::squared_distance(p, piece.a)), to_b = exact_root(CGAL::squared_distance(p, piece.b));
  FT nearer = CGAL::compare(to_a, to_b) == CGAL::SMALLER ? to_a : to_b;
  o.slack = o.on ? nearer : -nearer;
  return o;
}

CGAL::Sign later(const PathPiece& piece, const OnPiece& p, const OnPiece& q) {
  if (!piece.arc) return CGAL::sign(p.line_position - q.line_position);
  return (p.arc_position + -q.arc_position).sign();
}
}  // namespace

// TRC-CD-3: the earliest point along `held` that lies on one of the entry's pieces.
PieceCrossing piece_crossing(const PathPiece& held, const std::vector<PathPiece>& entry) {
  PieceCrossing out;
  if (!held.arc && held.a == held.b) return out;
  Carrier<Kernel> h = held.carrier();
  std::optional<OnPiece> best;
  for (std::size_t i = 0; i < entry.size(); ++i) {
    const PathPiece& e = entry[i];
    if (!e.arc && e.a == e.b) continue;
    Carrier<Kernel> c = e.carrier();
    std::optional<FT> depth;
    if (h.circle || c.circle) depth = -carrier_gap<Kernel>(h, c);
    for (const Point& p : carrier_intersections<Kernel>(h, c)) {
      OnPiece on_held = locate(held, p), on_entry = locate(e, p);
      FT slack = CGAL::compare(on_held.slack, on_entry.slack) == CGAL::SMALLER ? on_held.slack : on_entry.slack;
      if (depth && CGAL::compare(*depth, slack) == CGAL::SMALLER) slack = *depth;
      if (!on_held.on || !on_entry.on) {
        if (!out.near_miss || CGAL::compare(slack, *out.near_miss) == CGAL::LARGER) out.near_miss = slack;
        continue;
      }
      if (best && later(held, on_held, *best) != CGAL::NEGATIVE) continue;
      best = on_held, out.point = p, out.entry_piece = static_cast<int>(i), out.slack = slack;
    }
  }
  return out;
}

}  // namespace cutcom::ref

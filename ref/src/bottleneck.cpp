#include "bottleneck.hpp"

#include <optional>

#include "exact_root.hpp"
#include "piece_box.hpp"

namespace cutcom::ref {

PathPiece PathPiece::segment(const Point& from, const Point& to) {
  PathPiece p;
  p.a = from, p.b = to;
  return p;
}

PathPiece PathPiece::segment(const Point& from, const Point& to, const Carrier<Kernel>& line) {
  PathPiece p = segment(from, to);
  p.support = line;
  return p;
}

PathPiece PathPiece::circle(const Point& from, const Point& to, const Point& centre, const FT& radius, int sense,
                            bool full_turn) {
  PathPiece p;
  p.arc = true, p.a = from, p.b = to, p.centre = centre, p.radius = radius, p.sense = sense;
  p.full_turn = full_turn;
  return p;
}

Carrier<Kernel> PathPiece::carrier() const {
  if (support) return *support;
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
// Margins only pick the least or largest of exact values: an approximate comparison picks one of
// equal values as well, without the exact zero test of their difference (CORE's costliest case).
bool approx_less(const FT& a, const FT& b) { return rough(a) < rough(b); }

// Where a point of the carrier lies on the piece: `position` orders points along it, `slack` is
// the distance to the nearer end (along a segment, the chord at a circle), negative off it.
struct OnPiece {
  bool on = false;
  FT slack, line_position;  // line_position: times the segment's length
  CirclePosition arc_position;
};
// The very same exact numbers (shared by construction), without a zero test.
bool same_point(const Point& p, const Point& q) { return p.x().Rep() == q.x().Rep() && p.y().Rep() == q.y().Rep(); }

// `margins`: the slack too (a margin only: where nothing keeps the trace it is left out, see
// Trace::keeps_decisions; the exact distances to the ends were most of ref's time under CDON).
OnPiece locate(const PathPiece& piece, const Point& p, bool margins) {
  OnPiece o;
  if (same_point(p, piece.a) || same_point(p, piece.b)) {  // an end of the piece: on it, no slack
    bool at_a = same_point(p, piece.a);
    o.on = true, o.slack = FT(0);
    if (!piece.arc)
      o.line_position = at_a ? FT(0) : (piece.b - piece.a).squared_length();
    else
      o.arc_position = at_a ? piece.frame().start() : piece.frame().at(p - piece.centre);
    return o;
  }
  if (!piece.arc) {
    Vector d = piece.b - piece.a;
    // Signs on the lengths times |d| (no square root in the exact zero tests).
    FT along_d = (p - piece.a) * d, left_d = d * d - along_d;
    CGAL::Sign along_sign = CGAL::sign(along_d), left_sign = CGAL::sign(left_d);
    o.line_position = along_d;
    o.on = along_sign != CGAL::NEGATIVE && left_sign != CGAL::NEGATIVE;
    if (!margins) return o;
    FT length = exact_root(d.squared_length());
    FT along = along_d / length, left = left_d / length;
    if (o.on)
      o.slack = approx_less(along, left) ? along : left;
    else
      o.slack = along_sign == CGAL::NEGATIVE ? along : left;
    return o;
  }
  CircleFrame f = piece.frame();
  o.arc_position = f.at(p - piece.centre);
  o.on = piece.full_turn || f.compare(o.arc_position, f.at(piece.b - piece.centre)) != CGAL::POSITIVE;
  if (!margins) return o;
  FT to_a = exact_root(CGAL::squared_distance(p, piece.a)), to_b = exact_root(CGAL::squared_distance(p, piece.b));
  FT nearer = approx_less(to_a, to_b) ? to_a : to_b;
  o.slack = o.on ? nearer : -nearer;
  return o;
}

CGAL::Sign later(const PathPiece& piece, const OnPiece& p, const OnPiece& q) {
  if (!piece.arc) return CGAL::sign(p.line_position - q.line_position);
  return piece.frame().compare(p.arc_position, q.arc_position);
}
}  // namespace

namespace {
// Whether q lies on the carrier (exact; only zero in a degenerate case, decided by the filter
// otherwise).
bool on_carrier(const Carrier<Kernel>& c, const Point& q) {
  if (!c.circle) return CGAL::sign(CGAL::determinant(c.direction, q - c.point)) == CGAL::ZERO;
  return CGAL::compare((q - c.point).squared_length(), c.radius * c.radius) == CGAL::EQUAL;
}

// The carriers' common points when a piece's end q is known to be one of them: q itself (the
// same numbers, so locating it at that end needs no zero test) and the other one, found without
// a new square root (Vieta on the line, the mirror image across the line of centres); none for
// one and the same circle. A crossing exactly at an end otherwise costs CORE a zero test of
// nested radicals (minutes; campaign 81).
std::vector<Point> intersections_through(const Carrier<Kernel>& h, const Carrier<Kernel>& c, const Point& q) {
  std::vector<Point> out{q};
  if (h.circle != c.circle) {
    const Carrier<Kernel>& l = h.circle ? c : h;
    const Carrier<Kernel>& k = h.circle ? h : c;
    Vector pc = l.point - k.point;
    FT a = l.direction.squared_length(), b = l.direction * pc;
    // Tangent (q the only one) where the line runs square to the radius at q: the same as a zero
    // discriminant, but of degree 2 instead of 4, so a zero costs CORE far less (21 s of 58 in
    // campaign 20261213, case 164685).
    if (CGAL::sign((q - k.point) * l.direction) == CGAL::ZERO) return out;
    FT tq = (q - l.point) * l.direction / a;
    out.push_back(l.point + l.direction * (FT(-2) * b / a - tq));
    return out;
  }
  Vector d = c.point - h.point;
  FT dd = d.squared_length();
  if (CGAL::sign(dd) == CGAL::ZERO) return {};         // the same circle: no crossing (as concentric ones)
  Point m = h.point + d * (((q - h.point) * d) / dd);  // q's foot on the line of centres
  if (m == q) return out;                              // on that line: tangent circles
  out.push_back(m + (m - q));
  return out;
}

// Two lines that cross at one of the pieces' ends: that end itself (the same numbers), so that
// locating it needs no zero test. A crossing computed afresh at an end that is itself a deep
// expression (a point where an earlier cut ended the held piece, met again by the next piece of a
// straight entry) costs CORE a zero test of nested radicals: 70 s (campaign 20261129, case
// 62316). Only an end within a rounding of the other line is tested exactly.
std::optional<std::vector<Point>> line_crossing_at_an_end(const PathPiece& held, const PathPiece& e,
                                                          const Carrier<Kernel>& h, const Carrier<Kernel>& c) {
  auto near = [](const Carrier<Kernel>& line, const Point& q) {
    double d = rough(CGAL::determinant(line.direction, q - line.point));
    double l2 = rough(line.direction.squared_length());
    return d * d <= l2;  // within 1 unit (10^-9 mm) of the line
  };
  const Point* at = nullptr;
  for (const Point* q : {&held.a, &held.b})
    if (!at && near(c, *q) && on_carrier(c, *q)) at = q;
  for (const Point* q : {&e.a, &e.b})
    if (!at && near(h, *q) && on_carrier(h, *q)) at = q;
  if (!at) return std::nullopt;
  // On both lines: they cross there, unless they are one line (parallel: no crossing, the knife
  // edge of crossing, as carrier_intersections would find).
  if (CGAL::sign(CGAL::determinant(h.direction, c.direction)) == CGAL::ZERO) return std::vector<Point>{};
  return std::vector<Point>{*at};
}
}  // namespace

void OnCarrierFacts::add(const Point& p, const Carrier<Kernel>& k) {
  facts_.emplace_back(p, k);
  if (facts_.size() > kKeep) facts_.pop_front();
}

namespace {
// Two carriers are one: exactly equal centre and radius, or parallel directions through each
// other's point. The floating-point filter only turns clearly different ones away early; a wrong
// "different" costs time, never a decision (on_carrier then decides exactly).
bool same_carrier(const Carrier<Kernel>& u, const Carrier<Kernel>& v) {
  if (u.circle != v.circle) return false;
  auto near = [](const FT& a, const FT& b) {
    double x = rough(a), y = rough(b);
    return std::fabs(x - y) <= 1e-6 * std::max({1.0, std::fabs(x), std::fabs(y)});
  };
  if (u.circle) {
    if (!near(u.point.x(), v.point.x()) || !near(u.point.y(), v.point.y()) || !near(u.radius, v.radius)) return false;
    return u.point == v.point && u.radius == v.radius;
  }
  double cross = rough(CGAL::determinant(u.direction, v.direction));
  double scale = rough(u.direction.squared_length()) + rough(v.direction.squared_length());
  if (std::fabs(cross) > 1e-6 * scale) return false;
  return CGAL::sign(CGAL::determinant(u.direction, v.direction)) == CGAL::ZERO &&
         CGAL::sign(CGAL::determinant(u.direction, v.point - u.point)) == CGAL::ZERO;
}
}  // namespace

bool OnCarrierFacts::known(const Point& q, const Carrier<Kernel>& c) const {
  for (const auto& [p, k] : facts_)
    if (same_point(p, q) && same_carrier(k, c)) return true;
  return false;
}

// TRC-CD-3: the earliest point along `held` that lies on one of the entry's pieces.
PieceCrossing piece_crossing(const PathPiece& held, const std::vector<PathPiece>& entry, std::size_t from, bool margins,
                             const OnCarrierFacts* facts) {
  auto lies_on = [&](const Carrier<Kernel>& c, const Point& q) {
    return (facts && facts->known(q, c)) || on_carrier(c, q);
  };
  PieceCrossing out;
  if (!held.arc && held.a == held.b) return out;
  Carrier<Kernel> h = held.carrier();
  std::optional<OnPiece> best;
  // Without margins an entry piece whose certified box lies apart from the held piece's has no
  // point on it (PieceBox): its near miss is only a margin (PROP-TRACE-1).
  std::optional<PieceBox> held_box = margins ? std::nullopt : PieceBox::of(held);
  for (std::size_t i = from; i < entry.size(); ++i) {
    const PathPiece& e = entry[i];
    if (held_box) {
      std::optional<PieceBox> entry_box = PieceBox::of(e);
      if (entry_box && PieceBox::apart(*held_box, *entry_box)) continue;
    }
    if (!e.arc && e.a == e.b) continue;
    Carrier<Kernel> c = e.carrier();
    std::optional<FT> depth;
    if (margins && (h.circle || c.circle)) depth = -carrier_gap<Kernel>(h, c);
    std::vector<Point> xs;
    if (h.circle || c.circle) {  // (two lines: one intersection, cheap; or parallel, below)
      for (const Point* q : {&held.a, &held.b})
        if (xs.empty() && lies_on(c, *q)) xs = intersections_through(h, c, *q);
      for (const Point* q : {&e.a, &e.b})
        if (xs.empty() && lies_on(h, *q)) xs = intersections_through(h, c, *q);
    }
    std::optional<std::vector<Point>> at_end;
    if (!h.circle && !c.circle) at_end = line_crossing_at_an_end(held, e, h, c);
    if (at_end)
      xs = *at_end;
    else if (xs.empty())
      xs = carrier_intersections<Kernel>(h, c);
    if (!h.circle && !c.circle && xs.empty()) {
      // Parallel lines never cross; the near miss is their distance. Collinear ones are apart
      // along the line, or overlap (or touch): the knife edge of crossing, a miss of 0.
      FT length = exact_root(h.direction.squared_length());
      FT across = CGAL::determinant(h.direction, c.point - h.point);
      FT gap = CGAL::abs(across) / length;
      if (CGAL::sign(across) == CGAL::ZERO) {
        Vector along = held.b - held.a;  // (the carrier's direction may have another length)
        FT ta = (e.a - held.a) * along, tb = (e.b - held.a) * along, l2 = along.squared_length();
        const FT& lo = CGAL::compare(ta, tb) == CGAL::SMALLER ? ta : tb;
        const FT& hi = CGAL::compare(ta, tb) == CGAL::SMALLER ? tb : ta;
        if (CGAL::compare(lo, l2) == CGAL::LARGER)
          gap = (lo - l2) / exact_root(l2);  // the entry piece lies beyond the held piece's end
        else if (CGAL::sign(hi) == CGAL::NEGATIVE)
          gap = -hi / exact_root(l2);  // before its start
        else
          gap = FT(0), out.overlap = true;
      }
      if (!out.near_miss || approx_less(*out.near_miss, -gap)) out.near_miss = -gap;
    }
    for (const Point& p : xs) {
      OnPiece on_held = locate(held, p, margins), on_entry = locate(e, p, margins);
      bool on = on_held.on && on_entry.on;
      if (!margins) {  // the same crossing, without its slack and the near misses
        if (!on || (best && later(held, on_held, *best) != CGAL::NEGATIVE)) continue;
        best = on_held, out.point = p, out.entry_piece = static_cast<int>(i);
        continue;
      }
      // The margin: the least slack (off a piece, the violated one; off both, the worse).
      FT slack = approx_less(on_entry.slack, on_held.slack) ? on_entry.slack : on_held.slack;
      if (on && depth && approx_less(*depth, slack)) slack = *depth;
      if (!on) {
        if (!out.near_miss || approx_less(*out.near_miss, slack)) out.near_miss = slack;
        continue;
      }
      if (best && later(held, on_held, *best) != CGAL::NEGATIVE) continue;
      best = on_held, out.point = p, out.entry_piece = static_cast<int>(i), out.slack = slack;
    }
  }
  return out;
}

}  // namespace cutcom::ref

// fast: collision detection CDON (TRC-CD-*): a block's entry against the held-back output and the
// cut there. Geometry in bottleneck.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "compensation.hpp"

namespace cutcom::fast {

bool Compensation::entry_corner(const BlockCopy& m, const BlockCopy& before, Entry& en) {
  // A word at a time: m's element is often made just now (element_of) by 8-byte stores, which
  // the 16-byte loads of a plain copy would wait for.
  copy_by_words(en.element, element_of(m));
  en.radius = 0, en.lead = Entry::Lead::kNone;  // `en` is reused from block to block
  en.before = &before;
  const Element& next = en.element;
  double sr = s * r;
  if (next.arc) {
    en.radius = exactly_inside(m, next, next.equidistant_radius(sr));  // TRC-ARC-EQ-1's decision
    if (!(en.radius > 0)) return decide("TRC-CD-2", m.line, "collapsed", en.radius), false;
  }
  const Vec2 normal_start = Element::offset(next.start, next.start_tangent(), sr);
  en.normal_start = normal_start;
  en.normal_end = Element::offset(next.end, next.end_tangent(), sr);
  en.before_element = element_of(before);  // made a block ago: a plain copy
  const Element& prev = en.before_element;
  double prev_radius = prev.arc ? exactly_inside(before, prev, prev.equidistant_radius(sr)) : 0;
  en.before_radius = prev_radius;
  en.vertex = prev.end;
  en.own_start = normal_start;  // not read back from en: its two 8-byte stores do not forward to a 16-byte load
  Corner c = classify_corner(prev.end_tangent(), next.start_tangent(), s);
  decide_kind_exactly(before, m, c);
  if (prev.arc && !(prev_radius > 0)) {
    decide("TRC-CD-2", m.line, "after-collapse", prev_radius);
    c.kind = Corner::Kind::kTangent;
  } else {
    static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
    decide("TRC-CD-2", m.line, kKind[static_cast<int>(c.kind)], c.sine);
  }
  en.corner = c;
  en.extended = c.kind == Corner::Kind::kOuter && !outer_corner_circle(m.line, m.g451, c);
  return true;
}

bool Compensation::entry_pieces(const BlockCopy& m, Entry& en) {
  const Element& next = en.element;
  const Element& prev = en.before_element;
  const double prev_radius = en.before_radius, sr = s * r;
  const Corner& c = en.corner;
  const Vec2 end = en.normal_end;
  auto equidistant_from = [&](Vec2 from, bool full) {
    return next.arc ? PathPiece::circle(from, end, next.centre, en.radius, next.sense, full)
                    : PathPiece::segment(from, end);
  };
  en.count = 0;
  Vec2 prev_end = Element::offset(prev.end, prev.end_tangent(), sr);
  if (en.extended) {
    // G451 (TRC-G451-1, TRC-ARC-CORNER-1): both equidistants extended to their intersection;
    // none found (circles) is the circle (TRC-ARC-CORNER-2).
    Vec2 x;
    bool found = true;
    if (!prev.arc && !next.arc)
      x = Element::offset(prev.end, prev.unit, sr) - corner_trim(c, s, r) * prev.unit;
    else {
      Carrier u = carrier_of(prev, prev_radius), v = carrier_of(next, en.radius);
      found = intersection_memo.intersection(u, v, prev.end, next.start_tangent(), r, x);
      // The carriers may just touch: the margin is their gap (a knife edge at 0).
      if (trace.keeps_decisions())  // the gap is only the trace's margin
        decide("TRC-CD-2", m.line, found ? "g451-meets" : "g451-misses", corner_gap(u, v, r));
    }
    if (found) {
      en.own_start = x;
      en.lead = Entry::Lead::kExtension;
      en.pieces[en.count++] = prev.arc ? PathPiece::circle(prev_end, x, prev.centre, prev_radius, prev.sense)
                                       : PathPiece::segment(prev_end, x);
      en.pieces[en.count++] = equidistant_from(x, false);
      return true;
    }
  }
  if (c.kind == Corner::Kind::kOuter || c.kind == Corner::Kind::kReversal) {
    en.pieces[en.count++] = PathPiece::circle(prev_end, en.normal_start, prev.end, r, -s);
    en.lead = Entry::Lead::kCircle;
  }
  if (c.kind != Corner::Kind::kInner) {
    en.pieces[en.count++] = equidistant_from(en.normal_start, next.full);
    return true;
  }
  Carrier u = carrier_of(prev, prev_radius), v = carrier_of(next, en.radius);
  Vec2 x;
  if (!intersection_memo.intersection(u, v, prev.end, next.start_tangent(), r, x)) {
    decide("TRC-CD-2", m.line, "no-entry",
           u.circle || v.circle ? carrier_gap(u, v) : -std::numeric_limits<double>::infinity());
    return false;
  }
  double left = extent_of(next, en.radius, x).left;
  // With circles the entry also hinges on the carriers meeting at all: the nearer threshold.
  if (trace.keeps_decisions()) {  // the gap is only the trace's margin
    double margin = left >= 0 && (u.circle || v.circle) ? std::min(left, std::fabs(corner_gap(u, v, r))) : left;
    decide("TRC-CD-2", m.line, left < 0 ? "no-entry" : "entry", margin);
  }
  if (left < 0) return false;
  en.own_start = x;
  en.pieces[en.count++] = equidistant_from(x, false);
  return true;
}

// Every piece entry_pieces builds lies in the transition circle's box, in the box of m's
// equidistant from its normal start, or, after an inner corner, from the intersection x. In exact
// arithmetic x lies after the normal start (two lines: r tan(phi/2) >= 0 along m; a circle before
// a line: the root nearer the corner), but its rounding grows where the carriers cross at a small
// angle. So the box takes a circle's whole circle, and before a line the predecessor's circle
// (x lies on it to a few ulps) or, after a line, m's segment padded by x's rounding: 64 eps size
// / sine (intersection_error) with room to spare, where the sine is 2^-10 or more. A G451
// extension can reach far: no box then.
bool Compensation::entry_bound(const Entry& en, PieceBox& box) const {
  const Corner& c = en.corner;
  if (en.extended) return false;
  const Element& next = en.element;
  const bool inner = c.kind == Corner::Kind::kInner;
  PieceBox b = !next.arc ? PieceBox::of(PathPiece::segment(en.normal_start, en.normal_end))
               : inner   ? PieceBox::circle(next.centre, en.radius)
                         : PieceBox::of(PathPiece::circle(en.normal_start, en.normal_end, next.centre, en.radius,
                                                          next.sense, next.full));
  if (c.kind == Corner::Kind::kOuter || c.kind == Corner::Kind::kReversal)
    b = PieceBox::join(b, PieceBox::circle(en.vertex, r));
  double slide = 0;  // how far x may slide along two lines by rounding
  if (inner && !next.arc) {
    if (en.before_element.arc) {
      b = PieceBox::join(b, PieceBox::circle(en.before_element.centre, en.before_radius));
    } else {
      if (std::fabs(c.sine) < 0x1p-10) return false;
      // The carriers' points are the lines' offset starts: the predecessor's may lie far back.
      const Vec2 from = en.before_element.start;
      double size = std::fabs(from.a) + std::fabs(from.b) + r;
      // One by one, in this order: a loop over the four was vectorized into a 16-byte load of
      // two 8-byte stores, which the CPU cannot forward (a third of this function's samples).
      size += 2 * std::fabs(b.lo_a), size += 2 * std::fabs(b.lo_b);
      size += 2 * std::fabs(b.hi_a), size += 2 * std::fabs(b.hi_b);
      slide = 256 * std::numeric_limits<double>::epsilon() * size / std::fabs(c.sine);
    }
  }
  PieceBox sized = PieceBox::sized(b.lo_a, b.lo_b, b.hi_a, b.hi_b);
  double pad = std::max(1e-9 * (1 + sized.size), slide);
  box = PieceBox::sized(b.lo_a - pad, b.lo_b - pad, b.hi_a + pad, b.hi_b + pad);
  return true;
}

PathPiece Compensation::piece_of(const HeldRecord& rec) const {
  const PathElement& e = rec.element;
  Vec2 a = ab(e.start), b = ab(e.end);
  if (e.type == ElementType::kLine) return PathPiece::segment(a, b);
  return PathPiece::circle(a, b, ab(e.center), rec.radius, e.ccw ? 1 : -1, a.a == b.a && a.b == b.b);
}

// PieceBox::of(piece_of(rec)), computed once per record and plane.
const PieceBox& Compensation::box_of(const HeldRecord& rec) const {
  if (rec.boxed && rec.box_axes.abscissa == axes.abscissa && rec.box_axes.ordinate == axes.ordinate) return rec.box;
  rec.box = PieceBox::of(piece_of(rec));
  rec.boxed = true, rec.box_axes = axes;
  return rec.box;
}

PathPiece Compensation::open_piece() const {
  Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
  if (!open_el.arc) return PathPiece::segment(open_start, end);
  // A full circle is whole when it was opened at its normal start (as ref's exact equality).
  return PathPiece::circle(open_start, end, open_el.centre, open_radius, open_el.sense,
                           open_el.full && open_at_normal_start);
}

bool Compensation::is_candidate(const HeldRecord& rec) {
  return rec.is_element &&
         (rec.element.origin.kind == OriginKind::kOffset || rec.element.origin.kind == OriginKind::kTransitionCircle);
}

bool Compensation::bottleneck(const BlockCopy& m, const BlockCopy& before) {
  if (r == 0) return false;  // no width: nothing to collide
  int lo = m.seq - md.cutcom_maxnum_check_blocks, hi = m.seq - 2;
  Entry& entry = entry_scratch;
  enum class Built { kNothing, kCorner, kEntry, kNoEntry } built = Built::kNothing;
  double near = -std::numeric_limits<double>::infinity();  // the largest near miss
  bool overlap = false;                                    // collinear pieces overlap (a miss of 0)
  // A G451 lead is the predecessor's equidistant: m-2's held element ends on it, at their common
  // corner, and is not compared with it (in the look-ahead m-1 was passed over: no such corner).
  const bool margins = trace.keeps_decisions();
  PieceBox entry_box{};  // without margins: the bound, then the box of the pieces once built
  // Without margins the corner comes first and, where entry_bound can tell, a box around every
  // piece the entry may have: held pieces apart from it are passed over without building the
  // entry, which most blocks then never need.
  bool bounded = false;
  auto build = [&] {
    if (built == Built::kNothing && !entry_corner(m, before, entry)) return void(built = Built::kNoEntry);
    built = entry_pieces(m, entry) ? Built::kEntry : Built::kNoEntry;
    if (built == Built::kEntry && !margins) entry_box = PieceBox::around(entry.pieces, entry.count);
  };
  auto try_piece = [&](const PathPiece& held_piece, int seq, PieceCrossing& c) {
    if (built == Built::kNothing || built == Built::kCorner) build();
    if (built == Built::kNoEntry) return false;
    bool skip_lead = entry.lead == Entry::Lead::kExtension && seq == hi && !looking;
    c = piece_crossing(held_piece, entry.pieces, entry.count, skip_lead ? 1 : 0, margins);
    near = std::max(near, c.near_miss);
    overlap = overlap || c.overlap;
    return c.entry_piece >= 0;
  };
  PieceCrossing c;
  for (std::size_t i = 0; i < held.size(); ++i) {
    const HeldRecord& rec = held[i];
    if (!is_candidate(rec) || rec.seq < lo || rec.seq > hi) continue;
    if (built == Built::kNothing && !margins) {
      if (!entry_corner(m, before, entry)) return false;
      built = Built::kCorner, bounded = entry_bound(entry, entry_box);
    }
    // Apart from the bound is apart from every piece in it (its pad is no smaller).
    if (built == Built::kCorner && bounded && PieceBox::apart(box_of(rec), entry_box)) continue;
    if (built == Built::kNothing || built == Built::kCorner) build();
    if (built == Built::kNoEntry) return false;
    // A held piece plainly apart from the whole entry: piece_crossing would pass over each of its
    // pieces (the same path: PROP-TRACE-1), so the piece is not even built.
    if (!margins && PieceBox::apart(box_of(rec), entry_box)) continue;
    if (try_piece(piece_of(rec), rec.seq, c)) return cut(m, entry, static_cast<int>(i), c, near), true;
  }
  if (looking && open->seq >= lo && open->seq <= hi && try_piece(open_piece(), open->seq, c))
    return cut(m, entry, -1, c, near), true;
  // A miss of exactly 0 is an overlap of collinear pieces; a point at 0 would have been on both.
  if (built == Built::kEntry) decide("TRC-CD-3", m.line, near == 0 && overlap ? "overlap" : "none", near);
  return false;
}

void Compensation::cut(const BlockCopy& m, const Entry& en, int record, const PieceCrossing& c, double near) {
  const Vec2 x = c.point;
  double margin = std::min(c.slack, -near);  // lowered to a nearer miss before it
  decide("TRC-CD-3", m.line, "cut", margin);
  if (!cut_at(record, x, c.along, BlockPlace::of(m))) return;
  continue_entry(m, en, c.entry_piece, x);
}

bool Compensation::cut_at(int record, Vec2 x, double along, const BlockPlace& at) {
  // A held record's owner: the block, and for a SAR block which of its parts (its lead and its
  // element are owners of their own, as they are blocks of their own in ref).
  auto owner_of = [](int block, SarMove part) { return block * 8 + static_cast<int>(part); };
  auto owner = [&](const HeldRecord& k) { return owner_of(k.owner_block, k.owner_sar); };
  int last_run = -1;  // the last owner run again from held records
  if (record >= 0) {
    const HeldRecord crossed = held[static_cast<std::size_t>(record)];
    const PathPoint end = xyz(x, h(crossed.element.end));
    // Cut at (or, rounded, next to) its start: nothing is left of it; an arc from a point to
    // itself would read as a full circle.
    double scale = std::max({1.0, std::fabs(x.a), std::fabs(x.b)});
    bool vanishes = along <= 64 * std::numeric_limits<double>::epsilon() * scale;
    const std::vector<HeldRecord>& dropped = held.cut(static_cast<std::size_t>(record), end, vanishes);
    const int open_owner = owner_of(open->block, open->sar);
    bool rest = open_owner == owner(crossed);  // its equidistant was still open
    for (const HeldRecord& k : dropped) rest = rest || owner(k) == owner(crossed);
    if (rest) infeed_of(crossed, end, xyz(x, h(crossed.owner_end)));
    for (std::size_t i = 0; i < dropped.size(); ++i) {
      const HeldRecord& k = dropped[i];
      if (owner(k) == owner(crossed)) continue;
      if (owner(k) != last_run) {
        if (last_run >= 0) infeed_of(dropped[i - 1], x);
        decide("TRC-LOOK-3", k.owner_line, "skipped");
        last_run = owner(k);
      }
      if (!k.is_element) {
        HeldRecord a = k;
        a.action.at = xyz(x, h(k.owner_start));
        held.hold(a);
      }
    }
    if (last_run >= 0) infeed_of(dropped.back(), x);
    if (open_owner != owner(crossed) && open_owner != last_run) skip_at(*open, x);
  } else {
    looking = false;
    if (!close_open(x, at, Placed::kOnPiece)) return false;
  }
  for (BlockCopy& k : skipped) skip_at(k, x);
  skipped.clear();
  for (int i = 0; i < dummy_count; ++i) skip_at(dummies[static_cast<std::size_t>(i)], x);
  dummy_count = 0;
  looking = false;
  kont_first = false;
  return true;
}

void Compensation::continue_entry(const BlockCopy& m, const Entry& en, int entry_piece, Vec2 x) {
  bool on_lead = en.lead != Entry::Lead::kNone && entry_piece == 0 && !(x.a == en.own_start.a && x.b == en.own_start.b);
  if (!on_lead) {  // on m's own piece, from its start
    bool normal = en.own_start.a == en.normal_start.a && en.own_start.b == en.normal_start.b;
    return open_element(m, en.element, x, en.radius, Placed::kOnPiece, normal ? nullptr : &en.own_start);
  }
  double hv = h(m.start);
  BlockCopy owner = m;
  // PATH-ORIGIN-1: the predecessor's line, number, SAR movement, insert.
  Origin named = origin(*en.before, OriginKind::kOffset);
  if (en.lead == Entry::Lead::kCircle) {
    named.kind = OriginKind::kTransitionCircle, named.next_line = m.line, named.next_block = m.number;
    named.next_insert = m.insert;
    corner_circle(owner, xyz(x, hv), xyz(en.normal_start, hv), xyz(en.vertex, hv), s < 0, named);
    return open_element(owner, en.element, en.normal_start, en.radius, Placed::kNormal);
  }
  // The rest of the predecessor's extended equidistant, at m's applicate, named after it.
  named.kind = OriginKind::kOffset;
  const Element& p = en.before_element;
  if (p.arc)
    arc(owner, xyz(x, hv), xyz(en.own_start, hv), xyz(p.centre, hv), p.sense > 0, named);
  else
    line(owner, xyz(x, hv), xyz(en.own_start, hv), named, owner.rapid);
  open_element(owner, en.element, en.own_start, en.radius);
}

bool Compensation::search_further_back(BlockCopy& d, const EdgeCurve& curve) {
  PathPiece aux = curve_piece(curve);
  int lo = d.seq - md.cutcom_maxnum_check_blocks, hi = d.seq - 2;
  bool compared = false;
  double near = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < held.size(); ++i) {
    const HeldRecord& rec = held[i];
    if (!is_candidate(rec) || rec.seq < lo || rec.seq > hi) continue;
    compared = true;
    PieceCrossing c = piece_crossing(piece_of(rec), &aux, 1, 0, trace.keeps_decisions());
    near = std::max(near, c.near_miss);
    if (c.entry_piece < 0) continue;
    decide("TRC-CD-5", d.line, "earlier-block", std::min(c.slack, -near));
    if (!cut_at(static_cast<int>(i), c.point, c.along, BlockPlace::of(d))) return true;
    retraction_line(d, c.point);
    return true;
  }
  if (compared) decide("TRC-CD-5", d.line, "open-element", near);
  return false;
}

PathPiece Compensation::curve_piece(const EdgeCurve& curve) {
  const Carrier& k = curve.carrier;
  if (k.circle) {
    Vec2 a{k.point.a + k.radius, k.point.b};
    return PathPiece::circle(a, a, k.point, k.radius, 1, true);
  }
  if (curve.bound == EdgeCurve::Bound::kSegment) return PathPiece::segment(k.point, k.point + k.direction);
  return PathPiece::segment(k.point, k.point + (1e13 / norm(k.direction)) * k.direction);
}

}  // namespace cutcom::fast

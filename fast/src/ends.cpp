// fast: the ends of compensation - approach and retraction: NORM, KONT travelling around the
// start or end point (TRC-KONT-*), G460/G461/G462 (TRC-EDGE-*) and the end of the program.
#include <cmath>
#include <limits>

#include "compensation.hpp"
#include "exact_tangent.hpp"

namespace cutcom::fast {

void Compensation::approach(const Block& b) {
  if (b.state.side == Side::kOff) {
    // TRC-SEL-8: deselected before any traversing block: no selection takes place.
    decide("TRC-SEL-8", selection.line, "deselected-before-contour");
    line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
    run_held_back_uncompensated();
    phase = Phase::kOff;
    return compensation_off(b);
  }
  if (!still_compensable(b)) return;
  if (anew(b)) {
    // TRC-SIDE-3: selected anew before any contour block: the first selection had no contour.
    decide("TRC-SIDE-3", b.words.line, "before-contour");
    line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
    run_held_back_uncompensated();
    phase = Phase::kOff;
    return compensation_off(b);
  }
  if (!moves_in_plane(b)) return hold_back(b);  // TRC-DUMMY-3: no in-plane displacement
  if (!edge.in_force(b.state))                  // TRC-RADIUS-3: the approach has one radius
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change in the first contour block");
  prev_slot ^= 1;
  const BlockCopy& first = fill_slot(prev_slot, b);
  has_prev = true;
  Element e = element_of(first);
  double radius = 0;
  if (!equidistant_exists(b, first, e, radius)) return raise(10751, b.words);
  if (selection.kont) {
    // TRC-KONT-1: the corner of the approach line (start -> S) with the first block.
    Kont k{e.start, ab(selection.start), e.start - ab(selection.start), e.start_tangent(), std::nullopt, std::nullopt};
    if (!selection_from_tool && selection.exact) k.exact_sign = exact_side(first, false, selection.delta, -1);
    if (!selection_from_tool && selection.exact) k.exact_room = exact_room_sign(selection.delta);
    if (kont_behind(selection, k, k.d2, 10755)) return approach_around(first, e, radius, k);
    if (trace.stopped()) return;
  }
  // TRC-APPR-NORM-1: straight to the normal point of the first contour element's start.
  Vec2 q = Element::offset(e.start, e.start_tangent(), s * r);
  PathPoint to = xyz(q, h(selection.end));
  double length = std::sqrt((to.x - selection.start.x) * (to.x - selection.start.x) +
                            (to.y - selection.start.y) * (to.y - selection.start.y) +
                            (to.z - selection.start.z) * (to.z - selection.start.z));
  decide("TRC-APPR-NORM-1", selection.line, length == 0 ? "zero-length" : "line", length);
  // Output waits until the first element's end is known (TRC-EDGE-* may replace it).
  approach_pending = true;
  approach_to = to;
  for (int i = 0; i < dummy_count; ++i)
    approach_dummies[static_cast<std::size_t>(i)] = dummies[static_cast<std::size_t>(i)];
  approach_dummy_count = dummy_count;
  dummy_count = 0;
  open_element(first, e, q, radius, Placed::kNormal);
  phase = Phase::kActive;
}

void Compensation::flush_approach() {
  if (!approach_pending) return;
  approach_pending = false;
  line(selection, selection.start, approach_to, OriginKind::kApproach, selection.rapid);
  for (int i = 0; i < approach_dummy_count; ++i) {
    BlockCopy& d = approach_dummies[static_cast<std::size_t>(i)];
    line(d, xyz(ab(approach_to), h(d.start)), xyz(ab(approach_to), h(d.end)), OriginKind::kInfeed, d.rapid);
  }
  approach_dummy_count = 0;
}

std::optional<int> Compensation::exact_side(const BlockCopy& block, bool at_end, const std::array<Int128, 3>& u,
                                            int k) const {
  std::optional<IntVec> t = exact_tangent(block, axes, at_end);  // a line's displacement, a circle's tangent
  Int128 ua = u[static_cast<std::size_t>(axes.abscissa)], ub = u[static_cast<std::size_t>(axes.ordinate)];
  if (t && in_exact_range(ua) && in_exact_range(ub)) return k * sign_of_difference(t->a, ub, t->b, ua);
  // A CR= circle's tangent carries a root (once per approach or retraction: GMP's integers).
  std::optional<int> sign = root_tangents.side(block, at_end, axes, u);
  if (!sign) return std::nullopt;
  return k * *sign;
}

bool Compensation::kont_side(const BlockCopy& at_block, Vec2 vertex, Vec2 point, Vec2 tangent,
                             std::optional<int> exact_sign) {
  double cr = cross(tangent, point - vertex);
  int sign = exact_sign ? *exact_sign : (cr > 0) - (cr < 0);
  double margin = sign == 0 ? 0.0 : s * cr / norm(tangent);
  bool behind = s * sign < 0;
  decide("TRC-KONT-1", at_block.line, behind ? "behind" : "in-front", margin);
  return behind;
}

bool Compensation::kont_behind(const BlockCopy& at_block, const Kont& k, Vec2 tangent, int alarm) {
  if (!kont_side(at_block, k.vertex, k.point, tangent, k.exact_sign)) return false;
  Vec2 off = k.point - k.vertex;
  double distance = norm(off);
  // Between programmed points the distance is decided exactly (a start exactly r from the
  // contour's start has room); the margin keeps the sign decided.
  int room = k.exact_room ? *k.exact_room : (distance > r) - (distance < r);
  bool inside = room < 0;
  double gap = std::max(std::fabs(distance - r), std::numeric_limits<double>::denorm_min());
  double margin = room == 0 ? 0.0 : room > 0 ? gap : -gap;
  decide("TRC-KONT-2", at_block.line, inside ? "inside" : "room", margin);
  if (inside) raise(alarm, at_block, "TRC-KONT-2");
  return !inside;
}

bool Compensation::kont_intersection(const BlockCopy& at_block, const Kont& k, const Element& e, double e_radius,
                                     Vec2 on_line, Vec2 d, Vec2& x) {
  Vec2 u1 = (1.0 / norm(k.d1)) * k.d1;
  if (!e.arc) {
    Corner c = classify_corner(u1, (1.0 / norm(k.d2)) * k.d2, s);
    x = Element::offset(k.vertex, u1, s * r) - corner_trim(c, s, r) * u1;
    return true;
  }
  Carrier line_carrier;
  line_carrier.point = on_line, line_carrier.direction = (1.0 / norm(d)) * d;
  Carrier cu = carrier_of(e, e_radius);
  bool found = nearest_intersection(cu, line_carrier, k.vertex, k.d2, x);
  decide("TRC-ARC-CORNER-1", at_block.line, found ? "intersection" : "none", carrier_gap(cu, line_carrier));
  return found;
}

bool Compensation::kont_circle(const BlockCopy& at_block, const Kont& k) {
  Corner c = classify_corner((1.0 / norm(k.d1)) * k.d1, (1.0 / norm(k.d2)) * k.d2, s);
  return outer_corner_circle(at_block.line, at_block.g451, c);
}

void Compensation::approach_around(const BlockCopy& first, const Element& e, double radius, const Kont& k) {
  kont_first = true;
  Vec2 a = Element::offset(k.vertex, (1.0 / norm(k.d1)) * k.d1, s * r);
  bool circle = kont_circle(selection, k);
  Vec2 x;
  bool found = !circle && kont_intersection(selection, k, e, radius, a, k.d1, x);
  double hv = h(selection.end);
  if (!found) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
    decide("TRC-KONT-3", selection.line, "circle");
    line(selection, selection.start, xyz(a, hv), OriginKind::kApproach, selection.rapid);
    run_held_back(a);
    Vec2 q = Element::offset(k.vertex, e.start_tangent(), s * r);
    Origin corner = origin(selection, OriginKind::kTransitionCircle);
    corner.next_line = first.line, corner.next_block = first.number, corner.next_insert = first.insert;
    open_element(first, e, q, radius, Placed::kNormal);
    double h1 = h(first.start);  // after the held-back blocks
    if (r > 0) corner_circle(*open, xyz(a, h1), xyz(q, h1), xyz(k.vertex, h1), s < 0, corner);  // TRC-G450-2
  } else {                                                                                      // TRC-KONT-4
    decide("TRC-KONT-4", selection.line, "intersection");
    line(selection, selection.start, xyz(x, hv), OriginKind::kApproach, selection.rapid);
    run_held_back(x);
    open_element(first, e, x, radius);
  }
  phase = Phase::kActive;
}

void Compensation::retract_edge(const Block& b) {
  reject_kontc_kontt(b, true);  // TRC-UNSUP-1
  BlockCopy d = copy_of(b);
  const BlockCopy* last_block = nullptr;
  for (const BlockCopy& k : skipped)
    if (k.moves) last_block = &k;
  Element last = element_of(*last_block);
  decide("TRC-DESEL-1", d.line, "deselected");
  if (d.kont) {  // TRC-KONT-1/2, then TRC-EDGE-6
    Vec2 p = ab(d.end);
    Kont k{last.end, p, last.end_tangent(), p - last.end, std::nullopt, std::nullopt};
    if (d.exact) k.exact_sign = exact_side(*last_block, true, d.delta, 1);
    if (d.exact) k.exact_room = exact_room_sign(d.delta);
    if (kont_behind(d, k, k.d1, 10756)) return retract_edge_around(d, *last_block, k);
    if (trace.stopped()) return;
  }
  decide("TRC-EDGE-1", d.line, g_code(d.edge_strategy));
  Vec2 normal_end = Element::offset(last.end, last.end_tangent(), s * r);
  EdgeCurve curve = edge_curve(d.edge_strategy, r, last.end, normal_end, last.end_tangent(), ab(d.end), false);
  Vec2 hit;
  double margin = 0;
  PieceStart piece{open_start, open_from};
  bool found = edge_hit(curve, open_el, open_radius, s * r, &piece, false, hit, margin);
  decide("TRC-EDGE-5", d.line, found ? "hit" : "none", margin);
  if (d.cdon && search_further_back(d, curve)) return;
  if (!found) return raise(10751, d);
  looking = false;
  if (!close_open(hit, BlockPlace::of(d), Placed::kOnPiece)) return;
  for (BlockCopy& k : skipped) skip_at(k, hit);
  skipped.clear();
  retraction_line(d, hit);
}

void Compensation::retract_edge_around(BlockCopy& d, const BlockCopy& last_block, const Kont& k) {
  if (!kont_circle(d, k))
    throw UnsupportedError(  // TRC-EDGE-7 (planned)
        d.line, "KONT retraction from behind by intersection (G451) after a too-short last block");
  Vec2 rp = Element::offset(k.vertex, (1.0 / norm(k.d2)) * k.d2, s * r);
  EdgeCurve circle;
  circle.carrier.circle = true, circle.carrier.point = k.vertex, circle.carrier.radius = r;
  Vec2 x;
  double margin = 0;
  PieceStart piece{open_start, open_from};
  bool on_circle = edge_hit(circle, open_el, open_radius, s * r, &piece, false, x, margin);
  decide("TRC-EDGE-6", d.line, on_circle ? "circle" : "line", margin);
  if (!on_circle) {
    EdgeCurve line;
    line.bound = EdgeCurve::Bound::kSegment, line.carrier.point = rp, line.carrier.direction = k.point - rp;
    bool found = edge_hit(line, open_el, open_radius, s * r, &piece, false, x, margin);
    decide("TRC-EDGE-5", d.line, found ? "hit" : "none", margin);
    if (!found) return raise(10751, d);
  }
  looking = false;
  if (!close_open(x, BlockPlace::of(d), Placed::kOnPiece)) return;
  for (BlockCopy& k2 : skipped) skip_at(k2, x);
  skipped.clear();
  if (!on_circle) return retraction_line(d, x);
  Origin corner = origin(last_block, OriginKind::kTransitionCircle);
  corner.next_line = d.line, corner.next_block = d.number, corner.next_insert = d.insert;
  double hv = h(d.start);
  corner_circle(d, xyz(x, hv), xyz(rp, hv), xyz(k.vertex, hv), s < 0, corner);
  retraction_line(d, rp);
}

void Compensation::approach_edge(const Candidate& c) {
  decide("TRC-EDGE-1", selection.line, g_code(selection.edge_strategy));
  const Element& first = open_el;
  EdgeCurve curve = edge_curve(selection.edge_strategy, r, first.start, open_start, -1.0 * first.start_tangent(),
                               ab(selection.start), true);
  Vec2 hit;
  double margin = 0;
  bool found = edge_hit(curve, *c.element, c.radius, s * r, nullptr, true, hit, margin);
  decide("TRC-EDGE-5", selection.line, found ? "hit" : "none", margin);
  if (!found) return raise(10751, *c.block);
  approach_pending = false;
  line(selection, selection.start, xyz(hit, h(selection.end)), OriginKind::kApproach, selection.rapid);
  for (int i = 0; i < approach_dummy_count; ++i) skip_at(approach_dummies[static_cast<std::size_t>(i)], hit);
  approach_dummy_count = 0;
  skip_at(*open, hit);
  for (int i = 0; i < dummy_count; ++i) skip_at(dummies[static_cast<std::size_t>(i)], hit);
  dummy_count = 0;
  for (BlockCopy& k : skipped) skip_at(k, hit);
  skipped.clear();
  looking = false;
  BlockCopy block = *c.block;
  Element element = *c.element;
  open_element(block, element, hit, c.radius, Placed::kOnPiece);
  // TRC-CD-6: with CDON the later blocks of the window are searched too.
  if (selection.cdon) approach_curve = curve, approach_until = selection.seq + md.cutcom_maxnum_check_blocks;
}

bool Compensation::approach_further_ahead(const Block& b, const BlockCopy& m) {
  if (m.seq > approach_until || !m.cdon) {
    approach_until = -1;
    return false;
  }
  Element e = element_of(m);
  double radius = 0;
  if (e.arc) {
    radius = exactly_inside(m, e, e.equidistant_radius(s * r));
    if (!(radius > 0)) return false;
  }
  Vec2 hit;
  double margin = 0;
  bool found = edge_hit(approach_curve, e, radius, s * r, nullptr, true, hit, margin);
  decide("TRC-CD-6", b.words.line, found ? "later-block" : "none", margin);
  if (!found) return false;
  for (std::size_t i = 0; i < held.size(); ++i) {
    if (!held[i].is_element || held[i].element.origin.kind != OriginKind::kApproach) continue;
    // Cut back to (or, rounded, next to) its start, nothing is left of the approach line
    // (PATH-ELEMENT-1; campaign 20261254, case 196623: the hit was the tool's start point).
    double along = norm(hit - ab(held[i].element.start));
    if (!cut_at(static_cast<int>(i), hit, along, BlockPlace::of(m))) return true;
    open_element(m, e, hit, radius, Placed::kOnPiece);
    return true;
  }
  return false;
}

void Compensation::deselect(const Block& b) {
  reject_kontc_kontt(b, true);  // TRC-UNSUP-1
  decide("TRC-DESEL-1", b.words.line, "deselected");
  BlockCopy last = copy_of(b);
  if (last.kont) {
    Vec2 p = ab(last.end);
    Kont k{open_el.end, p, open_el.end_tangent(), p - open_el.end, std::nullopt, std::nullopt};
    if (last.exact) k.exact_sign = exact_side(*open, true, last.delta, 1);
    if (last.exact) k.exact_room = exact_room_sign(last.delta);
    if (kont_behind(last, k, k.d1, 10756)) return retract_around(last, k);
    if (trace.stopped()) return;
  }
  Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
  if (!close_open(end, BlockPlace::of(last), Placed::kNormal)) return;
  run_held_back(end);
  retraction_line(last, end);
}

// TRC-DESEL-3: G40 without a plane axis ends the last contour block at its normal end point now;
// the block (and those after it without a plane axis) run there.
void Compensation::deselect_in_place(const Block& b) {
  decide("TRC-DESEL-3", b.words.line, "in-place");
  Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
  if (!close_open(end, BlockPlace::of(b.words), Placed::kNormal)) return;
  run_held_back(end);
  retract_from = end;
  phase = Phase::kRetracting;
  retraction_pending(b);
}

void Compensation::retraction_pending(const Block& b) {
  if (b.state.plane != plane) return raise(10757, b.words);  // TRC-PLANE-1
  BlockCopy c = copy_of(b);
  if (!b.programs_plane_axis()) {
    line(c, xyz(retract_from, h(c.start)), xyz(retract_from, h(c.end)), OriginKind::kRetraction, c.rapid);
    return;
  }
  if (b.state.side == Side::kOff) {
    if (b.is_arc()) return raise(10754, b.words);  // TRC-DESEL-2
    decide("TRC-DESEL-3", b.words.line, "retraction");
    return retraction_line(c, retract_from);
  }
  // Selected again: the approach starts where the tool is (as after a side change, TRC-SIDE-1).
  PathPoint tool = xyz(retract_from, h(c.start));
  bool tool_on_contour = r_units == 0;  // radius 0: the tool stands on the programmed point
  phase = Phase::kOff;
  compensation_off(b);
  if (phase == Phase::kApproach) {
    selection.start = tool, selection.scale_over_size = -1;
    selection_from_tool = !tool_on_contour;
  }
}

void Compensation::retraction_line(BlockCopy& last, Vec2 from_point) {
  PathPoint from = xyz(from_point, h(last.start));
  double length =
      std::sqrt((last.end.x - from.x) * (last.end.x - from.x) + (last.end.y - from.y) * (last.end.y - from.y) +
                (last.end.z - from.z) * (last.end.z - from.z));
  decide("TRC-RETR-NORM-1", last.line, length == 0 ? "zero-length" : "line", length);
  line(last, from, last.end, OriginKind::kRetraction, last.rapid);
  phase = Phase::kOff;
}

void Compensation::retract_around(BlockCopy& last, const Kont& k) {
  Vec2 rp = Element::offset(k.vertex, (1.0 / norm(k.d2)) * k.d2, s * r);
  bool circle = kont_circle(last, k);
  Vec2 x;
  bool found = !circle && kont_intersection(last, k, open_el, open_radius, rp, k.d2, x);
  if (!found) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
    decide("TRC-KONT-3", last.line, "circle");
    Vec2 from = Element::offset(k.vertex, open_el.end_tangent(), s * r);
    Origin corner = origin(*open, OriginKind::kTransitionCircle);
    corner.next_line = last.line, corner.next_block = last.number, corner.next_insert = last.insert;
    if (!close_open(from, BlockPlace::of(last), Placed::kNormal)) return;
    run_held_back(from);
    double hv = h(last.start);
    if (r > 0) corner_circle(last, xyz(from, hv), xyz(rp, hv), xyz(k.vertex, hv), s < 0, corner);  // TRC-G450-2
    return retraction_line(last, rp);
  }
  decide("TRC-KONT-4", last.line, "intersection");
  if (!close_open(x, BlockPlace::of(last))) return;
  run_held_back(x);
  retraction_line(last, x);
}

void Compensation::end_of_program() {
  if (looking) {  // the program ends before an intersection was found
    const BlockCopy& last = skipped.back();
    decide("TRC-LOOK-2", last.line, "none");
    return raise(10751, last);
  }
  if (phase == Phase::kApproach) {
    decide("TRC-END-1", selection.line, "no-contour");
    sink.notice({selection.line, "TRC-END-1", "compensation selected but no block with motion in the plane follows",
                 selection.source});
    line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
    run_held_back_uncompensated();
  } else if (phase == Phase::kActive) {
    decide("TRC-END-1", open->line, "active-at-end");
    sink.notice({open->line, "TRC-END-1", "program ends with compensation active: last block ends at its normal point",
                 open->source});
    Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
    if (!close_open(end, BlockPlace::of(*open), Placed::kNormal)) return;
    run_held_back(end);
  }
  phase = Phase::kOff;
}

}  // namespace cutcom::fast

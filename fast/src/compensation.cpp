// Stage 2 of fast, the compensation (compensation.hpp), one block at a time: selection, corners,
// the look-ahead over too-short blocks and the output into the collision window. Clause IDs name
// the spec rule each step implements; ref implements the same clauses independently in exact
// arithmetic (ref/src/compensation.cpp).
#include "compensation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "arc_check.hpp"
#include "exact_tangent.hpp"

namespace cutcom::fast {

namespace {
// How many roundings a tangent computed in double may turn by, at most: the magnitude of the
// block's coordinates over the length that fixes its direction (a line's length, a CR= circle's
// radius; a centred circle's radius or, shorter, its chord, across which ARC-CENTRE-1 projects
// the centre); infinite for length 0. A length is taken as its larger component (no root): that
// only makes the bound larger.
double scale_over_size(const BlockCopy& c, PlaneAxes a) {
  auto larger = [](Vec2 v) { return std::max(std::fabs(v.a), std::fabs(v.b)); };
  Vec2 s = ab_in(c.start, a), e = ab_in(c.end, a);
  double scale = std::max({larger(s), larger(e), std::fabs(c.cr)});
  if (!c.arc) return scale / larger(e - s);
  if (!c.has_centre) return scale / std::fabs(c.cr);
  Vec2 k = ab_in(c.centre, a);
  scale = std::max(scale, larger(k));
  double radius = larger(s - k), chord = larger(e - s);
  return scale / (chord > 0 ? std::min(chord, radius) : radius);
}
}  // namespace

void Compensation::compensation_off(const Block& b) {
  if (b.state.side != Side::kOff) {
    if (b.is_arc()) return raise(10753, b.words);  // TRC-SEL-2
    if (!b.programs_plane_axis()) {
      decide("TRC-SEL-4", b.words.line, "no-plane-axis");
    } else if (b.state.tool == 0) {
      return raise(10750, b.words);  // TRC-SEL-6
    } else if (b.state.edge == 0) {
      decide("TRC-SEL-5", b.words.line, "d0");
      if (!d0_noticed) sink.notice({b.words.line, "TRC-SEL-5", "G41/G42 with D0: no compensation", b.words.source});
      d0_noticed = true;
    } else if (!b.state.edge_defined) {
      return raise(17181, b.words);  // TRC-SEL-7
    } else {
      return select(b);
    }
  }
  BlockCopy& c = uncompensated;
  copy_into(c, b);
  if (!c.arc) return line(c, c.start, c.end, OriginKind::kProgrammed, c.rapid);
  // A programmed circle about its (corrected, ARC-CENTRE-1) centre.
  axes = plane_axes(b.state.plane);
  Element e = element_of(c);
  arc(c, c.start, c.end, xyz(e.centre, h(c.start)), c.sense > 0, origin(c, OriginKind::kProgrammed));
}

void Compensation::change_side(const Block& b) {
  bool again = b.state.side == side;             // TRC-SIDE-2: the same G41/G42 programmed again
  if (b.is_arc()) return raise(10753, b.words);  // TRC-SEL-2
  if (!b.programs_plane_axis()) {
    decide(again ? "TRC-SIDE-2" : "TRC-SIDE-1", b.words.line, "no-plane-axis");
    return hold_back(b);
  }
  decide(again ? "TRC-SIDE-2" : "TRC-SIDE-1", b.words.line, again ? "selected-again" : "side-change");
  Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
  if (!close_open(end, BlockPlace::of(b.words), Placed::kNormal)) return;
  run_held_back(end);
  PathPoint tool = xyz(end, h(copy_of(b).start));
  bool tool_on_contour = r_units == 0;  // radius 0: the tool stands on the programmed point
  select(b);
  selection.start = tool, selection.scale_over_size = -1;  // the approach starts where the tool is
  selection_from_tool = !tool_on_contour;
}

void Compensation::select(const Block& b) {
  reject_kontc_kontt(b, false);  // TRC-UNSUP-1
  // TRC-SEL-1; TRC-SEL-3: a single plane axis was completed by the reader (NC-POS-1).
  decide("TRC-SEL-1", b.words.line, "selected");
  plane = b.state.plane;
  axes = plane_axes(plane);
  side = b.state.side;
  selection_word = b.state.selection;
  edge = ActiveEdge::of(b.state);
  CompensationSide cs = compensation_side(b.state);  // TRC-RADIUS-2 (decided in core)
  decide(cs.decision, b.words.line);
  s = cs.s;
  r = cs.r.to_double();
  r_units = cs.r.units();
  copy_into(selection, b);
  selection_from_tool = false;
  has_prev = false;
  approach_until = -1;
  dummy_count = 0;
  phase = Phase::kApproach;
}

bool Compensation::still_compensable(const Block& b, bool* radius_changes) {
  if (b.state.side == Side::kOff) {
    if (b.is_arc() && b.programs_plane_axis()) {  // TRC-DESEL-2
      raise(10754, b.words);
      return false;
    }
    return true;
  }
  if (b.state.plane != plane) {  // TRC-PLANE-1
    raise(10757, b.words);
    return false;
  }
  if (anew(b)) return true;                               // TRC-SIDE-1/2, handled by the caller
  bool changes = reject_change_while_active(b, edge, s);  // TRC-UNSUP-1, TRC-RADIUS-3
  if (radius_changes) *radius_changes = changes;
  return true;
}

void Compensation::hold_back(const Block& b) {
  if (dummy_count == md.cutcom_maxnum_dummy_blocks) return raise(10762, b.words);
  copy_into(dummies[static_cast<std::size_t>(dummy_count++)], b);  // in place: no action strings made
}

void Compensation::run_held_back(Vec2 at) {
  for (int i = 0; i < dummy_count; ++i) {
    BlockCopy& d = dummies[static_cast<std::size_t>(i)];
    line(d, xyz(at, h(d.start)), xyz(at, h(d.end)), OriginKind::kInfeed, d.rapid);
  }
  dummy_count = 0;
}

void Compensation::run_held_back_uncompensated() {
  for (int i = 0; i < dummy_count; ++i) {
    BlockCopy& d = dummies[static_cast<std::size_t>(i)];
    line(d, d.start, d.end, OriginKind::kProgrammed, d.rapid);
  }
  dummy_count = 0;
}

bool Compensation::close_open(Vec2& end_point, const BlockPlace& alarm_at, Placed placed, const Candidate* candidate) {
  const Element& e = open_el;
  const bool at_normal_end = placed == Placed::kNormal;
  // A full circle from its normal start to its normal end turns a whole turn exactly and ends where
  // it starts, as in ref. Its two rounded rotations could add up to a hair more, which
  // PATH-ELEMENT-2 below would take for a whole turn and a rest (campaign 20261262, case 192296: a
  // helix stopped as unsupported); an ulp apart its end would read as a sliver or nearly a turn.
  const bool whole_turn = e.arc && e.full && open_at_normal_start && at_normal_end;
  double margin;
  double turn = 0;  // arcs: the angle the trimmed element turns
  if (!e.arc) {
    margin = dot(end_point - open_start, e.unit);
  } else if (whole_turn) {
    turn = sweep(e);
    margin = turn * open_radius;
  } else if (placed == Placed::kOnPiece) {
    // TRC-ARC-ELEMENT-1: on the piece by the search, its rotation from the start. Past the
    // piece's end in double it lies at one of its ends within rounding: the nearer one.
    constexpr double kTurn = 2 * std::numbers::pi;
    double room = sweep(e) - open_from;
    turn = signed_rotation(open_start - e.centre, end_point - e.centre, e.sense);
    if (turn < 0) turn += kTurn;
    if (turn > room) turn = kTurn - turn < turn - room ? 0.0 : room;
    margin = turn * open_radius;
  } else {
    turn = sweep(e) - open_from + signed_rotation(e.end - e.centre, end_point - e.centre, e.sense);
    margin = turn * open_radius;
  }
  std::string_view clause = e.arc ? "TRC-ARC-ELEMENT-1" : "TRC-ELEMENT-1";
  if (margin < 0) {
    decide(clause, open->line, "reverses", margin);
    // TRC-EDGE-1: the first element after the approach is too short for its neighbour.
    if (approach_pending && candidate) return approach_edge(*candidate), false;
    if (kont_first && candidate)
      throw UnsupportedError(  // TRC-EDGE-7 (planned)
          selection.line, "KONT approach from behind the contour before a too-short first block");
    raise(10751, alarm_at);
    return false;
  }
  decide(clause, open->line, margin == 0 ? "vanishes" : "fits", margin);
  flush_approach();
  kont_first = false;
  PathPoint from = xyz(open_start, h(open->start)), to = xyz(end_point, h(open->end));
  if (margin == 0) {
    // TRC-ELEMENT-1: nothing left along the block; what it moves besides (the applicate, or across
    // from one radius to the other after a blend, TRC-RADIUS-3) runs at the point: no gap.
    bool across = open_blended && (open_start.a != end_point.a || open_start.b != end_point.b);
    if (!across && h(open->start) == h(open->end)) {
      actions(*open, to);
      return true;
    }
    line(*open, across ? from : xyz(end_point, h(open->start)), to, across ? OriginKind::kOffset : OriginKind::kInfeed,
         open->rapid);
    return true;
  }
  if (!e.arc) {
    line(*open, from, to, OriginKind::kOffset, open->rapid);
  } else {
    // The whole turn's end is its start; the snapped end is where the next element starts too (no
    // gap of a rounding after the circle).
    if (whole_turn) to = xyz(open_start, h(open->end)), end_point = open_start;
    // PATH-ELEMENT-2: a circle that turns more than half a turn but whose end, rounded, lies just
    // past its start (within 1e-8 of the radius) would read as a sliver: it ends at its start.
    // Nor may it end where its direction from the centre is the start's within rounding: whether
    // it turns 0 or a whole turn could not be read from its points (PATH-ELEMENT-2).
    Vec2 u = open_start - e.centre, v = end_point - e.centre;
    double nu = norm(u);
    // "Just past" is within the error of the two points: 1e-8 of the radius for intersections of
    // nearly touching carriers, far less for normal points and well-conditioned intersections
    // (campaign 20261209, case 63322: a full circle opened 1.85e-7 mm before its normal start by an
    // intersection at sine 3.7e-4 was closed into a whole turn; ref's arc turns 1e-8 rad).
    double snap = 1e-8 * std::max(1.0, open_radius);
    double normal = 64 * std::numeric_limits<double>::epsilon() * (nu + std::fabs(e.centre.a) + std::fabs(e.centre.b));
    double start_error = open_at_normal_start ? normal : open_start_error >= 0 ? open_start_error : snap;
    double end_error = at_normal_end ? normal : closing_point_error >= 0 ? closing_point_error : snap;
    snap = std::min(snap, std::max(start_error, end_error));
    bool unreadable = turn_undetermined(u, v);
    // How the points read (the rotation from start to end) matters only where they lie that close.
    bool near = norm(end_point - open_start) <= snap;
    double reads = near ? signed_rotation(u, v, e.sense) : 0;
    bool just_past = near && reads > 0;
    if (turn > std::numbers::pi && (just_past || unreadable))
      to = xyz(open_start, h(open->end)), end_point = open_start;
    // And a circle that turns less than half a turn, its end a rounding from its start (an
    // equidistant cut between two intersections of touching carriers), whose points cannot be
    // read or read as nearly a whole turn: it is its chord, a line a rounding long.
    bool just_before = near && reads <= 0;
    if (turn < std::numbers::pi && (just_before || unreadable)) {
      line(*open, from, to, OriginKind::kOffset, open->rapid);
      return true;
    }
    // PATH-ELEMENT-2: more than a whole turn (a full circle opened before its start or closed
    // after its end) is the whole turn first, then the rest: an arc reads at most one turn.
    // Closed in the plane: a helix whose end the snap above put over its start is one whole turn
    // (campaign 20261274, case 870612: a full helix opened by a KONT intersection at r = 0).
    bool closed = end_point.a == open_start.a && end_point.b == open_start.b;
    if (turn > 2 * std::numbers::pi && !closed) {
      if (h(open->start) != h(open->end))
        throw UnsupportedError(open->line, "a helix that turns more than a whole turn after its corners");
      arc(*open, from, from, xyz(e.centre, h(open->start)), e.sense > 0, origin(*open, OriginKind::kOffset));
    }
    arc(*open, from, to, xyz(e.centre, h(open->start)), e.sense > 0, origin(*open, OriginKind::kOffset));
  }
  return true;
}

double Compensation::scale_over_size_now(const BlockCopy& c) const {
  c.scale_over_size = cutcom::fast::scale_over_size(c, axes), c.scale_axes = axes;
  return c.scale_over_size;
}

void Compensation::decide_kind_on_integers(const BlockCopy& first, const BlockCopy& second, Corner& c) const {
  // Lines and circles with a centre: the tangents are integer vectors (exact_tangent.hpp).
  int cross = 0, dot = 0;
  if (!corner_signs.signs(first, second, axes, cross, dot)) {
    // A CR= circle (its tangent carries a root) or a tangent beyond the 256-bit range: in GMP's
    // integers (root_tangent.hpp), where the double sine is too small to be sure of.
    std::optional<RootTangents::Signs> signs = root_tangents.corner(first, second, axes);
    if (!signs) return;
    cross = signs->cross, dot = signs->dot;
  }
  if (cross == 0) {
    c.kind = dot > 0 ? Corner::Kind::kTangent : Corner::Kind::kReversal;
    c.sine = 0;
    return;
  }
  c.kind = (cross > 0) == (s > 0) ? Corner::Kind::kInner : Corner::Kind::kOuter;
  // The margin stays fast's double sine; where rounding gave it the other sign or 0, it is the
  // smallest double of the exact sign, so that branch and margin agree (PROP-BOUNDARY-1).
  double sign = c.kind == Corner::Kind::kInner ? 1.0 : -1.0;
  if (!(c.sine * sign > 0)) c.sine = sign * std::numeric_limits<double>::denorm_min();
}

std::optional<int> Compensation::exact_room_sign(const std::array<Int128, 3>& u) const {
  Int128 a = u[static_cast<std::size_t>(axes.abscissa)], b = u[static_cast<std::size_t>(axes.ordinate)];
  for (Int128 v : {a, b, r_units})
    if (!in_exact_range(v)) return std::nullopt;  // beyond the range: the double decision stands
  Int128 d = a * a + b * b - r_units * r_units;   // each square below 2^124: no overflow
  return (d > 0) - (d < 0);
}

bool Compensation::equidistant_exists(const Block& b, const BlockCopy& c, const Element& e, double& radius) {
  if (!e.arc) return true;
  radius = e.equidistant_radius(s * r);
  radius = exactly_inside(c, e, radius);
  decide("TRC-ARC-EQ-1", b.words.line, radius > 0 ? "concentric" : "collapses", radius);
  return radius > 0;
}

// Inside a programmed circle, rho - r is a decision on programmed decimals (decided in core) where
// the doubles cannot tell: a circle of exactly the tool's radius collapses (campaign 20261208,
// case 169769). Only near the tie, so no exact arithmetic runs per block.
double Compensation::exactly_inside(const BlockCopy& c, const Element& e, double radius) const {
  if (!c.exact || !c.arc || s * e.sense < 0 || std::fabs(radius) > 1e-9 * (e.radius + r)) return radius;
  ProgrammedCircle pc;
  pc.chord = {c.delta[static_cast<std::size_t>(axes.abscissa)], c.delta[static_cast<std::size_t>(axes.ordinate)]};
  pc.to_centre = {c.to_centre[static_cast<std::size_t>(axes.abscissa)],
                  c.to_centre[static_cast<std::size_t>(axes.ordinate)]};
  pc.by_centre = c.has_centre, pc.cr = c.cr_units;
  int sg = circle_radius_sign(pc, r_units);
  if (sg == 0) return 0;
  if ((sg > 0) != (radius > 0))
    return sg > 0 ? std::numeric_limits<double>::denorm_min() : -std::numeric_limits<double>::denorm_min();
  return radius;
}

void Compensation::open_element(const BlockCopy& b, const Element& e, Vec2 start, double radius, Placed placed,
                                const Vec2* piece_start) {
  if (std::size_t k = slot_of(b); k < 2) {
    open = &prev_blocks[k];  // a slot's block stays where it is
  } else {
    if (&b != &open_own) open_own = b;
    open = &open_own;
  }
  open_el = e;
  open_start = start;
  open_at_normal_start = placed == Placed::kNormal;
  open_from = 0;
  if (e.arc && placed == Placed::kCorner) open_from = rotation_memo.rotation(e, start);
  if (e.arc && placed == Placed::kOnPiece) {  // TRC-ARC-ELEMENT-1: [0, 2 pi) from the piece's start
    double base = piece_start ? rotation_memo.rotation(e, *piece_start) : 0.0;
    Vec2 from = piece_start ? *piece_start : Element::offset(e.start, e.start_tangent(), s * r);
    double t = signed_rotation(from - e.centre, start - e.centre, e.sense);
    open_from = base + (t < 0 ? t + 2 * std::numbers::pi : t);
    open_at_normal_start = !piece_start && t == 0;  // a full circle from its normal start stays whole
  }
  open_blended = false;
  open_radius = radius;
  open_start_error = closing_point_error;  // the point that closed the last element opens this one
  closing_point_error = -1;
}

void Compensation::compensation_active(const Block& b) {
  bool radius_changes = false;
  if (!still_compensable(b, &radius_changes)) return;
  bool again = anew(b);  // TRC-SIDE-1/2
  bool traversing = b.state.side == side && !again && moves_in_plane(b);
  // TRC-RADIUS-3: a new radius (D, DL, OFFN) is blended over the block that moves in the plane.
  bool blend = traversing && radius_changes;
  if (blend) reject_blend_here(b, looking || approach_until >= 0);
  const BlockCopy* current = nullptr;  // a traversing block, converted once
  if (traversing) {
    int slot = prev_slot ^ 1;  // two slots: the block and its predecessor, no copies
    current = &fill_slot(slot, b);
    const BlockCopy& before = prev_blocks[static_cast<std::size_t>(prev_slot)];
    bool had_prev = has_prev;
    prev_slot = slot, has_prev = true;
    if (approach_until >= 0 && approach_further_ahead(b, *current)) return;
    if (b.state.collision == CollisionMode::kCdon && had_prev && bottleneck(*current, before)) return;
  }
  if (looking) return look_ahead(b, current);
  if (again) return change_side(b);
  if (b.state.side == Side::kOff) {
    if (!b.programs_plane_axis()) return deselect_in_place(b);  // TRC-DESEL-3
    return deselect(b);
  }
  if (!moves_in_plane(b)) return hold_back(b);  // TRC-DUMMY-3
  corner(b, *current);
  if (blend && !trace.stopped()) blend_radius(b, *current);
}

// TRC-RADIUS-3: what the blend is not specified for (yet): a circle becomes a spiral; the
// collision check and the look-ahead would compare pieces of two radii.
void Compensation::reject_blend_here(const Block& b, bool searching) const {
  if (b.is_arc()) throw UnsupportedError(b.words.line, "a D, DL or OFFN change in a circle block (a spiral)");
  if (b.state.collision == CollisionMode::kCdon || searching)
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change under CDON or in the look-ahead");
}

// TRC-RADIUS-3: the block's corner at its start was taken with the old radius; from here on the
// new one counts, so that its end (the next corner, or its normal end) lies on the new
// equidistant and the element runs inclined between the two.
void Compensation::blend_radius(const Block& b, const BlockCopy& copy) {
  if (looking || open->seq != copy.seq)  // TRC-LOOK-1 passed the block over: not its own element
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change in a block the look-ahead passes over");
  CompensationSide cs = compensation_side(b.state);
  decide(cs.decision, b.words.line);
  decide("TRC-RADIUS-3", b.words.line, "blend");
  r = cs.r.to_double();
  r_units = cs.r.units();
  edge = ActiveEdge::of(b.state);
  open_blended = true;
}

void Compensation::corner(const Block& b, const BlockCopy& copy) {
  // Not copied: `copy` is in a slot (compensation_active's current block), whose element stays
  // while the corner is decided; a copy would wait for the element's stores (element_of).
  const Element& next = element_of(copy);
  double next_radius = 0;
  if (!equidistant_exists(b, copy, next, next_radius)) return start_look_ahead(b);
  Vec2 v = open_el.end;
  Corner c = classify_corner(open_el.end_tangent(), next.start_tangent(), s);
  decide_kind_exactly(*open, copy, c);
  static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
  decide("TRC-CORNER-1", b.words.line, kKind[static_cast<int>(c.kind)], c.sine);

  bool circle = c.kind == Corner::Kind::kReversal;  // TRC-G450-3: a reversal is always a circle
  if (c.kind == Corner::Kind::kOuter) circle = outer_corner_circle(b.words.line, copy.g451, c);
  if (circle) return transition_circle(copy, next, next_radius, v);
  Vec2 x;
  double x_error = -1;  // PATH-ELEMENT-2: how far x may be off, where known
  if (c.kind == Corner::Kind::kTangent) {
    x = Element::offset(v, open_el.end_tangent(), s * r);  // both equidistants pass through it
  } else if (!open_el.arc && !next.arc) {
    // TRC-G451-1 / TRC-INNER-1: the intersection of two straight equidistants.
    x = Element::offset(v, open_el.unit, s * r) - corner_trim(c, s, r) * open_el.unit;
  } else {
    // TRC-ARC-CORNER-1: the intersection of the carriers nearest to the corner.
    Carrier cu = carrier_of(open_el, open_radius), cv = carrier_of(next, next_radius);
    bool found = intersection_memo.intersection(cu, cv, v, next.start_tangent(), r, x);
    if (trace.keeps_decisions())  // the gap is only the trace's margin
      decide("TRC-ARC-CORNER-1", b.words.line, found ? "intersection" : "none", corner_gap(cu, cv, r));
    if (found) x_error = intersection_error(cu, cv, x);
    if (!found && c.kind == Corner::Kind::kOuter)
      return transition_circle(copy, next, next_radius, v);  // TRC-ARC-CORNER-2
    if (!found) return raise(10751, b.words);
  }
  if (c.kind != Corner::Kind::kTangent) {
    // TRC-LOOK-1: the next equidistant must reach the intersection before its own end (at a
    // tangent corner the point is its normal start).
    Extent reach = extent_of(next, next_radius, x);
    bool too_short = reach.left < 0;
    decide("TRC-LOOK-1", b.words.line, too_short ? "too-short" : "reaches", reach.left);
    if (too_short) return start_look_ahead(b);
  }
  Candidate cand{&copy, &next, next_radius};
  const bool tangent = c.kind == Corner::Kind::kTangent;
  closing_point_error = x_error;
  if (!close_open(x, BlockPlace::of(b.words), tangent ? Placed::kNormal : Placed::kCorner, &cand)) {
    closing_point_error = -1;
    return;
  }
  run_held_back(x);
  open_element(copy, next, x, next_radius, tangent ? Placed::kNormal : Placed::kCorner);
}

bool Compensation::outer_corner_circle(int line_no, bool g451, const Corner& c) {
  // Far from the limit the corner's side of it is its cosine's (the tangents are unit vectors to a
  // few ulps; 1e-9 leaves a wide margin): the angle is then wanted only as the trace's margin.
  double limit_cos = g451 ? corner_limit_cosine : insert_limit_cosine;
  if (!trace.keeps_decisions() && std::fabs(c.cosine - limit_cos) > 1e-9) return c.cosine < limit_cos;
  double angle = std::atan2(std::fabs(c.sine), c.cosine) * (180.0 / std::numbers::pi);
  if (g451) {  // TRC-CORNER-3: G451 switches to G450 above MD20210
    double limit = md.cutcom_corner_limit.to_double();
    bool circle = angle > limit;
    decide("TRC-CORNER-3", line_no, circle ? "switch-to-G450" : "keep-G451", angle - limit);
    return circle;
  }
  double limit = md.cutcom_curve_insert_limit.to_double();  // TRC-CORNER-4: G450 to G451 below MD20230
  bool circle = !(angle < limit);
  decide("TRC-CORNER-4", line_no, circle ? "keep-G450" : "switch-to-G451", angle - limit);
  return circle;
}

Compensation::Extent Compensation::extent_of(const Element& e, double radius, Vec2 p) const {
  if (!e.arc) {
    double along = dot(p - Element::offset(e.start, e.unit, s * r), e.unit);
    return {along, e.length - along};
  }
  double along = rotation_memo.rotation(e, p);
  return {along * radius, (sweep(e) - along) * radius};
}

void Compensation::skip(const BlockCopy& c) {
  if (skipped.capacity() == 0) skipped.reserve(kSkippedCapacity);
  skipped.push_back(c);
}

void Compensation::pass_over(const BlockCopy& c) {
  skip(c);
  if (examined >= md.cutcom_maxnum_check_blocks) raise(10751, c);
}

void Compensation::start_look_ahead(const Block& too_short) {
  for (int i = 0; i < dummy_count; ++i) skip(dummies[static_cast<std::size_t>(i)]);
  dummy_count = 0;
  skip(copy_of(too_short));
  examined = 1, dummy_run = 0;
  looking = true;
  if (examined >= md.cutcom_maxnum_check_blocks) raise(10751, too_short.words);
}

void Compensation::look_ahead(const Block& b, const BlockCopy* current) {
  if (b.state.side == Side::kOff && b.programs_plane_axis()) return retract_edge(b);  // TRC-EDGE-1
  if (anew(b)) {  // the contour ends before an intersection
    decide("TRC-LOOK-2", b.words.line, "none");
    return raise(10751, b.words);
  }
  if (!b.moves_in_plane()) {
    if (++dummy_run > md.cutcom_maxnum_dummy_blocks) return raise(10762, b.words);
    return skip(copy_of(b));
  }
  dummy_run = 0;
  ++examined;
  const BlockCopy& c = *current;
  Element cand = element_of(c);
  double radius = 0;
  if (!equidistant_exists(b, c, cand, radius)) return pass_over(c);
  Vec2 start = Element::offset(cand.start, cand.start_tangent(), s * r);
  Vec2 y;
  Carrier cu = carrier_of(open_el, open_radius), cv = carrier_of(cand, radius);
  // Programmed lines in the same direction have parallel equidistants, which never meet; their
  // unit vectors in double may cross by a rounding (campaign 20261205, case 29172: the candidate
  // ran along the open block's own line, and fast met it there).
  bool parallel = false;
  if (!open_el.arc && !cand.arc && open->exact && c.exact) {
    std::optional<LineProducts> p = line_products(open->delta, c.delta, axes);  // TRC-LOOK-2 exactly: cross 0
    parallel = p && p->cross == 0;
  } else if (!open_el.arc && !cand.arc) {
    // Lines built on one tangent (SAR lines at the two ends of a full circle: campaign 20261207,
    // case 314401) lie on one line for ref; in double they cross anywhere along it.
    parallel = on_one_line(cu, cv);
  } else if (open_el.arc && cand.arc) {
    // Arcs of one programmed circle have one circle as equidistant: no point for ref (-inf); in
    // double a centre corrected onto the chord's bisector is off by a rounding and the two cross
    // anywhere (campaign 20261241, case 419850).
    parallel = on_one_circle(cu, cv);
  }
  // Carriers within rounding of touching touch (campaign 20261214, case 492847: a line exactly
  // tangent to a SAR semicircle's equidistant missed it by 4e-16 mm, alarm 10751 in fast only;
  // 20261215, case 11707: the same crossed it 3.5e-8 mm off the point).
  NearerChoice choice;  // touching: one point, a tie
  bool found = !parallel && (touching_within_rounding(cu, cv, y) ||
                             nearest_intersection(cu, cv, start, cand.start_tangent(), y, &choice));
  if (found && (cu.circle || cv.circle)) decide_nearer(b.words.line, cu, cv, choice);
  bool valid = false;
  // No intersection at all: minus the gap between the carriers (parallel lines, and one circle
  // carrying both, which has no gap and no point: -inf).
  double gap = !parallel && (cu.circle || cv.circle) ? carrier_gap(cu, cv) : 0;
  double margin = gap > 0 ? -gap : -std::numeric_limits<double>::infinity();
  if (found) {
    Extent on = extent_of(cand, radius, y);
    valid = on.along >= 0 && on.left >= 0;
    margin = on.along < 0 ? on.along : on.left < 0 ? on.left : std::min(on.along, on.left);  // the nearer end
    // With a circle the carriers' overlap too (as ref): carriers that just touch are the knife
    // edge of meeting at all. They met, so it is at least 0, whatever the rounding of the gap.
    if (valid && (cu.circle || cv.circle)) margin = std::min(margin, std::max(-carrier_gap(cu, cv), 0.0));
  }
  decide("TRC-LOOK-2", b.words.line, valid ? "intersection" : "none", margin);
  if (!valid) return pass_over(c);
  looking = false;
  Candidate candidate{&c, &cand, radius};
  if (!close_open(y, BlockPlace::of(b.words), Placed::kCorner, &candidate)) return;
  for (BlockCopy& d : skipped) skip_at(d, y);
  skipped.clear();
  open_element(c, cand, y, radius);
}

// TRC-LOOK-4: which of the carriers' points the look-ahead took (nearest_intersection's choice).
// The margin is the lesser of the two distances at which the choice would change, as ref's: the
// normal start on the points' axis of symmetry, or the carriers no longer crossing (their gap).
void Compensation::decide_nearer(int line, const Carrier& u, const Carrier& v, const NearerChoice& choice) {
  // Two circles' points are named from the side (G42 swaps them), so that mirroring keeps names.
  double by = choice.first_nearer * (u.circle && v.circle ? s : 1);
  double depth = trace.keeps_decisions() ? std::fabs(carrier_gap(u, v)) : 0;  // only the margin needs it
  double margin = depth > 0 && depth < std::fabs(by) ? std::copysign(depth, by) : by;
  decide("TRC-LOOK-4", line, by == 0 ? "tie" : by > 0 ? "first" : "second", margin);
}

void Compensation::skip_at(BlockCopy& k, Vec2 at) {
  decide("TRC-LOOK-3", k.line, "skipped");
  line(k, xyz(at, h(k.start)), xyz(at, h(k.end)), OriginKind::kInfeed, k.rapid);
}

void Compensation::transition_circle(const BlockCopy& b, const Element& next, double next_radius, Vec2 v) {
  Vec2 from = Element::offset(v, open_el.end_tangent(), s * r);
  if (!close_open(from, BlockPlace::of(b), Placed::kNormal)) return;
  run_held_back(from);
  Vec2 to = Element::offset(v, next.start_tangent(), s * r);
  Origin corner = origin(*open, OriginKind::kTransitionCircle);
  open_element(b, next, to, next_radius, Placed::kNormal);
  // From b, which is (or was copied into) the open block: a copy's just-written fields would be
  // read back by loads the CPU cannot forward from its stores (a fifth of this function's samples).
  corner.next_line = b.line, corner.next_block = b.number, corner.next_insert = b.insert;
  if (r > 0) {  // TRC-G450-2: no circle for a zero radius
    double hv = h(open->start);
    // Around the outside: clockwise on the left, counter-clockwise on the right.
    corner_circle(*open, xyz(from, hv), xyz(to, hv), xyz(v, hv), s < 0, corner);
  }
}

void Compensation::corner_circle(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const PathPoint& centre,
                                 bool ccw, const Origin& named) {
  // PATH-ELEMENT-2: a circle around an outer corner turns less than half a turn; where the
  // equidistants meet within rounding (a tangent corner in exact terms, e.g. into a SAR circle)
  // its points cannot tell that turn from a whole one: its chord, a line a rounding long (or none).
  if (turn_undetermined(ab(from) - ab(centre), ab(to) - ab(centre))) return line(owner, from, to, named, owner.rapid);
  arc(owner, from, to, centre, ccw, named);
}

void Compensation::arc(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const PathPoint& centre, bool ccw,
                       const Origin& from_what) {
  actions(owner, from);
  auto fill = [&](PathElement& e) {
    e.type = ElementType::kArc, e.rapid = owner.rapid, e.start = from, e.end = to, e.center = centre, e.ccw = ccw;
    e.feed = owner.feed, e.feed_type = owner.feed_type, e.origin = from_what;
  };
  if (direct()) {
    fill(outgoing);
    return sink.element(outgoing);
  }
  HeldRecord& rec = hold_record_of(owner);
  rec.is_element = true, rec.radius = norm(ab(from) - ab(centre));
  fill(rec.element);
}

void Compensation::actions(BlockCopy& b, const PathPoint& at) {
  if (b.actions_done) return;
  b.actions_done = true;
  for (int i = 0; i < b.aux_count; ++i) {
    ActionEvent a{b.line, b.number, b.aux[static_cast<std::size_t>(i)], at};
    if (direct()) {
      sink.action(a);
      continue;
    }
    hold_record_of(b).action = a;
  }
}

void Compensation::release_window(const Block& b) {
  if (trace.stopped()) return;
  held.end_block(phase == Phase::kActive && b.state.collision == CollisionMode::kCdon);
}

void Compensation::step(const Block& b, const PlaneOverride* o, bool moves) {
  if (trace.stopped()) return;
  if (b.words.disc && b.words.disc->sign() > 0)  // TRC-DISC-1
    throw UnsupportedError(b.words.line, "DISC greater than 0 (a distorted transition circle)");
  if (o) over = *o;
  // Off, the compensation has no plane of its own yet: that of the block's overridden points.
  if (o && phase == Phase::kOff) axes = o->axes;
  over_block = o ? &b : nullptr;
  stepped = &b, stepped_moves = moves;
  held.begin_block(b, moves);
  if (!(b.is_arc() && b.sar.move == SarMove::kNone && !arc_is_consistent(b, md, trace))) {
    switch (phase) {
      case Phase::kOff:
        compensation_off(b);
        break;
      case Phase::kApproach:
        approach(b);
        break;
      case Phase::kActive:
        compensation_active(b);
        break;
      case Phase::kRetracting:
        retraction_pending(b);
        break;
    }
    release_window(b);
  }
  over_block = nullptr, stepped = nullptr;
}

}  // namespace cutcom::fast

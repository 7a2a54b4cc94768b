// Stage 2 of ref, the compensation (compensation.hpp), one block at a time: selection, corners
// (TRC-CORNER-*, TRC-G450/451-*, TRC-INNER-1), the look-ahead over too-short blocks (TRC-LOOK-*)
// and the output into the collision window. fast implements the same clauses independently in
// double (fast/src/compensation.cpp).
#include "compensation.hpp"

#include "arc_check.hpp"
#include "filtered.hpp"

namespace cutcom::ref::detail {

void Compensation::step(Block b, const std::optional<PlaneOverride>& over) {
  if (trace_.stopped()) return;
  b.index = next_index_++;
  if (over) overrides_[b.index] = *over;
  program_.push_back(b);
  actions_done_.push_back(false);
  const Block& kept = program_.back();
  held_.begin_block(kept);
  seq_.push_back(held_.seq());
  if (kept.words.disc && kept.words.disc->sign() > 0)  // TRC-DISC-1
    throw UnsupportedError(kept.words.line, "DISC greater than 0 (a distorted transition circle)");
  if (!(kept.is_arc() && kept.sar.move == SarMove::kNone && !arc_is_consistent(kept, md_, trace_))) {
    switch (phase_) {
      case Phase::kOff:
        compensation_off(kept);
        break;
      case Phase::kApproach:
        waiting_for_contour(kept);
        break;
      case Phase::kActive:
        compensation_active(kept);
        break;
      case Phase::kRetracting:
        retraction_pending(kept);
        break;
    }
  }
  release_window(kept);
  forget_old_blocks();
}

void Compensation::forget_old_blocks() {
  int keep_from = program_.back().index;
  auto pin = [&](const Block* b) {
    if (b) keep_from = std::min(keep_from, b->index);
  };
  for (const HeldRecord& r : held_.records()) pin(r.owner);
  for (const Block* b : skipped_) pin(b);
  for (const Block* b : dummies_) pin(b);
  if (approach_)
    for (const Block* b : approach_->held_back) pin(b);
  pin(open_block_), pin(prev_block_);
  if (phase_ == Phase::kApproach || approach_) pin(selection_);  // read until the approach is made
  keep_from -= kSpareBlocks;
  while (!program_.empty() && program_.front().index < keep_from) {
    program_.pop_front(), seq_.pop_front(), actions_done_.pop_front();
    ++first_kept_;
  }
  overrides_.erase(overrides_.begin(), overrides_.lower_bound(first_kept_));
}

void Compensation::run_uncompensated(const Block& b) {
  if (!b.is_arc()) return emit_line(b, start_of(b), end_of(b), OriginKind::kProgrammed);
  // A programmed circle, about its (corrected, ARC-CENTRE-1) centre; or a SAR circle.
  PlaneAxes axes = plane_axes(b.state.plane);
  ContourElement arc = element_of(b);
  Decimal h = coord(b.start, axes.applicate);
  emit_arc(b, start_of(b), end_of(b), ExactPoint::in_plane(arc.centre, h, axes), arc.radius, arc.sense > 0,
           origin(b, OriginKind::kProgrammed), axes);
}

void Compensation::compensation_off(const Block& b) {
  if (b.state.side == Side::kOff) return run_uncompensated(b);
  if (b.is_arc()) return raise(10753, b);  // TRC-SEL-2
  if (!b.programs_plane_axis()) {          // TRC-SEL-4
    decide("TRC-SEL-4", b.words.line, "no-plane-axis");
    return run_uncompensated(b);
  }
  if (b.state.tool == 0) return raise(10750, b);  // TRC-SEL-6
  if (b.state.edge == 0) {                        // TRC-SEL-5
    decide("TRC-SEL-5", b.words.line, "d0");
    if (!d0_noticed_) sink_.notice({b.words.line, "TRC-SEL-5", "G41/G42 with D0: no compensation", b.words.source});
    d0_noticed_ = true;
    return run_uncompensated(b);
  }
  if (!b.state.edge_defined) return raise(17181, b);  // TRC-SEL-7
  select(b);
}

void Compensation::change_side(const Block& b) {
  bool again = b.state.side == comp_->side;  // TRC-SIDE-2: the same G41/G42 programmed again
  if (b.is_arc()) return raise(10753, b);    // TRC-SEL-2: the new selection needs a linear block
  if (!b.programs_plane_axis()) {
    decide(again ? "TRC-SIDE-2" : "TRC-SIDE-1", b.words.line, "no-plane-axis");
    return hold_back(b);
  }
  decide(again ? "TRC-SIDE-2" : "TRC-SIDE-1", b.words.line, again ? "selected-again" : "side-change");
  Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
  if (!close_open(end, b, Placed::kNormal)) return;
  run_held_back(end);
  ExactPoint tool = at({end, coord(b.start, comp_->axes.applicate)});
  open_.reset();
  comp_.reset();
  select(b);
  selection_from_ = tool;
}

void Compensation::select(const Block& b) {
  selection_from_.reset();
  reject_kontc_kontt(b, false);  // TRC-UNSUP-1
  // TRC-SEL-3: a single programmed plane axis was completed by the reader (NC-POS-1).
  decide("TRC-SEL-1", b.words.line, "selected");
  CompensationSide side = compensation_side(b.state);  // TRC-RADIUS-2 (decided in core)
  decide(side.decision, b.words.line);
  int s = side.s;
  Decimal r = side.r;
  comp_ = InForce{b.state.plane,           plane_axes(b.state.plane), b.state.side, s, FT(s) * leaf(r), r,
                  ActiveEdge::of(b.state), b.state.selection};
  selection_ = &b;
  prev_block_ = nullptr;
  approach_search_.reset();
  dummies_.clear();
  phase_ = Phase::kApproach;
}

bool Compensation::still_compensable(const Block& b) {
  if (b.state.side == Side::kOff) {
    if (b.is_arc() && b.programs_plane_axis()) {  // TRC-DESEL-2
      raise(10754, b);
      return false;
    }
    return true;
  }
  if (b.state.plane != comp_->plane) {  // TRC-PLANE-1
    raise(10757, b);
    return false;
  }
  if (anew(b)) return true;                              // TRC-SIDE-1/2, handled by the caller
  reject_change_while_active(b, comp_->edge, comp_->s);  // TRC-UNSUP-1, TRC-RADIUS-3
  return true;
}

void Compensation::hold_back(const Block& b) {
  if (static_cast<int>(dummies_.size()) == md_.cutcom_maxnum_dummy_blocks) return raise(10762, b);
  dummies_.push_back(&b);
}

void Compensation::run_held_back(const Point& corner_point) {
  for (const Block* d : dummies_)
    emit_line(*d, at({corner_point, coord(d->start, comp_->axes.applicate)}),
              at({corner_point, coord(d->end, comp_->axes.applicate)}), OriginKind::kInfeed);
  dummies_.clear();
}

void Compensation::run_held_back_uncompensated() {
  for (const Block* d : dummies_) emit_line(*d, start_of(*d), end_of(*d), OriginKind::kProgrammed);
  dummies_.clear();
}

void Compensation::waiting_for_contour(const Block& b) {
  if (b.state.side == Side::kOff) {
    // TRC-SEL-8: deselected before any block moved in the plane: no selection took place.
    decide("TRC-SEL-8", selection_->words.line, "deselected-before-contour");
    emit_line(*selection_, selection_start(), end_of(*selection_), OriginKind::kProgrammed);
    run_held_back_uncompensated();
    phase_ = Phase::kOff;
    comp_.reset();
    return compensation_off(b);
  }
  if (!still_compensable(b)) return;
  if (anew(b)) {
    // TRC-SIDE-3: selected anew before any contour block: the first selection had no contour.
    decide("TRC-SIDE-3", b.words.line, "before-contour");
    emit_line(*selection_, selection_start(), end_of(*selection_), OriginKind::kProgrammed);
    run_held_back_uncompensated();
    phase_ = Phase::kOff;
    comp_.reset();
    return compensation_off(b);
  }
  if (!b.moves_in_plane()) return hold_back(b);  // TRC-DUMMY-3: no in-plane displacement
  if (!comp_->edge.in_force(b.state))            // TRC-RADIUS-3: the approach has one radius
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change in the first contour block");
  approach(b);
}

void Compensation::compensation_active(const Block& b) {
  if (!still_compensable(b)) return;
  bool traversing = b.state.side == comp_->side && !anew(b) && b.moves_in_plane();
  // TRC-RADIUS-3: a new radius (D, DL, OFFN) is blended over the block that moves in the plane.
  bool blend = traversing && !comp_->edge.in_force(b.state);
  if (blend) reject_blend_here(b, looking_ || approach_search_.has_value());
  if (traversing) {
    const Block* before = prev_block_;
    prev_block_ = &b;
    if (approach_search_ && approach_further_ahead(b)) return;
    if (b.state.collision == CollisionMode::kCdon && before && bottleneck(b, *before)) return;
  }
  if (looking_) return look_ahead(b);
  if (anew(b)) return change_side(b);
  if (b.state.side == Side::kOff) {
    if (!b.programs_plane_axis()) return deselect_in_place(b);  // TRC-DESEL-3
    return deselect(b);
  }
  if (!b.moves_in_plane()) return hold_back(b);  // TRC-DUMMY-3
  corner(b);
  if (blend && !trace_.stopped()) blend_radius(b);
}

// TRC-RADIUS-3: what the blend is not specified for (yet): a circle becomes a spiral; the
// collision check and the look-ahead would compare pieces of two radii.
void Compensation::reject_blend_here(const Block& b, bool searching) const {
  if (b.is_arc()) throw UnsupportedError(b.words.line, "a D, DL or OFFN change in a circle block (a spiral)");
  if (b.state.collision == CollisionMode::kCdon || searching)
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change under CDON or in the look-ahead");
}

// TRC-RADIUS-3: the corner at the block's start was taken with the old radius; from here on the
// new one counts: the block's end lies on the new equidistant, its element runs inclined.
void Compensation::blend_radius(const Block& b) {
  if (looking_ || open_block_ != &b)  // TRC-LOOK-1 passed the block over: not its own element
    throw UnsupportedError(b.words.line, "a D, DL or OFFN change in a block the look-ahead passes over");
  CompensationSide side = compensation_side(b.state);
  decide(side.decision, b.words.line);
  decide("TRC-RADIUS-3", b.words.line, "blend");
  comp_->radius = side.r;
  comp_->side_radius = FT(comp_->s) * leaf(side.r);
  comp_->edge = ActiveEdge::of(b.state);
  open_blended_ = true;
}

bool Compensation::close_open(const Point& end_point, const Block& reporting, Placed placed,
                              const Candidate* candidate) {
  const ContourElement& e = *open_;
  CGAL::Sign sign;
  std::string margin;
  bool beyond_a_turn = false;  // PATH-ELEMENT-2: a trimmed circle that turns more than a whole turn
  if (!e.is_arc()) {
    FT left = (end_point - open_start_) * e.d;  // signed length along the block, times |d|
    sign = CGAL::sign(left);                    // without the square root: a cheaper exact zero
    if (margins_kept()) margin = exact_mm(left / e.length);
  } else {
    // Positions on the programmed circle from its start: the start (open_from_, as it was placed)
    // and the end: a corner's a signed rotation from the normal end, after the sweep; a point
    // found on the piece the rotation from the start, in [0, 2 pi) (TRC-ARC-ELEMENT-1).
    CircleFrame f(e.a - e.centre, e.sense);
    const CirclePosition& from = open_from_;
    CirclePosition to = f.end(e.b - e.centre, e.full_circle);
    if (placed == Placed::kCorner) to = f.signed_from(to, end_point - e.centre);
    if (placed == Placed::kOnPiece) to = f.forward_from(from, end_point - e.centre);
    sign = f.compare(to, from);
    if (margins_kept()) margin = f.length_text(from, to, open_radius_);
    beyond_a_turn = f.compare(to, CirclePosition{from.turns + 1, from.v}) == CGAL::POSITIVE;
  }
  std::string_view clause = e.is_arc() ? "TRC-ARC-ELEMENT-1" : "TRC-ELEMENT-1";
  if (sign == CGAL::NEGATIVE) {
    decide(clause, e.line, "reverses", margin);
    // TRC-EDGE-1: the first element after the approach is too short for its neighbour.
    if (approach_ && candidate) return approach_edge(*candidate), false;
    if (kont_first_ && candidate)
      throw UnsupportedError(  // TRC-EDGE-7 (planned)
          selection_->words.line, "KONT approach from behind the contour before a too-short first block");
    raise(10751, reporting);
    return false;
  }
  decide(clause, e.line, sign == CGAL::ZERO ? "vanishes" : "fits", margin);
  flush_approach();
  kont_first_ = false;
  ExactPoint from = at({open_start_, coord(e.start3, comp_->axes.applicate)});
  ExactPoint to = at({end_point, coord(e.end3, comp_->axes.applicate)});
  if (sign == CGAL::ZERO) {
    // TRC-ELEMENT-1: nothing left along the block; what it moves besides (the applicate, or across
    // from one radius to the other after a blend, TRC-RADIUS-3) runs at the point: no gap.
    bool across = open_blended_ && open_start_ != end_point;  // (exact, only after a blend)
    Decimal h0 = coord(e.start3, comp_->axes.applicate);
    if (!across && h0 == coord(e.end3, comp_->axes.applicate)) {
      run_actions(*open_block_, path.output(to));
      return true;
    }
    emit_line(*open_block_, across ? from : at({end_point, h0}), to,
              across ? OriginKind::kOffset : OriginKind::kInfeed);
    return true;
  }
  if (!e.is_arc()) {
    // TRC-RADIUS-3: a blended element is no equidistant (PROP-EXACT-1 does not apply to it).
    emit_line(*open_block_, from, to, OriginKind::kOffset, open_blended_ ? nullptr : &e);
  } else {
    ExactPoint centre = at({e.centre, coord(e.start3, comp_->axes.applicate)});
    if (beyond_a_turn) {  // PATH-ELEMENT-2: the whole turn first, then the rest, each readable
      if (!(coord(e.start3, comp_->axes.applicate) == coord(e.end3, comp_->axes.applicate)))
        throw UnsupportedError(e.line, "a helix that turns more than a whole turn after its corners");
      emit_arc(*open_block_, from, from, centre, open_radius_, e.sense > 0, origin(*open_block_, OriginKind::kOffset),
               comp_->axes);
    }
    emit_arc(*open_block_, from, to, centre, open_radius_, e.sense > 0, origin(*open_block_, OriginKind::kOffset),
             comp_->axes);
  }
  return true;
}

void Compensation::corner(const Block& next_block) {
  ContourElement next = element_of(next_block);
  FT next_radius;
  if (!equidistant_exists(next, next_radius)) return start_look_ahead(next_block);
  const ContourElement& first = *open_;
  // TRC-CORNER-1 on the tangents: rational predicates where both are rational, exact Expr signs
  // otherwise (CR= circles).
  bool rational = first.rational && next.rational;
  std::optional<CornerClass> rc;
  CornerKind kind;
  FT cross, dot;
  if (rational) {
    rc = classify_corner(first.end_tangent, next.start_tangent, comp_->s);
    kind = rc->kind, cross = to_ft(rc->cross), dot = to_ft(rc->dot);
  } else {
    kind = classify_corner(first.end_dir, next.start_dir, comp_->s);
    cross = first.end_dir.x() * next.start_dir.y() - first.end_dir.y() * next.start_dir.x();
    dot = first.end_dir * next.start_dir;
  }
  static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
  std::string sine;  // the margin: the signed sine, |t1||t2| = sqrt(dot^2 + cross^2)
  if (margins_kept()) sine = exact_text(FT(comp_->s) * cross / exact_root(dot * dot + cross * cross));
  decide("TRC-CORNER-1", next_block.words.line, kKind[static_cast<int>(kind)], std::move(sine));

  bool circle = kind == CornerKind::kReversal;  // TRC-G450-3
  if (kind == CornerKind::kOuter) circle = outer_corner_circle(next_block, rc, cross, dot);
  const Point vertex = first.b;  // a copy: open() replaces the element it comes from
  if (circle) return transition_circle(next_block, next, next_radius, vertex);
  if (kind == CornerKind::kTangent) {
    // Both equidistants pass through the common normal point.
    Point x = equidistant_point<Kernel>(vertex, first.end_normal(), comp_->side_radius);
    if (!close_open(x, next_block, Placed::kNormal)) return;
    run_held_back(x);
    return open(next_block, next, x, next_radius, Placed::kNormal);
  }
  std::optional<Point> x;
  if (!first.is_arc() && !next.is_arc()) {
    // TRC-G451-1 / TRC-INNER-1 for two straight blocks.
    FT trim = corner_trim<Kernel>(cross, dot, first.length, next.length, comp_->side_radius);
    x = corner_intersection<Kernel>(vertex, first.normal, first.d, first.length, comp_->side_radius, trim);
  } else {
    // TRC-ARC-CORNER-1: the intersection of the equidistants' carriers nearest to the corner.
    Carrier<Kernel> u = carrier_of(first, open_radius_), v = carrier_of(next, next_radius);
    x = nearest_intersection(u, v, vertex, next.start_dir);
    decide("TRC-ARC-CORNER-1", next_block.words.line, x ? "intersection" : "none",
           margins_kept() ? exact_mm(carrier_gap<Kernel>(u, v)) : std::string());
    if (!x && kind == CornerKind::kOuter)
      return transition_circle(next_block, next, next_radius, vertex);  // TRC-ARC-CORNER-2
    if (!x) return raise(10751, next_block);
  }
  // TRC-LOOK-1: the next equidistant must reach the intersection before its own end.
  Extent reach = extent_of(next, next_radius, *x);
  bool too_short = reach.after_end == CGAL::NEGATIVE;
  decide("TRC-LOOK-1", next_block.words.line, too_short ? "too-short" : "reaches", reach.left_text);
  if (too_short) return start_look_ahead(next_block);
  Candidate cand{&next_block, &next, next_radius};
  if (!close_open(*x, next_block, Placed::kCorner, &cand)) return;
  run_held_back(*x);
  open(next_block, next, *x, next_radius);
}

bool Compensation::outer_corner_circle(const Block& at_block, const std::optional<CornerClass>& rc, const FT& cross,
                                       const FT& dot) {
  bool g451 = at_block.state.corner == CornerMode::kG451;
  const Decimal& limit = g451 ? md_.cutcom_corner_limit : md_.cutcom_curve_insert_limit;
  AngleComparison a;
  if (rc) {
    const CornerClass& c = *rc;
    mpz_class ic = c.a1 * c.b2 - c.b1 * c.a2, id = c.a1 * c.a2 + c.b1 * c.b2;
    mpz_class l2 = (c.a1 * c.a1 + c.b1 * c.b1) * (c.a2 * c.a2 + c.b2 * c.b2);
    a = compare_contour_angle(ic, id, l2, limit, margins_kept());
  } else {
    a = compare_contour_angle_exact(cross, dot, dot * dot + cross * cross, limit, margins_kept());
  }
  if (g451) {
    bool circle = a.sign > 0;
    decide("TRC-CORNER-3", at_block.words.line, circle ? "switch-to-G450" : "keep-G451", a.margin_text);
    return circle;
  }
  bool circle = !(a.sign < 0);
  decide("TRC-CORNER-4", at_block.words.line, circle ? "keep-G450" : "switch-to-G451", a.margin_text);
  return circle;
}

Compensation::Extent Compensation::extent_of(const ContourElement& e, const FT& radius, const Point& p) const {
  Extent x;
  if (!e.is_arc()) {
    Point start = equidistant_point<Kernel>(e.a, e.normal, comp_->side_radius);
    // Signs on the lengths times |d| (no square root in the exact zero tests).
    FT along_d = (p - start) * e.d, left_d = e.d * e.d - along_d;
    x.before_start = CGAL::sign(along_d), x.after_end = CGAL::sign(left_d);
    if (margins_kept()) {                             // the margins only: no trace, no texts
      x.start_nearer = margin_less(along_d, left_d);  // picks a margin (filtered.hpp)
      x.along_text = exact_mm(along_d / e.length), x.left_text = exact_mm(left_d / e.length);
    }
  } else {
    CircleFrame f(e.a - e.centre, e.sense);
    CirclePosition start = f.start(), at = f.signed_from(start, p - e.centre);
    CirclePosition end = f.end(e.b - e.centre, e.full_circle);
    x.before_start = f.compare(at, start), x.after_end = f.compare(end, at);
    if (margins_kept()) {  // the margins only: no trace, no texts
      x.start_nearer = std::fabs(f.radians(start, at)) < std::fabs(f.radians(at, end));  // picks a margin
      x.along_text = f.length_text(start, at, radius), x.left_text = f.length_text(at, end, radius);
    }
  }
  return x;
}

void Compensation::start_look_ahead(const Block& too_short) {
  for (const Block* d : dummies_) skipped_.push_back(d);
  dummies_.clear();
  skipped_.push_back(&too_short);
  examined_ = 1;
  dummy_run_ = 0;  // TRC-DUMMY-2: the too-short block moves in the plane; a new run starts after it
  looking_ = true;
  if (examined_ >= md_.cutcom_maxnum_check_blocks) raise(10751, too_short);
}

void Compensation::look_ahead(const Block& b) {
  if (b.state.side == Side::kOff && b.programs_plane_axis()) return retract_edge(b);  // TRC-EDGE-1
  if (anew(b)) {  // the contour ends before an intersection
    decide("TRC-LOOK-2", b.words.line, "none");
    return raise(10751, b);
  }
  if (!b.moves_in_plane()) {
    if (++dummy_run_ > md_.cutcom_maxnum_dummy_blocks) return raise(10762, b);  // TRC-DUMMY-2
    skipped_.push_back(&b);
    return;
  }
  dummy_run_ = 0;
  ++examined_;
  ContourElement cand = element_of(b);
  FT radius;
  if (!equidistant_exists(cand, radius)) return pass_over(b);
  Point start = equidistant_point<Kernel>(cand.a, cand.start_normal(), comp_->side_radius);
  Carrier<Kernel> u = carrier_of(*open_, open_radius_), v = carrier_of(cand, radius);
  CGAL::Sign farther = CGAL::ZERO;
  std::optional<Point> y = nearest_intersection(u, v, start, cand.start_dir, &farther);
  if (y && (u.circle || v.circle)) decide_nearer(b.words.line, u, v, start, farther);
  bool valid = false;
  // No intersection at all: minus the gap between the carriers (parallel lines, and one circle
  // carrying both, which has no gap and no point: "-inf").
  std::string margin = "-inf";
  if (!y && (u.circle || v.circle)) {
    FT gap = carrier_gap<Kernel>(u, v);
    if (CGAL::sign(gap) == CGAL::POSITIVE) margin = exact_mm(-gap);
  }
  if (y) {
    Extent on = extent_of(cand, radius, *y);
    valid = on.before_start != CGAL::NEGATIVE && on.after_end != CGAL::NEGATIVE;
    // The nearer end: the violated one, or on the equidistant the one with less to spare.
    if (on.before_start == CGAL::NEGATIVE)
      margin = on.along_text;
    else if (on.after_end == CGAL::NEGATIVE)
      margin = on.left_text;
    else
      margin = on.start_nearer ? on.along_text : on.left_text;
    // With a circle the carriers' overlap too, when it is less (picked by the texts' values, both
    // in mm: the depth itself is in the kernel's units): carriers that just touch are the knife
    // edge of meeting at all.
    if (valid && margins_kept() && (u.circle || v.circle)) {
      std::string depth = exact_mm(-carrier_gap<Kernel>(u, v));
      if (std::stod(depth) < std::stod(margin)) margin = depth;
    }
  }
  decide("TRC-LOOK-2", b.words.line, valid ? "intersection" : "none", margin);
  if (!valid) return pass_over(b);
  looking_ = false;
  Candidate candidate{&b, &cand, radius};
  if (!close_open(*y, b, Placed::kCorner, &candidate)) return;
  run_skipped(*y);
  open(b, cand, *y, radius);
}

// TRC-LOOK-4: which of the carriers' points the look-ahead took (`farther`: nearest_intersection's
// sign; one point, they touch, is a tie). The margin is the lesser of the two distances at which
// the choice would change: p on the points' axis of symmetry, or the carriers no longer crossing
// (their overlap, as TRC-LOOK-2's margin).
void Compensation::decide_nearer(int line, const Carrier<Kernel>& u, const Carrier<Kernel>& v, const Point& p,
                                 CGAL::Sign farther) {
  // Two circles' points are named from the side (G42 swaps them), so that mirroring keeps names.
  const int named = u.circle && v.circle ? comp_->s : 1;
  if (named < 0) farther = CGAL::opposite(farther);
  std::string margin;
  if (margins_kept() && farther != CGAL::ZERO) {
    FT depth = -carrier_gap<Kernel>(u, v), by = first_nearer_by(u, v, p) * FT(named);
    margin = exact_mm(rough(depth) < std::fabs(rough(by)) ? (farther == CGAL::NEGATIVE ? -depth : depth) : by);
  } else if (margins_kept()) {
    margin = exact_mm(FT(0));
  }
  decide("TRC-LOOK-4", line, farther == CGAL::ZERO ? "tie" : farther == CGAL::POSITIVE ? "first" : "second", margin);
}

void Compensation::pass_over(const Block& b) {
  skipped_.push_back(&b);
  if (examined_ >= md_.cutcom_maxnum_check_blocks) raise(10751, b);
}

void Compensation::run_skipped(const Point& at_point) {
  for (const Block* d : skipped_) {
    decide("TRC-LOOK-3", d->words.line, "skipped");
    emit_line(*d, at({at_point, coord(d->start, comp_->axes.applicate)}),
              at({at_point, coord(d->end, comp_->axes.applicate)}), OriginKind::kInfeed);
  }
  skipped_.clear();
}

std::optional<Point> Compensation::nearest_intersection(const Carrier<Kernel>& u, const Carrier<Kernel>& v,
                                                        const Point& vertex, const Vector& ahead, CGAL::Sign* farther) {
  std::vector<Point> xs = carrier_intersections<Kernel>(u, v);
  if (xs.empty()) return std::nullopt;
  std::size_t k = 0;
  if (xs.size() == 2) {
    // The nearer one; equally near, the one further along `ahead` (second_farther's algebra,
    // checked against the points in ref/test/intersection_order_test.cpp).
    CGAL::Sign c = second_farther(u, v, vertex);
    bool second = c == CGAL::ZERO ? second_ahead(u, v, ahead) == CGAL::POSITIVE : c == CGAL::NEGATIVE;
    k = second ? 1 : 0;
    if (farther) *farther = c;
  }
  tighten_filters(xs[k]);  // the corner's point: an end of held pieces, crossed by later ones (CDON)
  return xs[k];
}

void Compensation::transition_circle(const Block& next_block, const ContourElement& next, const FT& next_radius,
                                     const Point& vertex) {
  Point from = equidistant_point<Kernel>(vertex, open_->end_normal(), comp_->side_radius);
  if (!close_open(from, next_block, Placed::kNormal)) return;
  run_held_back(from);
  Point to = equidistant_point<Kernel>(vertex, next.start_normal(), comp_->side_radius);
  Decimal h = coord(next_block.start, comp_->axes.applicate);
  Origin corner = origin(*open_block_, OriginKind::kTransitionCircle);
  corner.next_line = next_block.words.line, corner.next_block = next_block.words.number;
  corner.next_insert = next_block.insert;
  open(next_block, next, to, next_radius, Placed::kNormal);
  if (comp_->radius.sign() != 0) {  // TRC-G450-2: no circle for a zero radius
    // Around the outside of the corner: clockwise on the left, counter-clockwise on the right.
    emit_corner_circle(next_block, from, to, vertex, h, corner);
  }
}

bool Compensation::equidistant_exists(const ContourElement& e, FT& radius) {
  if (!e.is_arc()) return true;
  radius = equidistant_radius<Kernel>(e.radius, e.sense, comp_->side_radius);
  CGAL::Sign sign = CGAL::sign(radius);
  decide("TRC-ARC-EQ-1", e.line, sign == CGAL::POSITIVE ? "concentric" : "collapses",
         margins_kept() ? exact_mm(radius) : std::string());
  return sign == CGAL::POSITIVE;
}

void Compensation::emit_line(const Block& owner, const ExactPoint& from, const ExactPoint& to, OriginKind kind,
                             const ContourElement* offset_of, const Block* named) {
  PathPoint a = path.output(from), b = path.output(to);
  run_actions(owner, a);
  if (path.same(from, to)) return;
  PathElement e;
  e.type = ElementType::kLine, e.rapid = owner.state.motion == Motion::kRapid, e.feed = owner.state.feed;
  e.feed_type = owner.state.feed_type;
  e.start = a, e.end = b, e.origin = origin(named ? *named : owner, kind);
  hold(owner, e,
       ExactPath::line_element(owner.words.line, from, to, offset_of, comp_ ? comp_->side_radius : FT(0),
                               comp_ ? comp_->axes : PlaneAxes{0, 1, 2}));
}

void Compensation::emit_arc(const Block& owner, const ExactPoint& from, const ExactPoint& to, const ExactPoint& centre,
                            const FT& radius, bool ccw, const Origin& from_what, PlaneAxes axes) {
  PathPoint a = path.output(from);
  run_actions(owner, a);
  PathElement e;
  e.type = ElementType::kArc, e.rapid = owner.state.motion == Motion::kRapid, e.feed = owner.state.feed;
  e.feed_type = owner.state.feed_type;
  e.start = a, e.end = path.output(to), e.center = path.output(centre), e.ccw = ccw;
  e.origin = from_what;
  hold(owner, e, ExactPath::circle_element(owner.words.line, from, to, centre, radius, axes));
}

void Compensation::emit_corner_circle(const Block& owner, const Point& from, const Point& to, const Point& vertex,
                                      const Decimal& h, const Origin& corner) {
  if (from == to) return;  // PATH-ELEMENT-1: a corner circle of no turn (campaign 20261284, case 557811)
  emit_arc(owner, at({from, h}), at({to, h}), at({vertex, h}), comp_->side_radius, comp_->s < 0, corner, comp_->axes);
}

void Compensation::run_actions(const Block& b, const PathPoint& at) {
  if (actions_done_[slot(b)]) return;
  actions_done_[slot(b)] = 1;
  for (int i = 0; i < b.words.aux_count; ++i) {
    HeldRecord r;
    r.owner = &b, r.seq = seq_of(b),
    r.action = {b.words.line, b.words.number, b.words.aux[static_cast<std::size_t>(i)], at};
    held_.hold(std::move(r));
  }
}

void Compensation::release_window(const Block& b) {
  if (trace_.stopped()) return;
  held_.end_block(phase_ == Phase::kActive && b.state.collision == CollisionMode::kCdon && comp_);
}

void Compensation::open(const Block& b, const ContourElement& e, const Point& start, const FT& radius, Placed placed,
                        const std::optional<Point>& piece_start) {
  open_at_normal_start_ = placed == Placed::kNormal;
  if (e.is_arc()) {  // TRC-ARC-ELEMENT-1: where the start lies on the programmed circle
    CircleFrame f(e.a - e.centre, e.sense);
    open_from_ = f.start();
    if (placed == Placed::kCorner) open_from_ = f.signed_from(f.start(), start - e.centre);
    if (placed == Placed::kOnPiece) {
      CirclePosition piece = piece_start ? f.signed_from(f.start(), *piece_start - e.centre) : f.start();
      open_from_ = f.forward_from(piece, start - e.centre);
      open_at_normal_start_ = f.compare(open_from_, f.start()) == CGAL::ZERO;
    }
  }
  open_blended_ = false;
  open_ = e;
  open_block_ = &b;
  open_start_ = start;
  open_radius_ = radius;
}

}  // namespace cutcom::ref::detail

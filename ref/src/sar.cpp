// Stage 1, the SAR expansion of ref (sar.hpp), exact. fast decides the same clauses in double in
// fast/src/sar.cpp.
#include "sar.hpp"

#include "arc_check.hpp"

namespace cutcom::ref::detail {

void SarExpansion::take(const Block& b) {
  std::optional<PlaneOverride> over = after_sar_end(b);
  switch (sequence_.take(b, b.moves_in_plane())) {
    case SarSequence::Step::kPass:
      return forward(b, over);
    case SarSequence::Step::kHold:
      return;
    case SarSequence::Step::kApproach:
      approach(sequence_.gathered(), sequence_.p4_index());
      return sequence_.release();
    case SarSequence::Step::kRetraction:
      if (!last_contour_) return trace_.raise(10744, b, "SAR-TANGENT-1");
      return retraction(b);
    case SarSequence::Step::kAlarm:
      return trace_.raise_catalogued(sequence_.alarm(), sequence_.alarm_block());
  }
}

void SarExpansion::forward(const Block& b, const std::optional<PlaneOverride>& over) {
  if (trace_.stopped()) return;
  if (b.sar.move == SarMove::kNone && b.moves_in_plane()) last_contour_ = b, last_contour_over_ = over;
  next_.step(b, over);
}

void SarExpansion::finish() {
  if (!trace_.stopped() && sequence_.finish() == SarSequence::Step::kAlarm)
    trace_.raise(sequence_.alarm(), sequence_.alarm_block(), "SAR-TANGENT-1");
}

std::optional<PlaneOverride> SarExpansion::after_sar_end(const Block& b) {
  if (!sar_end_) return std::nullopt;
  PlaneOverride over;
  over.start = sar_end_->at;
  if (keeps_sar_end(b, sar_end_->plane))
    over.end = sar_end_->at;
  else
    sar_end_.reset();
  return over;
}

SarExpansion::SarTrc SarExpansion::sar_trc(const ModalState& st) {
  if (st.side == Side::kOff || st.edge == 0 || st.tool == 0 || !st.edge_defined) return std::nullopt;
  return compensation_side(st);  // TRC-RADIUS-2 (decided in core)
}

int SarExpansion::sar_side(const Block& b, const SarTrc& trc, const Vector& t, const Point& p4,
                           const std::optional<Point>& p0) {
  SarSide mode = b.state.sar_side;
  if (mode == SarSide::kG141) return trace_.decide("SAR-SIDE-1", b.words.line, "G141-left"), 1;
  if (mode == SarSide::kG142) return trace_.decide("SAR-SIDE-1", b.words.line, "G142-right"), -1;
  if (mode == SarSide::kG140 && trc)
    return trace_.decide("SAR-SIDE-1", b.words.line, trc->s > 0 ? "G140-left" : "G140-right"), trc->s;
  // SAR-SIDE-2: G143 (or G140 without compensation): the side of the tangent P0 lies on.
  if (!p0) {
    trace_.decide("SAR-SIDE-3", b.words.line, "implicit-end-point");
    trace_.raise(10747, b, "SAR-SIDE-3");
    return 0;
  }
  Vector off = *p0 - p4;
  FT cross = t.x() * off.y() - t.y() * off.x();
  CGAL::Sign sign = CGAL::sign(cross);
  trace_.decide("SAR-SIDE-2", b.words.line,
                sign == CGAL::POSITIVE   ? "left"
                : sign == CGAL::NEGATIVE ? "right"
                                         : "on-tangent",
                exact_mm(cross / exact_root(t.squared_length())));
  if (sign == CGAL::ZERO) {
    trace_.raise(10744, b, "SAR-SIDE-2");
    return 0;
  }
  return sign == CGAL::POSITIVE ? 1 : -1;
}

std::optional<FT> SarExpansion::sar_size(const Block& b, const SarTrc& trc, int s) {
  SarSize z = cutcom::sar_size(b, trc, s);  // SAR-DISR-1/2 (decided in core)
  trace_.decide(z.decision, b.words.line);
  if (!z.size) return trace_.raise(10742, b, z.decision.clause), std::nullopt;
  return leaf(*z.size);
}

bool SarExpansion::sar_levels(const Block& b, SarLevels& h, SarEndCase end_case, const Decimal& h4) {
  h = cutcom::sar_levels(b, end_case, h4);
  // SAR-DISRP-2, SAR-DISCL-3 (decision 9): decided in core; P2 clamped there.
  SarLevelCheck check = check_sar_levels(b, h, md_);
  if (check.retraction_plane) trace_.decide(*check.retraction_plane, b.words.line);
  if (check.reversal) trace_.decide(*check.reversal, b.words.line);
  if (check.alarm) return trace_.raise(check.alarm, b, check.alarm == 10748 ? "SAR-DISRP-2" : "SAR-DISCL-3"), false;
  set_p3_level(b, h);  // SAR-SEG-1 / SAR-SEG-2
  return true;
}

void SarExpansion::approach(std::span<const Block> g, int p4_index) {
  const Block& a = g[0];
  const Block& m = g[static_cast<std::size_t>(p4_index)];
  const Block& d = g.back();
  PlaneAxes ax = plane_axes(a.state.plane);
  if (d.is_arc() && !arc_is_consistent(d, md_, trace_)) return;
  // SAR-TANGENT-1: the start tangent of the first element that starts at P4.
  ContourElement de = d.is_arc() ? ContourElement::of_arc(d, ax) : ContourElement::of_line(d, ax);
  Vector t = de.start_dir;
  trace_.decide("SAR-TANGENT-1", a.words.line, p4_index == 0 ? "p4-in-sar-block" : "p4-in-later-block");
  Point p4 = plane_point(m.end, ax), p0 = plane_point(a.start, ax);
  SarTrc trc = sar_trc(a.state);
  SarContour c = *a.words.sar_contour;
  int s = trc ? trc->s : 1;
  if (c != SarContour::kG147) s = sar_side(a, trc, t, p4, p0);
  if (s == 0) return;
  std::optional<FT> size = sar_size(a, trc, s);
  if (!size) return;
  SarShape shape = sar_shape(c, p4, t, s, *size);
  SarPlan plan;
  plan.approach = true;
  if (!sar_levels(a, plan.h, SarEndCase::kApproach, coord(m.end, ax.applicate))) return;
  plan.p0 = a.start, plan.p4 = m.end;
  plan.p3_a = nearest_decimal(CGAL::to_double(shape.p3.x()));
  plan.p3_b = nearest_decimal(CGAL::to_double(shape.p3.y()));
  FT lead = exact_root((shape.p3 - p0).squared_length());
  plan.lead_moves = CGAL::sign(lead) != CGAL::ZERO;
  plan.sense = shape.sense;
  trace_.decide("SAR-SUB-1", a.words.line, plan.lead_moves ? "lead" : "no-lead", exact_mm(lead));
  SarSubBlocks subs;
  sar_sub_blocks(a, m, plan, subs);
  // SAR-VAR-1: $P_APR = P3, $P_AEP = P4 (programmed contour, workpiece coordinates).
  SarVariables v;
  v.line = a.words.line, v.block = a.words.number;
  v.p_apr = path_.output(ExactPoint::in_plane(shape.p3, plan.h.h3, ax));
  v.p_aep = path_.output(ExactPoint::programmed(m.end));
  sink_.sar_variables(v);
  push_sub_blocks(subs, shape, std::nullopt);
  for (std::size_t k = 1; k < g.size() && !trace_.stopped(); ++k) {
    if (static_cast<int>(k) == p4_index && subs.element_in_p4_block) {
      PlaneOverride over;
      over.start = shape.p3, over.shape = shape;
      forward(subs.p4_element, over);
    } else {
      forward(g[k]);
    }
  }
}

void SarExpansion::retraction(const Block& r) {
  PlaneAxes ax = plane_axes(r.state.plane);
  // SAR-TANGENT-1: the end tangent of the contour's last block, in its plane.
  const Block& last = *last_contour_;
  const PlaneOverride* last_over = last_contour_over_ ? &*last_contour_over_ : nullptr;
  PlaneAxes last_axes = plane_axes(last.state.plane);
  Vector t = element_with(last, last_over, last_axes).end_dir;
  trace_.decide("SAR-TANGENT-1", r.words.line, "end-of-contour");
  SarEndCase end_case = sar_end_case(r);
  trace_.decide("SAR-END-1", r.words.line,
                end_case == SarEndCase::kNoAxis          ? "ends-at-p2"
                : end_case == SarEndCase::kApplicateOnly ? "ends-at-p1"
                                                         : "programmed-p0");
  Point p4 = end_with(last, last_over).plane(last_axes);
  std::optional<Point> p0;
  if (end_case == SarEndCase::kPlaneAxis) p0 = plane_point(r.end, ax);
  SarTrc trc = sar_trc(r.previous.side != Side::kOff ? r.previous : r.state);
  SarContour c = *r.words.sar_contour;
  int s = trc ? trc->s : 1;
  if (c != SarContour::kG148) s = sar_side(r, trc, t, p4, p0);
  if (s == 0) return;
  std::optional<FT> size = sar_size(r, trc, s);
  if (!size) return;
  SarShape shape = sar_shape(c, p4, t, s, *size);
  SarPlan plan;
  plan.approach = false;
  plan.end_case = end_case;
  if (!sar_levels(r, plan.h, end_case, coord(r.start, ax.applicate))) return;
  plan.p4 = r.start;
  plan.p0 = r.end;
  plan.p3_a = nearest_decimal(CGAL::to_double(shape.p3.x()));
  plan.p3_b = nearest_decimal(CGAL::to_double(shape.p3.y()));
  FT lead = p0 ? exact_root((shape.p3 - *p0).squared_length()) : FT(0);
  plan.lead_moves = CGAL::sign(lead) != CGAL::ZERO;
  plan.sense = shape.sense;
  // SAR-END-2: G40 without end point: P0 is the tool centre at P1 (normal end of the element).
  std::optional<Point> tool_centre;
  bool deselects = r.state.side == Side::kOff && r.previous.side != Side::kOff;
  if (end_case != SarEndCase::kPlaneAxis && deselects && trc) {
    Vector n = unit_left_normal(shape.end_dir);
    tool_centre = shape.p3 + n * (FT(trc->s) * leaf(trc->r));
    plan.tc_a = nearest_decimal(CGAL::to_double(tool_centre->x()));
    plan.tc_b = nearest_decimal(CGAL::to_double(tool_centre->y()));
  } else if (end_case != SarEndCase::kPlaneAxis && deselects) {
    tool_centre = shape.p3;
    plan.tc_a = plan.p3_a, plan.tc_b = plan.p3_b;
  }
  trace_.decide("SAR-SUB-1", r.words.line, plan.lead_moves ? "lead" : "no-lead", exact_mm(lead));
  SarSubBlocks subs;
  sar_sub_blocks(r, r, plan, subs);
  push_sub_blocks(subs, shape, tool_centre);
  if (trace_.stopped()) return;
  if (end_case == SarEndCase::kPlaneAxis) {
    // SAR-END-1: without the applicate the retraction ended at P2's level, not at the reader's.
    if (plan.h.h0 != coord(r.end, ax.applicate)) {
      Point3 p = r.end;
      Decimal* coords[3] = {&p.x, &p.y, &p.z};
      *coords[ax.applicate] = plan.h.h0;
      reposition_ = p;
    }
    return;
  }
  // SAR-END-3: the next blocks start where the retraction ended.
  Point end = tool_centre ? *tool_centre : shape.p3;
  sar_end_ = SarEnd{end, r.state.plane};
  Point3 picture = r.end;
  Decimal* cs[3] = {&picture.x, &picture.y, &picture.z};
  *cs[ax.abscissa] = tool_centre ? plan.tc_a : plan.p3_a;
  *cs[ax.ordinate] = tool_centre ? plan.tc_b : plan.p3_b;
  *cs[ax.applicate] = plan.h.h0;
  reposition_ = picture;
}

void SarExpansion::push_sub_blocks(const SarSubBlocks& subs, const SarShape& shape,
                                   const std::optional<Point>& tool_centre) {
  for (int k = 0; k < subs.count && !trace_.stopped(); ++k) {
    const Block& b = subs.blocks[static_cast<std::size_t>(k)];
    PlaneOverride over;
    if (b.sar.start_at_p3) over.start = shape.p3;
    if (b.sar.end_at_p3) over.end = shape.p3;
    if (b.sar.move == SarMove::kElement) {
      over.shape = shape;
      (shape.approach ? over.start : over.end) = shape.p3;
      (shape.approach ? over.end : over.start) = shape.p4;
    }
    if (b.sar.end_at_tool_centre) over.end = *tool_centre;
    forward(b, over);
  }
}

}  // namespace cutcom::ref::detail

// Stage 1, the SAR expansion of fast (sar.hpp), in double. ref decides the same clauses exactly
// in ref/src/sar.cpp.
#include "sar.hpp"

#include <cmath>

#include "arc_check.hpp"

namespace cutcom::fast {

namespace {
Vec2 plane_of(const Point3& p, PlaneAxes a) {
  return {coord(p, a.abscissa).to_double(), coord(p, a.ordinate).to_double()};
}

}  // namespace

void SarExpansion::keep_last_contour(const Block& b) {
  copy_by_words(last_contour_.start, b.start), copy_by_words(last_contour_.end, b.end);
  // A line (most contour blocks) has neither centre nor radius: set so, not copied word by word.
  if (b.centre)
    copy_by_words(last_contour_.centre, b.centre);
  else
    last_contour_.centre.reset();
  if (b.words.cr)
    copy_by_words(last_contour_.words.cr, b.words.cr);
  else
    last_contour_.words.cr.reset();
  last_contour_.circle = b.circle, last_contour_.state.motion = b.state.motion;
  // Its SarTag stays the default: forward keeps programmed blocks only.
}

void SarExpansion::forward(const Block& b, const PlaneOverride* o, bool moves) {
  if (trace_.stopped()) return;
  if (b.sar.move == SarMove::kNone && moves) {
    keep_last_contour(b), has_last_contour_ = true, last_contour_overridden_ = o != nullptr;
    if (o) last_contour_over_ = *o;
  }
  next_.step(b, o, moves);
}

void SarExpansion::finish() {
  if (!trace_.stopped() && sequence_.finish() == SarSequence::Step::kAlarm)
    trace_.raise_catalogued(sequence_.alarm(), sequence_.alarm_block());
}

void SarExpansion::take(const Block& b) {
  // SAR-END-3: after a retraction that ended without end point the blocks start there.
  const PlaneOverride* end_over = nullptr;
  if (at_sar_end_) {
    end_over_ = PlaneOverride{};
    end_over_.axes = plane_axes(sar_end_plane_);
    end_over_.start = true, end_over_.start_ab = sar_end_;
    if (keeps_sar_end(b, sar_end_plane_))
      end_over_.end = true, end_over_.end_ab = sar_end_;
    else
      at_sar_end_ = false;
    end_over = &end_over_;
  }
  bool moves = b.moves_in_plane();  // asked once for every stage
  switch (sequence_.take(b, moves)) {
    case SarSequence::Step::kPass:
      return forward(b, end_over, moves);
    case SarSequence::Step::kHold:
      return;
    case SarSequence::Step::kApproach:
      approach(sequence_.gathered(), sequence_.p4_index());
      return sequence_.release();
    case SarSequence::Step::kRetraction:
      if (!has_last_contour_) return trace_.raise_catalogued(10744, b);
      return retraction(b);
    case SarSequence::Step::kAlarm:
      return trace_.raise_catalogued(sequence_.alarm(), sequence_.alarm_block());
  }
}

SarExpansion::SarTrc SarExpansion::sar_trc(const ModalState& st) {
  if (st.side == Side::kOff || st.edge == 0 || st.tool == 0 || !st.edge_defined) return std::nullopt;
  return compensation_side(st);  // TRC-RADIUS-2 (decided in core)
}

int SarExpansion::sar_side(const Block& b, const SarTrc& trc, Vec2 t, Vec2 p4, const std::optional<Vec2>& p0) {
  SarSide mode = b.state.sar_side;
  int line_no = b.words.line;
  if (mode == SarSide::kG141) return trace_.decide("SAR-SIDE-1", line_no, "G141-left"), 1;
  if (mode == SarSide::kG142) return trace_.decide("SAR-SIDE-1", line_no, "G142-right"), -1;
  if (mode == SarSide::kG140 && trc)
    return trace_.decide("SAR-SIDE-1", line_no, trc->s > 0 ? "G140-left" : "G140-right"), trc->s;
  if (!p0) {  // SAR-SIDE-3
    trace_.decide("SAR-SIDE-3", line_no, "implicit-end-point");
    trace_.raise_catalogued(10747, b);
    return 0;
  }
  double distance = cross(t, *p0 - p4);  // SAR-SIDE-2 (t is a unit vector)
  trace_.decide("SAR-SIDE-2", line_no, distance > 0 ? "left" : distance < 0 ? "right" : "on-tangent", distance);
  if (distance == 0) {
    trace_.raise(10744, line_no, b.words.number, "SAR-SIDE-2", b.words.source);
    return 0;
  }
  return distance > 0 ? 1 : -1;
}

bool SarExpansion::sar_size(const Block& b, const SarTrc& trc, int sd, double& size) {
  SarSize z = cutcom::sar_size(b, trc, sd);  // SAR-DISR-1/2 (decided in core)
  trace_.decide(z.decision, b.words.line);
  if (!z.size) return trace_.raise(10742, b.words, z.decision.clause), false;
  size = z.size->to_double();
  return true;
}

bool SarExpansion::sar_levels(const Block& b, SarLevels& h, SarEndCase end_case, const Decimal& h4) {
  h = cutcom::sar_levels(b, end_case, h4);
  // SAR-DISRP-2, SAR-DISCL-3 (decision 9): decided in core; P2 clamped there.
  SarLevelCheck check = check_sar_levels(b, h, md_);
  if (check.retraction_plane) trace_.decide(*check.retraction_plane, b.words.line);
  if (check.reversal) trace_.decide(*check.reversal, b.words.line);
  if (check.alarm)
    return trace_.raise(check.alarm, b.words, check.alarm == 10748 ? "SAR-DISRP-2" : "SAR-DISCL-3"), false;
  set_p3_level(b, h);  // SAR-SEG-1 / SAR-SEG-2
  return true;
}

void SarExpansion::approach(std::span<const Block> g, int p4_index) {
  const Block& a = g[0];
  const Block& m = g[static_cast<std::size_t>(p4_index)];
  const Block& d = g.back();
  PlaneAxes ax = plane_axes(a.state.plane);
  if (d.is_arc() && !arc_is_consistent(d, md_, trace_)) return;
  Vec2 t = element_in(BlockCopy::of(d), ax).start_tangent();  // SAR-TANGENT-1
  trace_.decide("SAR-TANGENT-1", a.words.line, p4_index == 0 ? "p4-in-sar-block" : "p4-in-later-block");
  Vec2 p4 = plane_of(m.end, ax), p0 = plane_of(a.start, ax);
  SarTrc trc = sar_trc(a.state);
  SarContour c = *a.words.sar_contour;
  int sd = trc ? trc->s : 1;
  if (c != SarContour::kG147) sd = sar_side(a, trc, t, p4, p0);
  if (sd == 0) return;
  double size = 0;
  if (!sar_size(a, trc, sd, size)) return;
  SarShape shape = sar_shape(c, p4, t, sd, size);
  SarPlan plan;
  plan.approach = true;
  if (!sar_levels(a, plan.h, SarEndCase::kApproach, coord(m.end, ax.applicate))) return;
  plan.p0 = a.start, plan.p4 = m.end;
  plan.p3_a = nearest_decimal(shape.p3.a * Decimal::kUnitsPerOne);
  plan.p3_b = nearest_decimal(shape.p3.b * Decimal::kUnitsPerOne);
  plan.lead_moves = p0.a != shape.p3.a || p0.b != shape.p3.b;
  plan.sense = shape.sense;
  trace_.decide("SAR-SUB-1", a.words.line, plan.lead_moves ? "lead" : "no-lead", norm(shape.p3 - p0));
  sar_sub_blocks(a, m, plan, subs_);
  // SAR-VAR-1: $P_APR = P3, $P_AEP = P4 (programmed contour, workpiece coordinates).
  SarVariables v;
  v.line = a.words.line, v.block = a.words.number;
  v.p_apr = xyz_in(shape.p3, plan.h.h3.to_double(), ax);
  v.p_aep = xyz_in(p4, plan.h.h4.to_double(), ax);
  sink_.sar_variables(v);
  push_sub_blocks(shape, std::nullopt);
  for (std::size_t k = 1; k < g.size() && !trace_.stopped(); ++k) {
    if (static_cast<int>(k) == p4_index && subs_.element_in_p4_block) {
      PlaneOverride o;
      o.axes = ax;
      o.start = true, o.start_ab = shape.p3, o.end = true, o.end_ab = p4;
      o.take_element(shape), o.tangent_after = true;
      forward(subs_.p4_element, &o);
    } else {
      forward(g[k]);
    }
  }
}

void SarExpansion::retraction(const Block& block) {
  PlaneAxes ax = plane_axes(block.state.plane);
  BlockCopy copy = BlockCopy::of(last_contour_);
  if (last_contour_overridden_) last_contour_over_.apply(copy);
  Element last = element_in(copy, ax);
  Vec2 t = last.end_tangent(), p4 = last.end;  // SAR-TANGENT-1
  trace_.decide("SAR-TANGENT-1", block.words.line, "end-of-contour");
  SarEndCase end_case = sar_end_case(block);
  trace_.decide("SAR-END-1", block.words.line,
                end_case == SarEndCase::kNoAxis          ? "ends-at-p2"
                : end_case == SarEndCase::kApplicateOnly ? "ends-at-p1"
                                                         : "programmed-p0");
  std::optional<Vec2> p0;
  if (end_case == SarEndCase::kPlaneAxis) p0 = plane_of(block.end, ax);
  SarTrc trc = sar_trc(block.previous.side != Side::kOff ? block.previous : block.state);
  SarContour c = *block.words.sar_contour;
  int sd = trc ? trc->s : 1;
  if (c != SarContour::kG148) sd = sar_side(block, trc, t, p4, p0);
  if (sd == 0) return;
  double size = 0;
  if (!sar_size(block, trc, sd, size)) return;
  SarShape shape = sar_shape(c, p4, t, sd, size);
  SarPlan plan;
  plan.approach = false;
  plan.end_case = end_case;
  if (!sar_levels(block, plan.h, end_case, coord(block.start, ax.applicate))) return;
  plan.p4 = block.start, plan.p0 = block.end;
  plan.p3_a = nearest_decimal(shape.p3.a * Decimal::kUnitsPerOne);
  plan.p3_b = nearest_decimal(shape.p3.b * Decimal::kUnitsPerOne);
  plan.lead_moves = p0 && (p0->a != shape.p3.a || p0->b != shape.p3.b);
  plan.sense = shape.sense;
  // SAR-END-2: G40 without end point: P0 is the tool centre at P1 (normal end of the element).
  std::optional<Vec2> tool_centre;
  bool deselects = block.state.side == Side::kOff && block.previous.side != Side::kOff;
  if (end_case != SarEndCase::kPlaneAxis && deselects)
    tool_centre = trc ? Element::offset(shape.p3, shape.end_unit, trc->s * trc->r.to_double()) : shape.p3;
  if (tool_centre) {
    plan.tc_a = nearest_decimal(tool_centre->a * Decimal::kUnitsPerOne);
    plan.tc_b = nearest_decimal(tool_centre->b * Decimal::kUnitsPerOne);
  }
  trace_.decide("SAR-SUB-1", block.words.line, plan.lead_moves ? "lead" : "no-lead", p0 ? norm(shape.p3 - *p0) : 0.0);
  sar_sub_blocks(block, block, plan, subs_);
  push_sub_blocks(shape, tool_centre);
  if (trace_.stopped()) return;
  if (end_case == SarEndCase::kPlaneAxis) {
    // SAR-END-1: without the applicate the retraction ended at P2's level, not at the reader's.
    if (plan.h.h0 != coord(block.end, ax.applicate)) {
      Point3 p = block.end;
      Decimal* coords[3] = {&p.x, &p.y, &p.z};
      *coords[ax.applicate] = plan.h.h0;
      reposition_ = p;
    }
    return;
  }
  // SAR-END-3: the next blocks start where the retraction ended.
  at_sar_end_ = true;
  sar_end_ = tool_centre ? *tool_centre : shape.p3;
  sar_end_plane_ = block.state.plane;
  Point3 picture = block.end;
  Decimal* cs[3] = {&picture.x, &picture.y, &picture.z};
  *cs[ax.abscissa] = tool_centre ? plan.tc_a : plan.p3_a;
  *cs[ax.ordinate] = tool_centre ? plan.tc_b : plan.p3_b;
  *cs[ax.applicate] = plan.h.h0;
  reposition_ = picture;
}

void SarExpansion::push_sub_blocks(const SarShape& shape, const std::optional<Vec2>& tool_centre) {
  PlaneAxes ax = plane_axes(subs_.blocks[0].state.plane);
  for (int k = 0; k < subs_.count && !trace_.stopped(); ++k) {
    const Block& b = subs_.blocks[static_cast<std::size_t>(k)];
    PlaneOverride o;
    o.axes = ax;
    if (b.sar.start_at_p3) o.start = true, o.start_ab = shape.p3;
    if (b.sar.end_at_p3) o.end = true, o.end_ab = shape.p3;
    if (b.sar.move == SarMove::kElement) {
      o.start = o.end = true;
      o.start_ab = shape.approach ? shape.p3 : shape.p4;
      o.end_ab = shape.approach ? shape.p4 : shape.p3;
      o.take_element(shape);
      (shape.approach ? o.tangent_after : o.tangent_before) = true;
    }
    if (b.sar.end_at_tool_centre) o.end = true, o.end_ab = *tool_centre;
    forward(b, &o);
  }
}

}  // namespace cutcom::fast

// ref: smooth approach and retraction (spec sar.md). The SAR block is expanded into sub-blocks
// that run through the compensation as if programmed (SAR-TRC-1); their points are exact: P3
// has one square root (the unit tangent), the applicates are decimals.
#include "reference.hpp"

namespace cutcom::ref::detail {

void Reference::take(Block b) {
  if (!stopped_ && !b.notice.empty()) sink_.notice({b.words.line, b.notice_clause, b.notice});  // the reader's
  std::optional<PlaneOverride> over = after_sar_end(b);
  if (stopped_) return;
  switch (sar_seq_.take(b)) {
    case SarSequence::Step::kPass:
      return push(b, over);
    case SarSequence::Step::kHold:
      return;
    case SarSequence::Step::kApproach:
      sar_approach(sar_seq_.gathered(), sar_seq_.p4_index());
      return sar_seq_.release();
    case SarSequence::Step::kRetraction:
      if (last_contour_ < 0) return raise(10744, b, "SAR-TANGENT-1");
      return sar_retraction(b, program_[static_cast<std::size_t>(last_contour_)]);
    case SarSequence::Step::kAlarm: {
      const AlarmInfo* info = find_alarm(sar_seq_.alarm());
      return raise(sar_seq_.alarm(), sar_seq_.alarm_block(), info ? info->clause : std::string_view{});
    }
  }
}

void Reference::push(Block b, const std::optional<PlaneOverride>& over) {
  if (stopped_) return;
  b.index = static_cast<int>(program_.size());
  if (over) overrides_[b.index] = *over;
  program_.push_back(b);
  actions_done_.push_back(false);
  const Block& kept = program_.back();
  if (kept.moves_in_plane()) ++traversing_;
  if (kept.sar.move == SarMove::kNone && kept.moves_in_plane()) last_contour_ = kept.index;
  seq_.push_back(traversing_);
  step(kept);
  release_window(kept);
}

ExactPoint Reference::start_of(const Block& b) const {
  auto it = overrides_.find(b.index);
  if (it == overrides_.end() || !it->second.start) return at(b.start);
  return ExactPoint::in_plane(*it->second.start, coord(b.start, plane_axes(b.state.plane).applicate),
                              plane_axes(b.state.plane));
}

ExactPoint Reference::end_of(const Block& b) const {
  auto it = overrides_.find(b.index);
  if (it == overrides_.end() || !it->second.end) return at(b.end);
  return ExactPoint::in_plane(*it->second.end, coord(b.end, plane_axes(b.state.plane).applicate),
                              plane_axes(b.state.plane));
}

ContourElement Reference::element_of(const Block& b) const {
  PlaneAxes axes = comp_ ? comp_->axes : plane_axes(b.state.plane);
  auto it = overrides_.find(b.index);
  if (it == overrides_.end()) return b.is_arc() ? ContourElement::of_arc(b, axes) : ContourElement::of_line(b, axes);
  if (it->second.shape) return sar_element(*it->second.shape, b);
  return exact_line(b, start_of(b).plane(axes), end_of(b).plane(axes));
}

// SAR-END-3: after a retraction that ended without end point (cases 1 and 2) the tool stands at
// an exact point off the decimal grid; the blocks after it start there.
std::optional<PlaneOverride> Reference::after_sar_end(const Block& b) {
  if (!sar_end_) return std::nullopt;
  PlaneOverride over;
  over.start = sar_end_->at;
  if (keeps_sar_end(b, sar_end_->plane))
    over.end = sar_end_->at;
  else
    sar_end_.reset();
  return over;
}

Reference::SarTrc Reference::sar_trc(const ModalState& st) {
  if (st.side == Side::kOff || st.edge == 0 || st.tool == 0 || !st.edge_defined) return std::nullopt;
  return compensation_side(st);  // TRC-RADIUS-2 (decided in core)
}

int Reference::sar_side(const Block& b, const SarTrc& trc, const Vector& t, const Point& p4,
                        const std::optional<Point>& p0) {
  SarSide mode = b.state.sar_side;
  if (mode == SarSide::kG141) return decide("SAR-SIDE-1", b.words.line, "G141-left"), 1;
  if (mode == SarSide::kG142) return decide("SAR-SIDE-1", b.words.line, "G142-right"), -1;
  if (mode == SarSide::kG140 && trc)
    return decide("SAR-SIDE-1", b.words.line, trc->s > 0 ? "G140-left" : "G140-right"), trc->s;
  // SAR-SIDE-2: G143 (or G140 without compensation): the side of the tangent P0 lies on.
  if (!p0) {
    decide("SAR-SIDE-3", b.words.line, "implicit-end-point");
    raise(10747, b, "SAR-SIDE-3");
    return 0;
  }
  Vector off = *p0 - p4;
  FT cross = t.x() * off.y() - t.y() * off.x();
  CGAL::Sign sign = CGAL::sign(cross);
  decide("SAR-SIDE-2", b.words.line,
         sign == CGAL::POSITIVE   ? "left"
         : sign == CGAL::NEGATIVE ? "right"
                                  : "on-tangent",
         exact_mm(cross / exact_root(t.squared_length())));
  if (sign == CGAL::ZERO) {
    raise(10744, b, "SAR-SIDE-2");
    return 0;
  }
  return sign == CGAL::POSITIVE ? 1 : -1;
}

std::optional<FT> Reference::sar_size(const Block& b, const SarTrc& trc, int s) {
  SarSize z = cutcom::sar_size(b, trc, s);  // SAR-DISR-1/2 (decided in core)
  decide(z.decision, b.words.line);
  if (!z.size) return raise(10742, b, z.decision.clause), std::nullopt;
  return leaf(*z.size);
}

bool Reference::sar_levels(const Block& b, SarLevels& h, SarEndCase end_case, const Decimal& h4) {
  h = cutcom::sar_levels(b, end_case, h4);
  // SAR-DISRP-2, SAR-DISCL-3 (decision 9): decided in core; P2 clamped there.
  SarLevelCheck check = check_sar_levels(b, h, md_);
  if (check.retraction_plane) decide(*check.retraction_plane, b.words.line);
  if (check.reversal) decide(*check.reversal, b.words.line);
  if (check.alarm) return raise(check.alarm, b, check.alarm == 10748 ? "SAR-DISRP-2" : "SAR-DISCL-3"), false;
  set_p3_level(b, h);  // SAR-SEG-1 / SAR-SEG-2
  return true;
}

void Reference::sar_approach(std::span<const Block> g, int p4_index) {
  const Block& a = g[0];
  const Block& m = g[static_cast<std::size_t>(p4_index)];
  const Block& d = g.back();
  PlaneAxes ax = plane_axes(a.state.plane);
  if (d.is_arc() && !arc_is_consistent(d)) return;
  // SAR-TANGENT-1: the start tangent of the first element that starts at P4.
  ContourElement de = d.is_arc() ? ContourElement::of_arc(d, ax) : ContourElement::of_line(d, ax);
  Vector t = de.start_dir;
  decide("SAR-TANGENT-1", a.words.line, p4_index == 0 ? "p4-in-sar-block" : "p4-in-later-block");
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
  decide("SAR-SUB-1", a.words.line, plan.lead_moves ? "lead" : "no-lead", exact_mm(lead));
  SarSubBlocks subs;
  sar_sub_blocks(a, m, plan, subs);
  // SAR-VAR-1: $P_APR = P3, $P_AEP = P4 (programmed contour, workpiece coordinates).
  SarVariables v;
  v.line = a.words.line, v.block = a.words.number;
  v.p_apr = path.output(ExactPoint::in_plane(shape.p3, plan.h.h3, ax));
  v.p_aep = path.output(at(m.end));
  sink_.sar_variables(v);
  push_sub_blocks(subs, shape, std::nullopt);
  for (std::size_t k = 1; k < g.size() && !stopped_; ++k) {
    if (static_cast<int>(k) == p4_index && subs.element_in_p4_block) {
      PlaneOverride over;
      over.start = shape.p3, over.shape = shape;
      push(subs.p4_element, over);
    } else {
      push(g[k]);
    }
  }
}

void Reference::sar_retraction(const Block& r, const Block& last) {
  PlaneAxes ax = plane_axes(r.state.plane);
  // SAR-TANGENT-1: the end tangent of the contour's last block.
  Vector t = element_of(last).end_dir;
  decide("SAR-TANGENT-1", r.words.line, "end-of-contour");
  SarEndCase end_case = sar_end_case(r);
  decide("SAR-END-1", r.words.line,
         end_case == SarEndCase::kNoAxis          ? "ends-at-p2"
         : end_case == SarEndCase::kApplicateOnly ? "ends-at-p1"
                                                  : "programmed-p0");
  Point p4 = plane_end(last);
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
  decide("SAR-SUB-1", r.words.line, plan.lead_moves ? "lead" : "no-lead", exact_mm(lead));
  SarSubBlocks subs;
  sar_sub_blocks(r, r, plan, subs);
  push_sub_blocks(subs, shape, tool_centre);
  if (stopped_) return;
  if (end_case == SarEndCase::kPlaneAxis) {
    // SAR-END-1: without the applicate the retraction ended at P2's level, not at the reader's.
    if (plan.h.h0 != coord(r.end, ax.applicate)) {
      Point3 p = r.end;
      Decimal* coords[3] = {&p.x, &p.y, &p.z};
      *coords[ax.applicate] = plan.h.h0;
      reader_->set_position(p);
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
  reader_->set_position(picture);
}

void Reference::push_sub_blocks(const SarSubBlocks& subs, const SarShape& shape,
                                const std::optional<Point>& tool_centre) {
  for (int k = 0; k < subs.count && !stopped_; ++k) {
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
    push(b, over);
  }
}

}  // namespace cutcom::ref::detail

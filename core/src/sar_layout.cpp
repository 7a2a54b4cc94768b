// SAR-SUB-1, SAR-FEED-1/2, SAR-ACTION-1, SAR-TRC-1, SAR-END-1/2: the sub-blocks of a SAR block.
#include "cutcom/sar_layout.hpp"

#include <cmath>

#include "cutcom/engine.hpp"

namespace cutcom {

SarEndCase sar_end_case(const Block& sar) {
  if (sar.programs_plane_axis()) return SarEndCase::kPlaneAxis;
  PlaneAxes a = plane_axes(sar.state.plane);
  return sar.words.axis[static_cast<std::size_t>(a.applicate)].present ? SarEndCase::kApplicateOnly
                                                                       : SarEndCase::kNoAxis;
}

SarLevels sar_levels(const Block& b, SarEndCase end_case, const Decimal& h4) {
  PlaneAxes ax = plane_axes(b.state.plane);
  const BlockWords& w = b.words;
  SarLevels h;
  h.h4 = h4;
  auto level = [&](const AxisWord& word) {  // SAR-DISCL-1 / SAR-DISRP-1: AC() or from P4's plane
    return word.mode == ValueMode::kAbsolute ? word.value : h4 + word.value;
  };
  bool applicate = w.axis[static_cast<std::size_t>(ax.applicate)].present;
  if (end_case == SarEndCase::kApproach) {
    h.h0 = coord(b.start, ax.applicate);
    h.h1 = w.disrp.present ? level(w.disrp) : h.h0;
    h.h2 = w.discl.present ? level(w.discl) : h.h1;  // SAR-DISCL-2 (decision 7)
  } else if (end_case == SarEndCase::kNoAxis || (end_case == SarEndCase::kPlaneAxis && !applicate)) {
    // SAR-END-1, case 1 (and case 3 without the applicate): the retraction ends at P2's level.
    if (w.disrp.present) throw UnsupportedError(w.line, "DISRP in a SAR retraction that ends at P2");
    h.h0 = h.h1 = h.h2 = w.discl.present ? level(w.discl) : h4;
  } else {
    // Case 2 (ends at P1, the programmed level) and case 3 with the applicate.
    if (end_case == SarEndCase::kApplicateOnly && w.disrp.present)
      throw UnsupportedError(w.line, "DISRP in a SAR retraction that ends at P1 (the programmed applicate)");
    h.h0 = coord(b.end, ax.applicate);
    h.h1 = w.disrp.present ? level(w.disrp) : h.h0;
    h.h2 = w.discl.present ? level(w.discl) : h.h1;
  }
  // SAR-DISCL-2 (decision 12): G340 with DISCL=0 or without DISCL: one spatial element from P1.
  bool g340 = b.state.sar_segmentation == SarSegmentation::kG340;
  if (g340 && (!w.discl.present || (w.discl.mode != ValueMode::kAbsolute && w.discl.value.is_zero()))) h.h2 = h.h1;
  return h;
}

bool keeps_sar_end(const Block& b, Plane plane) {
  if (b.is_sar_block() && (*b.words.sar_contour == SarContour::kG147 || *b.words.sar_contour == SarContour::kG247 ||
                           *b.words.sar_contour == SarContour::kG347))
    throw UnsupportedError(b.words.line,
                           "SAR approach from where a SAR retraction without end point ended (program both plane axes "
                           "before it)");
  PlaneAxes a = plane_axes(plane);
  const AxisWord& u = b.words.axis[static_cast<std::size_t>(a.abscissa)];
  const AxisWord& v = b.words.axis[static_cast<std::size_t>(a.ordinate)];
  if (!u.present && !v.present && b.state.plane == plane && !b.is_arc()) return true;
  auto absolute = [&](const AxisWord& w) {
    return w.mode == ValueMode::kAbsolute || (w.mode == ValueMode::kModal && b.state.absolute);
  };
  if (!u.present || !v.present || !absolute(u) || !absolute(v) || b.is_arc() || b.state.plane != plane)
    throw UnsupportedError(b.words.line,
                           "after a SAR retraction without end point the next move in the plane must program both "
                           "plane axes absolutely, in a straight block");
  return false;
}

Decimal nearest_decimal(double units) { return Decimal::from_units(static_cast<Int128>(std::llround(units))); }

namespace {

Point3 point(PlaneAxes a, const Decimal& ab, const Decimal& ord, const Decimal& h) {
  Point3 p;
  Decimal* c[3] = {&p.x, &p.y, &p.z};
  *c[a.abscissa] = ab, *c[a.ordinate] = ord, *c[a.applicate] = h;
  return p;
}

Decimal feed_of(const Block& sar, FeedType& type) {
  const BlockWords& w = sar.words;
  type = w.fad_mode == FadMode::kPm   ? FeedType::kG94
         : w.fad_mode == FadMode::kPr ? FeedType::kG95
                                      : sar.state.feed_type;
  return *w.fad;
}

// A sub-block: the SAR block's words and state with its own motion, feed, points and tag.
Block sub(const Block& from, SarMove move, const Point3& start, const Point3& end, Motion motion, const Decimal& feed,
          FeedType type, bool plane_motion) {
  Block b = from;
  b.words.aux_count = 0;
  b.words.side.reset();
  b.words.tool.reset(), b.words.edge.reset(), b.words.offn.reset();
  b.state.motion = motion;
  b.state.feed = feed;
  b.state.feed_type = type;
  b.start = start, b.end = end;
  b.centre.reset();
  b.words.cr.reset();
  for (AxisWord& c : b.words.centre) c.present = false;
  b.circle = motion == Motion::kArcCw || motion == Motion::kArcCcw;
  b.sar = SarTag{};
  b.sar.move = move;
  b.sar.plane_motion = plane_motion;
  b.sar.sar_line = from.words.line;
  return b;
}

Motion element_motion(int sense) { return sense == 0 ? Motion::kLinear : sense > 0 ? Motion::kArcCcw : Motion::kArcCw; }

void push(SarSubBlocks& out, const Block& b) { out.blocks[static_cast<std::size_t>(out.count++)] = b; }

// SAR-ACTION-1 / SAR-TRC-1: the first (approach) or last (retraction) sub-block carries the SAR
// block's actions and its G41/G42/G40, T, D, OFFN words; the others carry none of them.
void give_words(const Block& sar, Block& b) {
  b.words.aux = sar.words.aux, b.words.aux_count = sar.words.aux_count;
  b.words.side = sar.words.side;
  b.words.tool = sar.words.tool, b.words.edge = sar.words.edge, b.words.offn = sar.words.offn;
}

// Each sub-block's `previous` is the state in force for the one before.
void chain(const Block& sar, SarSubBlocks& out) {
  ModalState before = sar.previous;
  for (int k = 0; k < out.count; ++k) {
    Block& b = out.blocks[static_cast<std::size_t>(k)];
    b.previous = before;
    before = b.state;
  }
}

void approach(const Block& a, const Block& m, const SarPlan& p, SarSubBlocks& out) {
  PlaneAxes ax = plane_axes(a.state.plane);
  const SarLevels& h = p.h;
  Point3 p1 = point(ax, p.p3_a, p.p3_b, h.h1), p2 = point(ax, p.p3_a, p.p3_b, h.h2);
  Point3 p3 = point(ax, p.p3_a, p.p3_b, h.h3);
  // SAR-FEED-1: up to P2 at the velocity of the block before (rapid with G0, decision 15).
  Motion before = a.previous.motion == Motion::kRapid ? Motion::kRapid : Motion::kLinear;
  const Decimal& old_feed = a.previous.feed;
  FeedType fad_type = a.state.feed_type;
  Decimal fad = a.words.fad ? feed_of(a, fad_type) : a.state.feed;
  if (p.lead_moves || h.h0 != h.h1) {
    Block b = sub(a, SarMove::kLead, p.p0, p1, before, old_feed, a.previous.feed_type, p.lead_moves);
    b.sar.end_at_p3 = true;
    push(out, b);
  }
  if (h.h1 != h.h2) {
    Block b = sub(a, SarMove::kFastInfeed, p1, p2, before, old_feed, a.previous.feed_type, false);
    b.sar.start_at_p3 = b.sar.end_at_p3 = true;
    push(out, b);
  }
  if (h.h2 != h.h3) {
    Block b = sub(a, SarMove::kSlowInfeed, p2, p3, Motion::kLinear, fad, fad_type, false);
    b.sar.start_at_p3 = b.sar.end_at_p3 = true;
    push(out, b);
  }
  // SAR-FEED-1: the element at F (from P3), or at FAD with G340 (from P2 = P3).
  bool g340_fad = a.state.sar_segmentation == SarSegmentation::kG340 && a.words.fad;
  FeedType el_type = g340_fad ? fad_type : m.state.feed_type;
  Decimal el_feed = g340_fad ? fad : m.state.feed;
  Block el = sub(m, SarMove::kElement, p3, p.p4, element_motion(p.sense), el_feed, el_type, true);
  el.sar.start_at_p3 = true;
  el.sar.sar_line = a.words.line;
  if (&m == &a) {
    push(out, el);
  } else {
    // SAR-P4-2: the element runs in the later block, which keeps its own words; the SAR block's
    // last sub-block is still output, without motion in the plane, if nothing else is.
    el.words.aux = m.words.aux, el.words.aux_count = m.words.aux_count;
    el.words.side = m.words.side;
    el.previous = m.previous;
    out.element_in_p4_block = true;
    out.p4_element = el;
    if (out.count == 0) {
      Block b = sub(a, SarMove::kLead, p1, p1, before, old_feed, a.previous.feed_type, false);
      b.sar.start_at_p3 = b.sar.end_at_p3 = true;
      push(out, b);
    }
  }
  give_words(a, out.blocks[0]);
  chain(a, out);
}

void retraction(const Block& r, const SarPlan& p, SarSubBlocks& out) {
  PlaneAxes ax = plane_axes(r.state.plane);
  const SarLevels& h = p.h;
  Point3 p1 = point(ax, p.p3_a, p.p3_b, h.h1), p2 = point(ax, p.p3_a, p.p3_b, h.h2);
  Point3 p3 = point(ax, p.p3_a, p.p3_b, h.h3);
  // SAR-FEED-2: the element (and the slow infeed) at the old feed, from P2 the new F.
  Motion after = r.state.motion == Motion::kRapid ? Motion::kRapid : Motion::kLinear;
  const Decimal& old_feed = r.previous.feed;
  FeedType fad_type = r.previous.feed_type;
  Decimal fad = r.words.fad ? feed_of(r, fad_type) : old_feed;
  bool g340_fad = r.state.sar_segmentation == SarSegmentation::kG340 && r.words.fad;
  Block el = sub(r, SarMove::kElement, p.p4, p3, element_motion(p.sense), g340_fad ? fad : old_feed,
                 g340_fad ? fad_type : r.previous.feed_type, true);
  el.sar.end_at_p3 = true;
  push(out, el);
  if (h.h3 != h.h2) {
    Block b = sub(r, SarMove::kSlowInfeed, p3, p2, Motion::kLinear, fad, fad_type, false);
    b.sar.start_at_p3 = b.sar.end_at_p3 = true;
    push(out, b);
  }
  if (h.h2 != h.h1) {
    Block b = sub(r, SarMove::kFastInfeed, p2, p1, after, r.state.feed, r.state.feed_type, false);
    b.sar.start_at_p3 = b.sar.end_at_p3 = true;
    push(out, b);
  }
  if (p.end_case == SarEndCase::kPlaneAxis) {
    if (p.lead_moves || h.h1 != h.h0) {
      Point3 p0 = p.p0;
      Decimal* c[3] = {&p0.x, &p0.y, &p0.z};
      *c[ax.applicate] = h.h0;  // SAR-END-1: without the applicate, P0 is at P2's level
      Block b = sub(r, SarMove::kLead, p1, p0, after, r.state.feed, r.state.feed_type, p.lead_moves);
      b.sar.start_at_p3 = true;
      push(out, b);
    }
  } else if (r.state.side == Side::kOff && r.previous.side != Side::kOff) {
    // SAR-END-2: G40 without an end point: P1 -> P0, P0 the tool centre at P1.
    Point3 tc = point(ax, p.tc_a, p.tc_b, h.h1);
    Block b = sub(r, SarMove::kEndPath, p1, tc, after, r.state.feed, r.state.feed_type, true);
    b.sar.start_at_p3 = true;
    b.sar.end_at_tool_centre = true;
    push(out, b);
  }
  // SAR-TRC-1: all but the last sub-block keep the compensation in force before the SAR block.
  for (int k = 0; k + 1 < out.count; ++k) out.blocks[static_cast<std::size_t>(k)].state.side = r.previous.side;
  give_words(r, out.blocks[static_cast<std::size_t>(out.count - 1)]);
  chain(r, out);
}

}  // namespace

void sar_sub_blocks(const Block& sar, const Block& p4_block, const SarPlan& plan, SarSubBlocks& out) {
  out.count = 0;
  out.element_in_p4_block = false;
  if (plan.approach)
    approach(sar, p4_block, plan, out);
  else
    retraction(sar, plan, out);
}

}  // namespace cutcom

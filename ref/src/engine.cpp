// ref's walk through the program. Each step cites the spec clause it implements; geometry comes
// from equidistant.hpp (exact constructions) and contour_element / contour_angle (exact predicates).
#include "cutcom/ref/engine.hpp"

#include <algorithm>
#include <climits>
#include <deque>
#include <optional>

#include "bottleneck.hpp"
#include "contour_angle.hpp"
#include "contour_element.hpp"
#include "edge_strategy.hpp"
#include "equidistant.hpp"
#include "exact_angle.hpp"
#include "exact_path.hpp"
#include "exact_root.hpp"
#include "held_output.hpp"

namespace cutcom::ref {

namespace {

// A point of the tool-centre path: exact in the plane, the applicate as programmed.
struct CentrePoint {
  Point plane;
  Decimal applicate;
};

class Reference {
 public:
  Reference(const MachineData& md, PathSink& sink) : md_(md), sink_(sink), held_(sink, path) {}

  // Blocks are read one by one, as a control reads them, and kept: ref may look back at any of
  // them (a deque keeps references to earlier blocks valid).
  bool run(ProgramReader& reader) {
    Block b;
    while (!stopped_ && reader.next(b)) {
      program_.push_back(b);
      actions_done_.push_back(false);
      if (b.moves_in_plane()) ++traversing_;
      seq_.push_back(traversing_);
      step(program_.back());
      release_window(program_.back());
    }
    // NC-ERR-2: a reading error anywhere rejects the program, even after an alarm.
    while (stopped_ && reader.next(b)) {
    }
    if (!stopped_) end_of_program();
    held_.release_before(INT_MAX);
    return !stopped_;
  }

  ExactPath path;

 private:
  enum class Phase { kOff, kApproach, kActive };

  // --- the compensation in force ---------------------------------------------------------------
  struct Compensation {
    Plane plane;
    PlaneAxes axes;
    Side side;
    int s;           // +1 left, -1 right (TRC-RADIUS-2 applied)
    FT side_radius;  // s * r, r = |effective radius| in units
    Decimal radius;  // r
    ActiveEdge edge;
  };

  // --- trace, alarms, output ---------------------------------------------------------------------
  void decide(std::string_view clause, int line, std::string_view branch) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch;
    sink_.decision(d);
  }
  void decide(std::string_view clause, int line, std::string_view branch, std::string margin) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch, d.has_margin = true, d.margin_exact = std::move(margin);
    sink_.decision(d);
  }
  void raise(int number, const Block& at, std::string_view clause = {}) {
    flush_approach();  // ALARM-1: what was decided before the alarm is output
    held_.release_before(INT_MAX);
    sink_.alarm(make_alarm(number, at.words.line, at.words.number, clause));
    stopped_ = true;
  }

  // Auxiliary functions of a block run before its first element (PATH-ACTION-1).
  void run_actions(const Block& b, const PathPoint& at) {
    if (actions_done_[static_cast<std::size_t>(b.index)]) return;
    actions_done_[static_cast<std::size_t>(b.index)] = true;
    for (int i = 0; i < b.words.aux_count; ++i) {
      HeldRecord r;
      r.owner = &b, r.seq = seq_of(b),
      r.action = {b.words.line, b.words.number, b.words.aux[static_cast<std::size_t>(i)], at};
      held_.hold(std::move(r));
    }
  }
  int seq_of(const Block& b) const { return seq_[static_cast<std::size_t>(b.index)]; }
  void hold(const Block& owner, const PathElement& e, ExactPath::Element exact) {
    HeldRecord r;
    r.owner = &owner, r.seq = seq_of(owner), r.element = e, r.exact = std::move(exact);
    held_.hold(std::move(r));
  }
  // TRC-CD-1: with CDON in force the output of the last MD20240 traversing blocks waits (a later
  // block may cut it); otherwise it goes out block by block.
  void release_window(const Block& b) {
    if (stopped_) return;
    bool window = phase_ == Phase::kActive && b.state.collision == CollisionMode::kCdon && comp_;
    held_.release_before(window ? traversing_ + 1 - md_.cutcom_maxnum_check_blocks : INT_MAX);
  }

  Origin origin(const Block& b, OriginKind kind) const {
    Origin o;
    o.kind = kind, o.line = b.words.line, o.block = b.words.number;
    return o;
  }

  // PATH-ELEMENT-1: a straight element; zero-length ones are not output.
  void emit_line(const Block& owner, const ExactPoint& from, const ExactPoint& to, OriginKind kind,
                 const ContourElement* offset_of = nullptr, const Block* named = nullptr) {
    PathPoint a = path.output(from), b = path.output(to);
    run_actions(owner, a);
    if (path.same(from, to)) return;
    PathElement e;
    e.type = ElementType::kLine, e.rapid = owner.state.motion == Motion::kRapid, e.feed = owner.state.feed;
    e.start = a, e.end = b, e.origin = origin(named ? *named : owner, kind);
    hold(owner, e,
         ExactPath::line_element(owner.words.line, from, to, offset_of, comp_ ? comp_->side_radius : FT(0),
                                 comp_ ? comp_->axes : PlaneAxes{0, 1, 2}));
  }

  // A circular element about `centre` (at the applicate of its start), radius `radius` in the plane;
  // `owner` gives feed, motion type and actions.
  void emit_arc(const Block& owner, const ExactPoint& from, const ExactPoint& to, const ExactPoint& centre,
                const FT& radius, bool ccw, const Origin& from_what, PlaneAxes axes) {
    PathPoint a = path.output(from);
    run_actions(owner, a);
    PathElement e;
    e.type = ElementType::kArc, e.rapid = owner.state.motion == Motion::kRapid, e.feed = owner.state.feed;
    e.start = a, e.end = path.output(to), e.center = path.output(centre), e.ccw = ccw;
    e.origin = from_what;
    hold(owner, e, ExactPath::circle_element(owner.words.line, from, to, centre, radius, axes));
  }

  ExactPoint at(const CentrePoint& p) const { return ExactPoint::in_plane(p.plane, p.applicate, comp_->axes); }
  static ExactPoint at(const Point3& p) { return ExactPoint::programmed(p); }

  // --- one block ---------------------------------------------------------------------------------
  void step(const Block& b) {
    if (b.words.disc && b.words.disc->sign() > 0)  // TRC-DISC-1
      throw UnsupportedError(b.words.line, "DISC greater than 0 (a distorted transition circle)");
    if (b.is_arc() && !arc_is_consistent(b)) return;
    switch (phase_) {
      case Phase::kOff:
        return compensation_off(b);
      case Phase::kApproach:
        return waiting_for_contour(b);
      case Phase::kActive:
        return compensation_active(b);
    }
  }

  // ARC-CENTRE-2: a circle's end point may miss the circle about its programmed centre by at most
  // max(MD21000, MD21010 * radius); beyond, alarm 14040. CR= circles are not supported yet.
  bool arc_is_consistent(const Block& b) {
    PlaneAxes axes = plane_axes(b.state.plane);
    if (!b.centre) {  // ARC-CR-1: a CR= circle must reach its end point
      CrReach reach = cr_reach(b, axes);
      decide("ARC-CR-1", b.words.line, reach.reachable ? "circle" : "unreachable", exact_mm(reach.margin));
      if (!reach.reachable) raise(14040, b, "ARC-CR-1");
      return reach.reachable;
    }
    ArcTolerance t = arc_end_point_check(b, axes, md_.circle_error_const, md_.circle_error_factor);
    decide("ARC-CENTRE-2", b.words.line, t.within ? "within" : "beyond", exact_mm(t.excess));
    if (!t.within) raise(14040, b);
    return t.within;
  }

  ContourElement element_of(const Block& b) const {
    return b.is_arc() ? ContourElement::of_arc(b, comp_->axes) : ContourElement::of_line(b, comp_->axes);
  }

  void run_uncompensated(const Block& b) {
    if (!b.is_arc()) return emit_line(b, at(b.start), at(b.end), OriginKind::kProgrammed);
    // A programmed circle, about its (corrected, ARC-CENTRE-1) centre.
    PlaneAxes axes = plane_axes(b.state.plane);
    ContourElement arc = ContourElement::of_arc(b, axes);
    Decimal h = coord(b.start, axes.applicate);
    emit_arc(b, at(b.start), at(b.end), ExactPoint::in_plane(arc.centre, h, axes), arc.radius, arc.sense > 0,
             origin(b, OriginKind::kProgrammed), axes);
  }

  // TRC-SEL-*: may this block select compensation?
  void compensation_off(const Block& b) {
    if (b.state.side == Side::kOff) return run_uncompensated(b);
    if (b.is_arc()) return raise(10753, b);  // TRC-SEL-2
    if (!b.programs_plane_axis()) {          // TRC-SEL-4
      decide("TRC-SEL-4", b.words.line, "no-plane-axis");
      return run_uncompensated(b);
    }
    if (b.state.tool == 0) return raise(10750, b);  // TRC-SEL-6
    if (b.state.edge == 0) {                        // TRC-SEL-5
      decide("TRC-SEL-5", b.words.line, "d0");
      if (!d0_noticed_) sink_.notice({b.words.line, "TRC-SEL-5", "G41/G42 with D0: no compensation"});
      d0_noticed_ = true;
      return run_uncompensated(b);
    }
    if (!b.state.edge_defined) return raise(17181, b);  // TRC-SEL-7
    select(b);
  }

  // TRC-SIDE-1 (ruling 30): G41 <-> G42 without G40. The last element of the old side ends at its
  // normal end point (blocks held back run there); the first block with the new side that
  // programs a plane axis is a selection block (NORM) starting where the tool is.
  void change_side(const Block& b) {
    if (b.is_arc()) return raise(10753, b);  // TRC-SEL-2: the new selection needs a linear block
    if (!b.programs_plane_axis()) {
      decide("TRC-SIDE-1", b.words.line, "no-plane-axis");
      return hold_back(b);
    }
    decide("TRC-SIDE-1", b.words.line, "side-change");
    Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
    if (!close_open(end, b, true)) return;
    run_held_back(end);
    ExactPoint tool = at({end, coord(b.start, comp_->axes.applicate)});
    open_.reset();
    comp_.reset();
    select(b);
    selection_from_ = tool;
  }

  // Where the selection block starts: its programmed start, or the tool after a side change.
  ExactPoint selection_start() const { return selection_from_ ? *selection_from_ : at(selection_->start); }

  // TRC-SEL-1: the selection block; TRC-RADIUS-1/2: effective radius and side.
  void select(const Block& b) {
    selection_from_.reset();
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT approach (needs polynomial output)");
    // TRC-SEL-3: a single programmed plane axis was completed by the reader (NC-POS-1).
    decide("TRC-SEL-1", b.words.line, "selected");
    Decimal effective = b.state.effective_radius();
    decide("TRC-RADIUS-2", b.words.line,
           effective.sign() < 0    ? "negative"
           : effective.sign() == 0 ? "zero"
                                   : "positive");
    int s = b.state.side == Side::kLeft ? 1 : -1;
    if (effective.sign() < 0) s = -s;  // TRC-RADIUS-2: a negative radius swaps G41 and G42
    Decimal r = effective.sign() < 0 ? -effective : effective;
    comp_ = Compensation{b.state.plane,          plane_axes(b.state.plane), b.state.side, s, FT(s) * leaf(r), r,
                         ActiveEdge::of(b.state)};
    selection_ = &b;
    prev_block_ = nullptr;
    approach_search_.reset();
    dummies_.clear();
    phase_ = Phase::kApproach;
  }

  // Checks of every block while compensation is selected. False: an alarm stopped the program.
  bool still_compensable(const Block& b) {
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
    if (b.state.side != comp_->side) return true;  // TRC-SIDE-1, handled by the caller
    if (b.words.side)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "re-selection of G41/G42 while compensation is active");
    if (!(ActiveEdge::of(b.state) == comp_->edge))
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "change of tool, D number or OFFN while compensation is active");
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT approach (needs polynomial output)");
    return true;
  }

  // TRC-DUMMY-2: at most MD20250 blocks without motion in the plane in a row.
  void hold_back(const Block& b) {
    if (static_cast<int>(dummies_.size()) == md_.cutcom_maxnum_dummy_blocks) return raise(10762, b);
    dummies_.push_back(&b);
  }

  // TRC-DUMMY-1: held-back blocks run at the corner point P*, only their applicate moving.
  void run_held_back(const Point& corner_point) {
    for (const Block* d : dummies_)
      emit_line(*d, at({corner_point, coord(d->start, comp_->axes.applicate)}),
                at({corner_point, coord(d->end, comp_->axes.applicate)}), OriginKind::kInfeed);
    dummies_.clear();
  }
  void run_held_back_uncompensated() {
    for (const Block* d : dummies_) emit_line(*d, at(d->start), at(d->end), OriginKind::kProgrammed);
    dummies_.clear();
  }

  // --- approach ----------------------------------------------------------------------------------
  void waiting_for_contour(const Block& b) {
    if (b.state.side == Side::kOff) {
      // TRC-SEL-8: deselected before any block moved in the plane: no selection took place.
      decide("TRC-SEL-8", selection_->words.line, "deselected-before-contour");
      emit_line(*selection_, selection_start(), at(selection_->end), OriginKind::kProgrammed);
      run_held_back_uncompensated();
      phase_ = Phase::kOff;
      comp_.reset();
      return compensation_off(b);
    }
    if (!still_compensable(b)) return;
    if (b.state.side != comp_->side)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "change of compensation side G41/G42 before the first contour block");
    if (!b.moves_in_plane()) return hold_back(b);  // TRC-DUMMY-3: no in-plane displacement
    approach(b);
  }

  // TRC-APPR-NORM-1 / TRC-KONT-*: the move onto the contour from the start position.
  void approach(const Block& first_block) {
    prev_block_ = &first_block;
    ContourElement first = element_of(first_block);
    FT radius;
    if (!equidistant_exists(first, radius)) return raise(10751, first_block);  // nothing before it to meet
    ExactPoint from = selection_start();
    Decimal h = coord(selection_->end, comp_->axes.applicate);
    if (selection_->state.approach == ApproachMode::kKont) {
      KontCorner k;
      k.vertex = first.a, k.point = from.plane(comp_->axes);
      k.d1 = k.vertex - k.point, k.d2 = first.start_dir;
      if (!selection_from_ && first.rational)
        k.r1 = RationalVector{mpq_class(units_of(coord(selection_->end, comp_->axes.abscissa)) -
                                        units_of(coord(selection_->start, comp_->axes.abscissa))),
                              mpq_class(units_of(coord(selection_->end, comp_->axes.ordinate)) -
                                        units_of(coord(selection_->start, comp_->axes.ordinate)))},
        k.r2 = first.start_tangent;
      if (kont_behind(*selection_, k, k.d2, 10755)) return approach_around(first_block, first, radius, from, h, k);
      if (stopped_) return;
    }
    Point onto = equidistant_point<Kernel>(first.a, first.start_normal(), comp_->side_radius);
    ExactPoint to = at({onto, h});
    FT length = path.distance(from, to);
    decide("TRC-APPR-NORM-1", selection_->words.line, CGAL::sign(length) == CGAL::ZERO ? "zero-length" : "line",
           exact_mm(length));
    // Output waits until the first element's end is known: if it turns out too short,
    // TRC-EDGE-* replace this line.
    approach_ = PendingApproach{from, to, std::move(dummies_)};
    dummies_.clear();
    open(first_block, first, onto, radius, true);
    phase_ = Phase::kActive;
  }

  // --- KONT: travelling around the start or end point (TRC-KONT-*) -----------------------------
  // The corner a KONT move makes with the contour at `vertex`: d1 runs into it, d2 out of it;
  // `point` is the tool-centre position off the contour (approach: start, retraction: end).
  struct KontCorner {
    Point vertex, point;
    Vector d1, d2;
    std::optional<RationalVector> r1, r2;  // the same directions, rational when all data are
  };

  // TRC-KONT-1: behind the contour = strictly on the far side of the contour's tangent line
  // (`tangent` at the vertex) from the compensation side; TRC-KONT-2: then the point must not lie
  // inside the circle of radius r about the vertex (alarm `alarm`). True: travel around.
  bool kont_side(const Block& at_block, const Point& vertex, const Point& point, const Vector& tangent) {
    Vector off = point - vertex;
    FT cross = tangent.x() * off.y() - tangent.y() * off.x();
    bool behind = comp_->s * static_cast<int>(CGAL::sign(cross)) < 0;
    decide("TRC-KONT-1", at_block.words.line, behind ? "behind" : "in-front",
           exact_mm(FT(comp_->s) * cross / exact_root(tangent.squared_length())));
    return behind;
  }
  bool kont_behind(const Block& at_block, const KontCorner& k, const Vector& tangent, int alarm) {
    if (!kont_side(at_block, k.vertex, k.point, tangent)) return false;
    Vector off = k.point - k.vertex;
    FT distance2 = off.squared_length();
    bool inside = CGAL::compare(distance2, comp_->side_radius * comp_->side_radius) == CGAL::SMALLER;
    decide("TRC-KONT-2", at_block.words.line, inside ? "inside" : "room",
           exact_mm(exact_root(distance2) - leaf(comp_->radius)));
    if (inside) raise(alarm, at_block, "TRC-KONT-2");
    return !inside;
  }

  // TRC-KONT-3/4 with TRC-CORNER-3/4: circle (G450) or intersection (G451), switched by the
  // contour angle of the corner like any outer corner; `mode` is the deciding block's G450/G451.
  bool kont_circle(const Block& at_block, const KontCorner& k) {
    if (k.r1 && k.r2) return outer_corner_circle(at_block, classify_corner(*k.r1, *k.r2, comp_->s), {}, {});
    FT cross = k.d1.x() * k.d2.y() - k.d1.y() * k.d2.x(), dot = k.d1 * k.d2;
    return outer_corner_circle(at_block, std::nullopt, cross, dot);
  }

  // Where the equidistant of the KONT line (through `on_line` with direction `d`) meets the
  // contour element's carrier, nearest the vertex; empty if they do not meet (circles only).
  std::optional<Point> kont_intersection(const Block& at_block, const KontCorner& k, const ContourElement& e,
                                         const FT& e_radius, const Point& on_line, const Vector& d) {
    if (!e.is_arc()) {
      FT cross = k.d1.x() * k.d2.y() - k.d1.y() * k.d2.x(), dot = k.d1 * k.d2;
      FT l1 = exact_root(k.d1.squared_length()), l2 = exact_root(k.d2.squared_length());
      FT trim = corner_trim<Kernel>(cross, dot, l1, l2, comp_->side_radius);
      Vector n1(-k.d1.y() / l1, k.d1.x() / l1);
      return corner_intersection<Kernel>(k.vertex, n1, k.d1, l1, comp_->side_radius, trim);
    }
    Carrier<Kernel> line;
    line.point = on_line, line.direction = d;
    Carrier<Kernel> u = carrier_of(e, e_radius);
    std::optional<Point> x = nearest_intersection(u, line, k.vertex, k.d2);
    decide("TRC-ARC-CORNER-1", at_block.words.line, x ? "intersection" : "none",
           exact_mm(carrier_gap<Kernel>(u, line)));
    return x;
  }

  static Vector unit_left_normal(const Vector& d) {
    FT l = exact_root(d.squared_length());
    return Vector(-d.y() / l, d.x() / l);
  }

  // TRC-KONT-3 / TRC-KONT-4 on approach: the approach line is a contour element ending at the
  // start point S and meeting the first block at an outer corner.
  void approach_around(const Block& first_block, const ContourElement& first, const FT& radius, const ExactPoint& from,
                       const Decimal& h, const KontCorner& k) {
    kont_first_ = true;
    Point a = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d1), comp_->side_radius);
    bool circle = kont_circle(*selection_, k);
    std::optional<Point> x;
    if (!circle) x = kont_intersection(*selection_, k, first, radius, a, k.d1);
    if (!x) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2: no intersection at an outer corner)
      decide("TRC-KONT-3", selection_->words.line, "circle");
      emit_line(*selection_, from, at({a, h}), OriginKind::kApproach);
      run_held_back(a);
      Point q = equidistant_point<Kernel>(k.vertex, first.start_normal(), comp_->side_radius);
      Origin corner = origin(*selection_, OriginKind::kTransitionCircle);
      corner.next_line = first_block.words.line, corner.next_block = first_block.words.number;
      Decimal h1 = coord(first_block.start, comp_->axes.applicate);  // after the held-back blocks
      if (comp_->radius.sign() != 0)                                 // TRC-G450-2
        emit_arc(first_block, at({a, h1}), at({q, h1}), at({k.vertex, h1}), comp_->side_radius, comp_->s < 0, corner,
                 comp_->axes);
      open(first_block, first, q, radius, true);
    } else {  // TRC-KONT-4
      decide("TRC-KONT-4", selection_->words.line, "intersection");
      emit_line(*selection_, from, at({*x, h}), OriginKind::kApproach);
      run_held_back(*x);
      open(first_block, first, *x, radius);
    }
    phase_ = Phase::kActive;
  }

  // --- compensation active -----------------------------------------------------------------------
  void compensation_active(const Block& b) {
    if (!still_compensable(b)) return;
    if (b.state.side == comp_->side && b.moves_in_plane()) {
      const Block* before = prev_block_;
      prev_block_ = &b;
      if (approach_search_ && approach_further_ahead(b)) return;
      if (b.state.collision == CollisionMode::kCdon && before && bottleneck(b, *before)) return;
    }
    if (looking_) return look_ahead(b);
    if (b.state.side != Side::kOff && b.state.side != comp_->side) return change_side(b);
    if (b.state.side == Side::kOff) {
      if (!b.programs_plane_axis()) {  // TRC-DESEL-3
        decide("TRC-DESEL-3", b.words.line, "no-plane-axis");
        return hold_back(b);
      }
      return deselect(b);
    }
    if (!b.moves_in_plane()) return hold_back(b);  // TRC-DUMMY-3
    corner(b);
  }

  // TRC-ELEMENT-1 / TRC-ARC-ELEMENT-1: the open element, from its start point to `end_point`, must
  // not run backwards; it is output unless it has length exactly 0.
  // `at_normal_end`: the end point was built as the normal end point (no cut at the end), so its
  // rotation from it is 0 by construction and needs no exact zero test.
  // `candidate`: the block whose equidistant fixed this end (for TRC-EDGE-* on approach).
  struct Candidate {
    const Block* block;
    const ContourElement* element;
    FT radius;
  };
  bool close_open(const Point& end_point, const Block& reporting, bool at_normal_end = false,
                  const Candidate* candidate = nullptr) {
    const ContourElement& e = *open_;
    CGAL::Sign sign;
    std::string margin;
    if (!e.is_arc()) {
      FT left = (end_point - open_start_) * e.d / e.length;  // signed length along the block
      sign = CGAL::sign(left);
      margin = exact_mm(left);
    } else {
      // Sweep of the programmed circle, less the rotation already cut at the start, plus the
      // (negative) rotation cut at the end.
      ExactAngle sweep =
          e.full_circle ? ExactAngle::full_turn() : ExactAngle::rotation(e.a - e.centre, e.b - e.centre, e.sense);
      ExactAngle left = sweep;
      if (!open_at_normal_start_)
        left = left + -ExactAngle::signed_rotation(e.a - e.centre, open_start_ - e.centre, e.sense);
      if (!at_normal_end) left = left + ExactAngle::signed_rotation(e.b - e.centre, end_point - e.centre, e.sense);
      sign = left.sign();
      margin = arc_length_text(left, open_radius_);
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
      run_actions(*open_block_, path.output(to));
      return true;
    }
    if (!e.is_arc()) {
      emit_line(*open_block_, from, to, OriginKind::kOffset, &e);
    } else {
      ExactPoint centre = at({e.centre, coord(e.start3, comp_->axes.applicate)});
      emit_arc(*open_block_, from, to, centre, open_radius_, e.sense > 0, origin(*open_block_, OriginKind::kOffset),
               comp_->axes);
    }
    return true;
  }

  // The carrier of an equidistant: the offset line, or the concentric circle.
  Carrier<Kernel> carrier_of(const ContourElement& e, const FT& radius) const {
    return ref::carrier_of(e, radius, comp_->side_radius);
  }

  void corner(const Block& next_block) {
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
    FT sine = FT(comp_->s) * cross / exact_root(dot * dot + cross * cross);  // |t1||t2| = sqrt(dot^2 + cross^2)
    decide("TRC-CORNER-1", next_block.words.line, kKind[static_cast<int>(kind)], exact_text(sine));

    bool circle = kind == CornerKind::kReversal;  // TRC-G450-3
    if (kind == CornerKind::kOuter) circle = outer_corner_circle(next_block, rc, cross, dot);
    const Point vertex = first.b;  // a copy: open() replaces the element it comes from
    if (circle) return transition_circle(next_block, next, next_radius, vertex);
    if (kind == CornerKind::kTangent) {
      // Both equidistants pass through the common normal point.
      Point x = equidistant_point<Kernel>(vertex, first.end_normal(), comp_->side_radius);
      if (!close_open(x, next_block, true)) return;
      run_held_back(x);
      return open(next_block, next, x, next_radius, true);
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
             exact_mm(carrier_gap<Kernel>(u, v)));
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
    if (!close_open(*x, next_block, false, &cand)) return;
    run_held_back(*x);
    open(next_block, next, *x, next_radius);
  }

  // TRC-CORNER-3 / TRC-CORNER-4: is an outer corner made with the transition circle? By the
  // G450/G451 of `at_block`, switched by the contour angle (exactly; rational where `rc` is given).
  bool outer_corner_circle(const Block& at_block, const std::optional<CornerClass>& rc, const FT& cross, const FT& dot,
                           bool traced = true) {
    bool g451 = at_block.state.corner == CornerMode::kG451;
    const Decimal& limit = g451 ? md_.cutcom_corner_limit : md_.cutcom_curve_insert_limit;
    AngleComparison a;
    if (rc) {
      const CornerClass& c = *rc;
      mpz_class ic = c.a1 * c.b2 - c.b1 * c.a2, id = c.a1 * c.a2 + c.b1 * c.b2;
      mpz_class l2 = (c.a1 * c.a1 + c.b1 * c.b1) * (c.a2 * c.a2 + c.b2 * c.b2);
      a = compare_contour_angle(ic, id, l2, limit);
    } else {
      a = compare_contour_angle_exact(cross, dot, dot * dot + cross * cross, limit);
    }
    if (g451) {
      bool circle = a.sign > 0;
      if (traced) decide("TRC-CORNER-3", at_block.words.line, circle ? "switch-to-G450" : "keep-G451", a.margin_text);
      return circle;
    }
    bool circle = !(a.sign < 0);
    if (traced) decide("TRC-CORNER-4", at_block.words.line, circle ? "keep-G450" : "switch-to-G451", a.margin_text);
    return circle;
  }

  // Where a point lies on an element's equidistant (normal start to normal end): the signed length
  // from the normal start, and what is left to the normal end; exact. Empty if it lies within.
  // TRC-LOOK-1 asks for the second only; TRC-LOOK-2 for both.
  struct Extent {
    CGAL::Sign before_start, after_end;  // NEGATIVE: before the start / beyond the end
    bool start_nearer = false;           // nearer to the normal start than to the normal end
    std::string along_text, left_text;   // lengths from the normal start and to the normal end (mm)
  };
  Extent extent_of(const ContourElement& e, const FT& radius, const Point& p) const {
    Extent x;
    if (!e.is_arc()) {
      Point start = equidistant_point<Kernel>(e.a, e.normal, comp_->side_radius);
      FT along = (p - start) * e.d / e.length;
      FT left = e.length - along;
      x.before_start = CGAL::sign(along), x.after_end = CGAL::sign(left);
      x.start_nearer = CGAL::compare(along, left) == CGAL::SMALLER;
      x.along_text = exact_mm(along), x.left_text = exact_mm(left);
    } else {
      ExactAngle sweep =
          e.full_circle ? ExactAngle::full_turn() : ExactAngle::rotation(e.a - e.centre, e.b - e.centre, e.sense);
      ExactAngle along = ExactAngle::signed_rotation(e.a - e.centre, p - e.centre, e.sense);
      ExactAngle left = sweep + -along;
      x.before_start = along.sign(), x.after_end = left.sign();
      x.start_nearer = (along + -left).sign() == CGAL::NEGATIVE;
      x.along_text = arc_length_text(along, radius), x.left_text = arc_length_text(left, radius);
    }
    return x;
  }

  // TRC-LOOK-2: the blocks after a too-short one are tried in turn, up to MD20240 examined after the
  // open element; the held-back and passed-over blocks are skipped.
  void start_look_ahead(const Block& too_short) {
    for (const Block* d : dummies_) skipped_.push_back(d);
    dummies_.clear();
    skipped_.push_back(&too_short);
    examined_ = 1;
    looking_ = true;
    if (examined_ >= md_.cutcom_maxnum_check_blocks) raise(10751, too_short);
  }

  void look_ahead(const Block& b) {
    if (b.state.side == Side::kOff && b.programs_plane_axis()) return retract_edge(b);  // TRC-EDGE-1
    if (b.state.side != comp_->side && b.state.side != Side::kOff) {  // the contour ends before an intersection
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
    std::optional<Point> y = nearest_intersection(u, v, start, cand.start_dir);
    bool valid = false;
    // No intersection at all: the gap between the carriers (lines: parallel, "inf").
    std::string margin = u.circle || v.circle ? exact_mm(carrier_gap<Kernel>(u, v)) : std::string("inf");
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
    }
    decide("TRC-LOOK-2", b.words.line, valid ? "intersection" : "none", margin);
    if (!valid) return pass_over(b);
    looking_ = false;
    Candidate candidate{&b, &cand, radius};
    if (!close_open(*y, b, false, &candidate)) return;
    run_skipped(*y);
    open(b, cand, *y, radius);
  }

  // A candidate that does not do: passed over; alarm 10751 once MD20240 blocks were examined.
  void pass_over(const Block& b) {
    skipped_.push_back(&b);
    if (examined_ >= md_.cutcom_maxnum_check_blocks) raise(10751, b);
  }

  // TRC-LOOK-3: skipped blocks lose their motion in the plane; their applicate motion and actions
  // run at the intersection point, in programmed order.
  void run_skipped(const Point& at_point) {
    for (const Block* d : skipped_) {
      decide("TRC-LOOK-3", d->words.line, "skipped");
      emit_line(*d, at({at_point, coord(d->start, comp_->axes.applicate)}),
                at({at_point, coord(d->end, comp_->axes.applicate)}), OriginKind::kInfeed);
    }
    skipped_.clear();
  }

  // The carriers' intersection nearest to `vertex`; of two equally near, the one further along
  // `ahead` (the second element's direction of travel), so that the choice does not depend on
  // the orientation of the plane (TRC-ARC-CORNER-1, TRC-LOOK-2).
  static std::optional<Point> nearest_intersection(const Carrier<Kernel>& u, const Carrier<Kernel>& v,
                                                   const Point& vertex, const Vector& ahead) {
    std::vector<Point> xs = carrier_intersections<Kernel>(u, v);
    if (xs.empty()) return std::nullopt;
    if (xs.size() == 1) return xs[0];
    CGAL::Comparison_result c = CGAL::compare_distance_to_point(vertex, xs[1], xs[0]);
    if (c == CGAL::EQUAL)
      return CGAL::compare((xs[1] - vertex) * ahead, (xs[0] - vertex) * ahead) == CGAL::LARGER ? xs[1] : xs[0];
    return c == CGAL::SMALLER ? xs[1] : xs[0];
  }

  void flush_approach() {
    if (!approach_) return;
    PendingApproach a = std::move(*approach_);
    approach_.reset();
    emit_line(*selection_, a.from, a.to, OriginKind::kApproach);
    dummies_.swap(a.held_back);
    run_held_back(a.to.plane(comp_->axes));
    dummies_.swap(a.held_back);
  }

  // --- G460 / G461 / G462: a too-short first or last block (TRC-EDGE-*, edge_strategy.cpp) ------
  EdgeCurve edge_curve(EdgeStrategy strategy, const Point& vertex, const Point& normal_point, const Vector& outward,
                       const Point& off_contour, bool approach) const {
    return ref::edge_curve(strategy, vertex, normal_point, outward, off_contour, approach, leaf(comp_->radius));
  }
  EdgeHit edge_hit(const EdgeCurve& curve, const ContourElement& e, const FT& radius, const std::optional<Point>& from,
                   bool last) const {
    return ref::edge_hit(curve, e, radius, comp_->side_radius, from, last);
  }

  // TRC-EDGE-1 on retraction: deselection while the look-ahead found no block to meet the open
  // element (the last block is too short). The open element ends at the hit, the blocks after it
  // are skipped (TRC-LOOK-3), the retraction line starts there.
  void retract_edge(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT retraction (needs polynomial output)");
    const Block* last_block = nullptr;
    for (const Block* d : skipped_)
      if (d->moves_in_plane()) last_block = d;
    ContourElement last = element_of(*last_block);
    decide("TRC-DESEL-1", b.words.line, "deselected");
    if (b.state.approach == ApproachMode::kKont) {  // TRC-KONT-1/2, then TRC-EDGE-6
      KontCorner k = retraction_corner(b, last);
      if (kont_behind(b, k, k.d1, 10756)) return retract_edge_around(b, *last_block, k);
      if (stopped_) return;
    }
    decide("TRC-EDGE-1", b.words.line, g_code(b.state.edge_strategy));
    Point normal_end = equidistant_point<Kernel>(last.b, last.end_normal(), comp_->side_radius);
    EdgeCurve curve =
        edge_curve(b.state.edge_strategy, last.b, normal_end, last.end_dir, plane_point(b.end, comp_->axes), false);
    EdgeHit edge = edge_hit(curve, *open_, open_radius_, open_start_, false);
    std::optional<Point> hit = edge.point;
    decide("TRC-EDGE-5", b.words.line, hit ? "hit" : "none", edge.margin);
    if (b.state.collision == CollisionMode::kCdon && search_further_back(b, curve)) return;
    if (!hit) return raise(10751, b);
    looking_ = false;
    if (!close_open(*hit, b)) return;
    run_skipped(*hit);
    retraction_line(b, *hit);
  }

  // TRC-CD-5: with CDON the retraction's search goes on over the held-back equidistants and circles
  // of the blocks m-W ... m-2 before the open element; the last hit found (the earliest block, on
  // it the earliest point) is valid. True: the path was cut there and the retraction made.
  bool search_further_back(const Block& b, const EdgeCurve& curve) {
    std::vector<PathPiece> aux{curve_piece(curve)};
    int lo = seq_of(b) - md_.cutcom_maxnum_check_blocks, hi = seq_of(b) - 2;
    std::optional<FT> near;
    bool compared = false;
    std::deque<HeldRecord>& records = held_.records();
    for (std::size_t i = 0; i < records.size(); ++i) {
      const HeldRecord& r = records[i];
      if (!r.candidate() || r.seq < lo || r.seq > hi) continue;
      compared = true;
      PieceCrossing c = piece_crossing(piece_of(r), aux);
      if (c.near_miss && (!near || rough(*near) < rough(*c.near_miss))) near = c.near_miss;
      if (!c.point) continue;
      FT margin = c.slack;
      if (near && rough(-*near) < rough(margin)) margin = -*near;
      decide("TRC-CD-5", b.words.line, "earlier-block", exact_mm(margin));
      const Point x = *c.point;
      if (!cut_at(b, i, x)) return true;
      retraction_line(b, x);
      return true;
    }
    if (compared) decide("TRC-CD-5", b.words.line, "open-element", near ? exact_mm(*near) : std::string("-inf"));
    return false;
  }

  // An auxiliary curve of TRC-EDGE-2..4 as a path piece: G460's segment, G461's whole circle,
  // G462's ray as a segment reaching beyond any programmable coordinate (10^13 mm).
  PathPiece curve_piece(const EdgeCurve& curve) const {
    const Carrier<Kernel>& k = curve.carrier;
    if (k.circle)
      return PathPiece::circle(k.point + Vector(k.radius, 0), k.point + Vector(k.radius, 0), k.point, k.radius, 1,
                               true);
    if (curve.bound == EdgeCurve::Bound::kSegment) return PathPiece::segment(k.point, k.point + k.direction);
    FT far = FT(10'000'000'000'000L) * FT(1'000'000'000L) / exact_root(k.direction.squared_length());
    return PathPiece::segment(k.point, k.point + k.direction * far);
  }

  // TRC-EDGE-1 on approach: the first element would run backwards to meet `c`'s equidistant.
  // The approach line ends at the hit on c's equidistant instead; the first block and those
  // between are skipped.
  void approach_edge(const Candidate& c) {
    const Block& sel = *selection_;
    decide("TRC-EDGE-1", sel.words.line, g_code(sel.state.edge_strategy));
    const ContourElement& first = *open_;
    EdgeCurve curve = edge_curve(sel.state.edge_strategy, first.a, open_start_, -first.start_dir,
                                 approach_->from.plane(comp_->axes), true);
    EdgeHit edge = edge_hit(curve, *c.element, c.radius, std::nullopt, true);
    std::optional<Point> hit = edge.point;
    decide("TRC-EDGE-5", sel.words.line, hit ? "hit" : "none", edge.margin);
    if (!hit) return raise(10751, *c.block);
    PendingApproach a = std::move(*approach_);
    approach_.reset();
    emit_line(sel, a.from, at({*hit, coord(sel.end, comp_->axes.applicate)}), OriginKind::kApproach);
    // Blocks passed over, in programmed order: held back before the first block, the first block,
    // held back after it, passed over by the look-ahead.
    std::vector<const Block*> passed = std::move(a.held_back);
    passed.push_back(open_block_);
    for (const Block* d : dummies_) passed.push_back(d);
    for (const Block* d : skipped_) passed.push_back(d);
    dummies_.clear();
    skipped_ = std::move(passed);
    looking_ = false;
    run_skipped(*hit);
    open(*c.block, *c.element, *hit, c.radius);
    // TRC-CD-6: with CDON the later blocks of the window are searched too.
    if (sel.state.collision == CollisionMode::kCdon)
      approach_search_ = ApproachSearch{curve, seq_of(sel) + md_.cutcom_maxnum_check_blocks};
  }

  // TRC-CD-6: with CDON the approach's search goes on over the later blocks while the approach line
  // is held back (up to MD20240 traversing blocks after the selection block); the last hit found
  // is valid: the approach line ends there instead and the blocks between lose their plane motion.
  // True: block m was entered so.
  bool approach_further_ahead(const Block& m) {
    if (seq_of(m) > approach_search_->until || m.state.collision != CollisionMode::kCdon) {
      approach_search_.reset();
      return false;
    }
    ContourElement e = element_of(m);
    FT radius;
    if (e.is_arc()) {
      radius = equidistant_radius<Kernel>(e.radius, e.sense, comp_->side_radius);
      if (CGAL::sign(radius) != CGAL::POSITIVE) return false;
    }
    EdgeHit hit = edge_hit(approach_search_->curve, e, radius, std::nullopt, true);
    decide("TRC-CD-6", m.words.line, hit.point ? "later-block" : "none", hit.margin);
    if (!hit.point) return false;
    std::deque<HeldRecord>& records = held_.records();
    for (std::size_t i = 0; i < records.size(); ++i) {
      if (!records[i].element || records[i].element->origin.kind != OriginKind::kApproach) continue;
      if (!cut_at(m, i, *hit.point)) return true;
      open(m, e, *hit.point, radius);
      return true;
    }
    return false;
  }
  struct ApproachSearch {
    EdgeCurve curve;
    int until;  // the last traversing block searched
  };
  std::optional<ApproachSearch> approach_search_;

  // --- CDON: bottleneck detection (TRC-CD-*, bottleneck.cpp) ------------------------------------
  // TRC-CD-2: a block's entry, built provisionally from its predecessor: the transition circle at an outer
  // corner (whatever G450/G451 say), then its equidistant from its normal start (from the inner
  // corner's intersection); none if that lies beyond its normal end or the equidistant collapses.
  struct Entry {
    ContourElement element;
    FT radius;
    Point vertex, normal_start;
    Point own_start;  // where m's own equidistant piece starts
    const Block* before = nullptr;
    ContourElement before_element;
    FT before_radius;
    // pieces[0] leads to m's equidistant: the transition circle, or (G451) the predecessor's
    // equidistant extended to the intersection.
    enum class Lead { kNone, kCircle, kExtension } lead = Lead::kNone;
    std::vector<PathPiece> pieces;
  };
  std::optional<Entry> entry_of(const Block& m, const Block& before) {
    Entry en;
    en.element = element_of(m);
    en.before = &before;
    const ContourElement& next = en.element;
    const FT& sr = comp_->side_radius;
    const int line = m.words.line;
    if (next.is_arc()) {
      en.radius = equidistant_radius<Kernel>(next.radius, next.sense, sr);
      if (CGAL::sign(en.radius) != CGAL::POSITIVE)
        return decide("TRC-CD-2", line, "collapsed", exact_mm(en.radius)), std::nullopt;
    }
    en.normal_start = equidistant_point<Kernel>(next.a, next.start_normal(), sr);
    Point end = equidistant_point<Kernel>(next.b, next.end_normal(), sr);
    auto equidistant_from = [&](const Point& from, bool full) {
      return next.is_arc() ? PathPiece::circle(from, end, next.centre, en.radius, next.sense, full)
                           : PathPiece::segment(from, end);
    };
    en.before_element = element_of(before);
    const ContourElement& prev = en.before_element;
    FT& prev_radius = en.before_radius;
    if (prev.is_arc()) prev_radius = equidistant_radius<Kernel>(prev.radius, prev.sense, sr);
    en.vertex = prev.b;
    en.own_start = en.normal_start;
    std::optional<CornerClass> rc;
    if (prev.rational && next.rational) rc = classify_corner(prev.end_tangent, next.start_tangent, comp_->s);
    CornerKind kind = rc ? rc->kind : classify_corner(prev.end_dir, next.start_dir, comp_->s);
    if (prev.is_arc() && CGAL::sign(prev_radius) != CGAL::POSITIVE) {
      decide("TRC-CD-2", line, "after-collapse", exact_mm(prev_radius));
      kind = CornerKind::kTangent;
    } else {
      static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
      FT cross = prev.end_dir.x() * next.start_dir.y() - prev.end_dir.y() * next.start_dir.x();
      FT dot = prev.end_dir * next.start_dir;
      decide("TRC-CD-2", line, kKind[static_cast<int>(kind)],
             exact_text(FT(comp_->s) * cross / exact_root(dot * dot + cross * cross)));
    }
    Point prev_end = equidistant_point<Kernel>(prev.b, prev.end_normal(), sr);
    if (kind == CornerKind::kOuter && !outer_corner_is_circle(m, prev, prev_radius, next, en.radius, rc)) {
      // G451 (TRC-G451-1, TRC-ARC-CORNER-1): both equidistants extended to their intersection.
      en.own_start = *g451_point_;
      en.lead = Entry::Lead::kExtension;
      en.pieces.push_back(prev.is_arc()
                              ? PathPiece::circle(prev_end, en.own_start, prev.centre, prev_radius, prev.sense)
                              : PathPiece::segment(prev_end, en.own_start));
      en.pieces.push_back(equidistant_from(en.own_start, false));
      return en;
    }
    if (kind == CornerKind::kOuter || kind == CornerKind::kReversal) {
      en.pieces.push_back(PathPiece::circle(prev_end, en.normal_start, prev.b, leaf(comp_->radius), -comp_->s));
      en.lead = Entry::Lead::kCircle;
    }
    if (kind != CornerKind::kInner) {
      en.pieces.push_back(equidistant_from(en.normal_start, next.full_circle));
      return en;
    }
    Carrier<Kernel> u = carrier_of(prev, prev_radius), v = carrier_of(next, en.radius);
    std::optional<Point> x = nearest_intersection(u, v, prev.b, next.start_dir);
    if (!x) {
      decide("TRC-CD-2", line, "no-entry", u.circle || v.circle ? exact_mm(carrier_gap<Kernel>(u, v)) : "-inf");
      return std::nullopt;
    }
    Extent reach = extent_of(next, en.radius, *x);
    bool beyond = reach.after_end == CGAL::NEGATIVE;
    decide("TRC-CD-2", line, beyond ? "no-entry" : "entry", reach.left_text);
    if (beyond) return std::nullopt;
    en.own_start = *x;
    en.pieces.push_back(equidistant_from(*x, false));
    return en;
  }

  // The outer corner of the entry as corner() will make it (TRC-CORNER-3/4 untraced here): true
  // for the circle; false for G451, with the intersection in g451_point_ (TRC-ARC-CORNER-2: none
  // found is the circle).
  bool outer_corner_is_circle(const Block& m, const ContourElement& prev, const FT& prev_radius,
                              const ContourElement& next, const FT& next_radius, const std::optional<CornerClass>& rc) {
    FT cross = rc ? to_ft(rc->cross) : prev.end_dir.x() * next.start_dir.y() - prev.end_dir.y() * next.start_dir.x();
    FT dot = rc ? to_ft(rc->dot) : prev.end_dir * next.start_dir;
    if (outer_corner_circle(m, rc, cross, dot, false)) return true;
    if (!prev.is_arc() && !next.is_arc()) {
      FT trim = corner_trim<Kernel>(cross, dot, prev.length, next.length, comp_->side_radius);
      g451_point_ = corner_intersection<Kernel>(prev.b, prev.normal, prev.d, prev.length, comp_->side_radius, trim);
      return false;
    }
    g451_point_ =
        nearest_intersection(carrier_of(prev, prev_radius), carrier_of(next, next_radius), prev.b, next.start_dir);
    return !g451_point_;
  }
  std::optional<Point> g451_point_;

  // A held-back element as a piece of the plane path.
  static PathPiece piece_of(const HeldRecord& r) {
    const ExactPath::Element& e = r.exact;
    Point a = e.start.plane(e.axes), b = e.end.plane(e.axes);
    if (r.element->type == ElementType::kLine) return PathPiece::segment(a, b);
    return PathPiece::circle(a, b, e.centre->plane(e.axes), CGAL::abs(e.side_radius), r.element->ccw ? 1 : -1, a == b);
  }
  // The open element from its start point to its normal end.
  PathPiece open_piece() const {
    const ContourElement& e = *open_;
    Point end = equidistant_point<Kernel>(e.b, e.end_normal(), comp_->side_radius);
    if (!e.is_arc()) return PathPiece::segment(open_start_, end);
    return PathPiece::circle(open_start_, end, e.centre, open_radius_, e.sense, e.full_circle && open_at_normal_start_);
  }

  // TRC-CD-3: block m's entry against the held-back elements of blocks m-W ... m-2 (W = MD20240)
  // and, in the look-ahead, the open element; the earliest block that it crosses wins, on it the
  // earliest point. True: the path was cut there. Margin: the crossing's least slack, or the
  // largest near miss.
  bool bottleneck(const Block& m, const Block& before) {
    if (comp_->radius.sign() == 0) return false;  // no width: nothing to collide
    int lo = seq_of(m) - md_.cutcom_maxnum_check_blocks, hi = seq_of(m) - 2;
    std::optional<Entry> entry;
    std::optional<FT> near;
    bool compared = false;
    // A G451 lead is the predecessor's equidistant: m-2's held element ends on it, at their common
    // corner, and is not compared with it (in the look-ahead m-1 was passed over: no such corner).
    auto try_piece = [&](const PathPiece& held, int seq) -> std::optional<PieceCrossing> {
      if (!entry && !compared) entry = entry_of(m, before);
      compared = true;
      if (!entry) return std::nullopt;
      bool skip_lead = entry->lead == Entry::Lead::kExtension && seq == hi && !looking_;
      PieceCrossing c = piece_crossing(held, entry->pieces, skip_lead ? 1 : 0);
      // The largest near miss (picked by the filter's value: see bottleneck.hpp).
      if (c.near_miss && (!near || rough(*near) < rough(*c.near_miss))) near = c.near_miss;
      if (!c.point) return std::nullopt;
      return c;
    };
    std::deque<HeldRecord>& records = held_.records();
    for (std::size_t i = 0; i < records.size(); ++i) {
      const HeldRecord& r = records[i];
      if (!r.candidate() || r.seq < lo || r.seq > hi) continue;
      if (std::optional<PieceCrossing> c = try_piece(piece_of(r), r.seq)) return cut(m, *entry, i, *c, near), true;
      if (compared && !entry) return false;
    }
    if (looking_ && seq_of(*open_block_) >= lo && seq_of(*open_block_) <= hi)
      if (std::optional<PieceCrossing> c = try_piece(open_piece(), seq_of(*open_block_)))
        return cut(m, *entry, std::nullopt, *c, near), true;
    if (entry) decide("TRC-CD-3", m.words.line, "none", near ? exact_mm(*near) : std::string("-inf"));
    return false;
  }

  // TRC-CD-4 (with TRC-LOOK-3): the path is cut at the crossing. The crossed block ends there; the
  // blocks after it lose their plane motion (the rest runs at the point, in programmed order);
  // block m goes on along its entry: the rest of the circle, then its equidistant.
  void cut(const Block& m, const Entry& en, std::optional<std::size_t> record, const PieceCrossing& c,
           const std::optional<FT>& near) {
    const Point x = *c.point;
    FT margin = c.slack;
    if (near && rough(-*near) < rough(margin)) margin = -*near;
    decide("TRC-CD-3", m.words.line, "cut", exact_mm(margin));
    if (!cut_at(m, record, x)) return;
    continue_entry(m, en, c.entry_piece, x);
  }

  // TRC-CD-4: cuts the held-back path at x on `record` (none: on the open element); the blocks
  // after it lose their plane motion and run at x (TRC-LOOK-3). False: an alarm stopped the run.
  bool cut_at(const Block& reporting, std::optional<std::size_t> record, const Point& x) {
    std::vector<const Block*> passed;
    auto pass = [&](const Block* b) {
      for (const Block* p : passed)
        if (p == b) return;
      passed.push_back(b);
    };
    if (record) {
      std::deque<HeldRecord>& records = held_.records();
      HeldRecord& r = records[*record];
      const Block* crossed = r.owner;
      ExactPoint end = r.exact.end;
      FT* coords[3] = {&end.x, &end.y, &end.z};
      *coords[comp_->axes.abscissa] = x.x(), *coords[comp_->axes.ordinate] = x.y();
      r.exact.end = end, r.element->end = path.output(end);
      bool rest = false;  // the crossed block had more after the cut element
      for (std::size_t i = *record + 1; i < records.size(); ++i) {
        const Block* owner = records[i].owner;
        if (!records[i].element) actions_done_[static_cast<std::size_t>(owner->index)] = false;  // run again at x
        if (owner == crossed)
          rest = true;
        else
          pass(owner);
      }
      records.erase(records.begin() + static_cast<std::ptrdiff_t>(*record) + 1, records.end());
      if (path.same(r.exact.start, r.exact.end)) records.erase(records.begin() + static_cast<std::ptrdiff_t>(*record));
      if (open_block_ == crossed)
        rest = true;  // its equidistant was still open
      else
        pass(open_block_);
      if (rest) {  // the crossed block's applicate motion still to come
        ExactPoint to = end;
        FT* t[3] = {&to.x, &to.y, &to.z};
        *t[comp_->axes.applicate] = leaf(coord(crossed->end, comp_->axes.applicate));
        emit_line(*crossed, end, to, OriginKind::kInfeed);
      }
    } else {
      looking_ = false;
      if (!close_open(x, reporting)) return false;
    }
    for (const Block* d : skipped_) pass(d);
    for (const Block* d : dummies_) pass(d);
    std::sort(passed.begin(), passed.end(), [](const Block* a, const Block* b) { return a->index < b->index; });
    skipped_ = std::move(passed);
    dummies_.clear();
    looking_ = false;
    kont_first_ = false;
    run_skipped(x);
    return true;
  }

  // TRC-CD-4: block m goes on from the crossing along its entry.
  void continue_entry(const Block& m, const Entry& en, int entry_piece, const Point& x) {
    const Entry::Lead lead = en.lead;
    bool on_lead = lead != Entry::Lead::kNone && entry_piece == 0 && x != en.own_start;
    if (!on_lead) return open(m, en.element, x, en.radius, x == en.normal_start);
    Decimal h = coord(m.start, comp_->axes.applicate);
    if (lead == Entry::Lead::kCircle) {
      Origin corner = origin(*en.before, OriginKind::kTransitionCircle);
      corner.next_line = m.words.line, corner.next_block = m.words.number;
      emit_arc(m, at({x, h}), at({en.normal_start, h}), at({en.vertex, h}), comp_->side_radius, comp_->s < 0, corner,
               comp_->axes);
      return open(m, en.element, en.normal_start, en.radius, true);
    }
    // The rest of the predecessor's extended equidistant, at m's applicate, named after it.
    const ContourElement& p = en.before_element;
    if (p.is_arc())
      emit_arc(m, at({x, h}), at({en.own_start, h}), at({p.centre, h}), en.before_radius, p.sense > 0,
               origin(*en.before, OriginKind::kOffset), comp_->axes);
    else
      emit_line(m, at({x, h}), at({en.own_start, h}), OriginKind::kOffset, &p, en.before);
    open(m, en.element, en.own_start, en.radius);
  }

  // TRC-G450-1: a circle of radius r about the programmed corner from the normal end point of the
  // first equidistant to the normal start point of the second; it belongs to the second block.
  void transition_circle(const Block& next_block, const ContourElement& next, const FT& next_radius,
                         const Point& vertex) {
    Point from = equidistant_point<Kernel>(vertex, open_->end_normal(), comp_->side_radius);
    if (!close_open(from, next_block, true)) return;
    run_held_back(from);
    Point to = equidistant_point<Kernel>(vertex, next.start_normal(), comp_->side_radius);
    Decimal h = coord(next_block.start, comp_->axes.applicate);
    Origin corner = origin(*open_block_, OriginKind::kTransitionCircle);
    corner.next_line = next_block.words.line, corner.next_block = next_block.words.number;
    open(next_block, next, to, next_radius, true);
    if (comp_->radius.sign() != 0) {  // TRC-G450-2: no circle for a zero radius
      // Around the outside of the corner: clockwise on the left, counter-clockwise on the right.
      emit_arc(next_block, at({from, h}), at({to, h}), at({vertex, h}), comp_->side_radius, comp_->s < 0, corner,
               comp_->axes);
    }
  }

  // TRC-ARC-EQ-1: a circle's equidistant must keep a positive radius rho - s sigma r. Decided when
  // the block comes; a collapsed one is passed over by the look-ahead (TRC-LOOK-1/2).
  bool equidistant_exists(const ContourElement& e, FT& radius) {
    if (!e.is_arc()) return true;
    radius = equidistant_radius<Kernel>(e.radius, e.sense, comp_->side_radius);
    CGAL::Sign sign = CGAL::sign(radius);
    decide("TRC-ARC-EQ-1", e.line, sign == CGAL::POSITIVE ? "concentric" : "collapses", exact_mm(radius));
    return sign == CGAL::POSITIVE;
  }

  // `at_normal_start`: the start point was built as the normal start point (see close_open).
  void open(const Block& b, const ContourElement& e, const Point& start, const FT& radius,
            bool at_normal_start = false) {
    open_at_normal_start_ = at_normal_start;
    open_ = e;
    open_block_ = &b;
    open_start_ = start;
    open_radius_ = radius;
  }

  // TRC-DESEL-1: deselection; with KONT from behind the end point TRC-KONT-* travel around it,
  // otherwise (NORM, KONT in front) TRC-RETR-NORM-1.
  void deselect(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT retraction (needs polynomial output)");
    decide("TRC-DESEL-1", b.words.line, "deselected");
    if (b.state.approach == ApproachMode::kKont) {
      KontCorner k = retraction_corner(b, *open_);
      if (kont_behind(b, k, k.d1, 10756)) return retract_around(b, k);
      if (stopped_) return;
    }
    Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
    if (!close_open(end, b, true)) return;
    run_held_back(end);
    retraction_line(b, end);
  }

  // The corner the retraction line (to b's end) makes with the last block at its end point.
  KontCorner retraction_corner(const Block& b, const ContourElement& last) const {
    KontCorner k;
    k.vertex = last.b, k.point = plane_point(b.end, comp_->axes);
    k.d1 = last.end_dir, k.d2 = k.point - k.vertex;
    if (last.rational)
      k.r1 = last.end_tangent,
      k.r2 = RationalVector{
          mpq_class(units_of(coord(b.end, comp_->axes.abscissa)) - units_of(coord(last.end3, comp_->axes.abscissa))),
          mpq_class(units_of(coord(b.end, comp_->axes.ordinate)) - units_of(coord(last.end3, comp_->axes.ordinate)))};
    return k;
  }

  // TRC-EDGE-6 (digest §2.5 rule 3): KONT from behind after a too-short last block. The
  // travel-around circle about the last block's end point is inserted whatever G460-G462 say: the
  // open element ends where it meets the circle (the first point along it, as G461 would find)
  // and the rest of the circle is traversed; if it misses the circle, where it meets the
  // retraction line. The blocks after the open element are skipped (TRC-LOOK-3).
  void retract_edge_around(const Block& b, const Block& last_block, const KontCorner& k) {
    if (!kont_circle(b, k))
      throw UnsupportedError(  // TRC-EDGE-7 (planned)
          b.words.line, "KONT retraction from behind by intersection (G451) after a too-short last block");
    Point r_point = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d2), comp_->side_radius);
    EdgeCurve circle;
    circle.carrier.circle = true, circle.carrier.point = k.vertex, circle.carrier.radius = leaf(comp_->radius);
    EdgeHit hit = edge_hit(circle, *open_, open_radius_, open_start_, false);
    decide("TRC-EDGE-6", b.words.line, hit.point ? "circle" : "line", hit.margin);
    bool on_circle = hit.point.has_value();
    if (!on_circle) {
      EdgeCurve line;
      line.bound = EdgeCurve::Bound::kSegment, line.carrier.point = r_point, line.carrier.direction = k.point - r_point;
      hit = edge_hit(line, *open_, open_radius_, open_start_, false);
      decide("TRC-EDGE-5", b.words.line, hit.point ? "hit" : "none", hit.margin);
      if (!hit.point) return raise(10751, b);
    }
    const Point x = *hit.point;
    looking_ = false;
    if (!close_open(x, b)) return;
    run_skipped(x);
    if (!on_circle) return retraction_line(b, x);
    Origin corner = origin(last_block, OriginKind::kTransitionCircle);
    corner.next_line = b.words.line, corner.next_block = b.words.number;
    Decimal h = coord(b.start, comp_->axes.applicate);
    emit_arc(b, at({x, h}), at({r_point, h}), at({k.vertex, h}), comp_->side_radius, comp_->s < 0, corner, comp_->axes);
    retraction_line(b, r_point);
  }

  // TRC-RETR-NORM-1: the straight line to the programmed end point, a tool-centre position.
  void retraction_line(const Block& b, const Point& from_point) {
    ExactPoint from = at({from_point, coord(b.start, comp_->axes.applicate)});
    ExactPoint to = at(b.end);
    FT length = path.distance(from, to);
    decide("TRC-RETR-NORM-1", b.words.line, CGAL::sign(length) == CGAL::ZERO ? "zero-length" : "line",
           exact_mm(length));
    emit_line(b, from, to, OriginKind::kRetraction);
    phase_ = Phase::kOff;
    comp_.reset();
    open_.reset();
  }

  // TRC-KONT-3 / TRC-KONT-4 on retraction: the retraction line is a contour element starting at
  // the end point E and meeting the last block at an outer corner.
  void retract_around(const Block& b, const KontCorner& k) {
    Point r = equidistant_point<Kernel>(k.vertex, unit_left_normal(k.d2), comp_->side_radius);
    bool circle = kont_circle(b, k);
    std::optional<Point> x;
    if (!circle) x = kont_intersection(b, k, *open_, open_radius_, r, k.d2);
    if (!x) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
      decide("TRC-KONT-3", b.words.line, "circle");
      Point from = equidistant_point<Kernel>(k.vertex, open_->end_normal(), comp_->side_radius);
      Origin corner = origin(*open_block_, OriginKind::kTransitionCircle);
      corner.next_line = b.words.line, corner.next_block = b.words.number;
      if (!close_open(from, b, true)) return;
      run_held_back(from);
      Decimal h = coord(b.start, comp_->axes.applicate);
      if (comp_->radius.sign() != 0)  // TRC-G450-2
        emit_arc(b, at({from, h}), at({r, h}), at({k.vertex, h}), comp_->side_radius, comp_->s < 0, corner,
                 comp_->axes);
      return retraction_line(b, r);
    }
    decide("TRC-KONT-4", b.words.line, "intersection");
    if (!close_open(*x, b)) return;
    run_held_back(*x);
    retraction_line(b, *x);
  }

  // TRC-END-1: the program ends while compensation is selected.
  void end_of_program() {
    if (looking_) {  // the program ends before an intersection was found
      decide("TRC-LOOK-2", skipped_.back()->words.line, "none");
      return raise(10751, *skipped_.back());
    }
    if (phase_ == Phase::kApproach) {
      decide("TRC-END-1", selection_->words.line, "no-contour");
      sink_.notice(
          {selection_->words.line, "TRC-END-1", "compensation selected but no block with motion in the plane follows"});
      emit_line(*selection_, selection_start(), at(selection_->end), OriginKind::kProgrammed);
      run_held_back_uncompensated();
    } else if (phase_ == Phase::kActive) {
      decide("TRC-END-1", open_->line, "active-at-end");
      sink_.notice(
          {open_->line, "TRC-END-1", "program ends with compensation active: last block ends at its normal point"});
      Point end = equidistant_point<Kernel>(open_->b, open_->end_normal(), comp_->side_radius);
      if (!close_open(end, *open_block_, true)) return;
      run_held_back(end);
    }
  }

  std::deque<Block> program_;
  const MachineData& md_;
  PathSink& sink_;
  std::vector<int> seq_;  // per block: the ordinal of the last traversing block up to it (TRC-CD-1)
  int traversing_ = 0;
  HeldOutput held_;
  std::vector<bool> actions_done_;
  Phase phase_ = Phase::kOff;
  bool stopped_ = false;
  bool d0_noticed_ = false;
  std::optional<Compensation> comp_;
  const Block* selection_ = nullptr;
  const Block* prev_block_ = nullptr;         // the last traversing block with compensation (TRC-CD-1)
  std::optional<ExactPoint> selection_from_;  // set after a side change (TRC-SIDE-1)
  std::vector<const Block*> dummies_;
  // TRC-APPR-NORM-1: the approach line and the blocks held back before the first contour block,
  // output once the first element's end is known (TRC-EDGE-* may replace them).
  struct PendingApproach {
    ExactPoint from, to;
    std::vector<const Block*> held_back;
  };
  std::optional<PendingApproach> approach_;
  bool kont_first_ = false;  // the open element is the first after a KONT travel-around
  std::optional<ContourElement> open_;
  const Block* open_block_ = nullptr;
  Point open_start_;
  FT open_radius_;  // arcs: radius of the open element's equidistant
  bool open_at_normal_start_ = false;
  // Look-ahead (TRC-LOOK-*): blocks passed over, traversing blocks examined after the open element.
  bool looking_ = false;
  std::vector<const Block*> skipped_;
  int examined_ = 0;
  int dummy_run_ = 0;
};

}  // namespace

bool run_exact(ProgramReader& reader, const MachineData& md, PathSink& sink, ExactPath& path) {
  Reference engine(md, sink);
  bool ok = engine.run(reader);
  path = std::move(engine.path);
  return ok;
}

bool run(ProgramReader& reader, const MachineData& md, PathSink& sink, ExactCheckReport* checks) {
  Reference engine(md, sink);
  bool ok = engine.run(reader);
  if (checks) engine.path.check(*checks);
  return ok;
}

}  // namespace cutcom::ref

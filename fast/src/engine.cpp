// fast's TRC state machine for the straight-line slice. Clause IDs name the spec rule each step
// implements; ref implements the same clauses independently in exact arithmetic.
#include "cutcom/fast/engine.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "plane_geometry.hpp"

namespace cutcom::fast {

namespace {

// What fast keeps of a block: converted once, copied into fixed slots (no allocation).
struct BlockCopy {
  int line = 0;
  std::optional<std::int64_t> number;
  PathPoint start, end;  // programmed, workpiece coordinates
  bool rapid = false;
  Decimal feed;
  std::array<AuxFunction, BlockWords::kMaxAux> aux{};
  int aux_count = 0;
  bool actions_done = false;

  static BlockCopy of(const Block& b) {
    BlockCopy c;
    c.line = b.words.line;
    c.number = b.words.number;
    c.start = {b.start.x.to_double(), b.start.y.to_double(), b.start.z.to_double()};
    c.end = {b.end.x.to_double(), b.end.y.to_double(), b.end.z.to_double()};
    c.rapid = b.state.motion == Motion::kRapid;
    c.feed = b.state.feed;
    c.aux = b.words.aux;
    c.aux_count = b.words.aux_count;
    return c;
  }
};

double pick(const PathPoint& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

}  // namespace

struct Engine::State {
  enum class Phase { kOff, kApproach, kActive };

  State(const MachineData& m, PathSink& out) : md(m), sink(out) {}

  const MachineData& md;
  PathSink& sink;
  Phase phase = Phase::kOff;
  bool stopped = false;
  bool d0_noticed = false;

  // Compensation in force (set at selection).
  PlaneAxes axes{0, 1, 2};
  Plane plane = Plane::kG17;
  Side side = Side::kOff;
  int s = 0;     // +1 left, -1 right (after TRC-RADIUS-2)
  double r = 0;  // |effective radius|
  ActiveEdge edge;

  BlockCopy selection;  // kApproach: the selection block
  // kActive: the open element, whose end waits for the next traversing block.
  BlockCopy open;
  LineSegment open_seg;
  Vec2 open_start;       // start point of its equidistant (after the previous corner)
  double open_trim = 0;  // shortening at its start
  // Blocks without motion in the plane since the last traversing block (fixed capacity).
  std::array<BlockCopy, MachineData::kMaxDummyBlocks + 1> dummies;
  int dummy_count = 0;

  // --- plane <-> workpiece coordinates -------------------------------------------------------
  Vec2 ab(const PathPoint& p) const { return {pick(p, axes.abscissa), pick(p, axes.ordinate)}; }
  double h(const PathPoint& p) const { return pick(p, axes.applicate); }
  PathPoint xyz(Vec2 v, double applicate) const {
    PathPoint p;
    double* c[3] = {&p.x, &p.y, &p.z};
    *c[axes.abscissa] = v.a, *c[axes.ordinate] = v.b, *c[axes.applicate] = applicate;
    return p;
  }

  // --- output ----------------------------------------------------------------------------------
  void decide(std::string_view clause, int line, std::string_view branch) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch;
    sink.decision(d);
  }
  void decide(std::string_view clause, int line, std::string_view branch, double margin) {
    Decision d;
    d.clause = clause, d.line = line, d.branch = branch, d.has_margin = true, d.margin = margin;
    sink.decision(d);
  }
  void raise(int number, int line, std::optional<std::int64_t> block) {
    sink.alarm(make_alarm(number, line, block));
    stopped = true;
  }
  void actions(BlockCopy& b, const PathPoint& at) {
    if (b.actions_done) return;
    b.actions_done = true;
    for (int i = 0; i < b.aux_count; ++i) sink.action({b.line, b.number, b.aux[static_cast<std::size_t>(i)], at});
  }
  Origin origin(const BlockCopy& b, OriginKind kind) const {
    Origin o;
    o.kind = kind, o.line = b.line, o.block = b.number;
    return o;
  }
  void line(BlockCopy& owner, const PathPoint& from, const PathPoint& to, OriginKind kind, bool rapid) {
    actions(owner, from);
    if (from.x == to.x && from.y == to.y && from.z == to.z) return;  // PATH-ELEMENT-1: no zero-length element
    PathElement e;
    e.type = ElementType::kLine, e.rapid = rapid, e.start = from, e.end = to, e.feed = owner.feed;
    e.origin = origin(owner, kind);
    sink.element(e);
  }

  // TRC-DUMMY-1: blocks without motion in the plane run at the corner point P*.
  void run_dummies(Vec2 at) {
    for (int i = 0; i < dummy_count; ++i) {
      BlockCopy& d = dummies[static_cast<std::size_t>(i)];
      line(d, xyz(at, h(d.start)), xyz(at, h(d.end)), OriginKind::kInfeed, d.rapid);
    }
    dummy_count = 0;
  }
  void run_dummies_uncompensated() {
    for (int i = 0; i < dummy_count; ++i) {
      BlockCopy& d = dummies[static_cast<std::size_t>(i)];
      line(d, d.start, d.end, OriginKind::kProgrammed, d.rapid);
    }
    dummy_count = 0;
  }
  // TRC-DUMMY-2: at most MD20250 of them between two traversing blocks.
  void queue_dummy(const Block& b) {
    if (dummy_count == md.cutcom_maxnum_dummy_blocks) return raise(10762, b.words.line, b.words.number);
    dummies[static_cast<std::size_t>(dummy_count++)] = BlockCopy::of(b);
  }

  // TRC-ELEMENT-1: the open element ends `trim_end` before its normal end point; it must not
  // reverse. Emits it (unless it vanishes). Returns false when an alarm stopped the program.
  // The alarm names `alarm_line`: the block whose preparation found the problem.
  bool close_open(Vec2 end_point, double trim_end, int alarm_line, std::optional<std::int64_t> alarm_block) {
    double margin = open_seg.length - open_trim - trim_end;
    if (margin < 0) {
      decide("TRC-ELEMENT-1", open.line, "reverses", margin);
      raise(10751, alarm_line, alarm_block);
      return false;
    }
    decide("TRC-ELEMENT-1", open.line, margin == 0 ? "vanishes" : "fits", margin);
    if (margin == 0) {
      actions(open, xyz(end_point, h(open.end)));
      return true;
    }
    line(open, xyz(open_start, h(open.start)), xyz(end_point, h(open.end)), OriginKind::kOffset, open.rapid);
    return true;
  }

  void open_element(const Block& b, const LineSegment& seg, Vec2 start, double trim) {
    open = BlockCopy::of(b);
    open_seg = seg;
    open_start = start;
    open_trim = trim;
  }

  // --- checks shared by the phases with compensation in force --------------------------------
  // Returns false if the block ended the program with an alarm.
  bool check_active_block(const Block& b) {
    if (b.state.side == Side::kOff) {
      if (b.is_arc() && b.programs_plane_axis()) {  // TRC-DESEL-2
        raise(10754, b.words.line, b.words.number);
        return false;
      }
      return true;
    }
    if (b.state.plane != plane) {  // TRC-PLANE-1
      raise(10757, b.words.line, b.words.number);
      return false;
    }
    if (b.is_arc())
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "circular interpolation G2/G3 with compensation active");
    if (b.state.side != side)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "change of compensation side G41/G42 without G40");
    if (b.words.side)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "re-selection of G41/G42 while compensation is active");
    if (!(ActiveEdge::of(b.state) == edge))
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "change of tool, D number or OFFN while compensation is active");
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT approach (needs polynomial output)");
    return true;
  }

  // --- phase: compensation off -----------------------------------------------------------------
  void off(const Block& b) {
    if (b.state.side != Side::kOff) {
      if (b.is_arc()) return raise(10753, b.words.line, b.words.number);  // TRC-SEL-2
      if (!b.programs_plane_axis()) {
        decide("TRC-SEL-4", b.words.line, "no-plane-axis");
      } else if (b.state.tool == 0) {
        return raise(10750, b.words.line, b.words.number);  // TRC-SEL-6
      } else if (b.state.edge == 0) {
        decide("TRC-SEL-5", b.words.line, "d0");
        if (!d0_noticed) sink.notice({b.words.line, "TRC-SEL-5", "G41/G42 with D0: no compensation"});
        d0_noticed = true;
      } else if (!b.state.edge_defined) {
        return raise(17181, b.words.line, b.words.number);  // TRC-SEL-7
      } else {
        return select(b);
      }
    }
    if (b.is_arc())
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "circular interpolation G2/G3");
    BlockCopy c = BlockCopy::of(b);
    line(c, c.start, c.end, OriginKind::kProgrammed, c.rapid);
  }

  void select(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT approach (needs polynomial output)");
    if (b.state.approach == ApproachMode::kKont)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONT approach");
    // TRC-SEL-1; TRC-SEL-3: a single plane axis was completed by the reader (NC-POS-1).
    decide("TRC-SEL-1", b.words.line, "selected");
    plane = b.state.plane;
    axes = plane_axes(plane);
    side = b.state.side;
    edge = ActiveEdge::of(b.state);
    Decimal eff = b.state.effective_radius();
    int sign = side == Side::kLeft ? 1 : -1;
    // TRC-RADIUS-2: a negative effective radius swaps the side.
    decide("TRC-RADIUS-2", b.words.line, eff.sign() < 0 ? "negative" : eff.sign() == 0 ? "zero" : "positive");
    s = eff.sign() < 0 ? -sign : sign;
    r = std::fabs(eff.to_double());
    selection = BlockCopy::of(b);
    dummy_count = 0;
    phase = Phase::kApproach;
  }

  // --- phase: selection block waiting for the first contour block --------------------------
  void approach(const Block& b) {
    if (b.state.side == Side::kOff) {
      // TRC-SEL-8: deselected before any traversing block: no selection takes place.
      decide("TRC-SEL-8", selection.line, "deselected-before-contour");
      line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
      run_dummies_uncompensated();
      phase = Phase::kOff;
      return off(b);
    }
    if (!check_active_block(b)) return;
    if (!b.moves_in_plane()) return queue_dummy(b);  // TRC-DUMMY-3: no in-plane displacement
    // TRC-APPR-NORM-1: straight to the normal point of the first contour element's start.
    BlockCopy first = BlockCopy::of(b);
    LineSegment seg = LineSegment::between(ab(first.start), ab(first.end));
    Vec2 q = seg.offset(seg.start, s * r);
    PathPoint to = xyz(q, h(selection.end));
    double length = std::sqrt((to.x - selection.start.x) * (to.x - selection.start.x) +
                              (to.y - selection.start.y) * (to.y - selection.start.y) +
                              (to.z - selection.start.z) * (to.z - selection.start.z));
    decide("TRC-APPR-NORM-1", selection.line, length == 0 ? "zero-length" : "line", length);
    line(selection, selection.start, to, OriginKind::kApproach, selection.rapid);
    run_dummies(q);
    open_element(b, seg, q, 0);
    phase = Phase::kActive;
  }

  // --- phase: compensation active --------------------------------------------------------------
  void active(const Block& b) {
    if (!check_active_block(b)) return;
    if (b.state.side == Side::kOff) {
      if (!b.programs_plane_axis()) {
        decide("TRC-DESEL-3", b.words.line, "no-plane-axis");
        return queue_dummy(b);
      }
      return deselect(b);
    }
    if (!b.moves_in_plane()) return queue_dummy(b);  // TRC-DUMMY-3
    corner(b);
  }

  void corner(const Block& b) {
    BlockCopy next = BlockCopy::of(b);
    LineSegment seg = LineSegment::between(ab(next.start), ab(next.end));
    Vec2 v = open_seg.end;
    Corner c = classify_corner(open_seg, seg, s, r);
    static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
    decide("TRC-CORNER-1", b.words.line, kKind[static_cast<int>(c.kind)], c.sine);

    bool circle = c.kind == Corner::Kind::kReversal;  // TRC-G450-3: a reversal is always a circle
    if (c.kind == Corner::Kind::kOuter) {
      // TRC-CORNER-2: the contour angle is the deflection angle, in degrees.
      double angle = std::atan2(std::fabs(c.sine), c.cosine) * (180.0 / std::numbers::pi);
      if (b.state.corner == CornerMode::kG451) {
        // TRC-CORNER-3: G451 switches to G450 above MD20210.
        double limit = md.cutcom_corner_limit.to_double();
        circle = angle > limit;
        decide("TRC-CORNER-3", b.words.line, circle ? "switch-to-G450" : "keep-G451", angle - limit);
      } else {
        // TRC-CORNER-4: G450 switches to G451 below MD20230.
        double limit = md.cutcom_curve_insert_limit.to_double();
        circle = !(angle < limit);
        decide("TRC-CORNER-4", b.words.line, circle ? "keep-G450" : "switch-to-G451", angle - limit);
      }
    }
    if (circle) {
      // TRC-G450-1: circle of radius r about the programmed corner, joining the normal points.
      Vec2 from = open_seg.offset(v, s * r);
      if (!close_open(from, 0, b.words.line, b.words.number)) return;
      run_dummies(from);
      Vec2 to = seg.offset(v, s * r);
      if (r > 0) {  // TRC-G450-2: no circle for a zero radius
        actions(next, xyz(from, h(next.start)));
        PathElement e;
        e.type = ElementType::kArc, e.rapid = next.rapid, e.feed = next.feed;
        e.start = xyz(from, h(next.start)), e.end = xyz(to, h(next.start)), e.center = xyz(v, h(next.start));
        e.ccw = s < 0;  // around the outside: clockwise on the left, counter-clockwise on the right
        e.origin = origin(open, OriginKind::kTransitionCircle);
        e.origin.next_line = next.line, e.origin.next_block = next.number;
        sink.element(e);
      }
      return open_element(b, seg, to, 0);
    }
    // TRC-G451-1 / TRC-INNER-1 / tangent: both equidistants end at their intersection.
    Vec2 x = open_seg.offset(v, s * r) - c.trim * open_seg.unit;
    if (!close_open(x, c.trim, b.words.line, b.words.number)) return;
    run_dummies(x);
    open_element(b, seg, x, c.trim);
  }

  // TRC-DESEL-1, TRC-RETR-NORM-1: the last element ends at its normal point, then a straight
  // line to the programmed end point of the deselection block.
  void deselect(const Block& b) {
    Vec2 end = open_seg.offset(open_seg.end, s * r);
    decide("TRC-DESEL-1", b.words.line, "deselected");
    if (!close_open(end, 0, b.words.line, b.words.number)) return;
    run_dummies(end);
    BlockCopy last = BlockCopy::of(b);
    PathPoint from = xyz(end, h(last.start));
    double length =
        std::sqrt((last.end.x - from.x) * (last.end.x - from.x) + (last.end.y - from.y) * (last.end.y - from.y) +
                  (last.end.z - from.z) * (last.end.z - from.z));
    decide("TRC-RETR-NORM-1", b.words.line, length == 0 ? "zero-length" : "line", length);
    line(last, from, last.end, OriginKind::kRetraction, last.rapid);
    phase = Phase::kOff;
  }

  // TRC-END-1: the program ends with compensation in force.
  void end_of_program() {
    if (phase == Phase::kApproach) {
      decide("TRC-END-1", selection.line, "no-contour");
      sink.notice({selection.line, "TRC-END-1", "compensation selected but no block with motion in the plane follows"});
      line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
      run_dummies_uncompensated();
    } else if (phase == Phase::kActive) {
      decide("TRC-END-1", open.line, "active-at-end");
      sink.notice(
          {open.line, "TRC-END-1", "program ends with compensation active: last block ends at its normal point"});
      Vec2 end = open_seg.offset(open_seg.end, s * r);
      if (!close_open(end, 0, open.line, open.number)) return;
      run_dummies(end);
    }
    phase = Phase::kOff;
  }
};

Engine::Engine(const MachineData& md, PathSink& sink) : state_(std::make_unique<State>(md, sink)) {}
Engine::~Engine() = default;

bool Engine::stopped() const { return state_->stopped; }

void Engine::push(const Block& b) {
  State& st = *state_;
  if (st.stopped) return;
  switch (st.phase) {
    case State::Phase::kOff:
      return st.off(b);
    case State::Phase::kApproach:
      return st.approach(b);
    case State::Phase::kActive:
      return st.active(b);
  }
}

void Engine::finish() {
  if (!state_->stopped) state_->end_of_program();
}

bool run(ProgramReader& reader, const MachineData& md, PathSink& sink) {
  Engine engine(md, sink);
  Block b;
  while (!engine.stopped() && reader.next(b)) engine.push(b);
  // NC-ERR-2: a reading error anywhere rejects the program, even after an alarm.
  while (engine.stopped() && reader.next(b)) {
  }
  engine.finish();
  return !engine.stopped();
}

}  // namespace cutcom::fast

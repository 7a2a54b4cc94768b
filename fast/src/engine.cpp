// fast's TRC state machine (lines, circles, corners, look-ahead). Clause IDs name the spec rule each step
// implements; ref implements the same clauses independently in exact arithmetic.
#include "cutcom/fast/engine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "bottleneck.hpp"
#include "edge_strategy.hpp"
#include "plane_geometry.hpp"

namespace cutcom::fast {

namespace {

// What fast keeps of a block: converted once, copied into fixed slots (no allocation).
struct BlockCopy {
  int line = 0;
  std::optional<std::int64_t> number;
  PathPoint start, end;  // programmed, workpiece coordinates
  bool rapid = false;
  bool arc = false;  // G2/G3 with I/J/K
  int sense = 1;     // +1 G3, -1 G2
  PathPoint centre;  // programmed centre (I/J/K arcs)
  bool has_centre = false;
  double cr = 0;                  // CR= arcs
  std::array<Int128, 3> delta{};  // exact programmed displacement X Y Z, units of 1e-9 mm
  Decimal feed;
  std::array<AuxFunction, BlockWords::kMaxAux> aux{};
  int aux_count = 0;
  bool actions_done = false;
  bool kont = false;  // KONT in force (approach and retraction)
  bool g451 = false;  // G451 in force
  bool cdon = false;  // CDON in force
  int seq = 0;        // ordinal of the last traversing block up to this one (TRC-CD-1 window)
  EdgeStrategy edge_strategy = EdgeStrategy::kG462;

  static BlockCopy of(const Block& b) {
    BlockCopy c;
    c.line = b.words.line;
    c.number = b.words.number;
    c.start = {b.start.x.to_double(), b.start.y.to_double(), b.start.z.to_double()};
    c.end = {b.end.x.to_double(), b.end.y.to_double(), b.end.z.to_double()};
    c.rapid = b.state.motion == Motion::kRapid;
    c.arc = b.is_arc();
    c.sense = b.state.motion == Motion::kArcCcw ? 1 : -1;
    c.has_centre = b.centre.has_value();
    if (b.centre) c.centre = {b.centre->x.to_double(), b.centre->y.to_double(), b.centre->z.to_double()};
    if (b.words.cr) c.cr = b.words.cr->to_double();
    c.delta = {(b.end.x - b.start.x).units(), (b.end.y - b.start.y).units(), (b.end.z - b.start.z).units()};
    c.feed = b.state.feed;
    c.aux = b.words.aux;
    c.aux_count = b.words.aux_count;
    c.kont = b.state.approach == ApproachMode::kKont;
    c.g451 = b.state.corner == CornerMode::kG451;
    c.cdon = b.state.collision == CollisionMode::kCdon;
    c.edge_strategy = b.state.edge_strategy;
    return c;
  }
};

double pick(const PathPoint& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

}  // namespace

struct Engine::State {
  enum class Phase { kOff, kApproach, kActive };

  State(const MachineData& m, PathSink& out) : md(m), sink(out) {
    // TRC-CD-1: what the window can hold: MD20240 + 2 traversing blocks, each with up to MD20250
    // blocks without plane motion, each block at most three elements and its actions.
    std::size_t capacity = static_cast<std::size_t>(m.cutcom_maxnum_check_blocks + 2) *
                           static_cast<std::size_t>(m.cutcom_maxnum_dummy_blocks + 1) * (3 + BlockWords::kMaxAux);
    held.reserve(capacity);
    held_scratch.reserve(capacity);
  }

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

  BlockCopy selection;               // kApproach: the selection block
  bool selection_from_tool = false;  // its start is the tool after a side change (TRC-SIDE-1)
  // TRC-APPR-NORM-1: the approach line and the blocks held back before the first contour block,
  // output once the first element's end is known.
  bool approach_pending = false;
  PathPoint approach_to;
  std::array<BlockCopy, MachineData::kMaxDummyBlocks + 1> approach_dummies;
  int approach_dummy_count = 0;
  bool kont_first = false;  // the open element is the first after a KONT travel-around
  // kActive: the open element, whose end waits for the next traversing block.
  BlockCopy open;
  Element open_el;
  Vec2 open_start;         // start point of its equidistant (after the previous corner)
  double open_radius = 0;  // arcs: radius of its equidistant
  // Blocks without motion in the plane since the last traversing block (fixed capacity).
  std::array<BlockCopy, MachineData::kMaxDummyBlocks + 1> dummies;
  int dummy_count = 0;
  // Look-ahead (TRC-LOOK-*): blocks passed over while trying later blocks (fixed capacity: at most
  // MD20240 traversing blocks, each after at most MD20250 blocks without plane motion).
  bool looking = false;
  // Reserved once, at the first look-ahead: never reallocated, nothing allocated per block.
  static constexpr std::size_t kSkippedCapacity = MachineData::kMaxCheckBlocks * (MachineData::kMaxDummyBlocks + 1);
  std::vector<BlockCopy> skipped;
  int examined = 0, dummy_run = 0;

  // TRC-CD-1: output waits here, in path order, until the MD20240 window has passed it (under
  // CDON); a bottleneck cut removes what follows the cut point. Reserved once.
  struct HeldRecord {
    int seq = 0;  // the owner's traversing ordinal
    bool is_element = false;
    PathElement element;
    double radius = 0;  // arcs: radius in the plane
    ActionEvent action;
    int owner_line = 0;  // the block it belongs to, to run it again at a cut
    std::optional<std::int64_t> owner_number;
    PathPoint owner_start, owner_end;
    bool owner_rapid = false;
    Decimal owner_feed;
  };
  std::vector<HeldRecord> held, held_scratch;
  bool holding = false;  // CDON in force for the block being processed: output waits in `held`
  int traversing = 0;
  std::array<BlockCopy, 2> prev_blocks;  // the last traversing block with compensation and the one before
  int prev_slot = 0;
  bool has_prev = false;
  EdgeCurve approach_curve;  // TRC-CD-6: the approach's curve, searched up to block approach_until
  int approach_until = -1;

  BlockCopy copy_of(const Block& b) const {
    BlockCopy c = BlockCopy::of(b);
    c.seq = traversing;
    return c;
  }
  HeldRecord record_of(const BlockCopy& owner) const {
    HeldRecord k;
    k.seq = owner.seq, k.owner_line = owner.line, k.owner_number = owner.number, k.owner_start = owner.start;
    k.owner_end = owner.end, k.owner_rapid = owner.rapid, k.owner_feed = owner.feed;
    return k;
  }
  // Under CDOF with nothing held, output goes straight out (it would be released at the block's end).
  bool direct() const { return !holding && held.empty(); }
  // Releases the records of traversing blocks before `seq`.
  void release_before(int seq) {
    std::size_t n = 0;
    for (; n < held.size() && held[n].seq < seq; ++n) {
      if (held[n].is_element)
        sink.element(held[n].element);
      else
        sink.action(held[n].action);
    }
    held.erase(held.begin(), held.begin() + static_cast<std::ptrdiff_t>(n));
  }
  void release_all() { release_before(std::numeric_limits<int>::max()); }
  // With CDON in force the output of the last MD20240 traversing blocks waits; otherwise it goes
  // out block by block.
  void release_window(const Block& b) {
    if (stopped) return;
    bool window = phase == Phase::kActive && b.state.collision == CollisionMode::kCdon;
    if (!window) return release_all();
    release_before(traversing + 1 - md.cutcom_maxnum_check_blocks);
  }

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
  void raise(int number, int line, std::optional<std::int64_t> block, std::string_view clause = {}) {
    flush_approach();  // ALARM-1: what was decided before the alarm is output
    release_all();
    sink.alarm(make_alarm(number, line, block, clause));
    stopped = true;
  }
  void actions(BlockCopy& b, const PathPoint& at) {
    if (b.actions_done) return;
    b.actions_done = true;
    for (int i = 0; i < b.aux_count; ++i) {
      ActionEvent a{b.line, b.number, b.aux[static_cast<std::size_t>(i)], at};
      if (direct()) {
        sink.action(a);
        continue;
      }
      HeldRecord rec = record_of(b);
      rec.action = a;
      held.push_back(rec);
    }
  }
  Origin origin(const BlockCopy& b, OriginKind kind) const {
    Origin o;
    o.kind = kind, o.line = b.line, o.block = b.number;
    return o;
  }
  void line(BlockCopy& owner, const PathPoint& from, const PathPoint& to, OriginKind kind, bool rapid) {
    line(owner, from, to, origin(owner, kind), rapid);
  }
  void line(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const Origin& named, bool rapid) {
    actions(owner, from);
    if (from.x == to.x && from.y == to.y && from.z == to.z) return;  // PATH-ELEMENT-1: no zero-length element
    PathElement e;
    e.type = ElementType::kLine, e.rapid = rapid, e.start = from, e.end = to, e.feed = owner.feed;
    e.origin = named;
    if (direct()) return sink.element(e);
    HeldRecord rec = record_of(owner);
    rec.is_element = true, rec.element = e;
    held.push_back(rec);
  }

  void arc(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const PathPoint& centre, bool ccw,
           const Origin& from_what) {
    actions(owner, from);
    PathElement e;
    e.type = ElementType::kArc, e.rapid = owner.rapid, e.start = from, e.end = to, e.center = centre, e.ccw = ccw;
    e.feed = owner.feed, e.origin = from_what;
    if (direct()) return sink.element(e);
    HeldRecord rec = record_of(owner);
    rec.is_element = true, rec.element = e, rec.radius = norm(ab(from) - ab(centre));
    held.push_back(rec);
  }

  Element element_of(const BlockCopy& c) const {
    if (!c.arc) return Element::line(ab(c.start), ab(c.end));
    if (c.has_centre) return Element::circle(ab(c.start), ab(c.end), ab(c.centre), c.sense);
    return Element::circle_by_radius(ab(c.start), ab(c.end), c.cr, c.sense);
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
    dummies[static_cast<std::size_t>(dummy_count++)] = copy_of(b);
  }

  // TRC-ELEMENT-1 / TRC-ARC-ELEMENT-1: the open element, from its start point to `end_point`, must
  // not run backwards; it is output unless its length is 0. The alarm names `alarm_line`: the
  // block whose preparation found the problem. False when an alarm stopped the program.
  // `candidate`: the block whose equidistant fixed this end (for TRC-EDGE-* on approach).
  struct Candidate {
    const BlockCopy* block;
    const Element* element;
    double radius;
  };
  bool close_open(Vec2 end_point, int alarm_line, std::optional<std::int64_t> alarm_block,
                  const Candidate* candidate = nullptr) {
    const Element& e = open_el;
    double margin;
    if (!e.arc) {
      margin = dot(end_point - open_start, e.unit);
    } else {
      double left = sweep(e) - signed_rotation(e.start - e.centre, open_start - e.centre, e.sense) +
                    signed_rotation(e.end - e.centre, end_point - e.centre, e.sense);
      margin = left * open_radius;
    }
    std::string_view clause = e.arc ? "TRC-ARC-ELEMENT-1" : "TRC-ELEMENT-1";
    if (margin < 0) {
      decide(clause, open.line, "reverses", margin);
      // TRC-EDGE-1: the first element after the approach is too short for its neighbour.
      if (approach_pending && candidate) return approach_edge(*candidate), false;
      if (kont_first && candidate)
        throw UnsupportedError(  // TRC-EDGE-7 (planned)
            selection.line, "KONT approach from behind the contour before a too-short first block");
      raise(10751, alarm_line, alarm_block);
      return false;
    }
    decide(clause, open.line, margin == 0 ? "vanishes" : "fits", margin);
    flush_approach();
    kont_first = false;
    PathPoint from = xyz(open_start, h(open.start)), to = xyz(end_point, h(open.end));
    if (margin == 0) {
      actions(open, to);
      return true;
    }
    if (!e.arc) {
      line(open, from, to, OriginKind::kOffset, open.rapid);
    } else {
      arc(open, from, to, xyz(e.centre, h(open.start)), e.sense > 0, origin(open, OriginKind::kOffset));
    }
    return true;
  }

  // TRC-CORNER-1 for two straight blocks, exactly: their displacements are whole numbers of
  // 1e-9 mm, and while each component stays below 2^62 the cross and dot products fit in 128 bits.
  // Tangency and reversal are then seen as ref sees them, not as a 1e-17 remainder.
  struct ExactProducts {
    Int128 cross, dot;
  };
  std::optional<ExactProducts> exact_products(const std::array<Int128, 3>& t, const std::array<Int128, 3>& u) const {
    const Int128 limit = Int128(1) << 62;
    Int128 a1 = t[static_cast<std::size_t>(axes.abscissa)], b1 = t[static_cast<std::size_t>(axes.ordinate)];
    Int128 a2 = u[static_cast<std::size_t>(axes.abscissa)], b2 = u[static_cast<std::size_t>(axes.ordinate)];
    for (Int128 v : {a1, b1, a2, b2})
      if (v >= limit || v <= -limit) return std::nullopt;  // beyond the range: the double decision stands
    return ExactProducts{a1 * b2 - b1 * a2, a1 * a2 + b1 * b2};
  }

  void decide_kind_exactly(const BlockCopy& first, const BlockCopy& second, Corner& c) const {
    std::optional<ExactProducts> p = exact_products(first.delta, second.delta);
    if (!p) return;
    Int128 cr = p->cross, dt = p->dot;
    if (cr == 0) {
      c.kind = dt > 0 ? Corner::Kind::kTangent : Corner::Kind::kReversal;
      c.sine = 0;
    } else {
      c.kind = (cr > 0) == (s > 0) ? Corner::Kind::kInner : Corner::Kind::kOuter;
    }
  }

  // TRC-ARC-EQ-1: a circle's equidistant must keep a positive radius; a collapsed one is passed
  // over by the look-ahead.
  bool equidistant_exists(const Block& b, const Element& e, double& radius) {
    if (!e.arc) return true;
    radius = e.equidistant_radius(s * r);
    decide("TRC-ARC-EQ-1", b.words.line, radius > 0 ? "concentric" : "collapses", radius);
    return radius > 0;
  }

  void open_element(const BlockCopy& b, const Element& e, Vec2 start, double radius) {
    open = b;
    open_el = e;
    open_start = start;
    open_radius = radius;
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
    if (b.state.side != side) return true;  // TRC-SIDE-1, handled by the caller
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
    BlockCopy c = copy_of(b);
    if (!c.arc) return line(c, c.start, c.end, OriginKind::kProgrammed, c.rapid);
    // A programmed circle about its (corrected, ARC-CENTRE-1) centre.
    axes = plane_axes(b.state.plane);
    Element e = element_of(c);
    arc(c, c.start, c.end, xyz(e.centre, h(c.start)), c.sense > 0, origin(c, OriginKind::kProgrammed));
  }

  // TRC-SIDE-1 (ruling 30): G41 <-> G42 without G40: the old side's last element ends at its normal
  // end point; the first new-side block with a plane axis is a selection block from the tool.
  void change_side(const Block& b) {
    if (b.is_arc()) return raise(10753, b.words.line, b.words.number);  // TRC-SEL-2
    if (!b.programs_plane_axis()) {
      decide("TRC-SIDE-1", b.words.line, "no-plane-axis");
      return queue_dummy(b);
    }
    decide("TRC-SIDE-1", b.words.line, "side-change");
    Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
    if (!close_open(end, b.words.line, b.words.number)) return;
    run_dummies(end);
    PathPoint tool = xyz(end, h(copy_of(b).start));
    select(b);
    selection.start = tool;  // the approach starts where the tool is
    selection_from_tool = true;
  }

  void select(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT approach (needs polynomial output)");
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
    selection = copy_of(b);
    selection_from_tool = false;
    has_prev = false;
    approach_until = -1;
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
    if (b.state.side != side)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "change of compensation side G41/G42 before the first contour block");
    if (!b.moves_in_plane()) return queue_dummy(b);  // TRC-DUMMY-3: no in-plane displacement
    prev_slot ^= 1;
    prev_blocks[static_cast<std::size_t>(prev_slot)] = copy_of(b);
    const BlockCopy& first = prev_blocks[static_cast<std::size_t>(prev_slot)];
    has_prev = true;
    Element e = element_of(first);
    double radius = 0;
    if (!equidistant_exists(b, e, radius)) return raise(10751, b.words.line, b.words.number);
    if (selection.kont) {
      // TRC-KONT-1: the corner of the approach line (start -> S) with the first block.
      Kont k{e.start, ab(selection.start), e.start - ab(selection.start), e.start_tangent(), std::nullopt};
      if (!selection_from_tool && !e.arc) k.exact_sign = exact_cross_sign(first.delta, selection.delta, -1);
      if (kont_behind(selection, k, k.d2, 10755)) return approach_around(first, e, radius, k);
      if (stopped) return;
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
    open_element(first, e, q, radius);
    phase = Phase::kActive;
  }

  void flush_approach() {
    if (!approach_pending) return;
    approach_pending = false;
    line(selection, selection.start, approach_to, OriginKind::kApproach, selection.rapid);
    for (int i = 0; i < approach_dummy_count; ++i) {
      BlockCopy& d = approach_dummies[static_cast<std::size_t>(i)];
      line(d, xyz(ab(approach_to), h(d.start)), xyz(ab(approach_to), h(d.end)), OriginKind::kInfeed, d.rapid);
    }
    approach_dummy_count = 0;
  }

  // --- KONT: travelling around the start or end point (TRC-KONT-*) -----------------------------
  // The corner a KONT move makes with the contour at `vertex`: d1 runs into it, d2 out of it;
  // `point` is the tool centre off the contour (approach: start, retraction: end).
  struct Kont {
    Vec2 vertex, point, d1, d2;
    std::optional<int> exact_sign;  // sign of cross(contour tangent, point - vertex), if decided in integers
  };

  // The sign of cross(t, k * u) for exact integer displacements t and u (k = +-1), if they are in range.
  std::optional<int> exact_cross_sign(const std::array<Int128, 3>& t, const std::array<Int128, 3>& u, int k) const {
    std::optional<ExactProducts> p = exact_products(t, u);
    if (!p) return std::nullopt;
    return k * ((p->cross > 0) - (p->cross < 0));
  }

  // TRC-KONT-1: behind = strictly on the far side of the contour's tangent line from the
  // compensation side; TRC-KONT-2: then not inside the circle of radius r about the vertex.
  bool kont_side(const BlockCopy& at_block, Vec2 vertex, Vec2 point, Vec2 tangent, std::optional<int> exact_sign) {
    double cr = cross(tangent, point - vertex);
    int sign = exact_sign ? *exact_sign : (cr > 0) - (cr < 0);
    double margin = sign == 0 ? 0.0 : s * cr / norm(tangent);
    bool behind = s * sign < 0;
    decide("TRC-KONT-1", at_block.line, behind ? "behind" : "in-front", margin);
    return behind;
  }
  bool kont_behind(const BlockCopy& at_block, const Kont& k, Vec2 tangent, int alarm) {
    if (!kont_side(at_block, k.vertex, k.point, tangent, k.exact_sign)) return false;
    Vec2 off = k.point - k.vertex;
    double distance = norm(off);
    bool inside = distance < r;
    decide("TRC-KONT-2", at_block.line, inside ? "inside" : "room", distance - r);
    if (inside) raise(alarm, at_block.line, at_block.number, "TRC-KONT-2");
    return !inside;
  }

  // Where the equidistant of the KONT line (through `on_line`, direction `d`) meets the element's
  // carrier, nearest the vertex; false if they do not meet (circles only).
  bool kont_intersection(const BlockCopy& at_block, const Kont& k, const Element& e, double e_radius, Vec2 on_line,
                         Vec2 d, Vec2& x) {
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

  // TRC-KONT-3/4 with TRC-CORNER-3/4: circle or intersection, switched like any outer corner.
  bool kont_circle(const BlockCopy& at_block, const Kont& k) {
    Corner c = classify_corner((1.0 / norm(k.d1)) * k.d1, (1.0 / norm(k.d2)) * k.d2, s);
    return outer_corner_circle(at_block.line, at_block.g451, c);
  }

  // TRC-KONT-3 / TRC-KONT-4 on approach: the approach line meets the first block at an outer corner.
  void approach_around(const BlockCopy& first, const Element& e, double radius, const Kont& k) {
    kont_first = true;
    Vec2 a = Element::offset(k.vertex, (1.0 / norm(k.d1)) * k.d1, s * r);
    bool circle = kont_circle(selection, k);
    Vec2 x;
    bool found = !circle && kont_intersection(selection, k, e, radius, a, k.d1, x);
    double hv = h(selection.end);
    if (!found) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
      decide("TRC-KONT-3", selection.line, "circle");
      line(selection, selection.start, xyz(a, hv), OriginKind::kApproach, selection.rapid);
      run_dummies(a);
      Vec2 q = Element::offset(k.vertex, e.start_tangent(), s * r);
      Origin corner = origin(selection, OriginKind::kTransitionCircle);
      corner.next_line = first.line, corner.next_block = first.number;
      open_element(first, e, q, radius);
      double h1 = h(first.start);                                                      // after the held-back blocks
      if (r > 0) arc(open, xyz(a, h1), xyz(q, h1), xyz(k.vertex, h1), s < 0, corner);  // TRC-G450-2
    } else {                                                                           // TRC-KONT-4
      decide("TRC-KONT-4", selection.line, "intersection");
      line(selection, selection.start, xyz(x, hv), OriginKind::kApproach, selection.rapid);
      run_dummies(x);
      open_element(first, e, x, radius);
    }
    phase = Phase::kActive;
  }

  // --- phase: compensation active --------------------------------------------------------------
  void active(const Block& b) {
    if (!check_active_block(b)) return;
    const BlockCopy* current = nullptr;  // a traversing block, converted once
    if (b.state.side == side && b.moves_in_plane()) {
      int slot = prev_slot ^ 1;  // two slots: the block and its predecessor, no copies
      prev_blocks[static_cast<std::size_t>(slot)] = copy_of(b);
      const BlockCopy& before = prev_blocks[static_cast<std::size_t>(prev_slot)];
      bool had_prev = has_prev;
      prev_slot = slot, has_prev = true;
      current = &prev_blocks[static_cast<std::size_t>(slot)];
      if (approach_until >= 0 && approach_further_ahead(b, *current)) return;
      if (b.state.collision == CollisionMode::kCdon && had_prev && bottleneck(*current, before)) return;
    }
    if (looking) return look_ahead(b, current);
    if (b.state.side != Side::kOff && b.state.side != side) return change_side(b);
    if (b.state.side == Side::kOff) {
      if (!b.programs_plane_axis()) {
        decide("TRC-DESEL-3", b.words.line, "no-plane-axis");
        return queue_dummy(b);
      }
      return deselect(b);
    }
    if (!b.moves_in_plane()) return queue_dummy(b);  // TRC-DUMMY-3
    corner(b, *current);
  }

  Carrier carrier_of(const Element& e, double radius) const { return fast::carrier_of(e, radius, s * r); }

  void corner(const Block& b, const BlockCopy& copy) {
    Element next = element_of(copy);
    double next_radius = 0;
    if (!equidistant_exists(b, next, next_radius)) return start_look_ahead(b);
    Vec2 v = open_el.end;
    Corner c = classify_corner(open_el.end_tangent(), next.start_tangent(), s);
    if (!open_el.arc && !next.arc) decide_kind_exactly(open, copy, c);
    static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
    decide("TRC-CORNER-1", b.words.line, kKind[static_cast<int>(c.kind)], c.sine);

    bool circle = c.kind == Corner::Kind::kReversal;  // TRC-G450-3: a reversal is always a circle
    if (c.kind == Corner::Kind::kOuter) circle = outer_corner_circle(b.words.line, copy.g451, c);
    if (circle) return transition_circle(copy, next, next_radius, v);
    Vec2 x;
    if (c.kind == Corner::Kind::kTangent) {
      x = Element::offset(v, open_el.end_tangent(), s * r);  // both equidistants pass through it
    } else if (!open_el.arc && !next.arc) {
      // TRC-G451-1 / TRC-INNER-1: the intersection of two straight equidistants.
      x = Element::offset(v, open_el.unit, s * r) - corner_trim(c, s, r) * open_el.unit;
    } else {
      // TRC-ARC-CORNER-1: the intersection of the carriers nearest to the corner.
      Carrier cu = carrier_of(open_el, open_radius), cv = carrier_of(next, next_radius);
      bool found = nearest_intersection(cu, cv, v, next.start_tangent(), x);
      decide("TRC-ARC-CORNER-1", b.words.line, found ? "intersection" : "none", carrier_gap(cu, cv));
      if (!found && c.kind == Corner::Kind::kOuter)
        return transition_circle(copy, next, next_radius, v);  // TRC-ARC-CORNER-2
      if (!found) return raise(10751, b.words.line, b.words.number);
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
    if (!close_open(x, b.words.line, b.words.number, &cand)) return;
    run_dummies(x);
    open_element(copy, next, x, next_radius);
  }

  // TRC-CORNER-3 / TRC-CORNER-4: is an outer corner made with the transition circle? By the
  // deciding block's G450/G451, switched by the contour angle (TRC-CORNER-2, degrees).
  bool outer_corner_circle(int line_no, bool g451, const Corner& c, bool traced = true) {
    double angle = std::atan2(std::fabs(c.sine), c.cosine) * (180.0 / std::numbers::pi);
    if (g451) {  // TRC-CORNER-3: G451 switches to G450 above MD20210
      double limit = md.cutcom_corner_limit.to_double();
      bool circle = angle > limit;
      if (traced) decide("TRC-CORNER-3", line_no, circle ? "switch-to-G450" : "keep-G451", angle - limit);
      return circle;
    }
    double limit = md.cutcom_curve_insert_limit.to_double();  // TRC-CORNER-4: G450 to G451 below MD20230
    bool circle = !(angle < limit);
    if (traced) decide("TRC-CORNER-4", line_no, circle ? "keep-G450" : "switch-to-G451", angle - limit);
    return circle;
  }

  // Where a point lies on an element's equidistant: length from its normal start, left to its end.
  struct Extent {
    double along, left;
  };
  Extent extent_of(const Element& e, double radius, Vec2 p) const {
    if (!e.arc) {
      double along = dot(p - Element::offset(e.start, e.unit, s * r), e.unit);
      return {along, e.length - along};
    }
    double along = signed_rotation(e.start - e.centre, p - e.centre, e.sense);
    return {along * radius, (sweep(e) - along) * radius};
  }

  void skip(const BlockCopy& c) {
    if (skipped.capacity() == 0) skipped.reserve(kSkippedCapacity);
    skipped.push_back(c);
  }
  // A candidate that does not do: passed over; alarm 10751 once MD20240 blocks were examined.
  void pass_over(const BlockCopy& c) {
    skip(c);
    if (examined >= md.cutcom_maxnum_check_blocks) raise(10751, c.line, c.number);
  }

  // TRC-LOOK-2: the blocks after a too-short one are tried in turn, up to MD20240 examined.
  void start_look_ahead(const Block& too_short) {
    for (int i = 0; i < dummy_count; ++i) skip(dummies[static_cast<std::size_t>(i)]);
    dummy_count = 0;
    skip(copy_of(too_short));
    examined = 1, dummy_run = 0;
    looking = true;
    if (examined >= md.cutcom_maxnum_check_blocks) raise(10751, too_short.words.line, too_short.words.number);
  }

  void look_ahead(const Block& b, const BlockCopy* current) {
    if (b.state.side == Side::kOff && b.programs_plane_axis()) return retract_edge(b);  // TRC-EDGE-1
    if (b.state.side != side && b.state.side != Side::kOff) {  // the contour ends before an intersection
      decide("TRC-LOOK-2", b.words.line, "none");
      return raise(10751, b.words.line, b.words.number);
    }
    if (!b.moves_in_plane()) {
      if (++dummy_run > md.cutcom_maxnum_dummy_blocks) return raise(10762, b.words.line, b.words.number);
      return skip(copy_of(b));
    }
    dummy_run = 0;
    ++examined;
    const BlockCopy& c = *current;
    Element cand = element_of(c);
    double radius = 0;
    if (!equidistant_exists(b, cand, radius)) return pass_over(c);
    Vec2 start = Element::offset(cand.start, cand.start_tangent(), s * r);
    Vec2 y;
    Carrier cu = carrier_of(open_el, open_radius), cv = carrier_of(cand, radius);
    bool found = nearest_intersection(cu, cv, start, cand.start_tangent(), y);
    bool valid = false;
    double margin = cu.circle || cv.circle ? carrier_gap(cu, cv) : std::numeric_limits<double>::infinity();
    if (found) {
      Extent on = extent_of(cand, radius, y);
      valid = on.along >= 0 && on.left >= 0;
      margin = on.along < 0 ? on.along : on.left < 0 ? on.left : std::min(on.along, on.left);  // the nearer end
    }
    decide("TRC-LOOK-2", b.words.line, valid ? "intersection" : "none", margin);
    if (!valid) return pass_over(c);
    looking = false;
    Candidate candidate{&c, &cand, radius};
    if (!close_open(y, b.words.line, b.words.number, &candidate)) return;
    for (BlockCopy& d : skipped) skip_at(d, y);
    skipped.clear();
    open_element(c, cand, y, radius);
  }

  // --- G460 / G461 / G462: a too-short first or last block (TRC-EDGE-*, edge_strategy.cpp) ------

  // TRC-EDGE-1 on retraction: deselection while the look-ahead found no block to meet the open
  // element; it ends at the hit, the blocks after it are skipped.
  void retract_edge(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT retraction (needs polynomial output)");
    BlockCopy d = copy_of(b);
    const BlockCopy* last_block = nullptr;
    for (const BlockCopy& k : skipped)
      if (k.delta[static_cast<std::size_t>(axes.abscissa)] != 0 ||
          k.delta[static_cast<std::size_t>(axes.ordinate)] != 0 || k.arc)
        last_block = &k;
    Element last = element_of(*last_block);
    decide("TRC-DESEL-1", d.line, "deselected");
    if (d.kont) {  // TRC-KONT-1/2, then TRC-EDGE-6
      Vec2 p = ab(d.end);
      Kont k{last.end, p, last.end_tangent(), p - last.end, std::nullopt};
      if (!last.arc) k.exact_sign = exact_cross_sign(last_block->delta, d.delta, 1);
      if (kont_behind(d, k, k.d1, 10756)) return retract_edge_around(d, *last_block, k);
      if (stopped) return;
    }
    decide("TRC-EDGE-1", d.line, g_code(d.edge_strategy));
    Vec2 normal_end = Element::offset(last.end, last.end_tangent(), s * r);
    EdgeCurve curve = edge_curve(d.edge_strategy, r, last.end, normal_end, last.end_tangent(), ab(d.end), false);
    Vec2 hit;
    double margin = 0;
    bool found = edge_hit(curve, open_el, open_radius, s * r, &open_start, false, hit, margin);
    decide("TRC-EDGE-5", d.line, found ? "hit" : "none", margin);
    if (d.cdon && search_further_back(d, curve)) return;
    if (!found) return raise(10751, d.line, d.number);
    looking = false;
    if (!close_open(hit, d.line, d.number)) return;
    for (BlockCopy& k : skipped) skip_at(k, hit);
    skipped.clear();
    retraction_line(d, hit);
  }

  // TRC-CD-5: with CDON the retraction's search goes on over the held-back equidistants and circles
  // of the blocks m-W ... m-2; the last hit found (the earliest block, on it the earliest point)
  // is valid. True: the path was cut there and the retraction made.
  bool search_further_back(BlockCopy& d, const EdgeCurve& curve) {
    PathPiece aux = curve_piece(curve);
    int lo = d.seq - md.cutcom_maxnum_check_blocks, hi = d.seq - 2;
    bool compared = false, has_near = false;
    double near = 0;
    for (std::size_t i = 0; i < held.size(); ++i) {
      const HeldRecord& rec = held[i];
      if (!is_candidate(rec) || rec.seq < lo || rec.seq > hi) continue;
      compared = true;
      PieceCrossing c = piece_crossing(piece_of(rec), &aux, 1);
      if (c.has_near_miss && (!has_near || c.near_miss > near)) near = c.near_miss, has_near = true;
      if (c.entry_piece < 0) continue;
      decide("TRC-CD-5", d.line, "earlier-block", has_near ? std::min(c.slack, -near) : c.slack);
      if (!cut_at(static_cast<int>(i), c.point, c.along, d.line, d.number)) return true;
      retraction_line(d, c.point);
      return true;
    }
    if (compared)
      decide("TRC-CD-5", d.line, "open-element", has_near ? near : -std::numeric_limits<double>::infinity());
    return false;
  }

  // An auxiliary curve of TRC-EDGE-2..4 as a path piece: G460's segment, G461's whole circle,
  // G462's ray as a segment reaching beyond any programmable coordinate (10^13 mm).
  static PathPiece curve_piece(const EdgeCurve& curve) {
    const Carrier& k = curve.carrier;
    if (k.circle) {
      Vec2 a{k.point.a + k.radius, k.point.b};
      return PathPiece::circle(a, a, k.point, k.radius, 1, true);
    }
    if (curve.bound == EdgeCurve::Bound::kSegment) return PathPiece::segment(k.point, k.point + k.direction);
    return PathPiece::segment(k.point, k.point + (1e13 / norm(k.direction)) * k.direction);
  }

  // TRC-LOOK-3: a skipped block loses its plane motion; the rest runs at `at`.
  void skip_at(BlockCopy& k, Vec2 at) {
    decide("TRC-LOOK-3", k.line, "skipped");
    line(k, xyz(at, h(k.start)), xyz(at, h(k.end)), OriginKind::kInfeed, k.rapid);
  }

  // TRC-EDGE-1 on approach: the first element would run backwards to meet c's equidistant; the
  // approach line ends at the hit on c's equidistant, the first block and those between are skipped.
  void approach_edge(const Candidate& c) {
    decide("TRC-EDGE-1", selection.line, g_code(selection.edge_strategy));
    const Element& first = open_el;
    EdgeCurve curve = edge_curve(selection.edge_strategy, r, first.start, open_start, -1.0 * first.start_tangent(),
                                 ab(selection.start), true);
    Vec2 hit;
    double margin = 0;
    bool found = edge_hit(curve, *c.element, c.radius, s * r, nullptr, true, hit, margin);
    decide("TRC-EDGE-5", selection.line, found ? "hit" : "none", margin);
    if (!found) return raise(10751, c.block->line, c.block->number);
    approach_pending = false;
    line(selection, selection.start, xyz(hit, h(selection.end)), OriginKind::kApproach, selection.rapid);
    for (int i = 0; i < approach_dummy_count; ++i) skip_at(approach_dummies[static_cast<std::size_t>(i)], hit);
    approach_dummy_count = 0;
    skip_at(open, hit);
    for (int i = 0; i < dummy_count; ++i) skip_at(dummies[static_cast<std::size_t>(i)], hit);
    dummy_count = 0;
    for (BlockCopy& k : skipped) skip_at(k, hit);
    skipped.clear();
    looking = false;
    BlockCopy block = *c.block;
    Element element = *c.element;
    open_element(block, element, hit, c.radius);
    // TRC-CD-6: with CDON the later blocks of the window are searched too.
    if (selection.cdon) approach_curve = curve, approach_until = selection.seq + md.cutcom_maxnum_check_blocks;
  }

  // TRC-CD-6: with CDON the approach's search goes on over the later blocks while the approach line
  // is held back (up to MD20240 traversing blocks after the selection block); the last hit found
  // is valid: the approach line ends there and the blocks between lose their plane motion.
  bool approach_further_ahead(const Block& b, const BlockCopy& m) {
    if (m.seq > approach_until || !m.cdon) {
      approach_until = -1;
      return false;
    }
    Element e = element_of(m);
    double radius = 0;
    if (e.arc) {
      radius = e.equidistant_radius(s * r);
      if (!(radius > 0)) return false;
    }
    Vec2 hit;
    double margin = 0;
    bool found = edge_hit(approach_curve, e, radius, s * r, nullptr, true, hit, margin);
    decide("TRC-CD-6", b.words.line, found ? "later-block" : "none", margin);
    if (!found) return false;
    for (std::size_t i = 0; i < held.size(); ++i) {
      if (!held[i].is_element || held[i].element.origin.kind != OriginKind::kApproach) continue;
      if (!cut_at(static_cast<int>(i), hit, std::numeric_limits<double>::infinity(), m.line, m.number)) return true;
      open_element(m, e, hit, radius);
      return true;
    }
    return false;
  }

  // --- CDON: bottleneck detection (TRC-CD-*, bottleneck.cpp) ------------------------------------
  // TRC-CD-2: block m's entry, built provisionally from its predecessor: the transition circle at an outer
  // corner (whatever G450/G451 say), then its equidistant from its normal start (from the inner
  // corner's intersection); none if that lies beyond its end or the equidistant collapses.
  struct Entry {
    Element element;
    double radius = 0;
    Vec2 vertex, normal_start;
    Vec2 own_start;       // where m's own equidistant piece starts
    int before_line = 0;  // the predecessor, which names the corner
    std::optional<std::int64_t> before_number;
    Element before_element;
    double before_radius = 0;
    // pieces[0] leads to m's equidistant: the transition circle, or (G451) the predecessor's
    // equidistant extended to the intersection.
    enum class Lead { kNone, kCircle, kExtension } lead = Lead::kNone;
    PathPiece pieces[2];
    int count = 0;
  };
  bool entry_of(const BlockCopy& m, const BlockCopy& before, Entry& en) {
    en.element = element_of(m);
    en.before_line = before.line, en.before_number = before.number;
    const Element& next = en.element;
    double sr = s * r;
    if (next.arc) {
      en.radius = next.equidistant_radius(sr);
      if (!(en.radius > 0)) return decide("TRC-CD-2", m.line, "collapsed", en.radius), false;
    }
    en.normal_start = Element::offset(next.start, next.start_tangent(), sr);
    Vec2 end = Element::offset(next.end, next.end_tangent(), sr);
    auto equidistant_from = [&](Vec2 from, bool full) {
      return next.arc ? PathPiece::circle(from, end, next.centre, en.radius, next.sense, full)
                      : PathPiece::segment(from, end);
    };
    en.before_element = element_of(before);
    const Element& prev = en.before_element;
    double prev_radius = prev.arc ? prev.equidistant_radius(sr) : 0;
    en.before_radius = prev_radius;
    en.vertex = prev.end;
    en.own_start = en.normal_start;
    Corner c = classify_corner(prev.end_tangent(), next.start_tangent(), s);
    if (!prev.arc && !next.arc) decide_kind_exactly(before, m, c);
    if (prev.arc && !(prev_radius > 0)) {
      decide("TRC-CD-2", m.line, "after-collapse", prev_radius);
      c.kind = Corner::Kind::kTangent;
    } else {
      static constexpr std::string_view kKind[] = {"tangent", "inner", "outer", "reversal"};
      decide("TRC-CD-2", m.line, kKind[static_cast<int>(c.kind)], c.sine);
    }
    en.count = 0;
    Vec2 prev_end = Element::offset(prev.end, prev.end_tangent(), sr);
    if (c.kind == Corner::Kind::kOuter && !outer_corner_circle(m.line, m.g451, c, false)) {
      // G451 (TRC-G451-1, TRC-ARC-CORNER-1): both equidistants extended to their intersection;
      // none found (circles) is the circle (TRC-ARC-CORNER-2).
      Vec2 x;
      bool found = true;
      if (!prev.arc && !next.arc)
        x = Element::offset(prev.end, prev.unit, sr) - corner_trim(c, s, r) * prev.unit;
      else
        found = nearest_intersection(carrier_of(prev, prev_radius), carrier_of(next, en.radius), prev.end,
                                     next.start_tangent(), x);
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
    if (!nearest_intersection(u, v, prev.end, next.start_tangent(), x)) {
      decide("TRC-CD-2", m.line, "no-entry",
             u.circle || v.circle ? carrier_gap(u, v) : -std::numeric_limits<double>::infinity());
      return false;
    }
    double left = extent_of(next, en.radius, x).left;
    decide("TRC-CD-2", m.line, left < 0 ? "no-entry" : "entry", left);
    if (left < 0) return false;
    en.own_start = x;
    en.pieces[en.count++] = equidistant_from(x, false);
    return true;
  }

  PathPiece piece_of(const HeldRecord& rec) const {
    const PathElement& e = rec.element;
    Vec2 a = ab(e.start), b = ab(e.end);
    if (e.type == ElementType::kLine) return PathPiece::segment(a, b);
    return PathPiece::circle(a, b, ab(e.center), rec.radius, e.ccw ? 1 : -1, a.a == b.a && a.b == b.b);
  }
  PathPiece open_piece() const {
    Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
    if (!open_el.arc) return PathPiece::segment(open_start, end);
    Vec2 normal_start = Element::offset(open_el.start, open_el.start_tangent(), s * r);
    bool full = open_el.full && open_start.a == normal_start.a && open_start.b == normal_start.b;
    return PathPiece::circle(open_start, end, open_el.centre, open_radius, open_el.sense, full);
  }
  static bool is_candidate(const HeldRecord& rec) {
    return rec.is_element &&
           (rec.element.origin.kind == OriginKind::kOffset || rec.element.origin.kind == OriginKind::kTransitionCircle);
  }

  // TRC-CD-3: block m's entry against the held-back elements of blocks m-W ... m-2 (W = MD20240)
  // and, in the look-ahead, the open element; the earliest block crossed wins, on it the earliest
  // point. True: the path was cut there.
  bool bottleneck(const BlockCopy& m, const BlockCopy& before) {
    if (r == 0) return false;  // no width: nothing to collide
    int lo = m.seq - md.cutcom_maxnum_check_blocks, hi = m.seq - 2;
    Entry entry;
    int state = 0;  // 0: not built, 1: built, -1: none
    bool has_near = false;
    double near = 0;
    // A G451 lead is the predecessor's equidistant: m-2's held element ends on it, at their common
    // corner, and is not compared with it (in the look-ahead m-1 was passed over: no such corner).
    auto try_piece = [&](const PathPiece& held_piece, int seq, PieceCrossing& c) {
      if (state == 0) state = entry_of(m, before, entry) ? 1 : -1;
      if (state < 0) return false;
      bool skip_lead = entry.lead == Entry::Lead::kExtension && seq == hi && !looking;
      c = piece_crossing(held_piece, entry.pieces, entry.count, skip_lead ? 1 : 0);
      if (c.has_near_miss && (!has_near || c.near_miss > near)) near = c.near_miss, has_near = true;
      return c.entry_piece >= 0;
    };
    PieceCrossing c;
    for (std::size_t i = 0; i < held.size(); ++i) {
      const HeldRecord& rec = held[i];
      if (!is_candidate(rec) || rec.seq < lo || rec.seq > hi) continue;
      if (try_piece(piece_of(rec), rec.seq, c)) return cut(m, entry, static_cast<int>(i), c, has_near, near), true;
      if (state < 0) return false;
    }
    if (looking && open.seq >= lo && open.seq <= hi && try_piece(open_piece(), open.seq, c))
      return cut(m, entry, -1, c, has_near, near), true;
    if (state > 0) decide("TRC-CD-3", m.line, "none", has_near ? near : -std::numeric_limits<double>::infinity());
    return false;
  }

  // TRC-CD-4 (with TRC-LOOK-3): the crossed block ends at the crossing; the blocks after it lose
  // their plane motion (the rest runs there, in programmed order); block m goes on along its entry.
  void cut(const BlockCopy& m, const Entry& en, int record, const PieceCrossing& c, bool has_near, double near) {
    const Vec2 x = c.point;
    double margin = has_near ? std::min(c.slack, -near) : c.slack;
    decide("TRC-CD-3", m.line, "cut", margin);
    if (!cut_at(record, x, c.along, m.line, m.number)) return;
    continue_entry(m, en, c.entry_piece, x);
  }

  // TRC-CD-4: cuts the held-back path at x on `record` (-1: on the open element), `along` it from
  // its start; the blocks after it lose their plane motion and run at x (TRC-LOOK-3). False: an
  // alarm stopped the run.
  bool cut_at(int record, Vec2 x, double along, int line_no, std::optional<std::int64_t> number) {
    int last_run = -1;  // the last block run again from held records
    if (record >= 0) {
      HeldRecord& rec = held[static_cast<std::size_t>(record)];
      const HeldRecord crossed = rec;
      rec.element.end = xyz(x, h(rec.element.end));
      const PathPoint end = rec.element.end;
      held_scratch.assign(held.begin() + record + 1, held.end());
      held.erase(held.begin() + record + 1, held.end());
      // Cut at (or, rounded, next to) its start: nothing is left of it; an arc from a point to
      // itself would read as a full circle.
      double scale = std::max({1.0, std::fabs(x.a), std::fabs(x.b)});
      if (along <= 64 * std::numeric_limits<double>::epsilon() * scale) held.erase(held.begin() + record);
      bool rest = open.line == crossed.owner_line;  // its equidistant was still open
      for (const HeldRecord& k : held_scratch) rest = rest || k.owner_line == crossed.owner_line;
      if (rest) infeed_of(crossed, end, xyz(x, h(crossed.owner_end)));
      for (std::size_t i = 0; i < held_scratch.size(); ++i) {
        const HeldRecord& k = held_scratch[i];
        if (k.owner_line == crossed.owner_line) continue;
        if (k.owner_line != last_run) {
          if (last_run >= 0) infeed_of(held_scratch[i - 1], x);
          decide("TRC-LOOK-3", k.owner_line, "skipped");
          last_run = k.owner_line;
        }
        if (!k.is_element) {
          HeldRecord a = k;
          a.action.at = xyz(x, h(k.owner_start));
          held.push_back(a);
        }
      }
      if (last_run >= 0) infeed_of(held_scratch.back(), x);
      if (open.line != crossed.owner_line && open.line != last_run) skip_at(open, x);
    } else {
      looking = false;
      if (!close_open(x, line_no, number)) return false;
    }
    for (BlockCopy& k : skipped) skip_at(k, x);
    skipped.clear();
    for (int i = 0; i < dummy_count; ++i) skip_at(dummies[static_cast<std::size_t>(i)], x);
    dummy_count = 0;
    looking = false;
    kont_first = false;
    return true;
  }

  // TRC-CD-4: block m goes on from the crossing along its entry.
  void continue_entry(const BlockCopy& m, const Entry& en, int entry_piece, Vec2 x) {
    bool on_lead =
        en.lead != Entry::Lead::kNone && entry_piece == 0 && !(x.a == en.own_start.a && x.b == en.own_start.b);
    if (!on_lead) return open_element(m, en.element, x, en.radius);
    double hv = h(m.start);
    BlockCopy owner = m;
    Origin named;
    named.line = en.before_line, named.block = en.before_number;
    if (en.lead == Entry::Lead::kCircle) {
      named.kind = OriginKind::kTransitionCircle, named.next_line = m.line, named.next_block = m.number;
      arc(owner, xyz(x, hv), xyz(en.normal_start, hv), xyz(en.vertex, hv), s < 0, named);
      return open_element(owner, en.element, en.normal_start, en.radius);
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
  // A block run again at a cut, from its held record: its applicate motion at x (its actions were
  // put back before).
  void infeed_of(const HeldRecord& k, const PathPoint& from, const PathPoint& to) {
    BlockCopy owner;
    owner.line = k.owner_line, owner.number = k.owner_number, owner.rapid = k.owner_rapid, owner.feed = k.owner_feed;
    owner.actions_done = true, owner.seq = k.seq;
    line(owner, from, to, OriginKind::kInfeed, owner.rapid);
  }
  void infeed_of(const HeldRecord& k, Vec2 x) { infeed_of(k, xyz(x, h(k.owner_start)), xyz(x, h(k.owner_end))); }

  // TRC-G450-1: circle of radius r about the programmed corner, joining the normal points; it
  // belongs to the second block.
  void transition_circle(const BlockCopy& b, const Element& next, double next_radius, Vec2 v) {
    Vec2 from = Element::offset(v, open_el.end_tangent(), s * r);
    if (!close_open(from, b.line, b.number)) return;
    run_dummies(from);
    Vec2 to = Element::offset(v, next.start_tangent(), s * r);
    Origin corner = origin(open, OriginKind::kTransitionCircle);
    open_element(b, next, to, next_radius);
    corner.next_line = open.line, corner.next_block = open.number;
    if (r > 0) {  // TRC-G450-2: no circle for a zero radius
      double hv = h(open.start);
      // Around the outside: clockwise on the left, counter-clockwise on the right.
      arc(open, xyz(from, hv), xyz(to, hv), xyz(v, hv), s < 0, corner);
    }
  }

  // TRC-DESEL-1: deselection; with KONT from behind the end point TRC-KONT-* travel around it,
  // otherwise (NORM, KONT in front) TRC-RETR-NORM-1.
  void deselect(const Block& b) {
    if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
      throw UnsupportedError(  // TRC-UNSUP-1
          b.words.line, "KONTC/KONTT retraction (needs polynomial output)");
    decide("TRC-DESEL-1", b.words.line, "deselected");
    BlockCopy last = copy_of(b);
    if (last.kont) {
      Vec2 p = ab(last.end);
      Kont k{open_el.end, p, open_el.end_tangent(), p - open_el.end, std::nullopt};
      if (!open_el.arc) k.exact_sign = exact_cross_sign(open.delta, last.delta, 1);
      if (kont_behind(last, k, k.d1, 10756)) return retract_around(last, k);
      if (stopped) return;
    }
    Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
    if (!close_open(end, last.line, last.number)) return;
    run_dummies(end);
    retraction_line(last, end);
  }

  // TRC-RETR-NORM-1: the straight line to the programmed end point, a tool-centre position.
  void retraction_line(BlockCopy& last, Vec2 from_point) {
    PathPoint from = xyz(from_point, h(last.start));
    double length =
        std::sqrt((last.end.x - from.x) * (last.end.x - from.x) + (last.end.y - from.y) * (last.end.y - from.y) +
                  (last.end.z - from.z) * (last.end.z - from.z));
    decide("TRC-RETR-NORM-1", last.line, length == 0 ? "zero-length" : "line", length);
    line(last, from, last.end, OriginKind::kRetraction, last.rapid);
    phase = Phase::kOff;
  }

  // TRC-KONT-3 / TRC-KONT-4 on retraction: the retraction line meets the last block at an outer corner.
  // TRC-EDGE-6 (digest §2.5 rule 3): KONT from behind after a too-short last block: the open
  // element meets the inserted circle about the last block's end point (the first point along it)
  // and the rest of the circle is traversed; if it misses the circle, it meets the retraction line.
  void retract_edge_around(BlockCopy& d, const BlockCopy& last_block, const Kont& k) {
    if (!kont_circle(d, k))
      throw UnsupportedError(  // TRC-EDGE-7 (planned)
          d.line, "KONT retraction from behind by intersection (G451) after a too-short last block");
    Vec2 rp = Element::offset(k.vertex, (1.0 / norm(k.d2)) * k.d2, s * r);
    EdgeCurve circle;
    circle.carrier.circle = true, circle.carrier.point = k.vertex, circle.carrier.radius = r;
    Vec2 x;
    double margin = 0;
    bool on_circle = edge_hit(circle, open_el, open_radius, s * r, &open_start, false, x, margin);
    decide("TRC-EDGE-6", d.line, on_circle ? "circle" : "line", margin);
    if (!on_circle) {
      EdgeCurve line;
      line.bound = EdgeCurve::Bound::kSegment, line.carrier.point = rp, line.carrier.direction = k.point - rp;
      bool found = edge_hit(line, open_el, open_radius, s * r, &open_start, false, x, margin);
      decide("TRC-EDGE-5", d.line, found ? "hit" : "none", margin);
      if (!found) return raise(10751, d.line, d.number);
    }
    looking = false;
    if (!close_open(x, d.line, d.number)) return;
    for (BlockCopy& k2 : skipped) skip_at(k2, x);
    skipped.clear();
    if (!on_circle) return retraction_line(d, x);
    Origin corner = origin(last_block, OriginKind::kTransitionCircle);
    corner.next_line = d.line, corner.next_block = d.number;
    double hv = h(d.start);
    arc(d, xyz(x, hv), xyz(rp, hv), xyz(k.vertex, hv), s < 0, corner);
    retraction_line(d, rp);
  }

  void retract_around(BlockCopy& last, const Kont& k) {
    Vec2 rp = Element::offset(k.vertex, (1.0 / norm(k.d2)) * k.d2, s * r);
    bool circle = kont_circle(last, k);
    Vec2 x;
    bool found = !circle && kont_intersection(last, k, open_el, open_radius, rp, k.d2, x);
    if (!found) {  // TRC-KONT-3 (also TRC-ARC-CORNER-2)
      decide("TRC-KONT-3", last.line, "circle");
      Vec2 from = Element::offset(k.vertex, open_el.end_tangent(), s * r);
      Origin corner = origin(open, OriginKind::kTransitionCircle);
      corner.next_line = last.line, corner.next_block = last.number;
      if (!close_open(from, last.line, last.number)) return;
      run_dummies(from);
      double hv = h(last.start);
      if (r > 0) arc(last, xyz(from, hv), xyz(rp, hv), xyz(k.vertex, hv), s < 0, corner);  // TRC-G450-2
      return retraction_line(last, rp);
    }
    decide("TRC-KONT-4", last.line, "intersection");
    if (!close_open(x, last.line, last.number)) return;
    run_dummies(x);
    retraction_line(last, x);
  }

  // TRC-END-1: the program ends with compensation in force.
  void end_of_program() {
    if (looking) {  // the program ends before an intersection was found
      const BlockCopy& last = skipped.back();
      decide("TRC-LOOK-2", last.line, "none");
      return raise(10751, last.line, last.number);
    }
    if (phase == Phase::kApproach) {
      decide("TRC-END-1", selection.line, "no-contour");
      sink.notice({selection.line, "TRC-END-1", "compensation selected but no block with motion in the plane follows"});
      line(selection, selection.start, selection.end, OriginKind::kProgrammed, selection.rapid);
      run_dummies_uncompensated();
    } else if (phase == Phase::kActive) {
      decide("TRC-END-1", open.line, "active-at-end");
      sink.notice(
          {open.line, "TRC-END-1", "program ends with compensation active: last block ends at its normal point"});
      Vec2 end = Element::offset(open_el.end, open_el.end_tangent(), s * r);
      if (!close_open(end, open.line, open.number)) return;
      run_dummies(end);
    }
    phase = Phase::kOff;
  }

  // ARC-CENTRE-2: the end point may miss the circle about the programmed centre by at most
  // max(MD21000, MD21010 * radius); beyond, alarm 14040. CR= circles are not supported yet.
  bool arc_is_consistent(const Block& b) {
    PlaneAxes ax = plane_axes(b.state.plane);
    if (!b.centre) {  // ARC-CR-1: a CR= circle must reach its end point
      double cr = std::fabs(b.words.cr->to_double());
      Vec2 s0{coord(b.start, ax.abscissa).to_double(), coord(b.start, ax.ordinate).to_double()};
      Vec2 e0{coord(b.end, ax.abscissa).to_double(), coord(b.end, ax.ordinate).to_double()};
      double chord = norm(e0 - s0);
      bool reachable = chord > 0 && chord <= 2 * cr;
      decide("ARC-CR-1", b.words.line, reachable ? "circle" : "unreachable", 2 * cr - chord);
      if (!reachable) raise(14040, b.words.line, b.words.number, "ARC-CR-1");
      return reachable;
    }
    auto at = [&](const Point3& p) {
      return Vec2{coord(p, ax.abscissa).to_double(), coord(p, ax.ordinate).to_double()};
    };
    Vec2 c = at(*b.centre);
    double rs = norm(at(b.start) - c), re = norm(at(b.end) - c);
    double tolerance = std::max(md.circle_error_const.to_double(), md.circle_error_factor.to_double() * rs);
    double excess = std::fabs(re - rs) - tolerance;
    decide("ARC-CENTRE-2", b.words.line, excess <= 0 ? "within" : "beyond", excess);
    if (excess > 0) raise(14040, b.words.line, b.words.number);
    return excess <= 0;
  }
};

Engine::Engine(const MachineData& md, PathSink& sink) : state_(std::make_unique<State>(md, sink)) {}
Engine::~Engine() = default;

bool Engine::stopped() const { return state_->stopped; }

void Engine::push(const Block& b) {
  State& st = *state_;
  if (st.stopped) return;
  if (b.words.disc && b.words.disc->sign() > 0)  // TRC-DISC-1
    throw UnsupportedError(b.words.line, "DISC greater than 0 (a distorted transition circle)");
  if (b.moves_in_plane()) ++st.traversing;
  st.holding = b.state.collision == CollisionMode::kCdon;
  if (b.is_arc() && !st.arc_is_consistent(b)) return;
  switch (st.phase) {
    case State::Phase::kOff:
      st.off(b);
      break;
    case State::Phase::kApproach:
      st.approach(b);
      break;
    case State::Phase::kActive:
      st.active(b);
      break;
  }
  st.release_window(b);
}

void Engine::finish() {
  if (!state_->stopped) state_->end_of_program();
  state_->release_all();
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

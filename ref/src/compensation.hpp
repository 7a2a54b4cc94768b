// Stage 2, the compensation: ref's walk through the blocks (as fast/src/compensation.hpp). Its
// member functions live in compensation.cpp (selection, corners, look-ahead, output into the
// collision window), ends.cpp (approach and retraction: NORM, KONT, G460-G462) and collision.cpp
// (the collision check under CDON: entry, crossing, cut). It owns its state; it hands its output
// to the collision window (stage 3) and its decisions and alarms to the trace. Private to ref.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <deque>
#include <map>
#include <optional>
#include <span>

#include "bottleneck.hpp"
#include "circle_position.hpp"
#include "collision_window.hpp"
#include "contour_angle.hpp"
#include "contour_element.hpp"
#include "cutcom/decision_trace.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "cutcom/ref/engine.hpp"
#include "edge_strategy.hpp"
#include "equidistant.hpp"
#include "exact_path.hpp"
#include "plane_override.hpp"

namespace cutcom::ref::detail {

// A point of the tool-centre path: exact in the plane, the applicate as programmed.
struct CentrePoint {
  Point plane;
  Decimal applicate;
};

class Compensation {
 public:
  Compensation(const MachineData& md, PathSink& sink, Trace& trace, CollisionWindow& window, ExactPath& exact_path)
      : md_(md), sink_(sink), trace_(trace), held_(window), path(exact_path) {}

  // A block from the SAR expansion; `over` gives its exact in-plane points where they are not its
  // decimals. Blocks are kept: ref may look back at any of them (a deque keeps references to
  // earlier blocks valid).
  void step(Block b, const std::optional<PlaneOverride>& over = std::nullopt);
  // TRC-END-1 at the program's end.
  void end_of_program();
  // ALARM-1: the approach line decided before an alarm is output.
  void flush_approach();

 private:
  // kRetracting: a G40 block without a plane axis left the tool at the normal end point of the
  // last contour block; the next block with a plane axis finishes the retraction (TRC-DESEL-3).
  enum class Phase { kOff, kApproach, kActive, kRetracting };

  // --- the compensation in force ---------------------------------------------------------------
  struct InForce {
    Plane plane;
    PlaneAxes axes;
    Side side;
    int s;           // +1 left, -1 right (TRC-RADIUS-2 applied)
    FT side_radius;  // s * r, r = |effective radius| in units
    Decimal radius;  // r
    ActiveEdge edge;
    std::uint32_t selection;  // the G41/G42 word that selected (TRC-SIDE-2)
  };

  // --- trace, alarms, output ---------------------------------------------------------------------
  void decide(std::string_view clause, int line, std::string_view branch) { trace_.decide(clause, line, branch); }
  void decide(std::string_view clause, int line, std::string_view branch, std::string margin) {
    trace_.decide(clause, line, branch, std::move(margin));
  }
  void decide(const ProgrammedDecision& d, int line) { trace_.decide(d, line); }
  // Whether margins reach anything: an exact margin as text costs an approximation of its value,
  // most of ref's time on a plain contour; without a trace the text is left out.
  bool margins_kept() const { return trace_.keeps_decisions(); }
  void raise(int number, const Block& at, std::string_view clause = {}) { trace_.raise(number, at, clause); }

  // Auxiliary functions of a block run before its first element (PATH-ACTION-1).
  void run_actions(const Block& b, const PathPoint& at);
  int seq_of(const Block& b) const { return seq_[slot(b)]; }
  // A block's place among those still kept (program_ starts at block first_kept_).
  std::size_t slot(const Block& b) const { return static_cast<std::size_t>(b.index - first_kept_); }
  void hold(const Block& owner, const PathElement& e, ExactPath::Element exact) {
    HeldRecord r;
    r.owner = &owner, r.seq = seq_of(owner), r.element = e, r.exact = std::move(exact);
    held_.hold(std::move(r));
  }
  // TRC-CD-1: with CDON in force the output of the last MD20240 traversing blocks waits (a later
  // block may cut it); otherwise it goes out block by block.
  void release_window(const Block& b);

  Origin origin(const Block& b, OriginKind kind) const {
    Origin o;
    o.kind = kind, o.line = b.words.line, o.source = b.words.source, o.block = b.words.number, o.sar = b.sar.move,
    o.insert = b.insert;
    return o;
  }

  // PATH-ELEMENT-1: a straight element; zero-length ones are not output.
  void emit_line(const Block& owner, const ExactPoint& from, const ExactPoint& to, OriginKind kind,
                 const ContourElement* offset_of = nullptr, const Block* named = nullptr);

  // A circular element about `centre` (at the applicate of its start), radius `radius` in the plane;
  // `owner` gives feed, motion type and actions.
  void emit_arc(const Block& owner, const ExactPoint& from, const ExactPoint& to, const ExactPoint& centre,
                const FT& radius, bool ccw, const Origin& from_what, PlaneAxes axes);
  // A circle around an outer corner (TRC-G450-1, TRC-KONT-3, TRC-EDGE-6, a CDON entry's lead) from
  // `from` to `to` about `vertex`, at the applicate `h`: it turns less than half a turn, so ends
  // that coincide exactly turn 0 and give no element (PATH-ELEMENT-1), not a whole turn.
  void emit_corner_circle(const Block& owner, const Point& from, const Point& to, const Point& vertex, const Decimal& h,
                          const Origin& corner);

  ExactPoint at(const CentrePoint& p) const { return ExactPoint::in_plane(p.plane, p.applicate, comp_->axes); }
  static ExactPoint at(const Point3& p) { return ExactPoint::programmed(p); }

  // The block's override, if the SAR expansion gave one.
  const PlaneOverride* override_of(const Block& b) const {
    auto it = overrides_.find(b.index);
    return it == overrides_.end() ? nullptr : &it->second;
  }
  ExactPoint start_of(const Block& b) const { return start_with(b, override_of(b)); }
  ExactPoint end_of(const Block& b) const { return end_with(b, override_of(b)); }
  Point plane_end(const Block& b) const { return end_of(b).plane(plane_axes(b.state.plane)); }

  // A kept block's element, built once: the corner, the entry and the open piece then share its
  // exact numbers, so that a point met again is the same (same_point) and CORE keeps the
  // approximations and signs it found for them.
  ContourElement element_of(const Block& b) const {
    PlaneAxes axes = comp_ ? comp_->axes : plane_axes(b.state.plane);
    for (const BuiltElement& k : built_)
      if (k.index == b.index && k.axes.abscissa == axes.abscissa && k.axes.ordinate == axes.ordinate) return k.element;
    BuiltElement& k = built_[next_built_++ % built_.size()];
    k.index = b.index, k.axes = axes, k.element = element_with(b, override_of(b), axes);
    return k.element;
  }

  void run_uncompensated(const Block& b);

  // TRC-SEL-*: may this block select compensation?
  void compensation_off(const Block& b);

  // TRC-SIDE-1 (decision 30): G41 <-> G42 without G40; TRC-SIDE-2: the same G41/G42 again. The
  // last element of the old selection ends at its normal end point (blocks held back run there);
  // the first block of the new one that programs a plane axis is a selection block (NORM)
  // starting where the tool is.
  void change_side(const Block& b);
  bool anew(const Block& b) const { return selects_anew(b.state, comp_->side, comp_->selection); }

  // Where the selection block starts: its programmed start, or the tool after a side change.
  ExactPoint selection_start() const { return selection_from_ ? *selection_from_ : start_of(*selection_); }

  // TRC-SEL-1: the selection block; TRC-RADIUS-1/2: effective radius and side.
  void select(const Block& b);

  // Checks of every block while compensation is selected. False: an alarm stopped the program.
  bool still_compensable(const Block& b);

  // TRC-DUMMY-2: at most MD20250 blocks without motion in the plane in a row.
  void hold_back(const Block& b);

  // TRC-DUMMY-1: held-back blocks run at the corner point P*, only their applicate moving.
  void run_held_back(const Point& corner_point);
  void run_held_back_uncompensated();

  // --- approach ----------------------------------------------------------------------------------
  void waiting_for_contour(const Block& b);

  // TRC-APPR-NORM-1 / TRC-KONT-*: the move onto the contour from the start position.
  void approach(const Block& first_block);

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
  bool kont_side(const Block& at_block, const Point& vertex, const Point& point, const Vector& tangent);
  bool kont_behind(const Block& at_block, const KontCorner& k, const Vector& tangent, int alarm);

  // TRC-KONT-3/4 with TRC-CORNER-3/4: circle (G450) or intersection (G451), switched by the
  // contour angle of the corner like any outer corner; `mode` is the deciding block's G450/G451.
  bool kont_circle(const Block& at_block, const KontCorner& k);

  // Where the equidistant of the KONT line (through `on_line` with direction `d`) meets the
  // contour element's carrier, nearest the vertex; empty if they do not meet (circles only).
  std::optional<Point> kont_intersection(const Block& at_block, const KontCorner& k, const ContourElement& e,
                                         const FT& e_radius, const Point& on_line, const Vector& d);

  // TRC-KONT-3 / TRC-KONT-4 on approach: the approach line is a contour element ending at the
  // start point S and meeting the first block at an outer corner.
  void approach_around(const Block& first_block, const ContourElement& first, const FT& radius, const ExactPoint& from,
                       const Decimal& h, const KontCorner& k);

  // --- compensation active -----------------------------------------------------------------------
  void reject_blend_here(const Block& b, bool searching) const;
  void blend_radius(const Block& b);
  void compensation_active(const Block& b);

  // How a point of the open element was placed; a circle reads its position by it
  // (TRC-ARC-ELEMENT-1). kNormal: built as the normal point, its rotation from it 0 by
  // construction (no exact zero test); kCorner: a corner's point, the signed rotation in (-pi, pi]
  // from the normal point; kOnPiece: found on the piece by a search (TRC-EDGE-5/6, TRC-CD-3..6),
  // the rotation in [0, 2 pi) from the piece's start.
  enum class Placed { kCorner, kNormal, kOnPiece };

  // TRC-ELEMENT-1 / TRC-ARC-ELEMENT-1: the open element, from its start point to `end_point`, must
  // not run backwards; it is output unless it has length exactly 0. `placed`: how `end_point` was
  // placed (kOnPiece: on the piece from the open element's start).
  // `candidate`: the block whose equidistant fixed this end (for TRC-EDGE-* on approach).
  struct Candidate {
    const Block* block;
    const ContourElement* element;
    FT radius;
  };
  bool close_open(const Point& end_point, const Block& reporting, Placed placed = Placed::kCorner,
                  const Candidate* candidate = nullptr);

  // The carrier of an equidistant: the offset line, or the concentric circle.
  Carrier<Kernel> carrier_of(const ContourElement& e, const FT& radius) const {
    return ref::carrier_of(e, radius, comp_->side_radius);
  }

  void corner(const Block& next_block);

  // TRC-CORNER-3 / TRC-CORNER-4: is an outer corner made with the transition circle? By the
  // G450/G451 of `at_block`, switched by the contour angle (exactly; rational where `rc` is given).
  bool outer_corner_circle(const Block& at_block, const std::optional<CornerClass>& rc, const FT& cross, const FT& dot);

  // Where a point lies on an element's equidistant (normal start to normal end): the signed length
  // from the normal start, and what is left to the normal end; exact. Empty if it lies within.
  // TRC-LOOK-1 asks for the second only; TRC-LOOK-2 for both.
  struct Extent {
    CGAL::Sign before_start, after_end;  // NEGATIVE: before the start / beyond the end
    bool start_nearer = false;           // nearer to the normal start than to the normal end
    std::string along_text, left_text;   // lengths from the normal start and to the normal end (mm)
  };
  Extent extent_of(const ContourElement& e, const FT& radius, const Point& p) const;

  // TRC-LOOK-2: the blocks after a too-short one are tried in turn, up to MD20240 examined after the
  // open element; the held-back and passed-over blocks are skipped.
  void start_look_ahead(const Block& too_short);

  void look_ahead(const Block& b);

  // A candidate that does not do: passed over; alarm 10751 once MD20240 blocks were examined.
  void pass_over(const Block& b);

  // TRC-LOOK-3: skipped blocks lose their motion in the plane; their applicate motion and actions
  // run at the intersection point, in programmed order.
  void run_skipped(const Point& at_point);

  // The carriers' intersection nearest to `vertex`; of two equally near, the one further along
  // `ahead` (the second element's direction of travel), so that the choice does not depend on
  // the orientation of the plane (TRC-ARC-CORNER-1, TRC-LOOK-2).
  // `farther`, where given: the sign of |xs[1] - vertex| - |xs[0] - vertex| it chose by (left as
  // it was for one point).
  static std::optional<Point> nearest_intersection(const Carrier<Kernel>& u, const Carrier<Kernel>& v,
                                                   const Point& vertex, const Vector& ahead,
                                                   CGAL::Sign* farther = nullptr);
  // TRC-LOOK-4: the look-ahead's choice of the two points where u and v meet, traced.
  void decide_nearer(int line, const Carrier<Kernel>& u, const Carrier<Kernel>& v, const Point& p, CGAL::Sign farther);

  // --- G460 / G461 / G462: a too-short first or last block (TRC-EDGE-*, edge_strategy.cpp) ------
  EdgeCurve edge_curve(EdgeStrategy strategy, const Point& vertex, const Point& normal_point, const Vector& outward,
                       const Point& off_contour, bool approach) const {
    return ref::edge_curve(strategy, vertex, normal_point, outward, off_contour, approach, leaf(comp_->radius));
  }
  EdgeHit edge_hit(const EdgeCurve& curve, const ContourElement& e, const FT& radius,
                   const std::optional<PieceStart>& from, bool last) const {
    return ref::edge_hit(curve, e, radius, comp_->side_radius, from, last);
  }

  // TRC-EDGE-1 on retraction: deselection while the look-ahead found no block to meet the open
  // element (the last block is too short). The open element ends at the hit, the blocks after it
  // are skipped (TRC-LOOK-3), the retraction line starts there.
  void retract_edge(const Block& b);

  // TRC-CD-5: with CDON the retraction's search goes on over the held-back equidistants and circles
  // of the blocks m-W ... m-2 before the open element; the last hit found (the earliest block, on
  // it the earliest point) is valid. True: the path was cut there and the retraction made.
  bool search_further_back(const Block& b, const EdgeCurve& curve);

  // An auxiliary curve of TRC-EDGE-2..4 as a path piece: G460's segment, G461's whole circle,
  // G462's ray as a segment reaching beyond any programmable coordinate (10^13 mm).
  PathPiece curve_piece(const EdgeCurve& curve) const;

  // TRC-EDGE-1 on approach: the first element would run backwards to meet `c`'s equidistant.
  // The approach line ends at the hit on c's equidistant instead; the first block and those
  // between are skipped.
  void approach_edge(const Candidate& c);

  // TRC-CD-6: with CDON the approach's search goes on over the later blocks while the approach line
  // is held back (up to MD20240 traversing blocks after the selection block); the last hit found
  // is valid: the approach line ends there instead and the blocks between lose their plane motion.
  // True: block m was entered so.
  bool approach_further_ahead(const Block& m);
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
  std::optional<Entry> entry_of(const Block& m, const Block& before);

  // The outer corner of the entry as corner() will make it: true for the circle; false for G451,
  // with the intersection in g451_point_ (TRC-ARC-CORNER-2: none found is the circle). TRC-CORNER-3/4
  // are traced here too: an angle exactly on the threshold may part the runs at the entry.
  bool outer_corner_is_circle(const Block& m, const ContourElement& prev, const FT& prev_radius,
                              const ContourElement& next, const FT& next_radius, const std::optional<CornerClass>& rc);
  std::optional<Point> g451_point_;

  // A held-back element as a piece of the plane path.
  static PathPiece piece_of(const HeldRecord& r);
  // The open element from its start point to its normal end.
  PathPiece open_piece() const;

  // TRC-CD-3: block m's entry against the held-back elements of blocks m-W ... m-2 (W = MD20240)
  // and, in the look-ahead, the open element; the earliest block that it crosses wins, on it the
  // earliest point. True: the path was cut there. Margin: the crossing's least slack, or the
  // largest near miss.
  bool bottleneck(const Block& m, const Block& before);

  // TRC-CD-4 (with TRC-LOOK-3): the path is cut at the crossing. The crossed block ends there; the
  // blocks after it lose their plane motion (the rest runs at the point, in programmed order);
  // block m goes on along its entry: the rest of the circle, then its equidistant.
  void cut(const Block& m, const Entry& en, std::optional<std::size_t> record, const PieceCrossing& c,
           const std::optional<FT>& near);

  // TRC-CD-4: cuts the held-back path at x on `record` (none: on the open element); the blocks
  // after it lose their plane motion and run at x (TRC-LOOK-3). False: an alarm stopped the run.
  bool cut_at(const Block& reporting, std::optional<std::size_t> record, const Point& x);

  // TRC-CD-4: block m goes on from the crossing along its entry.
  void continue_entry(const Block& m, const Entry& en, int entry_piece, const Point& x);

  // TRC-G450-1: a circle of radius r about the programmed corner from the normal end point of the
  // first equidistant to the normal start point of the second; it belongs to the second block.
  void transition_circle(const Block& next_block, const ContourElement& next, const FT& next_radius,
                         const Point& vertex);

  // TRC-ARC-EQ-1: a circle's equidistant must keep a positive radius rho - s sigma r. Decided when
  // the block comes; a collapsed one is passed over by the look-ahead (TRC-LOOK-1/2).
  bool equidistant_exists(const ContourElement& e, FT& radius);

  // `placed`: how the start point was placed (see close_open); kOnPiece: on the piece that starts
  // at `piece_start` (default: the normal start point).
  void open(const Block& b, const ContourElement& e, const Point& start, const FT& radius,
            Placed placed = Placed::kCorner, const std::optional<Point>& piece_start = std::nullopt);

  // TRC-DESEL-1: deselection; with KONT from behind the end point TRC-KONT-* travel around it,
  // otherwise (NORM, KONT in front) TRC-RETR-NORM-1.
  void deselect(const Block& b);
  void deselect_in_place(const Block& b);
  void retraction_pending(const Block& b);

  // The corner the retraction line (to b's end) makes with the last block at its end point.
  KontCorner retraction_corner(const Block& b, const ContourElement& last) const;

  // TRC-EDGE-6 (FM06 p.94): KONT from behind after a too-short last block. The
  // travel-around circle about the last block's end point is inserted whatever G460-G462 say: the
  // open element ends where it meets the circle (the first point along it, as G461 would find)
  // and the rest of the circle is traversed; if it misses the circle, where it meets the
  // retraction line. The blocks after the open element are skipped (TRC-LOOK-3).
  void retract_edge_around(const Block& b, const Block& last_block, const KontCorner& k);

  // TRC-RETR-NORM-1: the straight line to the programmed end point, a tool-centre position.
  void retraction_line(const Block& b, const Point& from_point);

  // TRC-KONT-3 / TRC-KONT-4 on retraction: the retraction line is a contour element starting at
  // the end point E and meeting the last block at an outer corner.
  void retract_around(const Block& b, const KontCorner& k);

  // The blocks still referred to (held output, the look-ahead, the approach), and a spare of
  // kSpareBlocks before them: memory follows the window, not the program's length.
  static constexpr int kSpareBlocks = 64;
  void forget_old_blocks();
  std::deque<Block> program_;
  struct BuiltElement {
    int index = -1;
    PlaneAxes axes{0, 1, 2};
    ContourElement element;
  };
  mutable std::array<BuiltElement, 4> built_;  // element_of's last ones
  mutable std::size_t next_built_ = 0;
  int first_kept_ = 0;  // the index of program_.front()
  int next_index_ = 0;
  std::map<int, PlaneOverride> overrides_;  // by block index
  const MachineData& md_;
  PathSink& sink_;
  Trace& trace_;
  CollisionWindow& held_;  // stage 3: where output goes (collision_window.hpp)
  OnCarrierFacts facts_;   // TRC-CD-3: cut points and corners, on the carriers they were built on
  ExactPath& path;         // rounds points as the output does
  std::deque<int> seq_;    // per kept block: the window's ordinal of the last traversing block up to it (TRC-CD-1)
  std::deque<char> actions_done_;  // per kept block
  Phase phase_ = Phase::kOff;
  bool d0_noticed_ = false;
  bool open_blended_ = false;  // TRC-RADIUS-3: the open element runs from one radius to another
  std::optional<InForce> comp_;
  const Block* selection_ = nullptr;
  const Block* prev_block_ = nullptr;         // the last traversing block with compensation (TRC-CD-1)
  std::optional<ExactPoint> selection_from_;  // set after a side change (TRC-SIDE-1)
  std::optional<Point> retract_from_;         // TRC-DESEL-3: where the tool waits in the plane
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
  CirclePosition open_from_;  // arcs: the start point's position from the programmed start
  // Look-ahead (TRC-LOOK-*): blocks passed over, traversing blocks examined after the open element.
  bool looking_ = false;
  std::vector<const Block*> skipped_;
  int examined_ = 0;
  int dummy_run_ = 0;
};

}  // namespace cutcom::ref::detail

// Stage 2, the compensation: the TRC state machine, block by block (as ref/src/compensation.hpp).
// Its member functions live in compensation.cpp (selection, corners, look-ahead, output into the
// collision window), ends.cpp (approach and retraction: NORM, KONT, G460-G462) and collision.cpp
// (the collision check under CDON: entry, crossing, cut). It owns its state; it hands its output
// to the collision window (stage 3) and its decisions and alarms to the trace. Private to fast.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <new>
#include <numbers>
#include <span>
#include <type_traits>
#include <vector>

#include "block_copy.hpp"
#include "bottleneck.hpp"
#include "collision_window.hpp"
#include "corner_memo.hpp"
#include "cutcom/decision_trace.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "edge_strategy.hpp"
#include "exact_tangent.hpp"
#include "plane_geometry.hpp"
#include "root_tangent.hpp"

namespace cutcom::fast {

// The block an alarm names: its line, N number and place in a subprogram (NC-PARAM-SUB-3).
struct BlockPlace {
  int line = 0;
  std::optional<std::int64_t> number;
  std::uint32_t source = 0;
  template <class B>  // a block's words or a BlockCopy
  static BlockPlace of(const B& b) {
    return {b.line, b.number, b.source};
  }
};

class Compensation {
 public:
  // Not copied: the open element's block may point into the object's own slots.
  Compensation(const Compensation&) = delete;
  Compensation& operator=(const Compensation&) = delete;
  Compensation(const MachineData& m, PathSink& out, Trace& t, CollisionWindow& window)
      : md(m),
        sink(out),
        trace(t),
        held(window),
        corner_limit_cosine(limit_cosine(m.cutcom_corner_limit)),
        insert_limit_cosine(limit_cosine(m.cutcom_curve_insert_limit)) {}

  // A block from the SAR expansion; `o` gives its in-plane points where they are not its decimals;
  // `moves` is b.moves_in_plane(), asked once by the SAR expansion for all the stages.
  void step(const Block& b, const PlaneOverride* o, bool moves);
  // TRC-END-1 at the program's end.
  void end_of_program();
  // ALARM-1: the approach line decided before an alarm is output.
  void flush_approach();
  // ALARM-1: the approach line decided before an alarm is output.
  // kRetracting: a G40 block without a plane axis left the tool at the normal end point of the
  // last contour block; the next block with a plane axis finishes the retraction (TRC-DESEL-3).
  enum class Phase { kOff, kApproach, kActive, kRetracting };

 private:
  const MachineData& md;
  PathSink& sink;
  Trace& trace;
  CollisionWindow& held;  // stage 3: where output goes (collision_window.hpp)
  // TRC-CORNER-3/4: the cosines of MD20210 and MD20230, to tell a corner's side of its limit
  // without atan2 where it is far from it (NaN for a limit outside 0…180°: always atan2).
  static double limit_cosine(const Decimal& degrees) {
    double d = degrees.to_double();
    return d >= 0 && d <= 180 ? std::cos(d * (std::numbers::pi / 180)) : std::numeric_limits<double>::quiet_NaN();
  }
  const double corner_limit_cosine, insert_limit_cosine;
  Phase phase = Phase::kOff;
  bool d0_noticed = false;

  // Compensation in force (set at selection).
  PlaneAxes axes{0, 1, 2};
  Plane plane = Plane::kG17;
  Side side = Side::kOff;
  std::uint32_t selection_word = 0;  // the G41/G42 word that selected (TRC-SIDE-2)
  int s = 0;                         // +1 left, -1 right (after TRC-RADIUS-2)
  double r = 0;                      // |effective radius|
  Int128 r_units = 0;                // the same, exactly, in 10^-9 mm (TRC-KONT-2 decides on it)
  ActiveEdge edge;

  // A block without compensation, converted in place: a BlockCopy made per block makes and
  // destroys its sixteen actions' strings.
  BlockCopy uncompensated;
  BlockCopy selection;  // kApproach: the selection block
  // Its start is the tool off the programmed contour after a side change (TRC-SIDE-1); with
  // radius 0 the tool is the programmed point, so TRC-KONT-1/2 stay exact on programmed decimals.
  bool selection_from_tool = false;
  Vec2 retract_from{};  // TRC-DESEL-3: where the tool waits in the plane
  // TRC-APPR-NORM-1: the approach line and the blocks held back before the first contour block,
  // output once the first element's end is known.
  bool approach_pending = false;
  PathPoint approach_to;
  std::array<BlockCopy, MachineData::kMaxDummyBlocks + 1> approach_dummies;
  int approach_dummy_count = 0;
  bool kont_first = false;  // the open element is the first after a KONT travel-around
  // kActive: the open element, whose end waits for the next traversing block. Its block is the
  // slot it was copied into, where it was one (a second copy of 352 bytes was 4 % of a block's
  // instructions), else `open_own`; a slot refilled while its block is open hands it over first
  // (fill_slot), so that the open block never changes under the element.
  BlockCopy open_own;
  BlockCopy* open = &open_own;
  Element open_el;
  Vec2 open_start;                    // start point of its equidistant (after the previous corner)
  bool open_blended = false;          // TRC-RADIUS-3: the open element runs from one radius to another
  bool open_at_normal_start = false;  // opened at its normal start by construction (a full circle stays whole)
  double open_from = 0;               // arcs: the start point's rotation from the normal start
  // PATH-ELEMENT-2: how far (mm) the open element's start and the point closing it may lie from
  // their exact places: an intersection of carriers crossing at sine c errs by about 64 u / c of
  // the size; -1: not known (the snap's full 1e-8 of the radius).
  double open_start_error = -1, closing_point_error = -1;
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

  std::array<BlockCopy, 2> prev_blocks;  // the last traversing block with compensation and the one before
  struct SlotElement {
    bool valid = false;
    PlaneAxes axes{0, 1, 2};
    Element element;
  };
  mutable std::array<SlotElement, 2> slot_elements;  // element_of's, per slot; copy_into empties its slot's
  mutable Element unslotted_element;                 // element_of's for a block outside the slots
  mutable RootTangents root_tangents;                // decide_kind_exactly's and exact_side's GMP numbers
  mutable CornerSignsMemo corner_signs;              // decide_kind_on_integers' integer signs, of the last corner
  // The entry and the corner step take the same intersection and rotation (corner_memo.hpp).
  IntersectionMemo intersection_memo;
  mutable RotationMemo rotation_memo;
  int prev_slot = 0;
  bool has_prev = false;
  EdgeCurve approach_curve;  // TRC-CD-6: the approach's curve, searched up to block approach_until
  int approach_until = -1;

  // The prev_blocks slot `c` is, 0 or 1; 2: none.
  std::size_t slot_of(const BlockCopy& c) const { return &c == &prev_blocks[0] ? 0 : &c == &prev_blocks[1] ? 1 : 2; }
  BlockCopy copy_of(const Block& b) const {
    BlockCopy c;
    copy_into(c, b);
    return c;
  }
  // A traversing block into prev_blocks[slot] (compensation_active, the first block after the
  // approach); the open element's block, if it is there, is moved aside first.
  const BlockCopy& fill_slot(int slot, const Block& b) {
    BlockCopy& c = prev_blocks[static_cast<std::size_t>(slot)];
    if (open == &c) open_own = c, open = &open_own;
    copy_into(c, b);
    return c;
  }
  void copy_into(BlockCopy& c, const Block& b) const {  // copy_of into a slot kept from block to block
    if (std::size_t k = slot_of(c); k < 2) slot_elements[k].valid = false;
    c.assign(b, moves_in_plane(b));
    c.seq = held.seq();
    if (&b == over_block) over.apply(c);
  }

  // The block being stepped and its override (SAR-SUB-1, SAR-END-3), as the SAR expansion gave it.
  PlaneOverride over;
  const Block* over_block = nullptr;
  // The block being stepped and whether it moves in the plane, as step was told.
  const Block* stepped = nullptr;
  bool stepped_moves = false;
  bool moves_in_plane(const Block& b) const { return &b == stepped ? stepped_moves : b.moves_in_plane(); }
  // The element handed to the sink directly: each one writes every field (fill), so that it is
  // not cleared first (a local one was 240 bytes of `rep stos` before each line and arc).
  PathElement outgoing;
  // A new held record of `owner`'s, filled in place.
  HeldRecord& hold_record_of(const BlockCopy& owner) {
    HeldRecord& k = held.hold_new();
    k.seq = owner.seq, k.owner_line = owner.line, k.owner_number = owner.number, k.owner_start = owner.start;
    k.owner_block = owner.block, k.owner_insert = owner.insert;
    k.owner_end = owner.end, k.owner_rapid = owner.rapid, k.owner_feed = owner.feed;
    k.owner_feed_type = owner.feed_type, k.owner_sar = owner.sar;
    return k;
  }
  bool direct() const { return held.direct(); }
  // TRC-CD-1: the window is in force while compensation is active under CDON.
  void release_window(const Block& b);

  // --- plane <-> workpiece coordinates -------------------------------------------------------
  Vec2 ab(const PathPoint& p) const { return ab_in(p, axes); }
  double h(const PathPoint& p) const { return h_in(p, axes); }
  PathPoint xyz(Vec2 v, double applicate) const { return xyz_in(v, applicate, axes); }

  // --- output ----------------------------------------------------------------------------------
  void decide(std::string_view clause, int line, std::string_view branch) { trace.decide(clause, line, branch); }
  void decide(std::string_view clause, int line, std::string_view branch, double margin) {
    trace.decide(clause, line, branch, margin);
  }
  void decide(const ProgrammedDecision& d, int line) { trace.decide(d, line); }
  template <class At>  // a block's words or a BlockCopy (NC-PARAM-SUB-3: the alarm names its place)
  void raise(int number, const At& at, std::string_view clause = {}) {
    trace.raise(number, at, clause);
  }
  void raise(int number, int line, std::optional<std::int64_t> block, std::string_view clause = {}) {
    trace.raise(number, line, block, clause);
  }
  void actions(BlockCopy& b, const PathPoint& at);
  // Written where it is kept: an Origin built aside and copied into the element was read back by
  // 16-byte loads the CPU cannot forward from the narrower stores that had just written it (a
  // fifth of close_open's samples waited there).
  static void set_origin(Origin& o, const BlockCopy& b, OriginKind kind) {
    o.kind = kind, o.line = b.line, o.source = b.source, o.block = b.number, o.sar = b.sar, o.insert = b.insert;
    o.next_line = 0, o.next_block.reset(), o.next_insert = ContourInsert{};
  }
  Origin origin(const BlockCopy& b, OriginKind kind) const {
    Origin o;
    set_origin(o, b, kind);
    return o;
  }
  void line(BlockCopy& owner, const PathPoint& from, const PathPoint& to, OriginKind kind, bool rapid) {
    line_element(owner, from, to, rapid, [&](Origin& o) { set_origin(o, owner, kind); });
  }
  void line(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const Origin& named, bool rapid) {
    line_element(owner, from, to, rapid, [&](Origin& o) { o = named; });
  }
  template <class NameIt>  // writes the element's origin
  void line_element(BlockCopy& owner, const PathPoint& from, const PathPoint& to, bool rapid, NameIt name_it) {
    actions(owner, from);
    if (from.x == to.x && from.y == to.y && from.z == to.z) return;  // PATH-ELEMENT-1: no zero-length element
    auto fill = [&](PathElement& e) {
      e.type = ElementType::kLine, e.rapid = rapid, e.start = from, e.end = to, e.center = {}, e.ccw = false;
      e.feed = owner.feed;
      e.feed_type = owner.feed_type;
      name_it(e.origin);
    };
    if (direct()) {
      fill(outgoing);
      return sink.element(outgoing);
    }
    HeldRecord& rec = hold_record_of(owner);
    rec.is_element = true;
    fill(rec.element);
  }

  void arc(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const PathPoint& centre, bool ccw,
           const Origin& from_what);
  // A circle around an outer corner (a transition circle, G450, or its like at an entry or a
  // retraction), written as it reads (PATH-ELEMENT-2).
  void corner_circle(BlockCopy& owner, const PathPoint& from, const PathPoint& to, const PathPoint& centre, bool ccw,
                     const Origin& named);

  // A block's element; that of a block in one of prev_blocks' slots is computed once per block
  // and plane (the entry under CDON, the corner and the next block's entry all ask for it). The
  // reference is valid until the next call (a slot's: until the slot or the plane changes); callers
  // copy it at once, but for the corner's. It is made in place: made aside and copied, its 8-byte
  // stores were read back by 16-byte loads the CPU cannot forward (an eighth of corner's samples).
  const Element& element_of(const BlockCopy& c) const {
    std::size_t k = slot_of(c);
    static_assert(std::is_trivially_destructible_v<Element>);
    if (k == 2) return *::new (static_cast<void*>(&unslotted_element)) Element(element_in(c, axes));
    SlotElement& m = slot_elements[k];
    if (!m.valid || m.axes.abscissa != axes.abscissa || m.axes.ordinate != axes.ordinate)
      ::new (static_cast<void*>(&m.element)) Element(element_in(c, axes)), m.axes = axes, m.valid = true;
    return m.element;
  }

  // TRC-DUMMY-1: blocks without motion in the plane run at the corner point P*.
  void run_held_back(Vec2 at);
  void run_held_back_uncompensated();
  // TRC-DUMMY-2: at most MD20250 of them between two traversing blocks.
  void hold_back(const Block& b);

  // TRC-ELEMENT-1 / TRC-ARC-ELEMENT-1: the open element, from its start point to `end_point`, must
  // not run backwards; it is output unless its length is 0. The alarm names `alarm_line`: the
  // block whose preparation found the problem. False when an alarm stopped the program.
  // `candidate`: the block whose equidistant fixed this end (for TRC-EDGE-* on approach).
  struct Candidate {
    const BlockCopy* block;
    const Element* element;
    double radius;
  };
  // How a point of the open element was placed; a circle reads its rotation by it, as ref's
  // close_open (TRC-ARC-ELEMENT-1). kNormal: the normal point by construction (rotation 0);
  // kCorner: a corner's point, the signed rotation in (-pi, pi] from the normal point; kOnPiece:
  // found on the piece by a search (TRC-EDGE-5/6, TRC-CD-3..6), the rotation in [0, 2 pi) from the
  // piece's start.
  enum class Placed { kCorner, kNormal, kOnPiece };
  bool close_open(Vec2& end_point, const BlockPlace& alarm_at, Placed placed = Placed::kCorner,
                  const Candidate* candidate = nullptr);

  void decide_kind_exactly(const BlockCopy& first, const BlockCopy& second, Corner& c) const {
    if (first.tangent_after || second.tangent_before) {  // SAR-POINTS-1/2: tangent by construction
      c.kind = Corner::Kind::kTangent, c.sine = 0;
      return;
    }
    // The filter: a double sine further from 0 than rounding can carry it has the exact sign, which
    // the integers would only confirm (few ulps times scale over size; 2^-24 leaves 10^8).
    if (!first.exact || !second.exact) return;  // a SAR block: the double decision stands
    if (std::fabs(c.sine) > 0x1p-24 * (1 + scale_over_size(first) + scale_over_size(second))) return;
    decide_kind_on_integers(first, second, c);
  }
  void decide_kind_on_integers(const BlockCopy& first, const BlockCopy& second, Corner& c) const;
  // The block's largest coordinate over its size (decide_kind_exactly's filter), computed once
  // per copy and plane: the entry and the corner ask for it of the same blocks.
  double scale_over_size(const BlockCopy& c) const {
    bool known =
        c.scale_over_size >= 0 && c.scale_axes.abscissa == axes.abscissa && c.scale_axes.ordinate == axes.ordinate;
    return known ? c.scale_over_size : scale_over_size_now(c);
  }
  double scale_over_size_now(const BlockCopy& c) const;

  // TRC-ARC-EQ-1: a circle's equidistant must keep a positive radius; a collapsed one is passed
  // over by the look-ahead.
  bool equidistant_exists(const Block& b, const BlockCopy& c, const Element& e, double& radius);
  double exactly_inside(const BlockCopy& c, const Element& e, double radius) const;

  // `placed`: how `start` was placed (see close_open); kOnPiece: on the piece that starts at
  // `piece_start` (default: the normal start point).
  void open_element(const BlockCopy& b, const Element& e, Vec2 start, double radius, Placed placed = Placed::kCorner,
                    const Vec2* piece_start = nullptr);

  // --- checks shared by the phases with compensation in force --------------------------------
  // Returns false if the block ended the program with an alarm.
  // `radius_changes`: whether the block changes the radius (TRC-RADIUS-3), where it was checked.
  bool still_compensable(const Block& b, bool* radius_changes = nullptr);

  // --- phase: compensation off -----------------------------------------------------------------
  void compensation_off(const Block& b);

  // TRC-SIDE-1 (decision 30): G41 <-> G42 without G40; TRC-SIDE-2: the same G41/G42 again. The old
  // selection's last element ends at its normal end point; the first block of the new one with a
  // plane axis is a selection block from the tool.
  void change_side(const Block& b);
  bool anew(const Block& b) const { return selects_anew(b.state, side, selection_word); }

  void select(const Block& b);

  // --- phase: selection block waiting for the first contour block --------------------------
  void approach(const Block& b);

  // --- KONT: travelling around the start or end point (TRC-KONT-*) -----------------------------
  // The corner a KONT move makes with the contour at `vertex`: d1 runs into it, d2 out of it;
  // `point` is the tool centre off the contour (approach: start, retraction: end).
  struct Kont {
    Vec2 vertex, point, d1, d2;
    std::optional<int> exact_sign;  // sign of cross(contour tangent, point - vertex), if decided in integers
    std::optional<int> exact_room;  // sign of |point - vertex|^2 - r^2, if decided in integers
  };
  // The sign of |u|^2 - r^2 in the plane for an exact displacement u, if in range.
  std::optional<int> exact_room_sign(const std::array<Int128, 3>& u) const;

  // TRC-KONT-1's side exactly: the sign of cross(t, k * u), t the exact tangent of `block` at its
  // start or end (a line's displacement, a circle's as TRC-CORNER-1), u an exact displacement
  // (k = +-1); nullopt where either is not exact or out of range.
  std::optional<int> exact_side(const BlockCopy& block, bool at_end, const std::array<Int128, 3>& u, int k) const;

  // TRC-KONT-1: behind = strictly on the far side of the contour's tangent line from the
  // compensation side; TRC-KONT-2: then not inside the circle of radius r about the vertex.
  bool kont_side(const BlockCopy& at_block, Vec2 vertex, Vec2 point, Vec2 tangent, std::optional<int> exact_sign);
  bool kont_behind(const BlockCopy& at_block, const Kont& k, Vec2 tangent, int alarm);

  // Where the equidistant of the KONT line (through `on_line`, direction `d`) meets the element's
  // carrier, nearest the vertex; false if they do not meet (circles only).
  bool kont_intersection(const BlockCopy& at_block, const Kont& k, const Element& e, double e_radius, Vec2 on_line,
                         Vec2 d, Vec2& x);

  // TRC-KONT-3/4 with TRC-CORNER-3/4: circle or intersection, switched like any outer corner.
  bool kont_circle(const BlockCopy& at_block, const Kont& k);

  // TRC-KONT-3 / TRC-KONT-4 on approach: the approach line meets the first block at an outer corner.
  void approach_around(const BlockCopy& first, const Element& e, double radius, const Kont& k);

  // --- phase: compensation active --------------------------------------------------------------
  void reject_blend_here(const Block& b, bool searching) const;
  void blend_radius(const Block& b, const BlockCopy& copy);
  void compensation_active(const Block& b);

  Carrier carrier_of(const Element& e, double radius) const { return fast::carrier_of(e, radius, s * r); }

  void corner(const Block& b, const BlockCopy& copy);

  // TRC-CORNER-3 / TRC-CORNER-4: is an outer corner made with the transition circle? By the
  // deciding block's G450/G451, switched by the contour angle (TRC-CORNER-2, degrees).
  bool outer_corner_circle(int line_no, bool g451, const Corner& c);

  // Where a point lies on an element's equidistant: length from its normal start, left to its end.
  struct Extent {
    double along, left;
  };
  Extent extent_of(const Element& e, double radius, Vec2 p) const;

  void skip(const BlockCopy& c);
  // A candidate that does not do: passed over; alarm 10751 once MD20240 blocks were examined.
  void pass_over(const BlockCopy& c);

  // TRC-LOOK-2: the blocks after a too-short one are tried in turn, up to MD20240 examined.
  void start_look_ahead(const Block& too_short);

  void look_ahead(const Block& b, const BlockCopy* current);

  // --- G460 / G461 / G462: a too-short first or last block (TRC-EDGE-*, edge_strategy.cpp) ------

  // TRC-EDGE-1 on retraction: deselection while the look-ahead found no block to meet the open
  // element; it ends at the hit, the blocks after it are skipped.
  void retract_edge(const Block& b);

  // TRC-CD-5: with CDON the retraction's search goes on over the held-back equidistants and circles
  // of the blocks m-W ... m-2; the last hit found (the earliest block, on it the earliest point)
  // is valid. True: the path was cut there and the retraction made.
  bool search_further_back(BlockCopy& d, const EdgeCurve& curve);

  // An auxiliary curve of TRC-EDGE-2..4 as a path piece: G460's segment, G461's whole circle,
  // G462's ray as a segment reaching beyond any programmable coordinate (10^13 mm).
  static PathPiece curve_piece(const EdgeCurve& curve);

  // TRC-LOOK-3: a skipped block loses its plane motion; the rest runs at `at`.
  void skip_at(BlockCopy& k, Vec2 at);
  void decide_nearer(int line, const Carrier& u, const Carrier& v, const NearerChoice& choice);  // TRC-LOOK-4

  // TRC-EDGE-1 on approach: the first element would run backwards to meet c's equidistant; the
  // approach line ends at the hit on c's equidistant, the first block and those between are skipped.
  void approach_edge(const Candidate& c);

  // TRC-CD-6: with CDON the approach's search goes on over the later blocks while the approach line
  // is held back (up to MD20240 traversing blocks after the selection block); the last hit found
  // is valid: the approach line ends there and the blocks between lose their plane motion.
  bool approach_further_ahead(const Block& b, const BlockCopy& m);

  // --- CDON: bottleneck detection (TRC-CD-*, bottleneck.cpp) ------------------------------------
  // TRC-CD-2: block m's entry, built provisionally from its predecessor: the transition circle at an outer
  // corner (whatever G450/G451 say), then its equidistant from its normal start (from the inner
  // corner's intersection); none if that lies beyond its end or the equidistant collapses.
  struct Entry {
    Element element;
    double radius = 0;
    Vec2 vertex, normal_start, normal_end;
    Vec2 own_start;  // where m's own equidistant piece starts
    // The predecessor, which names the corner and the rest of its equidistant (its slot in
    // prev_blocks, which the cut leaves as it is).
    const BlockCopy* before = nullptr;
    Element before_element;
    double before_radius = 0;
    // pieces[0] leads to m's equidistant: the transition circle, or (G451) the predecessor's
    // equidistant extended to the intersection.
    enum class Lead { kNone, kCircle, kExtension } lead = Lead::kNone;
    Corner corner;          // at m's start, as TRC-CD-2 decided it
    bool extended = false;  // an outer corner taken as G451: the lead is the extension
    PathPiece pieces[2];
    int count = 0;
  };
  // The entry in two steps: the elements and the corner (false: m's equidistant collapses), then
  // the pieces (false: an inner corner's intersection is missing or beyond m's end).
  bool entry_corner(const BlockCopy& m, const BlockCopy& before, Entry& en);
  bool entry_pieces(const BlockCopy& m, Entry& en);
  // A box around every piece entry_pieces can build after entry_corner, without building them;
  // false where it cannot tell (see collision.cpp).
  bool entry_bound(const Entry& en, PieceBox& box) const;
  Entry entry_scratch;  // bottleneck's, kept: constructing one per block cost more than its checks

  PathPiece piece_of(const HeldRecord& rec) const;
  const PieceBox& box_of(const HeldRecord& rec) const;
  PathPiece open_piece() const;
  static bool is_candidate(const HeldRecord& rec);

  // TRC-CD-3: block m's entry against the held-back elements of blocks m-W ... m-2 (W = MD20240)
  // and, in the look-ahead, the open element; the earliest block crossed wins, on it the earliest
  // point. True: the path was cut there.
  bool bottleneck(const BlockCopy& m, const BlockCopy& before);

  // TRC-CD-4 (with TRC-LOOK-3): the crossed block ends at the crossing; the blocks after it lose
  // their plane motion (the rest runs there, in programmed order); block m goes on along its entry.
  void cut(const BlockCopy& m, const Entry& en, int record, const PieceCrossing& c, double near);

  // TRC-CD-4: cuts the held-back path at x on `record` (-1: on the open element), `along` it from
  // its start; the blocks after it lose their plane motion and run at x (TRC-LOOK-3). False: an
  // alarm stopped the run.
  bool cut_at(int record, Vec2 x, double along, const BlockPlace& at);

  // TRC-CD-4: block m goes on from the crossing along its entry.
  void continue_entry(const BlockCopy& m, const Entry& en, int entry_piece, Vec2 x);
  // A block run again at a cut, from its held record: its applicate motion at x (its actions were
  // put back before).
  void infeed_of(const HeldRecord& k, const PathPoint& from, const PathPoint& to) {
    BlockCopy owner;
    owner.line = k.owner_line, owner.number = k.owner_number, owner.rapid = k.owner_rapid, owner.feed = k.owner_feed;
    owner.block = k.owner_block, owner.insert = k.owner_insert;
    owner.feed_type = k.owner_feed_type, owner.sar = k.owner_sar;
    owner.start = k.owner_start, owner.end = k.owner_end;  // a second cut runs it again from this record
    owner.actions_done = true, owner.seq = k.seq;
    line(owner, from, to, OriginKind::kInfeed, owner.rapid);
  }
  void infeed_of(const HeldRecord& k, Vec2 x) { infeed_of(k, xyz(x, h(k.owner_start)), xyz(x, h(k.owner_end))); }

  // TRC-G450-1: circle of radius r about the programmed corner, joining the normal points; it
  // belongs to the second block.
  void transition_circle(const BlockCopy& b, const Element& next, double next_radius, Vec2 v);

  // TRC-DESEL-1: deselection; with KONT from behind the end point TRC-KONT-* travel around it,
  // otherwise (NORM, KONT in front) TRC-RETR-NORM-1.
  void deselect(const Block& b);
  void deselect_in_place(const Block& b);
  void retraction_pending(const Block& b);

  // TRC-RETR-NORM-1: the straight line to the programmed end point, a tool-centre position.
  void retraction_line(BlockCopy& last, Vec2 from_point);

  // TRC-KONT-3 / TRC-KONT-4 on retraction: the retraction line meets the last block at an outer corner.
  // TRC-EDGE-6 (FM06 p.94): KONT from behind after a too-short last block: the open
  // element meets the inserted circle about the last block's end point (the first point along it)
  // and the rest of the circle is traversed; if it misses the circle, it meets the retraction line.
  void retract_edge_around(BlockCopy& d, const BlockCopy& last_block, const Kont& k);

  void retract_around(BlockCopy& last, const Kont& k);
};

}  // namespace cutcom::fast

// The block model shared by both engines: what a block programs (BlockWords), the modal state in
// force for it (ModalState) and the resolved block with exact programmed positions (Block).
// Fixed-size fields only, so reading a block allocates nothing in the steady state.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>

#include "cutcom/decimal.hpp"

namespace cutcom {

struct Point3 {
  Decimal x, y, z;
  friend bool operator==(const Point3&, const Point3&) = default;
};

// G groups and keyword groups (spec NC-MODAL-*).
enum class Motion : std::uint8_t { kRapid /*G0*/, kLinear /*G1*/, kArcCw /*G2*/, kArcCcw /*G3*/ };
enum class Plane : std::uint8_t { kG17, kG18, kG19 };
enum class Side : std::uint8_t { kOff /*G40*/, kLeft /*G41*/, kRight /*G42*/ };
enum class ApproachMode : std::uint8_t { kNorm, kKont, kKontC, kKontT };
enum class CornerMode : std::uint8_t { kG450, kG451 };
enum class CollisionMode : std::uint8_t { kCdof, kCdon, kCdof2 };
enum class EdgeStrategy : std::uint8_t { kG460, kG461, kG462 };  // group 48
inline std::string_view g_code(EdgeStrategy s) {
  return s == EdgeStrategy::kG460 ? "G460" : s == EdgeStrategy::kG461 ? "G461" : "G462";
}
enum class SarSide : std::uint8_t { kG140, kG141, kG142, kG143 };
enum class SarSegmentation : std::uint8_t { kG340, kG341 };
enum class SarContour : std::uint8_t { kG147, kG148, kG247, kG248, kG347, kG348 };
enum class FeedType : std::uint8_t { kG94, kG95, kG93 };
enum class PathMode : std::uint8_t { kG60, kG64 };

// Units (NC-UNIT-1): G71/G710 metric, G70/G700 inch; the 7x0 forms scale the feed too.
enum class Units : std::uint8_t { kG71, kG70, kG710, kG700 };
// Diameter programming of the transverse axis X in turning (NC-DIAM-1).
enum class DiameterMode : std::uint8_t { kDiamof, kDiamon, kDiam90 };

// Kinematic transformations: none (TRAFOOF), the 5-axis TRAORI (NC-WORD-11), the face's polar
// TRANSMIT (NC-WORD-13).
enum class Transformation : std::uint8_t { kOff, kTraori, kTransmit };

// Programmable frames (NC-FRAME-*): the block's axis words are the frame's values, not a move.
enum class FrameWord : std::uint8_t { kTrans, kAtrans, kScale, kAscale, kMirror, kAmirror, kRot, kArot };

// Contour definitions (NC-CONTOUR-*): circles by an intermediate point (CIP) or tangential (CT),
// poles of polar coordinates (NC-POLAR-1).
enum class CircleDefinition : std::uint8_t { kCip, kCt };
enum class PoleWord : std::uint8_t { kG110, kG111, kG112 };

// An element the reader inserted (NC-CONTOUR-*): the rounding or chamfer at the corner of the
// block and the next, or one of the full turns of a helix with TURN=.
enum class InsertKind : std::uint8_t { kNone, kRounding, kChamfer, kTurn };
struct ContourInsert {
  InsertKind kind = InsertKind::kNone;
  int next_line = 0;  // rounding / chamfer: the second block of the corner
  std::optional<std::int64_t> next_block;
  int turn = 0;  // kTurn: 1 … TURN
  friend bool operator==(const ContourInsert&, const ContourInsert&) = default;
};

// How an axis value is to be read: modal G90/G91, or forced by AC()/IC().
enum class ValueMode : std::uint8_t { kModal, kAbsolute, kIncremental };
enum class FadMode : std::uint8_t { kModal, kPm, kPr };

struct AxisWord {
  Decimal value;  // first, so that the two flags share one 8-byte slot after it (24 bytes, not 32)
  bool present = false;
  ValueMode mode = ValueMode::kModal;
  friend bool operator==(const AxisWord&, const AxisWord&) = default;
};

// An action: a word that does not move the geometry axes, executed where the engines place it
// (PATH-ACTION-1). M and H functions keep their address and number; every other action word
// (S, G642, MSG("..."), SPOS=90, G4 F2, ...) is kept as written (NC-WORD-*).
struct AuxFunction {
  char address = 'M';  // 'M' or 'H' with `value`; 0: the word as written in `text`
  std::int64_t value = 0;
  std::string text;
  std::string name() const { return address ? address + std::to_string(value) : text; }
};

// $TC_DPn[t,d] = value
struct ToolDataAssignment {
  int parameter = 0;  // 1 … 25: 1 type, 2 cutting edge position, 6 radius, 15 radius wear
  int tool = 0;
  int edge = 0;
  Decimal value;
};

// $TC_TP2[t] = "NAME"
struct ToolNameAssignment {
  int tool = 0;
  std::string name;
};

template <class T>
using Opt = std::optional<T>;

struct ContourWords {
  Opt<Decimal> rpl;  // ROT/AROT RPL=: rotation in the working plane (NC-FRAME-4)
  Opt<Decimal> rnd, rndm, chf, chr, frc, frcm;
  Opt<Decimal> ang;
  AxisWord ap;      // AP= / AP=IC()
  Opt<Decimal> rp;  // RP=
  Opt<PoleWord> pole;
  Opt<Decimal> ar;  // opening angle AR=
  Opt<std::int64_t> turn;
  Opt<CircleDefinition> circle_definition;
  std::array<AxisWord, 3> intermediate;  // I1= J1= K1= (CIP)
};

// Everything one NC line programs, as written (before modal resolution).
// The words of a block other than its action lists (reset as a whole for every block).
struct BlockWordFields {
  int line = 0;                    // 1-based source line
  std::uint32_t source = 0;        // NC-PARAM-SUB-3: where in a subprogram (0: the line itself)
  int word_count = 0;              // 0: blank or comment-only line
  bool plain = false;              // read by read_plain_block: only N, G0…G3, X Y Z, I J K, F, M, H
  Opt<std::int64_t> number;        // N number
  std::array<AxisWord, 3> axis;    // X Y Z
  std::array<AxisWord, 3> centre;  // I J K
  Opt<Decimal> cr;

  Opt<Motion> motion;
  Opt<int> thread;  // NC-WORD-12: G33 G34 G35 G331 G332 (motion kLinear), G63 (this block only)
  Opt<Plane> plane;
  Opt<bool> absolute;  // G90 true, G91 false
  Opt<Side> side;
  Opt<ApproachMode> approach;
  Opt<CornerMode> corner;
  Opt<CollisionMode> collision;
  Opt<EdgeStrategy> edge_strategy;
  Opt<SarSide> sar_side;
  Opt<SarSegmentation> sar_segmentation;
  Opt<SarContour> sar_contour;
  Opt<FeedType> feed_type;
  Opt<PathMode> path_mode;

  Opt<Decimal> feed;
  Opt<std::int64_t> tool;
  Opt<std::int64_t> edge;
  Opt<std::int64_t> sum_offset;  // DL=n (TOOL-SUM-1)
  Opt<Decimal> offn;
  Opt<Decimal> disc;
  Opt<Decimal> disr;
  AxisWord discl;  // DISCL= / DISCL=AC() (IC() not allowed)
  AxisWord disrp;
  Opt<Decimal> fad;
  FadMode fad_mode = FadMode::kModal;
  bool stopre = false;
  bool program_end = false;  // M2 / M30 (M17 / RET: end of a subprogram run on its own)
  bool dwell = false;        // G4: F and S in the block are the dwell, not feed or speed
  bool tool_change = false;  // M6 (TOOL-CHANGE-1)
  Opt<Units> units;
  Opt<int> settable_offset;  // G500 = 0, G54…G57 = 1…4, G505…G599 = 5…99 (NC-OFFSET-1)
  Opt<DiameterMode> diameter;
  Opt<FrameWord> frame;
  // NC-WORD-8: a rotary axis (A, B or C) programmed with X, Y or Z, and the column of the first
  // of them; allowed only in a rapid move without compensation (the reader decides).
  std::string_view rotary_with_plane;  // the rotary axis or orientation word moving with X, Y or Z (a literal)
  int rotary_column = 0;
  std::string_view orientation_word;   // A2…C3, LEAD, TILT, THETA, PSI: the tool's orientation (NC-WORD-11)
  Opt<Transformation> transformation;  // TRAORI, TRANSMIT, TRAFOOF: NC-WORD-11/13
  bool modal_call = false;             // MCALL: the cycle in `not_simulated` runs after every move
  bool modal_call_end = false;         // MCALL alone
  bool repeats_from_start = false;     // GOTOS (NC-PARAM-FLOW-7): also a program end
  bool synchronized_action = false;    // NC-WORD-9: WHEN/WHENEVER/EVERY/FROM/DO … kept as an action

  bool programs_any_axis() const { return axis[0].present || axis[1].present || axis[2].present; }
  friend bool operator==(const BlockWordFields&, const BlockWordFields&) = default;
};

// The fields are plain data whose empty values are zero bytes, so that a block's reset clears them
// (every field's default must stay zero: a unit test holds BlockWordFields{} all zero).
static_assert(std::is_trivially_copyable_v<BlockWordFields>);
// That clear, out of line (words.cpp): GCC's own clear of this size is `rep stosq` or a loop; it
// writes 33 unrolled 16-byte stores instead.
void reset_fields(BlockWordFields& fields);

struct BlockWords : BlockWordFields {
  static constexpr int kMaxAux = 16;
  static constexpr int kMaxToolData = 4;

  // A new block: every field reset, the strings and action lists emptied in place, so that they
  // keep their buffers (the reader's per-block cost; action entries past a count are stale).
  void reset(int source_line) {
    reset_fields(*this);
    contour.reset();
    line = source_line;
    tool_name.reset();
    not_simulated.clear();
    aux_count = tool_data_count = tool_names_count = 0;
  }

  // Contour definitions, polar coordinates and RPL: rare words, kept apart so that a block
  // without them stays small to reset (only its flag; NC-CONTOUR-*, NC-POLAR-*, NC-FRAME-4).
  Opt<ContourWords> contour;
  const ContourWords& cw() const {
    static const ContourWords kNone{};
    return contour ? *contour : kNone;
  }
  ContourWords& cw_set() { return contour ? *contour : contour.emplace(); }

  Opt<std::string> tool_name;  // T="NAME" (TOOL-NAME-1)
  // NC-CYCLE-1: a block that moves the tool along a path cutcom does not simulate (a standard
  // cycle, G74/G75, a G53/G153/SUPA move): what it is, as written ("CYCLE81", "SUPA").
  std::string not_simulated;

  std::array<AuxFunction, kMaxAux> aux{};
  int aux_count = 0;
  std::array<ToolDataAssignment, kMaxToolData> tool_data{};
  int tool_data_count = 0;
  std::array<ToolNameAssignment, kMaxToolData> tool_names{};
  int tool_names_count = 0;
};

// The modal state in force for a block (after applying its words).
struct ModalState {
  Motion motion = Motion::kRapid;
  Plane plane = Plane::kG17;
  bool absolute = true;
  Side side = Side::kOff;
  // TRC-SIDE-2: counts the G41/G42 words read so far. While compensation is active, a block whose
  // count differs from the selection's selects anew (the same side programmed again).
  std::uint32_t selection = 0;
  ApproachMode approach = ApproachMode::kNorm;
  CornerMode corner = CornerMode::kG450;
  Decimal disc;
  CollisionMode collision = CollisionMode::kCdof;
  EdgeStrategy edge_strategy = EdgeStrategy::kG462;
  SarSide sar_side = SarSide::kG140;
  SarSegmentation sar_segmentation = SarSegmentation::kG340;
  FeedType feed_type = FeedType::kG94;
  PathMode path_mode = PathMode::kG60;
  Decimal feed;
  std::int64_t tool = 0;                                 // 0: no tool active
  std::int64_t edge = 0;                                 // 0: D0, no edge active
  std::int64_t sum_offset = 0;                           // DL: 0 none (TOOL-SUM-1)
  Transformation transformation = Transformation::kOff;  // in force (NC-WORD-11/13)
  Decimal offn;
  // Edge data captured when T or D was programmed (spec TOOL-EDGE-2).
  Decimal edge_radius;  // $TC_DP6
  Decimal edge_wear;    // $TC_DP15
  bool edge_defined = false;
  // TOOL-TURN-1: a turning tool's cutting edge position $TC_DP2 (1 … 8); 0 when the edge centre
  // is the reference point (milling tools, positions 0 and 9).
  std::int8_t edge_position = 0;

  // Settings of the reader that machine data decide, not the program (TOOL-CHANGE-1/2):
  // MD20270 $MC_CUTTING_EDGE_DEFAULT and MD22550 $MC_TOOL_CHANGE_MODE.
  std::int64_t md_edge_default = 1;        // >0 that edge, 0 D0, -1 keep the D number
  std::int64_t md_sum_offset_default = 0;  // MD20272 $MC_SUMCORR_DEFAULT: the DL a new edge brings
  bool md_change_on_m6 = false;            // MD22550 = 1: T preselects, M6 changes

  // TRC-RADIUS-1: effective radius = $TC_DP6 + $TC_DP15 + OFFN (may be negative).
  Decimal effective_radius() const { return edge_radius + edge_wear + offn; }
};

// Abscissa, ordinate and applicate index (0=X,1=Y,2=Z) of a plane (spec NC-PLANE-1).
struct PlaneAxes {
  int abscissa, ordinate, applicate;
};
constexpr PlaneAxes plane_axes(Plane p) {
  switch (p) {
    case Plane::kG17:
      return {0, 1, 2};
    case Plane::kG18:
      return {2, 0, 1};
    case Plane::kG19:
      return {1, 2, 0};
  }
  return {0, 1, 2};
}

constexpr const Decimal& coord(const Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
constexpr Decimal& coord(Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// SAR sub-blocks (spec SAR-SUB-1): which movement of a smooth approach or retraction a block
// generated from a SAR block is. Its in-plane points at the SAR point P3 (and, for SAR-END-2,
// the tool centre there) are not decimals: each engine keeps them in its own number model, and
// the block's decimal coordinates there are only a rounded picture.
enum class SarMove : std::uint8_t {
  kNone,        // a programmed block
  kLead,        // P0 -> P1 (approach) / P1 -> P0 (retraction): parallel to the plane unless DISRP
  kFastInfeed,  // P1 <-> P2
  kSlowInfeed,  // P2 <-> P3 (G341)
  kElement,     // P3 <-> P4: the straight line, quadrant or semicircle (helix with G340)
  kEndPath,     // SAR-END-2: P1 -> P0 added when G40 deselects in a retraction without end point
};
struct SarTag {
  SarMove move = SarMove::kNone;
  bool plane_motion = false;  // decided by the engine that generated the block
  bool start_at_p3 = false, end_at_p3 = false;
  bool end_at_tool_centre = false;  // SAR-END-2: the end is the tool centre at P1
  int sar_line = 0;                 // source line of the SAR block
};

// A resolved block: its words, the modal state in force, and exact programmed start/end points.
struct Block {
  BlockWords words;
  ModalState state;
  ModalState previous;  // state in force for the block before (for changes detected by engines)
  Point3 start;         // programmed position before the block
  Point3 end;           // programmed position after the block (modal completion applied)
  Opt<Point3> centre;   // arc centre from I J K (G2/G3); CR= arcs leave this empty
  int index = 0;        // 0-based block index in the program
  bool circle = false;  // set by the reader: see is_arc()

  // TOOL-TURN-1: what the reader added to `start` and to `end` (and `centre`) for a turning tool's
  // tip; zero elsewhere. Pictures subtract it to draw the programmed contour.
  Point3 tip_shift_start, tip_shift_end;

  SarTag sar;            // a SAR sub-block (engines only; the reader leaves it empty)
  ContourInsert insert;  // an element the reader inserted (NC-CONTOUR-*); kNone for programmed ones
  // A notice of the reader's on this block (a move not simulated, a position assumed): the
  // engines pass it to the sink when they take the block.
  std::string_view notice_clause;
  std::string notice;

  // Any geometry axis of the active plane written in the block (spec TRC-SEL-3/4).
  bool programs_plane_axis() const {
    if (sar.move != SarMove::kNone) return sar.plane_motion;
    PlaneAxes a = plane_axes(state.plane);
    return words.axis[a.abscissa].present || words.axis[a.ordinate].present;
  }
  // In-plane displacement is non-zero (exact comparison of programmed decimals).
  // A circle always does: with equal start and end it is a full circle.
  bool moves_in_plane() const {
    if (sar.move != SarMove::kNone) return sar.plane_motion;
    if (is_arc()) return true;
    PlaneAxes a = plane_axes(state.plane);
    return coord(start, a.abscissa) != coord(end, a.abscissa) || coord(start, a.ordinate) != coord(end, a.ordinate);
  }
  bool is_linear() const { return state.motion == Motion::kRapid || state.motion == Motion::kLinear; }
  // A circle: G2/G3 in force and the block programs an axis or circle data (NC-ARC-2). A block
  // without them (only M8, say) moves nowhere, whatever the modal motion.
  bool is_arc() const { return circle; }
  bool is_sar_block() const { return words.sar_contour.has_value(); }  // SAR-BLOCK-1
};

}  // namespace cutcom

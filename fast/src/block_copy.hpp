// What fast's stages hand each other about a block: the block converted once into doubles
// (BlockCopy, copied into fixed slots: no allocation), and where a block's in-plane points are
// not its decimals, the points the SAR expansion computed (PlaneOverride, SAR-SUB-1, SAR-END-3).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

#include "cutcom/block.hpp"
#include "cutcom/sink.hpp"
#include "edge_strategy.hpp"
#include "plane_geometry.hpp"
#include "sar_shape.hpp"

namespace cutcom::fast {

// A copy 8 bytes at a time, each word through a register. For decimals the reader has just
// computed: Int128 arithmetic writes them as two 8-byte stores, from which the CPU cannot forward
// the 16-byte load of a plain copy; that load waits until both stores are written.
template <class T>
void copy_by_words(T& to, const T& from) {
  static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % 8 == 0);
  const char* s = reinterpret_cast<const char*>(&from);
  char* d = reinterpret_cast<char*>(&to);
  for (std::size_t i = 0; i < sizeof(T); i += 8) {
    std::uint64_t w;
    std::memcpy(&w, s + i, 8);
    asm("" : "+r"(w));  // no wider load made of two of them
    std::memcpy(d + i, &w, 8);
  }
}

// What fast keeps of a block but its actions: plain data.
struct BlockFacts {
  int line = 0;
  std::uint32_t source = 0;  // NC-PARAM-SUB-3
  int block = 0;             // the block's index in the program: its identity (inserted elements share a line)
  std::optional<std::int64_t> number;
  PathPoint start, end;  // programmed, workpiece coordinates
  bool rapid = false;
  bool arc = false;  // G2/G3 with I/J/K
  int sense = 1;     // +1 G3, -1 G2
  PathPoint centre;  // programmed centre (I/J/K arcs)
  bool has_centre = false;
  double cr = 0;                      // CR= arcs
  Int128 cr_units = 0;                // the same, exactly, in 10^-9 mm (the centre's height from integers)
  std::array<Int128, 3> delta{};      // exact programmed displacement X Y Z, units of 1e-9 mm
  std::array<Int128, 3> to_centre{};  // exact programmed centre less start (I/J/K arcs), units
  Decimal feed;
  int aux_count = 0;
  bool actions_done = false;
  bool kont = false;  // KONT in force (approach and retraction)
  bool g451 = false;  // G451 in force
  bool cdon = false;  // CDON in force
  int seq = 0;        // ordinal of the last traversing block up to this one (TRC-CD-1 window)
  EdgeStrategy edge_strategy = EdgeStrategy::kG462;
  FeedType feed_type = FeedType::kG94;
  SarMove sar = SarMove::kNone;
  ContourInsert insert;  // NC-CONTOUR-*: an element the reader inserted
  bool moves = false;    // motion in the plane
  bool exact = true;     // start and end are the programmed decimals (`delta` is valid)
  // SAR-POINTS-1/2: a SAR element is tangent to the contour at P4 by construction: after it on
  // approach, before it on retraction.
  bool tangent_after = false, tangent_before = false;
  // A SAR line's direction: the tangent it was built on, not its rounded points' difference, which
  // on a short element is off by far more than a rounding (TRC-LOOK-2: campaign 20261324, case
  // 33523, a 0.001 mm approach and the retraction on one tangent, which ref finds on one line).
  std::int8_t unit_abscissa = -1;  // the abscissa of the plane `unit` is in; -1: no unit, the points'
  Vec2 unit;
  // The corner filter's scale over size in the plane `scale_axes` (compensation.cpp), once asked
  // for (-1: not yet). It goes with the copies (the open element's is its slot's); reset where
  // the points change.
  mutable double scale_over_size = -1;
  mutable PlaneAxes scale_axes{0, 1, 2};
};

// What fast keeps of a block: converted once, copied into fixed slots (no allocation). A copy
// takes the block's own actions only: the sixteen slots' text was 8 % of a contour's engine time.
struct BlockCopy : BlockFacts {
  std::array<AuxFunction, BlockWords::kMaxAux> aux{};  // the first aux_count are the block's

  BlockCopy() = default;
  BlockCopy(const BlockCopy& o) : BlockFacts(o) { copy_actions(o); }
  BlockCopy& operator=(const BlockCopy& o) {
    static_cast<BlockFacts&>(*this) = o;
    copy_actions(o);
    return *this;
  }
  void copy_actions(const BlockCopy& o) { std::copy_n(o.aux.begin(), o.aux_count, aux.begin()); }

  static BlockCopy of(const Block& b) {
    BlockCopy c;
    c.assign(b, b.moves_in_plane());
    return c;
  }
  // The same in place: a slot kept from block to block reuses its actions' text (no allocation
  // and no string destruction per block); actions past aux_count are stale and never read.
  // `in_plane` is b.moves_in_plane(), which the caller has asked already.
  void assign(const Block& b, bool in_plane) {
    BlockCopy& c = *this;
    c.line = b.words.line;
    c.source = b.words.source;
    c.block = b.index;
    c.number = b.words.number;
    c.start = {b.start.x.to_double(), b.start.y.to_double(), b.start.z.to_double()};
    c.end = {b.end.x.to_double(), b.end.y.to_double(), b.end.z.to_double()};
    c.rapid = b.state.motion == Motion::kRapid;
    c.arc = b.is_arc();
    c.sense = b.state.motion == Motion::kArcCcw ? 1 : -1;
    c.has_centre = b.centre.has_value();
    c.centre =
        b.centre ? PathPoint{b.centre->x.to_double(), b.centre->y.to_double(), b.centre->z.to_double()} : PathPoint{};
    c.cr = b.words.cr ? b.words.cr->to_double() : 0;
    c.cr_units = b.words.cr ? b.words.cr->units() : 0;
    // Differences of two values within Decimal's limits: far inside Int128, no check needed. Set
    // one by one: a braced array was built aside and copied, a 16-byte load of two 8-byte stores
    // that the CPU cannot forward (a sixth of compensation_active's samples waited there).
    auto set_between = [](std::array<Int128, 3>& out, const Point3& from, const Point3& to) {
      out[0] = to.x.units() - from.x.units();
      out[1] = to.y.units() - from.y.units();
      out[2] = to.z.units() - from.z.units();
    };
    set_between(c.delta, b.start, b.end);
    if (b.centre) set_between(c.to_centre, b.start, *b.centre);
    c.feed = b.state.feed;
    std::copy_n(b.words.aux.begin(), b.words.aux_count, c.aux.begin());  // only the block's actions
    c.aux_count = b.words.aux_count;
    c.kont = b.state.approach == ApproachMode::kKont;
    c.g451 = b.state.corner == CornerMode::kG451;
    c.cdon = b.state.collision == CollisionMode::kCdon;
    c.edge_strategy = b.state.edge_strategy;
    c.feed_type = b.state.feed_type;
    c.sar = b.sar.move;
    c.insert = b.insert;
    c.moves = in_plane;
    c.exact = b.sar.move == SarMove::kNone;
    c.seq = 0, c.actions_done = false, c.tangent_after = c.tangent_before = false;
    c.unit_abscissa = -1;
    c.scale_over_size = -1;
  }
};

// Plane <-> workpiece coordinates in a given plane (the compensation's, or a SAR block's). The
// axes are plane_axes' of G17, G18 or G19 (the only ones made), which the abscissa tells apart:
// one branch, predicted, instead of an axis look-up per coordinate (every point of every block).
inline Vec2 ab_in(const PathPoint& p, PlaneAxes a) {
  switch (a.abscissa) {
    case 0:
      return {p.x, p.y};  // G17
    case 2:
      return {p.z, p.x};  // G18
    default:
      return {p.y, p.z};  // G19
  }
}
inline double h_in(const PathPoint& p, PlaneAxes a) { return a.abscissa == 0 ? p.z : a.abscissa == 2 ? p.y : p.x; }
inline PathPoint xyz_in(Vec2 v, double applicate, PlaneAxes a) {
  switch (a.abscissa) {
    case 0:
      return {v.a, v.b, applicate};
    case 2:
      return {v.b, applicate, v.a};
    default:
      return {applicate, v.a, v.b};
  }
}
// Integer displacements below 2^62 units: products of two and sums of two such stay in 128 bits.
inline bool in_exact_range(Int128 v) {
  const Int128 limit = Int128(1) << 62;
  return v < limit && v > -limit;
}

// The element of a block in the plane `a`.
inline Element element_in(const BlockCopy& c, PlaneAxes a) {
  if (!c.arc)
    return c.unit_abscissa == a.abscissa ? Element::line_along(ab_in(c.start, a), ab_in(c.end, a), c.unit)
                                         : Element::line(ab_in(c.start, a), ab_in(c.end, a));
  if (c.has_centre) return Element::circle(ab_in(c.start, a), ab_in(c.end, a), ab_in(c.centre, a), c.sense);
  // ARC-CR-1: q = CR^2 / chord^2 - 1/4 and the chord from the programmed integers, rounded once:
  // near a half circle the doubles' q cancels to a few ulps of 1/4, and on a short chord the
  // difference of two rounded points tilts it; the centre moves by CR times either error.
  double q = std::numeric_limits<double>::quiet_NaN();
  Vec2 chord{std::numeric_limits<double>::quiet_NaN(), 0};
  if (c.exact) {
    Int128 da = c.delta[static_cast<std::size_t>(a.abscissa)], db = c.delta[static_cast<std::size_t>(a.ordinate)];
    if (in_exact_range(da) && in_exact_range(db) && in_exact_range(c.cr_units)) {
      Int128 chord2 = da * da + db * db;
      if (chord2 > 0) {
        q = static_cast<double>(4 * c.cr_units * c.cr_units - chord2) / (4 * static_cast<double>(chord2));
        // The chord too: end - start of two rounded points loses digits on a short chord.
        chord = {static_cast<double>(da) / 1e9, static_cast<double>(db) / 1e9};
      }
    }
  }
  return Element::circle_by_radius(ab_in(c.start, a), ab_in(c.end, a), c.cr, c.sense, q, chord);
}

// Where a block's in-plane points are not its decimals (SAR-SUB-1, SAR-END-3): doubles in the
// plane of the SAR block.
struct PlaneOverride {
  PlaneAxes axes{0, 1, 2};  // the plane its points are in (the SAR block's)
  bool start = false, end = false;
  Vec2 start_ab, end_ab;
  bool circle = false;  // the SAR element's circle
  Vec2 centre;
  int sense = 0;
  bool tangent_after = false, tangent_before = false;
  bool line_unit = false;  // the SAR line's direction (BlockFacts::unit)
  Vec2 unit;

  // The SAR element's own shape: its circle, or the line's direction (the tangent it was built on).
  void take_element(const SarShape& shape) {
    circle = shape.circle, centre = shape.centre, sense = shape.sense;
    line_unit = !shape.circle, unit = shape.end_unit;
  }

  // The block's copy with these points.
  void apply(BlockCopy& c) const {
    PlaneAxes a = axes;
    if (start) c.start = xyz_in(start_ab, h_in(c.start, a), a);
    if (end) c.end = xyz_in(end_ab, h_in(c.end, a), a);
    if (circle) c.arc = true, c.has_centre = true, c.centre = xyz_in(centre, h_in(c.start, a), a), c.sense = sense;
    if (start || end || circle)
      c.exact = false, c.scale_over_size = -1;  // `delta` and `to_centre` are the decimals' no more
    c.tangent_after = tangent_after, c.tangent_before = tangent_before;
    c.unit = unit, c.unit_abscissa = static_cast<std::int8_t>(line_unit ? a.abscissa : -1);
  }
};

}  // namespace cutcom::fast

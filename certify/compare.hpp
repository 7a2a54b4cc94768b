// The differential comparison of fast against ref (docs/tolerances.md): decisions first, then
// coordinates. A divergence is acceptable only where ref's exact margin lies inside the band
// documented for that clause; coordinates must agree within a tolerance scaled to the contour.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cutcom/block.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::props {

constexpr double kUnitRoundoff = 0x1p-53;

// A decision's margin as a number: ref's exact text read to the nearest double, or fast's double.
inline double margin_value(const Decision& d) {
  return d.margin_exact.empty() ? d.margin : std::strtod(d.margin_exact.c_str(), nullptr);
}

// What the tolerances depend on, read off the program.
struct Conditioning {
  double size = 1;                // L: largest coordinate magnitude or radius, mm
  double shortest = 1;            // d_min: shortest in-plane block, mm
  double radius = 0;              // |r|, mm
  double corner = 1;              // kappa: largest 1/(1 + cos phi) over the contour's corners
  double crossing = 1;            // chi: largest 1/|sin phi| over corners with a circle (carrier intersections)
                                  // and over pairs of blocks the look-ahead or CDON may intersect (MD20240 apart)
  double reach = 0;               // largest coordinate magnitude of ref's path, mm (0: not read)
  int window = 3;                 // MD20240: blocks the look-ahead and CDON see ahead
  std::vector<int> plane_lines;   // lines of the blocks that move in the plane, ascending
  std::vector<int> circle_lines;  // of those, the circles and the SAR blocks (whose element may be one)
  // Blocks about which fast computes points in double: SAR blocks (their elements, and the points
  // of the blocks next to them) and new selections under compensation (TRC-SIDE-1/2: the
  // approach from the tool).
  std::vector<int> computed_lines;
};
// `window`: MD20240, how far apart the look-ahead (TRC-LOOK-2) and collision detection (TRC-CD-3)
// may intersect two blocks' equidistants.
// `generated`: ref's run of the program, for what the program does not show: the contour SAR
// generates (the corner of its lead with its element) and the reach of the path itself (a G451
// intersection of nearly reversed lines lies far away: r tan of half the turn).
Conditioning conditioning_of(const std::vector<Block>& program, int window = 5, const RunResult* generated = nullptr);
void add_generated(Conditioning& c, const std::vector<Block>& program, const RunResult& ref);

struct Tolerance {
  double coordinate;  // mm
  double sine;        // TRC-CORNER-1 margin (sine of the turn)
  double degrees;     // TRC-CORNER-3/4 margin (contour angle - threshold)
  // After a touching decision (TRC-EDGE-5 hit, TRC-CD-2 g451-*, TRC-ARC-CORNER-1 with the margin
  // in the band): a point on nearly tangent carriers moves along them by up to sqrt(4 L band).
  double touching;
  // PROP-DIFF-2: blocks after a knife edge whose decisions may follow from it (MD20240 + 1),
  // counted in blocks that move in the plane (`plane_lines`; empty: every line counts), as the
  // look-ahead and CDON count them.
  int window = 4;
  std::vector<int> plane_lines;
  std::vector<int> circle_lines;    // Conditioning::circle_lines, ascending
  std::vector<int> computed_lines;  // Conditioning::computed_lines, ascending
  static Tolerance for_program(const Conditioning& c);
  double band(std::string_view clause) const;  // the band of a clause's margin
};

struct Verdict {
  enum class Kind { kAgree, kKnifeEdge, kDiverge } kind = Kind::kAgree;
  std::string explanation;  // what differs, where, and by how much
  std::string clause;       // knife edge: the clause whose decision parted the runs
  double max_coordinate_error = 0;
  bool compared_after = false;  // PROP-DIFF-2: a knife edge after which the runs met again and agree
};

Verdict compare(const RunResult& ref, const RunResult& fast, const Tolerance& tol);

// PROP-BOUNDARY-1: the first decision of `run` whose branch its own margin contradicts under the
// clause's boundary rule (cutcom/boundary_rules.hpp), described; empty when there is none.
std::optional<std::string> broken_boundary_rule(const RunResult& run, std::string_view engine);
// PATH-ELEMENT-1: an element of length zero in an engine's output, as written (used for fast).
std::optional<std::string> zero_length_element(const RunResult& run, std::string_view engine);
// PATH-ELEMENT-2: an arc in an engine's output whose written points leave its turn undetermined (its
// end in its start's direction from the centre within rounding, not the same point; used for fast).
std::optional<std::string> undetermined_turn(const RunResult& run, std::string_view engine);

// PROP-TRACE-1: what differs between fast's run that keeps its decisions and the same run that
// keeps none (`cutcom run` without --trace, which may leave out work only margins need): path,
// actions and alarms must be identical, bit for bit. Empty when nothing does.
std::optional<std::string> untraced_difference(const RunResult& traced, const RunResult& untraced,
                                               std::string_view engine = "fast");

}  // namespace cutcom::props

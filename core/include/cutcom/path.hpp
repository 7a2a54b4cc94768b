// The output path model shared by both engines: tool-centre path elements with provenance.
// Coordinates are doubles: this is the output boundary (ref converts its exact values here).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "cutcom/block.hpp"

namespace cutcom {

struct PathPoint {
  double x = 0, y = 0, z = 0;
};

enum class ElementType : std::uint8_t { kLine, kArc };

// What made an element (spec PATH-ORIGIN-1).
enum class OriginKind : std::uint8_t {
  kProgrammed,        // a block run without compensation
  kApproach,          // the selection block's move onto the contour
  kOffset,            // the equidistant of a compensated block
  kTransitionCircle,  // the circle about the programmed corner of blocks `line` / `next_line`
  kRetraction,        // the deselection block's move off the contour
  kInfeed,            // motion of a block without motion in the plane, run at the corner point
};

struct Origin {
  OriginKind kind = OriginKind::kProgrammed;
  int line = 0;                       // source line of the block
  std::uint32_t source = 0;           // NC-PARAM-SUB-3: where in a subprogram (the reader's names)
  std::optional<std::int64_t> block;  // its N number
  int next_line = 0;                  // transition circle: line of the second corner block
  std::optional<std::int64_t> next_block;
  ContourInsert next_insert;     // transition circle: the second corner block is an inserted one
  SarMove sar = SarMove::kNone;  // the element belongs to this movement of a SAR block
  ContourInsert insert;          // the block is a rounding, chamfer or turn the reader inserted
  friend bool operator==(const Origin&, const Origin&) = default;
};

struct PathElement {
  ElementType type = ElementType::kLine;
  bool rapid = false;
  PathPoint start, end, center;         // center: arcs only
  bool ccw = false;                     // arcs: counter-clockwise seen from the positive applicate axis
  Decimal feed;                         // modal feed of the block the element belongs to
  FeedType feed_type = FeedType::kG94;  // G95 for revolutional feed (FAD=PR())
  Origin origin;
};

// An auxiliary function (M/H), executed at `at` before the next element.
struct ActionEvent {
  int line = 0;
  std::optional<std::int64_t> block;
  AuxFunction function;
  PathPoint at;
};

std::string_view origin_kind_name(OriginKind k);             // "offset", "transition_circle", ...
std::string describe(const Origin& o);                       // "transition circle at corner N30/N40"
void append_description(std::string& out, const Origin& o);  // the same, appended to `out`
constexpr std::size_t kDescriptionRoom = 320;                // at most the description's characters
char* put_description(char* p, const Origin& o);             // the same, written at `p`; returns the end
std::string_view sar_move_name(SarMove m);                   // "lead", "fast_infeed", ... ("" for kNone)
std::string_view insert_kind_name(InsertKind k);             // "rounding", "chamfer", "turn" ("" for kNone)

}  // namespace cutcom

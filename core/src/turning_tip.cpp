// TOOL-TURN-1: a turning tool with a cutting edge position. The program positions the tool's
// theoretical tip P; compensation runs the edge centre S at the radius from the contour, and P
// lies r from S along the directions of the cutting edge position. Translating the compensated
// contour by that vector is the same: the equidistant of the moved contour is S's path moved
// onto P's, and every decision (KONT's side, SAR's start) sees P's start point against the moved
// contour exactly as S's start against the programmed one. The engines stay as they are.
#include <fmt/format.h>

#include <array>

#include "cutcom/input_error.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

namespace {

// Abscissa and ordinate signs of P − S for positions 1 … 8. Positions 1 … 4: both edges in one
// quadrant, the tip on its diagonal; 5 … 8: an axis between the edges, the tip on that axis. The
// quadrants follow from the cut directions the manual allows each position (FM11 p.1526):
// 1 ordinate+ abscissa+, 2 ordinate+ abscissa−, 3 ordinate− abscissa−, 4 ordinate− abscissa+.
constexpr std::array<std::array<int, 2>, 9> kTipDirection{{
    {0, 0},
    {1, 1},
    {-1, 1},
    {-1, -1},
    {1, -1},
    {1, 0},
    {0, 1},
    {-1, 0},
    {0, -1},
}};

Decimal times_sign(const Decimal& r, int sign) { return sign > 0 ? r : sign < 0 ? -r : Decimal{}; }

void move(Point3& p, PlaneAxes ax, const Decimal& da, const Decimal& dor) {
  coord(p, ax.abscissa) = coord(p, ax.abscissa) + da;
  coord(p, ax.ordinate) = coord(p, ax.ordinate) + dor;
}

std::string_view axis_name(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

std::string direction_text(PlaneAxes ax, int position) {
  std::string out;
  auto [sa, so] = kTipDirection[static_cast<std::size_t>(position)];
  if (sa != 0) out += fmt::format("{}{}", sa > 0 ? "+" : "-", axis_name(ax.abscissa));
  if (so != 0) out += fmt::format("{}{}{}", out.empty() ? "" : " ", so > 0 ? "+" : "-", axis_name(ax.ordinate));
  return out;
}

}  // namespace

std::string ProgramReader::tool_and_edge(const ModalState& s) const {
  std::optional<std::string> name = tools_.name_of(s.tool);
  return name ? fmt::format("T=\"{}\" D{}", *name, s.edge) : fmt::format("T{} D{}", s.tool, s.edge);
}

std::int8_t ProgramReader::edge_position_of(const EdgeData* e, const ModalState& s, int line) const {
  if (!e || e->type < Decimal::from_int(500) || e->type >= Decimal::from_int(600)) return 0;
  std::optional<std::int64_t> p = e->position.to_integer();
  if (!p || *p < 0 || *p > 9)
    throw InputError(line, 1,
                     fmt::format("{}: cutting edge position {} ($TC_DP2) is not a whole number 0 … 9", tool_and_edge(s),
                                 e->position.to_string()));
  if (*p == 0 || *p == 9) return 0;  // the edge centre is the reference
  if (e->radius + e->wear < Decimal::from_int(0))
    throw InputError(line, 1,
                     fmt::format("{} is a turning tool with cutting edge position {} and a negative radius "
                                 "($TC_DP6 + $TC_DP15): cutcom does not simulate that tool tip",
                                 tool_and_edge(s), *p));
  return static_cast<std::int8_t>(*p);
}

void ProgramReader::tool_tip_offset(Block& b) {
  b.tip_shift_start = b.tip_shift_end = Point3{};
  const ModalState& s = b.state;
  bool selects = !tip_on_contour_ && s.side != Side::kOff && (b.programs_plane_axis() || b.is_sar_block());
  bool on_contour_after = s.side != Side::kOff && (tip_on_contour_ || selects);
  // A G40 block without a plane axis leaves the tool where it is (TRC-DESEL-3): nothing to move.
  bool deselects_in_place = tip_on_contour_ && s.side == Side::kOff && !b.programs_plane_axis() && !b.is_sar_block();
  const ModalState& edge = tip_on_contour_ ? b.previous : s;
  if (edge.edge_position != 0 && !deselects_in_place) {
    PlaneAxes ax = plane_axes(edge.plane);
    Decimal r = edge.edge_radius + edge.edge_wear;
    auto [sa, so] = kTipDirection[static_cast<std::size_t>(edge.edge_position)];
    Decimal da = times_sign(r, sa), dor = times_sign(r, so);
    if (tip_on_contour_) {
      move(b.start, ax, da, dor);
      move(b.tip_shift_start, ax, da, dor);
    }
    if (on_contour_after) {
      move(b.end, ax, da, dor);
      move(b.tip_shift_end, ax, da, dor);
      if (b.centre) move(*b.centre, ax, da, dor);
    }
    if (selects)
      note(b, "TOOL-TURN-1",
           fmt::format("{} is a turning tool with cutting edge position {}: the path is its tip's, which runs "
                       "{} mm {} of the edge centre while compensation is in force",
                       tool_and_edge(s), edge.edge_position, r.to_string(), direction_text(ax, edge.edge_position)));
  }
  tip_on_contour_ = on_contour_after;
}

}  // namespace cutcom

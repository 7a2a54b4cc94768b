// NC-MODAL-*, NC-POS-*, TOOL-*: modal resolution of blocks, exact positions and tool data.
#include <fmt/format.h>

#include <stdexcept>

#include "cutcom/reader.hpp"

namespace cutcom {

void ToolTable::assign(const ToolDataAssignment& a) {
  EdgeData& e = edges_[{a.tool, a.edge}];
  switch (a.parameter) {
    case 1:
      e.type = a.value;
      break;
    case 6:
      e.radius = a.value;
      break;
    case 15:
      e.wear = a.value;
      break;
    default:
      break;
  }
}

const EdgeData* ToolTable::find(std::int64_t tool, std::int64_t edge) const {
  auto it = edges_.find({tool, edge});
  return it == edges_.end() ? nullptr : &it->second;
}

ProgramReader::ProgramReader(std::istream& in, ModalState initial) : in_(in), state_(initial) {}

bool ProgramReader::next(Block& out) {
  while (std::getline(in_, text_)) {
    ++line_;
    parse_block_words(text_, line_, out.words);
    const BlockWords& w = out.words;
    bool empty = w.word_count == 0;
    if (empty) continue;  // blank or comment-only line
    if (end_line_ != 0)   // NC-END-1: nothing may follow M2/M30
      throw InputError(line_, 1, fmt::format("block after the end of the program (M2/M30 in line {})", end_line_));
    resolve(out);
    if (w.program_end) end_line_ = line_;
    return true;
  }
  if (in_.bad()) throw std::runtime_error("read error");
  return false;
}

void ProgramReader::resolve(Block& b) {
  const BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };

  for (int k = 0; k < w.tool_data_count; ++k) tools_.assign(w.tool_data[static_cast<std::size_t>(k)]);

  b.previous = state_;
  ModalState& s = state_;
  if (w.motion) s.motion = *w.motion;
  if (w.plane) s.plane = *w.plane;
  if (w.absolute) s.absolute = *w.absolute;
  if (w.side) s.side = *w.side;
  if (w.approach) s.approach = *w.approach;
  if (w.corner) s.corner = *w.corner;
  if (w.disc) s.disc = *w.disc;
  if (w.collision) s.collision = *w.collision;
  if (w.edge_strategy) s.edge_strategy = *w.edge_strategy;
  if (w.sar_side) s.sar_side = *w.sar_side;
  if (w.sar_segmentation) s.sar_segmentation = *w.sar_segmentation;
  if (w.feed_type) s.feed_type = *w.feed_type;
  if (w.path_mode) s.path_mode = *w.path_mode;
  if (w.feed) s.feed = *w.feed;
  if (w.offn) s.offn = *w.offn;
  // TOOL-EDGE-1/2: T selects the tool, D the edge; edge data are captured when T or D is
  // programmed, so a later $TC_DP write acts only from the next T or D.
  if (w.tool) s.tool = *w.tool;
  if (w.edge) s.edge = *w.edge;
  if (w.tool || w.edge) {
    const EdgeData* e = (s.tool != 0 && s.edge != 0) ? tools_.find(s.tool, s.edge) : nullptr;
    s.edge_defined = e != nullptr;
    s.edge_radius = e ? e->radius : Decimal{};
    s.edge_wear = e ? e->wear : Decimal{};
  }
  b.state = s;

  // NC-POS-1/2: G90/G91 modal, AC()/IC() per word; unprogrammed axes keep their position.
  b.start = position_;
  Point3 end = position_;
  for (int a = 0; a < 3; ++a) {
    const AxisWord& aw = w.axis[static_cast<std::size_t>(a)];
    if (!aw.present) continue;
    bool abs = aw.mode == ValueMode::kAbsolute || (aw.mode == ValueMode::kModal && s.absolute);
    Decimal& target = a == 0 ? end.x : a == 1 ? end.y : end.z;
    try {
      target = abs ? aw.value : target + aw.value;
    } catch (const std::overflow_error&) {
      fail("position out of range");
    }
  }
  b.end = end;

  // NC-ARC-1: I J K are incremental from the start point unless AC(); CR= gives the radius.
  bool has_centre = w.centre[0].present || w.centre[1].present || w.centre[2].present;
  b.centre.reset();
  // A SAR block is never a circle itself (SAR-BLOCK-1): its contour is generated, whatever G2/G3
  // is modally in force.
  b.circle = (s.motion == Motion::kArcCw || s.motion == Motion::kArcCcw) && !w.sar_contour &&
             (w.programs_any_axis() || has_centre || w.cr.has_value());
  if (has_centre || w.cr) {
    if (!b.is_arc()) fail("I, J, K or CR= programmed in a block without G2/G3");
    if (has_centre && w.cr) fail("an arc takes either I/J/K or CR=, not both");
  }
  if (b.is_arc()) {
    PlaneAxes pa = plane_axes(s.plane);
    if (w.centre[static_cast<std::size_t>(pa.applicate)].present)
      fail(fmt::format("{} is not a centre coordinate in the active plane", "IJK"[pa.applicate]));
    if (!has_centre && !w.cr) fail("G2/G3 needs the centre (I, J, K) or the radius (CR=)");
    if (has_centre) {
      Point3 c = b.start;
      for (int a : {pa.abscissa, pa.ordinate}) {
        const AxisWord& cw = w.centre[static_cast<std::size_t>(a)];
        Decimal& target = a == 0 ? c.x : a == 1 ? c.y : c.z;
        if (!cw.present) continue;
        target = cw.mode == ValueMode::kAbsolute ? cw.value : target + cw.value;
      }
      if (coord(c, pa.abscissa) == coord(b.start, pa.abscissa) && coord(c, pa.ordinate) == coord(b.start, pa.ordinate))
        fail("the circle centre lies on the start point (radius 0)");
      b.centre = c;
    }
  }
  position_ = end;
  b.index = index_++;
}

}  // namespace cutcom

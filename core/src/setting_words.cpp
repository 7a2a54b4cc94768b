// The words of a block beyond the plain ones (N, G0…G3, X Y Z, I J K, F): tool data and units,
// frames and poles, modal settings, dwell, SAR values, tool changes and cycles. resolve() leaves
// these steps out for a block read by read_plain_block, which holds none of their words: each
// take_*_words step acts on its words only. What acts on the reader's state alone stays in
// resolve, but for check_transmit_diameter, which both call (a PROC … SAVE return changes it).
#include <fmt/format.h>

#include <algorithm>

#include "cutcom/reader.hpp"

namespace cutcom {

const char* ProgramReader::transformation_name(Transformation t) {
  return t == Transformation::kTraori ? "TRAORI" : t == Transformation::kTransmit ? "TRANSMIT" : "TRAFOOF";
}

// TOOL-DATA-*, TOOL-NAME-1, NC-UNIT-1/2, NC-DIAM-*: the tables and units the block sets.
void ProgramReader::take_data_words(const BlockWords& w) {
  for (int k = 0; k < w.tool_data_count; ++k) tools_.assign(w.tool_data[static_cast<std::size_t>(k)]);
  for (int k = 0; k < w.tool_names_count; ++k) tools_.name(w.tool_names[static_cast<std::size_t>(k)]);
  if (w.units) units_ = *w.units;
  if (w.diameter) diameter_ = *w.diameter;
}

// NC-FRAME-*, NC-POLAR-1: a frame instruction or a pole.
void ProgramReader::take_frame_words(Block& b) {
  BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  if (w.frame) {
    if (w.motion || w.side || !w.not_simulated.empty())
      fail("a frame instruction (TRANS, SCALE, MIRROR, …) must stand in a block of its own");
    if (state_.side != Side::kOff)
      fail("a frame change with tool radius compensation G41/G42 in force: deselect with G40 first (not simulated)");
    try {
      apply_frame(w, w.plane ? *w.plane : state_.plane);
      refresh_programmed();
    } catch (const std::overflow_error&) {  // e.g. ASCALE repeated in a loop
      fail("the frame is out of range: its accumulated scale factor or translation is too large");
    }
  }
  if (w.cw().pole) {
    if (w.motion || w.frame) fail("a pole (G110/G111/G112) stands in a block without motion or frame words");
    set_pole(w, w.plane ? *w.plane : state_.plane);
  }
  if (w.cw().rpl && !(w.frame == FrameWord::kRot || w.frame == FrameWord::kArot)) fail("RPL= belongs to ROT or AROT");
}

// NC-WORD-13: which axis diameter programming means under TRANSMIT is the machine's data. Its
// state changes with words, and with the return from a PROC … SAVE: checked in every block.
void ProgramReader::check_transmit_diameter(const BlockWords& w) const {
  if (state_.transformation == Transformation::kTransmit && diameter_ != DiameterMode::kDiamof)
    throw InputError(w.line, 1,
                     "TRANSMIT with diameter programming (DIAMON, DIAM90) in force is SINUMERIK NC that cutcom does "
                     "not simulate: program DIAMOF before TRANSMIT");
}

// The modal settings, transformations, rotary axes, dwell, SAR values, tool change and cycles of
// the block; true when it switches TRANSMIT on or off (NC-WORD-13).
bool ProgramReader::take_modal_words(Block& b, ModalState& s) {
  BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  if (w.cw().circle_definition) circle_definition_ = *w.cw().circle_definition;
  if (w.cw().rndm) rounding_modal_ = length(*w.cw().rndm);  // NC-CONTOUR-2
  if (w.plane) s.plane = *w.plane, plane_programmed_ = true;
  if (w.absolute) s.absolute = *w.absolute;
  if (w.side) {
    s.side = *w.side;
    if (s.side != Side::kOff) ++s.selection;  // TRC-SIDE-2
  }
  // NC-WORD-8: a rotary axis with X, Y or Z. Without compensation X, Y and Z move as programmed
  // while it turns (a notice says what the path is not); with compensation it is 4/5-axis motion
  // along the contour, not simulated.
  // NC-WORD-11: under TRAORI X, Y, Z are the tool tip in the workpiece system whatever the rotary
  // axes do: without compensation they may move together in any block.
  bool transmit_switched = false;  // NC-WORD-13: where the tool is in the face's X, Y is not simulated
  if (w.transformation) {
    transmit_switched =
        (*w.transformation == Transformation::kTransmit) != (s.transformation == Transformation::kTransmit);
    if (s.side != Side::kOff)
      fail(fmt::format("{} while compensation is active is SINUMERIK NC that cutcom does not simulate",
                       transformation_name(*w.transformation)));
    s.transformation = *w.transformation;
    if (s.transformation == Transformation::kTransmit)
      note(b, "NC-WORD-13",
           "TRANSMIT: the path is the tool centre's in the face's cartesian X, Y as programmed (the machine turns "
           "the spindle's rotary axis for Y)");
  }
  check_transmit_diameter(w);
  if (!w.orientation_word.empty() && s.transformation != Transformation::kTraori)
    fail(fmt::format("{}= (the tool's orientation) is read under TRAORI, which is not in force", w.orientation_word));
  if (!w.rotary_with_plane.empty() && s.transformation == Transformation::kTraori) {
    if (s.side != Side::kOff)
      throw InputError(
          w.line, w.rotary_column,
          fmt::format("{} moving with X, Y or Z under TRAORI with compensation (the tool's orientation "
                      "changing along a compensated contour) is SINUMERIK NC that cutcom does not simulate",
                      w.rotary_with_plane));
    note(b, "NC-WORD-11",
         fmt::format("TRAORI: {} orients the tool while X, Y, Z move; the path is the tool tip's in the workpiece "
                     "system, as programmed",
                     w.rotary_with_plane));
  } else if (!w.rotary_with_plane.empty()) {
    if (s.side != Side::kOff)
      throw InputError(w.line, w.rotary_column,
                       fmt::format("the rotary axis {0} moving with X, Y or Z while compensation is active "
                                   "(4/5-axis motion along a compensated contour) is SINUMERIK NC that cutcom does not "
                                   "simulate; {0} alone, or with X, Y, Z without compensation, is kept as an action",
                                   w.rotary_with_plane));
    if (w.frame)  // TRANS X… B…: the frame's part for the rotary axis
      note(b, "NC-WORD-8",
           fmt::format("the frame's value for the rotary axis {} is kept as an action: the path's frame takes X, Y "
                       "and Z",
                       w.rotary_with_plane));
    else if (s.motion == Motion::kRapid)
      note(b, "NC-WORD-8",
           fmt::format("the rotary axis {} positions during this rapid move: the path shows X, Y and Z as programmed",
                       w.rotary_with_plane));
    else
      note(b, "NC-WORD-8",
           fmt::format("the rotary axis {} turns while X, Y and Z move: the path shows the linear axes as programmed, "
                       "not the cut on the turning workpiece or head",
                       w.rotary_with_plane));
  }
  if (w.repeats_from_start)
    note(b, "NC-PARAM-FLOW-7", "GOTOS: the control runs the program again from its start; the path shows one pass");
  if (w.synchronized_action)
    note(b, "NC-WORD-9",
         "the synchronized action acts while the program runs (outputs, overrides, variables); it moves no "
         "geometry axis, so the path is as programmed");
  if (w.approach) s.approach = *w.approach;
  if (w.corner) s.corner = *w.corner;
  if (w.disc) s.disc = *w.disc;
  if (w.collision) s.collision = *w.collision;
  if (w.edge_strategy) s.edge_strategy = *w.edge_strategy;
  if (w.sar_side) s.sar_side = *w.sar_side;
  if (w.sar_segmentation) s.sar_segmentation = *w.sar_segmentation;
  if (w.feed_type) s.feed_type = *w.feed_type;
  if (w.path_mode) s.path_mode = *w.path_mode;
  bool inch_feed = units_ == Units::kG700;
  if (inch_feed && w.contour) {  // NC-UNIT-1: G700 converts the feeds of roundings and chamfers too
    if (w.contour->frc) w.contour->frc = w.contour->frc->scaled(254, 10);
    if (w.contour->frcm) w.contour->frcm = w.contour->frcm->scaled(254, 10);
  }
  if (w.cw().frcm) corner_feed_modal_ = *w.cw().frcm;  // NC-CONTOUR-2
  if (w.dwell) {                                       // NC-WORD-4: G4 F… / G4 S… is a dwell, no feed
    if (w.programs_any_axis()) fail("G4 (dwell) must stand in a block without axis words");
    std::string text = w.feed ? fmt::format("G4 F{}", w.feed->to_string()) : "G4";
    w.feed.reset();
    for (int k = 0; k < w.aux_count; ++k) {  // G4 S…: spindle revolutions of dwell, not a speed
      std::string& t = w.aux[static_cast<std::size_t>(k)].text;
      if (w.aux[static_cast<std::size_t>(k)].address != 0 || t.empty() || (t[0] != 'S' && t[0] != 's')) continue;
      text += " " + t;
      std::rotate(w.aux.begin() + k, w.aux.begin() + k + 1, w.aux.begin() + w.aux_count);
      --w.aux_count;
      break;
    }
    AuxFunction a;
    a.address = 0, a.text = text;
    if (w.aux_count == BlockWords::kMaxAux) fail("too many actions in one block");
    w.aux[static_cast<std::size_t>(w.aux_count++)] = a;
  }
  if (w.fad && inch_feed) w.fad = w.fad->scaled(254, 10);
  if (w.offn) s.offn = length(*w.offn);
  if (w.disr) w.disr = length(*w.disr);
  if (w.discl.present || w.disrp.present) {  // along the infeed axis: its frame and offset only
    PlaneAxes pa = plane_axes(s.plane);
    std::size_t h = static_cast<std::size_t>(pa.applicate);
    if (frame_.factor[h] != Decimal::from_int(1))
      fail("DISCL/DISRP with a frame that scales or mirrors the infeed axis is not simulated");
    for (AxisWord* aw : {&w.discl, &w.disrp})
      if (aw->present) {
        aw->value = length(aw->value);
        if (aw->mode == ValueMode::kAbsolute)
          aw->value = aw->value + frame_.shift[h] + coord(offset_difference(), pa.applicate);
      }
  }
  change_tool(b, s);

  // NC-CYCLE-1/2: cycles and moves that cutcom does not simulate.
  if (w.modal_call_end) modal_call_ = false;
  if (w.modal_call) {
    modal_call_ = true;
    modal_cycle_ = w.not_simulated;
    note(b, "NC-CYCLE-2",
         fmt::format("MCALL {}: the cycle after each following move is not simulated", w.not_simulated));
  }
  if (!w.not_simulated.empty() && s.side != Side::kOff)
    fail(
        fmt::format("'{}' with tool radius compensation G41/G42 in force: a move cutcom does not simulate "
                    "cannot be compensated (deselect with G40 first)",
                    w.not_simulated));
  return transmit_switched;
}

}  // namespace cutcom

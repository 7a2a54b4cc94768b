// NC-MODAL-*, NC-POS-*, NC-UNIT-*, NC-OFFSET-*, NC-FRAME-*, NC-CYCLE-*, TOOL-*: modal resolution
// of blocks into exact positions in one coordinate system, and the tool data in force.
#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "contour_geometry.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

namespace {
// NC-CYCLE-1: the drilling cycles drill at the position they are called at and return to their
// retraction plane: only the infeed axis is left unknown.
bool is_drilling_cycle(const std::string& name) {
  static constexpr const char* kDrilling[] = {"CYCLE81", "CYCLE82", "CYCLE83", "CYCLE84", "CYCLE840",
                                              "CYCLE85", "CYCLE86", "CYCLE87", "CYCLE88", "CYCLE89"};
  for (const char* d : kDrilling)
    if (name == d) return true;
  return false;
}
}  // namespace

ProgramReader::ProgramReader(std::istream& in, ModalState initial)
    : in_(in), interpreter_(in, this), state_(initial), effective_(initial) {}

// The stages name their own values out of range (a position, a frame, a corner); this is the net
// behind them, so that no value beyond what cutcom holds exactly ends a run as an internal error.
template <typename Stage>
void ProgramReader::out_of_range_is_an_error(int line, Stage&& stage) {
  try {
    stage();
  } catch (const std::overflow_error&) {
    throw InputError(line, 1, "a value out of range: a position, offset or frame too large to hold exactly");
  }
}

bool ProgramReader::next(Block& out) {
  for (;;) {
    if (!ready_.empty()) {  // most blocks come straight from the text, not from here
      pop_ready(out);
      tool_tip_offset(out);
      return true;
    }
    if (!read_block(out)) {
      if (!pending_) return false;
      out_of_range_is_an_error(line_, [&] { finish_pending(nullptr); });
      continue;
    }
    if (!pending_ && !needs_contour_stage(out)) {
      out.index = index_++;
      tool_tip_offset(out);
      return true;
    }
    out_of_range_is_an_error(line_, [&] { contour_stage(out); });
  }
}

bool ProgramReader::read_block(Block& out) {
  while (!ended_ && (interpreter_.next_plain(out.words, line_) || interpreter_.next(text_, line_, &out.words))) {
    if (!interpreter_.in_subprogram()) {
      if (take_block(out, line_)) return true;
      continue;
    }
    // NC-PARAM-SUB-3: a subprogram's block is read and checked at its own line, so that an error
    // names it; it then carries the main program's calling line, as everything it produces.
    try {
      bool taken = take_block(out, interpreter_.current_line());
      out.words.line = line_;
      out.words.source = interpreter_.block_source();
      if (taken) return true;
      if (ended_) return false;
    } catch (const InputError& e) {
      throw interpreter_.where(e);
    }
  }
  if (in_.bad()) throw std::runtime_error("read error");
  return false;
}

bool ProgramReader::take_block(Block& out, int line) {
  if (!out.words.plain)  // else read by next()
    parse_block_words(text_, line, out.words, machine_cycles_, interpreter_.plain_refused());
  const BlockWords& w = out.words;
  if (w.word_count == 0) return false;  // blank, comment-only, header or label-only line
  if (end_line_ != 0 && interpreter_.uses_control_flow()) {
    ended_ = true;  // M30 ends the run (NC-PARAM-FLOW-1)
    return false;
  }
  if (end_line_ != 0)  // NC-END-1: nothing may follow M2/M30
    throw InputError(line, 1, fmt::format("block after the end of the program (M2/M30 in line {})", end_line_));
  out.notice.clear();
  out.notice_clause = {};
  out.insert = {};
  out_of_range_is_an_error(line, [&] { resolve(out); });
  if (w.program_end) end_line_ = line_;
  return true;
}

// A move given in polar coordinates only (AP=, RP=) without a pole word.
bool ProgramReader::polar_move(const BlockWords& w) {
  return (w.cw().ap.present || w.cw().rp.has_value()) && !w.cw().pole && !w.frame;
}

// NC-PARAM-SYS-2: the program writes a settable offset; it takes effect when an offset is
// selected (G54 …) next, as when it was given with --offsets.
namespace {
// One "$P_UIFR[n]…" line into `table`; an error without the table's source name (the program's
// line names it).
void load_assignment(OffsetTable& table, const std::string& assignment, const std::string& source) {
  std::istringstream in(assignment);
  try {
    table.load(in, source);
  } catch (const InputError& e) {
    std::string detail = e.detail();
    if (detail.rfind(source + ": ", 0) == 0) detail = detail.substr(source.size() + 2);
    throw InputError(0, 1, detail);
  }
}
}  // namespace

bool ProgramReader::write_settable_offset(const std::string& assignment) {
  load_assignment(offsets_, assignment, "$P_UIFR");
  return true;
}

// NC-PARAM-SYS-5: the program writes the settable frame in force ($P_IFRAME): a copy of the one in
// force with the assignment applied, selected at the next block as a G54 … would be.
bool ProgramReader::write_settable_frame(const std::string& assignment) {
  OffsetTable written;
  Point3 now = offsets_.translation(offset_index_);
  for (int a = 0; a < 3; ++a) written.set(1, a, coord(now, a));
  load_assignment(written, assignment, "$P_IFRAME");
  if (state_.side != Side::kOff)  // as a frame instruction (NC-FRAME-1)
    throw InputError(0, 1,
                     "a frame change with tool radius compensation G41/G42 in force: deselect with G40 first (not "
                     "simulated)");
  Point3 t = written.translation(1);
  for (int a = 0; a < 3; ++a) offsets_.set(kWrittenFrame, a, coord(t, a));
  written_frame_due_ = true;
  return true;
}

void ProgramReader::save_modal_state() {
  saved_.push_back({state_, units_, diameter_, offset_index_, frame_, circle_definition_});
}

// NC-PARAM-SUB-4: the modal G functions in force at the call come back, and with them the
// programmable frame and (if another one was selected) the settable offset. Not the tool
// radius compensation (group 7, decision 38), nor T, D, F or DISC, which are no G functions.
void ProgramReader::restore_modal_state() {
  if (saved_.empty()) return;
  SavedState s = std::move(saved_.back());
  saved_.pop_back();
  state_.motion = s.state.motion;
  state_.plane = s.state.plane;
  state_.absolute = s.state.absolute;
  state_.approach = s.state.approach;
  state_.corner = s.state.corner;
  state_.collision = s.state.collision;
  state_.edge_strategy = s.state.edge_strategy;
  state_.sar_side = s.state.sar_side;
  state_.sar_segmentation = s.state.sar_segmentation;
  state_.feed_type = s.state.feed_type;
  state_.path_mode = s.state.path_mode;
  units_ = s.units;
  diameter_ = s.diameter;
  circle_definition_ = s.circle_definition;
  bool frame_changed = s.frame.factor != frame_.factor || s.frame.shift != frame_.shift ||
                       s.frame.rotation != frame_.rotation || s.frame.rotation_axis != frame_.rotation_axis;
  if (frame_changed && state_.side != Side::kOff)  // as a programmed frame change (NC-FRAME-1)
    throw InputError(line_, 1,
                     "the return from a PROC … SAVE puts back another frame with tool radius compensation G41/G42 "
                     "in force: deselect with G40 first (not simulated)");
  bool offset_changed = offset_index_ != s.offset_index;
  if (offset_changed) select_offset(s.offset_index);
  frame_ = s.frame;
  as_written_due_ = true;
  if (frame_changed || offset_changed) refresh_programmed();
}

void ProgramReader::note(Block& b, std::string_view clause, std::string text) {
  if (!b.notice.empty()) {
    b.notice += "; ";
    b.notice += text;
    return;
  }
  b.notice_clause = clause;
  b.notice = std::move(text);
}

// NC-UNIT-1/2: a programmed length in mm on the 10^-9 grid.
Decimal ProgramReader::length(const Decimal& v) const {
  return (units_ == Units::kG70 || units_ == Units::kG700) ? v.scaled(254, 10) : v;
}

Decimal ProgramReader::to_base_framed(int axis, const AxisWord& aw, const Decimal& current, bool absolute,
                                      bool distance) const {
  std::size_t a = static_cast<std::size_t>(axis);
  Decimal scaled = frame_value(axis, aw, Decimal{}, absolute, distance).times(frame_.factor[a]);
  if (!absolute) return current + scaled;
  return coord(offset_difference(), axis) + frame_.shift[a] + scaled;
}

// TOOL-CHANGE-1/2, TOOL-NAME-1: which tool and edge are in force after the block's T, M6 and D.
void ProgramReader::change_tool(Block& b, ModalState& s) {
  const BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  std::optional<std::int64_t> t = w.tool;
  if (w.tool_name) {
    t = tools_.number_of(*w.tool_name);
    if (!t)
      fail(
          fmt::format("tool \"{0}\" is not in the tool table (give it with --tool \"{0}\"=RADIUS, its $TC_TP2 in "
                      "--tools FILE or in the program)",
                      *w.tool_name));
  }
  bool change = false;
  if (t) {
    if (s.md_change_on_m6) {
      preselected_ = *t;
    } else {
      s.tool = *t;
      change = true;
    }
  }
  if (w.tool_change && s.md_change_on_m6) {
    if (!preselected_) fail("M6 without a tool selected by T (MD22550 = 1: T selects, M6 changes)");
    s.tool = *preselected_;
    change = true;
  }
  if (w.edge) {
    s.edge = *w.edge;
  } else if (change) {  // TOOL-CHANGE-2: the edge MD20270 makes active on a tool change
    if (s.tool == 0 || s.md_edge_default == 0)
      s.edge = 0;
    else if (s.md_edge_default > 0)
      s.edge = s.md_edge_default;
  }
  // TOOL-SUM-1: a new edge brings MD20272's sum offset; DL in the block wins. The sum offsets act on
  // the lengths only (the tool tip stays on the programmed path): DL changes no radius.
  if (change || w.edge) s.sum_offset = s.edge == 0 ? 0 : s.md_sum_offset_default;
  if (w.sum_offset) s.sum_offset = s.edge == 0 ? 0 : *w.sum_offset;
  if (change || w.edge) {  // TOOL-EDGE-2: the edge data are taken now
    const EdgeData* e = (s.tool != 0 && s.edge != 0) ? tools_.find(s.tool, s.edge) : nullptr;
    s.edge_defined = e != nullptr;
    s.edge_radius = e ? e->radius : Decimal{};
    s.edge_wear = e ? e->wear : Decimal{};
    s.edge_position = edge_position_of(e, s, w.line);  // TOOL-TURN-1
  }
}

// MD-20150-2: the words that tell a lathe programmer why G17 is in force.
std::string ProgramReader::initial_plane_hint() const {
  if (plane_programmed_ || state_.plane != Plane::kG17) return "";
  return "; the program never selects a plane, so G17 is in force from the start: a lathe or grinding machine starts "
         "in G18, give it with --md 'MD20150[5]=2'";
}

// NC-WORD-12: under G33 … G332 (and in a G63 block) I, J, K are the thread's pitches, kept as
// actions; the block is a straight move. A thread under compensation is not simulated.
void ProgramReader::thread_block(Block& b, int thread) {
  BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };
  if (state_.side != Side::kOff)
    fail(
        fmt::format("thread cutting or tapping (G{}) with tool radius compensation G41/G42 in force is SINUMERIK "
                    "NC that cutcom does not simulate (deselect with G40 first)",
                    thread));
  for (int a = 0; a < 3; ++a) {
    AxisWord& pitch = w.centre[static_cast<std::size_t>(a)];
    if (!pitch.present) continue;
    if (w.aux_count == BlockWords::kMaxAux) fail("too many actions in one block");
    AuxFunction t;
    t.address = 0, t.text = fmt::format("{}{}", "IJK"[a], pitch.value.to_string());
    w.aux[static_cast<std::size_t>(w.aux_count++)] = t;
    pitch.present = false;
  }
  if (w.thread && w.programs_any_axis())
    note(b, "NC-WORD-12",
         fmt::format("G{}: {}; the path shows the straight move as programmed", thread,
                     thread == 63                     ? "tapping with a compensating chuck at the programmed feed"
                     : thread == 331 || thread == 332 ? "tapping at the pitch's feed"
                                                      : "thread cutting at the pitch's feed"));
}

void ProgramReader::resolve(Block& b) {
  BlockWords& w = b.words;
  auto fail = [&](const std::string& what) { throw InputError(w.line, 1, what); };

  // A plain block (read_plain_block: N, G0…G3, X Y Z, I J K, F, M, H) holds none of the words the
  // take_*_words steps read (setting_words.cpp): the reader's hot path leaves them out.
  if (!w.plain) take_data_words(w);
  if (offsets_changed_) select_offset(offset_index_);
  b.previous = effective_;
  ModalState& s = state_;
  std::optional<int> selected = w.settable_offset;
  if (written_frame_due_ && !selected) selected = kWrittenFrame;  // NC-PARAM-SYS-5
  written_frame_due_ = false;
  if (selected) {
    int idx = *selected;
    if (idx != offset_index_ && idx > 0) {
      if (first_offset_ < 0) {
        first_offset_ = idx;
        first_translation_ = offsets_.translation(idx);
        note(b, "NC-OFFSET-1",
             fmt::format("coordinates are in the workpiece system of {}",
                         idx == kWrittenFrame ? std::string("the frame written to $P_IFRAME")
                         : idx <= 4           ? fmt::format("G{}", idx + 53)
                                              : fmt::format("G{}", idx + 500)));
      } else if (!offsets_.defined(idx) || !offsets_.defined(first_offset_)) {
        note(b, "NC-OFFSET-1", "a second settable offset without --offsets data: taken as equal to the first");
      }
    }
    bool changed = idx != offset_index_ || idx == kWrittenFrame;
    select_offset(idx);
    if (changed) refresh_programmed();
  }
  if (!w.plain) take_frame_words(b);
  if (w.motion) circle_definition_.reset();
  if (w.motion) s.motion = *w.motion;
  bool tapping_block = w.thread && *w.thread == 63;  // NC-WORD-12: G63 is not modal
  if ((w.motion || w.cw().circle_definition) && !tapping_block) thread_ = w.thread ? *w.thread : 0;
  bool transmit_switched = false;  // NC-WORD-13: where the tool is in the face's X, Y is not simulated
  if (!w.plain)
    transmit_switched = take_modal_words(b, s);
  else
    check_transmit_diameter(w);
  if (w.feed) s.feed = units_ == Units::kG700 ? w.feed->scaled(254, 10) : *w.feed;  // NC-UNIT-1
  bool cycle = !w.not_simulated.empty() && !w.modal_call;                           // NC-CYCLE-1/2

  // The effective state of the block: a mirroring frame swaps G2/G3 and G41/G42 (NC-FRAME-3).
  ModalState& eff = b.state;  // built in place: the block's own copy is the one kept
  eff = s;
  if (tapping_block) eff.motion = Motion::kLinear;  // NC-WORD-12: G63 moves this block in a line
  // NC-POS-1/2: values as written (no frame, offset or unit conversion) also mirror nothing.
  if (!w.plain || as_written_due_) as_written_ = values_as_written(), as_written_due_ = false;
  {
    if (!as_written_ && mirrors_plane(s.plane)) {
      if (eff.motion == Motion::kArcCw)
        eff.motion = Motion::kArcCcw;
      else if (eff.motion == Motion::kArcCcw)
        eff.motion = Motion::kArcCw;
      if (eff.side == Side::kLeft)
        eff.side = Side::kRight;
      else if (eff.side == Side::kRight)
        eff.side = Side::kLeft;
      if (eff.sar_side == SarSide::kG141)  // SAR from the left / right: the same side of the contour
        eff.sar_side = SarSide::kG142;
      else if (eff.sar_side == SarSide::kG142)
        eff.sar_side = SarSide::kG141;
    }
  }
  effective_ = eff;

  // NC-POS-1/2: G90/G91 modal, AC()/IC() per word; unprogrammed axes keep their position.
  b.start = position_;
  b.end = position_;  // then written in place
  Point3& end = b.end;
  bool frame_values = w.frame.has_value() || w.cw().pole.has_value();  // the frame's or pole's values
  // The axes moved from an unknown position, as "XZ" (a fixed buffer: a string was built and
  // destroyed for every block, nearly always empty).
  char unknown_axes[3];
  std::size_t unknown_count = 0;
  for (int a = 0; a < 3; ++a) {
    std::size_t i = static_cast<std::size_t>(a);
    const AxisWord& aw = w.axis[i];
    bool abs = aw.mode == ValueMode::kAbsolute || (aw.mode == ValueMode::kModal && s.absolute);
    if (!aw.present || frame_values) {
      if (unknown_[i] && w.programs_any_axis() && !frame_values && !cycle) unknown_axes[unknown_count++] = "XYZ"[a];
      continue;
    }
    if (cycle) {  // a G53/G75/SUPA move: where it ends is not simulated
      unknown_[i] = true;
      continue;
    }
    Decimal& target = coord(end, a);
    try {
      target = to_base(a, aw, target, abs);
    } catch (const std::overflow_error&) {
      fail("position out of range");
    }
    if (unknown_[i]) {
      if (abs)
        unknown_[i] = false;
      else
        unknown_axes[unknown_count++] = "XYZ"[a];
    }
  }
  if (unknown_count != 0) {
    const std::string_view unknown_used(unknown_axes, unknown_count);
    PlaneAxes pa = plane_axes(s.plane);
    bool plane_unknown =
        unknown_[static_cast<std::size_t>(pa.abscissa)] || unknown_[static_cast<std::size_t>(pa.ordinate)];
    if (s.side != Side::kOff && plane_unknown)
      fail(
          fmt::format("the position of {} is not known since {} in line {}: program the plane axes absolutely "
                      "before compensating",
                      unknown_used, unknown_after_, unknown_line_));
    if (unknown_line_ != 0) {
      note(b, "NC-CYCLE-1",
           fmt::format("the position of {} is not known since {} in line {}: the move starts where the tool was "
                       "before it",
                       unknown_used, unknown_after_, unknown_line_));
      unknown_line_ = 0;  // said once per unknown stretch
    }
  }
  if (transmit_switched) {  // NC-WORD-13: the rotary axis' angle turns X into X and Y
    unknown_[0] = unknown_[1] = true;
    unknown_after_ = transformation_name(*w.transformation);
    unknown_line_ = w.line;
  }
  if (cycle) {
    note(b, "NC-CYCLE-1",
         fmt::format("{} is not simulated: its motion is not in the path, and the position stays unknown until the "
                     "axes are programmed absolutely",
                     w.not_simulated));
    if (is_drilling_cycle(w.not_simulated))  // it drills where it stands and ends at its retraction plane
      unknown_[static_cast<std::size_t>(plane_axes(s.plane).applicate)] = true;
    else if (w.not_simulated[0] != 'G' && w.not_simulated != "SUPA")
      unknown_ = {true, true, true};
    unknown_after_ = w.not_simulated;
    unknown_line_ = w.line;
    // Its axis words were the cycle's, not a move.
    for (AxisWord& aw : w.axis) aw.present = false;
  } else if (modal_call_ && !w.modal_call && w.programs_any_axis()) {
    if (is_drilling_cycle(modal_cycle_))
      unknown_[static_cast<std::size_t>(plane_axes(s.plane).applicate)] = true;
    else
      unknown_ = {true, true, true};
  }
  if (w.modal_call) {  // one notice for the whole modal call
    unknown_after_ = "MCALL " + modal_cycle_;
    unknown_line_ = w.line;
  }
  if (frame_values)
    for (AxisWord& aw : w.axis) aw.present = false;                        // NC-FRAME-1: the frame's values, not a move
  if (w.programs_any_axis() || polar_move(w)) interpreter_.block_moved();  // NC-PARAM-SUB-6: MCALL

  if (int thread = tapping_block ? 63 : thread_; thread != 0) thread_block(b, thread);  // NC-WORD-12
  // NC-ARC-1: I J K are incremental from the start point unless AC(); CR= gives the radius.
  bool has_centre = w.centre[0].present || w.centre[1].present || w.centre[2].present;
  b.centre.reset();
  // A SAR block is never a circle itself (SAR-BLOCK-1): its contour is generated, whatever G2/G3
  // is modally in force.
  bool polar = (w.cw().ap.present || w.cw().rp.has_value()) && !w.cw().pole;
  bool defined_circle = circle_definition_.has_value() || w.cw().ar.has_value() || polar;
  b.circle = (s.motion == Motion::kArcCw || s.motion == Motion::kArcCcw || circle_definition_) && !w.sar_contour &&
             !tapping_block &&
             (w.programs_any_axis() || has_centre || w.cr.has_value() || w.cw().ar.has_value() || polar);
  if (has_centre || w.cr) {
    if (!b.is_arc()) fail("I, J, K or CR= programmed in a block without G2/G3");
    if (has_centre && w.cr) fail("an arc takes either I/J/K or CR=, not both");
  }
  if (b.is_arc()) {
    PlaneAxes pa = plane_axes(s.plane);
    if (w.centre[static_cast<std::size_t>(pa.applicate)].present)
      fail(fmt::format("{} is not a centre coordinate in the active plane{}", "IJK"[pa.applicate],
                       initial_plane_hint()));
    // MD-20150-2: an arc in X and Z, in G17 from the start and without Y: a lathe program whose
    // machine starts in G18. The helix it is in G17 is drawn; the notice says how to run it.
    if (!plane_programmed_ && !lathe_hint_given_ && s.plane == Plane::kG17 && w.axis[2].present && !w.axis[1].present &&
        !w.centre[1].present) {
      lathe_hint_given_ = true;
      note(b, "MD-20150-2",
           fmt::format("G2/G3 with Z in G17 turns in X/Y and moves Z (a helix){}", initial_plane_hint()));
    }
    if (!has_centre && !w.cr && !defined_circle) fail("G2/G3 needs the centre (I, J, K) or the radius (CR=)");
    Decimal fa = frame_.factor[static_cast<std::size_t>(pa.abscissa)];
    Decimal fo = frame_.factor[static_cast<std::size_t>(pa.ordinate)];
    if (fa != fo && fa != -fo)
      fail("a circle under a frame that scales the plane axes differently is an ellipse: not simulated");
    if (w.cr) {
      w.cr = length(*w.cr).times(fa.sign() < 0 ? -fa : fa);
    }
    if (has_centre) {
      Point3 c = b.start;
      for (int a : {pa.abscissa, pa.ordinate}) {
        const AxisWord& cw = w.centre[static_cast<std::size_t>(a)];
        Decimal& target = coord(c, a);
        if (!cw.present) continue;
        // I=AC() is a position; incremental I is a distance (a radius value also under DIAMON).
        bool abs = cw.mode == ValueMode::kAbsolute;
        target = to_base(a, cw, target, abs, !abs);
      }
      if (coord(c, pa.abscissa) == coord(b.start, pa.abscissa) && coord(c, pa.ordinate) == coord(b.start, pa.ordinate))
        fail("the circle centre lies on the start point (radius 0)");
      b.centre = c;
    }
  }
  bool defined = false;
  try {
    defined = plane_definition(b, eff);
  } catch (const contour::ContourError& e) {
    fail(e.what);
  } catch (const std::domain_error&) {
    fail("the contour definition has no solution (a quantity that must not be 0 is 0)");
  } catch (const std::overflow_error&) {
    fail("position out of range");
  }
  // Outside a rotated frame the frame's position is its inverse image, taken only when needed.
  if (!defined && frame_.rotated())
    update_programmed(w, s.absolute);
  else if (!defined)
    programmed_known_ = false;
  if (w.cw().turn && *w.cw().turn > 0 && (!b.is_arc() || !b.centre))
    fail("TURN= needs a circle given by its centre (I, J, K, AR= with the centre, or a polar circle)");
  if (b.moves_in_plane()) {  // CT continues from here
    last_element_.start = b.start, last_element_.end = b.end, last_element_.centre = b.centre;
    last_element_.circle = b.circle, last_element_.state.plane = s.plane, last_element_.state.motion = b.state.motion;
    last_element_.words.cr = w.cr;
    last_element_valid_ = true;
  }
  position_ = b.end;
}

}  // namespace cutcom

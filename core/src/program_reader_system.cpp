// NC-PARAM-SYS-1/3: the system variables a program reads of the machine's state ($P_TOOLR,
// $P_EP, $P_GG, $TC_DP…, the run's mode), as of the blocks read so far.
#include <cmath>
#include <numbers>

#include "cutcom/reader.hpp"

namespace cutcom {

// NC-PARAM-SYS-1: what a program may read of the machine's state, as of the blocks read so far.
std::optional<double> ProgramReader::system_value(std::string_view n, const std::vector<NcValue>& idx) {
  bool inch = units_ == Units::kG70 || units_ == Units::kG700;
  auto in_units = [&](const Decimal& v) { return inch ? v.to_double() / 25.4 : v.to_double(); };
  if (n == "$P_TOOLR") return in_units(state_.edge_radius + state_.edge_wear);
  if (n == "$PI") return std::numbers::pi;          // NC-PARAM-SYS-1: the constant, as the control's REAL
  if (n == "$P_F") return state_.feed.to_double();  // the feed programmed last (F)
  if (n == "$P_OFFN") return in_units(state_.offn);
  if (n == "$P_TOOLNO") return static_cast<double>(state_.tool);
  if (n == "$P_TOOL") return static_cast<double>(state_.edge);
  if (n == "$P_EP" || n == "$AA_IW") {
    if (idx.size() != 1 || idx[0].type != NcValue::Type::kString || idx[0].text.size() != 1) return std::nullopt;
    int axis = idx[0].text[0] - 'X';
    if (axis < 0 || axis > 2) return std::nullopt;
    if (!programmed_known_) refresh_programmed(), programmed_known_ = true;
    return in_units(coord(programmed_, axis));
  }
  if (n == "$P_PFRAME" || n == "$P_UIFR" || n == "$P_IFRAME") return frame_component(n, idx);  // NC-PARAM-FRAME-2
  if (n == "$P_UIFRNUM" && idx.empty()) return static_cast<double>(offset_gcode_);
  if (n == "$P_GG" && idx.size() == 1 && idx[0].type != NcValue::Type::kString) return g_group_value(idx[0].number);
  // NC-PARAM-SYS-3: cutcom shows a normal run: no block search, no program test, no dry run, not
  // the control's own simulation; the tool programmed last.
  if (idx.empty() && (n == "$P_SEARCH" || n == "$P_SEARCHL" || n == "$P_ISTEST" || n == "$P_DRYRUN" || n == "$P_SIM"))
    return 0.0;
  if (n == "$P_TOOLP" && idx.empty())
    return static_cast<double>(state_.md_change_on_m6 && preselected_ ? *preselected_ : state_.tool);
  // $P_TOOLL[n]: the active edge's length n (1 … 3) with its wear, $TC_DP3..5 + $TC_DP12..14.
  if (n == "$P_TOOLL" && idx.size() == 1 && idx[0].type != NcValue::Type::kString) {
    double v = idx[0].number;
    if (!(v == 1 || v == 2 || v == 3)) return std::nullopt;
    int k = static_cast<int>(v);
    if (state_.edge == 0) return 0.0;
    const EdgeData* e = tools_.find(state_.tool, state_.edge);
    if (!e) return std::nullopt;
    return in_units(e->values[static_cast<std::size_t>(2 + k)] + e->values[static_cast<std::size_t>(11 + k)]);
  }
  bool active = n == "$P_AD" && idx.size() == 1;  // the active edge's parameter: $TC_DPn[T, D]
  if ((n.substr(0, 6) == "$TC_DP" && idx.size() == 2) || active) {
    int k = 0;
    if (active) {
      double v = idx[0].number;  // (checked before the cast: a huge index is no int)
      if (idx[0].type == NcValue::Type::kString || v != std::trunc(v) || !(v >= 1 && v <= 25)) return std::nullopt;
      k = static_cast<int>(v);
      if (state_.edge == 0) return 0.0;  // D0: no offset in force
    }
    for (char c : active ? std::string_view() : n.substr(6)) {
      if (c < '0' || c > '9' || k > 25) return std::nullopt;  // past 25 no parameter (nor an overflow)
      k = k * 10 + (c - '0');
    }
    const EdgeData* e = active ? tools_.find(state_.tool, state_.edge)
                               : tools_.find(std::llround(idx[0].number), std::llround(idx[1].number));
    if (!e || k < 1 || k > 25) return std::nullopt;
    return e->values[static_cast<std::size_t>(k)].to_double();  // as assigned; 0 if never
  }
  return std::nullopt;
}

// NC-PARAM-SYS-1: $P_GG[group], the G function in force as its number within the group (the
// manual's list of G function groups; the first of a group is 1). Only groups cutcom models.
std::optional<double> ProgramReader::g_group_value(double group) const {
  auto number = [](auto e) { return static_cast<double>(static_cast<int>(e) + 1); };
  switch (group >= 0 && group <= 1000 && std::trunc(group) == group ? static_cast<int>(group) : -1) {
    case 1:  // G0 G1 G2 G3 CIP … CT
      if (circle_definition_) return *circle_definition_ == CircleDefinition::kCip ? 5.0 : 15.0;
      if (thread_ != 0)  // G33 10, G331 11, G332 12, G34 16, G35 17
        return thread_ == 33 ? 10.0 : thread_ == 331 ? 11.0 : thread_ == 332 ? 12.0 : thread_ == 34 ? 16.0 : 17.0;
      return number(state_.motion);
    case 6:  // G17 G18 G19
      return number(state_.plane);
    case 7:  // G40 G41 G42
      return number(state_.side);
    case 8:  // G500 G54 … G57 G505 … G599
      return static_cast<double>(offset_gcode_ + 1);
    case 13:  // G70 G71 G700 G710
      return units_ == Units::kG70 ? 1.0 : units_ == Units::kG71 ? 2.0 : units_ == Units::kG700 ? 3.0 : 4.0;
    case 14:  // G90 G91
      return state_.absolute ? 1.0 : 2.0;
    case 15:  // G93 G94 G95
      return state_.feed_type == FeedType::kG93 ? 1.0 : state_.feed_type == FeedType::kG94 ? 2.0 : 3.0;
    case 17:  // NORM KONT KONTT KONTC
      return state_.approach == ApproachMode::kNorm    ? 1.0
             : state_.approach == ApproachMode::kKont  ? 2.0
             : state_.approach == ApproachMode::kKontT ? 3.0
                                                       : 4.0;
    case 18:  // G450 G451
      return number(state_.corner);
    case 29:  // DIAMOF DIAMON DIAM90
      return number(diameter_);
    case 40:  // CDOF CDON CDOF2
      return number(state_.collision);
    case 43:  // G140 G141 G142 G143
      return number(state_.sar_side);
    case 44:  // G340 G341
      return number(state_.sar_segmentation);
    case 48:  // G460 G461 G462
      return number(state_.edge_strategy);
    default:
      return std::nullopt;
  }
}

}  // namespace cutcom

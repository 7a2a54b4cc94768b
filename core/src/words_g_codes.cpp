// NC-LEX-3, NC-WORD-4/5, NC-OFFSET-1, NC-POLAR-1: the G codes cutcom reads, and their groups.
#include "word_lexer.hpp"

namespace cutcom::lexer {

void WordLexer::g_code(std::size_t at) {
  skip_space();
  std::int64_t g = integer("G");
  auto group = [&](auto& slot, auto value, const char* group_name) {
    if (slot) fail(fmt::format("two G codes of the {} group in one block", group_name), at);
    slot = value;
  };
  auto action = [&](unsigned grp, const char* group_name) {
    g_group(grp, group_name, at);
    add_text_action(fmt::format("G{}", g), at);
  };
  BlockWords& o = out_;
  switch (g) {
    case 0:
      if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
      return group(o.motion, Motion::kRapid, "motion");
    case 1:
      if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
      return group(o.motion, Motion::kLinear, "motion");
    case 2:
      if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
      return group(o.motion, Motion::kArcCw, "motion");
    case 3:
      if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
      return group(o.motion, Motion::kArcCcw, "motion");
    case 33:
    case 34:
    case 35:
    case 331:
    case 332:  // NC-WORD-12: thread cutting and tapping: a straight move (the pitch is the reader's)
      if (o.cw().circle_definition) fail("two G codes of the motion group in one block", at);
      group(o.motion, Motion::kLinear, "motion");
      o.thread = static_cast<int>(g);
      return add_text_action(fmt::format("G{}", g), at);
    case 63:  // NC-WORD-12: tapping with a compensating chuck, a straight move in this block only
      g_group(kGroupDwell, "non-modal (G4/G25/G26/G63/G74/G75)", at);
      o.thread = 63;
      return add_text_action("G63", at);
    case 4:  // NC-WORD-4: dwell; its F or S is the time or the revolutions
      g_group(kGroupDwell, "non-modal (G4/G25/G26/G74/G75)", at);
      o.dwell = true;
      return;
    case 9:  // NC-WORD-5: exact stop for this block
      return action(kGroupExactStop, "exact stop (G9)");
    case 17:
      return group(o.plane, Plane::kG17, "plane");
    case 18:
      return group(o.plane, Plane::kG18, "plane");
    case 19:
      return group(o.plane, Plane::kG19, "plane");
    case 40:
      return group(o.side, Side::kOff, "tool radius compensation");
    case 41:
      return group(o.side, Side::kLeft, "tool radius compensation");
    case 42:
      return group(o.side, Side::kRight, "tool radius compensation");
    case 53:
    case 153:  // NC-CYCLE-1: a move in machine coordinates is not simulated
      g_group(kGroupSuppression, "frame suppression (G53/G153)", at);
      o.not_simulated = fmt::format("G{}", g);
      return;
    case 60:
      g_group(kGroupPathMode, "exact stop / continuous path", at);
      return group(o.path_mode, PathMode::kG60, "exact stop / continuous path");
    case 64:
    case 641:
    case 642:
    case 643:
    case 644:
    case 645:  // NC-WORD-5: continuous path modes
      g_group(kGroupPathMode, "exact stop / continuous path", at);
      o.path_mode = PathMode::kG64;
      if (g != 64) add_text_action(fmt::format("G{}", g), at);
      return;
    case 601:
    case 602:
    case 603:
      return action(kGroupStopWindow, "exact stop window (G601/G602/G603)");
    case 62:
    case 621:  // NC-WORD-7: the feed slows at (inside) corners; the path is the same
      return action(kGroupCornerFeed, "corner deceleration (G62/G621)");
    case 290:  // NC-WORD-7: the SINUMERIK dialect, which cutcom reads (G291, ISO dialect: not simulated)
      return action(kGroupDialect, "dialect (G290/G291)");
    case 70:
      g_group(kGroupUnits, "units", at);
      o.units = Units::kG70;
      return;
    case 71:
      g_group(kGroupUnits, "units", at);
      o.units = Units::kG71;
      return;
    case 700:
      g_group(kGroupUnits, "units", at);
      o.units = Units::kG700;
      return;
    case 710:
      g_group(kGroupUnits, "units", at);
      o.units = Units::kG710;
      return;
    case 25:
    case 26:  // NC-WORD-8: spindle speed limits (with S); NC-WORD-7: with axes after it, the working area
      g_group(kGroupDwell, "non-modal (G4/G25/G26/G74/G75)", at);
      for (const AxisWord& a : o.axis)
        if (a.present) fail(area_limit_message(static_cast<int>(g)), at);
      area_limit_ = static_cast<int>(g);
      return add_text_action(fmt::format("G{}", g), at);
    case 74:
    case 75:  // NC-CYCLE-1: reference point / fixed point approach
      g_group(kGroupDwell, "non-modal (G4/G25/G26/G74/G75)", at);
      o.not_simulated = fmt::format("G{}", g);
      return;
    case 90:
      return group(o.absolute, true, "dimensions");
    case 91:
      return group(o.absolute, false, "dimensions");
    case 93:
      g_group(kGroupFeedType, "feed type", at);
      o.feed_type = FeedType::kG93;
      return add_text_action("G93", at);
    case 94:
    case 961:
    case 971:
      g_group(kGroupFeedType, "feed type", at);
      o.feed_type = FeedType::kG94;
      if (g != 94) add_text_action(fmt::format("G{}", g), at);
      return;
    case 95:
    case 96:
    case 97:
      g_group(kGroupFeedType, "feed type", at);
      o.feed_type = FeedType::kG95;
      if (g != 95) add_text_action(fmt::format("G{}", g), at);
      return;
    case 140:
      return group(o.sar_side, SarSide::kG140, "SAR side");
    case 141:
      return group(o.sar_side, SarSide::kG141, "SAR side");
    case 142:
      return group(o.sar_side, SarSide::kG142, "SAR side");
    case 143:
      return group(o.sar_side, SarSide::kG143, "SAR side");
    case 147:
      return group(o.sar_contour, SarContour::kG147, "SAR contour");
    case 148:
      return group(o.sar_contour, SarContour::kG148, "SAR contour");
    case 247:
      return group(o.sar_contour, SarContour::kG247, "SAR contour");
    case 248:
      return group(o.sar_contour, SarContour::kG248, "SAR contour");
    case 347:
      return group(o.sar_contour, SarContour::kG347, "SAR contour");
    case 348:
      return group(o.sar_contour, SarContour::kG348, "SAR contour");
    case 340:
      return group(o.sar_segmentation, SarSegmentation::kG340, "SAR segmentation");
    case 341:
      return group(o.sar_segmentation, SarSegmentation::kG341, "SAR segmentation");
    case 110:
    case 111:
    case 112:  // NC-POLAR-1: the pole
      return group(o.cw_set().pole, g == 110 ? PoleWord::kG110 : g == 111 ? PoleWord::kG111 : PoleWord::kG112, "pole");
    case 450:
      return group(o.corner, CornerMode::kG450, "outer corner");
    case 451:
      return group(o.corner, CornerMode::kG451, "outer corner");
    case 460:
      return group(o.edge_strategy, EdgeStrategy::kG460, "approach/retraction (group 48)");
    case 461:
      return group(o.edge_strategy, EdgeStrategy::kG461, "approach/retraction (group 48)");
    case 462:
      return group(o.edge_strategy, EdgeStrategy::kG462, "approach/retraction (group 48)");
    default:
      break;
  }
  // NC-OFFSET-1: settable work offsets.
  if (g == 500 || (g >= 54 && g <= 57) || (g >= 505 && g <= 599)) {
    g_group(kGroupOffset, "settable work offset", at);
    o.settable_offset = g == 500 ? 0 : g <= 57 ? static_cast<int>(g - 53) : static_cast<int>(g - 500);
    return;
  }
  // NC-LEX-3: a G code of the ISO dialect only (G291; Fanuc-like controls) most likely means a
  // program posted for another control: said so, rather than "not simulated".
  static constexpr int kIsoOnly[] = {10, 20, 21, 28, 30, 43, 44, 49, 65, 66, 67, 68, 69, 73,
                                     76, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 98, 99};
  if (std::find(std::begin(kIsoOnly), std::end(kIsoOnly), g) != std::end(kIsoOnly))
    fail(fmt::format("'G{}' is a G code of the ISO dialect (G291), not of the SINUMERIK dialect cutcom reads: is "
                     "this a program for another control?",
                     g),
         at);
  fail(unsupported_message(fmt::format("G{}", g)), at);
}

}  // namespace cutcom::lexer

// A generated contour program: what the generators draw and how it is written as NC text.
// Coordinates are integers (micrometres unless `decimals` says otherwise): exact decimal text.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace cutcom::props {

struct Step {
  std::int64_t dx = 0, dy = 0;  // in-plane move of one contour block, um
  bool g451 = false;            // corner mode programmed in this block
  int dummies = 0;              // blocks without plane motion before this block (Z moves, M functions)
  bool arc = false;             // G2/G3 instead of G1
  bool ccw = false;             // G3
  std::int64_t ci = 0, cj = 0;  // centre relative to the block's start (I, J in the plane)
  std::int64_t cr = 0;          // != 0: the circle is written with CR= instead
  bool flip = false;            // the block changes G41 <-> G42 (TRC-SIDE-1)
  bool again = false;           // the block programs the same G41/G42 again (TRC-SIDE-2)
  // NC-CONTOUR-1: 1 RND, 2 CHR, 3 CHF at the block's end corner, of `corner_value` (case units).
  int corner = 0;
  std::int64_t corner_value = 0;
  bool polar = false;  // NC-POLAR-2: a straight block written as AP= RP= about the workpiece zero
};

// A smooth approach in the selection block and/or a smooth retraction in the deselection block
// (spec SAR-*). Levels are in the same units as the coordinates.
struct SarEnds {
  bool approach = false, retraction = false;
  int contour_in = 147, contour_out = 148;  // 147/247/347, 148/248/348
  int side_in = 140, side_out = 140;        // G140 ... G143
  int seg_in = 340, seg_out = 340;          // G340 / G341
  std::int64_t disr_in = 0, disr_out = 0;
  bool discl_in = false, discl_out = false;
  bool discl_in_ac = false, discl_out_ac = false;
  std::int64_t discl_in_v = 0, discl_out_v = 0;
  bool fad_in = false;
  std::int64_t start_h = 0;  // applicate of the start position (P0 of the approach)
  std::int64_t end_h = 0;    // applicate programmed in the retraction block (case 3)
  int p4_mode = 0;           // approach: 0 P4 in the SAR block; 1 its Z there, X Y next block; 2 all next block
  int end_case = 3;          // retraction: 1 no axis, 2 applicate only, 3 plane axes and applicate, 4 plane axes only
  bool deselect = true;      // G40 in the retraction block
  bool follow = false;       // a rapid move of the applicate after the retraction (SAR-END-1/3: where it starts)
};

struct ContourCase {
  std::int64_t radius_um = 2000;                    // $TC_DP6 in um (0 and negative values included)
  bool right = false;                               // G42 instead of G41
  std::int64_t start_x = 0, start_y = 0;            // tool position before the selection block
  std::int64_t first_x = 0, first_y = 0;            // end of the selection block = start of the contour
  std::vector<Step> steps;                          // the contour blocks
  std::int64_t end_x = 0, end_y = 0;                // end point of the G40 block
  int plane = 17;                                   // 17, 18 or 19
  int decimals = 3;                                 // coordinates and radius in units of 10^-decimals mm
  int md20210 = 100, md20230 = 10;                  // degrees
  bool kont_select = false, kont_deselect = false;  // KONT instead of NORM in the G41/G42 and G40 blocks
  bool g451_select = false, g451_deselect = false;  // corner mode programmed in those blocks
  int edge_select = 462, edge_deselect = 462;       // G460 / G461 / G462 in those blocks
  bool cdon = false;                                // CDON instead of CDOF in the G41/G42 block
  int md20240 = 3;                                  // blocks in the look-ahead / collision window
  static constexpr int kMd20250 = 5;                // MD20250's default: written only where a case differs
  int md20250 = kMd20250;                           // blocks without plane motion in a row (TRC-DUMMY-2)
  std::string style;                                // which generator made it (for RC_TAG)
  SarEnds sar;                                      // smooth approach / retraction (SAR-*)
  // A variant of the program for the rules of selection, deselection and the blocks between
  // (the campaign draws them: the properties keep well-formed programs). See kVariantNames.
  int variant = 0;
  std::int64_t rotation_mdeg = 0;  // NC-FRAME-4: ROT RPL= (millidegrees) after the first block
  // The contour blocks move in the plane only, without actions, G0 ends, G95 or a D change
  // (PROP-DIFF-3 and TRC-RADIUS-3 vary the programs so): for properties that scale the program,
  // run it reversed or reason about its heights.
  bool plane_only = false;
};

// Names of ContourCase::variant: 0 "none", then one rule each (TRC-SEL-3 ... TRC-DUMMY-3,
// SAR-DISRP-1/2, SAR-STOP-1, SAR-AGAIN-1).
inline constexpr const char* kVariantNames[] = {"none",
                                                "one-plane-axis",
                                                "select-without-plane-axis",
                                                "d0",
                                                "no-tool",
                                                "edge-without-data",
                                                "plane-change",
                                                "deselect-in-circle",
                                                "deselect-without-plane-axis",
                                                "disc",
                                                "too-many-dummies",
                                                "standing-block",
                                                "disrp-above",
                                                "disrp-below",
                                                "stopre-before-direction",
                                                "sar-again"};
inline constexpr int kVariants = 16;
inline constexpr int kSarVariants = 12;  // variants from here on change a SAR approach

std::string to_program(const ContourCase& c);
// PROP-PARAM-1: the same program written parametrically: every coordinate and every CR=, DISR=,
// DISCL=, RND=, CHF= value an expression that returns it through binary64, the contour inside
// an IF that holds and a FOR loop that runs once.
std::string to_parametric_program(const std::string& plain);
std::string fixed(std::int64_t units, int decimals);  // fixed(12345, 3) = "12.345"

// The same contour run backwards (PROP-META-6, PROP-SAR-3): side swapped, start and end
// positions swapped, the approach and retraction settings swapped, circles about the same centre.
ContourCase reversed_contour(const ContourCase& c);

void showValue(const ContourCase& c, std::ostream& os);

}  // namespace cutcom::props

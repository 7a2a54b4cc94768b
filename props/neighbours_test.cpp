// The neighbours of a user's program (`cutcom certify --from`): what they move.
#include "neighbours.hpp"

#include <gtest/gtest.h>

namespace cutcom::props {
namespace {

// covers: PROP-FROM-1
TEST(Neighbours, MoveValuesBySmallStepsAndOntoTies) {
  const std::string program =
      "$TC_DP6[1,1]=2 ; radius\nN10 G0 X0 Y0 T1 D1\nN20 G1 G41 X10 Y0 F500\nN30 X10.5 Y7 ; X10 here\n"
      "N40 G3 X20 Y7 CR=5\nN50 G40 X30 Y0\n";
  MachineData md;
  int changed = 0, ties = 0, machine = 0;
  for (long k = 1; k <= 200; ++k) {
    Neighbour n = neighbour_of(program, md, 7, k);
    EXPECT_EQ(n.text, neighbour_of(program, md, 7, k).text);  // reproducible
    if (n.text != program) ++changed;
    // Only numbers after addresses move: the comments, N numbers, T, D and F stay as written.
    EXPECT_NE(n.text.find("; radius\n"), std::string::npos);
    EXPECT_NE(n.text.find("N20 G1 G41 "), std::string::npos);
    EXPECT_NE(n.text.find(" T1 D1"), std::string::npos);
    EXPECT_NE(n.text.find(" F500"), std::string::npos);
    if (n.text.find("N30 X10 Y7") != std::string::npos) ++ties;  // X10.5 onto the X10 before it
    if (n.change.find("MD20") != std::string::npos) ++machine;
  }
  EXPECT_GT(changed, 190);
  EXPECT_GT(ties, 0);
  EXPECT_EQ(machine, 50);  // every fourth
  // A step of 10^-9 mm is written exactly.
  bool nano = false;
  for (long k = 1; k <= 200 && !nano; ++k)
    nano = neighbour_of(program, md, 7, k).text.find(".000000001") != std::string::npos ||
           neighbour_of(program, md, 7, k).text.find(".999999999") != std::string::npos;
  EXPECT_TRUE(nano);
}

}  // namespace
}  // namespace cutcom::props

// Machine and setting data a parametric program reads, and the machine's initial plane
// (NC-PARAM-SYS-4, MD-20150-2).
#include <sstream>

#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"
#include "parametric_support.hpp"

namespace cutcom::test {
namespace {

// covers: NC-PARAM-SYS-4 MD-20150-2
TEST(Parametric, MachineAndSettingDataReadByTheirNames) {
  MachineData md;
  md.set_assignment("$MN_HW_SERIAL_NUMBER=\"SN-42\"");
  md.set_assignment("$mc_axconf_geoax_name_tab[ 1 ] = 7.5");
  md.set("$SC_TOOL_LENGTH_CONST", "17");
  md.set("MD20210", "120");
  auto last_x = [&](const std::string& text) {
    std::istringstream in(text);
    ProgramReader reader(in);
    reader.set_machine_values(md.program_values());
    Block b, last;
    while (reader.next(b)) last = b;
    return last.end.x.to_string();
  };
  EXPECT_EQ(last_x("IF $MN_HW_SERIAL_NUMBER<>\"SN-42\"\nG1 X1 F100\nELSE\nG1 X2 F100\nENDIF\n"), "2");
  EXPECT_EQ(last_x("R1=1\nG1 X=$MC_AXCONF_GEOAX_NAME_TAB[R1]*2+$SC_TOOL_LENGTH_CONST F100\n"), "32");
  // A datum cutcom models reads its value, by its name.
  EXPECT_EQ(last_x("G1 X=$MC_CUTCOM_CORNER_LIMIT F100\n"), "120");
  // ISVAR: a datum with a value, with or without its index.
  EXPECT_EQ(
      last_x(
          "G1 X=ISVAR(\"$MC_AXCONF_GEOAX_NAME_TAB\")+ISVAR(\"$MN_HW_SERIAL_NUMBER\")*2+ISVAR(\"$MN_NONE\")*4 F100\n"),
      "3");
  // One without a value, or with another index: an error that says how to give it.
  EXPECT_EQ(error_line("G1 X0 F100\nR1=$MN_SCALING_VALUE_INCH\n", "--md '$MN_SCALING_VALUE_INCH=VALUE'"), 2);
  EXPECT_EQ(error_line("R1=$SA_WORKAREA_PLUS_ENABLE[X]\n", "setting data that cutcom has no value for"), 1);
  EXPECT_THROW(md.set("$MN_X", "abc"), MachineDataError);
  EXPECT_THROW(md.set("$MQ_X", "1"), MachineDataError);
  // MD20150[5]: the plane at the start (G18 on a lathe): G2 in X and Z is then a circle.
  MachineData lathe;
  lathe.set("$MC_GCODE_RESET_VALUES[5]", "2");
  EXPECT_EQ(lathe.initial_state().plane, Plane::kG18);
  EXPECT_EQ(MachineData().initial_state().plane, Plane::kG17);
  EXPECT_THROW(lathe.set("MD20150[5]", "4"), MachineDataError);
  // A program that never selects a plane and turns in X and Z is told how to run on a lathe.
  auto first_arc_notice = [](const std::string& text) {
    std::istringstream in(text);
    ProgramReader reader(in);
    Block b;
    while (reader.next(b))
      if (b.is_arc()) return b.notice;
    return std::string();
  };
  EXPECT_NE(first_arc_notice("G0 X60 Z5\nG2 X30 Z-5 CR=30 F100\n").find("--md 'MD20150[5]=2'"), std::string::npos);
  EXPECT_EQ(first_arc_notice("G17 G0 X60 Z5\nG2 X30 Z-5 CR=30 F100\n"), "");
  EXPECT_EQ(first_arc_notice("G0 X60 Y5\nG2 X30 Y-5 Z1 CR=30 F100\n"), "");
  EXPECT_EQ(error_line("G0 X60 Z5\nG2 X40 Z-5 I0 K-10 F100\n", "a lathe or grinding machine starts in G18"), 2);
}

}  // namespace
}  // namespace cutcom::test

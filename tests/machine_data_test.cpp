#include "cutcom/machine_data.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "cutcom/alarm.hpp"

namespace cutcom {
namespace {

// covers: MD-20202-1 MD-20204-1 MD-20210-1 MD-20220-1 MD-20230-1 MD-20240-1 MD-20250-1 MD-20150-1
TEST(MachineData, DefaultsOfTheRulings) {
  MachineData md;
  EXPECT_EQ(md.wab_maxnum_dummy_blocks, 5);
  EXPECT_EQ(md.wab_clearance_tolerance, *Decimal::parse("0.01").value);
  EXPECT_EQ(md.cutcom_corner_limit, Decimal::from_int(100));
  EXPECT_EQ(md.cutcom_max_disc, Decimal::from_int(50));
  EXPECT_EQ(md.cutcom_curve_insert_limit, Decimal::from_int(10));
  EXPECT_EQ(md.cutcom_maxnum_check_blocks, 3);
  EXPECT_EQ(md.cutcom_maxnum_dummy_blocks, 5);
  EXPECT_EQ(md.initial_state().edge_strategy, EdgeStrategy::kG462);
}

TEST(MachineData, SetByNumberOrNameAndValidated) {
  MachineData md;
  md.set_assignment("MD20204=0.02");
  EXPECT_EQ(md.wab_clearance_tolerance, *Decimal::parse("0.02").value);
  md.set("$mc_cutcom_maxnum_check_blocks", " 7 ");
  EXPECT_EQ(md.cutcom_maxnum_check_blocks, 7);
  md.set("MD20150[47]", "2");
  EXPECT_EQ(md.initial_state().edge_strategy, EdgeStrategy::kG461);
  EXPECT_THROW(md.set("MD20210", "181"), MachineDataError);
  EXPECT_THROW(md.set("MD20240", "0"), MachineDataError);
  EXPECT_THROW(md.set("MD20240", "2.5"), MachineDataError);
  EXPECT_THROW(md.set("MD20204", "-1"), MachineDataError);
  EXPECT_THROW(md.set("MD99999", "1"), MachineDataError);
  EXPECT_THROW(md.set_assignment("MD20204"), MachineDataError);
  // The message says what is wrong with a number: out of range, too many decimals, not a number.
  auto message = [&](const char* name, const char* value) {
    try {
      md.set(name, value);
    } catch (const MachineDataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("MD20240", "99999999999999").find("out of range (1 .. 50)"), std::string::npos);
  EXPECT_NE(message("MD20204", "0.0000000001").find("more than nine decimals"), std::string::npos);
  EXPECT_NE(message("MD20204", "x").find("is not a decimal number"), std::string::npos);
}

TEST(MachineData, FileErrorsNameTheLine) {
  MachineData md;
  std::istringstream in("# machine\nMD20210 = 120 ; corner limit\n\nMD20230=abc\n");
  try {
    md.load(in, "m.md");
    ADD_FAILURE();
  } catch (const MachineDataError& e) {
    EXPECT_NE(std::string(e.what()).find("m.md:4"), std::string::npos) << e.what();
  }
  EXPECT_EQ(md.cutcom_corner_limit, Decimal::from_int(120));
}

// covers: MD-FILE-1
TEST(MachineData, AnArchiveOfTheControlIsReadAsItIsWritten) {
  MachineData md;
  std::istringstream in(
      "%_N_CH_TEA_INI\nCHANDATA(1)\n$MC_CHAN_NAME=\"CHAN1\"\n$MC_CUTCOM_CORNER_LIMIT=95.\n"
      "$MC_CUTCOM_MAXNUM_CHECK_BLOCKS='H0A'\n$MN_SOME_MASK='B101'\n$MA_JOG_VELO[AX1]=2000\nM17\n");
  md.load(in, "TEA.INI");
  EXPECT_EQ(md.cutcom_corner_limit, Decimal::from_int(95));
  EXPECT_EQ(md.cutcom_maxnum_check_blocks, 10);  // 'H0A'
  EXPECT_EQ(md.readable.at("$MN_SOME_MASK"), "5");
  EXPECT_EQ(md.readable.at("$MC_CHAN_NAME"), "\"CHAN1\"");
  auto error = [](const std::string& text) {
    MachineData m;
    std::istringstream file(text);
    try {
      m.load(file, "TEA.INI");
    } catch (const MachineDataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Two channels' data in one archive: which runs the program cannot be told.
  EXPECT_NE(
      error("CHANDATA(1)\nMD20210=90\nCHANDATA(2)\nMD20210=80\n").find("TEA.INI:3: CHANDATA(2) after CHANDATA(1)"),
      std::string::npos);
  // With the channel named, its data are read (and what stands before any CHANDATA).
  MachineData second;
  std::istringstream both("MD20240=4\nCHANDATA(1)\nMD20210=90\nCHANDATA(2)\nMD20210=80\n");
  second.load(both, "TEA.INI", 2);
  EXPECT_EQ(second.cutcom_corner_limit, Decimal::from_int(80));
  EXPECT_EQ(second.cutcom_maxnum_check_blocks, 4);
  MachineData third;
  std::istringstream none("CHANDATA(1)\nMD20210=90\n");
  try {
    third.load(none, "TEA.INI", 3);
    ADD_FAILURE() << "channel 3 read from an archive of channel 1";
  } catch (const MachineDataError& e) {
    EXPECT_NE(std::string(e.what()).find("no data of channel 3"), std::string::npos) << e.what();
  }
  EXPECT_NE(error("$MN_X='H1G'\n").find("TEA.INI:1: 'H1G' is not a hexadecimal constant"), std::string::npos);
  EXPECT_NE(error("$MN_X='B12'\n").find("is not a binary constant"), std::string::npos);
}

// covers: ALARM-1
TEST(Alarms, CatalogueNamesTheRaisingClause) {
  const AlarmInfo* a = find_alarm(10751);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->clause, "TRC-ELEMENT-1");
  EXPECT_TRUE(a->number_confirmed);
  EXPECT_EQ(find_alarm(12345), nullptr);
  Alarm x = make_alarm(10751, 12, 50);
  EXPECT_NE(x.text.find("N50"), std::string::npos);
}

}  // namespace
}  // namespace cutcom

// The command line as a user meets it: exit status, formats, stdin, machine data, errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli_shell.hpp"

using namespace cutcom::cli_test;

namespace {

// covers: CLI-1 PATH-ORIGIN-1
TEST(Cli, JsonOfTheExampleHasTheDocumentedShape) {
  for (const char* engine : {"fast", "ref"}) {
    Result r = sh(kCli + " run " + kExample + " --format json --engine " + engine);
    ASSERT_EQ(r.status, 0) << engine;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["engine"], engine);
    ASSERT_GT(j["path"].size(), 10u);
    bool saw_arc = false;
    for (const auto& e : j["path"]) {
      EXPECT_TRUE(e["type"] == "line" || e["type"] == "arc");
      EXPECT_TRUE(e["rapid"].is_boolean());
      EXPECT_EQ(e["start"].size(), 3u);
      EXPECT_EQ(e["end"].size(), 3u);
      EXPECT_TRUE(e["line"].is_number_integer());
      EXPECT_TRUE(e["origin"]["kind"].is_string());
      if (e["type"] == "arc") {
        saw_arc = true;
        EXPECT_EQ(e["center"].size(), 3u);
        EXPECT_TRUE(e["ccw"].is_boolean());
      }
    }
    EXPECT_TRUE(saw_arc);
    EXPECT_TRUE(j["alarms"].empty());
  }
}

// --stage-times: each thread's processor time on standard error, the output as without it.
// covers: CLI-1
TEST(Cli, StageTimesGoToStandardErrorAndLeaveTheOutputAlone) {
  const std::regex stage(R"((reader\+engine|writer) (\d+\.\d{3}) s,)");
  for (const char* format : {"text", "json", "svg"}) {
    std::string run = kCli + " run " + kExample + " --format " + format;
    Result plain = sh(run), timed = sh(run + " --stage-times");
    ASSERT_EQ(timed.status, 0) << format;
    EXPECT_EQ(timed.out, plain.out) << format;
    std::string err = sh_err(run + " --stage-times").out;
    std::vector<std::string> stages;
    for (auto m = std::sregex_iterator(err.begin(), err.end(), stage); m != std::sregex_iterator(); ++m)
      stages.push_back((*m)[1]);
    // The picture is drawn on the engine's thread: no writer's of its own.
    std::vector<std::string> expected = {"reader+engine", "writer"};
    if (std::string(format) == "svg") expected.pop_back();
    EXPECT_EQ(stages, expected) << err;
    EXPECT_NE(err.find("elapsed"), std::string::npos) << err;
  }
  EXPECT_EQ(sh_err(kCli + " run " + kExample).out, "");  // nothing without the flag
}

// covers: CLI-1 ALARM-1
TEST(Cli, AlarmGivesExitOneWithThePathBeforeIt) {
  std::string p =
      write_temp("alarm.mpf", "$TC_DP6[1,1]=2\nN10 T1 D1 G1 F1\nN20 G41 X0 Y0\nN30 X10\nN40 Y1\nN50 X0\nN60 G40 X-5\n");
  Result r = sh(kCli + " run " + p + " --format json");
  EXPECT_EQ(r.status, 1);
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["alarms"].size(), 1u);
  EXPECT_EQ(j["alarms"][0]["number"], 10751);
  EXPECT_EQ(j["alarms"][0]["line"], 7);  // the look-ahead found nothing up to the G40 block
  EXPECT_EQ(j["path"].size(), 1u);       // the approach; N30's end was never fixed
}

// covers: CLI-1 NC-ERR-1
TEST(Cli, BadInputAndUsageGiveExitTwo) {
  EXPECT_EQ(sh(kCli + " run " + write_temp("bad.mpf", "G1 X1\nQ7\n")).status, 2);
  EXPECT_EQ(sh(kCli + " run /nonexistent.mpf").status, 2);
  EXPECT_EQ(sh(kCli + " run " + kExample + " --md MD20210=500").status, 2);
  EXPECT_EQ(sh(kCli + " run " + kExample + " --format pdf").status, 2);
  EXPECT_EQ(sh(kCli + " frobnicate").status, 2);
  EXPECT_EQ(sh(kCli + " run " + write_temp("kont.mpf", "$TC_DP6[1,1]=1\nT1 D1 G1 G41 KONTT X1 F1\nX2\n")).status,
            2);  // not supported yet
}

// covers: CLI-1 NC-WORD-2
TEST(Cli, SkipLevelsFromTheCommandLine) {
  std::string program = write_temp("skip.mpf", "G0 X0 Y0\n/G0 X10\n/2 G0 Y10\nM30\n");
  auto elements = [&](const std::string& options) {
    Result r = sh(kCli + " run " + program + " --format json" + options);
    EXPECT_EQ(r.status, 0) << options;
    return r.status == 0 ? nlohmann::json::parse(r.out)["path"].size() : 0u;
  };
  EXPECT_EQ(elements(""), 2u);  // skip levels off: every block runs
  EXPECT_EQ(elements(" --skip 0"), 1u);
  EXPECT_EQ(elements(" --skip 0 --skip 2"), 0u);
  EXPECT_EQ(sh(kCli + " run " + program + " --skip 10").status, 2);
}

// covers: NC-CYCLE-3 CLI-1
TEST(Cli, MachineCyclesFromTheCommandLine) {
  std::string program = write_temp("toolchange.mpf", "G0 X0 Y0 Z50\nT1 D1\nL6\nG0 X10 Y0 Z5\nG1 Y10 F100\nM30\n");
  Result refused = sh(kCli + " run " + program + " --tool 1=3", true);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.out.find("--machine-cycle L6"), std::string::npos) << refused.out;
  for (const char* name : {"L6", "l6"}) {
    Result r = sh(kCli + " run " + program + " --tool 1=3 --format json --machine-cycle " + name);
    ASSERT_EQ(r.status, 0) << name;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["path"].size(), 3u);
    EXPECT_NE(j["notices"].dump().find("L6 is not simulated"), std::string::npos) << j["notices"].dump();
  }
  EXPECT_EQ(sh(kCli + " run " + program + " --machine-cycle 'L 6'").status, 2);
}

// covers: CLI-1 PATH-ORIGIN-1
TEST(Cli, StdinMachineDataAndSvg) {
  Result a = sh("printf 'G0 X1\\nG1 Y2 F5\\n' | " + kCli + " run - --format json");
  ASSERT_EQ(a.status, 0);
  EXPECT_EQ(nlohmann::json::parse(a.out)["path"].size(), 2u);
  // MD20210 = 130 keeps the 128 degree corner of the example as an intersection: one circle less.
  auto circles = [](const std::string& out) {
    int n = 0;
    const auto j = nlohmann::json::parse(out);  // kept alive: the loop walks into it
    for (const auto& e : j["path"]) n += e["type"] == "arc";
    return n;
  };
  Result d = sh(kCli + " run " + kExample + " --format json");
  Result m = sh(kCli + " run " + kExample + " --format json --md MD20210=130");
  EXPECT_EQ(circles(m.out), circles(d.out) - 1);
  Result s = sh(kCli + " run " + kExample + " --format svg");
  EXPECT_EQ(s.status, 0);
  EXPECT_NE(s.out.find("<svg"), std::string::npos);
  EXPECT_NE(s.out.find("transition circle"), std::string::npos);
  Result t = sh(kCli + " run " + kExample + " --trace");
  EXPECT_NE(t.out.find("TRC-CORNER-1"), std::string::npos);
}

// covers: NC-PARAM-SYS-4
TEST(Cli, SystemVariablesTheProgramReadsAreGivenOnTheCommandLine) {
  const std::string program =
      "printf 'IF $A_IN[1]==1\\nG1 X1 F100\\nELSE\\nG1 X2 F100\\nENDIF\\n"
      "G1 Y=$MN_SCALING_VALUE_INCH\\nM30\\n' | ";
  Result missing = sh(program + kCli + " run -", true);
  EXPECT_NE(missing.out.find("--sysvar '$A_IN[1]=VALUE'"), std::string::npos) << missing.out;
  Result given = sh(program + kCli + " run - --format json --sysvar '$a_in[1]=1' --md '$MN_SCALING_VALUE_INCH=25.4'");
  ASSERT_EQ(given.status, 0);
  const auto path = nlohmann::json::parse(given.out)["path"];
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[0]["end"][0], 1.0);
  EXPECT_EQ(path[1]["end"][1], 25.4);
  // A bad name or value, or machine data through --sysvar: exit 2, named.
  for (const char* bad : {"'A_IN=1'", "'$A_IN[1]=x'", "'$MC_CUTCOM_CORNER_LIMIT=1'"}) {
    Result r = sh(program + kCli + " run - --sysvar " + bad, true);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.out.find("--sysvar"), std::string::npos) << r.out;
  }
}

// A long program's picture keeps polylines within a stated bound (memory bounded); a short one
// is drawn element by element.
// covers: CLI-1
TEST(Cli, ALongProgramsPictureIsReducedAndSaysSo) {
  const std::string dir = CUTCOM_BINARY_DIR;
  {
    std::ofstream p(dir + "/long-picture.mpf");
    p << "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.5\nT1 D1 F1000\nG0 X0 Y-5\nG1 G41 X0 Y0\n";
    for (int k = 0; k < 12000; ++k)  // a zigzag along X with half circles: 24,000 blocks
      p << "G1 X" << 4 * k + 2 << " Y0\nG3 X" << 4 * k + 4 << " Y0 CR=1\n";
    p << "G40 G1 X" << 4 * 12000 + 5 << " Y-5\nM30\n";
  }
  Result s = sh(kCli + " run " + dir + "/long-picture.mpf --format svg");
  ASSERT_EQ(s.status, 0);
  EXPECT_NE(s.out.find("detail reduced for a long program: 48002 path elements and 24003 programmed segments<"),
            std::string::npos)
      << s.out.substr(0, 2000);
  EXPECT_NE(s.out.find("mm of the exact path"), std::string::npos);
  EXPECT_NE(s.out.find("the label of one programmed segment in 128 where labels do not cover one another"),
            std::string::npos);
  EXPECT_EQ(s.out.find("<title>"), std::string::npos);  // no per-element titles
  EXPECT_LT(s.out.size(), 8u << 20);
  Result small = sh(kCli + " run " + kExample + " --format svg");
  EXPECT_EQ(small.out.find("detail reduced"), std::string::npos);
  EXPECT_NE(small.out.find("<title>"), std::string::npos);
}

}  // namespace

namespace {
// covers: TRC-SEL-7 CLI-1
TEST(Cli, AnEdgeWithoutToolDataPointsToTheToolTable) {
  // A real program keeps its tool data in the control: without --tools, T1 D1 has none (17181),
  // and the message says where it comes from; with the tool file the same program runs.
  std::string program =
      write_temp("no_tool_data.mpf", "G17 G0 X-10 Y-10\nT1 D1\nG41 G1 X0 Y0 F100\nX20\nG40 X30 Y-10\n");
  Result r = sh(kCli + " run " + program, true);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("--tools FILE"), std::string::npos) << r.out;
  std::string tools = write_temp("no_tool_data.ini", "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n");
  EXPECT_EQ(sh(kCli + " run " + program + " --tools " + tools).status, 0);
}

// covers: TRACE-1
TEST(Cli, TheTraceRecordsEveryDecisionWithItsMargin) {
  // Both engines trace the same decisions of the example (clause, line, branch); fast gives its
  // margin as a number, ref as an exact decimal string, and the two agree in sign.
  Result f = sh(kCli + " run " + kExample + " --format json --trace --engine fast");
  Result r = sh(kCli + " run " + kExample + " --format json --trace --engine ref");
  ASSERT_EQ(f.status, 0);
  ASSERT_EQ(r.status, 0);
  const auto fj = nlohmann::json::parse(f.out), rj = nlohmann::json::parse(r.out);
  const auto& fd = fj["decisions"];
  const auto& rd = rj["decisions"];
  ASSERT_GT(fd.size(), 5u);
  ASSERT_EQ(fd.size(), rd.size());
  int margins = 0;
  for (std::size_t i = 0; i < fd.size(); ++i) {
    EXPECT_EQ(fd[i]["clause"], rd[i]["clause"]) << i;
    EXPECT_EQ(fd[i]["line"], rd[i]["line"]) << i;
    EXPECT_EQ(fd[i]["branch"], rd[i]["branch"]) << i;
    if (!rd[i].contains("margin_exact")) continue;
    ++margins;
    ASSERT_TRUE(fd[i].contains("margin")) << i;
    const std::string exact = rd[i]["margin_exact"];
    const double m = fd[i]["margin"];
    if (exact[0] == '-') {
      EXPECT_LT(m, 0) << fd[i]["clause"];
    } else if (exact != "0") {
      EXPECT_GT(m, 0) << fd[i]["clause"];
    }
  }
  EXPECT_GT(margins, 3);
}

}  // namespace

namespace {
// covers: SAR-VAR-1 CLI-1
TEST(Cli, SarVariablesInEveryFormat) {
  const std::string example = CUTCOM_SOURCE_DIR "/examples/sar-quadrant.mpf";
  for (const char* engine : {"fast", "ref"}) {
    Result j = sh(kCli + " run " + example + " --format json --engine " + engine);
    ASSERT_EQ(j.status, 0) << engine;
    auto doc = nlohmann::json::parse(j.out);
    ASSERT_EQ(doc["variables"].size(), 1u);
    const auto& v = doc["variables"][0];
    EXPECT_EQ(v["line"], 12);
    EXPECT_EQ(v["$P_APDV"], 1);
    EXPECT_EQ(v["$P_APR"], nlohmann::json::array({5, 15, 0}));  // P3 of the manual's contour example 2
    EXPECT_EQ(v["$P_AEP"], nlohmann::json::array({30, -10, 0}));
    bool saw_element = false;
    for (const auto& e : doc["path"]) saw_element = saw_element || e["origin"].value("sar", "") == "element";
    EXPECT_TRUE(saw_element);
  }
  Result t = sh(kCli + " run " + example);
  EXPECT_NE(t.out.find("$P_APR=(5.0000, 15.0000, 0.0000) $P_AEP=(30.0000, -10.0000, 0.0000) $P_APDV=1"),
            std::string::npos);
  Result s = sh(kCli + " run " + example + " --format svg");
  EXPECT_NE(s.out.find(">P3 L12<"), std::string::npos);
  EXPECT_NE(s.out.find(">P4 L12<"), std::string::npos);
  EXPECT_NE(s.out.find("side view"), std::string::npos);
}
}  // namespace

namespace {

// CORE (ref's numbers) writes a warning to "Core_Diagnostics" in the working directory where its
// floating-point filter sees a negative root argument or a zero divisor, and ends the process
// (exit 1, no path) where that file cannot be written. Near-tangent offsets give both: a root of
// an exactly positive number whose double is negative (the corpus program), and a KONT approach
// from behind nearly along the contour's way back, whose corner trim divides by nearly 0.
// covers: TRC-KONT-4
TEST(Cli, RefWritesNoFileInTheWorkingDirectory) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(CUTCOM_BINARY_DIR) / "ref-working-directory";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string kont = write_temp("kont-along-the-way-back.mpf",
                                "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\n"
                                "N10 G17 G90 G0 X20 Y-0.000000001 T1 D1\n"
                                "N20 G1 G41 KONT G451 X10 Y0 F500\nN30 X30 Y0\nN40 Y20\nN50 G40 X40 Y30\nM30\n");
  const std::string cases[] = {
      std::string(CUTCOM_SOURCE_DIR) + "/tests/corpus/rounding-with-the-tool-outside-offsets-cross-by-1e-21.mpf",
      kont + " --md MD20210=180"};
  for (const std::string& c : cases) {
    Result r = sh("cd " + dir.string() + " && " + kCli + " run --engine ref " + c);
    EXPECT_EQ(r.status, 0) << c;
    EXPECT_NE(r.out.find("path elements"), std::string::npos) << c;
    EXPECT_FALSE(fs::exists(dir / "Core_Diagnostics")) << c;
  }
  // The second one's approach meets the extended equidistant (TRC-KONT-4), both engines alike.
  Result fast = sh(kCli + " run " + kont + " --md MD20210=180");
  Result ref = sh(kCli + " run --engine ref " + kont + " --md MD20210=180");
  EXPECT_NE(ref.out.find("(-39999999990.0000, 2.0000, 0.0000) approach N20"), std::string::npos) << ref.out;
  EXPECT_EQ(fast.out.substr(fast.out.find('\n')), ref.out.substr(ref.out.find('\n')));
}
}  // namespace

namespace {

// covers: CLI-1 TOOL-FILE-1 NC-OFFSET-2 NC-CYCLE-1 NC-FRAME-3 TRC-DESEL-3 NC-CONTOUR-1 NC-CONTOUR-2
TEST(Cli, TheExampleJobRunsWithItsToolTableAndOffsets) {
  const std::string job = CUTCOM_SOURCE_DIR "/examples/job/";
  std::string args = " run " + job + "PLATE.MPF --tools " + job + "TO_INI.INI --offsets " + job +
                     "UFR.INI --md MD22550=1 --format json";
  for (const char* engine : {"fast", "ref"}) {
    Result r = sh(kCli + args + " --engine " + engine);
    ASSERT_EQ(r.status, 0) << engine;
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["unit"], "mm");
    EXPECT_GT(j["path"].size(), 40u);
    bool cycle_noticed = false;
    for (const auto& n : j["notices"])
      cycle_noticed |= n["text"].get<std::string>().find("CYCLE81") != std::string::npos;
    EXPECT_TRUE(cycle_noticed);
    bool msg = false;
    for (const auto& a : j["actions"]) msg |= a["function"] == "MSG(\"Drilling\")";
    EXPECT_TRUE(msg);
    int roundings = 0, chamfers = 0;  // RND and RNDM at 9 corners, CHR at 3, each offset once
    for (const auto& el : j["path"]) {
      if (!el["origin"].contains("inserted") || el["origin"]["kind"] != "offset") continue;
      roundings += el["origin"]["inserted"] == "rounding";
      chamfers += el["origin"]["inserted"] == "chamfer";
    }
    EXPECT_EQ(roundings, 9) << engine;
    EXPECT_EQ(chamfers, 3) << engine;
  }
  // Without the tool table the named tool is unknown: exit 2, naming it.
  Result e = sh_err(kCli + " run " + job + "PLATE.MPF --md MD22550=1");
  EXPECT_EQ(e.status, 2);
  EXPECT_NE(e.out.find("tool \"ROUGH_D16\" is not in the tool table"), std::string::npos) << e.out;
}

// covers: TOOL-FILE-2
// An archive of two channels: refused without --channel, naming the file and line; with it, the
// channel's tools are the ones in force.
// covers: MD-FILE-1 TOOL-FILE-1
TEST(Cli, TheChannelPicksItsDataFromAnArchiveOfSeveral) {
  std::string program = write_temp("channel.mpf", "T1 D1\nG0 X-10 Y-10\nG1 G41 X0 Y0 F500\nX40\nG40 X50 Y-10\nM30\n");
  std::string tools = write_temp("two-channels.ini",
                                 "%_N_TO_INI\nCHANDATA(1)\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4\nM17\n"
                                 "CHANDATA(2)\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=6\nM17\n");
  Result both = sh_err(kCli + " run " + program + " --tools " + tools);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.out.find("two-channels.ini:6:1: CHANDATA(2) after CHANDATA(1) in line 2"), std::string::npos)
      << both.out;
  EXPECT_NE(both.out.find("--channel N"), std::string::npos) << both.out;
  for (const auto& [channel, y] : {std::pair{"1", 4.0}, std::pair{"2", 6.0}}) {
    Result r = sh(kCli + " run --format json " + program + " --tools " + tools + " --channel " + channel);
    ASSERT_EQ(r.status, 0) << r.out;
    bool offset = false;  // the offset of X40 runs the channel's radius beside it
    const nlohmann::json j = nlohmann::json::parse(r.out);
    for (const auto& el : j["path"]) offset |= el["origin"]["kind"] == "offset" && el["start"][1].get<double>() == y;
    EXPECT_TRUE(offset) << "channel " << channel << ": " << r.out;
  }
  Result missing = sh_err(kCli + " run " + program + " --tools " + tools + " --channel 3");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.out.find("no data of channel 3"), std::string::npos) << missing.out;
  // `cutcom md` lists what an archive and --md give, as `run` takes them.
  std::string data = write_temp("two-channels-md.ini",
                                "%_N_CH_TEA_INI\nCHANDATA(1)\n$MC_CUTCOM_CORNER_LIMIT=95\nM17\n"
                                "CHANDATA(2)\n$MC_CUTCOM_CORNER_LIMIT=85\nM17\n");
  Result listed = sh(kCli + " md --md-file " + data + " --channel 2 --md MD20240=7");
  ASSERT_EQ(listed.status, 0) << listed.out;
  auto row = [&](const std::string& id) {
    std::size_t at = listed.out.find(id + " ");
    return at == std::string::npos ? std::string() : listed.out.substr(at, listed.out.find('\n', at) - at);
  };
  EXPECT_NE(row("MD20210").find("= 85 "), std::string::npos) << listed.out;
  EXPECT_NE(row("MD20240").find("= 7 "), std::string::npos) << listed.out;
  EXPECT_EQ(sh_err(kCli + " md --md-file " + data).status, 2);
}

TEST(Cli, AToolEdgeGivenOnTheCommandLine) {
  std::string program = write_temp("named_tool.mpf",
                                   "T=\"FLAT 10\" D1\nM6\nG0 X-10 Y-10\nG1 G41 X0 Y0 F500\nX40\nY30\n"
                                   "G40 X50 Y40\nM30\n");
  Result r = sh(kCli + " run --format json --tool '\"FLAT 10\"=5' " + program);
  ASSERT_EQ(r.status, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  bool offset_by_5 = false;  // the offset of X40 runs 5 mm beside it
  for (const auto& el : j["path"])
    offset_by_5 |= el["origin"]["kind"] == "offset" && el["start"][1].get<double>() == 5.0;
  EXPECT_TRUE(offset_by_5) << r.out;
  Result bad = sh_err(kCli + " run --tool 'FLAT=wide' " + program);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--tool 'FLAT=wide', column 6: 'wide' is not a radius"), std::string::npos) << bad.out;
  Result unknown = sh_err(kCli + " run " + program);
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.out.find("--tool \"FLAT 10\"=RADIUS"), std::string::npos) << unknown.out;
  // A turning tool from the command line: the lathe example with --tool instead of its archive.
  const std::string turning = CUTCOM_SOURCE_DIR "/examples/turning/";
  std::string lathe = kCli + " run " + turning + "SHAFT.MPF --md 'MD20150[5]=2' --format json";
  Result archive = sh(lathe + " --tools " + turning + "TO_INI.INI");
  Result given = sh(lathe + " --tool '\"FINISH_R04\"=0.4,3' --tool '\"FACE_R02\"=0.2,8'");
  ASSERT_EQ(given.status, 0) << given.out;
  EXPECT_EQ(nlohmann::json::parse(given.out)["path"], nlohmann::json::parse(archive.out)["path"]);
}

// covers: CLI-1 NC-PARAM-SUB-8 NC-PARAM-FLOW-1
TEST(Cli, AProgramPipedInJumpsBackAndCallsItsUnits) {
  // A loop (a backward jump) and a call of a unit of the same text, read from standard input.
  Result r =
      sh("printf 'R1=0\\nAGAIN: R1=R1+1\\nSTEP(R1)\\nIF R1<3 GOTOB AGAIN\\nM30\\n"
         "%%_N_STEP_SPF\\nPROC STEP(REAL XX)\\nG1 X=XX*10 F100\\nRET\\n' | " +
         kCli + " run - --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["path"].size(), 3u) << r.out;
  EXPECT_EQ(j["path"][2]["end"][0], 30.0);
}

// covers: CLI-1 NC-WORD-13
TEST(Cli, TheFaceMillingExampleRunsUnderTransmit) {
  const std::string flats = CUTCOM_SOURCE_DIR "/examples/turning/FLATS.MPF";
  for (const char* engine : {"fast", "ref"}) {
    Result r = sh(kCli + " run " + flats + " --md 'MD20150[5]=2' --tool 3=4 --format json --engine " + engine);
    ASSERT_EQ(r.status, 0) << engine << r.out;
    nlohmann::json j = nlohmann::json::parse(r.out);
    int offsets = 0, circles = 0;  // the hexagon's six sides, its six outer corners with G450
    for (const auto& el : j["path"]) {
      offsets += el["origin"]["kind"] == "offset";
      circles += el["origin"]["kind"] == "transition_circle";
    }
    EXPECT_EQ(offsets, 7) << engine;  // the top flat in two halves
    EXPECT_EQ(circles, 6) << engine;
    bool noticed = false;
    for (const auto& n : j["notices"]) noticed |= n["clause"] == "NC-WORD-13";
    EXPECT_TRUE(noticed) << engine;
  }
}

// covers: CLI-1 NC-ERR-3
TEST(Cli, RejectedProgramsLeaveNoOutputFileAndDirectoriesAreNamed) {
  std::string out = std::string(CUTCOM_BINARY_DIR) + "/rejected.txt";
  std::remove(out.c_str());
  Result r = sh(kCli + " run " + write_temp("rejected.mpf", "G1 X1\nGOTOF END\n") + " -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(std::ifstream(out).good());
  EXPECT_FALSE(std::ifstream(out + ".part").good());
  Result d = sh_err(kCli + " run " + std::string(CUTCOM_BINARY_DIR));
  EXPECT_EQ(d.status, 2);
  EXPECT_NE(d.out.find("is a directory"), std::string::npos) << d.out;
  Result t = sh_err(kCli + " run " + kExample + " --tools " + write_temp("bad-tools.ini", "$TC_DP6[1,1]=5\nG1 X1\n"));
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.out.find("bad-tools.ini:2:1"), std::string::npos) << t.out;
  Result g = sh_err(kCli + " run " + write_temp("words.mpf", "G1 X1 R_T=4\n"));
  EXPECT_NE(g.out.find("line 1, column 7: 'R_T' is not a SINUMERIK word cutcom knows"), std::string::npos) << g.out;
}

// Bad input half-way still closes the document on standard output: JSON that parses, with the
// error and the path before it; text ends with an ERROR line. Exit status 2.
// covers: CLI-1
TEST(Cli, BadInputHalfWayEndsTheDocumentWithTheError) {
  std::string prog = write_temp("halfway.mpf", "N10 G0 X0 Y0\nN20 G1 X5 F100\nN30 Y5\nN40 X0\nN50 GOTOF NOWHERE\n");
  Result j = sh(kCli + " run " + prog + " --format json");
  EXPECT_EQ(j.status, 2);
  nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_GE(doc["path"].size(), 3U) << j.out;  // the blocks before the error (one may be held back)
  EXPECT_EQ(doc["error"]["line"], 5);
  EXPECT_NE(doc["error"]["message"].get<std::string>().find("NOWHERE"), std::string::npos) << j.out;
  Result t = sh(kCli + " run " + prog);
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.out.find("ERROR " + prog + " line 5, column"), std::string::npos) << t.out;
}

// A device, pipe or link as the output is written through, never renamed over: `-o /dev/null` as
// root once replaced the device with a regular file.
// covers: CLI-1
TEST(Cli, OutputThroughAPipeOrALinkKeepsWhatItIs) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(CUTCOM_BINARY_DIR) / "output-kinds";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::path fifo = dir / "pipe", link = dir / "link.txt", target = dir / "target.txt";
  Result r =
      sh("mkfifo " + fifo.string() + " && (timeout 20 cat " + fifo.string() + " > " + (dir / "piped.txt").string() +
         " &) && " + kCli + " run " + kExample + " -o " + fifo.string() + "; s=$?; wait; exit $s");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_FALSE(fs::exists(dir / "pipe.part"));
  fs::create_symlink(target, link);
  EXPECT_EQ(sh(kCli + " run " + kExample + " -o " + link.string()).status, 0);
  EXPECT_TRUE(fs::is_symlink(link));
  std::ifstream written(target);
  std::string first;
  std::getline(written, first);
  EXPECT_EQ(first.rfind("cutcom tool-centre path", 0), 0u) << first;
}
}  // namespace

namespace {
// covers: NC-PARAM-FLOW-4 NC-PARAM-FLOW-3 NC-PARAM-FLOW-6 CLI-1 NC-PARAM-SUB-1 NC-PARAM-SUB-3 NC-PARAM-SUB-4
TEST(Cli, ParametricExampleRunsAndARunawayLoopStops) {
  const std::string example = CUTCOM_SOURCE_DIR "/examples/slots.mpf";
  Result fast = sh(kCli + " run " + example + " --format json");
  Result ref = sh(kCli + " run " + example + " --format json --engine ref");
  ASSERT_EQ(fast.status, 0);
  ASSERT_EQ(ref.status, 0);
  auto f = nlohmann::json::parse(fast.out), r = nlohmann::json::parse(ref.out);
  // Three slots, two passes each: 6 approaches, each followed by 4 walls, 4 roundings, 1 closing wall.
  int approaches = 0;
  for (const auto& e : f["path"]) approaches += e["origin"]["kind"] == "approach";
  EXPECT_EQ(approaches, 6);
  EXPECT_EQ(f["path"].size(), r["path"].size());
  // The machine builder's cycle called for two sizes: two SAR approaches, eight roundings, the
  // subprogram's lines named.
  const std::string cycle = CUTCOM_SOURCE_DIR "/examples/cycle/FLANGE.MPF";
  Result cf = sh(kCli + " run " + cycle + " --format json");
  Result cr = sh(kCli + " run " + cycle + " --format json --engine ref");
  ASSERT_EQ(cf.status, 0) << cf.out;
  ASSERT_EQ(cr.status, 0) << cr.out;
  auto jf = nlohmann::json::parse(cf.out), jr = nlohmann::json::parse(cr.out);
  EXPECT_EQ(jf["path"].size(), jr["path"].size());
  EXPECT_EQ(jf["variables"].size(), 2u);
  int roundings = 0;
  for (const auto& e : jf["path"]) roundings += e["origin"].value("inserted", "") == "rounding";
  EXPECT_EQ(roundings, 8);
  EXPECT_EQ(jf["path"][6]["origin"]["source"], "PROFILE.SPF line 14");
  const std::string dir = CUTCOM_BINARY_DIR;
  std::ofstream(dir + "/endless.mpf") << "G1 X0 F100\nAGAIN: R1=R1+1\nGOTOB AGAIN\n";
  Result loop = sh(kCli + " run " + dir + "/endless.mpf --max-loops 500", true);
  EXPECT_EQ(loop.status, 2);
  EXPECT_NE(loop.out.find("line 3, column 1: the program runs away: more than 500"), std::string::npos) << loop.out;
}

// covers: TOOL-TURN-1 MD-20150-2 NC-DIAM-1
TEST(Cli, TheLatheExampleRunsWithItsTurningTools) {
  // Two turning tools with cutting edge positions from the archive, G18 from the machine data,
  // diameters: both engines alike, each selection noting the tip's offset.
  const std::string turning = CUTCOM_SOURCE_DIR "/examples/turning/";
  std::string lathe =
      " run " + turning + "SHAFT.MPF --tools " + turning + "TO_INI.INI --md 'MD20150[5]=2' --format json";
  Result tf = sh(kCli + lathe), tr = sh(kCli + lathe + " --engine ref");
  ASSERT_EQ(tf.status, 0) << tf.out;
  ASSERT_EQ(tr.status, 0) << tr.out;
  auto lf = nlohmann::json::parse(tf.out), lr = nlohmann::json::parse(tr.out);
  ASSERT_EQ(lf["path"].size(), lr["path"].size());
  int tips = 0;
  for (const auto& n : lf["notices"]) tips += n["clause"] == "TOOL-TURN-1";
  EXPECT_EQ(tips, 2);
  // Position 3 on the 24 mm cylinder (N70): the tip runs at the programmed diameter, as radius 12.
  for (const auto& e : lf["path"])
    if (e.value("block", 0) == 70) EXPECT_EQ(e["start"][0], 12.0) << e.dump();
}

// covers: NC-PARAM-VAR-3 NC-PARAM-SUB-5 NC-PARAM-SUB-2
TEST(Cli, DefinitionsFileAndASubprogramRunOnItsOwn) {
  const std::string dir = CUTCOM_BINARY_DIR;
  std::ofstream(dir + "/gud.def")
      << "%_N_GUD_DEF\n; global data\nDEF NCK SYNRW REAL PHU 1 LLI 0 ULI 99 APW 2 _DEPTH=2.5\n"
         "DEF CHAN INT _LAPS\nM30\n";
  std::ofstream(dir + "/WALL.SPF") << "PROC WALL(REAL LEN, INT LAPS)\nG1 Z=-_DEPTH F100\nG1 X=LEN*LAPS\n_LAPS=LAPS\n"
                                      "G1 X=_LAPS\nM17\n";
  Result ok = sh(kCli + " run " + dir + "/WALL.SPF --definitions " + dir + "/gud.def --args \"4, 3\" --format json");
  ASSERT_EQ(ok.status, 0) << ok.out;
  auto j = nlohmann::json::parse(ok.out);
  ASSERT_EQ(j["path"].size(), 3u);
  EXPECT_EQ(j["path"][0]["end"][2], -2.5);
  EXPECT_EQ(j["path"][1]["end"][0], 12);
  EXPECT_EQ(j["path"][2]["end"][0], 3);
  // Without the definitions the variable is undefined; a wrong definitions line or argument list
  // names where it is wrong.
  Result missing = sh(kCli + " run " + dir + "/WALL.SPF --args \"4, 3\"", true);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.out.find("line 2, column 7: undefined variable '_DEPTH'"), std::string::npos) << missing.out;
  std::ofstream(dir + "/bad.def") << "DEF REAL _OK\nG1 X1\n";
  Result bad = sh(kCli + " run " + dir + "/WALL.SPF --definitions " + dir + "/bad.def", true);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("bad.def:2:1: a definitions file holds DEF and DEFINE lines only"), std::string::npos)
      << bad.out;
  Result args = sh(kCli + " run " + dir + "/WALL.SPF --definitions " + dir + "/gud.def --args \"4, 3, 1\"", true);
  EXPECT_EQ(args.status, 2);
  EXPECT_NE(args.out.find("3 arguments given, the PROC has 2 parameters"), std::string::npos) << args.out;
}
}  // namespace

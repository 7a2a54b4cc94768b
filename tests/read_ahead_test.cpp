// The reader on its own thread (ReadAhead, issue "Performance"): the engines see the same blocks,
// the same errors at the same place, and SAR-END-3's new position reaches the reader in time.
#include "cutcom/read_ahead.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "cutcom/fast/engine.hpp"
#include "cutcom/output.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/ref/engine.hpp"

namespace cutcom {
namespace {

// A pocket loop of many batches, with a subprogram unit whose name the blocks carry.
std::string long_program(int passes) {
  return "%_N_MAIN_MPF\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nDEF INT PASS\nN10 G0 X0 Y0 Z5 T1 D1\nN20 G1 G41 X10 Y0 "
         "F100\nFOR PASS=1 TO " +
         std::to_string(passes) +
         "\nSIDE\nENDFOR\nN90 G40 G0 X0 Y0\nM30\n%_N_SIDE_SPF\nG91 X20\nY20\nG3 X-20 Y0 CR=10\nG1 Y-20\nG90\nM17\n";
}

std::string run_fast(BlockSource& blocks, const std::function<std::string(std::uint32_t)>& names) {
  std::ostringstream out;
  TextWriter writer(out, "fast", true);
  std::string error;
  try {
    fast::run(blocks, MachineData{}, writer);
  } catch (const InputError& e) {
    error = e.what();
  }
  writer.finish();
  return out.str() + error + names(1);
}

// covers: NC-PARAM-SUB-3
TEST(ReadAhead, GivesTheEngineTheReadersBlocksInOrder) {
  std::string text = long_program(400);  // 2,000 blocks: many batches, each of a few
  std::istringstream a(text), b(text);
  ProgramReader alone(a), ahead_of(b);
  ReadAhead ahead(ahead_of);
  Block want;
  int count = 0;
  std::uint32_t in_side = 0;  // the id of a block of _N_SIDE_SPF
  while (alone.next(want)) {
    const Block* got = ahead.next_block();
    ASSERT_NE(got, nullptr) << count;
    EXPECT_EQ(got->words.line, want.words.line);
    EXPECT_EQ(got->end, want.end) << count;
    EXPECT_EQ(got->words.source, want.words.source);
    if (want.words.source != 0) in_side = want.words.source;
    ++count;
  }
  EXPECT_EQ(ahead.next_block(), nullptr);
  EXPECT_EQ(ahead.next_block(), nullptr);  // and stays at the end
  EXPECT_GT(count, 2000);
  EXPECT_EQ(ahead.source_text(in_side), alone.source_text(in_side));
  EXPECT_NE(ahead.source_text(in_side).find("_N_SIDE_SPF"), std::string::npos) << ahead.source_text(in_side);
}

// An engine slower than the reader now and then: the reader fills its queue, sleeps, and is woken
// again when half of it is taken (the blocks keep their order; a lost wake-up would hang here).
// covers: NC-PARAM-SUB-3
TEST(ReadAhead, AReaderWithAFullQueueIsWokenAgain) {
  std::string text = long_program(3000);  // 15,000 blocks: 58 batches, the queue full many times
  std::istringstream a(text), b(text);
  ProgramReader alone(a), ahead_of(b);
  ReadAhead ahead(ahead_of);
  Block want;
  int count = 0;
  while (alone.next(want)) {
    if (count % 1500 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));  // the reader runs ahead
    const Block* got = ahead.next_block();
    ASSERT_NE(got, nullptr) << count;
    ASSERT_EQ(got->words.line, want.words.line) << count;
    ASSERT_EQ(got->end, want.end) << count;
    ++count;
  }
  EXPECT_EQ(ahead.next_block(), nullptr);
  EXPECT_GT(count, 15000);
}

// covers: NC-ERR-2
TEST(ReadAhead, ThrowsTheReadersErrorAfterTheBlocksBeforeIt) {
  std::string text = "N10 G0 X0 Y0\n";
  for (int i = 0; i < 300; ++i) text += "G1 X" + std::to_string(i) + " F100\n";
  text += "G1 X1 QQQ=5\nG1 X2\n";
  std::istringstream in(text);
  ProgramReader reader(in);
  ReadAhead ahead(reader);
  int blocks = 0;
  try {
    while (ahead.next_block()) ++blocks;
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 302);
  }
  EXPECT_EQ(blocks, 301);
  EXPECT_THROW(ahead.next_block(), InputError);  // asked again, the same error
}

// covers: SAR-END-3
TEST(ReadAhead, ASarRetractionsEndReachesTheReaderBeforeItReadsOn) {
  // After G248 without end point the tool is at (35, 7, 3); N50's Z and N60's increments start
  // there, which the reader learns from the engine only after N40.
  std::string text =
      "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nN10 G0 X0 Y0 Z5 T1 D1\nN20 G1 G41 X10 Y0 Z0 F100\nN30 X30\n"
      "N40 G248 DISR=5 DISCL=3 G40\nN50 G0 Z50\nN60 G91 Z-5\nN70 G90 X0 Y0\n";
  for (int i = 0; i < 200; ++i) text += "G1 X" + std::to_string(i % 7) + " Y1\n";
  std::istringstream a(text), b(text);
  ProgramReader alone(a), ahead_of(b);
  ReadAhead ahead(ahead_of);
  auto none = [](std::uint32_t) { return std::string(); };
  std::string want = run_fast(alone, none), got = run_fast(ahead, none);
  EXPECT_EQ(got, want);
  EXPECT_NE(want.find("(35.0000, 7.0000, 50.0000)"), std::string::npos) << want;
  EXPECT_NE(want.find("(35.0000, 7.0000, 45.0000)"), std::string::npos) << want;
}

TEST(ReadAhead, ANewPositionAfterAnyOtherBlockIsALogicError) {
  std::istringstream in("N10 G0 X0 Y0\nN20 X5\n");
  ProgramReader reader(in);
  ReadAhead ahead(reader);
  ASSERT_NE(ahead.next_block(), nullptr);
  EXPECT_THROW(ahead.set_position(Point3{}), std::logic_error);
}

TEST(ReadAhead, StopsWhenTheEngineStopsEarly) {
  std::string text = long_program(20000);  // far more than it reads ahead
  std::istringstream in(text);
  ProgramReader reader(in);
  {
    ReadAhead ahead(reader);
    for (int i = 0; i < 10; ++i) ASSERT_NE(ahead.next_block(), nullptr);
  }  // joins the reader's thread: no hang, no use after the end
  SUCCEED();
}

TEST(ReadAhead, BothEnginesRunFromIt) {
  std::string text = long_program(20);
  std::istringstream a(text), b(text);
  ProgramReader fast_reader(a), ref_reader(b);
  ReadAhead fast_blocks(fast_reader), ref_blocks(ref_reader);
  CollectingSink f, r;
  EXPECT_TRUE(fast::run(fast_blocks, MachineData{}, f));
  EXPECT_TRUE(ref::run(ref_blocks, MachineData{}, r));
  EXPECT_EQ(f.result.path.size(), r.result.path.size());
  EXPECT_GT(f.result.path.size(), 80u);
}

}  // namespace
}  // namespace cutcom

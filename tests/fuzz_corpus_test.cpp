// The reader target's corpus (fuzz/corpus, its findings among it) replayed as the target reads it:
// in the sanitizer job (scripts/sanitize.sh) a finding that comes back is a failed test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "reader_input.hpp"

namespace cutcom {
namespace {

// covers: NC-PARAM-TYPE-1 NC-PARAM-SYS-1
TEST(FuzzCorpus, EveryUnitIsReadOrRejectedWithAnInputError) {
  int units = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CUTCOM_SOURCE_DIR "/fuzz/corpus")) {
    std::ifstream f(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << f.rdbuf();
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_NO_THROW(fuzz::read_input(bytes.str()));
    ++units;
  }
  EXPECT_GE(units, 13);
}

}  // namespace
}  // namespace cutcom

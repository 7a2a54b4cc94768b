// Helpers of the program-words tests (program_words_test.cpp, program_tools_cycles_test.cpp):
// a program read into blocks, decimals and points from text, a block's actions, a program's
// reading error.
#pragma once

#include <string>
#include <vector>

#include "cutcom/reader.hpp"
#include "support.hpp"

namespace cutcom::words_test {

inline std::vector<Block> read(const std::string& text, ModalState initial = {}, const OffsetTable* offsets = nullptr) {
  return testing::read_blocks(text, initial, offsets);
}

inline Decimal dec(const char* s) { return *Decimal::parse(s).value; }
inline Point3 pt(const char* x, const char* y, const char* z) { return {dec(x), dec(y), dec(z)}; }

inline std::vector<std::string> actions(const Block& b) {
  std::vector<std::string> a;
  for (int i = 0; i < b.words.aux_count; ++i) a.push_back(b.words.aux[static_cast<std::size_t>(i)].name());
  return a;
}

// The reading error of a program, or "accepted" when it reads.
inline std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.detail();
  }
  return "accepted";
}

}  // namespace cutcom::words_test

// Helpers of the parametric-program tests: a folder of subprograms, what a program's last block ends at, the line of
// the error it raises, and two runs' paths compared element by element.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cutcom/interpreter.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::test {

// A folder of subprogram files for one test.
inline std::string folder_with(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("cutcom-" + name);
  std::filesystem::create_directories(dir);
  for (const auto& [file, text] : files) std::ofstream(dir / file) << text;
  return dir.string();
}

inline std::string end_x(const std::string& text) {
  std::istringstream in(text);
  ProgramReader reader(in);
  Block b, last;
  while (reader.next(b)) last = b;
  return last.end.x.to_string();
}

// The actions (M, H and the words kept as written) of the first block of `text`.
inline std::vector<std::string> first_block_actions(const std::string& text) {
  std::istringstream in(text);
  ProgramReader reader(in);
  Block b;
  std::vector<std::string> out;
  if (!reader.next(b)) return out;
  for (int k = 0; k < b.words.aux_count; ++k) out.push_back(b.words.aux[static_cast<std::size_t>(k)].name());
  return out;
}

// The line of the error reading `text` gives (its message must hold `words`); subprograms are
// looked for in `dir`.
inline int error_line(const std::string& text, const std::string& words, InterpreterLimits limits = {},
                      const std::string& dir = {}) {
  std::istringstream in(text);
  ProgramReader reader(in);
  reader.set_limits(limits);
  if (!dir.empty()) reader.set_search_path({dir});
  Block b;
  try {
    while (reader.next(b)) {
    }
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    return e.line();
  }
  ADD_FAILURE() << "no error in:\n" << text;
  return 0;
}

// The path without origins' lines (the plain text has other line numbers).
inline void expect_same_path(const RunResult& a, const RunResult& b) {
  ASSERT_EQ(a.path.size(), b.path.size());
  ASSERT_EQ(a.alarms.size(), b.alarms.size());
  for (std::size_t i = 0; i < a.path.size(); ++i) {
    const PathElement &x = a.path[i], &y = b.path[i];
    EXPECT_EQ(x.type, y.type) << i;
    EXPECT_EQ(x.origin.kind, y.origin.kind) << i;
    EXPECT_EQ(x.ccw, y.ccw) << i;
    for (auto [p, q] : {std::pair{x.start, y.start}, {x.end, y.end}, {x.center, y.center}}) {
      EXPECT_EQ(p.x, q.x) << i;
      EXPECT_EQ(p.y, q.y) << i;
      EXPECT_EQ(p.z, q.z) << i;
    }
  }
}

}  // namespace cutcom::test

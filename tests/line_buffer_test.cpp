// The program's lines read ahead in large pieces (core/include/cutcom/line_buffer.hpp) are
// std::getline's, across the buffer's seams, at the end without a newline and after a seek.
#include "cutcom/line_buffer.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> by_getline(const std::string& text, std::streamoff from = 0) {
  std::istringstream in(text);
  in.seekg(from);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> by_buffer(std::istream& in, cutcom::LineBuffer& buffer) {
  std::vector<std::string> lines;
  for (std::string line; buffer.next(in, line);) lines.push_back(line);
  return lines;
}

// Short lines, empty ones, CR LF, and now and then one longer than the buffer's piece.
std::string random_text(std::mt19937_64& random) {
  std::string text;
  int lines = static_cast<int>(random() % 50);
  for (int n = 0; n < lines; ++n) {
    std::size_t length = random() % 10 == 0 ? random() % 200000 : random() % 40;
    for (std::size_t c = 0; c < length; ++c) text += static_cast<char>(random() % 4 == 0 ? ' ' : 'A' + random() % 26);
    if (random() % 5 == 0) text += '\r';
    if (n + 1 < lines || random() % 2) text += '\n';
  }
  return text;
}

// covers: NC-LEX-1
TEST(LineBuffer, LinesAreThoseOfGetline) {
  std::mt19937_64 random(20261129);
  for (int k = 0; k < 300; ++k) {
    std::string text = random_text(random);
    std::istringstream in(text);
    cutcom::LineBuffer buffer;
    ASSERT_EQ(by_buffer(in, buffer), by_getline(text)) << "text " << k;
    // After a seek (the reader resets the buffer first) the lines from there
    std::streamoff from = text.empty() ? 0 : static_cast<std::streamoff>(random() % text.size());
    in.clear();
    in.seekg(from);
    buffer.reset();
    ASSERT_EQ(by_buffer(in, buffer), by_getline(text, from)) << "text " << k << " from " << from;
  }
}

// A line given back (Interpreter::next_plain leaves a line it does not take to next()) is the
// next line again, wherever it lies in the buffer.
// covers: NC-LEX-1
TEST(LineBuffer, ALineGivenBackComesAgain) {
  std::mt19937_64 random(20261204);
  for (int k = 0; k < 200; ++k) {
    std::string text = random_text(random);
    std::istringstream in(text);
    cutcom::LineBuffer buffer;
    std::vector<std::string> lines_read;
    for (std::string_view line; buffer.next(in, line);) {
      if (random() % 3 == 0) {  // given back, then read again: the same line
        std::string was(line);
        buffer.give_back(line);
        ASSERT_TRUE(buffer.next(in, line)) << "text " << k;
        ASSERT_EQ(std::string(line), was) << "text " << k;
      }
      lines_read.emplace_back(line);
    }
    ASSERT_EQ(lines_read, by_getline(text)) << "text " << k;
  }
}

}  // namespace

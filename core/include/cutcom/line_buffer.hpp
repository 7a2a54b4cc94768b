// A program's lines read from its stream in large pieces: std::getline per line took a tenth of
// the reader's time (issue "Performance"). The lines are std::getline's: up to a '\n', without
// it, the last one also without; the stream is read forward from where it stands, so a reader
// that moves the stream (a seek, another reader) resets the buffer first (Interpreter::getline).
#pragma once

#include <algorithm>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace cutcom {

class LineBuffer {
 public:
  // Forget what was read ahead: the stream is about to be moved.
  void reset() { begin_ = end_ = 0, at_end_ = false; }

  // The next line, as std::getline(in, text) would give it; false at the end of the stream.
  bool next(std::istream& in, std::string& text) {
    std::string_view line;
    if (!next(in, line)) return false;
    text.assign(line);
    return true;
  }
  // The same without a copy: `line` points into the buffer and holds until the next call. The
  // line is followed in the buffer by its '\n', or by a zero after the last line, and at least
  // kPadding readable bytes (read_plain_block reads the digits of a number eight at a time).
  static constexpr std::size_t kPadding = 16;
  // The line the last next() gave is given again by the next one (it is still in the buffer).
  void give_back(std::string_view line) { begin_ = static_cast<std::size_t>(line.data() - data_.data()); }
  bool next(std::istream& in, std::string_view& line) {
    std::size_t searched = begin_;  // what holds no '\n' is not searched again
    while (true) {
      const char* data = data_.data();  // null before the first read: nothing to search then
      const void* newline = end_ > searched ? find_newline(data + searched, end_ - searched) : nullptr;
      if (newline) {
        auto at = static_cast<std::size_t>(static_cast<const char*>(newline) - data);
        line = std::string_view(data + begin_, at - begin_);
        begin_ = at + 1;
        return true;
      }
      if (at_end_) {
        if (begin_ == end_) return false;
        line = std::string_view(data + begin_, end_ - begin_);
        begin_ = end_;
        return true;
      }
      // Keep the line begun, then read more after it (a longer line than the buffer grows it).
      std::size_t kept = end_ - begin_;
      if (begin_ > 0) std::memmove(data_.data(), data + begin_, kept);
      begin_ = 0, end_ = kept, searched = kept;
      if (data_.size() < kRead || data_.size() - end_ < kRead / 2)
        data_.resize(std::max(kRead, 2 * data_.size()) + kPadding);
      in.read(data_.data() + end_, static_cast<std::streamsize>(data_.size() - kPadding - end_));
      auto got = static_cast<std::size_t>(in.gcount());
      end_ += got;
      std::memset(data_.data() + end_, 0, kPadding);
      if (!in) at_end_ = true;  // the end, or an error: the caller sees the stream's state
    }
  }

 private:
  // memchr for '\n' in [p, p + n), the first 16 bytes looked at inline: a block's line is mostly
  // shorter (the call was a fifth of the reading of a short line). The padding after the buffer's
  // end makes those 16 bytes readable.
  static const void* find_newline(const char* p, std::size_t n) {
#if defined(__SSE2__)
    __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    auto mask = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, _mm_set1_epi8('\n'))));
    if (mask != 0) {
      auto at = static_cast<std::size_t>(__builtin_ctz(mask));
      return at < n ? p + at : nullptr;
    }
    if (n <= 16) return nullptr;
    return std::memchr(p + 16, '\n', n - 16);
#else
    return std::memchr(p, '\n', n);
#endif
  }
  static constexpr std::size_t kRead = 1 << 16;
  std::vector<char> data_;
  std::size_t begin_ = 0, end_ = 0;  // the lines not yet given: data_[begin_, end_)
  bool at_end_ = false;
};

}  // namespace cutcom

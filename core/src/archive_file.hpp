// The control's archive files as cutcom reads them (TO_INI.INI: TOOL-FILE-1, UFR.INI:
// NC-OFFSET-2, machine data: MD-FILE-1): the lines that frame the data, and one channel's data.
#pragma once

#include <fmt/format.h>

#include <cctype>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace cutcom::archive {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

inline std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// The channel a CHANDATA(n) line selects; 0 for any other line.
inline int chandata_channel(std::string_view u) {
  if (u.rfind("CHANDATA", 0) != 0) return 0;
  int n = 0;
  for (char c : u.substr(8))
    if (std::isdigit(static_cast<unsigned char>(c)) && n < 1000) n = n * 10 + (c - '0');
  return n;
}

// Lines that carry no data cutcom needs: blank, a header, the channel's selection, the end, a comment.
inline bool frame_line(std::string_view u) {
  return u.empty() || u[0] == '%' || u[0] == ';' || u.rfind("CHANDATA", 0) == 0 || u == "M17" || u == "M30" ||
         u == "M02" || u == "M2";
}

// Calls data(line number, line, upper-case trimmed line) for each data line of `channel`'s:
// those before any CHANDATA(n) and those after CHANDATA(channel). Without a channel (0) an
// archive of several channels (a second CHANDATA(n) with another n) is refused through
// fail(line number, message): their data would overwrite one another, and which channel runs
// the program cutcom cannot tell. A channel the archive holds no data of is refused too.
template <class Data, class Fail>
void read_lines(std::istream& in, Data data, Fail fail, int channel = 0) {
  std::string line;
  int n = 0, seen = 0, seen_line = 0;  // the first channel seen, and where
  bool wanted = true, found = false;   // in a wanted part; the wanted channel's part found
  while (std::getline(in, line)) {
    ++n;
    if (n == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // a UTF-8 byte order mark
    std::string u = upper(trim(line));
    if (int c = chandata_channel(u); c != 0) {
      if (channel == 0 && seen != 0 && c != seen)
        fail(n, fmt::format("CHANDATA({}) after CHANDATA({}) in line {}: the archive holds the data of more than "
                            "one channel; say which channel runs the program (--channel N)",
                            c, seen, seen_line));
      if (seen == 0) seen = c, seen_line = n;
      wanted = channel == 0 || c == channel;
      found = found || c == channel;
    }
    if (wanted && !frame_line(u)) data(n, line, u);
  }
  if (in.bad()) fail(n, "read error");
  if (channel != 0 && seen != 0 && !found)
    fail(n, fmt::format("the archive holds no data of channel {} (CHANDATA({}) in line {})", channel, seen, seen_line));
}

}  // namespace cutcom::archive

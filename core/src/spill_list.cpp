#include "cutcom/spill_list.hpp"

#include <stdexcept>

namespace cutcom {

void SpillList::append(const std::string& item) {
  memory_ += item;
  memory_ += '\n';
  ++count_;
  if (memory_.size() >= bound_) spill();
}

void SpillList::spill() {
  if (file_failed_) return;
  if (!file_) {
    file_.reset(std::tmpfile());
    if (!file_) {
      file_failed_ = true;
      return;
    }
  }
  if (std::fwrite(memory_.data(), 1, memory_.size(), file_.get()) != memory_.size())
    throw std::runtime_error("writing the JSON output's temporary file failed (disk full?)");
  memory_.clear();
}

void SpillList::write_to(std::ostream& out, const char* separator) const {
  bool first = true;
  // Items end with '\n': the first is written as it is, every later one after the separator.
  auto emit = [&](const char* data, std::size_t n) {
    std::size_t at = 0;
    while (at < n) {
      std::size_t end = at;
      while (end < n && data[end] != '\n') ++end;
      if (end == n) return at;  // an item continues in the next chunk
      if (!first) out << separator;
      first = false;
      out.write(data + at, static_cast<std::streamsize>(end - at));
      at = end + 1;
    }
    return at;
  };
  if (file_) {
    if (std::fflush(file_.get()) != 0 || std::fseek(file_.get(), 0, SEEK_SET) != 0)
      throw std::runtime_error("reading the JSON output's temporary file failed");
    std::string carry;
    char chunk[1 << 16];
    std::size_t n;
    while ((n = std::fread(chunk, 1, sizeof chunk, file_.get())) > 0) {
      carry.append(chunk, n);
      std::size_t used = emit(carry.data(), carry.size());
      carry.erase(0, used);
    }
    if (std::ferror(file_.get())) throw std::runtime_error("reading the JSON output's temporary file failed");
    if (!carry.empty()) throw std::runtime_error("the JSON output's temporary file ends inside an item");
    std::fseek(file_.get(), 0, SEEK_END);  // further appends go after what is there
  }
  emit(memory_.data(), memory_.size());
}

}  // namespace cutcom

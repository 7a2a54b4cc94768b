// libFuzzer target: any bytes as NC text, read as reader_input.hpp says.
#include <cstddef>
#include <cstdint>

#include "reader_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cutcom::fuzz::read_input({reinterpret_cast<const char*>(data), size});
  return 0;
}

// The JSON writer's lists after the path spill to a temporary file beyond a bound (CLI-1: memory
// flat whatever the program length): what is written is what was appended, in order.
#include "cutcom/spill_list.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cutcom/output.hpp"

namespace {

std::string item(int k) {  // items of 1 to ~5,000 characters, crossing the 64 KB read chunks
  return "{\"k\":" + std::to_string(k) + ",\"pad\":\"" + std::string(static_cast<std::size_t>((k * 7919) % 5000), 'x') +
         "\"}";
}

// covers: CLI-1
TEST(SpillList, ItemsComeBackInOrderFromMemoryAndFromTheFile) {
  for (std::size_t bound : {std::size_t{16}, std::size_t{1} << 20, std::size_t{1} << 30}) {
    cutcom::SpillList list(bound);
    std::string expected;
    auto check = [&] {
      for (int pass = 0; pass < 2; ++pass) {  // writing leaves the list as it was
        std::ostringstream out;
        list.write_to(out, ",\n");
        ASSERT_EQ(out.str(), expected) << "bound " << bound << " pass " << pass;
      }
    };
    check();  // empty
    EXPECT_TRUE(list.empty());
    for (int k = 0; k < 3000; ++k) {
      expected += (k ? ",\n" : "") + item(k);
      list.append(item(k));
    }
    EXPECT_EQ(list.size(), 3000u);
    check();
    for (int k = 3000; k < 3100; ++k) {  // appended after a write
      expected += ",\n" + item(k);
      list.append(item(k));
    }
    check();
  }
}

// covers: CLI-1
TEST(SpillList, JsonWriterKeepsEveryActionOfALongProgram) {
  std::ostringstream out;
  {
    cutcom::JsonWriter w(out, "fast", false);
    for (int k = 0; k < 40000; ++k) {  // about 3 MB of actions: past the writer's 1 MB in memory
      cutcom::ActionEvent a;
      a.line = k + 1;
      a.function.value = k % 100;
      a.at = {k * 0.5, -1.0, 2.0};
      w.action(a);
    }
    w.finish();
  }
  auto j = nlohmann::json::parse(out.str());
  ASSERT_EQ(j["actions"].size(), 40000u);
  for (int k = 0; k < 40000; k += 997) {
    EXPECT_EQ(j["actions"][k]["line"], k + 1);
    std::string name = "M";  // (not "M" + …: GCC 12's -Wrestrict misreads it)
    name += std::to_string(k % 100);
    EXPECT_EQ(j["actions"][k]["function"], name);
    EXPECT_EQ(j["actions"][k]["at"][0], k * 0.5);
  }
}

}  // namespace

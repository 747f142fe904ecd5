// Each fluid model's and time scheme's own keys (io/case_schema.hpp, keys_read_only_by): every one is a key
// of the schema and has one reader; a case of another model that gives one is told it does not read it;
// the reference table says who reads it.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "io/case_file.hpp"
#include "io/case_schema.hpp"

using namespace cellsim;

TEST(ModelKeys, EachIsASchemaKeyWithOneReader) {
  std::set<std::string> seen;
  for (const KeysReadOnlyBy& own : keys_read_only_by()) {
    for (const std::string& key : own.keys) {
      EXPECT_NE(find_param(key), nullptr) << key << " (" << own.reader() << ") is not a case key";
      EXPECT_TRUE(seen.insert(key).second) << key << " has two readers";
      EXPECT_EQ(read_only_by(key), own.reader());
    }
    const ParamSpec* reader = find_param(own.choice_key);
    ASSERT_TRUE(reader && is_choice(*reader)) << own.choice_key;
    EXPECT_NE(std::find(reader->choices.begin(), reader->choices.end(), own.value), reader->choices.end()) << own.reader();
  }
  EXPECT_EQ(read_only_by("wall.G_MPa"), "");
}

TEST(ModelKeys, AnotherModelGivenOneIsToldAndTheTableSaysWhoReadsIt) {
  const nlohmann::json closed = {{"cell", {{"n_wall", 162}, {"diameter_um", 40}}}, {"fluid", {{"model", "cavity"},
                                 {"viscosity_Pa_s", 0.5}}}};
  EXPECT_EQ(keys_the_case_ignores(closed, validate_case(closed)), std::vector<std::string>{"fluid.viscosity_Pa_s"});
  const nlohmann::json sph = {{"time", {{"equilibrium_tolerance", 1e-4}}}};
  EXPECT_EQ(keys_the_case_ignores(sph, validate_case(sph)), std::vector<std::string>{"time.equilibrium_tolerance"});
  const std::string table = reference_markdown();
  EXPECT_NE(table.find("| read only by |"), std::string::npos);
  const auto row = table.substr(table.find("| `fluid.viscosity_Pa_s`"));
  EXPECT_NE(row.substr(0, row.find('\n')).find("`fluid.model = sph`"), std::string::npos) << row.substr(0, 300);
}

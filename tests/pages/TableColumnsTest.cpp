// A results table as a page's columns: every key, the most compact exact-enough encoding for
// each, and nothing lost that a page shows.

#include "parksim/pages/TableColumns.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/pages/PageTestSupport.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;
using testing::unpack;

const nlohmann::json& columnNamed(const nlohmann::json& table, const std::string& name) {
  for (const nlohmann::json& c : table["columns"]) {
    if (c["name"] == name) return c;
  }
  throw std::runtime_error("no column " + name);
}

// The column's values as the page reads them: levels looked up, numbers unpacked.
std::vector<nlohmann::json> valuesOf(const nlohmann::json& c, std::size_t rows) {
  std::vector<nlohmann::json> out;
  if (c["encoding"] == "const") return std::vector<nlohmann::json>(rows, c["value"]);
  for (const double x : unpack(c)) {
    if (c["encoding"] == "levels") {
      out.push_back(c["levels"][static_cast<std::size_t>(x)]);
    } else {
      out.push_back(std::isnan(x) ? nlohmann::json() : nlohmann::json(x));
    }
  }
  return out;
}

std::vector<Json> sampleRows(int n) {
  std::vector<Json> rows;
  for (int i = 0; i < n; ++i) {
    Json r;
    r["episode_id"] = "id" + std::to_string(i);
    r["world"] = i % 2 ? "head_in" : "parallel";
    r["seed"] = i % 3 + 1;
    r["status"] = i == 4 ? "contact" : "met";
    r["met_tolerance"] = i != 4;
    r["steps"] = 1000 + 3 * i;                       // whole numbers, many distinct
    r["max_pos_err_m"] = 1e-5 * (i + 1) + 1e-9 / 3;  // many distinct reals
    if (i != 2) r["plan_cost_m"] = 0.5 * i;          // absent in one row
    r["host"] = "box";                               // the same everywhere
    r["contact_bodies"] = i == 4 ? Json{"robot_3", "wall_1"} : Json::array();
    r["plan_phase_times_s"] = {{"sampling", 0.25 * i}, {"smoothing", 0.0}};
    r["plan_cost_history"] = Json::array({Json::array({0.1, 5, 1.5})});
    r["noise_seed"] = std::uint64_t{18446744073709551615u} - static_cast<std::uint64_t>(i % 2);
    rows.push_back(r);
  }
  return rows;
}

TEST(TableColumnsTest, EveryKeyInTheOrderRowsFirstUseIt) {
  const nlohmann::json t = tableColumns(sampleRows(300));
  EXPECT_EQ(t["rows"], 300);
  std::vector<std::string> names;
  for (const nlohmann::json& c : t["columns"]) names.push_back(c["name"]);
  EXPECT_EQ(names,
            (std::vector<std::string>{"episode_id", "world", "seed", "status", "met_tolerance",
                                      "steps", "max_pos_err_m", "plan_cost_m", "host",
                                      "contact_bodies", "plan_phase_times_s.sampling",
                                      "plan_phase_times_s.smoothing", "noise_seed"}));
  EXPECT_EQ(t["omitted"], (std::vector<std::string>{"plan_cost_history"}));
}

TEST(TableColumnsTest, EachColumnIsPackedAsItsValuesAllow) {
  const std::vector<Json> rows = sampleRows(300);
  const nlohmann::json t = tableColumns(rows);
  EXPECT_EQ(columnNamed(t, "host")["encoding"], "const");
  EXPECT_EQ(columnNamed(t, "host")["value"], "box");
  EXPECT_EQ(columnNamed(t, "plan_phase_times_s.smoothing")["encoding"], "const");
  EXPECT_EQ(columnNamed(t, "world")["encoding"], "levels");
  EXPECT_EQ(columnNamed(t, "world")["levels"], (std::vector<std::string>{"head_in", "parallel"}));
  EXPECT_EQ(columnNamed(t, "world")["kind"], "text");
  // Few distinct numbers (an axis) are levels, exact and numeric.
  EXPECT_EQ(columnNamed(t, "seed")["encoding"], "levels");
  EXPECT_EQ(columnNamed(t, "seed")["levels"], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(columnNamed(t, "seed")["kind"], "number");
  EXPECT_EQ(columnNamed(t, "met_tolerance")["kind"], "bool");
  EXPECT_EQ(columnNamed(t, "steps")["encoding"], "integer");
  EXPECT_EQ(columnNamed(t, "steps")["type"], "u16");
  EXPECT_EQ(columnNamed(t, "max_pos_err_m")["encoding"], "number");
  EXPECT_EQ(columnNamed(t, "max_pos_err_m")["type"], "f32");
  // 2^64 - 1 is not exact as a page's number: text, digit for digit.
  EXPECT_EQ(columnNamed(t, "noise_seed")["kind"], "text");
  EXPECT_EQ(columnNamed(t, "noise_seed")["levels"][1], "18446744073709551615");
  EXPECT_EQ(columnNamed(t, "episode_id")["type"], "u16");  // 300 distinct ids
}

TEST(TableColumnsTest, ValuesReadBackAsThePageShowsThem) {
  const std::vector<Json> rows = sampleRows(300);
  const nlohmann::json t = tableColumns(rows);
  const auto check = [&](const std::string& name, const auto& expected) {
    const std::vector<nlohmann::json> values = valuesOf(columnNamed(t, name), rows.size());
    ASSERT_EQ(values.size(), rows.size()) << name;
    for (std::size_t i = 0; i < rows.size(); ++i) expected(rows[i], values[i]);
  };
  check("episode_id", [](const Json& r, const nlohmann::json& v) {
    EXPECT_EQ(v, nlohmann::json(r["episode_id"]));
  });
  check("steps",
        [](const Json& r, const nlohmann::json& v) { EXPECT_EQ(v, nlohmann::json(r["steps"])); });
  check("met_tolerance", [](const Json& r, const nlohmann::json& v) {
    EXPECT_EQ(v, nlohmann::json(r["met_tolerance"]));
  });
  check("max_pos_err_m", [](const Json& r, const nlohmann::json& v) {
    EXPECT_EQ(v.get<double>(), static_cast<float>(r["max_pos_err_m"].get<double>()));
  });
  check("plan_cost_m", [](const Json& r, const nlohmann::json& v) {
    if (r.contains("plan_cost_m")) {
      EXPECT_EQ(v, nlohmann::json(r["plan_cost_m"]));
    } else {
      EXPECT_TRUE(v.is_null());
    }
  });
  check("contact_bodies", [](const Json& r, const nlohmann::json& v) {
    EXPECT_EQ(v, r["contact_bodies"].empty() ? "" : "robot_3|wall_1");
  });
  check("plan_phase_times_s.sampling", [](const Json& r, const nlohmann::json& v) {
    EXPECT_EQ(v, nlohmann::json(r["plan_phase_times_s"]["sampling"]));
  });
}

TEST(TableColumnsTest, AnEmptyTableHasNoColumns) {
  const nlohmann::json t = tableColumns({});
  EXPECT_EQ(t["rows"], 0);
  EXPECT_TRUE(t["columns"].empty());
}

}  // namespace
}  // namespace parksim

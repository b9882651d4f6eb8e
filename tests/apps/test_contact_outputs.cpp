// What a run reports about its contacts (docs/user-guide.md, summary.json's
// rigid.contacts and warnings; docs/theory/rigid.md section 4a), checked
// against the run's own time histories: under the thesis's bilateral springs
// (`contacts: linear`) the shipped plow's bounce tire pulls, and the fraction
// of samples in which response.csv's bounce_tire_force is negative is the
// reported tension_fraction, with a contact_in_tension warning in summary.json
// and on stderr; with one-sided contacts (the default) no contact pulls, and
// the fraction of samples in which the force is exactly zero is the reported
// lift_off_fraction. The 3-D summary has the same keys with the same meaning.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn::testing;
using Json = nlohmann::json;

std::string shipped(const std::string& name) { return read_file(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/" + name); }

std::string with_contacts(std::string study, const std::string& law) {
  const std::string key = "\nattachment: plow\n";
  const auto at = study.find(key);
  if (at == std::string::npos) throw std::runtime_error("no 'attachment: plow' line");
  return study.insert(at + key.size(), "contacts: " + law + "\n");
}

// One column of response.csv.
std::vector<double> column(const std::string& csv, const std::string& header) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::istringstream h(line);
    std::string cell;
    while (std::getline(h, cell, ',')) names.push_back(cell);
  }
  const auto it = std::find(names.begin(), names.end(), header);
  if (it == names.end()) throw std::runtime_error("no column " + header);
  const std::size_t k = static_cast<std::size_t>(it - names.begin());
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::istringstream r(line);
    std::string cell;
    for (std::size_t i = 0; i <= k; ++i) std::getline(r, cell, ',');
    values.push_back(std::stod(cell));
  }
  return values;
}

struct StudyRun {
  RunResult result;
  Json summary;
  std::string response;
};

StudyRun run_study(const TempDir& dir, const std::string& text) {
  std::ofstream(dir / "study.yaml") << text;
  StudyRun r;
  r.result = framedyn::testing::framedyn(dir, "run study.yaml --out results");  // the default level: warnings on stderr (-q prints errors only)
  if (r.result.status != 0) throw std::runtime_error("framedyn failed: " + r.result.err);
  r.summary = Json::parse(read_file(dir / "results" / "summary.json"));
  r.response = read_file(dir / "results" / "response.csv");
  return r;
}

TEST(ContactOutputs, BilateralBounceTirePullsForTheReportedFractionAndIsWarnedAboutInSummaryAndOnStderr) {
  TempDir dir;
  const StudyRun r = run_study(dir, with_contacts(shipped("r100_plow_2d.yaml"), "linear"));
  const std::vector<double> f = column(r.response, "bounce_tire_force [lbf]");
  const double pulling = static_cast<double>(std::count_if(f.begin(), f.end(), [](double x) { return x < 0; })) / static_cast<double>(f.size());
  const Json& c = r.summary["rigid"]["contacts"]["bounce_tire"];
  EXPECT_GT(pulling, 0.5);
  EXPECT_DOUBLE_EQ(c["tension_fraction"].get<double>(), pulling);
  EXPECT_EQ(c["lift_off_fraction"].get<double>(), 0.0);
  EXPECT_EQ(c["min_force"]["unit"], "lbf");
  // response.csv is printed to about 6 digits; the summary's value is the same sample's force.
  const double least = *std::min_element(f.begin(), f.end());
  EXPECT_NEAR(c["min_force"]["value"].get<double>(), least, 1e-4 * std::abs(least));
  ASSERT_TRUE(r.summary.contains("warnings"));
  bool warned = false;
  for (const Json& w : r.summary["warnings"])
    warned = warned || (w["code"] == "contact_in_tension" && w["message"].get<std::string>().rfind("bounce_tire ", 0) == 0);
  EXPECT_TRUE(warned) << r.summary["warnings"].dump();
  EXPECT_NE(r.result.err.find("framedyn: warning [contact_in_tension]: bounce_tire"), std::string::npos) << r.result.err;
}

// The shipped plow, started from its own statics (docs/theory/rigid.md section 11),
// keeps its bounce tire on the ground (least force 746 lbf of 2,794 at rest:
// docs/validation.md P1.3); with twice the shaker force it lifts the plow off it.
std::string with_shaker_force(std::string study, const std::string& force) {
  const std::string key = "force: 26530,";
  const auto at = study.find(key);
  if (at == std::string::npos) throw std::runtime_error("no 'force: 26530,' in the shaker");
  return study.replace(at, key.size(), "force: " + force + ",");
}

TEST(ContactOutputs, OneSidedContactsNeverPullAndTransmitNothingExactlyWhileLost) {
  TempDir dir;
  const StudyRun r = run_study(dir, with_shaker_force(shipped("r100_plow_2d.yaml"), "53060"));  // the default: unilateral
  for (const auto& [name, c] : r.summary["rigid"]["contacts"].items()) {
    EXPECT_GE(c["min_force"]["value"].get<double>(), 0.0) << name;
    EXPECT_EQ(c["tension_fraction"].get<double>(), 0.0) << name;
  }
  const std::vector<double> f = column(r.response, "bounce_tire_force [lbf]");
  const double zero = static_cast<double>(std::count(f.begin(), f.end(), 0.0)) / static_cast<double>(f.size());
  EXPECT_GT(zero, 0.1);  // the bounce tire is off the ground for a good part of the run (37 %)
  EXPECT_DOUBLE_EQ(r.summary["rigid"]["contacts"]["bounce_tire"]["lift_off_fraction"].get<double>(), zero);
  // No contact pulls, so no contact_in_tension (the run warns of other things:
  // steady operation not reached, docs/validation.md P1.4).
  ASSERT_TRUE(r.summary.contains("warnings"));
  for (const Json& w : r.summary["warnings"]) EXPECT_NE(w["code"], "contact_in_tension") << w.dump();
  EXPECT_EQ(r.result.err.find("[contact_in_tension]"), std::string::npos);
}

// The same run's summary says that steady operation was not reached:
// rigid.steady.reached_at is null (the one null a results file may hold, with
// period_multiple), the warning carries its figures with units, and the peaks
// are start-up peaks only (docs/user-guide.md, "Steady operation").
TEST(ContactOutputs, SummaryReportsSteadyOperationNotReachedAsNullWithTheWarningsFigures) {
  TempDir dir;
  const StudyRun r = run_study(dir, shipped("r100_plow_2d.yaml"));
  const Json& st = r.summary["rigid"]["steady"];
  EXPECT_TRUE(st["reached_at"].is_null());
  EXPECT_TRUE(st["period_multiple"].is_null());
  EXPECT_EQ(st["tolerance"].get<double>(), 0.01);
  EXPECT_EQ(st["peaks"]["plow_force_signed_magnitude"]["start_up"]["unit"], "lbf");
  EXPECT_FALSE(st["peaks"]["plow_force_signed_magnitude"].contains("steady"));
  EXPECT_EQ(st["peaks"]["plow_force_signed_magnitude"]["start_up"]["value"].get<double>(),
            r.summary["rigid"]["response"]["peak_cutting_force"]["value"].get<double>());
  EXPECT_FALSE(st["peaks"].contains("plow_force_angle_deg"));  // a direction, not a load
  bool found = false;
  for (const Json& w : r.summary["warnings"])
    if (w["code"] == "steady_not_reached") {
      found = true;
      EXPECT_EQ(w["figures"]["remaining_change"]["value"].get<double>(), st["remaining_change"]["value"].get<double>());
      EXPECT_EQ(w["figures"]["duration"]["unit"], "s");
    }
  EXPECT_TRUE(found) << r.summary["warnings"].dump();
  EXPECT_NE(r.result.err.find("framedyn: warning [steady_not_reached]"), std::string::npos);
}

TEST(ContactOutputs, ThreeDSummaryReportsEveryTireAndTheBounceTireWithTheSameKeys) {
  TempDir dir;
  const StudyRun r = run_study(dir, with_contacts(shipped("r100_plow_offset.yaml"), "linear"));
  const Json& contacts = r.summary["rigid"]["contacts"];
  for (const char* name : {"front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire", "bounce_tire"}) {
    ASSERT_TRUE(contacts.contains(name)) << name;
    const Json& c = contacts[name];
    for (const char* key : {"min_force", "max_force"}) EXPECT_EQ(c[key]["unit"], "lbf") << name << " " << key;
    EXPECT_LE(c["min_force"]["value"].get<double>(), c["max_force"]["value"].get<double>()) << name;
    EXPECT_EQ(c["lift_off_fraction"].get<double>(), 0.0) << name;
    // tension_fraction > 0 exactly when the least force is negative.
    EXPECT_EQ(c["tension_fraction"].get<double>() > 0.0, c["min_force"]["value"].get<double>() < 0.0) << name;
  }
  EXPECT_FALSE(r.summary["warnings"].empty());  // the offset plow's bounce tire pulls too
}

// rigid.static: one force per contact {value, unit}, every engaged one pushing,
// and the engaged/lifted lists naming every contact once; rigid.modes_by_state
// with its three states: the same keys in 2-D and 3-D (the weight balance is
// checked in tests/rigid/test_contact_statics.cpp).
TEST(ContactOutputs, StaticContactForcesAndModesByStateHaveTheSameKeysIn2DAnd3D) {
  for (const char* example : {"r100_plow_2d.yaml", "r100_plow_offset.yaml"}) {
    TempDir dir;
    const StudyRun r = run_study(dir, shipped(example));
    const Json& s = r.summary["rigid"]["static"];
    ASSERT_TRUE(s.contains("contact_forces")) << example;
    const Json& contacts = r.summary["rigid"]["contacts"];
    std::size_t listed = s["engaged"].size() + s["lifted"].size();
    EXPECT_EQ(listed, contacts.size()) << example;
    EXPECT_EQ(s["contact_forces"].size(), contacts.size()) << example;
    for (const auto& [name, f] : s["contact_forces"].items()) {
      EXPECT_TRUE(contacts.contains(name)) << example << " " << name;
      EXPECT_EQ(f["unit"], "lbf") << example << " " << name;
    }
    for (const Json& name : s["engaged"]) EXPECT_GT(s["contact_forces"][name.get<std::string>()]["value"].get<double>(), 0.0) << example;
    EXPECT_EQ(r.summary["rigid"]["modes_state"], "cutting") << example;
    for (const char* state : {"cutting", "backing_off", "contact_lost"})
      EXPECT_TRUE(r.summary["rigid"]["modes_by_state"].contains(state)) << example << " " << state;
  }
}

}  // namespace

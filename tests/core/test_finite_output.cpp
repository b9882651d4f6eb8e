// No NaN or Inf reaches a results file (core/finite_output.h): every file a
// ResultsFolder writes is checked, and a non-finite number stops the run with
// a message naming the file and where the value is (the row and column of a
// CSV table, the DataArray of a VTU file, the key path of a JSON summary);
// nothing is written and the results folder never appears. Files with only
// finite numbers, and words that merely contain "inf" or "nan", pass.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "report/csv_writer.h"
#include "core/error.h"
#include "core/finite_output.h"
#include "core/results_folder.h"
#include "report/vtu_writer.h"
#include "report/xdmf_writer.h"
#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;
using core::NumericalError;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The message check_finite_output gives for `content` as file `file`, or "" if it passes.
std::string refusal(const std::string& file, const std::string& content) {
  try {
    core::check_finite_output(file, content);
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "";
}

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(FiniteOutput, CsvNaNNamesFileRowColumnAndTheRowsFirstValue) {
  report::CsvTable t({report::column("time", "s"), report::column("z_frame", "m"), report::column("theta_frame", "rad")});
  t.row().add(0.0).add(0.001).add(0.0);
  t.row().add(0.0005).add(0.002).add(kNaN);  // fmt writes "nan"
  const std::string m = refusal("out/response.csv", t.str());
  std::printf("%s\n", m.c_str());
  expect_contains(m, "out/response.csv: row 2 (line 3), column \"theta_frame [rad]\" (where time [s] = 0.0005) is NaN");
  expect_contains(m, "framedyn writes no file with non-finite numbers");
}

TEST(FiniteOutput, CsvInfinitiesOfBothSignsAndQuotedTextColumns) {
  report::CsvTable t({"label", report::column("force", "N")});
  t.row().add(std::string("a, quoted \"label\"")).add(-kInf);
  const std::string m = refusal("sweep.csv", t.str());
  expect_contains(m, "sweep.csv: row 1 (line 2), column \"force [N]\" (where label = a, quoted \"label\") is -infinite (\"-inf\")");
  EXPECT_NE(refusal("a.csv", "x,y\n1,inf\n"), "");
  EXPECT_NE(refusal("a.csv", "x,y\n1,Infinity\n"), "");
  EXPECT_NE(refusal("a.csv", "x,y\n-nan,1\n"), "");
}

TEST(FiniteOutput, LoadHistoryCommentLinesAreNotTheHeader) {
  const std::string text =
      "# framedyn load history\n# units: m-N-s\n# point P24 0 0 0\n"
      "time [s],P24.Fx [N]\n0,1\n0.001,2\n0.002,nan\n";
  const std::string m = refusal("frame_loads.csv", text);
  expect_contains(m, "frame_loads.csv: row 3 (line 7), column \"P24.Fx [N]\" (where time [s] = 0.002) is NaN");
  // A non-finite location in a comment line is given by its line.
  expect_contains(refusal("frame_loads.csv", "# point P24 inf 0 0\ntime [s],P24.Fx [N]\n0,1\n"), "frame_loads.csv: line 1 is infinite");
}

TEST(FiniteOutput, FiniteFilesAndWordsThatContainInfOrNanPass) {
  report::CsvTable t({"dominant", report::column("frequency", "Hz"), "note"});
  t.row().add(std::string("infinite_plane")).add(1.5e-300).add(std::string("nano inference info Nancy"));
  t.row().add(std::string("z")).add(1e300).add(std::string("-"));
  EXPECT_EQ(refusal("modes.csv", t.str()), "");
  EXPECT_EQ(refusal("notes.txt", "information: banana, infinitely nanny\n"), "");
  EXPECT_EQ(refusal("summary.json", R"({"note": "inf", "values": [1, 2.5e-3], "nested": {"name": "nan"}})"), "");
}

TEST(FiniteOutput, VtuNamesTheDataArrayEntryAndComponent) {
  fem::FrameModel model;
  model.nodes = {{1, Eigen::Vector3d(0, 0, 0)}, {2, Eigen::Vector3d(1, 0, 0)}, {3, Eigen::Vector3d(2, 0, 0)}};
  report::VtuField displacement{"displacement", 3, {0, 0, 0, 0.1, 0.2, 0.3, 0.4, kInf, 0.6}};
  const std::string m = refusal("series/frame_response_00012.vtu", report::vtu_document(model, 1.0, {displacement}, {}));
  std::printf("%s\n", m.c_str());
  expect_contains(m, "series/frame_response_00012.vtu: DataArray \"displacement\", entry 2, component 1 (both counted from 0; line ");
  expect_contains(m, "is infinite");
  // A non-finite node coordinate is in the Points array.
  model.nodes[1].position.y() = kNaN;
  expect_contains(refusal("modes.vtu", report::vtu_document(model, 1.0, {}, {})), "modes.vtu: DataArray \"Points\", entry 1, component 1 (both counted from 0;");
}

// The XDMF series' HDF5 arrays are checked as they are written: the message
// names the .h5 file, the field, the step (from 1), entry and component; the
// results folder, never committed, does not appear.
TEST(FiniteOutput, XdmfSeriesNamesTheFieldStepEntryAndComponent) {
  testing::TempDir dir;
  fem::FrameModel model;
  model.nodes = {{1, Eigen::Vector3d(0, 0, 0)}, {2, Eigen::Vector3d(1, 0, 0)}, {3, Eigen::Vector3d(2, 0, 0)}};
  std::string m;
  {
    core::ResultsFolder folder(dir / "out");
    report::XdmfSeries series(folder, "frame_response", model, 1.0, 2);
    series.add(0.0, {{"displacement [m]", 3, std::vector<double>(9, 0.0)}}, {});
    try {
      series.add(0.1, {{"displacement [m]", 3, {0, 0, 0, 0.1, 0.2, 0.3, 0.4, kInf, 0.6}}}, {});
    } catch (const NumericalError& e) {
      m = e.what();
    }
  }
  expect_contains(m, "frame_response.h5: displacement [m] of step 2, entry 2, component 1 (both counted from 0) is infinite");
  EXPECT_FALSE(fs::exists(dir / "out"));
  model.nodes[1].position.y() = kNaN;  // a node coordinate, before any step
  core::ResultsFolder folder(dir / "out2");
  try {
    report::XdmfSeries series(folder, "modes", model, 1.0, 1);
    m.clear();
  } catch (const NumericalError& e) {
    m = e.what();
  }
  expect_contains(m, "modes.h5: the node coordinates, entry 1, component 1 (both counted from 0) is NaN");
}

TEST(FiniteOutput, JsonSummaryNullFromANaNNamesTheKeyPath) {
  nlohmann::json j;
  j["frame"]["modes"] = nlohmann::json::array();
  j["frame"]["modes"].push_back({{"mode", 1}, {"frequency", {{"value", 12.5}, {"unit", "Hz"}}}});
  j["frame"]["modes"].push_back({{"mode", 2}, {"frequency", {{"value", kNaN}, {"unit", "Hz"}}}});  // nlohmann writes null
  const std::string m = refusal("results/summary.json", j.dump(2) + "\n");
  std::printf("%s\n", m.c_str());
  expect_contains(m, "results/summary.json: key frame.modes[1].frequency.value is null (nlohmann::json writes a NaN or an infinity as null)");
  // Hand-written JSON with a bare nan (not valid JSON) is found by its line.
  expect_contains(refusal("summary.json", "{\n  \"a\": 1,\n  \"b\": nan\n}\n"), "summary.json: line 3 is NaN");
}

// Steady operation not reached is written as rigid.steady.reached_at: null
// (and period_multiple: null): those two keys may be null, no other, and a
// NaN under them is still refused.
TEST(FiniteOutput, SteadyOperationNotReachedIsTheOnlyNullASummaryMayHold) {
  nlohmann::json j;
  j["rigid"]["steady"]["reached_at"] = nullptr;
  j["rigid"]["steady"]["period_multiple"] = nullptr;
  j["rigid"]["steady"]["tolerance"] = 0.01;
  EXPECT_NO_THROW(framedyn::core::check_finite_output("summary.json", j.dump(2)));
  j["rigid"]["steady"]["remaining_change"] = kNaN;
  expect_contains(refusal("summary.json", j.dump(2)), "summary.json: key rigid.steady.remaining_change is null");
  j["rigid"]["steady"]["remaining_change"] = 0.5;
  j["rigid"]["steady"]["reached_at"] = {{"value", kNaN}, {"unit", "s"}};
  expect_contains(refusal("summary.json", j.dump(2)), "summary.json: key rigid.steady.reached_at.value is null");
}

TEST(FiniteOutput, ResultsFolderWritesNothingAndLeavesEarlierResults) {
  testing::TempDir dir;
  const fs::path target = dir / "results";
  {
    core::ResultsFolder first(target);
    first.write_text("summary.json", "{\"ok\": 1}\n");
    first.commit();
  }
  try {
    core::ResultsFolder second(target);
    second.write_text("modes.csv", "mode,frequency [Hz]\n1,3.5\n");
    report::CsvTable t({report::column("time", "s"), report::column("a_plow", "m/s^2")});
    t.row().add(0.25).add(kNaN);
    second.write_text("response.csv", t.str());
    ADD_FAILURE() << "no NumericalError";
    second.commit();
  } catch (const NumericalError& e) {
    expect_contains(e.what(), (target / "response.csv").string() + ": row 1 (line 2), column \"a_plow [m/s^2]\"");
  }
  // The earlier results are untouched, and no partial folder is left.
  EXPECT_TRUE(fs::exists(target / "summary.json"));
  EXPECT_FALSE(fs::exists(target / "modes.csv"));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

}  // namespace
}  // namespace framedyn

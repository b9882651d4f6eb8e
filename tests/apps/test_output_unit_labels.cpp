// Units are never typed in (issue 14): every unit an output carries (a CSV
// header's "[unit]", a summary.json "unit" string or *_unit entry, a VTU
// field's "[unit]") is one of the unit system's own labels, core/units'
// UnitSystem::labels(), the table of every quantity. The commands are run as a
// user runs them, on the same cantilever in SI and in inches, and the
// pipeline's shipped inch study; no source is searched. A few columns are
// also checked for the quantity they must carry (the phase in degrees, the
// load PSD in 1/Hz, the displacement PSD in length^2/Hz of the run's system).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/units.h"
#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::core::Quantity;
using framedyn::core::UnitSystem;
using framedyn::testing::framedyn;
using framedyn::testing::read_file;
using framedyn::testing::RunResult;
using framedyn::testing::TempDir;

// A 2 m cantilever of 8 B31 elements, clamped at node 1, loaded at the tip; `units` is its '** units:' line
// (the numbers are the same: only the labels are checked here, test_output_units checks values across systems).
std::string cantilever(const std::string& units) {
  std::string m = "** units: " + units + "\n*NODE, NSET=ALL\n";
  for (int n = 1; n <= 9; ++n) m += std::to_string(n) + ", " + std::to_string(0.25 * (n - 1)) + ", 0, 0\n";
  m += "*NSET, NSET=TIP\n9\n*ELEMENT, TYPE=B31, ELSET=FRAME\n";
  for (int e = 1; e <= 8; ++e) m += std::to_string(e) + ", " + std::to_string(e) + ", " + std::to_string(e + 1) + "\n";
  return m + "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n"
             "*DENSITY\n7850\n*BOUNDARY\n1, ENCASTRE\n*STEP\n*STATIC\n*CLOAD\n9, 3, -1000.\n*END STEP\n";
}

// Every unit a results folder carries, with where it was found.
struct FoundUnit {
  std::string unit, where;
};

std::vector<std::string> csv_header(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') break;  // load-history files open with comment lines
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  return cells;
}

void units_of_json(const nlohmann::json& j, const std::string& path, std::vector<FoundUnit>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string key = it.key();
      if (key == "unit" && it->is_string()) out.push_back({it->get<std::string>(), path + ".unit"});
      else if (key.size() > 5 && key.compare(key.size() - 5, 5, "_unit") == 0 && it->is_object())
        for (auto u = it->begin(); u != it->end(); ++u) out.push_back({u->get<std::string>(), path + "." + key + "." + u.key()});
      else units_of_json(*it, path + "." + key, out);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) units_of_json(j[i], path + "[" + std::to_string(i) + "]", out);
  }
}

std::vector<FoundUnit> units_in(const fs::path& folder) {
  std::vector<FoundUnit> out;
  const std::regex bracket(R"(\[([^\]]*)\]\s*$)");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    const std::string name = f.filename().string();
    if (f.extension() == ".csv") {
      for (const std::string& h : csv_header(f))
        if (std::smatch m; std::regex_search(h, m, bracket)) out.push_back({m[1], name + " column '" + h + "'"});
    } else if (f.extension() == ".json") {
      units_of_json(nlohmann::json::parse(read_file(f)), name, out);
    } else if ((f.extension() == ".vtu" && (name == "modes.vtu" || name == "static.vtu" || name == "frame_response_00000.vtu")) ||
               f.extension() == ".xdmf") {  // the XDMF series: its Attribute names
      const std::string text = read_file(f);
      const std::regex field(R"re(Name="[^"]*\[([^\]"]*)\]")re");
      for (auto it = std::sregex_iterator(text.begin(), text.end(), field); it != std::sregex_iterator(); ++it)
        out.push_back({(*it)[1], name + " field " + it->str()});
    }
  }
  return out;
}

// Each unit found is one of the system's labels; returns how many were checked.
std::size_t expect_table_labels(const fs::path& folder, const UnitSystem& u) {
  const std::vector<std::string> labels = u.labels();
  const std::vector<FoundUnit> found = units_in(folder);
  for (const FoundUnit& f : found)
    EXPECT_NE(std::find(labels.begin(), labels.end(), f.unit), labels.end())
        << folder.filename() << ": " << f.where << ": '" << f.unit << "' is not a label of " << u.name();
  return found.size();
}

bool has_column(const fs::path& csv, const std::string& header) {
  const std::vector<std::string> h = csv_header(csv);
  return std::find(h.begin(), h.end(), header) != h.end();
}

std::string column(const std::string& name, const UnitSystem& u, Quantity q) { return name + " [" + u.label(q) + "]"; }

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

class FrameCommands : public ::testing::TestWithParam<std::string> {};

TEST_P(FrameCommands, EveryUnitOfModesStaticHarmonicAndRandomIsALabelOfTheMeshsUnitSystem) {
  const UnitSystem u = UnitSystem::from_name(GetParam());
  TempDir dir("unit_labels");
  write(dir / "frame.inp", cantilever(u.name()));
  write(dir / "psd.csv", "frequency [Hz],psd [1/Hz]\n1,0.01\n100,0.01\n");
  for (const std::string& args : {std::string("modes frame.inp --modes 4 --mode-shapes-csv --paraview vtu --out modes -q"), std::string("static frame.inp --out static -q"),
                                  std::string("harmonic frame.inp -f 1:100:20 -z 0.02 --no-figures --out harmonic -q"),
                                  std::string("random frame.inp --psd psd.csv -z 0.02 --no-figures --output-set TIP --out random -q")}) {
    const RunResult r = framedyn(dir, args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
  }
  std::size_t checked = 0;
  for (const char* folder : {"modes", "static", "harmonic", "random"}) checked += expect_table_labels(dir / folder, u);
  EXPECT_GT(checked, 60u);  // the count is the outputs' (about 90): a folder read as empty would pass
  EXPECT_TRUE(has_column(dir / "modes" / "modes.csv", column("frequency", u, Quantity::frequency)));
  EXPECT_TRUE(has_column(dir / "modes" / "mode_shapes.csv", column("ux", u, Quantity::mass_normalised_translation)));
  EXPECT_TRUE(has_column(dir / "harmonic" / "frf.csv", column("uz_phase", u, Quantity::angle_degrees)));
  EXPECT_TRUE(has_column(dir / "harmonic" / "frf.csv", column("rx_amplitude", u, Quantity::angle)));
  EXPECT_TRUE(has_column(dir / "random" / "response_psd.csv", column("load_psd", u, Quantity::per_frequency)));
  EXPECT_TRUE(has_column(dir / "random" / "response_psd.csv", column("uz_psd", u, Quantity::translation_psd)));
  EXPECT_TRUE(has_column(dir / "random" / "response_psd.csv", column("rx_psd", u, Quantity::rotation_psd)));
}

INSTANTIATE_TEST_SUITE_P(SiAndInch, FrameCommands, ::testing::Values("m-N-s", "in-lbf-s"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param == "m-N-s" ? std::string("SI") : std::string("Inch"); });

TEST(FrameResponseCommand, EveryUnitOfTheSiPortalFrameIsALabelOfSi) {
  TempDir dir("unit_labels_portal");
  std::string study = read_file(fs::path(FRAMEDYN_SOURCE_DIR) / "examples" / "portal_frame_sway.yaml");
  study.replace(study.find("../meshes/portal_frame.inp"), 26, std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/portal_frame.inp");
  study.replace(study.find("loads: portal_frame_sway_loads.csv"), 34, "loads: " + std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway_loads.csv");
  write(dir / "study.yaml", study);  // the ParaView series by default: frame_response.xdmf
  const RunResult r = framedyn(dir, "frame-response study.yaml --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const UnitSystem si = UnitSystem::si();
  EXPECT_GT(expect_table_labels(dir / "results", si), 100u);
  EXPECT_TRUE(has_column(dir / "results" / "frame_nodes_corners.csv", column("time", si, Quantity::time)));
  EXPECT_TRUE(has_column(dir / "results" / "frame_modes.csv", column("frequency", si, Quantity::frequency)));
}

TEST(PipelineRun, EveryUnitOfTheShippedInchStudyIsALabelOfInLbfS) {
  TempDir dir("unit_labels_pipeline");
  std::string study = read_file(fs::path(FRAMEDYN_SOURCE_DIR) / "examples" / "offset_plowing.yaml");
  study.replace(study.find("../meshes/r100_frame.inp"), 24, std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
  const std::size_t d = study.find("duration: 10.0");
  ASSERT_NE(d, std::string::npos);
  study.replace(d, 14, "duration: 0.05");  // the labels do not depend on the duration
  write(dir / "study.yaml", study);
  const RunResult r = framedyn(dir, "run study.yaml --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const UnitSystem in = UnitSystem::from_name("in-lbf-s");
  EXPECT_GT(expect_table_labels(dir / "results", in), 100u);
  EXPECT_TRUE(has_column(dir / "results" / "response.csv", column("time", in, Quantity::time)));
  EXPECT_TRUE(has_column(dir / "results" / "frame_loads.csv", column("time", in, Quantity::time)));
}

}  // namespace

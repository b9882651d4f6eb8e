// Design studies (`framedyn batch`, issue 19) and the library call under them,
// report::run_study_document (report/study_run.h):
//   - a study run in memory gives summary.json's content byte for byte and writes nothing;
//   - a parsed document changed in memory runs as the same change made in the file.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "coupling/yaml_input.h"
#include "report/study_run.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::testing::TempDir;
namespace report = framedyn::report;

const fs::path kExamples = fs::path(FRAMEDYN_SOURCE_DIR) / "examples";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The shipped plow studies with the shortest runs: 2-D (0.2 s) and 3-D offset plowing (0.2 s).
const fs::path kPlow2D = kExamples / "r100_plow_2d_vertical_path.yaml";
const fs::path kPlow3D = kExamples / "r100_plow_offset.yaml";

TEST(StudyRun, SummaryInMemoryIsSummaryJsonByteForByteAndWritesNothing) {
  for (const auto& [study, model] : {std::pair{kPlow2D, "rigid_2d"}, std::pair{kPlow3D, "rigid_3d"}}) {
    TempDir dir;
    report::StudyRunOptions to_disk;
    to_disk.out = dir / "results";
    const report::StudyRun written = report::run_study_file(study, to_disk);
    const report::StudyRun in_memory = report::run_study_file(study);
    EXPECT_EQ(in_memory.model, model);
    EXPECT_EQ(in_memory.summary.dump(2) + "\n", read_text(dir / "results" / "summary.json")) << study;
    EXPECT_EQ(written.summary, in_memory.summary);
    // Nothing but the folder asked for: no second results folder, no partial one.
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
    EXPECT_EQ(entries, 1u);
  }
}

TEST(StudyRun, DocumentChangedInMemoryRunsAsTheSameChangeInTheFile) {
  TempDir dir;
  YAML::Node doc = framedyn::coupling::load_yaml_file(kPlow2D.string());
  const double damping = doc["soil"]["damping"].as<double>();
  doc["soil"]["damping"] = 2.0 * damping;
  const fs::path changed = dir / "r100_plow_offset.yaml";
  std::ofstream(changed) << YAML::Dump(doc) << "\n";
  const report::StudyRun from_doc = report::run_study_document(doc, changed);
  const report::StudyRun from_file = report::run_study_file(changed);
  EXPECT_EQ(from_doc.summary, from_file.summary);
  const report::StudyRun base = report::run_study_file(kPlow2D);
  EXPECT_NE(base.summary["rigid"]["response"]["peak_cutting_force"]["value"], from_doc.summary["rigid"]["response"]["peak_cutting_force"]["value"]);
}

}  // namespace

// Design studies (`framedyn batch`, issue 19) and the library call under them,
// report::run_study_document (report/study_run.h):
//   - a study run in memory gives summary.json's content byte for byte and writes nothing;
//   - a parsed document changed in memory runs as the same change made in the file;
//   - key paths (the one walker, coupling/study_key_path) set exactly the number they name and refuse
//     what is not one with Study.set's messages, from a design file too;
//   - a pipeline run with its worker's frame model reused gives the summary of a run that builds its own;
//   - a summary computed only for a design's outputs gives the whole run's numbers, its hot spots
//     skipped when no output reads them and kept when one does;
//   - the inverse normal CDF against tabulated quantiles; Latin hypercube strata each sampled once;
//   - standardised regression coefficients of an exactly linear output equal their closed form,
//     Spearman's rho of a monotone output is 1, tied values get average ranks;
//   - the table is byte-identical on 1 and 2 threads; a failed run is recorded and the rest complete;
//     a batch resumed from a checkpoint gives the table of an uninterrupted one;
//   - `framedyn batch --figures` writes whole PNG files whose plotted numbers are runs.csv's
//     (each output against each parameter; the mean per level of a grid), and summary.json lists them;
//   - `framedyn batch` killed (SIGKILL) after a checkpoint and run again with --resume gives the
//     uninterrupted batch's runs.csv and summary.json byte for byte, and leaves the user's files alone;
//   - `sweep` is a special case: a grid over one parameter gives the numbers `framedyn sweep` gives,
//     in 2-D and in 3-D (where `sweep` runs on the batch engine as well), the reference run included;
//   - the sweep under `framedyn sweep` (batch::run_one_parameter_sweep) is nothing but the study run
//     with one number set by hand, whatever the number of threads; the soil damping leaves the
//     undamped natural frequencies alone but changes the response; K5 raises the soil modes;
//     bad requests are input errors naming the key;
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <thread>

#include "batch/batch_figures.h"
#include "batch/design.h"
#include "batch/engine.h"
#include "batch/sampling.h"
#include "batch/sensitivity.h"
#include "batch/sweep_runs.h"
#include "core/error.h"
#include "coupling/frame_model_cache.h"
#include "coupling/parameter_sweep.h"
#include "coupling/rigid_study.h"
#include "coupling/study_key_path.h"
#include "core/number_text.h"
#include "coupling/yaml_input.h"
#include "report/study_run.h"
#include "tests/support/run_framedyn.h"
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

// ------------------------------------------------------------- key paths

namespace batch = framedyn::batch;

const char* kDoc = R"(soil: {stiffness: 40000, damping: 300}
frame:
  parts:
    - {name: frame_structure, from: frame_mesh}
    - {name: engine, weight: 850, position: [40, 0, 14]}
plow: {shaker: {force: 26530, frequency_hz: 18.33}}
)";

TEST(KeyPath, SetsExactlyTheNumberItNamesByKeyIndexOrName) {
  YAML::Node doc = YAML::Load(kDoc);
  using framedyn::coupling::set_study_number;
  set_study_number(doc, "soil.damping", 0.1 + 0.2, "study.yaml");
  set_study_number(doc, "frame.parts[engine].weight", 900, "study.yaml");
  set_study_number(doc, "frame.parts[1].position[2]", -3.5, "study.yaml");
  set_study_number(doc, "plow.shaker.frequency_hz", 20.125, "study.yaml");
  EXPECT_EQ(framedyn::coupling::study_number(doc, "soil.damping", "study.yaml"), 0.1 + 0.2);  // read back exactly (shortest round-trip text)
  EXPECT_EQ(doc["frame"]["parts"][1]["weight"].Scalar(), "900");
  EXPECT_EQ(doc["frame"]["parts"][1]["position"][2].Scalar(), "-3.5");
  EXPECT_EQ(doc["plow"]["shaker"]["frequency_hz"].as<double>(), 20.125);
  EXPECT_EQ(doc["soil"]["stiffness"].as<double>(), 40000.0);  // nothing else changed
  YAML::Node list = YAML::Load("[[1, 2], [3, 4]]");  // a path may begin with an item, and items may follow items
  set_study_number(list, "[1][0]", 7, "study.yaml");
  EXPECT_EQ(list[1][0].Scalar(), "7");
}

// The one walker (coupling/study_key_path) behind Study.set and design files:
// docs/errors.md PY-01 to PY-05, naming the study file, the line of the deepest key found and the path.
TEST(KeyPath, RefusesAnUnknownKeyOrATargetThatIsNotANumberSayingWhatIsThere) {
  YAML::Node doc = YAML::Load(kDoc);
  const auto message = [&](const std::string& path, double value = 1.0) {
    try {
      framedyn::coupling::set_study_number(doc, path, value, "study.yaml");
    } catch (const framedyn::core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("soil.dampin"), "study.yaml:1: soil.dampin: expected a key of the study (soil has stiffness, damping), found no key 'dampin'");
  EXPECT_EQ(message("frame.parts[cab].weight"),
            "study.yaml:4: frame.parts[cab].weight: expected an item of frame.parts (index 0 to 1, or the name of an item), found no item 'cab'");
  EXPECT_EQ(message("frame.parts[2].weight"),
            "study.yaml:4: frame.parts[2].weight: expected an item of frame.parts (index 0 to 1, or the name of an item), found no item '2'");
  EXPECT_EQ(message("frame.parts[0].from").rfind("study.yaml:4: frame.parts[0].from: expected a number there (a key path sets numbers only), found ", 0), 0u);
  EXPECT_EQ(message("plow.shaker").rfind("study.yaml:6: plow.shaker: expected a number there (a key path sets numbers only), found ", 0), 0u);
  EXPECT_EQ(message("soil.damping", std::nan("")), "study.yaml:1: soil.damping: expected a finite number, found nan");
  for (const std::string& bad : std::vector<std::string>{"soil..damping", "parts[", "a.[0]", "a[0]b", "a]", "soil."})
    EXPECT_EQ(message(bad), "study.yaml: " + bad + ": expected a key path: keys joined by '.', a list item as key[index] or key[name], found '" + bad + "'")
        << bad;
}

// A design file's parameter key goes through the same walker: the message is Study.set's, naming the study file.
TEST(KeyPath, ADesignsUnknownParameterKeyGetsTheStudySetMessage) {
  TempDir dir("framedyn_test_batch");
  dir.write("study.yaml", kDoc);
  dir.write("design.yaml",
            "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: monte_carlo, samples: 4}\nparameters:\n"
            "  - {key: soil.dampin, low: 1, high: 2}\noutputs: [frame.peak_normal_stress]\n");
  std::string from_design, from_set;
  try {
    batch::read_batch_design((dir / "design.yaml").string());
  } catch (const framedyn::core::InputError& e) {
    from_design = e.what();
  }
  try {
    YAML::Node doc = YAML::Load(kDoc);
    framedyn::coupling::set_study_number(doc, "soil.dampin", 1.5, (dir / "study.yaml").string());
  } catch (const framedyn::core::InputError& e) {
    from_set = e.what();
  }
  EXPECT_FALSE(from_set.empty());
  EXPECT_EQ(from_design, from_set);
}

// ------------------------------------------------------------- a frame model built once per worker

// The pipeline (examples/offset_plowing.yaml, 0.1 s) with the worker's frame models reused
// (coupling/frame_model_cache.h) gives whole summaries identical to runs that build their own:
// the soil's damping changes only the vehicle's run, so one build serves all three; a part's
// weight changes the frame model, so it makes a second build, and the first is still kept.
TEST(FrameModelReuse, PipelineSummariesWithReuseEqualRunsThatBuildTheirOwn) {
  const fs::path study = kExamples / "offset_plowing.yaml";
  const YAML::Node base = framedyn::coupling::load_yaml_file(study.string());
  const auto summary = [&](double damping, double engine_weight, framedyn::coupling::FrameModelCache* cache) {
    YAML::Node doc = YAML::Clone(base);
    framedyn::coupling::set_study_number(doc, "analysis.response.duration", 0.1, study.string());
    framedyn::coupling::set_study_number(doc, "soil.damping", damping, study.string());
    framedyn::coupling::set_study_number(doc, "frame.parts[engine].weight", engine_weight, study.string());
    report::StudyRunOptions o;
    o.frame_cache = cache;
    return report::run_study_document(doc, study, o).summary.dump(2);
  };
  framedyn::coupling::FrameModelCache cache;
  const std::vector<std::pair<double, double>> runs = {{200, 850}, {300, 850}, {400, 850}, {300, 900}, {250, 850}};
  std::set<std::string> distinct;
  for (const auto& [damping, weight] : runs) {
    const std::string built = summary(damping, weight, nullptr), reused = summary(damping, weight, &cache);
    EXPECT_EQ(reused, built) << "soil.damping " << damping << ", engine weight " << weight;
    distinct.insert(built);
  }
  EXPECT_EQ(distinct.size(), runs.size());  // every run's numbers differ: the reuse is not of results
  EXPECT_EQ(cache.builds(), 2u);            // the 850-lb engine's frame, then the 900-lb engine's
  EXPECT_EQ(cache.reuses(), 3u);            // damping 300 and 400, and 250 back on the first build
}

// The shipped main job cut to 0.1 s, run in memory with the summary computed for a design's
// `outputs` (none: the whole run).
report::StudyRun short_offset_plowing_run(std::optional<std::vector<std::string>> outputs) {
  const fs::path study = kExamples / "offset_plowing.yaml";
  YAML::Node doc = framedyn::coupling::load_yaml_file(study.string());
  framedyn::coupling::set_study_number(doc, "analysis.response.duration", 0.1, study.string());
  report::StudyRunOptions o;
  o.summary_outputs = std::move(outputs);
  return report::run_study_document(doc, study, o);
}

// A design's outputs (StudyRunOptions::summary_outputs) are read from a summary computed only for them:
// a pipeline run whose outputs lie in the rigid block and the frame's rail peaks skips the frame's stress
// histories and hot spots, and every other key of the summary is the whole run's, number for number
// (the same response and recovery, not a cheaper approximation); an output among the hot spots keeps them.
TEST(StudyRun, SummaryOutputsOutsideTheHotSpotsGiveTheWholeRunsNumbersWithoutComputingThem) {
  const auto run = [](std::optional<std::vector<std::string>> outputs) { return short_offset_plowing_run(std::move(outputs)).summary; };
  const nlohmann::ordered_json whole = run(std::nullopt);
  const nlohmann::ordered_json rails = run(std::vector<std::string>{"frame.peak_normal_stress", "rigid.response.peak_cutting_force",
                                                                    "frame.steady.rails.left_rail.peak_abs_normal_stress.steady"});
  const std::set<std::string> hot_spot_keys = {"hot_spots", "hot_spots_by_normal_stress_range", "peak_von_mises", "hot_spot_window"};
  for (const std::string& key : hot_spot_keys) {
    ASSERT_TRUE(whole["frame"].contains(key)) << key;
    EXPECT_FALSE(rails["frame"].contains(key)) << key << ": computed although no output reads it";
  }
  nlohmann::ordered_json frame = whole["frame"];
  for (const std::string& key : hot_spot_keys) frame.erase(key);
  EXPECT_EQ(rails["frame"].dump(2), frame.dump(2));  // modes, loads, rails, static state, steady peaks: the whole run's
  EXPECT_EQ(rails["rigid"].dump(2), whole["rigid"].dump(2));
  EXPECT_NE(rails["frame"]["peak_normal_stress"]["value"].get<double>(), 0.0);  // signed: the largest magnitude, here compressive
  // An output among the hot spots (by key or as a map's item by name) keeps them, with the whole run's numbers.
  for (const char* path : {"frame.peak_von_mises", "frame[hot_spots][0]"}) {
    const nlohmann::ordered_json hot = run(std::vector<std::string>{path, "frame.peak_normal_stress"});
    EXPECT_EQ(hot["frame"].dump(2), whole["frame"].dump(2)) << path;
  }
}

// Outputs all in the rigid block (a design on the vehicle's response, a sweep: "rigid" names the whole
// block) need no frame: the run skips it, and its input and rigid blocks are the whole run's, number for
// number (the vehicle's response does not depend on the frame model); any frame path runs the frame.
TEST(StudyRun, SummaryOutputsInTheRigidBlockAloneSkipTheFrameAndGiveTheWholeRunsRigidNumbers) {
  const auto run = [](std::optional<std::vector<std::string>> outputs) { return short_offset_plowing_run(std::move(outputs)); };
  const report::StudyRun whole = run(std::nullopt);
  ASSERT_TRUE(whole.summary.contains("frame"));
  for (const std::vector<std::string>& outputs : {std::vector<std::string>{"rigid"},
                                                  std::vector<std::string>{"rigid.response.peak_cutting_force", "rigid.modes[0].frequency", "input.name"}}) {
    const report::StudyRun vehicle = run(outputs);
    EXPECT_FALSE(vehicle.summary.contains("frame")) << outputs.front() << ": the frame was run although no output reads it";
    EXPECT_EQ(vehicle.summary["rigid"].dump(2), whole.summary["rigid"].dump(2)) << outputs.front();
    EXPECT_EQ(vehicle.summary["input"].dump(2), whole.summary["input"].dump(2)) << outputs.front();
    EXPECT_GT(vehicle.summary["rigid"]["response"]["peak_cutting_force"]["value"].get<double>(), 0.0);
  }
  for (const char* path : {"frame.modes[0].frequency", "warnings", "fatigue.min_life"}) {
    const report::StudyRun with_frame = run(std::vector<std::string>{"rigid.response.peak_cutting_force", path});
    EXPECT_EQ(with_frame.summary["frame"]["modes"].dump(2), whole.summary["frame"]["modes"].dump(2)) << path;
  }
}

// ------------------------------------------------------------- sampling

TEST(Sampling, NormalQuantileMatchesTabulatedValuesAndInvertsTheCdf) {
  // Tabulated standard normal quantiles (Abramowitz and Stegun, Table 26.5).
  EXPECT_NEAR(batch::standard_normal_quantile(0.975), 1.959963984540054, 1e-13);
  EXPECT_NEAR(batch::standard_normal_quantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(batch::standard_normal_quantile(0.001), -3.090232306167814, 1e-12);
  EXPECT_NEAR(batch::standard_normal_cdf(1.0), 0.8413447460685429, 1e-15);
  for (double p : {1e-9, 1e-4, 0.02, 0.3, 0.7, 0.98, 1 - 1e-6}) EXPECT_NEAR(batch::standard_normal_cdf(batch::standard_normal_quantile(p)), p, 1e-14 + 1e-12 * p);
}

TEST(Sampling, LatinHypercubeSamplesEachStratumOfEveryParameterExactlyOnce) {
  batch::Sampling s{batch::SamplingMethod::latin_hypercube, 17, 42};
  std::vector<batch::ParameterSpec> params(4);
  params[0].distribution = batch::Distribution::uniform, params[0].low = 150, params[0].high = 450;
  params[1].distribution = batch::Distribution::normal, params[1].mean = 4e4, params[1].std_dev = 4e3;
  params[2].distribution = batch::Distribution::lognormal, params[2].median = 2.0, params[2].log_std = 0.3;
  params[3].distribution = batch::Distribution::truncated_normal, params[3].mean = 0, params[3].std_dev = 1, params[3].low = -0.5, params[3].high = 2;
  const auto rows = batch::draw_samples(s, params);
  ASSERT_EQ(rows.size(), 17u);
  for (std::size_t j = 0; j < params.size(); ++j) {
    std::set<std::size_t> strata;
    for (const auto& row : rows) strata.insert(batch::stratum_of(batch::cdf(params[j], row[j]), 17));
    EXPECT_EQ(strata.size(), 17u) << "parameter " << j;
  }
  EXPECT_EQ(batch::draw_samples(s, params), rows);  // the same seed, the same samples
}

TEST(Sampling, GridRunsEveryCombinationWithTheLastParameterFastest) {
  std::vector<batch::ParameterSpec> params(2);
  params[0].values = {1, 2};
  params[1].values = {10, 20, 30};
  const auto rows = batch::draw_samples({batch::SamplingMethod::grid, 0, 1}, params);
  const std::vector<std::vector<double>> expected = {{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
  EXPECT_EQ(rows, expected);
}

// ------------------------------------------------------------- sensitivity

TEST(Sensitivity, RegressionCoefficientsOfAnExactlyLinearOutputEqualTheClosedForm) {
  // y = 2 a - b: SRC_a = 2 s_a / s_y, SRC_b = -s_b / s_y, s_y^2 = 4 s_a^2 + s_b^2 - 4 cov(a, b) (sample moments).
  const std::vector<double> a = {1, 2, 3, 4, 5, 6, 7, 9}, b = {3, 1, 4, 1, 5, 9, 2, 6};
  std::vector<std::vector<double>> x;
  std::vector<double> y;
  for (std::size_t i = 0; i < a.size(); ++i) {
    x.push_back({a[i], b[i]});
    y.push_back(2 * a[i] - b[i]);
  }
  const auto mean = [](const std::vector<double>& v) { double m = 0; for (double e : v) m += e; return m / v.size(); };
  const auto cov = [&](const std::vector<double>& u, const std::vector<double>& v) {
    double c = 0, mu = mean(u), mv = mean(v);
    for (std::size_t i = 0; i < u.size(); ++i) c += (u[i] - mu) * (v[i] - mv);
    return c / (u.size() - 1);
  };
  const double sy = std::sqrt(4 * cov(a, a) + cov(b, b) - 4 * cov(a, b));
  const auto src = batch::standardised_regression_coefficients(x, y);
  ASSERT_TRUE(src);
  EXPECT_NEAR((*src)[0], 2 * std::sqrt(cov(a, a)) / sy, 1e-12);
  EXPECT_NEAR((*src)[1], -std::sqrt(cov(b, b)) / sy, 1e-12);
  EXPECT_EQ(batch::ranking(*src), (std::vector<std::size_t>{0, 1}));
}

TEST(Sensitivity, SpearmanOfAMonotoneOutputIsOneAndTiesGetAverageRanks) {
  const std::vector<double> a = {0.3, -1.2, 2.5, 0.9, 1.7, -0.4};
  std::vector<double> up, down;
  for (double v : a) {
    up.push_back(std::exp(3 * v));
    down.push_back(-v * v * v);
  }
  EXPECT_DOUBLE_EQ(*batch::spearman(a, up), 1.0);
  EXPECT_DOUBLE_EQ(*batch::spearman(a, down), -1.0);
  EXPECT_EQ(batch::average_ranks({5, 1, 3, 3, 9, 3}), (std::vector<double>{5, 1, 3, 3, 6, 3}));
  EXPECT_EQ(batch::average_ranks({2, 2}), (std::vector<double>{1.5, 1.5}));
  EXPECT_FALSE(batch::spearman({1, 1, 1}, {1, 2, 3}));  // a constant series has no rank correlation
  // A near-tie of coefficients keeps parameter order, whatever the round-off.
  EXPECT_EQ(batch::ranking({0.5, -0.5 * (1 + 1e-9), 0.9}), (std::vector<std::size_t>{2, 0, 1}));
}

// ------------------------------------------------------------- engine

// A Latin hypercube over the 2-D plow's soil (8 runs of 0.05 s). With a damping
// range reaching below zero, some samples are refused by the study reader:
// failed runs, recorded, while the rest complete.
std::string design_text(const std::string& damping) {
  return "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: latin_hypercube, samples: 8, seed: 3}\nparameters:\n"
         "  - {key: soil.stiffness, distribution: uniform, low: 30000, high: 50000}\n  - " + damping +
         "\noutputs:\n  - rigid.response.peak_cutting_force\n  - rigid.modes[0].frequency\n";
}

TEST(BatchEngine, TableIsByteIdenticalOnOneAndTwoThreadsAndAFailedRunIsRecorded) {
  TempDir dir;
  fs::copy_file(kPlow2D, dir / "study.yaml");
  dir.write("design.yaml", design_text("{key: soil.damping, distribution: uniform, low: -300, high: 450}"));
  const batch::BatchDesign d = batch::read_batch_design((dir / "design.yaml").string());
  batch::BatchOptions one, two;
  one.out = dir / "one";
  two.out = dir / "two";
  two.threads = 2;
  const batch::BatchCounts c1 = batch::run_batch(d, one);
  batch::run_batch(d, two);
  const std::string table = read_text(dir / "one" / "runs.csv");
  EXPECT_EQ(table, read_text(dir / "two" / "runs.csv"));
  EXPECT_EQ(c1.total, 8u);
  EXPECT_GE(c1.failed, 1u);  // the negative dampings
  EXPECT_GE(c1.done, 4u);
  EXPECT_EQ(c1.done + c1.failed, 8u);
  EXPECT_NE(table.find(",failed,"), std::string::npos);
  EXPECT_NE(table.find("soil.damping: expected"), std::string::npos) << table;  // the reader's own message, with the key
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "one" / "summary.json"));
  EXPECT_EQ(summary["runs"]["failed"], c1.failed);
  EXPECT_EQ(summary["complete"], true);
  EXPECT_EQ(summary["figures"], nlohmann::json::array());  // no --figures: an empty list
}

TEST(BatchEngine, BatchResumedFromACheckpointGivesTheUninterruptedTable) {
  TempDir dir;
  fs::copy_file(kPlow2D, dir / "study.yaml");
  dir.write("design.yaml", design_text("{key: soil.damping, distribution: uniform, low: 150, high: 450}"));
  const batch::BatchDesign d = batch::read_batch_design((dir / "design.yaml").string());
  batch::BatchOptions whole;
  whole.out = dir / "whole";
  batch::run_batch(d, whole);
  // A batch stopped after three runs: its last checkpoint holds rows 0, 2 and 5 (threads finish out of order).
  batch::BatchOptions part;
  part.out = dir / "part";
  const auto samples = batch::design_samples(d);
  std::vector<batch::RunRecord> rows(samples.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].index = i;
  for (std::size_t i : {0, 2, 5}) rows[i] = batch::run_sample(d, i, samples[i]);
  batch::write_batch_folder(d, rows, part);
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "part" / "summary.json"))["complete"], false);
  part.resume = true;
  const batch::BatchCounts c = batch::run_batch(d, part);
  EXPECT_EQ(c.skipped, 3u);
  EXPECT_EQ(read_text(dir / "part" / "runs.csv"), read_text(dir / "whole" / "runs.csv"));
  EXPECT_EQ(read_text(dir / "part" / "summary.json"), read_text(dir / "whole" / "summary.json"));
}

// framedyn sweep's sweep.csv row by row: the parameter and the three response
// peaks, as text (both tables write 10 significant digits).
TEST(BatchEngine, GridOverOneParameterGivesTheNumbersOfFramedynSweep) {
  TempDir dir;
  fs::copy_file(kPlow2D, dir / "study.yaml");
  const auto sweep = framedyn::testing::framedyn(dir, "sweep study.yaml -p soil.damping --values 200,300,400 --no-figures --out sweep -q");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  dir.write("design.yaml",
            "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: grid}\nparameters:\n  - {key: soil.damping, values: [200, 300, 400]}\n"
            "outputs:\n  - rigid.response.plow_vertical_pp\n  - rigid.response.peak_cutting_force\n  - rigid.response.peak_backing_force\n");
  batch::BatchOptions opt;
  opt.out = dir / "grid";
  batch::run_batch(batch::read_batch_design((dir / "design.yaml").string()), opt);
  std::istringstream sw(read_text(dir / "sweep" / "sweep.csv")), grid(read_text(dir / "grid" / "runs.csv"));
  std::string a, b;
  std::getline(sw, a);
  std::getline(grid, b);
  EXPECT_EQ(b, "index,soil.damping [in-lbf-s],rigid.response.plow_vertical_pp [in],rigid.response.peak_cutting_force [lbf],"
               "rigid.response.peak_backing_force [lbf],status,message");
  int rows = 0;
  while (std::getline(sw, a) && std::getline(grid, b)) {
    std::vector<std::string> ca, cb;
    std::istringstream la(a), lb(b);
    for (std::string c; std::getline(la, c, ',');) ca.push_back(c);
    for (std::string c; std::getline(lb, c, ',');) cb.push_back(c);
    ASSERT_GE(ca.size(), 4u);
    ASSERT_GE(cb.size(), 6u);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(ca[k], cb[k + 1]) << "row " << rows << " column " << k;
    EXPECT_EQ(cb[5], "done");
    ++rows;
  }
  EXPECT_EQ(rows, 3);
}

// `framedyn sweep` on the 3-D offset plow (0.1 s): its rows and its reference run
// (the study's own damping, 300, not among the values) are the batch grid's
// runs of the same values, as text; the relative changes are (value - reference)
// / reference of those numbers.
TEST(BatchEngine, SweepOfA3DStudyGivesTheNumbersOfTheBatchGrid) {
  TempDir dir;
  std::string study = read_text(kPlow3D);
  const std::size_t at = study.find("duration: 0.5,");
  ASSERT_NE(at, std::string::npos) << "the shipped study's duration changed";
  study.replace(at, 14, "duration: 0.1,");
  dir.write("study.yaml", study);
  const auto sweep = framedyn::testing::framedyn(dir, "sweep study.yaml -p soil.damping --values 200,400 --no-figures --out sweep -j 2 -q");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  dir.write("design.yaml",
            "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: grid}\nparameters:\n  - {key: soil.damping, values: [200, 300, 400]}\n"
            "outputs:\n  - rigid.response.plow_vertical_pp\n  - rigid.response.peak_cutting_force\n");
  batch::BatchOptions opt;
  opt.out = dir / "grid";
  batch::run_batch(batch::read_batch_design((dir / "design.yaml").string()), opt);
  const auto cells = [](const std::string& line) {
    std::vector<std::string> c;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) c.push_back(cell);
    return c;
  };
  std::vector<std::vector<std::string>> sw, grid;
  std::istringstream a(read_text(dir / "sweep" / "sweep.csv")), b(read_text(dir / "grid" / "runs.csv"));
  for (std::string line; std::getline(a, line);) sw.push_back(cells(line));
  for (std::string line; std::getline(b, line);) grid.push_back(cells(line));
  ASSERT_EQ(sw.size(), 3u);    // header, 200, 400
  ASSERT_EQ(grid.size(), 4u);  // header, 200, 300, 400
  EXPECT_EQ(sw[0][0], "soil.damping [lbf*s/in]");
  for (const auto& [row, run] : {std::pair{1, 1}, std::pair{2, 3}}) {
    EXPECT_EQ(sw[row][0], grid[run][1]);  // the damping
    EXPECT_EQ(sw[row][1], grid[run][2]);  // plow_vertical_pp
    EXPECT_EQ(sw[row][2], grid[run][3]);  // peak_cutting_force
    ASSERT_EQ(grid[run][4], "done");
  }
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "sweep" / "summary.json"));
  const nlohmann::json& ref = summary["sweep"]["reference"];
  EXPECT_EQ(ref["in_values"], false);
  EXPECT_EQ(ref["parameter"]["value"], 300.0);
  EXPECT_EQ(framedyn::core::format_number(ref["peak_cutting_force"]["value"].get<double>()), grid[2][3]);
  EXPECT_EQ(framedyn::core::format_number(ref["plow_vertical_pp"]["value"].get<double>()), grid[2][2]);
  for (int row : {1, 2}) {
    const double v = std::stod(sw[row][2]), r = std::stod(grid[2][3]);
    EXPECT_NEAR(std::stod(sw[row][7]), 100.0 * (v - r) / r, 1e-6) << "row " << row;  // peak_cutting_force_change [%], from 10-digit text
  }
}

// ------------------------------------------------------------- figures

// A PNG file that is whole: the signature, and the IEND chunk as its last 12 bytes.
bool whole_png(const fs::path& p) {
  const std::string b = read_text(p);
  const std::string signature = "\x89PNG\r\n\x1a\n", iend = std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return b.size() > 1000 && b.compare(0, 8, signature) == 0 && b.compare(b.size() - 12, 12, iend) == 0;
}

// A grid of 3 dampings x 2 stiffnesses of the 2-D plow (0.1 s each) with
// --figures: one scatter and one main-effect figure per output, each a whole
// PNG; each panel's points are runs.csv's columns (parsed here on their own),
// each main-effect point the mean of the output over the runs at that level.
TEST(BatchFigures, ScatterAndMainEffectFiguresPlotTheNumbersOfRunsCsv) {
  TempDir dir;
  std::string study = read_text(kPlow2D);
  const std::size_t at = study.find("duration: 0.5,");
  ASSERT_NE(at, std::string::npos) << "the shipped study's duration changed";
  study.replace(at, 14, "duration: 0.1,");
  dir.write("study.yaml", study);
  dir.write("design.yaml",
            "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: grid}\nparameters:\n  - {key: soil.damping, values: [200, 300, 400]}\n"
            "  - {key: soil.stiffness, values: [30000, 50000]}\noutputs:\n  - rigid.response.peak_cutting_force\n  - rigid.modes[0].frequency\n");
  const auto r = framedyn::testing::framedyn(dir, "batch design.yaml --out results --figures -j 2 -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> files = {"scatter_1_rigid.response.peak_cutting_force.png", "scatter_2_rigid.modes_0_.frequency.png",
                                          "main_effects_1_rigid.response.peak_cutting_force.png", "main_effects_2_rigid.modes_0_.frequency.png"};
  for (const std::string& f : files) EXPECT_TRUE(whole_png(dir / "results" / f)) << f;
  // summary.json names the figure files it wrote, relative to the folder, and nothing else is in it.
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "results" / "summary.json"))["figures"], nlohmann::json(files));
  std::set<std::string> in_folder;
  for (const auto& e : fs::directory_iterator(dir / "results")) in_folder.insert(e.path().filename().string());
  std::set<std::string> expected(files.begin(), files.end());
  expected.insert({"runs.csv", "summary.json", ".framedyn-manifest"});
  EXPECT_EQ(in_folder, expected);

  // runs.csv on its own: index, damping, stiffness, force, frequency, status, message.
  std::vector<std::vector<double>> table;
  std::istringstream csv(read_text(dir / "results" / "runs.csv"));
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::vector<std::string> c;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) c.push_back(cell);
    ASSERT_GE(c.size(), 6u);
    ASSERT_EQ(c[5], "done");
    table.push_back({std::stod(c[1]), std::stod(c[2]), std::stod(c[3]), std::stod(c[4])});
  }
  ASSERT_EQ(table.size(), 6u);

  const batch::BatchDesign d = batch::read_batch_design((dir / "design.yaml").string());
  const auto figures = report::design_figures(batch::design_table(d, batch::read_runs_csv(d, dir / "results" / "runs.csv")));
  ASSERT_EQ(figures.size(), files.size());
  for (std::size_t k = 0; k < figures.size(); ++k) {
    EXPECT_EQ(figures[k].file, files[k]);
    const std::size_t o = k % 2;  // the output
    const bool main_effects = k >= 2;
    ASSERT_EQ(figures[k].figure.panels.size(), 2u);
    for (std::size_t p = 0; p < 2; ++p) {
      const report::PlotSeries& s = figures[k].figure.panels[p].series.at(0);
      EXPECT_EQ(figures[k].figure.panels[p].x_label, p == 0 ? "soil.damping" : "soil.stiffness");
      if (!main_effects) {
        ASSERT_EQ(s.x.size(), table.size());
        for (std::size_t i = 0; i < table.size(); ++i) {
          EXPECT_EQ(s.x[i], table[i][p]);
          EXPECT_EQ(s.y[i], table[i][2 + o]);
        }
        continue;
      }
      std::map<double, std::vector<double>> levels;
      for (const auto& row : table) levels[row[p]].push_back(row[2 + o]);
      ASSERT_EQ(s.x.size(), levels.size());
      std::size_t i = 0;
      for (const auto& [level, ys] : levels) {
        double sum = 0.0;
        for (double y : ys) sum += y;
        EXPECT_EQ(s.x[i], level);
        EXPECT_DOUBLE_EQ(s.y[i], sum / static_cast<double>(ys.size())) << "level " << level;
        ++i;
      }
    }
  }
}

// ------------------------------------------------------------- one-parameter sweeps

// The shipped 2-D plow (0.5 s, cut-face reading), as `framedyn sweep` runs it.
const fs::path kSweepStudy = kExamples / "r100_plow_2d.yaml";

// lbf*s/in of the study file into SI, as the reader converts them.
double damping_si(const framedyn::coupling::RigidStudy& s, double v) {
  return s.units.to_si(v, framedyn::core::Quantity::translational_damping);
}

batch::OneParameterSweepResult sweep(const fs::path& study, const std::string& key, const std::vector<double>& values, int threads) {
  batch::OneParameterSweep q;
  q.study_file = study.string();
  q.key = key;
  q.values = values;
  q.threads = threads;
  return batch::run_one_parameter_sweep(q);
}

void expect_same(const framedyn::coupling::SweepPoint& p, const framedyn::coupling::RigidResults& r) {
  ASSERT_TRUE(r.plow_vertical_peak_to_peak && r.peak_cutting_force && r.peak_backing_force);
  ASSERT_TRUE(p.plow_vertical_pp && p.peak_cutting_force && p.peak_backing_force);
  // Exact: the same computation on the same data, on whichever thread.
  EXPECT_EQ(*p.plow_vertical_pp, *r.plow_vertical_peak_to_peak);
  EXPECT_EQ(*p.peak_cutting_force, *r.peak_cutting_force);
  EXPECT_EQ(*p.peak_backing_force, *r.peak_backing_force);
  ASSERT_EQ(p.frequencies_hz.size(), r.modes.size());
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    EXPECT_EQ(p.frequencies_hz[m], r.modes[m].frequency_hz);
    EXPECT_EQ(p.dominant[m], r.modes[m].dominant);
  }
}

TEST(OneParameterSweep, SoilDampingSweepEqualsSeparateRunsWithTheParameterSetByHand) {
  namespace coupling = framedyn::coupling;
  const coupling::RigidStudy study = coupling::read_rigid_study(kSweepStudy.string());
  const batch::OneParameterSweepResult out = sweep(kSweepStudy, "soil.damping", {200, 400}, 2);
  const coupling::SweepResult& s = out.result;
  EXPECT_EQ(s.parameter, "soil.damping");
  EXPECT_EQ(s.quantity, framedyn::core::Quantity::translational_damping);
  EXPECT_EQ(out.parameter_unit, "lbf*s/in");
  ASSERT_EQ(s.points.size(), 2u);
  const std::vector<double> values = {damping_si(study, 200), damping_si(study, 400)};
  for (std::size_t i = 0; i < values.size(); ++i) {
    coupling::RigidStudy by_hand = study;
    coupling::set_parameter(by_hand.machine, "soil.damping", values[i]);
    SCOPED_TRACE(i);
    EXPECT_EQ(s.points[i].value, values[i]);
    expect_same(s.points[i], coupling::run_rigid_study(by_hand));
  }
  // The study's own C5 = 300 is not among the values: run on its own as the reference.
  EXPECT_EQ(s.reference_index, -1);
  EXPECT_EQ(s.reference.value, damping_si(study, 300));
  expect_same(s.reference, coupling::run_rigid_study(study));
}

TEST(OneParameterSweep, ThreadsGiveTheSameResultsAsASequentialSweep) {
  const std::vector<double> values = {100, 200, 300, 400, 500};
  const framedyn::coupling::SweepResult one = sweep(kSweepStudy, "soil.damping", values, 1).result;
  const framedyn::coupling::SweepResult two = sweep(kSweepStudy, "soil.damping", values, 2).result;
  const framedyn::coupling::SweepResult many = sweep(kSweepStudy, "soil.damping", values, 8).result;
  for (const framedyn::coupling::SweepResult* other : {&two, &many}) {
    ASSERT_EQ(other->points.size(), one.points.size());
    for (std::size_t i = 0; i < one.points.size(); ++i) {
      EXPECT_EQ(other->points[i].plow_vertical_pp, one.points[i].plow_vertical_pp) << i;
      EXPECT_EQ(other->points[i].peak_cutting_force, one.points[i].peak_cutting_force) << i;
      EXPECT_EQ(other->points[i].peak_backing_force, one.points[i].peak_backing_force) << i;
      EXPECT_EQ(other->points[i].frequencies_hz, one.points[i].frequencies_hz) << i;
    }
    EXPECT_EQ(other->reference_index, 2);
  }
}

TEST(OneParameterSweep, SoilDampingChangesTheResponseButNotTheNaturalFrequencies) {
  // The modes are those of M and K; C5 is in C only. The response, driven at
  // 18.33 Hz through the soil, does feel C5 (thesis: plowing is mainly
  // velocity-dependent), so the C5 sweep must move the amplitude and forces.
  namespace coupling = framedyn::coupling;
  const coupling::SweepResult s = sweep(kSweepStudy, "soil.damping", {100, 300, 500}, 2).result;
  ASSERT_EQ(s.reference_index, 1);
  EXPECT_EQ(s.points[0].frequencies_hz, s.points[1].frequencies_hz);
  EXPECT_EQ(s.points[2].frequencies_hz, s.points[1].frequencies_hz);
  EXPECT_EQ(coupling::relative_change(s.points[1].plow_vertical_pp, s.reference.plow_vertical_pp), 0.0);
  EXPECT_GT(std::abs(*coupling::relative_change(s.points[0].plow_vertical_pp, s.reference.plow_vertical_pp)), 0.01);
  EXPECT_GT(std::abs(*coupling::relative_change(s.points[2].peak_backing_force, s.reference.peak_backing_force)), 0.01);
}

TEST(OneParameterSweep, SoilStiffnessRaisesTheSoilModes) {
  // K5 stiffens the plow on the ground: no natural frequency may fall as K5 rises.
  // The modes are those of the state the response cuts in (docs/theory/rigid.md
  // section 11), so the sweep is made in Eq. 2.37's printed reading
  // (spring_reference: equilibrium), where a cutting blade is held by K5 (the
  // shipped cut-face reading has no spring while cutting).
  TempDir dir;
  std::string study = read_text(kSweepStudy);
  const std::string cut_face = "spring_reference: cut_face";
  const std::size_t at = study.find(cut_face);
  ASSERT_NE(at, std::string::npos) << "the shipped study's soil reading changed";
  study.replace(at, cut_face.size(), "spring_reference: equilibrium");
  dir.write("study.yaml", study);
  const framedyn::coupling::SweepResult s = sweep(dir / "study.yaml", "soil.stiffness", {20000, 60000}, 2).result;
  ASSERT_EQ(s.points[0].frequencies_hz.size(), s.points[1].frequencies_hz.size());
  bool one_rises = false;
  for (std::size_t m = 0; m < s.points[0].frequencies_hz.size(); ++m) {
    EXPECT_GE(s.points[1].frequencies_hz[m], s.points[0].frequencies_hz[m]) << "mode " << m + 1;
    one_rises = one_rises || s.points[1].frequencies_hz[m] > 1.05 * s.points[0].frequencies_hz[m];
  }
  EXPECT_TRUE(one_rises);
}

TEST(OneParameterSweep, BadRequestsAreInputErrorsNamingTheKey) {
  TempDir dir;
  const auto expect_error = [&](const fs::path& study, const std::string& key, const std::vector<double>& values, const std::string& text) {
    try {
      (void)sweep(study, key, values, 1);
      ADD_FAILURE() << "no error for " << text;
    } catch (const framedyn::core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  expect_error(kSweepStudy, "soil.viscosity", {1.0}, "soil.viscosity: expected a key of the study");
  expect_error(kSweepStudy, "soil.viscosity", {1.0}, "stiffness, damping");  // the message names what soil has
  expect_error(kSweepStudy, "soil.damping", {}, "--values: expected at least one value");
  expect_error(kSweepStudy, "soil.damping", {-1.0}, "soil.damping");  // the study reader refuses the run's value, naming the key
  std::string study = read_text(kSweepStudy);
  const std::size_t at = study.find("  response: {");
  ASSERT_NE(at, std::string::npos);
  study.erase(at, study.find('\n', at) + 1 - at);
  dir.write("no_response.yaml", study);
  expect_error(dir / "no_response.yaml", "soil.damping", {1.0}, "analysis.response: expected a forced response to sweep");
}

// ------------------------------------------------------------- kill and resume

// `framedyn ARGS...` started in `dir` as a child process (stdout and stderr to
// /dev/null), so that the test can kill it at a moment of its choosing.
pid_t start_framedyn(const fs::path& dir, std::vector<std::string> args) {
  args.insert(args.begin(), FRAMEDYN_BINARY);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    std::FILE* null = std::fopen("/dev/null", "w");
    if (null) ::dup2(::fileno(null), 1), ::dup2(::fileno(null), 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// The user's files below `folder` (relative path -> content): all but framedyn's
// results folders "results" and "whole" and partial folders "results.partial-<pid>".
std::map<std::string, std::string> user_files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    const std::string rel = fs::relative(e.path(), folder).generic_string();
    const std::string top = rel.substr(0, rel.find('/'));
    if (top == "results" || top == "whole" || top.rfind("results.partial-", 0) == 0 || e.is_directory()) continue;
    files[rel] = read_text(e.path());
  }
  return files;
}

// A grid of 20 runs of the 2-D plow (0.2 s each) on one thread, checkpointed
// every 2 runs, is killed with SIGKILL as soon as its first checkpoint is in
// place (nothing catches SIGKILL: the process stops between any two
// instructions, possibly half-way through writing the next checkpoint). Run
// again with --resume, it must read the checkpoint's runs back, do the others
// and give the uninterrupted batch's runs.csv and summary.json byte for byte;
// the user's files (the inputs and a note beside them) are as they were.
TEST(BatchEngine, BatchKilledAfterACheckpointAndResumedGivesTheUninterruptedTable) {
  TempDir dir;
  std::string study = read_text(kPlow2D);
  const std::size_t at = study.find("duration: 0.5,");
  ASSERT_NE(at, std::string::npos) << "the shipped study's duration changed";
  study.replace(at, 14, "duration: 0.2,");
  dir.write("study.yaml", study);
  std::string dampings;
  for (int k = 0; k < 20; ++k) dampings += (k ? ", " : "") + std::to_string(150 + 20 * k);
  dir.write("design.yaml", "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: grid}\nparameters:\n  - {key: soil.damping, values: [" +
                               dampings + "]}\noutputs:\n  - rigid.response.peak_cutting_force\n  - rigid.modes[0].frequency\n");
  dir.write("notes.txt", "the user's own notes\n");
  const std::map<std::string, std::string> before = user_files(dir.path());

  const auto whole = framedyn::testing::framedyn(dir, "batch design.yaml --out whole -j 1 --checkpoint 2 -q");
  ASSERT_EQ(whole.status, 0) << whole.err;

  const pid_t pid = start_framedyn(dir.path(), {"batch", "design.yaml", "--out", "results", "-j", "1", "--checkpoint", "2", "-q"});
  ASSERT_GT(pid, 0);
  const auto start = std::chrono::steady_clock::now();
  bool killed = false;
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
    if (fs::exists(dir / "results" / "runs.csv")) {  // a checkpoint is committed (one rename: whole or absent)
      ::kill(pid, SIGKILL);
      killed = true;
      break;
    }
    int raw = 0;
    if (::waitpid(pid, &raw, WNOHANG) == pid) break;  // ended before its first checkpoint: nothing to resume
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(killed) << "the batch ended (or took 60 s) before its first checkpoint";
  int raw = 0;
  ASSERT_EQ(::waitpid(pid, &raw, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(raw) && WTERMSIG(raw) == SIGKILL) << "the batch finished before the kill reached it";
  const nlohmann::json checkpoint = nlohmann::json::parse(read_text(dir / "results" / "summary.json"));
  EXPECT_EQ(checkpoint["complete"], false);
  const int kept = checkpoint["runs"]["done"].get<int>() + checkpoint["runs"]["failed"].get<int>();
  EXPECT_GE(kept, 2);
  EXPECT_LT(kept, 20);

  const auto resumed = framedyn::testing::framedyn(dir, "batch design.yaml --out results -j 1 --checkpoint 2 --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(std::to_string(kept) + " read back by --resume"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_text(dir / "results" / "runs.csv"), read_text(dir / "whole" / "runs.csv"));
  EXPECT_EQ(read_text(dir / "results" / "summary.json"), read_text(dir / "whole" / "summary.json"));
  // The user's files byte for byte; besides them only framedyn's folders: the two
  // results and, at most, the partial checkpoint the kill interrupted.
  EXPECT_EQ(user_files(dir.path()), before);
  for (const auto& e : fs::directory_iterator(dir.path())) {
    const std::string name = e.path().filename().string();
    const bool framedyns = name == "results" || name == "whole" || name == "results.partial-" + std::to_string(pid);
    EXPECT_TRUE(framedyns || before.count(name)) << "unexpected " << name;
  }
}

}  // namespace

// An output is read with its unit whether the summary gives it as {value, unit} or as a
// number beside its group's unit (hot_spots[i].von_mises {static, dynamic, total, unit}),
// so runs.csv's header carries the unit in both cases; a group without one stays "1".
TEST(BatchOutputs, ANumberBesideItsGroupsUnitIsReadWithThatUnit) {
  const nlohmann::ordered_json summary = nlohmann::ordered_json::parse(
      R"({"frame": {"peak_von_mises": {"value": 2.5, "unit": "psi"},
                    "hot_spots": [{"von_mises": {"static": 1.0, "dynamic": 2.0, "total": 3.0, "unit": "psi"}}],
                    "counts": {"modes": 10}}})");
  double v = 0.0;
  std::string unit, why;
  ASSERT_TRUE(framedyn::batch::summary_value(summary, "frame.hot_spots[0].von_mises.total", v, unit, why)) << why;
  EXPECT_EQ(v, 3.0);
  EXPECT_EQ(unit, "psi");
  ASSERT_TRUE(framedyn::batch::summary_value(summary, "frame.peak_von_mises", v, unit, why)) << why;
  EXPECT_EQ(v, 2.5);
  EXPECT_EQ(unit, "psi");
  ASSERT_TRUE(framedyn::batch::summary_value(summary, "frame.counts.modes", v, unit, why)) << why;
  EXPECT_EQ(v, 10.0);
  EXPECT_EQ(unit, "1");
}

// `framedyn batch --figures`; see batch_figures.h.
#include "batch/batch_figures.h"

#include <fstream>
#include <sstream>

#include "core/cell_text.h"
#include "core/results_folder.h"

namespace framedyn::batch {

namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

report::DesignTable design_table(const BatchDesign& design, const std::vector<RunRecord>& rows) {
  report::DesignTable t;
  t.title = std::filesystem::path(design.file).filename().string();
  t.grid = design.sampling.method == SamplingMethod::grid;
  for (const ParameterSpec& p : design.parameters) {
    t.parameters.push_back(p.key);
    t.parameter_units.push_back(design.study_units);  // as runs.csv's header says
  }
  t.outputs = design.outputs;
  t.output_units.assign(design.outputs.size(), "");
  for (const RunRecord& r : rows) {
    if (!r.present || !r.done) continue;
    std::vector<double> x;
    for (const std::string& cell : r.parameters) {
      double v = 0.0;
      core::parse_number(cell, v);
      x.push_back(v);
    }
    std::vector<std::optional<double>> y;
    for (std::size_t o = 0; o < r.outputs.size(); ++o) {
      double v = 0.0;
      y.push_back(core::parse_number(r.outputs[o], v) ? std::optional<double>(v) : std::nullopt);
      if (t.output_units[o].empty() && o < r.output_units.size()) t.output_units[o] = r.output_units[o];
    }
    t.parameter_values.push_back(std::move(x));
    t.output_values.push_back(std::move(y));
  }
  return t;
}

std::vector<std::string> write_batch_figures(const BatchDesign& design, const BatchOptions& options) {
  const std::string csv = read_text(options.out / "runs.csv");
  nlohmann::ordered_json summary = nlohmann::ordered_json::parse(read_text(options.out / "summary.json"));
  const std::vector<RunRecord> rows = read_runs_csv(design, options.out / "runs.csv");
  core::ResultsFolder folder(options.out, batch_inputs(design));
  folder.write_text("runs.csv", csv);
  std::vector<std::string> files;
  for (const report::DesignFigure& f : report::design_figures(design_table(design, rows))) {
    report::write_png(f.figure, folder.path_of(f.file));
    files.push_back(f.file);
  }
  summary["figures"] = files;  // the figure files, relative to the folder
  folder.write_text("summary.json", summary.dump(2) + "\n");
  folder.commit();
  return files;
}

}  // namespace framedyn::batch

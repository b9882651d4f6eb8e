// Running a design study on threads and writing its results; see engine.h.
#include "batch/engine.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "batch/sensitivity.h"
#include "core/cell_text.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "coupling/frame_model_cache.h"
#include "coupling/study_key_path.h"
#include "report/csv_writer.h"
#include "report/study_run.h"

namespace framedyn::batch {

bool summary_value(const nlohmann::ordered_json& summary, const std::string& path, double& value, std::string& unit, std::string& why) {
  const nlohmann::ordered_json* n = &summary;
  const nlohmann::ordered_json* parent = nullptr;  // the object the last step read from
  std::string here;  // the path so far
  const std::vector<coupling::KeyPathStep> steps = coupling::parse_key_path(path).value();  // checked when the design was read
  for (const coupling::KeyPathStep& k : steps) {
    parent = n;
    if (!k.is_item) {
      if (!n->is_object() || !n->contains(k.key)) {
        why = fmt::format("the run's summary has no {}{}{}", here, here.empty() ? "" : ".", k.key);
        return false;
      }
      n = &(*n)[k.key];
      here += (here.empty() ? "" : ".") + k.key;
    } else if (!k.by_name) {
      if (!n->is_array() || k.index >= n->size()) {
        why = fmt::format("the run's summary has no {}[{}]", here, k.index);
        return false;
      }
      n = &(*n)[k.index];
      here += fmt::format("[{}]", k.index);
    } else {
      const nlohmann::ordered_json* found = nullptr;
      if (n->is_array())
        for (const auto& item : *n)
          if (item.is_object() && item.contains("name") && item["name"] == k.name) {
            found = &item;
            break;
          }
      if (!found && n->is_object() && n->contains(k.name)) found = &(*n)[k.name];
      if (!found) {
        why = fmt::format("the run's summary has no {}[{}]", here, k.name);
        return false;
      }
      n = found;
      here += "[" + k.name + "]";
    }
  }
  unit = "1";
  if (n->is_object() && n->contains("value")) {
    if (n->contains("unit") && (*n)["unit"].is_string()) unit = (*n)["unit"].get<std::string>();
    n = &(*n)["value"];
  } else if (n->is_number() && parent && parent->is_object() && parent->contains("unit") && (*parent)["unit"].is_string()) {
    // A number beside its group's unit, as in hot_spots[i].von_mises {static, dynamic, total, unit}.
    unit = (*parent)["unit"].get<std::string>();
  }
  if (n->is_boolean()) {
    value = n->get<bool>() ? 1.0 : 0.0;
    return true;
  }
  if (!n->is_number()) {
    why = fmt::format("the run's summary has {} at {}, not a number", n->is_null() ? "null" : n->type_name(), here);
    return false;
  }
  value = n->get<double>();
  return true;
}

namespace {

// One line of a CSV row into cells (quotes as report::CsvTable writes them).
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s;
}

std::vector<std::string> header(const BatchDesign& d, const std::vector<RunRecord>& rows) {
  std::vector<std::string> h = {"index"};
  for (const ParameterSpec& p : d.parameters) h.push_back(report::column(p.key, d.study_units));
  for (std::size_t o = 0; o < d.outputs.size(); ++o) {
    std::string unit;  // the lowest-index run that gives one (units do not change between runs)
    for (const RunRecord& r : rows)
      if (r.present && o < r.output_units.size() && !r.output_units[o].empty()) {
        unit = r.output_units[o];
        break;
      }
    h.push_back(report::column(d.outputs[o], unit));
  }
  h.push_back("status");
  h.push_back("message");
  return h;
}

}  // namespace

std::vector<std::vector<double>> design_samples(const BatchDesign& design) {
  std::vector<std::vector<double>> rows = draw_samples(design.sampling, design.parameters);
  for (auto& row : rows)
    for (double& v : row) {
      double back = v;
      core::parse_number(report::format_number(v), back);
      v = back;
    }
  return rows;
}

RunRecord run_sample(const BatchDesign& design, std::size_t index, const std::vector<double>& values, const std::optional<std::filesystem::path>& keep,
                     coupling::FrameModelCache* frame_cache) {
  RunRecord r;
  r.index = index;
  r.present = true;
  for (double v : values) r.parameters.push_back(report::format_number(v));
  r.outputs.assign(design.outputs.size(), "");
  r.output_units.assign(design.outputs.size(), "");
  try {
    YAML::Node doc = YAML::Load(design.study_text);  // with its marks: a refused sample's error names the study's line
    for (std::size_t j = 0; j < values.size(); ++j) coupling::set_study_number(doc, design.parameters[j].key, values[j], design.study_file.string());
    report::StudyRunOptions opt;
    if (keep) opt.out = *keep;
    else opt.summary_outputs = design.outputs;  // only what the outputs read (the row is the same)
    opt.frame_cache = frame_cache;
    const report::StudyRun run = report::run_study_document(doc, design.study_file, opt);
    std::string notes;
    for (std::size_t o = 0; o < design.outputs.size(); ++o) {
      double v = 0.0;
      std::string unit, why;
      if (summary_value(run.summary, design.outputs[o], v, unit, why)) {
        r.outputs[o] = report::format_number(v);
        r.output_units[o] = unit;
      } else {
        notes += (notes.empty() ? "" : "; ") + why;
      }
    }
    r.done = true;
    r.message = one_line(notes);
  } catch (const std::exception& e) {
    r.done = false;
    r.message = one_line(e.what());
  }
  return r;
}

std::string runs_csv(const BatchDesign& design, const std::vector<RunRecord>& rows) {
  report::CsvTable t(header(design, rows));
  for (const RunRecord& r : rows) {
    if (!r.present) continue;
    t.row().add(static_cast<long long>(r.index));
    for (const std::string& p : r.parameters) t.add(p);
    for (const std::string& o : r.outputs) t.add(o);
    t.add(std::string(r.done ? "done" : "failed")).add(r.message);
  }
  return t.str();
}

std::vector<RunRecord> read_runs_csv(const BatchDesign& design, const std::filesystem::path& csv) {
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw core::InputError({"command line", 0, "--resume"}, "runs.csv in the results folder of an earlier batch", "no " + csv.string());
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> h = csv_cells(line);
  const std::size_t np = design.parameters.size(), no = design.outputs.size();
  bool same = h.size() == np + no + 3 && h.front() == "index";
  for (std::size_t j = 0; same && j < np; ++j) same = h[1 + j] == report::column(design.parameters[j].key, design.study_units);
  for (std::size_t o = 0; same && o < no; ++o) same = h[1 + np + o].rfind(design.outputs[o], 0) == 0;
  if (!same)
    throw core::InputError({csv.string(), 1, ""}, "the header of this design's runs.csv (index, its parameters, its outputs, status, message)",
                           "'" + line + "' (--resume continues the same design only)");
  std::vector<RunRecord> rows;
  std::size_t number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const std::vector<std::string> c = csv_cells(line);
    double index = 0.0;
    if (c.size() != h.size() || !core::parse_number(c[0], index))
      throw core::InputError({csv.string(), static_cast<int>(number), ""}, fmt::format("a row of {} cells", h.size()), "'" + line + "'");
    RunRecord r;
    r.index = static_cast<std::size_t>(index);
    r.present = true;
    r.parameters.assign(c.begin() + 1, c.begin() + 1 + static_cast<long>(np));
    r.outputs.assign(c.begin() + 1 + static_cast<long>(np), c.begin() + 1 + static_cast<long>(np + no));
    for (std::size_t o = 0; o < no; ++o) {
      const std::string& col = h[1 + np + o];
      const std::size_t open = col.rfind(" [");
      r.output_units.push_back(open != std::string::npos && col.back() == ']' ? col.substr(open + 2, col.size() - open - 3) : "");
    }
    r.done = c[1 + np + no] == "done";
    r.message = c[2 + np + no];
    rows.push_back(r);
  }
  return rows;
}

nlohmann::ordered_json batch_summary(const BatchDesign& d, const std::vector<RunRecord>& rows) {
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "batch"}};
  nlohmann::ordered_json design;
  design["file"] = d.file;
  design["study"] = d.study_file.generic_string();
  design["study_units"] = d.study_units;
  design["sampling"] = {{"method", sampling_name(d.sampling.method)}};
  if (d.sampling.method != SamplingMethod::grid) {
    design["sampling"]["samples"] = d.sampling.samples;
    design["sampling"]["seed"] = d.sampling.seed;
  }
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  for (const ParameterSpec& p : d.parameters) {
    nlohmann::ordered_json jp = {{"key", p.key}};
    if (d.sampling.method == SamplingMethod::grid) {
      jp["values"] = p.values;
    } else {
      jp["distribution"] = distribution_name(p.distribution);
      if (p.distribution == Distribution::uniform || p.distribution == Distribution::truncated_normal) {
        jp["low"] = p.low;
        jp["high"] = p.high;
      }
      if (p.distribution == Distribution::normal || p.distribution == Distribution::truncated_normal) {
        jp["mean"] = p.mean;
        jp["std_dev"] = p.std_dev;
      }
      if (p.distribution == Distribution::lognormal) {
        jp["median"] = p.median;
        jp["log_std"] = p.log_std;
      }
    }
    params.push_back(jp);
  }
  design["parameters"] = params;
  design["outputs"] = d.outputs;
  j["design"] = design;
  std::size_t total = rows.size(), done = 0, failed = 0;
  for (const RunRecord& r : rows) {
    done += r.present && r.done;
    failed += r.present && !r.done;
  }
  j["runs"] = {{"total", total}, {"done", done}, {"failed", failed}, {"missing", total - done - failed}};
  j["complete"] = done + failed == total;
  // Sensitivity over the done runs that give the output (numbers as runs.csv holds them).
  nlohmann::ordered_json sens = nlohmann::ordered_json::object();
  for (std::size_t o = 0; o < d.outputs.size(); ++o) {
    std::vector<std::vector<double>> x;
    std::vector<double> y;
    for (const RunRecord& r : rows) {
      double v = 0.0;
      if (!r.present || !r.done || !core::parse_number(r.outputs[o], v)) continue;
      std::vector<double> row;
      for (const std::string& p : r.parameters) {
        double pv = 0.0;
        core::parse_number(p, pv);
        row.push_back(pv);
      }
      x.push_back(row);
      y.push_back(v);
    }
    nlohmann::ordered_json js;
    js["runs"] = y.size();
    const std::optional<std::vector<double>> src = standardised_regression_coefficients(x, y);
    nlohmann::ordered_json rank = nlohmann::ordered_json::array();
    if (src) {
      for (std::size_t k : ranking(*src)) {
        nlohmann::ordered_json e = {{"parameter", d.parameters[k].key}, {"src", (*src)[k]}};
        if (d.sampling.method == SamplingMethod::monte_carlo) {
          std::vector<double> col;
          for (const auto& row : x) col.push_back(row[k]);
          const std::optional<double> rho = spearman(col, y);
          e["spearman"] = rho ? nlohmann::ordered_json(*rho) : nlohmann::ordered_json(nullptr);
        }
        rank.push_back(e);
      }
    }
    js["ranking"] = rank;
    if (!src) js["note"] = "not determined (fewer done runs than parameters + 2, or the output does not vary)";
    sens[d.outputs[o]] = js;
  }
  j["sensitivity"] = sens;
  j["figures"] = nlohmann::ordered_json::array();  // the figure files in the folder (batch --figures: write_batch_figures lists them)
  return j;
}

std::vector<std::filesystem::path> batch_inputs(const BatchDesign& design) { return {design.file, design.study_file}; }

void write_batch_folder(const BatchDesign& design, const std::vector<RunRecord>& rows, const BatchOptions& options) {
  core::ResultsFolder folder(options.out, batch_inputs(design));
  folder.write_text("runs.csv", runs_csv(design, rows));
  folder.write_text("summary.json", batch_summary(design, rows).dump(2) + "\n");
  folder.commit();
}

std::vector<RunRecord> starting_rows(const BatchDesign& design, const BatchOptions& options, std::size_t total) {
  std::vector<RunRecord> rows(total);
  for (std::size_t i = 0; i < total; ++i) rows[i].index = i;
  if (!options.resume) return rows;
  for (RunRecord& r : read_runs_csv(design, options.out / "runs.csv"))
    if (r.index < total) rows[r.index] = r;
  return rows;
}

void keep_freed_memory_for_next_runs() {
#if defined(__GLIBC__)
  // A pipeline run allocates matrices of 1-3 MB (displacements, modal coordinates, stresses at 1,001 times):
  // above glibc's default mmap threshold each is mapped, faulted in page by page and unmapped at every run,
  // and the heap's top is trimmed between runs. 32 MB (glibc's largest threshold) and a 256 MB trim
  // threshold keep them in the heap for the next run.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
}

void run_on_threads(std::size_t count, int threads, bool reuse_models, const std::function<void(std::size_t, coupling::FrameModelCache*)>& run) {
  keep_freed_memory_for_next_runs();
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex m;
  std::exception_ptr failure;
  const auto worker = [&] {
    coupling::FrameModelCache models;  // this worker's: built by its first run, reused by the next
    while (!stop) {
      const std::size_t i = next++;
      if (i >= count) return;
      try {
        run(i, reuse_models ? &models : nullptr);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(std::max<std::size_t>(1, count))));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

BatchCounts run_batch(const BatchDesign& design, const BatchOptions& options) {
  core::check_results_target(options.out, batch_inputs(design));  // before the runs: a refusal costs no time
  const std::vector<std::vector<double>> samples = design_samples(design);
  std::vector<RunRecord> rows = starting_rows(design, options, samples.size());
  std::vector<std::size_t> todo;
  BatchCounts counts;
  counts.total = samples.size();
  for (const RunRecord& r : rows)
    if (r.present) ++counts.skipped;
    else todo.push_back(r.index);
  const std::size_t every = options.checkpoint_runs > 0 ? options.checkpoint_runs : std::max<std::size_t>(1, samples.size() / 20);
  std::mutex m;
  std::size_t finished = 0, since = 0;
  std::exception_ptr failure;
  run_on_threads(todo.size(), options.threads, options.reuse_models, [&](std::size_t k, coupling::FrameModelCache* models) {
    const std::size_t i = todo[k];
    std::optional<std::filesystem::path> keep;
    if (options.keep_runs) keep = std::filesystem::path(options.out.string() + "_runs") / fmt::format("run_{:06d}", i);
    RunRecord r = run_sample(design, i, samples[i], keep, models);
    std::lock_guard<std::mutex> lock(m);
    rows[i] = std::move(r);
    ++finished;
    if (options.progress) options.progress(finished, todo.size());
    if (++since >= every && finished < todo.size() && !failure) {
      since = 0;
      try {
        write_batch_folder(design, rows, options);  // a checkpoint: --resume continues from it
      } catch (...) {
        failure = std::current_exception();
      }
    }
  });
  if (failure) std::rethrow_exception(failure);
  if (options.stage) options.stage("writing results");
  write_batch_folder(design, rows, options);
  for (const RunRecord& r : rows) {
    counts.done += r.present && r.done;
    counts.failed += r.present && !r.done;
  }
  return counts;
}

}  // namespace framedyn::batch

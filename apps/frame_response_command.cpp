// `framedyn frame-response STUDY.yaml`: the transient response of any beam
// mesh to a load history (the frame side of the pipeline on its own). A study
// with `model: frame_transient` names the mesh, a load-history file
// (coupling/load_history.h), the supports (by node-set name, the mesh's
// *BOUNDARY, or none), the modes, the method, the damping and its output
// sets; the command runs the transient, recovers the section forces and
// fiber stresses of the element sets and the nodal histories of the node
// sets, and writes DIR/summary.json (key "frame"), CSV tables and, with
// a ParaView time series (frame.paraview: xdmf by default, vtu or none).
// The summary is assembled in report/frame_response_summary.h; here the
// options, the progress and the console's lines.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>

#include "apps/commands.h"
#include "apps/progress.h"
#include "report/run_outputs.h"
#include "core/results_folder.h"
#include "core/units.h"
#include "coupling/frame_study.h"
#include "report/frame_outputs.h"
#include "report/frame_response_summary.h"

namespace framedyn::apps {

namespace {

struct FrameResponseOptions {
  std::string study;
  std::string loads;  // overrides frame.loads
  std::string out;
  ProgressFlags progress;
};

int run_frame_response(const FrameResponseOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.study).stem().string() + "_results" : opt.out;
  std::vector<std::filesystem::path> inputs = {opt.study};
  if (!opt.loads.empty()) inputs.emplace_back(opt.loads);
  core::check_results_target(out_dir, inputs);  // before the run: a refusal costs no time
  progress.stage("reading " + opt.study);
  coupling::FrameStudyRequest q = coupling::read_frame_study(opt.study);
  if (!opt.loads.empty()) q.loads = std::filesystem::path(opt.loads);
  inputs.push_back(q.mesh);
  if (q.loads) inputs.push_back(*q.loads);
  core::check_results_target(out_dir, inputs);
  progress.stage("frame transient");
  const coupling::FrameStudyResults r = coupling::run_frame_study(q);
  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, inputs);
  report::write_frame_outputs(r, q, folder, progress.step_callback());
  const nlohmann::ordered_json j = report::frame_response_summary(opt.study, r, q, print_warning);
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  using core::Quantity;
  const core::UnitSystem& u = q.units;
  fmt::print("framedyn frame-response: {} ({}, units {})\n", opt.study, q.name, u.name());
  fmt::print("frame: {} nodes, {} elements; {} output times; {:.3f} s\n", r.model.nodes.size(), r.model.beams.size(), r.response.times.size(),
             r.wall_seconds);
  fmt::print("\n mode  frequency [Hz]\n");
  for (Eigen::Index i = 0; i < std::min<Eigen::Index>(10, r.frequencies_hz.size()); ++i) fmt::print("{:5d}  {:14.3f}\n", i + 1, r.frequencies_hz(i));
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  const auto at = [&](const coupling::RailPeak& p) {
    return fmt::format("at ({:.4g}, {:.4g}, {:.4g}) {} (element {}), t = {:.4g} s", p.point.x() * lf, p.point.y() * lf, p.point.z() * lf,
                       u.label(Quantity::length), p.element_id, p.time);
  };
  for (const coupling::RailRecovery& rail : r.rails) {
    fmt::print("\n{}: peak bending moment {:.5g} {} {}\n", rail.spec.name, u.from_si(rail.peak_bending_moment.value, Quantity::moment),
               u.label(Quantity::moment), at(rail.peak_bending_moment));
    fmt::print("{}: peak normal stress {:.5g} {} {}; bending share {:.1f} %\n", rail.spec.name, u.from_si(rail.peak_normal_stress.value, Quantity::stress),
               u.label(Quantity::stress), at(rail.peak_normal_stress), 100.0 * rail.bending_share);
  }
  if (!r.rails.empty()) fmt::print("\n");
  report::print_hot_spot_line(r, u);
  report::print_fatigue_line(r, q);
  for (const coupling::NodalHistory& h : r.nodal) {
    fmt::print("\n{}: peak displacement {:.5g} {} ({} of node {}), t = {:.4g} s\n", h.spec.name, h.peak_displacement.value * lf, u.label(Quantity::length),
               fem::dof_name(h.peak_displacement.dof), h.peak_displacement.node_id, h.peak_displacement.time);
  }
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace

void add_frame_response_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<FrameResponseOptions>();
  CLI::App* cmd = app.add_subcommand("frame-response",
                                     "Run a frame transient study (model: frame_transient): load history -> nodal histories, section forces, stresses");
  cmd->add_option("study", opt->study, "Study file (.yaml) with model: frame_transient")->required();
  cmd->add_option("--loads", opt->loads, "Load-history file (overrides frame.loads)");
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <study name>_results)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_frame_response(*opt); }; });
}

}  // namespace framedyn::apps

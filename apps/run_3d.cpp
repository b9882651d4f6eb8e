// The console of `framedyn run` for model: rigid_3d (thesis CMW3D, Chapter III)
// and the pipeline: the modes with dominant coordinates, the calibration, the
// frame's peaks, static state, hot spot and fatigue lines. The run and its
// results folder are report::run_study_file's (report/study_run.cpp).
#include "apps/run_3d.h"

#include <fmt/format.h>

#include "apps/progress.h"
#include "report/calibration_output.h"
#include "report/run_outputs.h"
#include "report/study_run_details.h"

namespace framedyn::apps {

int print_run_3d(const std::string& study_file, const report::StudyRun& run, bool figures, const std::string& out_dir) {
  using core::Quantity;
  const coupling::RigidStudy3D& study = *run.details->study_3d;
  const coupling::RigidResults3D& r = *run.details->results_3d;
  const std::optional<coupling::FrameStudyResults>& frame = run.details->frame;
  const core::UnitSystem& u = study.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  fmt::print("framedyn run: {} ({}, 3-D, {} coordinates, units {})\n", study_file, study.name, r.coordinates.size(), u.name());
  if (!r.modes.empty()) {
    fmt::print("\n mode  frequency [Hz]  dominant\n");
    for (std::size_t i = 0; i < r.modes.size(); ++i) fmt::print("{:5d}  {:14.4f}  {}\n", i + 1, r.modes[i].frequency_hz, r.modes[i].dominant);
  }
  if (r.calibration && study.calibration) report::print_calibration(*study.calibration, *r.calibration);
  if (frame) {
    const coupling::FrameStudyResults& f = *frame;
    fmt::print("\nframe ({}): {} nodes, {} beam elements, {} elastic modes used, lowest {:.2f} Hz; {} output times in {:.3f} s\n",
               study.frame_response->mesh.filename().string(), f.model.nodes.size(), f.model.beams.size(), f.frequencies_hz.size(),
               f.frequencies_hz.size() > 0 ? f.frequencies_hz(0) : 0.0, f.response.times.size(), f.wall_seconds);
    for (const coupling::RailRecovery& rail : f.rails)
      fmt::print("{}: peak bending moment {:.5g} {} at X = {:.4g} {}, t = {:.4f} s; peak normal stress {:.5g} {} ({:.0f} % from bending)\n",
                 rail.spec.name, u.from_si(rail.peak_bending_moment.value, Quantity::moment), u.label(Quantity::moment),
                 rail.peak_bending_moment.point.x() * lf, u.label(Quantity::length), rail.peak_bending_moment.time,
                 u.from_si(rail.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), 100.0 * rail.bending_share);
    if (f.static_state) {
      const coupling::FrameStaticState& st = *f.static_state;
      fmt::print("static state (gravity and the static loads): peak normal stress {:.5g} {} on {} at X = {:.4g} {}; balance residual {:.1e} (force), "
                 "{:.1e} (moment)\n",
                 u.from_si(st.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), st.peak_output,
                 st.peak_normal_stress.point.x() * lf, u.label(Quantity::length), st.force_residual, st.moment_residual);
      for (const coupling::RailRecovery& rail : f.rails)
        fmt::print("{}: peak total (static + dynamic) normal stress {:.5g} {} at X = {:.4g} {}, t = {:.4f} s\n", rail.spec.name,
                   u.from_si(rail.peak_total_normal_stress.value, Quantity::stress), u.label(Quantity::stress),
                   rail.peak_total_normal_stress.point.x() * lf, u.label(Quantity::length), rail.peak_total_normal_stress.time);
    }
    report::print_hot_spot_line(f, u);
    report::print_fatigue_line(f, *study.frame_response);
  }
  if (figures) {
    std::string list;
    for (const std::string& f : run.figures) list += (list.empty() ? "" : ", ") + f;
    fmt::print("\nfigures: {}\n", list.empty() ? std::string("none (the study has no response)") : list);
  }
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace framedyn::apps

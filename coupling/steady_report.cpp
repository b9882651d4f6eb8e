// Steady operation and validity warnings of a vehicle run: see steady_report.h.
#include "coupling/steady_report.h"

#include <fmt/format.h>

#include <algorithm>

#include "coupling/frame_loads_2d.h"
#include "coupling/rigid_study.h"
#include "coupling/validity_warnings.h"

namespace framedyn::coupling {

namespace {

using core::Quantity;

enum Group { motion = 0, force = 1, moment = 2 };

struct History {
  std::string name;
  Quantity quantity;
  std::vector<double> values;  // SI
};

// analysis.modal_soil's value for a contact state.
const char* modal_soil_key(rigid::ModalSoil soil) {
  return soil == rigid::ModalSoil::cutting ? "cutting" : soil == rigid::ModalSoil::backing ? "backing" : "none";
}

bool is_blade_motion(const std::string& name) { return name == "blade_x" || name == "blade_y" || name == "blade_z"; }

// The detector over the blade motion and the frame loads, and the peaks of
// every history split at reached_at.
SteadyReport steady_report(const rigid::Trajectory& trajectory, double shaker_hz, const std::vector<Series>& series,
                           const std::vector<History>& frame_loads) {
  const std::vector<double>& time = trajectory.time;
  SteadyReport rep;
  if (!(shaker_hz > 0)) {
    rep.not_assessed = "no shaker: steady operation is judged over shaker periods (a plow with plow.shaker)";
    return rep;
  }
  rep.assessed = true;
  std::vector<rigid::WatchedSignal> watched;
  for (const Series& s : series)
    if (is_blade_motion(s.name)) watched.push_back({s.name, &s.values, motion});
  for (const History& h : frame_loads) watched.push_back({h.name, &h.values, h.quantity == Quantity::force ? force : moment});
  for (const rigid::WatchedSignal& w : watched) rep.watched.push_back(w.name);
  // The switches (soil law, contacts): forces jump there (Eq. 17.1).
  std::vector<double> breaks;
  for (const auto& e : trajectory.events) breaks.push_back(e.time);
  std::sort(breaks.begin(), breaks.end());
  rep.operation = rigid::detect_steady_operation(time, watched, 1.0 / shaker_hz, rep.criterion, breaks);
  // Peaks of loads and motions; the plow force's direction (an angle) has none worth reporting.
  for (const Series& s : series)
    if (s.quantity != Quantity::dimensionless) rep.peaks.push_back({s.name, s.quantity, rigid::split_peaks(time, s.values, rep.operation.reached_at)});
  for (const History& h : frame_loads) rep.peaks.push_back({h.name, h.quantity, rigid::split_peaks(time, h.values, rep.operation.reached_at)});
  return rep;
}

void add_validity_warnings(const RigidStudy& study, const rigid::Multibody& model, double shaker_hz, const std::string& modes_label, RigidResults& r) {
  const ResponseRequest& req = *study.response;
  if (auto w = rotation_warning(largest_body_rotation(model, r.trajectory))) r.warnings.push_back(*w);
  const double window = switching_window(shaker_hz);
  for (core::Warning& w : chattering_warnings(switching_activity(r.trajectory.events, window), window,
                                              req.method == ResponseRequest::Method::event_located, req.rk4_step, shaker_hz > 0))
    r.warnings.push_back(std::move(w));
  for (core::Warning& w : resonance_warnings(shaker_hz, r.modes, modes_label)) r.warnings.push_back(std::move(w));
  if (r.steady.assessed)
    if (auto w = steady_warning(r.steady.operation, r.steady.criterion, req.duration)) r.warnings.push_back(*w);
}

}  // namespace

void assess_response(const RigidStudy& study, const rigid::VehicleModel& model, const rigid::VehicleRunState& run, RigidResults& r) {
  if (!study.response) return;
  const double shaker_hz = study.shaker_frequency();
  // The frame loads the detector watches: 2-D the loads on the tube (computed here if the study did not
  // ask for frame_output), 3-D the six components at each load point.
  std::vector<History> frame;
  if (study.dimensions() == 2) {
    const std::vector<FrameLoad2D> computed =
        r.frame_loads_2d.empty() ? frame_loads_2d(model, study.machine_2d(), run, r.trajectory) : std::vector<FrameLoad2D>{};
    const std::vector<FrameLoad2D>& loads = r.frame_loads_2d.empty() ? computed : r.frame_loads_2d;
    for (const FrameLoad2D& l : loads) {
      History fx{l.name + "_fx", Quantity::force, {}}, fz{l.name + "_fz", Quantity::force, {}}, my{l.name + "_my", Quantity::moment, l.moment};
      for (const Eigen::Vector2d& f : l.force) {
        fx.values.push_back(f.x());
        fz.values.push_back(f.y());
      }
      for (History* h : {&fx, &fz, &my}) frame.push_back(std::move(*h));
    }
  } else if (r.frame_loads_3d) {
    for (const LoadPointHistory* p : frame_load_points(*r.frame_loads_3d))
      for (int c = 0; c < 6; ++c) {
        History h{p->name + "_" + kLoadComponents[c], c < 3 ? Quantity::force : Quantity::moment, {}};
        h.values.assign(p->values.col(c).data(), p->values.col(c).data() + p->values.rows());
        frame.push_back(std::move(h));
      }
  }
  r.steady = steady_report(r.trajectory, shaker_hz, r.series, frame);
  // The rail's top-fiber stress at the output points (frame_output.rail, 2-D): peaks only.
  if (r.steady.assessed && !r.rail_top_stress.empty())
    for (std::size_t k = 0; k < r.rail_top_stress.front().size(); ++k) {
      std::vector<double> s;
      for (const std::vector<double>& row : r.rail_top_stress) s.push_back(row[k]);
      r.steady.peaks.push_back({fmt::format("rail_top_stress_point_{}", k + 1), Quantity::stress,
                                rigid::split_peaks(r.trajectory.time, s, r.steady.operation.reached_at)});
    }
  // The modes' label in the shaker_near_mode warning: 2-D names the modal soil state; 3-D names it
  // only when it is not the default (the state the response starts in).
  const std::string modes_label =
      study.dimensions() == 2 ? fmt::format("with analysis.modal_soil: {}", modal_soil_key(study.modal_soil))
      : study.modal_soil == rigid::ModalSoil::cutting
          ? std::string("of the 3-D model")
          : fmt::format("of the 3-D model with analysis.modal_soil: {}", modal_soil_key(study.modal_soil));
  add_validity_warnings(study, model.multibody, shaker_hz, modes_label, r);
}

}  // namespace framedyn::coupling

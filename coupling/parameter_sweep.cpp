// Parameter sweeps' points; see parameter_sweep.h.
#include "coupling/parameter_sweep.h"

namespace framedyn::coupling {

SweepPoint sweep_point(const VehicleResults& r, double value) {
  SweepPoint p;
  p.value = value;
  p.plow_vertical_pp = r.plow_vertical_peak_to_peak;
  p.peak_cutting_force = r.peak_cutting_force;
  p.peak_backing_force = r.peak_backing_force;
  p.average_peak_cutting_force = r.average_peak_cutting_force;
  p.average_peak_backing_force = r.average_peak_backing_force;
  for (const rigid::RigidMode& m : r.modes) {
    p.frequencies_hz.push_back(m.frequency_hz);
    p.dominant.push_back(m.dominant);
  }
  return p;
}

std::optional<double> relative_change(const std::optional<double>& value, const std::optional<double>& reference) {
  if (!value || !reference || *reference == 0.0) return std::nullopt;
  return (*value - *reference) / *reference;
}

}  // namespace framedyn::coupling

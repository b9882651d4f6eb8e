// Harmonic sweep by modal superposition; see harmonic_response.h.
#include "fem/harmonic_response.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace framedyn::fem {

namespace {

constexpr double kTwoPi = 6.283185307179586;
// Frequencies evaluated together: bounds the work arrays (outputs x block) for large frames.
constexpr Eigen::Index kBlock = 64;

Eigen::MatrixXcd modal_block(const ModalFrequencyResponse& r, const std::vector<double>& f, Eigen::Index start, Eigen::Index count) {
  Eigen::MatrixXcd q(r.mode_count(), count);
  for (Eigen::Index k = 0; k < count; ++k) q.col(k) = r.modal_coordinates(kTwoPi * f[static_cast<std::size_t>(start + k)]);
  return q;
}

}  // namespace

std::vector<int> free_translation_dofs(const FrameDynamics& frame) {
  std::vector<int> out;
  for (int g : frame.dofs().free_dofs)
    if (g % kDofsPerNode < 3) out.push_back(g);
  return out;
}

HarmonicResult harmonic_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load,
                                 const HarmonicOptions& options) {
  const FrameModel& model = frame.model();
  if (options.frequencies_hz.empty()) throw std::invalid_argument("the harmonic response needs at least one frequency");
  for (double f : options.frequencies_hz)
    if (!(f > 0.0) || !std::isfinite(f)) throw std::invalid_argument(fmt::format("harmonic frequencies must be positive and finite, found {} Hz", f));
  for (int g : options.output_dofs)
    if (g < 0 || g >= model.dof_count()) throw std::invalid_argument(fmt::format("output DOF {} outside the model's {} DOFs", g, model.dof_count()));

  const ModalFrequencyResponse response = modal_frequency_response(frame, basis, load, options.response);
  const std::vector<int> translations = free_translation_dofs(frame);
  const LinearOutputs displacement = displacement_outputs(response, translations);
  std::vector<FiberPoint> points;
  const LinearOutputs stress = fiber_stress_outputs(model, response, points);
  const LinearOutputs chosen = displacement_outputs(response, options.output_dofs);

  HarmonicResult r;
  r.frequencies_hz = options.frequencies_hz;
  r.output_dofs = options.output_dofs;
  r.modes_used = response.mode_count();
  r.rigid_body_modes = response.rigid_body_modes;
  r.static_correction = response.static_correction;
  const Eigen::Index nf = static_cast<Eigen::Index>(r.frequencies_hz.size());
  r.output.resize(chosen.size(), nf);
  Eigen::Index max_row = -1, stress_row = -1;
  for (Eigen::Index start = 0; start < nf; start += kBlock) {
    const Eigen::Index count = std::min(kBlock, nf - start);
    const Eigen::MatrixXcd q = modal_block(response, r.frequencies_hz, start, count);
    if (chosen.size() > 0) r.output.middleCols(start, count) = chosen.evaluate(q);
    // The largest amplitude of `outputs` over this block, kept if it beats
    // `peak` so far (squared moduli: the same maximum, no square root per entry).
    auto track = [&](const LinearOutputs& outputs, double& peak, Eigen::Index& peak_row, int& peak_frequency) {
      if (outputs.size() == 0) return;
      Eigen::Index row = 0, col = 0;
      const double block_peak = std::sqrt(outputs.evaluate(q).cwiseAbs2().maxCoeff(&row, &col));
      if (block_peak > peak || peak_row < 0) {
        peak = block_peak;
        peak_row = row;
        peak_frequency = static_cast<int>(start + col);
      }
    };
    track(displacement, r.max_displacement, max_row, r.max_displacement_frequency);
    track(stress, r.max_fiber_stress, stress_row, r.max_fiber_stress_frequency);
  }
  // The spectra at the two peaks, for the figures.
  Eigen::MatrixXcd q_all(response.mode_count(), nf);
  for (Eigen::Index k = 0; k < nf; ++k) q_all.col(k) = response.modal_coordinates(kTwoPi * r.frequencies_hz[static_cast<std::size_t>(k)]);
  if (max_row >= 0) {
    r.max_displacement_dof = translations[static_cast<std::size_t>(max_row)];
    r.max_displacement_frf = displacement_outputs(response, {r.max_displacement_dof}).evaluate(q_all).row(0).transpose();
  }
  if (stress_row >= 0) {
    r.max_fiber_stress_point = points[static_cast<std::size_t>(stress_row)];
    LinearOutputs one;
    one.modal = stress.modal.row(stress_row);
    one.residual = stress.residual.segment(stress_row, 1);
    r.max_fiber_stress_spectrum = one.evaluate(q_all).row(0).transpose().cwiseAbs();
  }
  return r;
}

}  // namespace framedyn::fem

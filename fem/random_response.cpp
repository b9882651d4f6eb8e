// Random response by modal superposition; see random_response.h.
#include "fem/random_response.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/harmonic_response.h"

namespace framedyn::fem {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr Eigen::Index kBlock = 64;

// Trapezoidal weights of a grid (Eq. S.4).
std::vector<double> trapezoid_weights(const std::vector<double>& f) {
  std::vector<double> w(f.size(), 0.0);
  for (std::size_t k = 0; k + 1 < f.size(); ++k) {
    const double h = 0.5 * (f[k + 1] - f[k]);
    w[k] += h;
    w[k + 1] += h;
  }
  return w;
}

// Largest entry of a block of PSDs; updates (peak, row, column) when larger.
void track_peak(const Eigen::MatrixXd& psd, Eigen::Index start, double& peak, Eigen::Index& row, int& col) {
  if (psd.size() == 0) return;
  Eigen::Index r = 0, c = 0;
  const double v = psd.maxCoeff(&r, &c);
  if (v > peak || row < 0) {
    peak = v;
    row = r;
    col = static_cast<int>(start + c);
  }
}

}  // namespace

std::vector<double> random_response_grid(const LoadPsd& psd, const ModalFrequencyResponse& response, const RandomOptions& options) {
  const double lo = psd.lowest(), hi = psd.highest();
  std::vector<double> f = psd.frequency_hz;
  const int n_base = std::max(2, static_cast<int>(std::ceil(options.points_per_decade * std::log10(hi / lo))) + 1);
  for (int k = 0; k < n_base; ++k) f.push_back(lo * std::pow(hi / lo, static_cast<double>(k) / (n_base - 1)));
  for (int j = 0; j < response.mode_count(); ++j) {
    const double w = std::sqrt(std::max(response.eigenvalues(j), 0.0));
    if (!(w > 0.0)) continue;
    const double fj = w / kTwoPi, zeta = response.damping(j) / (2.0 * w);
    if (!(zeta > 0.0)) continue;
    // x = (f - f_j) / (zeta f_j) = sinh(s) with even steps h in s (Eq. S.5). Near the peak
    // |H|^2 ~ 1 / (1 + x^2) is sampled every h half-bandwidths; away from it the spacing grows
    // like h |x|, so that the trapezoidal rule's relative error stays about h^2 / 2 where |H|^2 falls
    // like 1/x^2 (h = 0.03: 5e-4 of the little area out there). Down to 0.1 f_j and up to 1.9 f_j;
    // the base grid takes the smooth remainder.
    const double s_max = std::asinh(0.9 / zeta);
    const int n = std::max(3, static_cast<int>(std::ceil(2.0 * s_max / options.mode_step)) + 1);
    for (int i = 0; i < n; ++i) {
      const double fi = fj * (1.0 + zeta * std::sinh(-s_max + 2.0 * s_max * i / (n - 1)));
      if (fi >= lo && fi <= hi) f.push_back(fi);
    }
  }
  std::sort(f.begin(), f.end());
  std::vector<double> out;
  for (double v : f)
    if (out.empty() || v > out.back() * (1.0 + 1e-12)) out.push_back(v);
  out.back() = hi;
  return out;
}

RandomResult random_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load, const LoadPsd& psd,
                             const RandomOptions& options) {
  const FrameModel& model = frame.model();
  check_load_psd(psd, "load PSD");
  for (int g : options.output_dofs)
    if (g < 0 || g >= model.dof_count()) throw std::invalid_argument(fmt::format("output DOF {} outside the model's {} DOFs", g, model.dof_count()));
  if (options.inertia_relief && frame.rigid_count() == 0)
    throw std::invalid_argument(
        "inertia relief needs a frame whose supports leave rigid motions free; this one is held against every rigid motion");
  const ModalFrequencyResponse full = modal_frequency_response(frame, basis, load, options.response);
  if (full.rigid_body_modes > 0 && !options.inertia_relief)
    throw std::invalid_argument(
        "a frame that is free to move as a rigid body has no stationary random response (its rigid-body motion "
        "under a random load grows without bound): support it, or ask for inertia relief (the elastic part)");
  // Inertia relief (Eq. S.6): the rigid-body modes' terms left out; the residual is the relieved one already.
  const ModalFrequencyResponse response = options.inertia_relief ? elastic_part(full) : full;

  RandomResult r;
  r.frequencies_hz = random_response_grid(psd, response, options);
  r.output_dofs = options.output_dofs;
  r.modes_used = response.mode_count();
  r.static_correction = response.static_correction;
  r.rigid_body_modes = full.rigid_body_modes;
  r.inertia_relief = options.inertia_relief;
  const Eigen::Index nf = static_cast<Eigen::Index>(r.frequencies_hz.size());
  for (double f : r.frequencies_hz) r.load_psd.push_back(psd.at(f));
  const std::vector<double> w = trapezoid_weights(r.frequencies_hz);

  const std::vector<int>& free = frame.dofs().free_dofs;
  const LinearOutputs displacement = displacement_outputs(response, free);
  std::vector<FiberPoint> points;
  const LinearOutputs stress = fiber_stress_outputs(model, response, points);
  const LinearOutputs chosen = displacement_outputs(response, options.output_dofs);
  std::vector<char> translation(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) translation[k] = free[k] % kDofsPerNode < 3;

  Eigen::VectorXd mean_square = Eigen::VectorXd::Zero(displacement.size());
  Eigen::VectorXd stress_mean_square = Eigen::VectorXd::Zero(stress.size());
  r.output_psd.resize(chosen.size(), nf);
  Eigen::Index disp_row = -1, stress_row = -1;
  for (Eigen::Index start = 0; start < nf; start += kBlock) {
    const Eigen::Index count = std::min(kBlock, nf - start);
    Eigen::MatrixXcd q(response.mode_count(), count);
    Eigen::VectorXd s(count), ws(count);
    for (Eigen::Index k = 0; k < count; ++k) {
      const std::size_t i = static_cast<std::size_t>(start + k);
      q.col(k) = response.modal_coordinates(kTwoPi * r.frequencies_hz[i]);
      s(k) = r.load_psd[i];
      ws(k) = w[i] * r.load_psd[i];
    }
    // S_y = |H_y|^2 S_a (Eq. S.2); sigma_y^2 += w_k S_y(f_k) (Eq. S.4).
    if (chosen.size() > 0) r.output_psd.middleCols(start, count) = chosen.evaluate(q).cwiseAbs2() * s.asDiagonal();
    if (displacement.size() > 0) {
      const Eigen::MatrixXd h2 = displacement.evaluate(q).cwiseAbs2();
      mean_square += h2 * ws;
      Eigen::MatrixXd psd_t = h2 * s.asDiagonal();
      for (Eigen::Index k = 0; k < psd_t.rows(); ++k)
        if (!translation[static_cast<std::size_t>(k)]) psd_t.row(k).setZero();
      track_peak(psd_t, start, r.max_displacement_psd, disp_row, r.max_displacement_psd_frequency);
    }
    if (stress.size() > 0) {
      const Eigen::MatrixXd h2 = stress.evaluate(q).cwiseAbs2();
      stress_mean_square += h2 * ws;
      track_peak(h2 * s.asDiagonal(), start, r.max_stress_psd, stress_row, r.max_stress_psd_frequency);
    }
  }

  r.rms = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double rms = std::sqrt(mean_square(static_cast<Eigen::Index>(k)));
    r.rms(free[k]) = rms;
    if (translation[k] && rms > r.max_displacement_rms) {
      r.max_displacement_rms = rms;
      r.max_displacement_rms_dof = free[k];
    }
  }
  if (stress.size() > 0) {
    Eigen::Index k = 0;
    r.max_stress_rms = std::sqrt(stress_mean_square.maxCoeff(&k));
    r.max_stress_rms_point = points[static_cast<std::size_t>(k)];
  }

  // Spectra at the two PSD peaks, for the figures.
  Eigen::MatrixXcd q_all(response.mode_count(), nf);
  Eigen::VectorXd s_all(nf);
  for (Eigen::Index k = 0; k < nf; ++k) {
    q_all.col(k) = response.modal_coordinates(kTwoPi * r.frequencies_hz[static_cast<std::size_t>(k)]);
    s_all(k) = r.load_psd[static_cast<std::size_t>(k)];
  }
  if (disp_row >= 0) {
    r.max_displacement_psd_dof = free[static_cast<std::size_t>(disp_row)];
    r.max_displacement_psd_spectrum =
        displacement_outputs(response, {r.max_displacement_psd_dof}).evaluate(q_all).row(0).transpose().cwiseAbs2().cwiseProduct(s_all);
  }
  if (stress_row >= 0) {
    r.max_stress_psd_point = points[static_cast<std::size_t>(stress_row)];
    LinearOutputs one;
    one.modal = stress.modal.row(stress_row);
    one.residual = stress.residual.segment(stress_row, 1);
    r.max_stress_psd_spectrum = one.evaluate(q_all).row(0).transpose().cwiseAbs2().cwiseProduct(s_all);
  }
  return r;
}

}  // namespace framedyn::fem

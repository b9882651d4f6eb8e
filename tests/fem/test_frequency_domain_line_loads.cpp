// Beam line loads (*DLOAD) as harmonic load amplitudes: the fiber-stress
// outputs of the modal frequency response carry the load's fixed-end terms
// (Eq. H.8) and look inside the loaded elements (9 stations), checked against
//   - the direct frequency-domain solve (K - omega^2 M + i omega C) u = F of
//     the same mesh, its section forces recovered with the line load (exact:
//     both solve the same equations);
//   - the closed-form modal series of a simply supported Euler-Bernoulli beam
//     under a uniform load q e^{i omega t} (Rayleigh damping c_n = alpha +
//     beta omega_n^2):
//       M(L/2, omega) = sum_{n odd} (-1)^{(n-1)/2} (4 q / (n pi rho A)) (n pi / L)^2 E I
//                                 / (omega_n^2 - omega^2 + i c_n omega),
//       omega_n = (n pi / L)^2 sqrt(E I / (rho A)),
//     which tends to the static q L^2/8 as omega -> 0.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "fem/distributed_loads.h"
#include "fem/harmonic_response.h"
#include "fem/inp_reader.h"
#include "fem/modal_frequency_response.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/frequency_domain.h"

namespace {

using namespace framedyn::fem;
using cd = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kAlpha = 4.0, kBeta = 2e-5;  // Rayleigh damping: diagonal in the modes, the same in every solve

const double kL = 3.0, kQ = 2500.0, kE = 2.1e11, kRho = 7850.0, kA = 0.05 * 0.1, kI = 0.1 * 0.05 * 0.05 * 0.05 / 12;

// A simply supported span along X (pinned at node 1, a roller at the tip; no
// twist), `elements` elements of TYPE=`type` (three-node elements: midside
// nodes at the middle), 0.05 x 0.1 steel rectangle with n1 = -Z, under PZ = q.
FrameModel simply_supported(const std::string& type, int elements) {
  const bool quadratic = type == "B32" || type == "B32R";
  const int per = quadratic ? 2 : 1, nodes = per * elements + 1;
  std::string s = "** units: m-N-s\n*NODE\n";
  for (int i = 0; i < nodes; ++i) s += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, kL * i / (nodes - 1));
  s += "*ELEMENT, TYPE=" + type + ", ELSET=BEAM\n";
  for (int e = 1; e <= elements; ++e)
    s += quadratic ? fmt::format("{}, {}, {}, {}\n", e, 2 * e - 1, 2 * e, 2 * e + 1) : fmt::format("{}, {}, {}\n", e, e, e + 1);
  s += fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, 0.3\n*DENSITY\n{}\n", kE, kRho);
  s += "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 0, -1\n";
  s += fmt::format("*BOUNDARY\n1, 1, 4\n{}, 2, 3\n*DLOAD\nBEAM, PZ, {}\n", nodes, kQ);
  return read_inp_text(s, "beam.inp", ".");
}

// (K - omega^2 M + i omega (alpha M + beta K)) u = F on the free DOFs by sparse LU, on all DOFs.
Eigen::VectorXcd direct_solve(const FrameDynamics& frame, const Eigen::VectorXd& load, double omega) {
  return framedyn::testing::direct_frequency_solve(frame, load, omega, kAlpha, kBeta);
}

// The closed-form series above (odd n up to 2001: the terms fall as n^-3).
cd midspan_moment_series(double omega) {
  cd m = 0.0;
  for (int n = 1; n <= 2001; n += 2) {
    const double k = n * kPi / kL, wn2 = k * k * k * k * kE * kI / (kRho * kA);
    const double sign = ((n - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
    m += sign * (4 * kQ / (n * kPi * kRho * kA)) * k * k * kE * kI / cd(wn2 - omega * omega, (kAlpha + kBeta * wn2) * omega);
  }
  return m;
}

double first_frequency_euler_bernoulli() { return (kPi / kL) * (kPi / kL) * std::sqrt(kE * kI / (kRho * kA)); }

// The modal outputs (all modes, no truncation) at every station of every
// element equal the stresses recovered from the direct solution: the real
// part with the line load's fixed-end terms (the load's amplitude is real),
// the imaginary part without.
TEST(FrequencyDomainLineLoads, StressOutputsEqualTheRecoveryOfTheDirectSolve) {
  for (const char* type : {"B31", "B33", "B32", "B32R"}) {
    const FrameModel model = simply_supported(type, 4);
    FrameDynamics frame(model);
    FrequencyResponseOptions o;
    o.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
    o.static_correction = false;  // all modes: the series is complete
    const Eigen::VectorXd load = applied_loads(model);
    const ModalFrequencyResponse r = modal_frequency_response(frame, frame.all_modes(), load, o);
    std::vector<FiberPoint> points;
    const LinearOutputs stress = fiber_stress_outputs(model, r, points);
    const std::vector<BeamLineLoad> loads = beam_line_loads(model);
    for (double f_hz : {0.5, 12.0, 60.0}) {
      const double w = 2 * kPi * f_hz;
      const Eigen::VectorXcd u = direct_solve(frame, load, w);
      Eigen::MatrixXcd q(r.mode_count(), 1);
      q.col(0) = r.modal_coordinates(w);
      const Eigen::VectorXcd modal = stress.evaluate(q).col(0);
      std::size_t row = 0;
      double scale = 0.0, worst = 0.0;
      for (std::size_t e = 0; e < model.beams.size(); ++e) {
        ASSERT_EQ(frequency_response_stations(model.beams[e], loads[e]), 9) << "a loaded element is looked at in eighths";
        const std::vector<StationResult> re = beam_stations(model, static_cast<int>(e), u.real(), 9, loads[e]);
        const std::vector<StationResult> im = beam_stations(model, static_cast<int>(e), u.imag(), 9);
        for (std::size_t s = 0; s < re.size(); ++s)
          for (std::size_t p = 0; p < re[s].fiber_stress.size(); ++p, ++row) {
            ASSERT_LT(row, points.size());
            EXPECT_EQ(points[row].element_id, re[s].element_id);
            EXPECT_EQ(points[row].station, static_cast<int>(s));
            const cd direct(re[s].fiber_stress[p], im[s].fiber_stress[p]);
            scale = std::max(scale, std::abs(direct));
            worst = std::max(worst, std::abs(direct - modal(static_cast<Eigen::Index>(row))));
          }
      }
      EXPECT_EQ(row, points.size());
      std::printf("%s at %g Hz: modal vs direct stresses %.2e of the largest\n", type, f_hz, worst / scale);
      EXPECT_LT(worst, 1e-8 * scale) << type << " " << f_hz << " Hz";  // round-off, as in test_harmonic_response
    }
  }
}

// The harmonic sweep's largest fiber stress of a simply supported span (at
// midspan: |sigma| = |M| c / I22) against the closed-form series, and at a low
// frequency against the static q L^2/8. The span is statically determinate,
// so at omega -> 0 the modal response with static correction gives q L^2/8
// exactly; above zero the elements' modes differ from the Euler-Bernoulli
// ones by the shear and rotary inertia of a Timoshenko beam (relative
// frequency shift of about (pi r / L)^2 (1 + E/(k G)) / 2 = 2.4e-4 for the
// first mode; r^2 = I / A) and by the discretisation (8 elements: below 1e-6
// for B32R's first mode), so the series and the sweep agree to a few 1e-4
// away from resonance, amplified near it by omega_1^2 / |omega_1^2 - omega^2|
// (measured for B32R: 2.9e-4 at 0.5 f1 and 2.5 f1). B32 locks in shear (its
// 3-point rule; test_quadratic_beam_loads), which stiffens its modes by an
// error falling as h^2: on 8 elements it is 3.1e-3 off the series at 0.5 f1
// and 8.7e-3 at 2.5 f1, so for B32 only the static limit is held to the
// closed form here (its modal stresses are checked exactly against its own
// direct solve above).
TEST(FrequencyDomainLineLoads, MidspanMomentOfASimplySupportedBeamFollowsTheModalSeries) {
  const double w1 = first_frequency_euler_bernoulli(), f1 = w1 / (2 * kPi);
  for (const char* type : {"B32R", "B32"}) {
    const FrameModel model = simply_supported(type, 8);
    const SectionProperties& sec = model.sections[0].properties;
    const double c = std::abs(sec.stress_points[0].x());  // the section's corners are at x1 = +-a/2
    FrameDynamics frame(model);
    HarmonicOptions o;
    o.response.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
    o.response.mode_count = 6;
    o.response.static_correction = true;
    o.frequencies_hz = {0.001 * f1, 0.5 * f1, 2.5 * f1};
    const HarmonicResult h = harmonic_response(frame, frame.all_modes(), applied_loads(model), o);
    ASSERT_EQ(h.max_fiber_stress_spectrum.size(), 3);
    const double m_static = kQ * kL * kL / 8;
    for (int k = 0; k < 3; ++k) {
      const double w = 2 * kPi * o.frequencies_hz[static_cast<std::size_t>(k)];
      const double fe = h.max_fiber_stress_spectrum(k) * sec.i22 / c;  // |M| at the peak point
      const double series = std::abs(midspan_moment_series(w));
      std::printf("%s at %.4g f1: |M| %.6f of q L^2/8, series %.6f of q L^2/8, relative difference %.2e\n", type, w / w1, fe / m_static,
                  series / m_static, std::abs(fe - series) / series);
      if (k == 0) {
        EXPECT_NEAR(fe / m_static, 1.0, 1e-5) << type << ": at 0.001 f1 the dynamic part is (0.001)^2";
      }
      if (std::string(type) == "B32R") {
        EXPECT_NEAR(fe / series, 1.0, 1e-3) << type << " at " << w / w1 << " f1";
      }
    }
    // The peak point is at midspan: the last station of element 4 or the first of element 5.
    const int e = h.max_fiber_stress_point.element_id, s = h.max_fiber_stress_point.station;
    EXPECT_TRUE((e == 4 && s == 8) || (e == 5 && s == 0)) << "element " << e << " station " << s;
  }
}

}  // namespace

// S-N curves, mean stress and Palmgren-Miner damage (docs/validation.md V14.3-V14.6):
// the codes' curves against their defining numbers (EN 1993-1-9 Table 7.1's rounded
// limits), a constant-amplitude sine against n/N, a two-block load whose damage does not
// depend on the blocks' order, and a narrow-band Gaussian stress against the closed-form
// Rayleigh damage.
#include <gtest/gtest.h>

#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "core/error.h"
#include "fatigue/mean_stress.h"
#include "fatigue/miner_damage.h"
#include "fatigue/rainflow.h"
#include "fatigue/sn_curve.h"

namespace {

using namespace framedyn::fatigue;
constexpr double MPa = 1e6;
constexpr double kPi = 3.14159265358979323846;

TEST(SnCurves, Iiw2016NormalStressPassesFatAt2e6KneeAt1e7ThenSlope22) {
  const SnCurve c = iiw_normal_stress(90);
  EXPECT_EQ(c.code(), "IIW 2016 (Hobbacher, IIW-2259-15)");
  EXPECT_NEAR(c.cycles_to_failure(90 * MPa), 2e6, 2e6 * 1e-12);
  EXPECT_NEAR(c.cycles_to_failure(180 * MPa), 2e6 / 8, 1e-6);  // m = 3
  const double knee = 90 * MPa * std::cbrt(0.2);                // 52.6 MPa
  EXPECT_NEAR(c.cycles_to_failure(knee), 1e7, 1e7 * 1e-12);
  EXPECT_NEAR(c.cycles_to_failure(30 * MPa), 1e7 * std::pow(knee / (30 * MPa), 22), 1e-12 * 1e7 * std::pow(knee / (30 * MPa), 22));
  EXPECT_TRUE(std::isinf(iiw_normal_stress(90, IiwVariant::constant_amplitude).cycles_to_failure(30 * MPa)));
  const SnCurve tau = iiw_shear_stress(100);  // m = 5 to the knee at 1e8
  EXPECT_NEAR(tau.cycles_to_failure(50 * MPa), 2e6 * 32, 2e6 * 32 * 1e-12);
  EXPECT_NEAR(tau.range_at(1e8).value(), 100 * MPa * std::pow(2e6 / 1e8, 0.2), 1e-6);
}

TEST(SnCurves, En1993DetailCategory71MatchesTable71sLimits) {
  const SnCurve c = en1993_normal_stress(71);
  EXPECT_EQ(c.code(), "EN 1993-1-9:2005");
  // EN 1993-1-9 Table 7.1 lists, for category 71, Delta sigma_D = 52 and Delta sigma_L = 29 MPa (rounded).
  EXPECT_NEAR(c.range_at(5e6).value() / MPa, 52, 0.5);
  EXPECT_NEAR(c.range_at(1e8).value() / MPa, 29, 0.5);
  EXPECT_FALSE(c.range_at(2e8).has_value());               // beyond the cut-off no range has a finite life
  EXPECT_TRUE(std::isinf(c.cycles_to_failure(28 * MPa)));  // below the cut-off: no damage
  const double d = 71 * MPa * std::cbrt(0.4);
  EXPECT_NEAR(c.cycles_to_failure(40 * MPa), 5e6 * std::pow(d / (40 * MPa), 5), 1e-4);
  // Shear, category 100: Table 7.1 gives Delta tau_L = 46 MPa.
  EXPECT_NEAR(en1993_shear_stress(100).range_at(1e8).value() / MPa, 46, 0.5);
  // Size effect: 50 mm plate, k_s = (25/50)^0.2 = 0.8706.
  EXPECT_NEAR(en1993_size_effect(c, 0.050).reference_range() / MPa, 71 * std::pow(0.5, 0.2), 1e-9);
  EXPECT_EQ(en1993_size_effect(c, 0.020).reference_range(), c.reference_range());  // no bonus below 25 mm
  EXPECT_NEAR(iiw_thickness_correction(iiw_normal_stress(80), 0.040, 0.3).reference_range() / MPa, 80 * std::pow(25.0 / 40.0, 0.3), 1e-9);
}

TEST(SnCurves, UserCurvesInterpolateLogLogAndBasquinHasOneSlope) {
  const SnCurve u = user_curve({{1e4, 300}, {1e6, 150}, {1e7, 100}}, "test steel");
  EXPECT_EQ(u.code(), "user");
  EXPECT_NEAR(u.cycles_to_failure(std::sqrt(300.0 * 150.0) * MPa), 1e5, 1e5 * 1e-12);  // geometric mid-point
  EXPECT_TRUE(std::isinf(u.cycles_to_failure(90 * MPa)));
  const SnCurve b = basquin_curve(2e12, 3, "C = 2e12");
  EXPECT_EQ(b.single_slope().value(), 3.0);
  EXPECT_NEAR(b.cycles_to_failure(100 * MPa), 2e12 / 1e6, 1e-3);
  EXPECT_NEAR(b.reference_range() / MPa, 100, 1e-10);
  EXPECT_THROW(sn_curve_from_name("FAT"), std::invalid_argument);
  EXPECT_THROW(sn_curve_from_name("EN71:ca"), std::invalid_argument);
  EXPECT_EQ(sn_curve_from_name("FAT90").name(), iiw_normal_stress(90).name());
  EXPECT_EQ(sn_curve_from_name("EN36:shear").name(), en1993_shear_stress(36).name());
}

TEST(MeanStress, GoodmanRaisesTensileMeansOnlyAndNoneLeavesTheRange) {
  const MeanStressCorrection g = MeanStressCorrection::goodman(400 * MPa);
  EXPECT_DOUBLE_EQ(g.equivalent_range(100 * MPa, 100 * MPa), 100 * MPa / 0.75);
  EXPECT_EQ(g.equivalent_range(100 * MPa, -100 * MPa), 100 * MPa);
  EXPECT_EQ(MeanStressCorrection::none().equivalent_range(100 * MPa, 300 * MPa), 100 * MPa);
  EXPECT_THROW(g.equivalent_range(10 * MPa, 400 * MPa), framedyn::core::NumericalError);
}

// K periods of S/2 cos(2 pi k / 40) + mean: 40 samples a period, the peaks sampled exactly.
std::vector<double> cosine(double range, double mean, int periods) {
  std::vector<double> x;
  for (int k = 0; k <= 40 * periods; ++k) x.push_back(mean + 0.5 * range * std::cos(2.0 * kPi * (k % 40) / 40.0));
  return x;
}

double damage_of(const std::vector<double>& x, const SnCurve& c, Residue r, double pa_per_unit = MPa, MeanStressCorrection msc = MeanStressCorrection::none()) {
  MinerDamage d(c, pa_per_unit, msc);
  count_cycles(x, r, d);
  return d.damage();
}

TEST(MinerDamage, ConstantAmplitudeSineDoesNOverNFromTheCurve) {
  // 1000 periods of range 100 MPa: 2000 half cycles (every one holds S) = 1000 cycles.
  const SnCurve fat90 = iiw_normal_stress(90), en71 = en1993_normal_stress(71);
  const double n_fat90 = 2e6 * std::pow(90.0 / 100.0, 3);  // 1.458e6
  EXPECT_NEAR(damage_of(cosine(100, 20, 1000), fat90, Residue::half_cycles), 1000 / n_fat90, 1e-12 * 1000 / n_fat90);
  EXPECT_NEAR(damage_of(cosine(100, 20, 1000), fat90, Residue::repeated_block), 1000 / n_fat90, 1e-12 * 1000 / n_fat90);
  // EN 71 at 40 MPa (between Delta sigma_D and the cut-off, m = 5), and below the cut-off.
  const double n_en = 5e6 * std::pow(71 * std::cbrt(0.4) / 40, 5);
  EXPECT_NEAR(damage_of(cosine(40, 0, 1000), en71, Residue::half_cycles), 1000 / n_en, 1e-12 * 1000 / n_en);
  EXPECT_EQ(damage_of(cosine(20, 0, 1000), en71, Residue::half_cycles), 0.0);
  // Goodman with S_u = 400 MPa: a mean of 100 MPa raises 100 MPa to 133.3 MPa.
  const double n_g = 2e6 * std::pow(90.0 / (100.0 / 0.75), 3);
  EXPECT_NEAR(damage_of(cosine(100, 100, 1000), fat90, Residue::half_cycles, MPa, MeanStressCorrection::goodman(400 * MPa)), 1000 / n_g, 1e-12 * 1000 / n_g);
  // The equivalent range at 2e6 cycles: 2e6 cycles of it do the damage D, N(S_eq) = 2e6 / D.
  // Here 2e6 / D = 2.9e9 cycles, beyond the knee: S_eq on the m = 22 piece, knee (1e7 D / 2e6)^(1/22).
  const double d = damage_of(cosine(100, 20, 1000), fat90, Residue::half_cycles);
  EXPECT_NEAR(equivalent_range(fat90, d).value() / MPa, 90 * std::cbrt(0.2) * std::pow(1e7 * d / 2e6, 1.0 / 22), 1e-9);
  // On a one-slope curve the closed form (F.13): S_eq = (n S^m / 2e6)^(1/m) = 100 (1000 / 2e6)^(1/3).
  const double d_b = damage_of(cosine(100, 20, 1000), basquin_curve(2e12, 3, "C = 2e12"), Residue::half_cycles);
  EXPECT_NEAR(equivalent_range(basquin_curve(2e12, 3, "C = 2e12"), d_b).value() / MPa, 100 * std::cbrt(1000 / 2e6), 1e-9);
  // Below the EN cut-off's damage (D < 2e6 / 1e8) no range does D in 2e6 cycles.
  EXPECT_FALSE(equivalent_range(en71, 0.01).has_value());
  // The same in psi: the damage does not change.
  const double psi = 6894.757293168361;
  EXPECT_NEAR(damage_of(cosine(100 * MPa / psi, 20 * MPa / psi, 1000), fat90, Residue::half_cycles, psi), 1000 / n_fat90, 1e-12 * 1000 / n_fat90);
}

TEST(MinerDamage, TwoBlockLoadDamageDoesNotDependOnTheBlocksOrder) {
  // Block A: 300 periods of range 160 MPa about 50 MPa (peaks 130, valleys -30); block B: 5000
  // periods of 60 MPa (peaks 80, valleys 20). As a repeated block, A then B is B then A rotated.
  // Counted by hand: A's 300 cycles of 160; B sits on A's descent from 130 and its rise back to
  // 130, so its first and last peaks are no turning points: 4999 cycles 20..80 (60) and one
  // 20..130 (110). Miner: D = 300/N(160) + 4999/N(60) + 1/N(110), in either order.
  const SnCurve c = iiw_normal_stress(71);
  std::vector<double> a = cosine(160, 50, 300), b = cosine(60, 50, 5000);
  std::vector<double> ab = a, ba = b;
  ab.insert(ab.end(), b.begin(), b.end());
  ba.insert(ba.end(), a.begin(), a.end());
  auto n_of = [](double s) { return 2e6 * std::pow(71.0 / s, 3); };  // all three ranges above the knee (41.2 MPa)
  const double hand = 300 / n_of(160) + 4999 / n_of(60) + 1 / n_of(110);
  const double d_ab = damage_of(ab, c, Residue::repeated_block), d_ba = damage_of(ba, c, Residue::repeated_block);
  EXPECT_NEAR(d_ab, hand, 1e-12 * hand);
  EXPECT_NEAR(d_ba, hand, 1e-12 * hand);
  EXPECT_NEAR(d_ab, d_ba, 1e-13 * hand);  // the same cycles, summed in another order
}

// Uniform in [0, 1) from the top 53 bits (not std::uniform_real_distribution, whose output
// differs between standard libraries).
double uniform(std::mt19937_64& gen) { return static_cast<double>(gen() >> 11) * 0x1.0p-53; }

TEST(MinerDamage, NarrowBandGaussianStressMatchesTheRayleighClosedForm) {
  // A Gaussian stress of standard deviation sigma = 30 MPa with a flat one-sided PSD over
  // 9.5-10.5 Hz (bandwidth B = 1 Hz, 10 % of the centre frequency), synthesised by an
  // inverse FFT of M = 2^21 equal-amplitude lines with seeded random phases (fs = 400 Hz,
  // 40 samples a cycle, record T = M / fs = 5243 s). For a narrow band the ranges are twice
  // Rayleigh amplitudes, and with N = C S^-m (m = 3, C = 2e12 MPa^3):
  //   D = nu0 T (2 sqrt(2) sigma)^m Gamma(1 + m/2) / C     (F.14), nu0 = sqrt(m2/m0).
  // Statistical tolerance: D-hat is a mean of A^3 over the record; A^3 of a Rayleigh A has
  // CV^2 = Gamma(1+m)/Gamma(1+m/2)^2 - 1 = 2.395 (CV 1.548), and the envelope decorrelates
  // in about 1/B, so about n = B T = 5243 independent amplitudes: sd(D-hat)/D = 1.548/sqrt(n)
  // = 2.1 %. Bound 4 sd = 8.6 %, plus the bias of rainflow on a band of finite width
  // (irregularity factor 0.9984 here; Wirsching-Light's correction at that width < 2 %) and
  // of 40 samples a cycle (peaks low by < 0.3 %, ranges^3 < 1 %): 12 % in all.
  constexpr int M = 1 << 21;
  constexpr double fs = 400.0, sigma = 30.0, m = 3.0, C = 2e12;
  const double df = fs / M;
  const int k1 = static_cast<int>(std::ceil(9.5 / df)), k2 = static_cast<int>(std::floor(10.5 / df));
  const int lines = k2 - k1 + 1;
  const double a = sigma * std::sqrt(2.0 / lines);  // sum of a^2 / 2 over the lines = sigma^2
  std::mt19937_64 gen(8608);
  // Half spectrum of a real signal: x_j = (1/M) sum over the Hermitian spectrum = (2/M) Re sum_k X_k e^(2 pi i k j / M),
  // so X_k = (M a / 2) e^(i phi_k) makes x = sum_k a cos(2 pi k j / M + phi_k).
  std::vector<std::complex<double>> spectrum(M / 2 + 1, 0.0);
  double m0 = 0, m2 = 0;
  for (int k = k1; k <= k2; ++k) {
    spectrum[k] = std::polar(0.5 * a * M, 2.0 * kPi * uniform(gen));
    m0 += 1.0;
    m2 += (k * df) * (k * df);
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<double> x;
  fft.inv(x, spectrum, M);
  // The synthesis against one line summed directly (round-off of the FFT: < 1e-9 of sigma).
  double direct = 0.0;
  const int j0 = 12345;
  for (int k = k1; k <= k2; ++k) direct += a * std::cos(2.0 * kPi * static_cast<double>((static_cast<long long>(k) * j0) % M) / M + std::arg(spectrum[k]));
  ASSERT_NEAR(x[j0], direct, 1e-9 * sigma);

  const double T = M / fs, nu0 = std::sqrt(m2 / m0);
  const double expected = nu0 * T * std::pow(2.0 * std::sqrt(2.0) * sigma, m) * std::tgamma(1.0 + m / 2.0) / C;
  const double d = damage_of(x, basquin_curve(C, m, "C = 2e12"), Residue::repeated_block);
  const double ratio = d / expected;
  RecordProperty("rayleigh_ratio", std::to_string(ratio));
  std::printf("narrow-band damage %.6g, Rayleigh %.6g, ratio %.4f (%d lines, T = %.0f s)\n", d, expected, ratio, lines, T);
  EXPECT_NEAR(ratio, 1.0, 0.12) << "damage " << d << ", Rayleigh " << expected;
}

}  // namespace

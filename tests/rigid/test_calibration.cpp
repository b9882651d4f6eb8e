// Calibration of vehicle parameters to target natural frequencies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "coupling/rigid_study.h"
#include "rigid/calibration.h"

namespace framedyn {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kNewtonPerMetrePerLbfPerInch = 4.4482216152605 / 0.0254;

// One mass on one spring: the fitted stiffness must be m (2 pi f)^2. The fit
// minimises the log-frequency error plus 1e-3 times the log of the parameter's
// move (a pull towards the start that makes under-determined fits move the
// parameters least); for one parameter and one target that pull biases the
// result by about 1e-6 (the square of the weight, relative), far below the
// 1e-4 asked here.
TEST(Calibration, SingleSpringMassRecoversTheStiffnessOfTheTargetFrequency) {
  const double m = 3.0, target = 2.5;
  const rigid::ModesOfParameters modes_of = [&](const std::vector<double>& p) {
    Eigen::MatrixXd mm(1, 1), kk(1, 1);
    mm << m;
    kk << p[0];
    return rigid::rigid_modes(mm, kk, {"x"});
  };
  const rigid::CalibrationResult r = rigid::calibrate(modes_of, {100.0}, {{target, "x"}});
  EXPECT_NEAR(r.fitted[0] / (m * std::pow(kTwoPi * target, 2)), 1.0, 1e-4);
  EXPECT_TRUE(r.labels_match);
  EXPECT_LT(r.max_relative_error, 1e-4);
}

// Two uncoupled oscillators, targets given in the opposite order of the
// modes: the matching by dominant coordinate pairs each target with its own
// mode, and both stiffnesses come out right.
TEST(Calibration, TargetsArePairedWithModesByDominantCoordinate) {
  const rigid::ModesOfParameters modes_of = [&](const std::vector<double>& p) {
    Eigen::MatrixXd mm = Eigen::MatrixXd::Identity(2, 2), kk = Eigen::MatrixXd::Zero(2, 2);
    kk(0, 0) = p[0];
    kk(1, 1) = p[1];
    return rigid::rigid_modes(mm, kk, {"a", "b"});
  };
  const rigid::CalibrationResult r = rigid::calibrate(modes_of, {10.0, 1000.0}, {{1.0, "b"}, {3.0, "a"}});
  EXPECT_NEAR(std::sqrt(r.fitted[1]) / kTwoPi, 1.0, 1e-4);
  EXPECT_NEAR(std::sqrt(r.fitted[0]) / kTwoPi, 3.0, 3e-4);
  EXPECT_TRUE(r.labels_match);
}

// Thesis Table IV, case 1: the calibrated case file reproduces CMW2D's five
// frequencies within 1 % (the requirement; the fit reaches ~1e-5)
// with the same dominant coordinates.
TEST(ThesisCase1, CalibratedFrequenciesMatchTableIVWithItsModeLabels) {
  const coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/thesis/case1.yaml");
  const coupling::RigidResults r = coupling::run_rigid_study(study);
  ASSERT_TRUE(r.calibration.has_value());
  EXPECT_TRUE(r.calibration->labels_match);
  EXPECT_LT(r.calibration->max_relative_error, 1e-2);
  const std::vector<std::pair<double, std::string>> table = {{2.175, "x"}, {2.792, "z"}, {3.841, "theta_y"}, {6.268, "theta_v"}, {7.051, "w"}};
  ASSERT_EQ(r.modes.size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_NEAR(r.modes[i].frequency_hz / table[i].first, 1.0, 1e-2) << "mode " << i + 1;
    EXPECT_EQ(r.modes[i].dominant, table[i].second) << "mode " << i + 1;
  }
}

// Thesis Table V, case 4, psi: with every other coordinate held, the psi
// mode of the parallelogram linkage is sqrt((K5 + K8) / M2) (Eq. G.12 with
// the errata's M2). The formula is exact for this set-up, so the tolerance is
// the dense eigensolver's round-off, far inside the 1e-6.
TEST(ThesisCase4, PsiModeMatchesAppendixGFormula) {
  const coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/thesis/case4_psi_2d.yaml");
  const coupling::RigidResults r = coupling::run_rigid_study(study);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.modes[0].dominant, "psi");
  const rigid::Machine2DParameters& p = study.machine;
  const double expected = std::sqrt((p.soil.stiffness + p.plow.bounce_tire.stiffness) / p.plow.mass) / kTwoPi;
  EXPECT_NEAR(r.modes[0].frequency_hz / expected, 1.0, 1e-9);
  EXPECT_NEAR(r.modes[0].frequency_hz / 8.321, 1.0, 1e-6);  // the thesis's hand value, which the file's M2 encodes
}

}  // namespace
}  // namespace framedyn

namespace framedyn {
namespace {

// A two-coordinate system whose mode shapes turn with a parameter: M = I,
// K = R(angle) diag(k1, k2) R(angle)^T. The start has both frequencies right
// (1 and 2 Hz) but the 1 Hz mode led by b, the 2 Hz one by a, against the
// targets' labels. With the labels fitted, the calibration must turn the
// shapes (angle below pi/4) until each target's mode carries its label while
// keeping both frequencies: the labels are part of the fit, not only of the
// pairing.
TEST(Calibration, LabelFitTurnsTheModeShapesUntilEachTargetModeCarriesItsLabel) {
  const rigid::ModesOfParameters modes_of = [&](const std::vector<double>& p) {
    const double c = std::cos(p[2]), s = std::sin(p[2]);
    Eigen::Matrix2d r;
    r << c, -s, s, c;
    const Eigen::Matrix2d k = r * Eigen::Vector2d(p[0], p[1]).asDiagonal() * r.transpose();
    return rigid::rigid_modes(Eigen::MatrixXd::Identity(2, 2), k, {"a", "b"});
  };
  const std::vector<double> start = {std::pow(kTwoPi * 1.0, 2), std::pow(kTwoPi * 2.0, 2), 1.2};
  const std::vector<rigid::FrequencyTarget> targets = {{1.0, "a"}, {2.0, "b"}};
  const std::vector<rigid::RigidMode> before = modes_of(start);
  ASSERT_EQ(before[0].dominant, "b");  // the set-up: labels wrong at the start
  rigid::CalibrationOptions options;
  options.coordinates = {"a", "b"};
  const rigid::CalibrationResult r = rigid::calibrate(modes_of, start, targets, options);
  EXPECT_TRUE(r.labels_match);
  // The fit's pull towards the start (weight 1e-3 on each log-parameter's
  // move; the angle has to move by ~0.5) biases the frequencies by a few 1e-6.
  EXPECT_LT(r.max_relative_error, 1e-5);
  const std::vector<rigid::RigidMode> after = modes_of(r.fitted);
  // The label holds with the fit's 1 % margin of energy share.
  EXPECT_GT(after[0].energy_share(0) - after[0].energy_share(1), 0.009);
}

// Thesis Table V, case 5 (plow attached), 2-D column: the calibrated case file
// reproduces CMW2D's six frequencies within 1 % (the requirement) with
// the table's dominant coordinates, the modal analysis seeing the soil at
// full value (examples/thesis/case5_2d.yaml states the reading).
TEST(ThesisCase5, CalibratedFrequenciesMatchTableVWithItsModeLabels) {
  const coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/thesis/case5_2d.yaml");
  ASSERT_TRUE(study.modal_soil == rigid::Machine2D::ModalSoil::cutting);
  const coupling::RigidResults r = coupling::run_rigid_study(study);
  ASSERT_TRUE(r.calibration.has_value());
  EXPECT_TRUE(r.calibration->labels_match);
  EXPECT_LT(r.calibration->max_relative_error, 1e-2);
  const std::vector<std::pair<double, std::string>> table = {{2.129, "x"},       {2.718, "z"}, {3.890, "theta_v"},
                                                             {5.533, "theta_y"}, {7.777, "w"}, {8.321, "psi"}};
  ASSERT_EQ(r.modes.size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_NEAR(r.modes[i].frequency_hz / table[i].first, 1.0, 1e-2) << "mode " << i + 1;
    EXPECT_EQ(r.modes[i].dominant, table[i].second) << "mode " << i + 1;
  }
}

// Why Table V's psi equals case 4's hand value with the frame free: with the
// parallelogram's arms horizontal, a floating lift cylinder and the soil and
// bounce tire in line with the plow's c.g., the plow's vertical motion does
// not reach the frame, so sqrt((K5 + K8)/M2) of Appendix G (Eq. G.12, errata
// M2) is an exact mode of the coupled machine, whatever K5, M2 and the frame
// are. Checked on the case-5 machine at its starting values (nothing fitted)
// and at three other soil stiffnesses: round-off tolerance.
TEST(ThesisCase5, PsiModeOfTheAttachedPlowIsTheIsolatedAppendixGModeExactly) {
  const coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/thesis/case5_2d.yaml");
  for (const double k5 : {0.0, 6000.0 * kNewtonPerMetrePerLbfPerInch, 40000.0 * kNewtonPerMetrePerLbfPerInch, 1e8}) {  // lbf/in -> N/m
    rigid::Machine2DParameters p = study.machine;
    p.soil.stiffness = k5;
    const rigid::Machine2D m(p);
    const std::vector<rigid::RigidMode> modes = rigid::rigid_modes(m.mass_matrix(), m.stiffness_matrix(), m.model().coordinate_names());
    const double expected = std::sqrt((k5 + p.plow.bounce_tire.stiffness) / p.plow.mass) / kTwoPi;
    const int psi = m.coordinate("psi");
    bool found = false;
    for (const rigid::RigidMode& mode : modes)
      if (mode.dominant == "psi") {
        found = true;
        EXPECT_NEAR(mode.frequency_hz / expected, 1.0, 1e-9) << "K5 = " << k5 << " N/m";
        EXPECT_NEAR(mode.energy_share(psi), 1.0, 1e-9) << "K5 = " << k5 << " N/m";  // the frame and cab stand still
      }
    EXPECT_TRUE(found) << "K5 = " << k5 << " N/m";
  }
}

// Thesis Table V, case 6 (digging chain attached), 2-D column, the same way.
// The table's last label "y" is read as theta_y (thesis-errata.md).
TEST(ThesisCase6, CalibratedFrequenciesMatchTableVWithItsModeLabels) {
  const coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/thesis/case6_2d.yaml");
  const coupling::RigidResults r = coupling::run_rigid_study(study);
  ASSERT_TRUE(r.calibration.has_value());
  EXPECT_TRUE(r.calibration->labels_match);
  EXPECT_LT(r.calibration->max_relative_error, 1e-2);
  const std::vector<std::pair<double, std::string>> table = {{1.650, "z"}, {3.835, "x"}, {5.766, "w"}, {6.510, "theta_v"}, {8.903, "theta_y"}};
  ASSERT_EQ(r.modes.size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_NEAR(r.modes[i].frequency_hz / table[i].first, 1.0, 1e-2) << "mode " << i + 1;
    EXPECT_EQ(r.modes[i].dominant, table[i].second) << "mode " << i + 1;
  }
}

// The two case files are calibrated independently, each with K5 free from
// 40,000 lbf/in. That both land on about the same soil stiffness is what
// supports the reading (one verification-era K5 in both tables' runs), so it
// is checked here rather than only reported: within 10 % of each other, and
// far below the operating 40,000.
TEST(ThesisCase5And6, IndependentFitsAgreeOnTheVerificationSoilStiffness) {
  double k5[2];
  int i = 0;
  for (const char* file : {FRAMEDYN_SOURCE_DIR "/examples/thesis/case5_2d.yaml", FRAMEDYN_SOURCE_DIR "/examples/thesis/case6_2d.yaml"}) {
    const coupling::RigidStudy study = coupling::read_rigid_study(file);
    const coupling::RigidResults r = coupling::run_rigid_study(study);
    const auto& names = study.calibration->parameters;
    const auto it = std::find(names.begin(), names.end(), "soil.stiffness");
    ASSERT_NE(it, names.end());
    k5[i++] = r.calibration->fitted[static_cast<std::size_t>(it - names.begin())] / kNewtonPerMetrePerLbfPerInch;
  }
  EXPECT_NEAR(k5[0] / k5[1], 1.0, 0.10);
  EXPECT_LT(std::max(k5[0], k5[1]), 10000.0);
}

// analysis.modal_soil: the three stiffness matrices differ by the soil's
// share alone, K5 sum G^T G over the blade's X and Z springs, scaled by 1,
// REK or 0.
TEST(ModalSoil, CuttingBackingAndNoneDifferByTheSoilSpringsShare) {
  coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml");
  study.machine.soil.stiffness_reduction = 0.3;
  const rigid::Machine2D m(study.machine);
  Eigen::MatrixXd soil = Eigen::MatrixXd::Zero(m.size(), m.size());
  for (int e : m.soil_elements()) {
    const Eigen::RowVectorXd g = m.model().elongation_map(e);
    soil += study.machine.soil.stiffness * g.transpose() * g;
  }
  using S = rigid::Machine2D::ModalSoil;
  const double scale = m.stiffness_matrix().norm();
  EXPECT_LT((m.stiffness_matrix(S::cutting) - m.stiffness_matrix()).norm(), 1e-14 * scale);
  EXPECT_LT((m.stiffness_matrix(S::cutting) - m.stiffness_matrix(S::none) - soil).norm(), 1e-12 * scale);
  EXPECT_LT((m.stiffness_matrix(S::backing) - m.stiffness_matrix(S::none) - 0.3 * soil).norm(), 1e-12 * scale);
}

}  // namespace
}  // namespace framedyn

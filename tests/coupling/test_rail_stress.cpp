// Recovery along a rail: peaks, where and when, and the bending share, against beam theory.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "coupling/output_sets.h"
#include "coupling/rail_stress.h"
#include "fem/inp_reader.h"
#include "fem/beam_section.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

using namespace framedyn;

// A 2 m cantilever rail along X (clamped at X = 0), box 0.10 deep (local 1 = Z) x 0.06 wide.
fem::FrameModel cantilever_rail() {
  framedyn::testing::StraightBeamSpec spec;
  spec.length = 2.0;
  spec.elements = 8;
  spec.section = fem::box_section(0.10, 0.06, 0.005, 0.005, 0.005, 0.005);
  spec.material = framedyn::testing::steel();
  spec.n1_direction = Eigen::Vector3d(0, 0, 1);
  fem::FrameModel m = framedyn::testing::straight_beam(spec);
  framedyn::testing::clamp_node(m, 0);
  for (const auto& b : m.beams) m.element_sets["LEFT_RAIL"].push_back(b.id);
  return m;
}

TEST(RailStress, CantileverPeakIsTipLoadTimesLengthAtTheRootAtTheLargestLoad) {
  fem::FrameModel m = cantilever_rail();
  const double f = 1000.0, n = 20000.0;  // N: tip force down, axial tension
  framedyn::testing::add_nodal_force(m, 8, Eigen::Vector3d(n, 0, -f));
  const Eigen::VectorXd u = fem::solve_static(m).displacement;
  Eigen::VectorXd times(3);
  times << 0.0, 0.1, 0.2;
  Eigen::MatrixXd hist(u.size(), 3);
  hist << 0.3 * u, u, -0.5 * u;  // the largest load at t = 0.1
  const auto r = coupling::recover_rails(m, times, hist, {{"left_rail", "LEFT_RAIL"}}, 5);
  ASSERT_EQ(r.size(), 1u);
  const coupling::RailRecovery& rail = r[0];
  // Linear beam, no loads between nodes: the recovered moment is exact to round-off.
  EXPECT_NEAR(rail.peak_bending_moment.value, f * 2.0, 1e-9 * f * 2.0);
  EXPECT_DOUBLE_EQ(rail.peak_bending_moment.time, 0.1);
  EXPECT_NEAR(rail.peak_bending_moment.point.x(), 0.0, 1e-15);
  EXPECT_EQ(rail.peak_bending_moment.element_id, 1);
  EXPECT_EQ(rail.peak_bending_moment.station, 0);
  EXPECT_NEAR(std::abs(rail.peak_mz.value), f * 2.0, 1e-9 * f * 2.0);  // vertical bending is about n2
  EXPECT_LT(std::abs(rail.peak_my.value), 1e-9 * f);
  // Corner stress: N/A + M (a/2) / I22, bending share (M a/2 / I22) / (N/A + M a/2 / I22).
  const fem::SectionProperties s = fem::box_section(0.10, 0.06, 0.005, 0.005, 0.005, 0.005);
  const double sb = f * 2.0 * 0.05 / s.i22, sn = n / s.area;
  EXPECT_NEAR(rail.peak_normal_stress.value, sb + sn, 1e-9 * (sb + sn));
  EXPECT_NEAR(rail.bending_share, sb / (sb + sn), 1e-12);
  EXPECT_NEAR(rail.envelope_bending_moment(0), f * 2.0, 1e-9 * f * 2.0);
  EXPECT_NEAR(rail.envelope_bending_moment(rail.envelope_bending_moment.size() - 1), 0.0, 1e-9 * f);
  EXPECT_NEAR(rail.series_bending_moment(2), 0.5 * f * 2.0, 1e-9 * f);
}

// The same tip-loaded cantilever of four B32R elements: the rail recovery and
// an element output set take the three-node elements' own stations (by
// statics of their nodal forces, evenly spaced in arc length), so the root
// moment is again f L, exact to round-off (a determinate member).
TEST(RailStress, ThreeNodeBeamRailAndElementSetHaveTheRootMomentTipLoadTimesLength) {
  std::string deck = "** units: m-N-s\n*NODE\n";
  for (int i = 0; i <= 8; ++i) deck += std::to_string(i + 1) + ", " + std::to_string(0.25 * i) + ", 0, 0\n";
  deck += "*ELEMENT, TYPE=B32R, ELSET=LEFT_RAIL\n1, 1, 2, 3\n2, 3, 4, 5\n3, 5, 6, 7\n4, 7, 8, 9\n"
          "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n"
          "*BEAM SECTION, ELSET=LEFT_RAIL, MATERIAL=STEEL, SECTION=BOX\n0.10, 0.06, 0.005, 0.005, 0.005, 0.005\n0, 0, 1\n"
          "*BOUNDARY\n1, ENCASTRE\n*CLOAD\n9, 3, -1000.\n";
  const fem::FrameModel m = fem::read_inp_text(deck, "rail.inp", ".");
  const double f = 1000.0, L = 2.0;
  const Eigen::VectorXd u = fem::solve_static(m).displacement;
  Eigen::VectorXd times(2);
  times << 0.0, 0.1;
  Eigen::MatrixXd hist(u.size(), 2);
  hist << 0.5 * u, u;
  const auto r = coupling::recover_rails(m, times, hist, {{"left_rail", "LEFT_RAIL"}}, 5);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0].peak_bending_moment.value, f * L, 1e-9 * f * L);
  EXPECT_DOUBLE_EQ(r[0].peak_bending_moment.time, 0.1);
  EXPECT_EQ(r[0].peak_bending_moment.element_id, 1);
  EXPECT_EQ(r[0].peak_bending_moment.station, 0);
  EXPECT_NEAR(r[0].peak_bending_moment.point.x(), 0.0, 1e-15);
  EXPECT_NEAR(r[0].envelope_bending_moment(r[0].envelope_bending_moment.size() - 1), 0.0, 1e-9 * f);
  const coupling::SectionHistory h = coupling::section_history(m, hist, "LEFT_RAIL", 5);
  ASSERT_EQ(h.element_ids.size(), 20u);
  EXPECT_NEAR(h.station_x[4], 0.5, 1e-14);  // the element's arc length
  EXPECT_NEAR(std::abs(h.values(20 + 0, 5)), f * L, 1e-9 * f * L);   // Mz at the root at t = 0.1
  EXPECT_NEAR(std::abs(h.values(20 + 2, 5)), f * 1.75, 1e-9 * f * L);  // middle of element 1, x = 0.25
}

TEST(RailStress, UnknownElementSetIsAnInputError) {
  const fem::FrameModel m = cantilever_rail();
  EXPECT_THROW(coupling::recover_rails(m, Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Zero(m.dof_count(), 1), {{"right_rail", "RIGHT_RAIL"}}, 3),
               core::InputError);
}

}  // namespace

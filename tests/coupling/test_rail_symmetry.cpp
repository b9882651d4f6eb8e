// The two rails of the shipped frame (meshes/r100_frame.inp) under mirror-symmetric and offset loads:
// the facts docs/validation.md P7 ("Figure 25 revisited") rests on. The frame is mirror-symmetric about
// its X-Z plane, so the rails' vertical bending moments differ only by the response to the antisymmetric
// part of the loads (lateral forces, roll and yaw moments, a one-sided vertical force); and whatever the
// split, the two rails together carry what the statics of a cut through both rails requires.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "fem/inp_reader.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

using namespace framedyn;

fem::FrameModel shipped_frame() { return fem::read_inp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp"); }

void clamp_rear_end(fem::FrameModel& m) {
  for (int node : m.node_sets.at("REAR_END")) framedyn::testing::clamp_node(m, node);
}

// Section forces at every station of every element, by element id.
std::map<int, std::vector<fem::StationResult>> stations_by_element(const fem::FrameModel& m, const Eigen::VectorXd& u) {
  std::map<int, std::vector<fem::StationResult>> out;
  for (auto& s : fem::recover_stations(m, u, 5)) out[s.element_id].push_back(s);
  return out;
}

// Mesh numbering (docs/meshes/r100_frame.md): left rail nodes 1-22 and elements 1-21, the right rail's
// mirror images are node k + 22 and element k + 21, each running front to rear as its left partner.
constexpr int kRailElements = 21;
constexpr int kRightNodeOffset = 22;

// A general load set on the left rail's nodes and the centreline nodes, and the mirror image of the
// left-rail part on the right rail: mirror about X-Z, F = (FX, FY, FZ) -> (FX, -FY, FZ) and, a moment
// being an axial vector, M = (MX, MY, MZ) -> (-MX, MY, -MZ). Centreline nodes get the mirror-invariant
// components only (FX, FZ, MY).
void add_mirror_symmetric_loads(fem::FrameModel& m) {
  struct Load {
    int node;  // left rail (1-22) or centreline (45-51)
    Eigen::Vector3d f, mom;
  };
  const std::vector<Load> loads = {
      {6, {300, -120, 900}, {40, -75, 25}},     // X = 0, the front axle's station
      {16, {-150, 80, -400}, {-30, 60, 15}},    // X = 52, rear cab mounts
      {19, {0, 50, 1200}, {10, 0, -20}},        // X = 68, where the leveling cylinder sits on the right
      {22, {500, -200, -700}, {0, 90, 35}},     // X = 80, rear end plate
      {45, {250, 0, -350}, {0, 45, 0}},         // the reel's centre node
      {50, {-800, 0, 1500}, {0, -120, 0}},      // the rear axle pin's centre node
  };
  for (const auto& l : loads) {
    const int i = m.node_index(l.node);
    framedyn::testing::add_nodal_force(m, i, l.f);
    framedyn::testing::add_nodal_moment(m, i, l.mom);
    if (l.node <= 22) {
      const int r = m.node_index(l.node + kRightNodeOffset);
      framedyn::testing::add_nodal_force(m, r, {l.f.x(), -l.f.y(), l.f.z()});
      framedyn::testing::add_nodal_moment(m, r, {-l.mom.x(), l.mom.y(), -l.mom.z()});
    }
  }
}

// Largest |difference| between each left-rail station and its mirror image on the right, per section
// force, with the sign the mirror gives it (n1 = +Z and t = +X are mirror-invariant, n2 = t x n1 = -Y is
// not: N, Vy (vertical), Mz (vertical bending) keep their sign; Vz, T, My (lateral bending) change it).
struct MirrorCheck {
  double mz_scale = 0.0, worst_even = 0.0, worst_odd = 0.0;
};
MirrorCheck compare_rails(const fem::FrameModel& m, const Eigen::VectorXd& u) {
  const auto st = stations_by_element(m, u);
  MirrorCheck c;
  for (int e = 1; e <= kRailElements; ++e)
    for (std::size_t k = 0; k < st.at(e).size(); ++k) {
      const fem::SectionForces& l = st.at(e)[k].forces;
      const fem::SectionForces& r = st.at(e + kRailElements)[k].forces;
      c.mz_scale = std::max({c.mz_scale, std::abs(l.mz), std::abs(l.my)});
      c.worst_even = std::max({c.worst_even, std::abs(l.mz - r.mz), std::abs(l.n - r.n) * 0.381, std::abs(l.vy - r.vy) * 0.381});
      c.worst_odd = std::max({c.worst_odd, std::abs(l.my + r.my), std::abs(l.t + r.t), std::abs(l.vz + r.vz) * 0.381});
    }
  return c;
}

// Under a mirror-symmetric load set the two rails' section forces are mirror images at every station:
// the same vertical bending moment, axial and vertical shear force, opposite lateral bending, torque and
// lateral shear, with the rear end clamped (the thesis's SAPIV support) and free-free with inertia relief
// (the pipeline's default). Forces are scaled by the rail half-spacing, 0.381 m, to compare them with
// moments. Tolerance 1e-10 of the largest moment: round-off of a direct sparse solve of a 306-DOF
// model whose stiffness spans about five decades (residual ~1e-14, amplified by the condition number).
TEST(RailSymmetry, MirrorSymmetricLoadsBendBothRailsAlikeToRoundOffClampedAndFreeFree) {
  for (const bool clamped : {true, false}) {
    fem::FrameModel m = shipped_frame();
    if (clamped) clamp_rear_end(m);
    add_mirror_symmetric_loads(m);
    fem::StaticOptions options;
    options.inertia_relief = !clamped;
    const fem::StaticResult r = fem::solve_static(m, {}, options);
    const MirrorCheck c = compare_rails(m, r.displacement);
    SCOPED_TRACE(clamped ? "rear end clamped" : "free-free, inertia relief");
    ASSERT_GT(c.mz_scale, 100.0);  // N m: the loads bend the rails (the check is not vacuous)
    EXPECT_LT(c.worst_even, 1e-10 * c.mz_scale);
    EXPECT_LT(c.worst_odd, 1e-10 * c.mz_scale);
    std::printf("%s: largest moment %.6g N m; left - mirror of right: %.3g (N, Vy, Mz), %.3g (Vz, T, My)\n",
                clamped ? "clamped" : "free-free", c.mz_scale, c.worst_even, c.worst_odd);
  }
}

// A vertical force P on one rail only (the right rail's front end, node 23 at X = -25 in, Y = +15 in),
// rear end clamped. Cut the frame at any station: only the two rails cross the cut, so the statics of the
// piece ahead of it gives, exactly, whatever the frame's stiffness:
//   MzL + MzR = P (X_cut - X_P)                         (pitch: the cantilever moment, shared by the rails)
//   VyL + VyR = -P                                      (vertical force)
//   TL + TR + Y_L VyL + Y_R VyR + Y_P P = 0             (roll about the cut's X axis)
// (section forces on the positive face, outward normal +X, of the piece ahead: theory/fem.md "Recovery";
// M_z is about n2 = -Y, V_y along n1 = +Z). The symmetric half of the load (P/2 on each rail) bends the
// rails alike, M_z = P (X_cut - X_P) / 2 each; the rails differ only by the antisymmetric half, the roll
// couple Y_P P, whose share carried as differential bending (the rest as torsion) the stiffness decides.
// Tolerance 1e-10 of P times the frame's length: round-off (exact statics, no loads between nodes).
TEST(RailSymmetry, OffsetVerticalLoadOnTheClampedFrameGivesTheCutsPitchAndRollStatics) {
  fem::FrameModel m = shipped_frame();
  clamp_rear_end(m);
  const double p = 1000.0;  // N, upward
  const int loaded = m.node_index(23);
  const Eigen::Vector3d xp = m.nodes[static_cast<std::size_t>(loaded)].position;
  framedyn::testing::add_nodal_force(m, loaded, {0, 0, p});
  const Eigen::VectorXd u = fem::solve_static(m).displacement;
  const auto st = stations_by_element(m, u);
  const double y_left = m.nodes[static_cast<std::size_t>(m.node_index(1))].position.y();
  const double y_right = xp.y();
  ASSERT_NEAR(y_left, -y_right, 1e-12);
  const double scale = p * 105 * 0.0254;  // P times the frame's length, N m
  double largest_difference = 0.0, at_clamp_a = 0.0, at_clamp_s = 0.0;
  for (int e = 1; e <= kRailElements; ++e)
    for (std::size_t k = 0; k < st.at(e).size(); ++k) {
      const fem::StationResult& l = st.at(e)[k];
      const fem::StationResult& r = st.at(e + kRailElements)[k];
      ASSERT_NEAR(l.point.x(), r.point.x(), 1e-12);
      const double arm = l.point.x() - xp.x();
      EXPECT_NEAR(l.forces.mz + r.forces.mz, p * arm, 1e-10 * scale) << "X = " << l.point.x();
      EXPECT_NEAR(l.forces.vy + r.forces.vy, -p, 1e-10 * p) << "X = " << l.point.x();
      EXPECT_NEAR(l.forces.t + r.forces.t + y_left * l.forces.vy + y_right * r.forces.vy + y_right * p, 0.0, 1e-10 * scale)
          << "X = " << l.point.x();
      largest_difference = std::max(largest_difference, std::abs(l.forces.mz - r.forces.mz));
      if (e == kRailElements && k + 1 == st.at(e).size()) {
        at_clamp_a = 0.5 * (l.forces.mz - r.forces.mz);
        at_clamp_s = 0.5 * (l.forces.mz + r.forces.mz);
      }
    }
  // The offset load does make the rails differ (the split is not trivially symmetric).
  EXPECT_GT(largest_difference, 1e-3 * scale);
  // The symmetric half alone: both rails carry P (X_cut - X_P) / 2.
  fem::FrameModel half = shipped_frame();
  clamp_rear_end(half);
  framedyn::testing::add_nodal_force(half, loaded, {0, 0, p / 2});
  framedyn::testing::add_nodal_force(half, half.node_index(1), {0, 0, p / 2});
  const auto sh = stations_by_element(half, fem::solve_static(half).displacement);
  for (int e = 1; e <= kRailElements; ++e)
    for (std::size_t k = 0; k < sh.at(e).size(); ++k) {
      const double arm = sh.at(e)[k].point.x() - xp.x();
      EXPECT_NEAR(sh.at(e)[k].forces.mz, p * arm / 2, 1e-10 * scale);
      EXPECT_NEAR(sh.at(e + kRailElements)[k].forces.mz, p * arm / 2, 1e-10 * scale);
    }
  // For the record (docs/validation.md P7): the antisymmetric part at the clamp against the symmetric.
  std::printf("offset load P = %g N at X = %g m: at the clamp S = %.6g N m (= P L / 2), A = %.6g N m, A / S = %.4f\n", p, xp.x(),
              at_clamp_s, at_clamp_a, at_clamp_a / at_clamp_s);
}

}  // namespace

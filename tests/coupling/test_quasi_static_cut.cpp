// Issue 5, study (a): the beam frame in the quasi-static limit reproduces the
// 2-D static cut (thesis Eq. 2.47). A physical law, not a thesis opinion:
// for loads applied slowly to the frame clamped at its rear end, the front
// part's free body gives, at a cut through both rails at X, the sum of the
// rails' axial forces SRX = -sum FX and vertical bending moments SRMY = the
// moment of the loads in front about the cut (Eq. 2.47 with no inertia),
// whatever the statically indeterminate split between the rails. The load
// set is a real one: the 2-D plow study's frame loads at one instant (tires,
// cab mounts, added-mass inertia, plow pins), ramped on over T.
// docs/validation.md, "Quasi-static cut against the beam frame, and the
// thesis's results 2-5 (issue 5)".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "coupling/frame_loads_2d.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "fem/section_forces.h"
#include "rigid/machine_2d.h"

namespace c = framedyn::coupling;
namespace fem = framedyn::fem;

namespace {

// Sum over both rails, at the cut just in front of the node at X, of the axial
// force (tension +) and of the moment about +Y with the sign of SRMY (the
// moment of the loads in front about the cut = minus the moment on the front
// part's rear face).
struct RailCutSum {
  double srx = 0.0, srmy = 0.0;
  int elements = 0;
};
RailCutSum rails_at(const fem::FrameModel& m, const Eigen::VectorXd& u, double x) {
  RailCutSum s;
  for (const char* set : {"LEFT_RAIL", "RIGHT_RAIL"})
    for (int id : m.element_sets.at(set)) {
      const fem::BeamElement& e = m.beams[static_cast<std::size_t>(m.beam_index(id))];
      const Eigen::Vector3d a = m.nodes[static_cast<std::size_t>(e.node_a)].position, b = m.nodes[static_cast<std::size_t>(e.node_b)].position;
      if (!(std::abs(b.x() - x) < 1e-9 && a.x() < x)) continue;
      const fem::BeamGeometry g = fem::beam_geometry(m, e);
      const fem::SectionForces f = fem::section_forces_at(fem::element_end_forces(g, e, u), g.data.length);
      const Eigen::Vector3d t = g.axes.row(0).transpose(), n1 = g.axes.row(1).transpose(), n2 = g.axes.row(2).transpose();
      s.srx += f.n * t.x();
      s.srmy -= (f.t * t + f.my * n1 + f.mz * n2).y();
      ++s.elements;
    }
  return s;
}

}  // namespace

TEST(QuasiStaticCut, BeamFrameUnderSlowlyAppliedPlowLoadsReproducesTheStaticCutOfEq247) {
  const std::string src = FRAMEDYN_SOURCE_DIR;
  c::RigidStudy study = c::read_rigid_study(src + "/examples/r100_plow_2d.yaml");
  study.response->duration = 0.25;  // past the start-up: the loads of steady plowing
  const c::RigidResults run = c::run_rigid_study(study);
  ASSERT_FALSE(run.frame_loads_2d.empty());
  const std::size_t i = run.trajectory.time.size() - 1;

  // Eq. 2.47 at that instant with the frame at rest (no tube inertia): the static cut of the loads.
  const framedyn::rigid::VehicleModel machine = framedyn::rigid::build_vehicle_model(study.machine_2d());
  framedyn::rigid::Trajectory still;
  still.time = {0.0};
  still.q = {Eigen::VectorXd::Zero(run.trajectory.q[i].size())};
  still.v = still.q;
  still.a = still.q;
  std::vector<c::FrameLoad2D> loads;
  for (const c::FrameLoad2D& l : run.frame_loads_2d) loads.push_back({l.name, l.point, {l.force[i]}, {l.moment[i]}});

  // The same loads on the beam frame, ramped on linearly over T and held. Each
  // 2-D load (X, Z) is a 3-D point (X, 0, Z) carried by a rigid spider to its
  // three nearest nodes (resultant force and moment kept).
  const double ramp = 5.0;
  c::LoadHistory h;
  h.times = Eigen::Vector3d(0.0, ramp, ramp + 0.5);
  for (const c::FrameLoad2D& l : loads) {
    c::LoadPointHistory p;
    p.name = "Q_" + l.name;
    p.location = Eigen::Vector3d(l.point.x(), 0.0, l.point.y());
    p.values = Eigen::MatrixXd::Zero(3, 6);
    for (int k = 1; k < 3; ++k) {
      p.values(k, 0) = l.force[0].x();
      p.values(k, 2) = l.force[0].y();
      p.values(k, 4) = l.moment[0];
    }
    h.points.push_back(p);
  }
  c::FrameStudyRequest q;
  q.file = "test";
  q.mesh = src + "/meshes/r100_frame.inp";
  q.units = framedyn::core::UnitSystem::from_name("in-lbf-s");  // the mesh's (a study in other units must ask to convert)
  q.supports = c::FrameSupports::fixed_rear_end;
  q.modes = -1;
  q.method = c::FrameMethod::mode_displacement;  // all modes, no static correction: the dynamics decide
  q.damping = fem::ModalDamping::ratio(0.02);
  const c::FrameStudyResults fe = c::run_frame_study(q, &h);
  ASSERT_EQ(fe.response.times.size(), 3);
  EXPECT_NEAR(fe.response.times(1), ramp, 1e-12);

  // Cuts at the rail nodes in front of the clamp (X = 80 in), just in front of
  // the node (the FE station ends the rail element that reaches X; Eq. 2.47
  // takes the loads with X_j < X). A load carried by a spider counts on the
  // side of its point in Eq. 2.47 and on the side of its nodes on the frame:
  // cuts between the two are left out.
  std::vector<double> cuts;
  for (double xin : {-20, -15, -10, -5, 0, 5, 10, 15, 20, 26, 31, 36, 41, 46, 52, 57, 62, 68, 72, 76}) {
    const double x = xin * 0.0254, tol = 1e-9;
    bool straddled = false;
    for (const c::MappedLoadPoint& p : fe.mapping.points) {
      double lo = 1e300, hi = -1e300;
      for (int n : p.nodes) {
        lo = std::min(lo, fe.model.nodes[static_cast<std::size_t>(n)].position.x());
        hi = std::max(hi, fe.model.nodes[static_cast<std::size_t>(n)].position.x());
      }
      const bool in_front = hi < x - tol && p.location.x() < x;
      const bool behind = lo > x - tol && p.location.x() >= x;
      if (!in_front && !behind) straddled = true;
    }
    if (!straddled) cuts.push_back(x);
  }
  ASSERT_GE(cuts.size(), 8u);
  const c::StressResultants cut = c::frame_stress_resultants(machine, study.machine_2d().frame, still, loads, cuts, 0.0);

  // Bound of the dynamic residual of a linear ramp of duration T on an
  // undamped oscillator of circular frequency w: 2 / (w T) of the static
  // value (the slowest, first mode gives the largest).
  const double w1 = 2.0 * 3.141592653589793 * fe.frequencies_hz(0);
  const double bound = 2.0 / (w1 * ramp);
  double scale_m = 0.0, scale_n = 0.0;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    scale_m = std::max(scale_m, std::abs(cut.srmy[0][k]));
    scale_n = std::max(scale_n, std::abs(cut.srx[0][k]));
  }
  ASSERT_GT(scale_m, 0.0);
  const Eigen::VectorXd u = fe.response.displacement.col(1);
  double worst_m = 0.0, worst_n = 0.0;
  std::string where;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const RailCutSum s = rails_at(fe.model, u, cuts[k]);
    worst_m = std::max(worst_m, std::abs(s.srmy - cut.srmy[0][k]) / scale_m);
    worst_n = std::max(worst_n, std::abs(s.srx - cut.srx[0][k]) / scale_n);
    where += " " + std::to_string(static_cast<int>(std::lround(cuts[k] / 0.0254)));
    ASSERT_EQ(s.elements, 2) << "X = " << cuts[k] / 0.0254 << " in";
    EXPECT_NEAR(s.srmy, cut.srmy[0][k], bound * scale_m) << "SRMY at X = " << cuts[k] / 0.0254 << " in";
    EXPECT_NEAR(s.srx, cut.srx[0][k], bound * scale_n) << "SRX at X = " << cuts[k] / 0.0254 << " in";
  }
  std::cout << "cuts at X =" << where << " in; largest |FE - Eq. 2.47| / largest |value|: SRMY " << worst_m << ", SRX " << worst_n
            << "; bound 2 / (w1 T) = " << bound << " (first mode " << fe.frequencies_hz(0) << " Hz, T = " << ramp << " s)\n";
}

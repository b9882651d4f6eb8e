// A peer on the 3-D model (issue 4): Table IV case 2's set-up — the frame
// assembly as one rigid body on its tires, springs in three directions —
// computed by CalculiX and by framedyn's 3-D model (rigid/machine_3d.h) from
// the same data, examples/thesis/case2.yaml as shipped (no calibration), as
// the thesis checked CMW3D against SAPIV; and the same with steered tires.
//
// The CalculiX model is built here from the raw parts, independently of
// framedyn's Appendix F combination: the test sums the parts' masses, c.g.s
// and inertia tensors (parallel-axis theorem) and represents the combined body
// exactly by six equal point masses (MASS elements) on the principal axes of
// its second-moment tensor (the frame structure's own radii of gyration
// violate the triangle inequality slightly, so parts cannot be point masses
// one by one; the sum can); *RIGID BODY ties them, the rear tire contacts and
// the cab-mount points to one reference node; each spring is a SPRING1
// element to ground, or a SPRINGA to a held node when steering turns it off
// the axes. The cab (1e-5 lbf in case 2) is held in framedyn, so its mounts
// act from the frame to ground, as in CalculiX. eta, the front axle's
// ABSOLUTE roll, is held as the case file does: the front axle moves with the
// pin and pitches and yaws with the frame but does not roll with it, so its
// tire contacts are *EQUATION-tied to the frame's reference and rotation
// nodes without the roll term (tying them rigidly to the frame instead is off
// by 8.7e-4 in the y and theta_x modes).
//
// What CalculiX 2.20 needs (tried on one- and seven-node models first,
// docs/validation.md V11): *FREQUENCY returns all-zero eigenvalues without an
// error when the model has few equations (ccx.log: ARPACK's info = -3, the
// Lanczos basis is larger than the problem). Eight independent padding
// oscillators (mass 1 kg, springs 1e12 N/m: 1.6e5 Hz, far above the frame's
// modes) give it enough equations. *RIGID BODY with REF NODE and ROT NODE,
// MASS, SPRING1, SPRINGA and *EQUATION on the rotation node all work in a
// frequency step; no beam elements are used.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "coupling/rigid_study.h"
#include "tests/support/calculix.h"
#include "tests/support/temp_dir.h"

namespace {

using framedyn::rigid::RigidPart3D;

struct Spring {
  Eigen::Vector3d at;
  Eigen::Vector3d direction;  // unit vector: along a global axis a SPRING1, else a SPRINGA to a grounded node
  double stiffness;
  bool on_front_axle = false;  // at a point of the front axle: it pitches and yaws with the frame, its roll is held
};

// The CalculiX input (model data only) of one rigid body with mass properties
// `body` on grounded springs, with `padding` independent stiff oscillators.
// A spring on the front axle acts at a node tied by *EQUATION to the frame's
// reference node (1001, translations) and rotation node (1002): the axle
// point moves with the pin, turned by the frame's pitch and yaw only, since
// eta (the axle's absolute roll) is held.
std::string calculix_rigid_body_on_springs(const RigidPart3D& body, const std::vector<Spring>& springs, const Eigen::Vector3d& front_pin,
                                           int padding) {
  // Second-moment tensor J = tr(I)/2 * 1 - I about the c.g.; six masses M/6 at
  // c +- a_k e_k with a_k = sqrt(3 j_k / M) reproduce M, c and I exactly.
  const Eigen::Matrix3d j = 0.5 * body.inertia.trace() * Eigen::Matrix3d::Identity() - body.inertia;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(j);
  std::ostringstream inp;
  inp.precision(17);
  inp << "*NODE, NSET=BODY\n";
  int node = 1;
  std::vector<int> mass_nodes, spring_nodes;
  for (int k = 0; k < 3; ++k) {
    if (es.eigenvalues()(k) < 0) throw std::logic_error("the combined body's second moments are not all positive");
    const double a = std::sqrt(3.0 * es.eigenvalues()(k) / body.mass);
    for (double sign : {1.0, -1.0}) {
      const Eigen::Vector3d p = body.cg + sign * a * es.eigenvectors().col(k);
      inp << node << ", " << p.x() << ", " << p.y() << ", " << p.z() << "\n";
      mass_nodes.push_back(node++);
    }
  }
  std::vector<int> axle_nodes;
  for (const Spring& s : springs) {
    if (s.on_front_axle) continue;
    inp << node << ", " << s.at.x() << ", " << s.at.y() << ", " << s.at.z() << "\n";
    spring_nodes.push_back(node++);
  }
  inp << "*NODE\n";  // front-axle points: not in BODY
  for (const Spring& s : springs) {
    if (!s.on_front_axle) continue;
    inp << node << ", " << s.at.x() << ", " << s.at.y() << ", " << s.at.z() << "\n";
    axle_nodes.push_back(node++);
  }
  inp << "*NODE\n1001, " << body.cg.x() << ", " << body.cg.y() << ", " << body.cg.z() << "\n1002, " << body.cg.x() << ", " << body.cg.y()
      << ", " << body.cg.z() << "\n";
  for (int i = 0; i < padding; ++i) inp << 2001 + i << ", " << 100.0 + i << ", 100., 100.\n";
  inp << "*ELEMENT, TYPE=MASS, ELSET=BODY_MASSES\n";
  for (std::size_t i = 0; i < mass_nodes.size(); ++i) inp << 3001 + i << ", " << mass_nodes[i] << "\n";
  inp << "*MASS, ELSET=BODY_MASSES\n" << body.mass / 6.0 << "\n";
  std::size_t on_frame = 0, on_axle = 0;
  for (std::size_t i = 0; i < springs.size(); ++i) {
    const int n = springs[i].on_front_axle ? axle_nodes[on_axle++] : spring_nodes[on_frame++];
    const Eigen::Vector3d& e = springs[i].direction;
    int axis = -1;
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::abs(e(k)) - 1.0) < 1e-15) axis = k;
    if (axis >= 0) {
      inp << "*ELEMENT, TYPE=SPRING1, ELSET=S" << i << "\n" << 4001 + i << ", " << n << "\n*SPRING, ELSET=S" << i << "\n" << axis + 1 << "\n"
          << springs[i].stiffness << "\n";
    } else {  // an axial spring to a node 1 m away along the direction, held
      const Eigen::Vector3d g = springs[i].at + e;
      inp << "*NODE\n" << 7001 + i << ", " << g.x() << ", " << g.y() << ", " << g.z() << "\n*BOUNDARY\n" << 7001 + i << ", 1, 3\n";
      inp << "*ELEMENT, TYPE=SPRINGA, ELSET=S" << i << "\n" << 4001 + i << ", " << n << ", " << 7001 + i << "\n*SPRING, ELSET=S" << i << "\n\n"
          << springs[i].stiffness << "\n";
    }
  }
  // u_c = u_ref + theta x (pin - ref) + (0, theta_y, theta_z) x (c - pin), one equation per direction:
  // u_c,i - u_ref,i - sum_j A_ij theta_j = 0 with A = -[pin - ref]x - [c - pin]x diag(0, 1, 1).
  const auto cross_matrix = [](const Eigen::Vector3d& r) {
    Eigen::Matrix3d m;
    m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
    return m;
  };
  on_axle = 0;
  for (const Spring& s : springs) {
    if (!s.on_front_axle) continue;
    const int n = axle_nodes[on_axle++];
    const Eigen::Matrix3d a = -cross_matrix(front_pin - body.cg) - cross_matrix(s.at - front_pin) * Eigen::Vector3d(0, 1, 1).asDiagonal();
    for (int i = 0; i < 3; ++i) {
      std::vector<std::string> terms = {std::to_string(n) + ", " + std::to_string(i + 1) + ", 1.", "1001, " + std::to_string(i + 1) + ", -1."};
      for (int jx = 0; jx < 3; ++jx)
        if (a(i, jx) != 0.0) {
          std::ostringstream t;
          t.precision(17);
          t << "1002, " << jx + 1 << ", " << -a(i, jx);
          terms.push_back(t.str());
        }
      inp << "*EQUATION\n" << terms.size() << "\n";
      for (std::size_t k = 0; k < terms.size(); ++k) inp << terms[k] << (k + 1 == terms.size() || k % 4 == 3 ? "\n" : ", ");
    }
  }
  inp << "*ELEMENT, TYPE=MASS, ELSET=PAD_MASSES\n";
  for (int i = 0; i < padding; ++i) inp << 5001 + i << ", " << 2001 + i << "\n";
  inp << "*MASS, ELSET=PAD_MASSES\n1.\n";
  for (int d = 1; d <= 3; ++d) {
    inp << "*ELEMENT, TYPE=SPRING1, ELSET=PAD_SPRINGS_" << d << "\n";
    for (int i = 0; i < padding; ++i) inp << 6001 + 100 * d + i << ", " << 2001 + i << "\n";
    inp << "*SPRING, ELSET=PAD_SPRINGS_" << d << "\n" << d << "\n1.e12\n";
  }
  inp << "*RIGID BODY, NSET=BODY, REF NODE=1001, ROT NODE=1002\n";
  return inp.str();
}

// The parts' sum by the parallel-axis theorem (done here, not by rigid::combine).
RigidPart3D sum_of(const std::vector<RigidPart3D>& parts) {
  RigidPart3D s;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (const RigidPart3D& p : parts) {
    s.mass += p.mass;
    first_moment += p.mass * p.cg;
  }
  s.cg = first_moment / s.mass;
  for (const RigidPart3D& p : parts) {
    const Eigen::Vector3d d = p.cg - s.cg;
    s.inertia += p.inertia + p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return s;
}

// framedyn's frequencies and CalculiX's, lowest six, for case 2 with the
// given steering angles (rad) and the tires' lateral stiffness scaled by
// `lateral_scale` (front, rear).
void compare_with_calculix(double front_steering, double rear_steering, double front_lateral_scale = 1.0, double rear_lateral_scale = 1.0) {
  framedyn::coupling::RigidStudy study =
      framedyn::coupling::read_rigid_study(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/thesis/case2.yaml");
  study.calibration.reset();  // the shipped data as they stand, not the fit to CMW3D
  study.response.reset();
  study.modes = true;
  study.fixed_coordinates = {"eta", "u", "v", "w", "theta_u", "theta_v", "theta_w"};
  study.machine_3d().front_tires.steering_angle = front_steering;
  study.machine_3d().rear_tires.steering_angle = rear_steering;
  for (framedyn::rigid::Tire3D* t : {&study.machine_3d().front_tires.left, &study.machine_3d().front_tires.right}) t->lateral.stiffness *= front_lateral_scale;
  for (framedyn::rigid::Tire3D* t : {&study.machine_3d().rear_tires.left, &study.machine_3d().rear_tires.right}) t->lateral.stiffness *= rear_lateral_scale;
  const framedyn::coupling::RigidResults framedyn_result = framedyn::coupling::run_rigid_study(study);
  ASSERT_EQ(framedyn_result.modes.size(), 6u);

  const framedyn::rigid::Machine3DParameters& p = study.machine_3d();
  std::vector<RigidPart3D> parts = p.frame.parts;
  parts.push_back(p.frame.reel_and_carrier);
  parts.push_back(p.frame.rear_axle);
  // The shrunk front axle (0.001 lbf, 3e-7 of the total) counted with the frame; its roll inertia, held by eta, is left out.
  parts.push_back(p.front_axle.axle);
  const RigidPart3D body = sum_of(parts);
  std::vector<Spring> springs;
  for (const framedyn::rigid::Axle3D* axle : {&p.front_tires, &p.rear_tires}) {
    // Steered by delta to the right (+Y): rolling direction (cos, -sin, 0) (forward is -X), axle direction (sin, cos, 0).
    const double d = axle->steering_angle;
    const Eigen::Vector3d rolling(std::cos(d), -std::sin(d), 0), across(std::sin(d), std::cos(d), 0);
    for (const framedyn::rigid::Tire3D* t : {&axle->left, &axle->right}) {
      const bool front = axle == &p.front_tires;
      springs.push_back({t->contact, d == 0.0 ? Eigen::Vector3d::UnitX() : rolling, t->longitudinal.stiffness, front});
      springs.push_back({t->contact, d == 0.0 ? Eigen::Vector3d::UnitY() : across, t->lateral.stiffness, front});
      springs.push_back({t->contact, Eigen::Vector3d::UnitZ(), t->vertical.stiffness, front});
    }
  }
  for (const framedyn::rigid::CabMount3D& m : p.cab.mounts) {  // the cab held: each mount from the frame to ground
    springs.push_back({m.position, Eigen::Vector3d::UnitX(), m.x.stiffness});
    springs.push_back({m.position, Eigen::Vector3d::UnitY(), m.y.stiffness});
    springs.push_back({m.position, Eigen::Vector3d::UnitZ(), m.z.stiffness});
  }
  framedyn::testing::TempDir dir("framedyn_rigid_frame_ccx");
  const std::string model = (dir / "frame_on_springs.inp").string();
  std::ofstream(model) << calculix_rigid_body_on_springs(body, springs, p.front_axle.pin, 8);
  const framedyn::testing::CalculixResult ccx = framedyn::testing::run_calculix_frequency(model, 6, (dir / "run").string());
  ASSERT_EQ(ccx.frequencies_hz.size(), 6u);

  std::vector<double> ours;
  for (const auto& m : framedyn_result.modes) ours.push_back(m.frequency_hz);
  std::sort(ours.begin(), ours.end());
  for (std::size_t i = 0; i < 6; ++i) {
    std::printf("mode %zu: framedyn %.7f Hz (%s), CalculiX %.7f Hz, relative difference %.2e\n", i + 1, ours[i],
                framedyn_result.modes[i].dominant.c_str(), ccx.frequencies_hz[i], ours[i] / ccx.frequencies_hz[i] - 1.0);
    // The issue asks for 0.1 %; both solve the same 6 x 6 problem and CalculiX
    // prints 7 significant digits (rounding <= 5e-7 relative), so 1e-6 is
    // checked: a slip such as tying the front tires rigidly to the frame
    // (its roll held instead of eta) shows as 8.7e-4.
    EXPECT_NEAR(ours[i] / ccx.frequencies_hz[i], 1.0, 1e-6) << "mode " << i + 1;
  }
}

TEST(RigidFrameOnSpringsMatchesCalculix, TableIVCase2FrameAloneOnItsTires) {
  if (!framedyn::testing::calculix_available()) GTEST_SKIP() << "ccx (CalculiX) not on PATH; install calculix-ccx (README)";
  compare_with_calculix(0.0, 0.0);
}

// The same with both axles steered to the right, by different angles (the
// tire springs turned with the wheels: SPRINGA elements in CalculiX). Case 2's
// tires are as stiff across as along, which steering would leave unchanged:
// here the lateral springs are made softer, by 0.5 (front) and 0.3 (rear).
TEST(RigidFrameOnSpringsMatchesCalculix, TableIVCase2WithSteeredTires) {
  if (!framedyn::testing::calculix_available()) GTEST_SKIP() << "ccx (CalculiX) not on PATH; install calculix-ccx (README)";
  compare_with_calculix(22.0 * M_PI / 180.0, 17.6 * M_PI / 180.0, 0.5, 0.3);
}

}  // namespace

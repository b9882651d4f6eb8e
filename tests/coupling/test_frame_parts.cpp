// The frame assembly's parts on the beam model (docs/theory/coupling.md,
// section 9): on a small T-shaped frame (a rail along X and a cross member
// along Y, steel RECT tubes, Euler-Bernoulli elements) with two parts, one off
// the frame on a rigid link and one on a node,
//  - the model's rigid-body mass (T^T M T of the assembled, link-reduced mass
//    matrix, Eq. 9.3) equals a hand sum: each tube a slender rod (m L^2/12
//    across it, rho A (a^2 + b^2)/12 L about its axis), each part its own
//    tensor, moved to the common c.g. by the parallel-axis theorem; and equals
//    the vehicle model's rigid::combine of the same bodies;
//  - free-free, loads that are exactly the d'Alembert forces of a rigid-body
//    acceleration (the tubes' M T a, each part's m a and J alpha + arm x m a
//    applied at its frame node, computed without the model's parts) are
//    relieved completely: inertia relief's rigid-body acceleration is the one
//    imposed, and the elastic response and the stresses are zero. The bare
//    model under the same loads is stressed (the parts' inertia is missing);
//  - the frame node a part hangs from is the nearest beam node, a tie going to
//    the lowest node number;
//  - a part on several mounts (a distributing coupling, Eqs. 9.5-9.6, R.6-R.8)
//    follows a rigid motion of the frame exactly, adds no stiffness (the
//    reduced stiffness matrix is the bare frame's, entry for entry), keeps the
//    hand-summed rigid-body mass, and passes a load at its c.g. to its mounts
//    with the load's resultant and moment (statics), 1/N each when the c.g. is
//    over the mounts' centroid;
//  - the rigid-only 3-D studies of the shipped machine (examples/r100_*.yaml),
//    which have no mesh to take the structure from, carry the mesh's mass, c.g.
//    and radii of gyration (to the digits they print);
//  - the mesh as the source of the frame structure's mass (Eq. 9.4): a study
//    part that disagrees with the mesh is refused, one that agrees is replaced
//    by the mesh's values, a part the mesh carries is not counted twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "coupling/frame_balance.h"
#include "coupling/frame_mass_source.h"
#include "coupling/frame_parts.h"
#include "coupling/rigid_study.h"
#include "fem/assembly.h"
#include "fem/beam_element.h"
#include "fem/inp_reader.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"
#include "rigid/machine_3d.h"

namespace {

using namespace framedyn;
using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kRho = 7850.0, kA = 0.04, kB = 0.06;  // steel RECT 40 x 60 mm

// Rail 1-2-3-4 along X (0 to 1.2 m), cross member 5-3-6 along Y at X = 0.8 (0.6 m).
const std::string kFrame =
    "** units: m-N-s\n"
    "*NODE\n1, 0, 0, 0\n2, 0.4, 0, 0\n3, 0.8, 0, 0\n4, 1.2, 0, 0\n5, 0.8, -0.3, 0\n6, 0.8, 0.3, 0\n"
    "*ELEMENT, TYPE=B33, ELSET=RAIL\n1, 1, 2\n2, 2, 3\n3, 3, 4\n"
    "*ELEMENT, TYPE=B33, ELSET=CROSS\n4, 5, 3\n5, 3, 6\n"
    "*BEAM SECTION, ELSET=RAIL, MATERIAL=STEEL, SECTION=RECT\n0.04, 0.06\n0, 0, -1\n"
    "*BEAM SECTION, ELSET=CROSS, MATERIAL=STEEL, SECTION=RECT\n0.04, 0.06\n0, 0, -1\n"
    "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n";

fem::FrameModel small_frame() { return fem::read_inp_text(kFrame, "frame.inp", "."); }

// The two parts: an engine-like body off the rail (products of inertia), a hitch-like body on node 4.
std::vector<rigid::RigidPart3D> two_parts() {
  return {{"engine", 40.0, Vector3d(0.5, 0.1, 0.25), rigid::inertia_tensor(1.2, 0.9, 0.7, 0.1, -0.05, 0.02)},
          {"hitch", 15.0, Vector3d(1.2, 0.0, 0.0), rigid::inertia_tensor(0.3, 0.4, 0.5)}};
}

// A uniform slender rod from p to q with the RECT section: mass, c.g., inertia about the c.g.
rigid::RigidPart3D rod(const std::string& name, const Vector3d& p, const Vector3d& q) {
  const double length = (q - p).norm(), m = kRho * kA * kB * length;
  const Vector3d e = (q - p) / length;
  const Matrix3d axial = e * e.transpose();
  return {name, m, 0.5 * (p + q),
          m * length * length / 12.0 * (Matrix3d::Identity() - axial) + m * (kA * kA + kB * kB) / 12.0 * axial};
}

TEST(FrameParts, TwoPartsOnASmallFrameGiveTheHandSummedMassCentreOfGravityAndInertia) {
  fem::FrameModel model = small_frame();
  const std::vector<coupling::MountedPart> mounted = coupling::mount_frame_parts(model, two_parts());
  ASSERT_EQ(mounted.size(), 2u);
  // The engine hangs on a link from node 2 (0.4, 0, 0), the nearest; the hitch's c.g. is node 4.
  EXPECT_TRUE(mounted[0].linked);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(mounted[0].frame_node)].id, 2);
  EXPECT_FALSE(mounted[1].linked);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(mounted[1].mass_node)].id, 4);
  EXPECT_EQ(model.rigid_links.size(), 1u);
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(model);

  // Hand sum: rail (1.2 m) and cross member (0.6 m) as rods, then the parts; parallel axes to the common c.g.
  std::vector<rigid::RigidPart3D> bodies = {rod("rail", Vector3d(0, 0, 0), Vector3d(1.2, 0, 0)), rod("cross", Vector3d(0.8, -0.3, 0), Vector3d(0.8, 0.3, 0))};
  for (const rigid::RigidPart3D& p : two_parts()) bodies.push_back(p);
  double mass = 0.0;
  Vector3d first = Vector3d::Zero();
  for (const auto& b : bodies) {
    mass += b.mass;
    first += b.mass * b.cg;
  }
  const Vector3d cg = first / mass;
  Matrix3d inertia = Matrix3d::Zero();
  for (const auto& b : bodies) {
    const Vector3d r = b.cg - cg;
    inertia += b.inertia + b.mass * (r.dot(r) * Matrix3d::Identity() - r * r.transpose());
  }
  // 1.8 m of 2.4e-3 m^2 steel = 33.912 kg of tubes, 55 kg of parts.
  EXPECT_NEAR(mass, 88.912, 1e-9);
  EXPECT_NEAR(body.mass, mass, 1e-12 * mass);
  EXPECT_LT((body.cg - cg).norm(), 1e-12);
  EXPECT_LT((body.inertia - inertia).norm(), 1e-11 * inertia.norm());
  // The vehicle model's way (rigid::combine) gives the same: the frame model and the vehicle model agree.
  const rigid::RigidPart3D vehicle = rigid::combine(bodies, "frame assembly");
  EXPECT_LT((body.inertia - vehicle.inertia).norm(), 1e-11 * inertia.norm());
  std::printf("[ measured ] small frame with two parts: mass %.6f kg (hand %.6f), c.g. off by %.1e m, inertia off by %.1e relative\n", body.mass, mass,
              (body.cg - cg).norm(), (body.inertia - inertia).norm() / inertia.norm());
}

// The largest |fiber stress| over the beams' ends for all-DOF displacements u.
double peak_stress(const fem::FrameModel& model, const Eigen::VectorXd& u) {
  double peak = 0.0;
  for (const fem::BeamElement& b : model.beams) {
    const fem::BeamGeometry g = fem::beam_geometry(model, b);
    const fem::Vector12d f = fem::element_end_forces(g, b, u);
    for (double x : {0.0, g.data.length})
      for (double s : fem::fiber_stresses(g.data.section, fem::section_forces_at(f, x))) peak = std::max(peak, std::abs(s));
  }
  return peak;
}

// Inertia relief of an all-DOF load on a free-free model: rigid-body acceleration (6, about `about`), elastic u (all DOFs).
struct Relieved {
  coupling::Vector6d acceleration;
  Eigen::VectorXd u;
};
Relieved relieve(const fem::FrameModel& model, const Eigen::VectorXd& f_all, const Vector3d& about) {
  const fem::FrameDynamics frame(model);
  EXPECT_TRUE(frame.free_free());
  const fem::DofMap& dofs = frame.dofs();
  fem::SparseMatrix b(model.dof_count(), 1);
  for (Eigen::Index i = 0; i < f_all.size(); ++i)
    if (f_all(i) != 0.0) b.insert(i, 0) = f_all(i);
  const Eigen::VectorXd f_rel = frame.free_loads(b).col(0);
  Relieved out;
  out.u = frame.expand(frame.static_response(f_rel));
  // a_r = M_r^-1 T^T f (Eq. C.11), through the load's resultant.
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(model);
  const Eigen::MatrixXd t = fem::rigid_body_vectors(model, body.cg);
  const coupling::Vector6d a_cg = body.matrix.ldlt().solve(t.transpose() * f_all);
  out.acceleration << a_cg.head<3>() + a_cg.tail<3>().cross(about - body.cg), a_cg.tail<3>();
  (void)dofs;
  return out;
}

TEST(FrameParts, FreeFrameUnderTheDAlembertForcesOfARigidAccelerationIsUnstressed) {
  const fem::FrameModel bare = small_frame();
  fem::FrameModel model = bare;
  const std::vector<coupling::MountedPart> mounted = coupling::mount_frame_parts(model, two_parts());
  // A rigid-body acceleration: a0 of the origin and alpha.
  const Vector3d a0(1.5, -0.8, 9.81), alpha(0.4, -1.1, 0.6);
  const auto accel_at = [&](const Vector3d& x) -> Vector3d { return a0 + alpha.cross(x); };
  // Its d'Alembert forces, built without the model's parts: the tubes' M T a on the bare model ...
  const fem::DofMap dofs = fem::make_dof_map(bare);
  fem::AssemblyOptions options;
  options.storage = fem::Storage::full;
  const fem::SparseMatrix m = fem::assemble(bare, dofs, options).mass;
  Eigen::VectorXd a_rigid(bare.dof_count());
  for (std::size_t n = 0; n < bare.nodes.size(); ++n) a_rigid.segment<6>(6 * static_cast<Eigen::Index>(n)) << accel_at(bare.nodes[n].position), alpha;
  Eigen::VectorXd a_free(dofs.free_count());
  for (int i = 0; i < dofs.free_count(); ++i) a_free(i) = a_rigid(dofs.free_dofs[static_cast<std::size_t>(i)]);
  const Eigen::VectorXd f_tubes = m * a_free;
  Eigen::VectorXd f(model.dof_count());
  f.setZero();
  for (int i = 0; i < dofs.free_count(); ++i) f(dofs.free_dofs[static_cast<std::size_t>(i)]) = f_tubes(i);
  // ... and each part's m a(c) and J alpha + (c - x_n) x m a(c) at its frame node (the rigid body has no angular velocity).
  for (const coupling::MountedPart& p : mounted) {
    const Vector3d xn = model.nodes[static_cast<std::size_t>(p.frame_node)].position;
    const Vector3d force = p.part.mass * accel_at(p.part.cg);
    f.segment<3>(6 * p.frame_node) += force;
    f.segment<3>(6 * p.frame_node + 3) += p.part.inertia * alpha + (p.part.cg - xn).cross(force);
  }
  const Relieved with = relieve(model, f, Vector3d::Zero());
  const Relieved without = relieve(bare, f.head(bare.dof_count()), Vector3d::Zero());
  EXPECT_LT((with.acceleration.head<3>() - a0).norm(), 1e-10 * a0.norm());
  EXPECT_LT((with.acceleration.tail<3>() - alpha).norm(), 1e-10 * alpha.norm());
  const double s_with = peak_stress(model, with.u), s_without = peak_stress(bare, without.u);
  std::printf("[ measured ] rigid acceleration field: relief acceleration off by %.1e m/s^2; peak stress %.2e Pa with the parts, %.4g Pa without\n",
              (with.acceleration.head<3>() - a0).norm(), s_with, s_without);
  // The bare model is loaded by inertia it does not have; with the parts the loads are exactly relieved.
  EXPECT_GT(s_without, 1e4);
  EXPECT_LT(s_with, 1e-9 * s_without);
}

TEST(FrameParts, APartEquallyFarFromTwoNodesHangsFromTheLowerNodeNumber) {
  fem::FrameModel model = small_frame();
  // (0.6, 0, 0.1): 0.2236 m from node 2 (0.4) and node 3 (0.8) alike.
  const auto mounted = coupling::mount_frame_parts(model, std::vector<rigid::RigidPart3D>{{"tank", 10.0, Vector3d(0.6, 0.0, 0.1), rigid::inertia_tensor(0.1, 0.1, 0.1)}});
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(mounted[0].frame_node)].id, 2);
  // Never another part's c.g. node: a second part at the first's c.g. hangs from a beam node too.
  const auto second = coupling::mount_frame_parts(model, std::vector<rigid::RigidPart3D>{{"tank2", 5.0, Vector3d(0.6, 0.0, 0.1), rigid::inertia_tensor(0.1, 0.1, 0.1)}});
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(second[0].frame_node)].id, 2);
}

// The engine of two_parts() on four mounts: nodes 2 and 4 on the rail, 5 and 6 at the cross member's ends.
coupling::FramePart engine_on_four_mounts() {
  coupling::FramePart p{two_parts()[0], {}, {"study.yaml", 9, "frame.parts[0].mounts"}};
  for (int n : {2, 4, 5, 6}) p.mounts.push_back({n, false, Vector3d::Zero(), {"study.yaml", 9, "frame.parts[0].mounts"}});
  return p;
}

TEST(FrameParts, DistributingCouplingFollowsARigidMotionExactlyAndAddsNoStiffness) {
  fem::FrameModel model = small_frame();
  const fem::FrameModel bare = small_frame();
  const std::vector<coupling::MountedPart> mounted = coupling::mount_frame_parts(model, {engine_on_four_mounts()});
  ASSERT_EQ(mounted.size(), 1u);
  ASSERT_EQ(model.distributing_couplings.size(), 1u);
  EXPECT_TRUE(model.rigid_links.empty());
  const int c = mounted[0].mass_node;
  EXPECT_EQ((model.nodes[static_cast<std::size_t>(c)].position - two_parts()[0].cg).norm(), 0.0);

  // A rigid motion of the frame (translation a, rotation theta about the origin): the c.g. node moves with it (Eq. R.7-R.8).
  const fem::DofMap dofs = fem::make_dof_map(model);
  const Vector3d a(1e-3, -2e-3, 0.5e-3), theta(0.01, -0.02, 0.015);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    if (static_cast<int>(i) == c) continue;
    u.segment<3>(6 * static_cast<Eigen::Index>(i)) = a + theta.cross(model.nodes[i].position);
    u.segment<3>(6 * static_cast<Eigen::Index>(i) + 3) = theta;
  }
  fem::fill_slave_dofs(dofs.links, u);
  const Vector3d expected = a + theta.cross(two_parts()[0].cg);
  EXPECT_LT((u.segment<3>(6 * c) - expected).norm(), 1e-15);
  EXPECT_LT((u.segment<3>(6 * c + 3) - theta).norm(), 1e-15);

  // No stiffness added: the c.g. node is a slave, the free DOFs are the bare frame's, K is the bare frame's.
  fem::AssemblyOptions full;
  full.storage = fem::Storage::full;
  const fem::SparseMatrix k_with = fem::assemble(model, dofs, full).stiffness;
  const fem::SparseMatrix k_bare = fem::assemble(bare, fem::make_dof_map(bare), full).stiffness;
  ASSERT_EQ(k_with.rows(), k_bare.rows());
  EXPECT_EQ((Eigen::MatrixXd(k_with) - Eigen::MatrixXd(k_bare)).cwiseAbs().maxCoeff(), 0.0);

  // The rigid-body mass is the hand sum of tubes and part (Eq. 9.3), as with a rigid link.
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(model);
  const rigid::RigidPart3D hand = rigid::combine({rod("rail", Vector3d(0, 0, 0), Vector3d(1.2, 0, 0)), rod("cross", Vector3d(0.8, -0.3, 0), Vector3d(0.8, 0.3, 0)),
                                                  two_parts()[0]},
                                                 "frame");
  EXPECT_NEAR(body.mass, hand.mass, 1e-13 * hand.mass);
  EXPECT_LT((body.cg - hand.cg).norm(), 1e-13);
  EXPECT_LT((body.inertia - hand.inertia).norm(), 1e-12 * hand.inertia.norm());

  // Statics (Eq. 9.6): a force and moment on the c.g. node reach the mounts with the same resultant and moment.
  const Vector3d force(120.0, -80.0, -400.0), moment(15.0, 30.0, -10.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  f.segment<3>(6 * c) = force;
  f.segment<3>(6 * c + 3) = moment;
  fem::fold_slave_forces(dofs.links, f);
  Vector3d resultant = Vector3d::Zero(), about_origin = Vector3d::Zero();
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const Vector3d fi = f.segment<3>(6 * static_cast<Eigen::Index>(i));
    EXPECT_EQ(f.segment<3>(6 * static_cast<Eigen::Index>(i) + 3).norm(), 0.0) << "a moment at node " << model.nodes[i].id;
    resultant += fi;
    about_origin += model.nodes[i].position.cross(fi);
  }
  EXPECT_LT((resultant - force).norm(), 1e-12 * force.norm());
  EXPECT_LT((about_origin - (moment + two_parts()[0].cg.cross(force))).norm(), 1e-12 * force.norm());
  // Mounts 2, 4, 5, 6 (X 0.4, 1.2, 0.8, 0.8) have their centroid at (0.8, 0, 0): a vertical 400 N there goes 1/4 to each
  // mount. At (0.7, 0, 0) it adds the moment 400 N x 0.1 m about Y, which only the rail mounts 2 and 4 (arms -+0.4 m)
  // resist, by least squares +-M r / sum r^2 = 40 x 0.4 / 0.32 = 50 N: 150 N at node 2, 50 N at node 4, 100 N at 5 and 6.
  const auto vertical_shares = [&](double x) {
    fem::FrameModel centred = small_frame();
    coupling::FramePart at = engine_on_four_mounts();
    at.part.cg = Vector3d(x, 0.0, 0.0);
    const auto placed = coupling::mount_frame_parts(centred, {at});
    const fem::DofMap centred_dofs = fem::make_dof_map(centred);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(centred.dof_count());
    g(6 * placed[0].mass_node + 2) = -400.0;
    fem::fold_slave_forces(centred_dofs.links, g);
    std::vector<double> shares;
    for (int id : {2, 4, 5, 6}) shares.push_back(g(6 * centred.node_index(id) + 2));
    return shares;
  };
  const std::vector<double> over_centroid = vertical_shares(0.8), ahead = vertical_shares(0.7);
  const double hand_centroid[4] = {-100, -100, -100, -100}, hand_ahead[4] = {-150, -50, -100, -100};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(over_centroid[i], hand_centroid[i], 1e-12) << "mount " << i;
    EXPECT_NEAR(ahead[i], hand_ahead[i], 1e-12) << "mount " << i;
  }
}

TEST(FrameParts, PartsOnMountsWrittenAsDistributingCouplingsReadBackAsTheSameModel) {
  // frame_parts.inp writes a coupled part as *ELEMENT, TYPE=DCOUP3D + *DISTRIBUTING COUPLING; the reader gives it back.
  fem::FrameModel model = small_frame();
  const auto mounted = coupling::mount_frame_parts(model, {engine_on_four_mounts()});
  const std::string fragment = coupling::frame_parts_inp(model, mounted);
  EXPECT_NE(fragment.find("*DISTRIBUTING COUPLING, ELSET=ENGINE_MOUNTS\n2, 1\n4, 1\n5, 1\n6, 1\n"), std::string::npos) << fragment;
  const fem::FrameModel back = fem::read_inp_text(kFrame + fragment, "frame.inp", ".");
  ASSERT_EQ(back.distributing_couplings.size(), 1u);
  std::vector<int> ids;
  for (int n : back.distributing_couplings[0].mount_nodes) ids.push_back(back.nodes[static_cast<std::size_t>(n)].id);
  EXPECT_EQ(ids, (std::vector<int>{2, 4, 5, 6}));
  fem::AssemblyOptions full;
  full.storage = fem::Storage::full;
  const Eigen::MatrixXd m_run(fem::assemble(model, fem::make_dof_map(model), full).mass);
  const Eigen::MatrixXd m_back(fem::assemble(back, fem::make_dof_map(back), full).mass);
  ASSERT_EQ(m_run.rows(), m_back.rows());
  // 17 significant digits in the file: the same matrix to round-off.
  EXPECT_LT((m_run - m_back).cwiseAbs().maxCoeff(), 1e-13 * m_run.cwiseAbs().maxCoeff());
}

TEST(FrameParts, MountsOnOneLineOrTwiceAtANodeOrOffTheBeamsAreRefusedNamingTheEntry) {
  // Nodes 1, 2, 4 lie on the rail: their rigid fit leaves the rotation about the rail free.
  coupling::FramePart p = engine_on_four_mounts();
  p.mounts.erase(p.mounts.begin() + 2, p.mounts.end());  // 2, 4
  p.mounts.push_back({1, false, Vector3d::Zero(), {"study.yaml", 9, "frame.parts[0].mounts[2]"}});
  fem::FrameModel model = small_frame();
  try {
    coupling::mount_frame_parts(model, {p}, "frame.inp");
    ADD_FAILURE() << "mounts on one line were accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().key, "frame.parts[0].mounts");
  }
  // A point snapped to node 2 next to node 2 given by number.
  coupling::FramePart twice = engine_on_four_mounts();
  twice.mounts[1] = {0, true, Vector3d(0.41, 0.0, 0.0), {"study.yaml", 10, "frame.parts[0].mounts[1]"}};
  model = small_frame();
  EXPECT_THROW(coupling::mount_frame_parts(model, {twice}, "frame.inp"), core::InputError);
  coupling::FramePart off = engine_on_four_mounts();
  off.mounts[3].node = 99;
  model = small_frame();
  EXPECT_THROW(coupling::mount_frame_parts(model, {off}, "frame.inp"), core::InputError);
}

TEST(FrameMassSource, RigidOnlyStudiesOfTheShippedMachineCarryTheMeshsFrameStructure) {
  const std::string source = FRAMEDYN_SOURCE_DIR;
  const coupling::RigidBodyMass mesh = coupling::frame_rigid_body_mass(fem::read_inp(source + "/meshes/r100_frame.inp"));
  constexpr double kInch = 0.0254, kMassUnit = 4.4482216152605 / kInch;
  const Vector3d radii(std::sqrt(mesh.inertia(0, 0) / mesh.mass), std::sqrt(mesh.inertia(1, 1) / mesh.mass), std::sqrt(mesh.inertia(2, 2) / mesh.mass));
  std::printf("[ measured ] meshes/r100_frame.inp: %.4f lbf s^2/in (%.2f lb), c.g. (%.3f, %.1e, %.1e) in, radii of gyration (%.3f, %.3f, %.3f) in, "
              "largest product of inertia %.1e of the largest moment\n",
              mesh.mass / kMassUnit, mesh.mass / kMassUnit * 386.088, mesh.cg.x() / kInch, mesh.cg.y() / kInch, mesh.cg.z() / kInch, radii.x() / kInch,
              radii.y() / kInch, radii.z() / kInch,
              std::max({std::abs(mesh.inertia(0, 1)), std::abs(mesh.inertia(0, 2)), std::abs(mesh.inertia(1, 2))}) / mesh.inertia.maxCoeff());
  for (const char* study : {"r100_plow_straight", "r100_plow_offset", "r100_chain_center", "r100_chain_offset"}) {
    const coupling::RigidStudy s = coupling::read_rigid_study(source + "/examples/" + study + ".yaml");
    const auto& parts = s.machine_3d().frame.parts;
    const auto it = std::find_if(parts.begin(), parts.end(), [](const rigid::RigidPart3D& p) { return p.name == "frame_structure"; });
    ASSERT_NE(it, parts.end()) << study;
    // The study prints weight to 0.1 lb, the c.g. to 0.01 in, the radii to 0.01 in: agreement to those digits.
    EXPECT_NEAR(it->mass / kMassUnit * 386.088, mesh.mass / kMassUnit * 386.088, 0.05) << study;
    EXPECT_LT((it->cg - mesh.cg).norm() / kInch, 0.005) << study;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::sqrt(it->inertia(k, k) / it->mass) / kInch, radii(k) / kInch, 0.005) << study << " axis " << k;
  }
}

coupling::StudyFramePart study_part(const rigid::RigidPart3D& p, bool values = true) {
  coupling::StudyFramePart s;
  s.part = p;
  s.has_values = values;
  s.where = {"study.yaml", 7, "frame.parts[0]"};
  return s;
}

TEST(FrameMassSource, TheMeshGivesTheStructuresMassAndADisagreeingStudyValueIsRefused) {
  const fem::FrameModel mesh = small_frame();
  const coupling::RigidBodyMass tubes = coupling::frame_rigid_body_mass(mesh);
  const core::UnitSystem si = core::UnitSystem::si();
  // The structure as the study wrote it, 0.5 % heavy: within tolerance, replaced by the mesh's values.
  rigid::RigidPart3D close{"frame_structure", 1.005 * tubes.mass, tubes.cg, tubes.inertia};
  const coupling::FrameMassSources ok = coupling::frame_mass_from_mesh({study_part(close), study_part(two_parts()[0])}, mesh, "frame.inp",
                                                                       {"study.yaml", 5, "frame.parts"}, si);
  ASSERT_EQ(ok.vehicle_parts.size(), 2u);
  EXPECT_EQ(ok.vehicle_parts[0].mass, tubes.mass);
  EXPECT_EQ(ok.mounted.size(), 1u);
  EXPECT_EQ(ok.mounted[0].part.name, "engine");
  // Its c.g. 5 cm off (more than 1 % of the 1.2 m extent): refused, naming the part's entry.
  rigid::RigidPart3D off = close;
  off.mass = tubes.mass;
  off.cg.x() += 0.05;
  try {
    coupling::frame_mass_from_mesh({study_part(off)}, mesh, "frame.inp", {"study.yaml", 5, "frame.parts"}, si);
    ADD_FAILURE() << "a structure 5 cm off the mesh's c.g. was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().line, 7);
  }
  // No structure part: refused.
  EXPECT_THROW(coupling::frame_mass_from_mesh({study_part(two_parts()[0])}, mesh, "frame.inp", {"study.yaml", 5, "frame.parts"}, si), core::InputError);
}

TEST(FrameMassSource, APartTheMeshAlreadyCarriesIsNotCountedTwice) {
  // The mesh carries the hitch as a *MASS at node 4 in element set HITCH.
  const fem::FrameModel mesh = fem::read_inp_text(kFrame + "*ELEMENT, TYPE=MASS, ELSET=HITCH\n9, 4\n*MASS, ELSET=HITCH\n15\n", "frame.inp", ".");
  coupling::StudyFramePart structure = study_part({"frame_structure", 0, Vector3d::Zero(), Matrix3d::Zero()}, false);
  structure.from_mesh = true;
  const coupling::FrameMassSources s = coupling::frame_mass_from_mesh({structure, study_part(two_parts()[0]), study_part(two_parts()[1])}, mesh,
                                                                      "frame.inp", {"study.yaml", 5, "frame.parts"}, core::UnitSystem::si());
  ASSERT_EQ(s.carried_by_mesh.size(), 1u);
  EXPECT_EQ(s.carried_by_mesh[0], "hitch");
  EXPECT_EQ(s.mounted.size(), 1u);
  ASSERT_EQ(s.vehicle_parts.size(), 2u);
  // The structure holds the tubes' 33.912 kg and the hitch's 15 kg.
  EXPECT_NEAR(s.vehicle_parts[0].mass, 48.912, 1e-9);
  // Frame model (mesh + mounted) and vehicle model (its parts combined) carry the same mass, c.g. and inertia.
  fem::FrameModel model = mesh;
  coupling::mount_frame_parts(model, s.mounted);
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(model);
  const rigid::RigidPart3D vehicle = rigid::combine(s.vehicle_parts, "frame");
  EXPECT_NEAR(body.mass, vehicle.mass, 1e-12 * vehicle.mass);
  EXPECT_LT((body.cg - vehicle.cg).norm(), 1e-12);
  EXPECT_LT((body.inertia - vehicle.inertia).norm(), 1e-11 * vehicle.inertia.norm());
}

}  // namespace

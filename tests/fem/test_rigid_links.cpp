// Rigid links (*RIGID BODY, *MPC BEAM; fem/rigid_links.h) against closed
// forms and against hand-built equivalents:
//   - a load on a rigid arm at a cantilever tip: bending plus the twist the
//     arm's moment causes, P L^3/(3 E I) + P d^2 L/(G J), exact for cubic
//     (B33) elements;
//   - the arm as a beam of stiffness f E I instead: the offset point moves
//     further by exactly the arm's own cantilever deflection P d^3/(3 f E I),
//     so the stiff-beam model converges to the rigid one as 1/f;
//   - an offset point mass on a rigid arm at the tip of a massless cantilever:
//     the six frequencies from the 2x2 problems with the mass's inertia about
//     the tip (m d^2 plus its own rotary inertia), and the stiff-arm model's
//     frequencies converging to them as 1/f;
//   - which end of a link is the reference node changes no frequency;
//   - mass bookkeeping: total mass and centre of mass of a free frame with
//     offset masses on links from the reduced mass matrix T^T M T equal the
//     hand sum; six rigid-body modes;
//   - a *RIGID BODY of several nodes read from a deck moves rigidly (every
//     pair's linearised length change is zero, all rotations equal), and the
//     reactions balance the loads on the tied nodes;
//   - the transient solvers' static path (FrameDynamics) equals the static solve;
//   - the reader's refusals (ROT NODE, conflicts, chains, undefined nodes).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/modal_transient.h"
#include "fem/rigid_links.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

namespace fem = framedyn::fem;
namespace support = framedyn::testing;
using fem::FrameModel;

constexpr double kE = 210.0e9, kNu = 0.3;

// A B33 cantilever along +x from the origin, clamped there; tip = node `elements`.
FrameModel cantilever(double length, int elements, const fem::SectionProperties& section, double density) {
  support::StraightBeamSpec spec;
  spec.length = length;
  spec.elements = elements;
  spec.section = section;
  spec.material = support::isotropic_material("S", kE, kNu, density);
  spec.theory = fem::BeamTheory::euler_bernoulli;
  FrameModel m = support::straight_beam(spec);
  support::clamp_node(m, 0);
  return m;
}

void add_link(FrameModel& m, int reference, std::vector<int> slaves) {
  fem::RigidLink link;
  link.reference_node = reference;
  link.slave_nodes = std::move(slaves);
  link.source = "test link";
  m.rigid_links.push_back(link);
  m.index();
}

// The arm as one B33 element of `factor` times the beam's stiffness (E and G scaled), massless.
int add_stiff_arm(FrameModel& m, int from, const Eigen::Vector3d& to, const fem::SectionProperties& section, double factor,
                  const Eigen::Vector3d& n1) {
  fem::Material stiff = support::isotropic_material("ARM", kE * factor, kNu, 0.0);
  const int s = support::add_section(m, section, stiff, n1);
  const std::vector<int> line = support::add_beam_line(m, from, to, 1, s, fem::BeamTheory::euler_bernoulli);
  m.index();
  return line.back();
}

void add_point_mass(FrameModel& m, int node, double mass, const Eigen::Vector3d& inertia) {
  fem::PointMass pm;
  pm.node = node;
  pm.mass = mass;
  pm.rotary_inertia = inertia.asDiagonal();
  m.point_masses.push_back(pm);
}

// Resultant force and moment about the origin of the reactions and the applied loads: zero in equilibrium.
Eigen::Matrix<double, 6, 1> out_of_balance(const FrameModel& m, const fem::StaticResult& r) {
  Eigen::Matrix<double, 6, 1> sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const Eigen::Index o = static_cast<Eigen::Index>(6 * i);
    const Eigen::Vector3d f = r.reaction.segment<3>(o) + r.applied.segment<3>(o);
    const Eigen::Vector3d mo = r.reaction.segment<3>(o + 3) + r.applied.segment<3>(o + 3);
    sum.head<3>() += f;
    sum.tail<3>() += mo + m.nodes[i].position.cross(f);
  }
  return sum;
}

double applied_scale(const FrameModel& m, const fem::StaticResult& r) {
  double s = 0.0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    s += r.applied.segment<3>(static_cast<Eigen::Index>(6 * i)).norm() * (1.0 + m.nodes[i].position.norm()) +
         r.applied.segment<3>(static_cast<Eigen::Index>(6 * i + 3)).norm();
  return s;
}

// ------------------------------------------------------------------ statics

const double kL = 2.0, kArm = 0.5, kP = 1000.0;

TEST(RigidLinks, LoadOnARigidArmBendsAndTwistsTheCantileverAsTheClosedFormSays) {
  const fem::SectionProperties sq = fem::rectangle_section(0.06, 0.06, kNu);
  FrameModel m = cantilever(kL, 8, sq, 7850.0);
  const int tip = 8;
  const int off = support::add_node(m, Eigen::Vector3d(kL, 0.0, -kArm));
  add_link(m, tip, {off});
  support::add_nodal_force(m, off, Eigen::Vector3d(0.0, kP, 0.0));
  const fem::StaticResult r = fem::solve_static(m);
  const double g = kE / (2.0 * (1.0 + kNu));
  // Moment of P about the tip, (0,0,-d) x (0,P,0) = (P d, 0, 0): twist theta_x = P d L / (G J),
  // which moves the arm's end by theta_x d in y on top of the bending P L^3 / (3 E I).
  const double bending = kP * kL * kL * kL / (3.0 * kE * sq.i11);
  const double twist = kP * kArm * kL / (g * sq.torsion_constant);
  EXPECT_NEAR(r.displacement(6 * off + 1), bending + twist * kArm, 1e-10 * (bending + twist * kArm));
  std::printf("offset point deflection %.10g m, closed form %.10g m, relative error %.2e\n", r.displacement(6 * off + 1),
              bending + twist * kArm, r.displacement(6 * off + 1) / (bending + twist * kArm) - 1.0);
  EXPECT_NEAR(r.displacement(6 * tip + 3), twist, 1e-10 * twist);
  // The arm's end turns with the tip (theta_s = theta_r).
  for (int k = 3; k < 6; ++k) EXPECT_EQ(r.displacement(6 * off + k), r.displacement(6 * tip + k));
  // Clamp reactions: -P in y and -(P d, 0, P L) about the clamp.
  EXPECT_NEAR(r.reaction(1), -kP, 1e-9 * kP);
  EXPECT_NEAR(r.reaction(3), -kP * kArm, 1e-9 * kP);
  EXPECT_NEAR(r.reaction(5), -kP * kL, 1e-9 * kP);
  EXPECT_LT(out_of_balance(m, r).norm(), 1e-12 * applied_scale(m, r));
}

TEST(RigidLinks, StiffBeamArmConvergesToTheRigidLinkByTheArmsOwnDeflection) {
  const fem::SectionProperties sq = fem::rectangle_section(0.06, 0.06, kNu);
  FrameModel rigid = cantilever(kL, 8, sq, 7850.0);
  const int off = support::add_node(rigid, Eigen::Vector3d(kL, 0.0, -kArm));
  add_link(rigid, 8, {off});
  support::add_nodal_force(rigid, off, Eigen::Vector3d(0.0, kP, 0.0));
  const double u_rigid = fem::solve_static(rigid).displacement(6 * off + 1);
  double previous = 0.0;
  for (double factor : {1.0, 10.0, 100.0, 1000.0, 10000.0}) {
    FrameModel beam = cantilever(kL, 8, sq, 7850.0);
    const int end = add_stiff_arm(beam, 8, Eigen::Vector3d(kL, 0.0, -kArm), sq, factor, Eigen::Vector3d::UnitX());
    support::add_nodal_force(beam, end, Eigen::Vector3d(0.0, kP, 0.0));
    const double u_beam = fem::solve_static(beam).displacement(6 * end + 1);
    // The arm (along -z, loaded in y) is a cantilever on the tip: it adds P d^3 / (3 f E I), nothing else.
    const double arm = kP * kArm * kArm * kArm / (3.0 * factor * kE * sq.i11);
    // Round-off: the solve loses about eps times the condition number, which grows with f.
    EXPECT_NEAR(u_beam - u_rigid, arm, 1e-8 * arm + 1e-13 * factor * u_rigid) << "factor " << factor;
    std::printf("arm stiffness factor %g: u_beam - u_rigid = %.6e m, P d^3/(3 f E I) = %.6e m, relative difference %.2e\n", factor,
                u_beam - u_rigid, arm, (u_beam - u_rigid) / arm - 1.0);
    if (previous > 0.0) {
      EXPECT_LT(u_beam - u_rigid, previous / 5.0);
    }
    previous = u_beam - u_rigid;
  }
}

TEST(RigidLinks, SupportedReferenceNodeCarriesTheLoadsOfItsTiedNodes) {
  // A cantilever whose clamped root carries a bracket: the load on the
  // bracket goes straight to the support, the beam stays unstrained.
  const fem::SectionProperties sq = fem::rectangle_section(0.06, 0.06, kNu);
  FrameModel m = cantilever(kL, 4, sq, 7850.0);
  const int bracket = support::add_node(m, Eigen::Vector3d(-0.3, 0.2, 0.1));
  add_link(m, 0, {bracket});
  support::add_nodal_force(m, bracket, Eigen::Vector3d(100.0, -200.0, 300.0));
  support::add_nodal_force(m, 4, Eigen::Vector3d(0.0, 0.0, -50.0));
  const fem::StaticResult r = fem::solve_static(m);
  EXPECT_EQ(r.displacement.segment<6>(6 * bracket).norm(), 0.0);
  EXPECT_LT(out_of_balance(m, r).norm(), 1e-12 * applied_scale(m, r));
  EXPECT_NEAR(r.reaction(0), -100.0, 1e-9);
  EXPECT_NEAR(r.reaction(1), 200.0, 1e-9);
  EXPECT_NEAR(r.reaction(2), -250.0, 1e-9);
}

// ------------------------------------------------------------------ modes

// Eigenvalues of the 2x2 problem K x = lambda M x, ascending.
Eigen::Vector2d eigenvalues_2x2(const Eigen::Matrix2d& k, const Eigen::Matrix2d& m) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, m);
  return es.eigenvalues();
}

// A massless one-element cantilever (length 1, 40 x 80 mm) with a 50 kg mass
// on a rigid arm 0.3 m beyond its tip along the beam axis.
struct OffsetMassCase {
  double length = 1.0, arm = 0.3, mass = 50.0;
  Eigen::Vector3d inertia{2.0, 3.0, 4.0};  // kg m^2, the mass's own, about its centre
  fem::SectionProperties section = fem::rectangle_section(0.04, 0.08, kNu);
};

// The six exact eigenvalues (rad^2/s^2): axial, torsion, and the two bending
// planes, each a 2x2 problem in (deflection, slope) at the tip with the
// mass's inertia about the tip m d^2 + J (the cubic element is the exact
// stiffness of the massless beam).
std::vector<double> offset_mass_eigenvalues(const OffsetMassCase& c) {
  const double l = c.length, d = c.arm, m = c.mass, g = kE / (2.0 * (1.0 + kNu));
  std::vector<double> out;
  out.push_back(kE * c.section.area / l / m);
  out.push_back(g * c.section.torsion_constant / l / c.inertia.x());
  // n1 = -z: i11 is about z (bending in y), i22 about y (bending in z).
  for (const auto& [i, j] : {std::pair<double, double>{c.section.i11, c.inertia.z()}, {c.section.i22, c.inertia.y()}}) {
    Eigen::Matrix2d k, mm;
    k << 12.0, -6.0 * l, -6.0 * l, 4.0 * l * l;
    k *= kE * i / (l * l * l);
    mm << m, m * d, m * d, m * d * d + j;
    const Eigen::Vector2d ev = eigenvalues_2x2(k, mm);
    out.push_back(ev(0));
    out.push_back(ev(1));
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(RigidLinks, OffsetMassOnARigidArmHasTheFrequenciesOfItsInertiaAboutTheTip) {
  const OffsetMassCase c;
  FrameModel m = cantilever(c.length, 1, c.section, 0.0);
  const int off = support::add_node(m, Eigen::Vector3d(c.length + c.arm, 0.0, 0.0));
  add_link(m, 1, {off});
  add_point_mass(m, off, c.mass, c.inertia);
  const std::vector<double> exact = offset_mass_eigenvalues(c);

  // All six by the dense solution of T^T K T, T^T M T.
  const fem::FrameDynamics frame(m);
  const fem::ModalBasis all = frame.all_modes();
  ASSERT_EQ(all.eigenvalues.size(), 6);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(all.eigenvalues(i), exact[static_cast<std::size_t>(i)], 1e-10 * exact[static_cast<std::size_t>(i)]);
    std::printf("mode %d: %.8g Hz, closed form %.8g Hz, relative eigenvalue error %.2e\n", i + 1, std::sqrt(all.eigenvalues(i)) / (2 * M_PI),
                std::sqrt(exact[static_cast<std::size_t>(i)]) / (2 * M_PI), all.eigenvalues(i) / exact[static_cast<std::size_t>(i)] - 1.0);
  }

  // The Lanczos path, and the shapes expanded to the tied node: u_s = u_r + theta_r x d.
  fem::ModalOptions o;
  o.mode_count = 5;
  const fem::ModalResult modes = fem::compute_modes(m, o);
  const Eigen::Vector3d d(c.arm, 0.0, 0.0);
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(modes.modes[static_cast<std::size_t>(i)].eigenvalue, exact[static_cast<std::size_t>(i)], 1e-9 * exact[static_cast<std::size_t>(i)]);
    const Eigen::VectorXd phi = modes.shapes.col(i);
    const Eigen::Vector3d u_s = phi.segment<3>(6).eval() + phi.segment<3>(9).cross(d);
    EXPECT_LT((phi.segment<3>(6 * off) - u_s).norm(), 1e-14 * phi.norm());
    EXPECT_LT((phi.segment<3>(6 * off + 3) - phi.segment<3>(9)).norm(), 1e-14 * phi.norm());
  }
  // Without the m d^2 the fundamental would be far off: the check above is sharp.
  const double l = c.length;
  const double naive = 3.0 * kE * c.section.i22 / (l * l * l) / c.mass;
  EXPECT_GT(std::abs(exact[0] - naive), 0.2 * naive);
}

TEST(RigidLinks, WhichEndOfARigidLinkIsTheReferenceChangesNothing) {
  // The same offset mass, once with the beam's tip as the reference node and
  // once with the mass's node as the reference (the beam element then ends on
  // a slave node): a rigid link is symmetric, the choice is bookkeeping.
  const OffsetMassCase c;
  std::vector<Eigen::VectorXd> eigenvalues;
  for (bool tip_is_reference : {true, false}) {
    FrameModel m = cantilever(2.0, 10, c.section, 7850.0);
    const int off = support::add_node(m, Eigen::Vector3d(2.0 + c.arm, 0.1, -0.2));
    if (tip_is_reference) add_link(m, 10, {off});
    else add_link(m, off, {10});
    add_point_mass(m, off, c.mass, c.inertia);
    support::add_nodal_force(m, off, Eigen::Vector3d(100.0, -200.0, 300.0));
    fem::ModalOptions o;
    o.mode_count = 8;
    const fem::ModalResult modes = fem::compute_modes(m, o);
    Eigen::VectorXd ev(8);
    for (int i = 0; i < 8; ++i) ev(i) = modes.modes[static_cast<std::size_t>(i)].eigenvalue;
    eigenvalues.push_back(ev);
    if (!tip_is_reference) {
      const fem::StaticResult r = fem::solve_static(m);
      EXPECT_LT(out_of_balance(m, r).norm(), 1e-12 * applied_scale(m, r));
    }
  }
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(eigenvalues[1](i), eigenvalues[0](i), 1e-9 * eigenvalues[0](i)) << "mode " << i + 1;
}

TEST(RigidLinks, StiffBeamArmFrequenciesConvergeToTheRigidLinkAsOneOverItsStiffness) {
  const OffsetMassCase c;
  // A small mass at the tip so that the beam-arm model has no massless node.
  auto base = [&]() {
    FrameModel m = cantilever(c.length, 1, c.section, 0.0);
    add_point_mass(m, 1, 1.0, Eigen::Vector3d(0.01, 0.01, 0.01));
    return m;
  };
  FrameModel rigid = base();
  const int off = support::add_node(rigid, Eigen::Vector3d(c.length + c.arm, 0.0, 0.0));
  add_link(rigid, 1, {off});
  add_point_mass(rigid, off, c.mass, c.inertia);
  fem::ModalOptions o;
  o.mode_count = 5;
  const fem::ModalResult reference = fem::compute_modes(rigid, o);
  std::vector<double> worst;
  std::vector<Eigen::VectorXd> eigenvalues;
  const std::vector<double> factors = {1e1, 1e2, 1e3, 1e4};
  for (double factor : factors) {
    FrameModel beam = base();
    const int end = add_stiff_arm(beam, 1, Eigen::Vector3d(c.length + c.arm, 0.0, 0.0), c.section, factor, Eigen::Vector3d(0, 0, -1));
    add_point_mass(beam, end, c.mass, c.inertia);
    const fem::ModalResult modes = fem::compute_modes(beam, o);
    double e = 0.0;
    eigenvalues.emplace_back(5);
    for (int i = 0; i < 5; ++i) {
      eigenvalues.back()(i) = modes.modes[static_cast<std::size_t>(i)].eigenvalue;
      const double lr = reference.modes[static_cast<std::size_t>(i)].eigenvalue;
      e = std::max(e, std::abs(modes.modes[static_cast<std::size_t>(i)].eigenvalue - lr) / lr);
    }
    worst.push_back(e);
  }
  // The arm's compliance is 1/f of the beam's order: the error falls tenfold per decade of f
  // (first-order perturbation): measured 0.149 at f = 10 down to 1.75e-4 at f = 1e4.
  for (std::size_t k = 1; k < worst.size(); ++k) {
    const double ratio = worst[k - 1] / worst[k];
    std::printf("f = %g: largest relative eigenvalue error %.3e (f = %g: %.3e), ratio %.3f\n", factors[k], worst[k], factors[k - 1], worst[k - 1], ratio);
    EXPECT_GT(ratio, 8.0) << "f = " << factors[k];
    EXPECT_LT(ratio, 12.0) << "f = " << factors[k];
  }
  // The limit is the rigid link's: lambda(f) = lambda_0 + C/f + D/f^2, so the
  // Richardson value (10 lambda(1e4) - lambda(1e3)) / 9 = lambda_0 - 1e-7 D
  // (D of order C^2, C about 1.75 from the errors above: a few 1e-7; measured up to 3.1e-7).
  for (int i = 0; i < 5; ++i) {
    const double extrapolated = (10.0 * eigenvalues[3](i) - eigenvalues[2](i)) / 9.0;
    const double lr = reference.modes[static_cast<std::size_t>(i)].eigenvalue;
    EXPECT_NEAR(extrapolated, lr, 2e-6 * lr) << "mode " << i + 1;
    std::printf("mode %d: Richardson limit of the stiff arm against the rigid link: %.2e\n", i + 1, extrapolated / lr - 1.0);
  }
}

// ------------------------------------------------------------ mass bookkeeping

TEST(RigidLinks, MassAndCentreOfMassOfAFrameWithOffsetMassesEqualTheHandSum) {
  const fem::SectionProperties sq = fem::rectangle_section(0.06, 0.06, kNu);
  support::StraightBeamSpec spec;
  spec.length = kL;
  spec.elements = 10;
  spec.section = sq;
  spec.material = support::steel();
  FrameModel m = support::straight_beam(spec);  // free-free
  // An engine of three mounts tied to node 5, a tank on an arm at node 10.
  const Eigen::Vector3d p1(0.8, 0.3, 0.4), p2(1.2, -0.3, 0.4), p3(1.0, 0.0, 0.9), p4(kL, 0.1, -0.5);
  const int n1 = support::add_node(m, p1), n2 = support::add_node(m, p2), n3 = support::add_node(m, p3), n4 = support::add_node(m, p4);
  add_link(m, 5, {n1, n2, n3});
  add_link(m, 10, {n4});
  add_point_mass(m, n1, 40.0, Eigen::Vector3d(1, 1, 1));
  add_point_mass(m, n2, 60.0, Eigen::Vector3d(1, 1, 1));
  add_point_mass(m, n3, 100.0, Eigen::Vector3d(2, 2, 2));
  add_point_mass(m, n4, 80.0, Eigen::Vector3d(3, 3, 3));
  const double beam_mass = 7850.0 * sq.area * kL;
  const double total = beam_mass + 40.0 + 60.0 + 100.0 + 80.0;
  const Eigen::Vector3d first_moment = beam_mass * Eigen::Vector3d(kL / 2, 0, 0) + 40.0 * p1 + 60.0 * p2 + 100.0 * p3 + 80.0 * p4;

  // Rigid-body vectors about the origin on the equations (the masters), against T^T M T.
  const fem::DofMap dofs = fem::make_dof_map(m);
  const fem::FreeSystem sys = fem::assemble(m, dofs, {fem::MassFormulation::consistent, fem::Storage::full});
  const Eigen::MatrixXd r_all = fem::rigid_body_vectors(m, Eigen::Vector3d::Zero());
  Eigen::MatrixXd r(dofs.free_count(), 6);
  for (int e = 0; e < dofs.free_count(); ++e) r.row(e) = r_all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
  const Eigen::MatrixXd m6 = r.transpose() * (sys.mass * r);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m6(k, k), total, 1e-12 * total);
  // r_y^T M r_rz = sum m x, r_z^T M r_rx = sum m y, r_x^T M r_ry = sum m z (rotation e_k x p).
  EXPECT_NEAR(m6(1, 5), first_moment.x(), 1e-12 * total);
  EXPECT_NEAR(m6(2, 3), first_moment.y(), 1e-12 * total);
  EXPECT_NEAR(m6(0, 4), first_moment.z(), 1e-12 * total);
  std::printf("total mass %.12g kg (hand %.12g), centre of mass (%.9g, %.9g, %.9g) m (hand (%.9g, %.9g, %.9g))\n", m6(0, 0), total,
              m6(1, 5) / m6(0, 0), m6(2, 3) / m6(0, 0), m6(0, 4) / m6(0, 0), first_moment.x() / total, first_moment.y() / total,
              first_moment.z() / total);
  // The modal solver reports the same total and finds the six rigid-body modes.
  fem::ModalOptions o;
  o.mode_count = 8;
  const fem::ModalResult modes = fem::compute_modes(m, o);
  EXPECT_NEAR(modes.total_mass(0), total, 1e-12 * total);
  int rigid_modes = 0;
  for (const fem::Mode& mode : modes.modes) rigid_modes += mode.rigid_body ? 1 : 0;
  EXPECT_EQ(rigid_modes, 6);
  EXPECT_GT(modes.modes[6].frequency_hz, 0.0);
  // The free-free dynamics (inertia relief) sets up on the masters only.
  const fem::FrameDynamics frame(m);
  EXPECT_TRUE(frame.free_free());
  for (int e : frame.auxiliary_supports()) EXPECT_FALSE(dofs.links.is_slave(dofs.free_dofs[static_cast<std::size_t>(e)]));
}

// ------------------------------------------------------------- from a deck

const std::string kEngineDeck =
    "** units: m-N-s\n"
    "*NODE, NSET=ALL\n"
    "1, 0, 0, 0\n2, 0.5, 0, 0\n3, 1.0, 0, 0\n4, 1.5, 0, 0\n5, 2.0, 0, 0\n"
    "11, 0.8, 0.3, 0.4\n12, 1.2, -0.3, 0.4\n13, 1.0, 0.0, 0.9\n20, 2.0, 0.2, -0.5\n"
    "*NSET, NSET=ENGINE\n11, 12, 13\n"
    "*ELEMENT, TYPE=B31, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
    "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.06, 0.08\n"
    "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n"
    "*RIGID BODY, NSET=ENGINE, REF NODE=3\n"
    "*MPC\nBEAM, 20, 5\n"
    "*BOUNDARY\n1, 1, 6\n"
    "*CLOAD\n11, 2, 1000\n13, 1, -500\n13, 3, 300\n12, 3, -800\n20, 2, 400\n20, 4, 50\n";

FrameModel read(const std::string& text) { return fem::read_inp_text(text, "frame.inp", "."); }

TEST(RigidLinks, RigidBodyOfSeveralNodesMovesRigidlyInAStaticSolve) {
  const FrameModel m = read(kEngineDeck);
  ASSERT_EQ(m.rigid_links.size(), 2u);
  const fem::StaticResult r = fem::solve_static(m);
  auto disp = [&](int id) { return r.displacement.segment<3>(6 * m.node_index(id)).eval(); };
  auto rot = [&](int id) { return r.displacement.segment<3>(6 * m.node_index(id) + 3).eval(); };
  auto pos = [&](int id) { return m.nodes[static_cast<std::size_t>(m.node_index(id))].position; };
  for (const std::vector<int>& body : {std::vector<int>{3, 11, 12, 13}, std::vector<int>{5, 20}}) {
    const double scale = disp(body[0]).norm() + rot(body[0]).norm();
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < body.size(); ++i) {
      EXPECT_LT((rot(body[i]) - rot(body[0])).norm(), 1e-15 * scale);
      for (std::size_t j = i + 1; j < body.size(); ++j) {
        // A small rigid motion changes no length to first order: (x_i - x_j) . (u_i - u_j) = 0.
        const Eigen::Vector3d dx = pos(body[i]) - pos(body[j]);
        EXPECT_LT(std::abs(dx.dot(disp(body[i]) - disp(body[j]))), 1e-14 * dx.norm() * scale)
            << "nodes " << body[i] << " and " << body[j];
      }
    }
  }
  // The beam is loaded only through the links; the clamp balances it all.
  EXPECT_LT(out_of_balance(m, r).norm(), 1e-12 * applied_scale(m, r));
  EXPECT_GT(r.displacement.segment<3>(6 * m.node_index(5)).norm(), 0.0);
}

TEST(RigidLinks, TransientSolversStaticPathEqualsTheStaticSolve) {
  const FrameModel m = read(kEngineDeck);
  const fem::StaticResult r = fem::solve_static(m);
  const fem::FrameDynamics frame(m);
  fem::SparseMatrix distribution(m.dof_count(), 1);
  std::vector<Eigen::Triplet<double, int>> t;
  for (const fem::NodalLoad& l : m.loads) t.emplace_back(6 * l.node + l.dof, 0, l.value);
  distribution.setFromTriplets(t.begin(), t.end());
  const Eigen::VectorXd u = frame.expand(frame.static_response(frame.free_loads(distribution).col(0)));
  EXPECT_LT((u - r.displacement).norm(), 1e-12 * r.displacement.norm());
}

// ------------------------------------------------------------ reader errors

// The message of the InputError that reading `text` throws ("" if none).
std::string read_error(const std::string& text) {
  try {
    read(text);
  } catch (const framedyn::core::InputError& e) {
    return e.what();
  }
  return "";
}

// kEngineDeck with `from` replaced by `to`.
std::string engine_with(const std::string& from, const std::string& to) {
  std::string s = kEngineDeck;
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(RigidLinksReader, TiedNodeWithABoundaryIsRefused) {
  EXPECT_EQ(read_error(engine_with("*BOUNDARY\n1, 1, 6\n", "*BOUNDARY\n1, 1, 6\n12, 2\n")),
            "frame.inp:26: *RIGID BODY: expected no *BOUNDARY on the nodes the link ties (support the reference node 3 "
            "instead), found a *BOUNDARY on node 12 (uy)");
}

TEST(RigidLinksReader, NodeTiedByTwoLinksIsRefused) {
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "BEAM, 20, 5\nBEAM, 13, 5\n")),
            "frame.inp:29: *MPC: expected each node tied to one rigid link only, found node 13 already tied by "
            "frame.inp:26: *RIGID BODY");
}

TEST(RigidLinksReader, ChainOfRigidLinksIsRefused) {
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "BEAM, 20, 13\n")),
            "frame.inp:28: *MPC: expected a reference node that is not tied to another rigid link (chains of rigid links "
            "are not resolved), found reference node 13, tied by frame.inp:26: *RIGID BODY");
}

TEST(RigidLinksReader, UndefinedReferenceNodeIsRefused) {
  EXPECT_EQ(read_error(engine_with("REF NODE=3", "REF NODE=99")),
            "frame.inp:26: *RIGID BODY: expected a reference node defined by *NODE, found node 99");
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "BEAM, 20, 77\n")),
            "frame.inp:28: *MPC: expected a reference node defined by *NODE, found node 77");
}

TEST(RigidLinksReader, RotNodeIsRefusedWithWhatToDoInstead) {
  const std::string msg = read_error(engine_with("REF NODE=3", "REF NODE=3, ROT NODE=5"));
  EXPECT_EQ(msg.rfind("frame.inp:26: *RIGID BODY: expected no ROT NODE", 0), 0u) << msg;
  EXPECT_NE(msg.find("DOFs 4-6 of the REF NODE"), std::string::npos) << msg;
}

TEST(RigidLinksReader, OtherMpcTypesAndMalformedLinesAreRefused) {
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "PIN, 20, 5\n")),
            "frame.inp:28: *MPC: expected an MPC of type BEAM (a rigid link; framedyn reads no other MPC type), found 'PIN'");
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "BEAM, 20\n")),
            "frame.inp:28: *MPC: expected BEAM, slave node, master node, found 'BEAM, 20'");
  EXPECT_EQ(read_error(engine_with("BEAM, 20, 5\n", "BEAM, 5, 5\n")),
            "frame.inp:28: *MPC: expected slave nodes other than the reference node, found node 5 in both roles");
  EXPECT_EQ(read_error(engine_with("*RIGID BODY, NSET=ENGINE, REF NODE=3\n", "*RIGID BODY, REF NODE=3\n")),
            "frame.inp:26: *RIGID BODY: expected NSET=, TIE NSET= or PIN NSET= naming the nodes the reference node "
            "carries, found none");
  EXPECT_EQ(read_error(engine_with("REF NODE=3", "REF NODE=ENGINE")),
            "frame.inp:26: *RIGID BODY: expected one reference node, found set ENGINE of 3 nodes");
}

TEST(RigidLinksReader, LeverArmThatWouldOverflowTheReducedMatricesIsRefused) {
  // Each element is within range, but T^T K T multiplies by d^2 (found by thinking like the fuzzer).
  const std::string msg = read_error(engine_with("20, 2.0, 0.2, -0.5", "20, 2.0, 0.2, -1e150"));
  EXPECT_EQ(msg.rfind("frame.inp:28: *MPC: expected a lever arm that keeps the tied node's stiffness, mass and loads within floating "
                      "point once carried to the reference node (at most 1e300 in SI units), found node 20 at d = 1e+150 m",
                      0),
            0u)
      << msg;
  // A long but sane arm is accepted.
  EXPECT_EQ(read_error(engine_with("20, 2.0, 0.2, -0.5", "20, 2.0, 0.2, -1e3")), "");
}

TEST(RigidLinksReader, PinNsetTiesTranslationsOnly) {
  const FrameModel m = read(engine_with("*RIGID BODY, NSET=ENGINE", "*RIGID BODY, PIN NSET=ENGINE"));
  ASSERT_EQ(m.rigid_links.size(), 2u);
  EXPECT_FALSE(m.rigid_links[0].slave_rotations);
  const fem::DofMap dofs = fem::make_dof_map(m);
  const int n = m.node_index(11);
  EXPECT_TRUE(dofs.links.is_slave(6 * n));
  EXPECT_FALSE(dofs.links.is_slave(6 * n + 3));
}

}  // namespace

// ---------------------------------------------------------------------------
// Beam offsets (CalculiX OFFSET1/OFFSET2, Eq. 3.5) are rigid eccentricities.
namespace {

// A cantilever along x whose axis lies e = OFFSET1 a below its nodes (n1 = y;
// CalculiX: OFFSET1 = 0.5 puts the nodes on the section's +1 face, the axis at
// y = -a/2). An axial tip force P at the node acts at e from the axis: the
// member carries N = P and a constant moment M_z = -P e, so the axis bends by
// -P e L^2 / (2 E I) at the tip and turns by -P e L / (E I); the node, e above
// the axis, moves along x by P L / (E A) + P e^2 L / (E I). Exact for
// any element (constant moment, no shear).
TEST(BeamOffsets, AxialTipLoadOnAnOffsetAxisBendsByTheEccentricMoment) {
  constexpr double kE = 2.1e11, kA1 = 0.1, kA2 = 0.05, kL = 1.0, kP = 1e4;
  for (const char* type : {"B31", "B33", "B32"}) {
    const bool quadratic = std::string(type) == "B32";
    std::string s = "** units: m-N-s\n*NODE\n";
    const int n = quadratic ? 9 : 5;
    for (int i = 0; i < n; ++i) s += fmt::format("{}, {:.15g}, 0, 0\n", i + 1, kL * i / (n - 1));
    s += fmt::format("*ELEMENT, TYPE={}, ELSET=FRAME\n", type);
    if (quadratic)
      for (int e = 0; e < 4; ++e) s += fmt::format("{}, {}, {}, {}\n", e + 1, 2 * e + 1, 2 * e + 2, 2 * e + 3);
    else
      for (int e = 0; e < 4; ++e) s += fmt::format("{}, {}, {}\n", e + 1, e + 1, e + 2);
    s += "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT, OFFSET1=0.5\n0.1, 0.05\n0, 1, 0\n"
         "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*BOUNDARY\n1, 1, 6\n";
    s += fmt::format("*STEP\n*STATIC\n*CLOAD\n{}, 1, {:.15g}\n*END STEP\n", n, kP);
    const fem::FrameModel m = fem::read_inp_text(s, "deck.inp", ".");
    EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(n + (quadratic ? 12 : 8))) << type;  // one axis node per element end
    const fem::StaticResult r = fem::solve_static(m);
    const double e = 0.5 * kA1, i = kA2 * kA1 * kA1 * kA1 / 12.0, area = kA1 * kA2;
    const int tip = 6 * m.node_index(n);
    const double ux = kP * kL / (kE * area) + kP * e * e * kL / (kE * i), uy = -kP * e * kL * kL / (2.0 * kE * i), rz = -kP * e * kL / (kE * i);
    EXPECT_NEAR(r.displacement(tip + 0), ux, 1e-9 * ux) << type;
    EXPECT_NEAR(r.displacement(tip + 1), uy, 1e-9 * std::abs(uy)) << type;
    EXPECT_NEAR(r.displacement(tip + 5), rz, 1e-9 * std::abs(rz)) << type;
    // The root's reactions balance P: no moment at the node from an eccentric axis the link holds.
    EXPECT_NEAR(r.reaction(0), -kP, 1e-6 * kP) << type;
  }
}

}  // namespace

// ---------------------------------------------------------------------------
// Offsets on every section shape (docs/theory/fem.md section 21, Eq. 21.1).
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& e) {
  Eigen::Matrix3d s;
  s << 0, -e.z(), e.y(), e.z(), 0, -e.x(), -e.y(), e.x(), 0;
  return s;
}

// A B33 cantilever along x (n1 = y, so local 1 = y, local 2 = z), clamped at
// node 1, OFFSET1 = 0.5 and OFFSET2 = -0.25 section heights. The tip node's
// flexibility (six unit loads at the node) must equal the centroidal
// cantilever's, C_a (Euler-Bernoulli, exact for end loads), carried to the
// node by the rigid arm from axis to node: C_n = T C_a T^T, T = [I, S(e); 0, I],
// u_n = u_a + e x theta_a, with e = x_a - x_n = -(OFFSET1 h1 n1 + OFFSET2 h2 n2)
// (Eq. 21.1). The section heights h1, h2 are the hand values CalculiX uses
// (measured on its expanded mesh): CIRC the value written (0.1), PIPE the outer
// diameter 2r; I and CHANNEL their outline (wider flange along 1, height along 2).
// This couples axial force with both bending planes and torsion with the
// transverse forces: every entry of the 6 x 6 matrix is checked.
TEST(BeamOffsets, OffsetSectionIsTheCentroidalCantileverCarriedByTheRigidArmOnEveryShape) {
  struct Shape {
    const char* section;
    const char* dims;
    double h1, h2;
  };
  const std::vector<Shape> shapes = {{"CIRC", "0.1", 0.1, 0.1},
                                     {"PIPE", "0.1, 0.01", 0.2, 0.2},
                                     {"I", "0, 0.3, 0.15, 0.2, 0.02, 0.025, 0.01", 0.2, 0.3},
                                     {"CHANNEL", "0.2, 0.08, 0.01, 0.008", 0.08, 0.2},
                                     {"RECT", "0.1, 0.05", 0.1, 0.05}};
  constexpr double kE = 2.1e11, kNu = 0.3, kL = 2.0;
  const double g = kE / (2.0 * (1.0 + kNu));
  for (const Shape& sh : shapes) {
    std::string s = "** units: m-N-s\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n*ELEMENT, TYPE=B33, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n";
    s += fmt::format("*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION={}, OFFSET1=0.5, OFFSET2=-0.25\n{}\n0, 1, 0\n", sh.section, sh.dims);
    s += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*BOUNDARY\n1, 1, 6\n";
    fem::FrameModel m = fem::read_inp_text(s, "deck.inp", ".");
    const fem::SectionProperties& p = m.sections.at(0).properties;
    const double a = p.area, i1 = p.i11, i2 = p.i22, j = p.torsion_constant;
    // Centroidal cantilever, tip (F, M) -> (u, theta), global axes x, y = 1, z = 2.
    Eigen::Matrix<double, 6, 6> ca = Eigen::Matrix<double, 6, 6>::Zero();
    ca(0, 0) = kL / (kE * a);
    ca(1, 1) = kL * kL * kL / (3 * kE * i2), ca(1, 5) = ca(5, 1) = kL * kL / (2 * kE * i2), ca(5, 5) = kL / (kE * i2);   // along 1: I22
    ca(2, 2) = kL * kL * kL / (3 * kE * i1), ca(2, 4) = ca(4, 2) = -kL * kL / (2 * kE * i1), ca(4, 4) = kL / (kE * i1);  // along 2: I11
    ca(3, 3) = kL / (g * j);
    const Eigen::Vector3d e = -(0.5 * sh.h1 * Eigen::Vector3d::UnitY() + (-0.25) * sh.h2 * Eigen::Vector3d::UnitZ());
    Eigen::Matrix<double, 6, 6> t = Eigen::Matrix<double, 6, 6>::Identity();
    t.block<3, 3>(0, 3) = skew(e);
    const Eigen::Matrix<double, 6, 6> expected = t * ca * t.transpose();
    // The model's axis nodes lie at the mesh nodes + e.
    EXPECT_LT((m.nodes.back().position - (Eigen::Vector3d(2, 0, 0) + e)).norm(), 1e-12) << sh.section;
    Eigen::Matrix<double, 6, 6> measured;
    const int tip = 6 * m.node_index(3);
    for (int d = 0; d < 6; ++d) {
      m.loads = {{m.node_index(3), d, 1.0}};
      const fem::StaticResult r = fem::solve_static(m);
      measured.col(d) = r.displacement.segment<6>(tip);
    }
    std::printf("%s: largest flexibility difference %.2e of the largest entry (e = (0, %.4g, %.4g) m)\n", sh.section,
                (measured - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff(), e.y(), e.z());
    EXPECT_LT((measured - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.cwiseAbs().maxCoeff())
        << sh.section << "\nmeasured\n" << measured << "\nexpected\n" << expected;
  }
}

}  // namespace

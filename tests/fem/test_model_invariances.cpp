// Properties every correct frame model has, whatever its geometry: frequencies
// independent of where the frame stands and how it is turned, six rigid-body
// modes of a free frame that carry all of its mass, symmetric K and M with M
// positive definite and K's null space the rigid-body motions, orthogonal
// modes whose effective masses add up to the mass, equilibrium of reactions
// and loads, and clear errors for mechanisms, massless DOFs and unsupported
// frames.
//
// Most checks run on the shipped R-100-like frame (meshes/r100_frame.inp:
// 51 nodes, 61 B31 box-section elements, in-lbf-s converted to SI), small
// enough (306 DOFs) for dense reference computations.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

namespace fem = framedyn::fem;
namespace support = framedyn::testing;
using framedyn::core::NumericalError;
using fem::BeamTheory;
using fem::FrameModel;

constexpr double kEps = std::numeric_limits<double>::epsilon();

FrameModel r100_frame() { return fem::read_inp(FRAMEDYN_SOURCE_DIR "/meshes/r100_frame.inp"); }

// The only node of a one-node set.
int set_node(const FrameModel& model, const std::string& name) {
  const auto it = model.node_sets.find(name);
  if (it == model.node_sets.end() || it->second.size() != 1) throw std::runtime_error("no one-node set " + name);
  return it->second.front();
}

// Dense K_ff and M_ff (both triangles).
struct DenseSystem {
  fem::DofMap dofs;
  Eigen::MatrixXd k, m;
};

DenseSystem dense_system(const FrameModel& model, fem::MassFormulation mass = fem::MassFormulation::consistent) {
  DenseSystem d;
  d.dofs = fem::make_dof_map(model);
  const fem::FreeSystem s = fem::assemble(model, d.dofs, {mass, fem::Storage::full});
  d.k = Eigen::MatrixXd(s.stiffness);
  d.m = Eigen::MatrixXd(s.mass);
  return d;
}

// Rows of an all-DOF matrix at the free DOFs.
Eigen::MatrixXd free_rows(const fem::DofMap& dofs, const Eigen::MatrixXd& all) {
  Eigen::MatrixXd out(dofs.free_count(), all.cols());
  for (int e = 0; e < dofs.free_count(); ++e) out.row(e) = all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
  return out;
}

// Hand sum of rho A L over the beams (the frame's structural mass).
double beam_mass(const FrameModel& model) {
  double total = 0.0;
  for (const fem::BeamElement& b : model.beams) {
    const fem::SectionAssignment& s = model.sections[static_cast<std::size_t>(b.section)];
    const double length = (model.nodes[static_cast<std::size_t>(b.node_b)].position - model.nodes[static_cast<std::size_t>(b.node_a)].position).norm();
    total += s.material.density * s.properties.area * length;
  }
  return total;
}

// A small clamped L-frame: 5 RECT elements along x from a clamped root, then
// 5 PIPE elements along y, both Timoshenko; 60 free DOFs.
FrameModel clamped_l_frame() {
  FrameModel model;
  const int root = support::add_node(model, Eigen::Vector3d(0.0, 0.0, 0.0));
  const int rect = support::add_section(model, fem::rectangle_section(0.05, 0.08, 0.3), support::steel(), Eigen::Vector3d(0, 0, 1));
  const int pipe = support::add_section(model, fem::pipe_section(0.04, 0.005, 0.3), support::steel(), Eigen::Vector3d(0, 0, 1));
  const std::vector<int> first = support::add_beam_line(model, root, Eigen::Vector3d(1.5, 0.0, 0.0), 5, rect, BeamTheory::timoshenko);
  support::add_beam_line(model, first.back(), Eigen::Vector3d(1.5, 1.0, 0.3), 5, pipe, BeamTheory::timoshenko);
  support::clamp_node(model, root);
  return model;
}

template <class F>
std::string numerical_error_message(F&& f) {
  try {
    f();
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "(no NumericalError thrown)";
}

}  // namespace

// ---------------------------------------------------------------------------
// Rigid motion of the whole model

TEST(RigidlyMovedFrame, TranslationAndRotationLeaveFrequenciesUnchanged) {
  const FrameModel original = r100_frame();
  FrameModel moved = original;
  const Eigen::Matrix3d rot =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()) * Eigen::AngleAxisd(-1.9, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  const Eigen::Vector3d shift(12.3, -45.6, 7.8);  // m; the frame is 2.7 m long
  for (fem::Node& n : moved.nodes) n.position = rot * n.position + shift;
  for (fem::SectionAssignment& s : moved.sections) s.n1_direction = rot * s.n1_direction;
  moved.index();

  fem::ModalOptions options;
  options.mode_count = 20;
  const fem::ModalResult a = fem::compute_modes(original, options);
  const fem::ModalResult b = fem::compute_modes(moved, options);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  // Tolerance 1e-9: Spectra's convergence test bounds the relative error of
  // each shift-inverted Ritz value by tol = 1e-10, i.e. about 1e-10 in
  // lambda = omega^2 for these modes (lambda >> |sigma|), half that in f;
  // round-off, eps max(K_ii/M_ii) / lambda_7 ~ 6e-12, and the coordinates'
  // round-off after a 50 m shift (1e-14 m on 0.1 m elements) are smaller.
  double worst = 0.0;
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    EXPECT_EQ(a.modes[i].rigid_body, b.modes[i].rigid_body) << "mode " << i + 1;
    if (a.modes[i].rigid_body) continue;
    const double rel = b.modes[i].frequency_hz / a.modes[i].frequency_hz - 1.0;
    EXPECT_NEAR(rel, 0.0, 1e-9) << "mode " << i + 1 << " (" << a.modes[i].frequency_hz << " Hz)";
    worst = std::max(worst, std::abs(rel));
  }
  // The total mass in every translation direction is rho A L summed, wherever the frame points.
  EXPECT_NEAR(b.total_mass.head<3>().sum() / a.total_mass.head<3>().sum(), 1.0, 1e-12);
  std::printf("rotated and translated R-100 frame: largest relative frequency change %.2e over modes 7-20\n", worst);
}

// ---------------------------------------------------------------------------
// Free-free frame: rigid-body modes and masses

TEST(FreeFreeFrame, SixRigidBodyModesCarryTheWholeMass) {
  const FrameModel model = r100_frame();
  fem::ModalOptions options;
  options.mode_count = 12;
  const fem::ModalResult r = fem::compute_modes(model, options);
  EXPECT_EQ(r.rigid_body_modes_expected, 6);
  double largest_rigid = 0.0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(r.modes[static_cast<std::size_t>(i)].rigid_body) << "mode " << i + 1;
    EXPECT_EQ(r.modes[static_cast<std::size_t>(i)].frequency_hz, 0.0) << "mode " << i + 1;
    largest_rigid = std::max(largest_rigid, std::abs(r.modes[static_cast<std::size_t>(i)].eigenvalue));
  }
  // The seventh is elastic, with a gap of many orders of magnitude.
  EXPECT_FALSE(r.modes[6].rigid_body);
  EXPECT_GT(r.modes[6].eigenvalue, 1e6 * largest_rigid);
  EXPECT_GT(r.modes[6].frequency_hz, 1.0);

  // Structural mass: the consistent mass moves rigidly with exactly rho A L
  // per element (the Hermite and Timoshenko translational masses integrate a
  // constant exactly); the sums agree to round-off (1e-12 for ~100 terms).
  const double mass = beam_mass(model);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(r.total_mass(d) / mass, 1.0, 1e-12) << "direction " << d;

  // The rigid modes span the rigid-body motions, so their effective masses
  // add up to r_d^T M r_d in each of the six directions. The shortfall is the
  // squared component of r_d outside the computed span: (eigenvector error)^2
  // plus the M-orthonormality error of the vectors (<= 1e-12, see
  // ComputedModes); allow 1e-10.
  Eigen::Matrix<double, 6, 1> rigid_sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (int i = 0; i < 6; ++i) rigid_sum += r.modes[static_cast<std::size_t>(i)].effective_mass;
  for (int d = 0; d < 6; ++d) EXPECT_NEAR(rigid_sum(d) / r.total_mass(d), 1.0, 1e-10) << "direction " << d;
  // ... and the elastic modes carry none of it.
  for (std::size_t i = 6; i < r.modes.size(); ++i)
    for (int d = 0; d < 3; ++d) EXPECT_LE(r.modes[i].effective_mass(d), 1e-10 * mass) << "mode " << i + 1;
  std::printf("free-free R-100 frame: mass %.6g kg; rigid effective mass / total - 1 = %.1e %.1e %.1e; f7 = %.4g Hz\n", mass,
              rigid_sum(0) / r.total_mass(0) - 1.0, rigid_sum(1) / r.total_mass(1) - 1.0, rigid_sum(2) / r.total_mass(2) - 1.0,
              r.modes[6].frequency_hz);
}

TEST(FreeFreeBeam, SixRigidBodyModesAtAnyMeshDensity) {
  // Round-off in a zero eigenvalue grows with the mesh's highest element
  // frequency, as h^-4 for Euler–Bernoulli elements, while the lowest elastic
  // frequency stays put: on a 640-element slender beam (3 mm elements) the
  // rigid-body eigenvalues come out near 0.05 rad^2/s^2 and the first elastic
  // one at 2.8e4. All six must still be recognised, and the cantilever's
  // fundamental (lambda = 690) must not be taken for a mechanism.
  for (int elements : {40, 640}) {
    support::StraightBeamSpec spec;
    spec.direction = Eigen::Vector3d(1.0, 2.0, -0.5);
    spec.length = 2.0;
    spec.elements = elements;
    spec.section = fem::rectangle_section(0.04, 0.02, 0.3);
    spec.material = support::steel();
    spec.theory = BeamTheory::euler_bernoulli;
    spec.n1_direction = Eigen::Vector3d(0.0, 0.0, 1.0);
    FrameModel model = support::straight_beam(spec);
    fem::ModalOptions options;
    options.mode_count = 8;
    const fem::ModalResult free = fem::compute_modes(model, options);
    for (int i = 0; i < 6; ++i) EXPECT_TRUE(free.modes[static_cast<std::size_t>(i)].rigid_body) << elements << " elements, mode " << i + 1;
    // First free-free mode: (4.730^2 / (2 pi L^2)) sqrt(E I11 / rho A) = 26.6 Hz.
    EXPECT_NEAR(free.modes[6].frequency_hz, 26.6, 0.1) << elements << " elements";
    support::clamp_node(model, 0);
    const fem::ModalResult clamped = fem::compute_modes(model, options);
    EXPECT_NEAR(clamped.modes[0].frequency_hz, 4.18, 0.01) << elements << " elements";
  }
}

// ---------------------------------------------------------------------------
// Assembled matrices

TEST(AssembledMatrices, SymmetricMassPositiveDefiniteStiffnessNullSpaceIsRigidMotion) {
  const FrameModel model = r100_frame();
  for (fem::MassFormulation mass : {fem::MassFormulation::consistent, fem::MassFormulation::lumped}) {
    const DenseSystem s = dense_system(model, mass);
    const int n = s.dofs.free_count();
    ASSERT_EQ(n, 306);
    // Symmetry to round-off. Each entry of T^T k T is a sum of a few dozen
    // products; the two triangles are summed in different orders and differ
    // by a few eps times the entry's scale, bounded for a semi-definite
    // matrix by sqrt(A_ii A_jj). Allow 1e-13 (~450 eps).
    double k_asym = 0.0, m_asym = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j) {
        k_asym = std::max(k_asym, std::abs(s.k(i, j) - s.k(j, i)) / std::sqrt(s.k(i, i) * s.k(j, j)));
        m_asym = std::max(m_asym, std::abs(s.m(i, j) - s.m(j, i)) / std::sqrt(s.m(i, i) * s.m(j, j)));
      }
    EXPECT_LE(k_asym, 1e-13);
    EXPECT_LE(m_asym, 1e-13);

    // M is positive definite: its Cholesky factorisation succeeds.
    const Eigen::LLT<Eigen::MatrixXd> llt(s.m);
    EXPECT_EQ(llt.info(), Eigen::Success);

    // K is positive semi-definite with exactly six zero eigenvalues. The
    // Jacobi-scaled D^-1/2 K D^-1/2 (a congruence: same inertia, same null
    // space dimension) has unit diagonal, so its eigenvalues lie in
    // [0, ~10] and round-off puts the zero ones within about n eps = 7e-14
    // of zero; "zero" is |lambda| <= 1e-11, and the seventh must be far above.
    if (mass != fem::MassFormulation::consistent) continue;
    const Eigen::VectorXd d = s.k.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd ks = d.asDiagonal() * s.k * d.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(ks, Eigen::EigenvaluesOnly);
    const Eigen::VectorXd lambda = es.eigenvalues();  // ascending
    const double zero = 1e-11;
    int zeros = 0;
    for (int i = 0; i < n; ++i) zeros += std::abs(lambda(i)) <= zero ? 1 : 0;
    EXPECT_EQ(zeros, 6);
    EXPECT_GE(lambda(0), -zero) << "K is positive semi-definite";
    EXPECT_GT(lambda(6), 1e4 * zero) << "a clear gap after the six zero eigenvalues";
    std::printf("R-100 K (Jacobi-scaled): eigenvalues 1-6 within %.1e of zero, 7th %.2e, largest %.2f; asymmetry K %.1e, M %.1e\n",
                std::max(std::abs(lambda(0)), std::abs(lambda(5))), lambda(6), lambda(n - 1), k_asym, m_asym);

    // The null space is the rigid-body motions: K r_d = 0 for the six
    // rigid-body vectors, to the round-off of the products, eps times the
    // sum of |K_ij r_dj|; allow 1e-13 (~450 eps) of that.
    const Eigen::MatrixXd r = free_rows(s.dofs, fem::rigid_body_vectors(model, Eigen::Vector3d(0.3, -0.2, 0.1)));
    const Eigen::MatrixXd kr = s.k * r;
    const Eigen::MatrixXd kr_scale = s.k.cwiseAbs() * r.cwiseAbs();
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 6; ++c)
        if (kr_scale(i, c) > 0.0) worst = std::max(worst, std::abs(kr(i, c)) / kr_scale(i, c));
    EXPECT_LE(worst, 1e-13);
  }
}

// ---------------------------------------------------------------------------
// Orthogonality of the computed modes and effective masses

TEST(ComputedModes, AreMassOrthonormalAndStiffnessOrthogonal) {
  FrameModel model = r100_frame();
  for (int node : model.node_sets.at("REAR_END")) support::clamp_node(model, node);
  fem::ModalOptions options;
  options.mode_count = 20;
  const fem::ModalResult r = fem::compute_modes(model, options);
  const DenseSystem s = dense_system(model);
  const Eigen::MatrixXd phi = free_rows(s.dofs, r.shapes);
  const int n = static_cast<int>(r.modes.size());
  Eigen::VectorXd lambda(n);
  for (int i = 0; i < n; ++i) lambda(i) = r.modes[static_cast<std::size_t>(i)].eigenvalue;
  const Eigen::MatrixXd mm = phi.transpose() * s.m * phi;
  const Eigen::MatrixXd kk = phi.transpose() * s.k * phi;
  // Phi^T M Phi = I: Spectra orthonormalises the Lanczos basis in the M
  // inner product to round-off; allow 1e-10 (the convergence tolerance).
  const double m_err = (mm - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff();
  EXPECT_LE(m_err, 1e-10);
  // Phi^T K Phi = diag(lambda), entry (i, j) relative to sqrt(lambda_i lambda_j)
  // (the scale of |phi_i^T K phi_j| by Cauchy–Schwarz in the K inner
  // product): the Ritz values' and vectors' tolerance 1e-10.
  double k_err = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double target = i == j ? lambda(i) : 0.0;
      k_err = std::max(k_err, std::abs(kk(i, j) - target) / std::sqrt(lambda(i) * lambda(j)));
    }
  EXPECT_LE(k_err, 1e-10);
  std::printf("clamped R-100 frame, 20 modes: max |Phi^T M Phi - I| %.1e, max relative |Phi^T K Phi - Lambda| %.1e\n", m_err, k_err);
}

TEST(ComputedModes, EffectiveMassesOfAllModesSumToTheSupportCoupledMass) {
  const FrameModel model = clamped_l_frame();
  const DenseSystem s = dense_system(model);
  const int n = s.dofs.free_count();
  ASSERT_EQ(n, 60);
  // The rigid acceleration of the whole model, supports included, loads the
  // free DOFs with b_d = M_ff r_f + M_fs r_s (the rows of the free DOFs of
  // M r over all DOFs). With all modes, Phi Phi^T = M_ff^-1, so
  // sum_i (phi_i^T b_d)^2 = b_d^T M_ff^-1 b_d, computed here by a direct solve.
  fem::DofMap all;
  for (int g = 0; g < model.dof_count(); ++g) {
    all.free_index.push_back(g);
    all.free_dofs.push_back(g);
  }
  const Eigen::MatrixXd m_all(fem::assemble(model, all, {fem::MassFormulation::consistent, fem::Storage::full}).mass);
  const Eigen::MatrixXd r_all = fem::rigid_body_vectors(model, Eigen::Vector3d::Zero());
  const Eigen::MatrixXd b = free_rows(s.dofs, m_all * r_all);
  const Eigen::VectorXd coupled = (b.transpose() * s.m.ldlt().solve(b)).diagonal();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(s.k, s.m);
  ASSERT_EQ(dense.info(), Eigen::Success);
  const Eigen::MatrixXd gamma = dense.eigenvectors().transpose() * b;  // n x 6
  const Eigen::VectorXd dense_sum = gamma.cwiseProduct(gamma).colwise().sum().transpose();

  // compute_modes for all modes but one (the most a Lanczos run can give).
  fem::ModalOptions options;
  options.mode_count = n - 1;
  const fem::ModalResult modes = fem::compute_modes(model, options);
  ASSERT_EQ(static_cast<int>(modes.modes.size()), n - 1);
  // The total mass is the structure's, rho A L summed (the consistent mass
  // moves rigidly with exactly rho A L per element), supported DOFs included.
  EXPECT_NEAR(modes.total_mass(0) / beam_mass(model), 1.0, 1e-12);
  // The free mass is less: the consistent mass ties part of the first
  // element's mass to the clamped root. Along x, the first element's axis,
  // that part is exact: of its axial mass (rho A L / 6)[2 1; 1 2] only the
  // free node's 2/6 remains, so the free mass is the total less 2/3 rho A L
  // of the first element.
  const fem::BeamElement& root_beam = model.beams.front();
  const fem::SectionAssignment& root_section = model.sections[static_cast<std::size_t>(root_beam.section)];
  const double root_length = (model.nodes[static_cast<std::size_t>(root_beam.node_b)].position -
                              model.nodes[static_cast<std::size_t>(root_beam.node_a)].position).norm();
  const double first_element = root_section.material.density * root_section.properties.area * root_length;
  EXPECT_NEAR(modes.free_mass(0) / (beam_mass(model) - 2.0 / 3.0 * first_element), 1.0, 1e-12);

  Eigen::Matrix<double, 6, 1> lanczos_sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (const fem::Mode& m : modes.modes) lanczos_sum += m.effective_mass;
  const Eigen::RowVectorXd last = gamma.row(n - 1).cwiseProduct(gamma.row(n - 1));
  // Tolerance 1e-9: the dense solver reduces with the Cholesky factor of M
  // (condition number of M here ~1e5, so M-orthonormality to ~1e-11) and the
  // shift-invert solver is least accurate for its highest modes (relative
  // eigenvalue accuracy tol |lambda - sigma| / lambda in the transformed
  // problem, vectors of the top modes to ~1e-10).
  for (int d = 0; d < 6; ++d) {
    EXPECT_NEAR(dense_sum(d) / coupled(d), 1.0, 1e-9) << "direction " << d << ", dense, all modes";
    EXPECT_NEAR((lanczos_sum(d) + last(d)) / coupled(d), 1.0, 1e-9) << "direction " << d << ", compute_modes + the last dense mode";
    // The modes of a clamped frame cannot carry the mass that sits on the
    // support: their fractions of the total stay below one.
    EXPECT_LT(coupled(d), modes.total_mass(d)) << "direction " << d;
  }
  // The two solvers agree mode by mode on the lowest ten.
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(modes.modes[static_cast<std::size_t>(i)].eigenvalue / dense.eigenvalues()(i), 1.0, 1e-9) << "mode " << i + 1;
  std::printf("clamped L-frame: sum of effective masses / b^T M_ff^-1 b - 1: dense %.1e %.1e %.1e, Lanczos + last %.1e %.1e %.1e; "
              "of the total mass %.4f %.4f %.4f\n",
              dense_sum(0) / coupled(0) - 1, dense_sum(1) / coupled(1) - 1, dense_sum(2) / coupled(2) - 1,
              (lanczos_sum(0) + last(0)) / coupled(0) - 1, (lanczos_sum(1) + last(1)) / coupled(1) - 1,
              (lanczos_sum(2) + last(2)) / coupled(2) - 1, coupled(0) / modes.total_mass(0), coupled(1) / modes.total_mass(1),
              coupled(2) / modes.total_mass(2));
}

// ---------------------------------------------------------------------------
// Errors

TEST(ModelErrors, BeamWithoutTorsionStiffnessIsAMechanism) {
  // A clamped beam whose section has no torsion constant twists freely: a
  // motion without strain that is no rigid motion of the (clamped) beam.
  support::StraightBeamSpec spec;
  spec.length = 1.0;
  spec.elements = 4;
  spec.section = fem::rectangle_section(0.04, 0.02, 0.3);
  spec.section.torsion_constant = 0.0;
  spec.material = support::steel();
  FrameModel model = support::straight_beam(spec);
  support::clamp_node(model, 0);
  const std::string message = numerical_error_message([&] { fem::compute_modes(model); });
  EXPECT_NE(message.find("mechanism"), std::string::npos) << message;
  EXPECT_NE(message.find("(rx)"), std::string::npos) << message;  // the twist, named by node and DOF
  std::printf("%s\n", message.c_str());
}

TEST(ModelErrors, DisconnectedBeamBesideASupportedOneHasSixRigidBodyModes) {
  // (Until issue 13 this was refused as a mechanism: any support made the
  // expected number of rigid-body modes zero.) The loose beam is a part of
  // its own with no restraint: six rigid-body modes, then the clamped
  // beam's and the loose beam's elastic modes.
  support::StraightBeamSpec spec;
  spec.length = 1.0;
  spec.elements = 4;
  spec.section = fem::rectangle_section(0.04, 0.02, 0.3);
  spec.material = support::steel();
  FrameModel model = support::straight_beam(spec);
  support::clamp_node(model, 0);
  const int loose = support::add_node(model, Eigen::Vector3d(0.0, 1.0, 0.0));
  support::add_beam_line(model, loose, Eigen::Vector3d(1.0, 1.0, 0.0), 4, 0, BeamTheory::euler_bernoulli);
  fem::ModalOptions options;
  options.mode_count = 8;
  const fem::ModalResult r = fem::compute_modes(model, options);
  EXPECT_EQ(r.parts, 2);
  EXPECT_EQ(r.rigid_body_modes_expected, 6);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(r.modes[static_cast<std::size_t>(i)].rigid_body, i < 6) << "mode " << i + 1;
  // Mode 7: the clamped beam's fundamental, 3.516 / (2 pi L^2) sqrt(E I / rho A)
  // about the weak axis (I = 0.04 * 0.02^3 / 12): 16.7 Hz (4 elements: within 0.5 %).
  const double f1 = 3.5160 / (2.0 * M_PI) * std::sqrt(210e9 * 0.04 * std::pow(0.02, 3) / 12.0 / (7850.0 * 0.04 * 0.02));
  EXPECT_NEAR(r.modes[6].frequency_hz / f1, 1.0, 5e-3);
}

TEST(ModelErrors, NodeWithoutMassIsRejected) {
  support::StraightBeamSpec spec;
  spec.length = 1.0;
  spec.elements = 4;
  spec.section = fem::rectangle_section(0.04, 0.02, 0.3);
  spec.material = support::steel();
  FrameModel model = support::straight_beam(spec);
  support::clamp_node(model, 0);
  // A massless extension: only a density-0 element reaches the new tip node.
  fem::Material massless = support::steel();
  massless.density = 0.0;
  const int section = support::add_section(model, spec.section, massless, spec.n1_direction);
  const std::vector<int> line = support::add_beam_line(model, spec.elements, Eigen::Vector3d(1.5, 0.0, 0.0), 1, section,
                                                       BeamTheory::euler_bernoulli);
  const std::string message = numerical_error_message([&] { fem::compute_modes(model); });
  EXPECT_NE(message.find("no mass"), std::string::npos) << message;
  const std::string tip = "node " + std::to_string(model.nodes[static_cast<std::size_t>(line.back())].id);
  EXPECT_NE(message.find(tip), std::string::npos) << "names the massless node: " << message;
}

TEST(ModelErrors, StaticSolveOfUnsupportedFrameUnderAnUnbalancedLoadNamesTheRigidMotionItDrives) {
  FrameModel model = r100_frame();
  model.loads.push_back({set_node(model, "P24_REEL"), 2, -1000.0});
  const std::string message = numerical_error_message([&] { fem::solve_static(model); });
  EXPECT_NE(message.find("6 free rigid motions): the loads drive its rotation about"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------
// Static equilibrium

TEST(StaticFrame, ReactionsBalanceAppliedForcesAndMoments) {
  // The frame on its two axle pins (three translations each) and the
  // levelling cylinder (vertical), loaded at the reel, the cab mounts and
  // the hitch with forces and moments.
  FrameModel model = r100_frame();
  support::pin_dofs(model, set_node(model, "P25_FRONT_AXLE_PIN"), {0, 1, 2});
  support::pin_dofs(model, set_node(model, "P26_REAR_AXLE_PIN"), {0, 1, 2});
  support::pin_dofs(model, set_node(model, "P27_LEVELING_CYLINDER"), {2});
  support::add_nodal_force(model, set_node(model, "P24_REEL"), Eigen::Vector3d(1500.0, -300.0, -9000.0));
  support::add_nodal_moment(model, set_node(model, "P24_REEL"), Eigen::Vector3d(200.0, 800.0, -150.0));
  for (const char* mount : {"P28_CAB_MOUNT_FL", "P29_CAB_MOUNT_FR", "P30_CAB_MOUNT_RL", "P31_CAB_MOUNT_RR"})
    support::add_nodal_force(model, set_node(model, mount), Eigen::Vector3d(0.0, 120.0, -2500.0));
  for (int node : model.node_sets.at("REAR_END")) support::add_nodal_force(model, node, Eigen::Vector3d(-4000.0, 0.0, 500.0));
  const fem::StaticResult r = fem::solve_static(model);

  // Sum of forces, and of moments about the origin, of loads plus reactions:
  // R^T (f + reaction) with the rigid-body vectors about the origin.
  const Eigen::MatrixXd rigid = fem::rigid_body_vectors(model, Eigen::Vector3d::Zero());
  const Eigen::VectorXd resultant = rigid.transpose() * (r.applied + r.reaction);
  double force_scale = 0.0, lever = 0.0;
  for (const fem::NodalLoad& l : model.loads) force_scale += std::abs(l.value);
  for (const fem::Node& n : model.nodes) lever = std::max(lever, n.position.norm());
  // The reactions are K u - f at the supports; K annihilates rigid motions,
  // so the resultant is the solve's residual at the free DOFs
  // (relative_residual ||f||) plus round-off in the element forces K u,
  // eps times the terms |k_ij u_j| that cancel in each end force: those are
  // the loads amplified by the element stiffness contrast (axial to bending,
  // EA L^2 / 12 EI < 1e3 for these tubes), so allow 1e-11 (~5e4 eps) of the loads.
  const double tol = 1e-11 + r.relative_residual;
  EXPECT_LE(resultant.head<3>().norm(), tol * force_scale) << resultant.transpose();
  EXPECT_LE(resultant.tail<3>().norm(), tol * force_scale * lever) << resultant.transpose();
  // The supports do carry the load.
  EXPECT_GT(r.reaction.norm(), 0.5 * 9000.0);
  std::printf("R-100 frame on its axle pins: |sum F| / sum|f| = %.1e, |sum M| / (sum|f| r_max) = %.1e, relative residual %.1e\n",
              resultant.head<3>().norm() / force_scale, resultant.tail<3>().norm() / (force_scale * lever), r.relative_residual);
}

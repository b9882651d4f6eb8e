// Member-end releases (*RELEASE) against beam theory. A released moment is
// condensed out of the element (fem/member_releases.h), so a member between
// two clamped nodes behaves as if pinned at its released end:
//   propped cantilever (clamped at x = 0, released at x = L) under w:
//     reaction at the released end R = 3 w L / 8, clamp 5 w L / 8, clamp moment w L^2 / 8;
//   both ends released: simply supported, midspan deflection 5 w L^4 / (384 E I),
//     midspan moment w L^2 / 8, end moments 0;
//   a tip load P on a cantilever whose root element is released in torsion
//     at its tip end carries no torque across that end.
// The released moment at the released end is zero in the recovered section forces.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/beam_element.h"
#include "fem/inp_reader.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;
const double kE = 2.1e11, kA = 0.05, kB = 0.1;  // RECT a along 1 (global Y), b along 2 (global Z)
const double kI22 = kB * kA * kA * kA / 12;         // bending about axis 2, deflection along 1 = Y

// A beam along X of `elements` B33 elements (nodes 1..n+1), n1 = +Y so that
// PY is along local 1 and the moment about local 2 (M2) is the one it bends.
std::string deck(int elements, double length, const std::string& extra, const std::string& type = "B33") {
  std::string s = "** units: m-N-s\n*NODE\n";
  for (int i = 0; i <= elements; ++i) s += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, length * i / elements);
  s += "*ELEMENT, TYPE=" + type + ", ELSET=BEAM\n";
  for (int i = 1; i <= elements; ++i) s += fmt::format("{}, {}, {}\n", i, i, i + 1);
  s += fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n{}, {}\n0, 1, 0\n", kA, kB);
  s += fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, 0.3\n*DENSITY\n7850\n", kE);
  return s + extra;
}

fem::FrameModel read(const std::string& text) { return fem::read_inp_text(text, "beam.inp", "."); }
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Both nodes of the span clamped; the last element released in M2 at its
// second node: a propped cantilever, R = 3wL/8 at the released end.
TEST(EndReleases, ProppedCantileverFromAReleasedEndHasReactionThreeWLOverEight) {
  const double L = 4.0, w = 1200.0;
  for (int n : {1, 2, 5}) {
    const fem::FrameModel m = read(deck(n, L, fmt::format("*RELEASE\n{}, S2, M2\n*BOUNDARY\n1, ENCASTRE\n{}, ENCASTRE\n*DLOAD\nBEAM, PY, {}\n", n, n + 1, -w)));
    ASSERT_EQ(m.beams.back().released, fem::release_bit(1, fem::kReleaseM2));
    Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dof_count());
    Eigen::VectorXd reaction;
    if (n > 1) {
      const fem::StaticResult r = fem::solve_static(m);
      u = r.displacement;
      reaction = r.reaction;
    } else {
      // No free DOF: the reactions are the element's released end forces, -p*.
      const fem::BeamGeometry g = fem::beam_geometry(m, m.beams[0]);
      const fem::Vector12d p = fem::beam_local_uniform_load(g.data, g.axes * Eigen::Vector3d(0, -w, 0));
      reaction = -(fem::beam_transformation(g.axes).transpose() * p);
    }
    std::printf("propped cantilever, %d element(s): R = 3wL/8 to %.2e, clamp moment wL^2/8 to %.2e\n", n, rel(reaction(6 * n + 1), 3 * w * L / 8),
                rel(std::abs(reaction(5)), w * L * L / 8));
    EXPECT_LT(rel(reaction(6 * n + 1), 3 * w * L / 8), 1e-10) << n;
    EXPECT_LT(rel(reaction(1), 5 * w * L / 8), 1e-10) << n;
    EXPECT_LT(rel(std::abs(reaction(5)), w * L * L / 8), 1e-10) << n;
    EXPECT_NEAR(reaction(6 * n + 5), 0.0, 1e-10 * w * L * L) << n;  // the clamp at the released end holds no moment
    const std::vector<fem::StationResult> st = fem::recover_stations(m, u, 5);
    EXPECT_NEAR(st.back().forces.mz, 0.0, 1e-10 * w * L * L) << n;  // released: M2 = 0 at the end
    EXPECT_LT(rel(std::abs(st.front().forces.mz), w * L * L / 8), 1e-10) << n;
    // M(x) = R (L - x) - w (L - x)^2 / 2 from the released end, everywhere.
    for (const fem::StationResult& s : st) {
      const double y = L - s.point.x();
      EXPECT_NEAR(std::abs(s.forces.mz - (3 * w * L / 8 * y - w * y * y / 2)), 0.0, 1e-9 * w * L * L) << n << " x=" << s.point.x();
    }
  }
}

// A fixed-fixed member released in M2 at both ends is simply supported:
// midspan deflection 5 w L^4 / (384 E I), midspan moment w L^2 / 8.
TEST(EndReleases, FixedFixedMemberReleasedAtBothEndsIsSimplySupported) {
  const double L = 3.0, w = 900.0;
  // One element: its section forces alone (no free DOF).
  {
    const fem::FrameModel m = read(deck(1, L, "*RELEASE\n1, S1, M2\n1, S2, M2\n*BOUNDARY\n1, ENCASTRE\n2, ENCASTRE\n" + fmt::format("*DLOAD\nBEAM, PY, {}\n", -w)));
    const std::vector<fem::StationResult> st = fem::recover_stations(m, Eigen::VectorXd::Zero(m.dof_count()), 3);
    EXPECT_NEAR(st[0].forces.mz, 0.0, 1e-12 * w * L * L);
    EXPECT_NEAR(st[2].forces.mz, 0.0, 1e-12 * w * L * L);
    EXPECT_LT(rel(st[1].forces.mz, w * L * L / 8), 1e-12);
    EXPECT_LT(rel(std::abs(st[0].forces.vy), w * L / 2), 1e-12);
  }
  // Two and eight elements: the midspan node deflects 5 w L^4 / (384 E I).
  for (int n : {2, 8}) {
    const fem::FrameModel m =
        read(deck(n, L, fmt::format("*RELEASE\n1, S1, M2\n{}, S2, M2\n*BOUNDARY\n1, ENCASTRE\n{}, ENCASTRE\n*DLOAD\nBEAM, PY, {}\n", n, n + 1, -w)));
    const fem::StaticResult r = fem::solve_static(m);
    std::printf("released fixed-fixed member, %d elements: midspan deflection 5wL^4/384EI to %.2e\n", n,
                rel(r.displacement(6 * (n / 2) + 1), -5 * w * std::pow(L, 4) / (384 * kE * kI22)));
    EXPECT_LT(rel(r.displacement(6 * (n / 2) + 1), -5 * w * std::pow(L, 4) / (384 * kE * kI22)), 1e-10) << n;
    const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
    EXPECT_NEAR(st.front().forces.mz, 0.0, 1e-10 * w * L * L) << n;
    EXPECT_NEAR(st.back().forces.mz, 0.0, 1e-10 * w * L * L) << n;
    for (const fem::StationResult& s : st) {
      if (std::abs(s.point.x() - L / 2) < 1e-12) {
        EXPECT_LT(rel(s.forces.mz, w * L * L / 8), 1e-10) << n;
      }
    }
    // The released ends turn freely: the element's end rotation is not the clamped node's.
    EXPECT_EQ(r.displacement(5), 0.0);
  }
}

// A member released in torsion at one end carries no torque at all (torsion
// is constant along it): its twist rows vanish at both ends, while axial and
// bending stiffness, which do not couple with twist on a straight member, stay.
TEST(EndReleases, ReleasedTorsionRemovesTheTwistStiffnessAndKeepsBending) {
  const double L = 2.0;
  const fem::FrameModel m = read(deck(1, L, "*RELEASE\n1, S2, T\n*BOUNDARY\n1, ENCASTRE\n"));
  const fem::BeamGeometry g = fem::beam_geometry(m, m.beams[0]);
  const fem::Matrix12d k = fem::beam_local_stiffness(g.data);
  fem::BeamElementData plain = g.data;
  plain.released = 0;
  const fem::Matrix12d k0 = fem::beam_local_stiffness(plain);
  EXPECT_EQ(k.row(9).norm(), 0.0);
  EXPECT_EQ(k.row(3).norm(), 0.0);  // the other end's twist is no longer resisted either
  // Bending and axial blocks unchanged (torsion decouples on a straight member).
  for (int i : {0, 1, 2, 4, 5, 6, 7, 8, 10, 11})
    for (int j : {0, 1, 2, 4, 5, 6, 7, 8, 10, 11}) EXPECT_EQ(k(i, j), k0(i, j));
}

// The condensed mass keeps the element's mass: a rigid translation of a
// released element has no released rotation (K_rc u_c = 0), so its kinetic
// energy is that of rho A L. And a released element's stiffness is still
// free of strain under rigid motion (rows of K* times a rigid motion = 0).
TEST(EndReleases, ReleasedElementKeepsItsMassAndItsRigidBodyMotions) {
  const double L = 1.7;
  const fem::FrameModel m = read(deck(1, L, "*RELEASE\n1, S1, ALLM\n1, S2, M1-M2\n"));
  const fem::BeamGeometry g = fem::beam_geometry(m, m.beams[0]);
  const fem::Matrix12d k = fem::beam_local_stiffness(g.data);
  const fem::Matrix12d mass = fem::beam_local_mass(g.data, fem::MassFormulation::consistent);
  const double total = 7850 * kA * kB * L;
  for (int d = 0; d < 3; ++d) {
    fem::Vector12d r = fem::Vector12d::Zero();
    r(d) = r(6 + d) = 1.0;
    EXPECT_LT(rel(r.dot(mass * r), total), 1e-13) << d;
    EXPECT_LT((k * r).norm(), 1e-12 * k.norm()) << d;
  }
  // Rigid rotation about local z through node a: v = x theta, rz = theta at both nodes.
  fem::Vector12d rot = fem::Vector12d::Zero();
  rot(5) = rot(11) = 1.0;
  rot(7) = L;
  EXPECT_LT((k * rot).norm(), 1e-12 * k.norm());
  // K* and M* stay symmetric positive semi-definite.
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  EXPECT_LT((mass - mass.transpose()).norm(), 1e-12 * mass.norm());
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<fem::Matrix12d>(mass).eigenvalues().minCoeff(), -1e-12 * mass.norm());
}

// A simply supported beam made of clamped nodes and released end members
// vibrates like the pinned-pinned beam: omega_1 = (pi/L)^2 sqrt(E I / (rho A)).
// The released rotations follow the element statically (T^T M T), as Guyan
// reduction does, so the frequency converges from above as the mesh is refined,
// with the fourth-order error of the Hermite element.
TEST(EndReleases, ReleasedEndsVibrateLikeAPinnedPinnedBeam) {
  const double L = 2.0, rho = 7850;
  const double exact = kPi * kPi / (L * L) * std::sqrt(kE * kI22 / (rho * kA * kB));
  double previous_error = 0.0;
  for (int n : {8, 16, 32}) {
    std::string extra = fmt::format("*RELEASE\n1, S1, M2\n{}, S2, M2\n*BOUNDARY\n1, ENCASTRE\n{}, ENCASTRE\n", n, n + 1);
    for (int i = 2; i <= n; ++i) extra += fmt::format("{}, 3, 5\n", i);  // in-plane: uz, rx, ry fixed
    const fem::FrameModel m = read(deck(n, L, extra));
    const fem::DofMap dofs = fem::make_dof_map(m);
    const fem::FreeSystem sys = fem::assemble(m, dofs, {fem::MassFormulation::consistent, fem::Storage::full});
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(sys.stiffness), Eigen::MatrixXd(sys.mass));
    // The lowest mode: bending in x-y (axial modes are far higher for this slender beam).
    const double omega = std::sqrt(es.eigenvalues()(0));
    const double error = omega / exact - 1.0;
    EXPECT_GT(error, 0.0) << n;  // consistent mass and condensation both bound from above
    // Cubic Hermite elements with consistent mass: +(beta h)^4 / 1440 (see
    // test_beam_analytic.cpp); the condensed end elements add 1.1 % of it at
    // 8 elements and less on finer meshes (measured), so 5 % bounds them.
    const double hermite = std::pow(kPi / n, 4) / 1440;
    EXPECT_LT(error, 1.05 * hermite) << n;
    if (previous_error > 0.0) {
      EXPECT_GT(previous_error / error, 15.0) << n;  // fourth order in h, as the pinned beam
    }
    std::printf("n = %d: omega / exact - 1 = %.4e, (pi h / L)^4 / 1440 = %.4e\n", n, error, hermite);
    previous_error = error;
  }
}

// ---------------------------------------------------------------- reader errors

TEST(EndReleases, MalformedReleasesAreRefusedWithTheLine) {
  struct Case {
    std::string name, release, marker, message;
  };
  const std::vector<Case> cases = {
      {"BadEnd", "*RELEASE\n1, S3, M1\n", "S3", "*RELEASE: expected the element end S1 (first node) or S2 (second node), found 'S3'"},
      {"BadCombination", "*RELEASE\n1, S1, M3\n", "M3", "*RELEASE: expected a release combination of M1, M2, T (joined by '-') or ALLM, found 'M3'"},
      {"MissingField", "*RELEASE\n1, S1\n", "1, S1", "*RELEASE: expected element or ELSET, S1 or S2, release combination, found '1, S1'"},
      {"TorsionAtBothEnds", "*RELEASE\n1, S1, T\n1, S2, T\n", "1, S2, T",
       "*RELEASE: expected releases that leave the element stiff against every motion of its nodes, found element 1: the released rotations "
       "(S1: T; S2: T) leave the element free to rotate without strain (torsion released at both ends?)"},
      {"NotABeam", "*ELEMENT, TYPE=MASS, ELSET=PM\n100, 2\n*MASS, ELSET=PM\n5\n*RELEASE\nPM, S1, M1\n", "PM, S1",
       "*RELEASE: expected beam elements (B31, B32, B32R, B33) to release, found element 100 of type MASS"},
  };
  for (const Case& c : cases) {
    const std::string text = deck(1, 1.0, c.release);
    int line = 0, n = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
      ++n;
      const std::size_t end = text.find('\n', pos);
      if (line == 0 && text.substr(pos, end - pos).find(c.marker) != std::string::npos) line = n;
      pos = end == std::string::npos ? text.size() : end + 1;
    }
    try {
      read(text);
      ADD_FAILURE() << c.name << ": no error";
    } catch (const framedyn::core::InputError& e) {
      EXPECT_EQ(std::string(e.what()), fmt::format("beam.inp:{}: {}", line, c.message)) << c.name;
    }
  }
}

}  // namespace

// Section options of the beam elements against closed forms:
//  - *TRANSVERSE SHEAR STIFFNESS (K23, K13 = G A_s along local 2 and 1) in the
//    Timoshenko element: a cantilever with a tip load P deflects
//    P L^3 / (3 E I) + P L / K, exactly at every mesh; B33 ignores K.
//  - RAYLEIGH on a section: Euler-Bernoulli elements with the rotary inertia
//    of bending. A simply supported Rayleigh beam (Rayleigh 1877; e.g. Han,
//    Benaroya & Wei 1999, J. Sound Vib. 225) has, with k = n pi / L, r^2 = I / A,
//      omega_n^2 = (E I / (rho A)) k^4 / (1 + r^2 k^2).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "fem/static_analysis.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;

// A beam along X, nodes 1..n+1, elements 1..n in ELSET BEAM, then `rest`.
std::string beam(int elements, double length, const std::string& type, const std::string& rest) {
  std::string s = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= elements; ++i) s += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, length * i / elements);
  s += "*ELEMENT, TYPE=" + type + ", ELSET=BEAM\n";
  for (int i = 1; i <= elements; ++i) s += fmt::format("{}, {}, {}\n", i, i, i + 1);
  return s + rest;
}

fem::FrameModel read(const std::string& text) { return fem::read_inp_text(text, "beam.inp", "."); }
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// A short GENERAL-section cantilever (L = 0.3 m, n1 = +Y): a tip load along Y
// bends it about axis 2 (I22) and shears it along 1 (K13); along Z, I11 and K23.
TEST(TransverseShearStiffness, ShortCantileverDeflectsPL3Over3EIPlusPLOverK) {
  const double L = 0.3, A = 4e-3, i11 = 6e-6, i22 = 2e-6, J = 5e-6, E = 2.0e11, G = 7.7e10, K23 = 1.5e8, K13 = 0.3e8, P = 2.0e4;
  for (const char* type : {"B31", "B33"}) {
    for (int n : {1, 4}) {
      const std::string deck = beam(n, L, type,
                                    fmt::format("*BEAM GENERAL SECTION, ELSET=BEAM, SECTION=GENERAL, DENSITY=7850\n{}, {}, 0, {}, {}\n0, 1, 0\n{}, {}\n"
                                                "*TRANSVERSE SHEAR STIFFNESS\n{}, {}\n*BOUNDARY\n1, ENCASTRE\n*CLOAD\n{}, 2, {}\n{}, 3, {}\n",
                                                A, i11, i22, J, E, G, K23, K13, n + 1, P, n + 1, P));
      const fem::StaticResult r = fem::solve_static(read(deck));
      const bool shear = std::string(type) == "B31";
      const double uy = P * L * L * L / (3 * E * i22) + (shear ? P * L / K13 : 0.0);
      const double uz = P * L * L * L / (3 * E * i11) + (shear ? P * L / K23 : 0.0);
      std::printf("%s, %d element(s): tip deflections along 1 and 2 to %.2e, %.2e\n", type, n, rel(r.displacement(6 * n + 1), uy), rel(r.displacement(6 * n + 2), uz));
      EXPECT_LT(rel(r.displacement(6 * n + 1), uy), 1e-10) << type << " " << n;
      EXPECT_LT(rel(r.displacement(6 * n + 2), uz), 1e-10) << type << " " << n;
    }
  }
  // The shear term is a real part of the answer here (a short, shear-soft beam).
  EXPECT_GT(P * L / K13, 0.2 * P * L * L * L / (3 * E * i22));
  EXPECT_GT(P * L / K23, 0.2 * P * L * L * L / (3 * E * i11));
}

TEST(TransverseShearStiffness, MalformedUseIsRefusedWithTheLine) {
  const std::string section = "*BEAM GENERAL SECTION, ELSET=BEAM, SECTION=GENERAL\n1e-3, 1e-6, 0, 1e-6, 2e-6\n0, 1, 0\n2e11, 8e10\n";
  struct Case {
    std::string name, text, message;
  };
  const std::vector<Case> cases = {
      {"NotAfterASection", section + "*BOUNDARY\n1, ENCASTRE\n*TRANSVERSE SHEAR STIFFNESS\n1e8, 1e8\n",
       "beam.inp:15: *TRANSVERSE SHEAR STIFFNESS: expected *TRANSVERSE SHEAR STIFFNESS directly after the *BEAM SECTION or *BEAM GENERAL "
       "SECTION it belongs to, found it after *BOUNDARY"},
      {"NegativeStiffness", section + "*TRANSVERSE SHEAR STIFFNESS\n1e8, -1e8\n",
       "beam.inp:14: *TRANSVERSE SHEAR STIFFNESS: expected positive shear stiffnesses K23 and K13, found '1e8, -1e8'"},
      {"SlendernessCompensation", section + "*TRANSVERSE SHEAR STIFFNESS\n1e8, 1e8, 0.25\n",
       "beam.inp:14: *TRANSVERSE SHEAR STIFFNESS: expected a slenderness compensation factor of 0 or blank (framedyn uses K as given), found '1e8, 1e8, 0.25'"},
      {"OneValue", section + "*TRANSVERSE SHEAR STIFFNESS\n1e8\n",
       "beam.inp:14: *TRANSVERSE SHEAR STIFFNESS: expected K23, K13[, slenderness compensation] (2 to 3 values), found 1 values in '1e8'"},
      {"RayleighWithAValue", "*BEAM GENERAL SECTION, ELSET=BEAM, SECTION=GENERAL, RAYLEIGH=YES\n1e-3, 1e-6, 0, 1e-6, 2e-6\n0, 1, 0\n2e11, 8e10\n",
       "beam.inp:9: *BEAM GENERAL SECTION: expected RAYLEIGH without a value, found RAYLEIGH=YES"},
  };
  for (const Case& c : cases) {
    try {
      read(beam(2, 1.0, "B31", c.text));
      ADD_FAILURE() << c.name << ": no error";
    } catch (const framedyn::core::InputError& e) {
      EXPECT_EQ(std::string(e.what()), c.message) << c.name;
    }
  }
}

// The lowest `count` eigenvalues (rad^2/s^2) of a model, by a dense solve.
Eigen::VectorXd lowest_eigenvalues(const fem::FrameModel& m, int count) {
  const fem::DofMap dofs = fem::make_dof_map(m);
  const fem::FreeSystem sys = fem::assemble(m, dofs, {fem::MassFormulation::consistent, fem::Storage::full});
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(sys.stiffness), Eigen::MatrixXd(sys.mass));
  return es.eigenvalues().head(count);
}

// A stocky simply supported steel beam (L / r = 69) in one plane: B33 with
// RAYLEIGH against the Rayleigh closed form, B33 without it against
// Euler-Bernoulli; the rotary-inertia correction (1.6 % at mode 4) is two
// orders of magnitude above the discretisation error.
TEST(RayleighBeam, SimplySupportedFrequenciesIncludeTheRotaryInertiaCorrection) {
  const double L = 1.0, a = 0.05, E = 2.1e11, rho = 7850;
  const double area = a * a, inertia = a * a * a * a / 12, r2 = inertia / area;
  const int n = 40;
  std::string supports = "*BOUNDARY\n1, 2, 2\n" + fmt::format("{}, 2, 2\n", n + 1);
  // In-plane bending only: no axial, out-of-plane or twisting motion.
  supports += "ALL, 1, 1\nALL, 3, 5\n";
  for (bool rayleigh : {true, false}) {
    const std::string deck =
        beam(n, L, "B33", fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT{}\n{}, {}\n0, 1, 0\n", rayleigh ? ", RAYLEIGH" : "", a, a) +
                              fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, 0.3\n*DENSITY\n{}\n", E, rho) + supports);
    const fem::FrameModel m = read(deck);
    EXPECT_EQ(m.sections[0].bending_rotary_inertia, rayleigh);
    const Eigen::VectorXd lambda = lowest_eigenvalues(m, 4);
    for (int mode = 1; mode <= 4; ++mode) {
      const double k = mode * kPi / L;
      const double euler = std::sqrt(E * inertia / (rho * area)) * k * k;
      const double exact = rayleigh ? euler / std::sqrt(1 + r2 * k * k) : euler;
      const double omega = std::sqrt(lambda(mode - 1));
      // Hermite discretisation error +(k h)^4 / 1440 (test_beam_analytic.cpp), with 5 % for the rotary terms.
      const double hermite = std::pow(k * L / n, 4) / 1440;
      std::printf("%s mode %d: omega / closed form - 1 = %.3e (Hermite estimate %.3e; rotary-inertia correction %.3e)\n",
                  rayleigh ? "Rayleigh" : "Euler-Bernoulli", mode, omega / exact - 1, hermite, 1 - 1 / std::sqrt(1 + r2 * k * k));
      EXPECT_GT(omega / exact - 1, 0.0) << mode;
      EXPECT_LT(omega / exact - 1, 1.05 * hermite) << mode;
      EXPECT_GT(1 - 1 / std::sqrt(1 + r2 * k * k), 100 * hermite) << mode;
    }
  }
}

}  // namespace

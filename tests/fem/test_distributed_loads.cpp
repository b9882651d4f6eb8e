// Distributed loads (*DLOAD GRAV, P1, P2, PX, PY, PZ) against beam theory:
// consistent nodal loads make the nodal displacements of Euler-Bernoulli and
// Timoshenko elements exact for a uniform load, and the fixed-end terms make
// the recovered section forces exact along every element. Closed forms
// (Roark, any strength-of-materials text), w the load per length:
//   cantilever:        root moment w L^2/2, root shear w L, tip deflection w L^4/(8 E I);
//   clamped-clamped:   end moments w L^2/12, midspan moment w L^2/24, end shear w L/2;
//   point mass m at the tip of a cantilever under g: a tip force m g, P L^3/(3 E I).
// The meshes are read from .inp text, so the reader, the unit conversion
// (in-lbf-s: GRAV in in/s^2, P in lbf/in) and the solver are checked together.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/units.h"
#include "fem/distributed_loads.h"
#include "fem/frame_model.h"
#include "fem/inp_reader.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"

namespace {

namespace fem = framedyn::fem;
using framedyn::core::Quantity;
using framedyn::core::UnitSystem;

// A straight beam from (0,0,0) along `direction` (need not be a unit vector)
// of `length`, `elements` elements of TYPE=`type`, section lines `section`
// (ELSET=BEAM), steel, and `extra` keyword lines at the end. Nodes 1..n+1.
std::string beam_deck(const std::string& units, const Eigen::Vector3d& direction, double length, int elements, const std::string& type,
                      const std::string& section, const std::string& material, const std::string& extra) {
  std::string s = "** units: " + units + "\n*NODE, NSET=ALL\n";
  const Eigen::Vector3d t = direction.normalized();
  for (int i = 0; i <= elements; ++i) {
    const Eigen::Vector3d x = t * (length * i / elements);
    s += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", i + 1, x.x(), x.y(), x.z());
  }
  s += "*ELEMENT, TYPE=" + type + ", ELSET=BEAM\n";
  for (int i = 1; i <= elements; ++i) s += fmt::format("{}, {}, {}\n", i, i, i + 1);
  s += fmt::format("*NSET, NSET=TIP\n{}\n", elements + 1);
  return s + section + material + extra;
}

fem::FrameModel read(const std::string& text) { return fem::read_inp_text(text, "beam.inp", "."); }

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

const std::string kSteelSi = "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n";

// ---------------------------------------------------------------- gravity

// A steel cantilever along X in in-lbf-s under GRAV 386.09 in/s^2 along -Z:
// the weight per length w = rho A g, root shear w L, root moment w L^2/2 and
// the tip deflection w L^4 / (8 E I) (the load acts along local 1 = -Z, so
// the section bends about its 2-axis, I22 = b a^3 / 12).
TEST(DistributedLoads, CantileverUnderGravityHasRootMomentWL2Over2AndTipDeflectionWL4Over8EI) {
  const double L = 80.0, a = 2.0, b = 4.0, E = 30e6, rho = 7.33e-4, g = 386.09;  // in, in, in, psi, lbf s^2/in^4, in/s^2
  for (const char* type : {"B33", "B31"}) {
    const std::string deck =
        beam_deck("in-lbf-s", Eigen::Vector3d::UnitX(), L, 8, type, fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n{}, {}\n", a, b),
                  fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, 0.3\n*DENSITY\n{}\n", E, rho),
                  fmt::format("*BOUNDARY\n1, ENCASTRE\n*STEP\n*STATIC\n*DLOAD\nBEAM, GRAV, {}, 0, 0, -1\n*END STEP\n", g));
    const fem::FrameModel m = read(deck);
    const UnitSystem& u = m.units;
    ASSERT_EQ(m.element_loads.size(), 8u);
    const double w = rho * a * b * g;  // lbf/in
    const fem::StaticResult r = fem::solve_static(m);
    const double root_shear = r.reaction(2) / u.to_si_factor(Quantity::force);
    const double root_moment = r.reaction(4) / u.to_si_factor(Quantity::moment);  // about Y
    std::printf("%s gravity cantilever: root shear %.2e, root moment %.2e, tip %.2e (relative errors)\n", type, rel(root_shear, w * L),
                rel(root_moment, -w * L * L / 2), rel(r.displacement(6 * 8 + 2) / u.to_si_factor(Quantity::length),
                                                      -w * L * L * L * L / (8 * E * (b * a * a * a / 12)) -
                                                          (std::string(type) == "B31" ? w * L * L / (2 * (10 * 1.3 / (12 + 11 * 0.3)) * (E / 2.6) * a * b) : 0.0)));
    EXPECT_LT(rel(root_shear, w * L), 1e-12) << type;
    // The weight along -Z at x > 0 turns the root about +Y: the support holds -w L^2/2.
    EXPECT_LT(rel(root_moment, -w * L * L / 2), 1e-12) << type;
    const double i22 = b * a * a * a / 12;
    const double tip = r.displacement(6 * 8 + 2) / u.to_si_factor(Quantity::length);
    const double eb = -w * L * L * L * L / (8 * E * i22);
    if (std::string(type) == "B33") {
      EXPECT_LT(rel(tip, eb), 1e-10);
    } else {
      // Timoshenko: plus the shear deflection w L^2 / (2 k G A), exact at the nodes too.
      const double nu = 0.3, G = E / (2 * (1 + nu)), k = 10 * (1 + nu) / (12 + 11 * nu);
      EXPECT_LT(rel(tip, eb - w * L * L / (2 * k * G * a * b)), 1e-10);
    }
    // Section forces of the root element at its root: the root moment and shear, exactly.
    const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
    const double mf = u.to_si_factor(Quantity::moment), ff = u.to_si_factor(Quantity::force);
    EXPECT_LT(rel(std::abs(st[0].forces.mz) / mf, w * L * L / 2), 1e-10) << type;
    EXPECT_LT(rel(std::abs(st[0].forces.vy) / ff, w * L), 1e-10) << type;
    // Mid-element station of the tip element (x = L - h/2): M = w (h/2)^2 / 2, from the fixed-end terms.
    const double h = L / 8;
    EXPECT_LT(rel(std::abs(st[3 * 7 + 1].forces.mz) / mf, w * h * h / 8), 1e-9) << type;
    EXPECT_NEAR(st[3 * 7 + 2].forces.mz / mf, 0.0, 1e-9 * w * L * L) << type;
  }
}

// GRAV on a MASS element: its weight m g at its node. A point mass at the tip
// of a massless cantilever deflects it by m g L^3 / (3 E I); a blank element
// field applies gravity to every element (Abaqus).
TEST(DistributedLoads, GravityOnAPointMassIsItsWeightAtItsNode) {
  const double L = 2.0, m = 150.0, g = 9.81, E = 2.1e11, a = 0.05, b = 0.1;
  const std::string deck = beam_deck(
      "m-N-s", Eigen::Vector3d::UnitX(), L, 4, "B33", fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n{}, {}\n", a, b),
      fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, 0.3\n", E),
      fmt::format("*ELEMENT, TYPE=MASS, ELSET=PM\n100, 5\n*MASS, ELSET=PM\n{}\n*BOUNDARY\n1, ENCASTRE\n*DLOAD\n, GRAV, {}, 0, 0, -1\n", m, g));
  const fem::FrameModel model = read(deck);
  EXPECT_TRUE(model.element_loads.empty());  // the beams have no density
  const fem::StaticResult r = fem::solve_static(model);
  EXPECT_LT(rel(r.reaction(2), m * g), 1e-12);
  const double i22 = b * a * a * a / 12;
  EXPECT_LT(rel(r.displacement(6 * 4 + 2), -m * g * L * L * L / (3 * E * i22)), 1e-10);
}

// ---------------------------------------------------------------- fixed-end moments

// A clamped-clamped span under a uniform load w: end moments w L^2/12 (hogging),
// midspan w L^2/24 (sagging), end shears w L/2, from the section forces of a
// single element and of several; both element theories (the fixed-end moments
// of a uniform load do not depend on shear flexibility).
TEST(DistributedLoads, ClampedClampedUniformLoadHasEndMomentsWL2Over12AndMidspanWL2Over24) {
  const double L = 3.0, w = 2500.0;
  for (const char* type : {"B33", "B31"}) {
    for (int n : {1, 2, 6}) {
      const std::string deck =
          beam_deck("m-N-s", Eigen::Vector3d::UnitX(), L, n, type, "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 1, 0\n",
                    kSteelSi, fmt::format("*BOUNDARY\n1, ENCASTRE\nTIP, ENCASTRE\n*DLOAD\nBEAM, PY, {}\n", -w));
      const fem::FrameModel m = read(deck);
      // One element between two clamps has no free DOF: u = 0 and its section
      // forces are its fixed-end terms alone.
      Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dof_count());
      if (n > 1) {
        const fem::StaticResult r = fem::solve_static(m);
        EXPECT_LT(rel(r.reaction(1), w * L / 2), 1e-10) << type << " " << n;
        EXPECT_LT(rel(r.reaction(6 * n + 1), w * L / 2), 1e-10) << type << " " << n;
        u = r.displacement;
      }
      // Stations 0, 1/2, 1 of each element: for n = 1 the middle one is at midspan.
      const int stations = 3;
      const std::vector<fem::StationResult> st = fem::recover_stations(m, u, stations);
      const double end_a = st.front().forces.mz, end_b = st.back().forces.mz;
      std::printf("%s clamped-clamped, %d element(s): end moments %.2e, %.2e (relative errors)\n", type, n, rel(end_a, -w * L * L / 12), rel(end_b, -w * L * L / 12));
      EXPECT_LT(rel(end_a, -w * L * L / 12), 1e-9) << type << " " << n;
      EXPECT_LT(rel(end_b, -w * L * L / 12), 1e-9) << type << " " << n;
      EXPECT_LT(rel(std::abs(st.front().forces.vy), w * L / 2), 1e-9) << type << " " << n;
      bool found_mid = false;
      for (const fem::StationResult& s : st) {
        const double x = s.point.x();
        // M(x) = w x (L - x)/2 - w L^2/12 everywhere along the span.
        EXPECT_NEAR(s.forces.mz, w * x * (L - x) / 2 - w * L * L / 12, 1e-9 * w * L * L) << type << " n=" << n << " x=" << x;
        if (std::abs(x - L / 2) < 1e-12) {
          found_mid = true;
          EXPECT_LT(rel(s.forces.mz, w * L * L / 24), 1e-9) << type << " " << n;
        }
      }
      EXPECT_TRUE(found_mid);
    }
  }
}

// ---------------------------------------------------------------- modal transient

// The mesh's load pattern (fem::applied_load_vector: the consistent loads of
// a GRAV line) switched on at t = 0 on a cantilever at rest: undamped, every
// mode i follows q_i = (p_i / omega_i^2)(1 - cos omega_i t), p_i = phi_i^T f,
// so u(t) + sum_i phi_i (p_i / omega_i^2) cos(omega_i t) is the static
// deflection at every time: the tip's w L^4 / (8 E I) and the static solve's
// displacements, from the same consistent loads.
TEST(DistributedLoads, SuddenGravityOnACantileverOscillatesAboutItsStaticDeflection) {
  const double L = 1.2, a = 0.03, b = 0.05, E = 2.1e11, rho = 7850, g = 9.81;
  const fem::FrameModel m =
      read(beam_deck("m-N-s", Eigen::Vector3d::UnitX(), L, 6, "B33", fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n{}, {}\n", a, b),
                     kSteelSi, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\n, GRAV, {}, 0, 0, -1\n", g)));
  const fem::FrameDynamics frame(m);
  const fem::ModalBasis basis = frame.all_modes();
  const Eigen::VectorXd f = fem::applied_load_vector(m);
  fem::TransientInput in;
  in.times = Eigen::VectorXd::LinSpaced(5, 0.0, 0.004);
  std::vector<Eigen::Triplet<double, int>> t;
  for (Eigen::Index i = 0; i < f.size(); ++i)
    if (f(i) != 0.0) t.emplace_back(static_cast<int>(i), 0, f(i));
  in.distribution.resize(m.dof_count(), 1);
  in.distribution.setFromTriplets(t.begin(), t.end());
  in.components = Eigen::MatrixXd::Ones(1, 5);
  fem::ModalTransientOptions o;
  o.method = fem::ResponseMethod::mode_displacement;
  o.damping = fem::ModalDamping::ratio(0.0);
  o.initial = fem::InitialState::rest;
  const fem::TransientResult r = fem::modal_transient(frame, basis, in, o);
  const Eigen::VectorXd u_static = fem::solve_static(m).displacement;
  const Eigen::VectorXd f_free = frame.free_loads(in.distribution).col(0);
  const double w = rho * a * b * g, tip = -w * std::pow(L, 4) / (8 * E * b * a * a * a / 12);
  EXPECT_LT(rel(u_static(6 * 6 + 2), tip), 1e-10);
  for (Eigen::Index k = 0; k < r.times.size(); ++k) {
    Eigen::VectorXd free = Eigen::VectorXd::Zero(frame.dofs().free_count());
    for (Eigen::Index i = 0; i < basis.eigenvalues.size(); ++i) {
      const double omega2 = basis.eigenvalues(i), p = basis.shapes.col(i).dot(f_free);
      free += basis.shapes.col(i) * (p / omega2 * std::cos(std::sqrt(omega2) * r.times(k)));
    }
    const Eigen::VectorXd static_part = r.displacement.col(k) + frame.expand(free);
    EXPECT_LT((static_part - u_static).norm(), 1e-8 * u_static.norm()) << "t = " << r.times(k);
  }
}

// ---------------------------------------------------------------- local axes

// P1 and P2 act along the section's local 1 and 2 directions of each element:
// on an oblique cantilever with an oblique n1, P1 = w equals PX, PY, PZ of
// w n1, and P2 gives the tip deflection w L^4 / (8 E I11) along n2 (bending
// about axis 1); P1 gives w L^4 / (8 E I22) along n1.
TEST(DistributedLoads, P1AndP2FollowTheSectionAxesOfARotatedMember) {
  const Eigen::Vector3d t = Eigen::Vector3d(1, 2, 2) / 3.0, n1_hint(0, 0, 1);
  const Eigen::Vector3d n2 = t.cross(n1_hint).normalized(), n1 = n2.cross(t);
  const double L = 1.5, w = 800.0, a = 0.04, b = 0.07, E = 2.1e11;
  const std::string section = fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n{}, {}\n0, 0, 1\n", a, b);
  auto run = [&](const std::string& dload) {
    return fem::solve_static(read(beam_deck("m-N-s", t, L, 5, "B33", section, kSteelSi, "*BOUNDARY\n1, ENCASTRE\n*DLOAD\n" + dload)));
  };
  const fem::StaticResult p1 = run(fmt::format("BEAM, P1, {}\n", w));
  const fem::StaticResult global = run(fmt::format("BEAM, PX, {:.17g}\nBEAM, PY, {:.17g}\nBEAM, PZ, {:.17g}\n", w * n1.x(), w * n1.y(), w * n1.z()));
  EXPECT_LT((p1.displacement - global.displacement).norm(), 1e-12 * p1.displacement.norm());
  const Eigen::Vector3d tip1 = p1.displacement.segment<3>(6 * 5);
  EXPECT_LT(rel(tip1.dot(n1), w * std::pow(L, 4) / (8 * E * b * a * a * a / 12)), 1e-10);
  EXPECT_NEAR(tip1.dot(n2), 0.0, 1e-10 * tip1.norm());
  const fem::StaticResult p2 = run(fmt::format("BEAM, P2, {}\n", w));
  const Eigen::Vector3d tip2 = p2.displacement.segment<3>(6 * 5);
  EXPECT_LT(rel(tip2.dot(n2), w * std::pow(L, 4) / (8 * E * a * b * b * b / 12)), 1e-10);
  EXPECT_NEAR(tip2.dot(n1), 0.0, 1e-10 * tip2.norm());
  EXPECT_NEAR(tip2.dot(t), 0.0, 1e-10 * tip2.norm());
}

// The load vector of a line load sums to w L in its direction and its moment
// about the origin is that of the resultant at the span's centre: the
// consistent loads are statically equivalent to the load.
TEST(DistributedLoads, ConsistentLoadsAreStaticallyEquivalentToTheLineLoad) {
  const Eigen::Vector3d t = Eigen::Vector3d(2, -1, 2) / 3.0;
  const double L = 2.4, w = 1000.0;
  const fem::FrameModel m = read(beam_deck("m-N-s", t, L, 3, "B31", "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=PIPE\n0.05, 0.005\n1, 0, 0\n",
                                          kSteelSi, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\nBEAM, P2, {}\nBEAM, PZ, {}\n", w, -w)));
  const Eigen::VectorXd f = fem::element_load_vector(m);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const Eigen::Vector3d fi = f.segment<3>(static_cast<Eigen::Index>(6 * i));
    force += fi;
    moment += f.segment<3>(static_cast<Eigen::Index>(6 * i + 3)) + m.nodes[i].position.cross(fi);
  }
  const Eigen::Vector3d n2 = t.cross(Eigen::Vector3d::UnitX()).normalized();
  const Eigen::Vector3d q = w * n2 - w * Eigen::Vector3d::UnitZ();
  EXPECT_LT((force - q * L).norm(), 1e-12 * w * L);
  EXPECT_LT((moment - (t * L / 2).cross(q * L)).norm(), 1e-12 * w * L * L);
}

// ---------------------------------------------------------------- reader errors

// Line number of the first line of `text` containing `marker` (1-based).
int line_of(const std::string& text, const std::string& marker) {
  int n = 1;
  for (std::size_t pos = 0; pos < text.size(); ++n) {
    const std::size_t end = text.find('\n', pos);
    if (text.substr(pos, end - pos).find(marker) != std::string::npos) return n;
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return -1;
}

struct DloadError {
  std::string name, dload, marker, message;  // message after "beam.inp:LINE: *DLOAD: "
};

TEST(DistributedLoads, MalformedLinesNameTheLineAndWhatWasExpected) {
  const std::vector<DloadError> cases = {
      {"UnknownLoadType", "*DLOAD\nBEAM, P3, 10\n", "P3", "expected a load type framedyn reads on beams: GRAV, P1, P2, PX, PY or PZ (uniform), found 'P3'"},
      {"GravWithoutDirection", "*DLOAD\nBEAM, GRAV, 9.81\n", "GRAV", "expected element or ELSET (empty: all elements), GRAV, acceleration, direction x, y, z, found 'BEAM, GRAV, 9.81'"},
      {"GravZeroDirection", "*DLOAD\nBEAM, GRAV, 9.81, 0, 0, 0\n", "GRAV", "expected a nonzero, finite gravity direction, found 'BEAM, GRAV, 9.81, 0, 0, 0'"},
      {"LineLoadWithoutMagnitude", "*DLOAD\nBEAM, PY\n", "BEAM, PY", "expected element or ELSET, PY, force per length, found 'BEAM, PY'"},
      {"LineLoadOnAllElements", "*DLOAD\n, PY, 5\n", ", PY", "expected an element or ELSET for PY (only GRAV applies to all elements), found an empty field"},
      {"UndefinedSet", "*DLOAD\nBEEM, PY, 5\n", "BEEM", "expected an element number or a defined *ELSET, found 'BEEM'"},
      {"UndefinedElement", "*DLOAD\n9, PY, 5\n", "9, PY", "expected an element defined by *ELEMENT or a defined *ELSET, found element 9"},
      {"NotANumber", "*DLOAD\nBEAM, PY, heavy\n", "heavy", "expected a force per length (a finite number), found 'heavy'"},
      {"LineLoadOnAMassElement", "*ELEMENT, TYPE=MASS, ELSET=PM\n100, 3\n*MASS, ELSET=PM\n5\n*DLOAD\nPM, PZ, 5\n", "PM, PZ",
       "expected beam elements (B31, B32, B32R, B33) for a PZ line load, found element 100 of type MASS"},
  };
  for (const DloadError& c : cases) {
    const std::string deck = beam_deck("m-N-s", Eigen::Vector3d::UnitX(), 2.0, 2, "B31",
                                       "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n", kSteelSi, c.dload);
    try {
      read(deck);
      ADD_FAILURE() << c.name << ": no error";
    } catch (const framedyn::core::InputError& e) {
      EXPECT_EQ(std::string(e.what()), fmt::format("beam.inp:{}: *DLOAD: {}", line_of(deck, c.marker), c.message)) << c.name;
    }
  }
  // GRAV on beams without density: no mass to weigh.
  const std::string massless = beam_deck("m-N-s", Eigen::Vector3d::UnitX(), 2.0, 2, "B31",
                                         "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n",
                                         "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n", "*DLOAD\nBEAM, GRAV, 9.81, 0, 0, -1\n");
  try {
    read(massless);
    ADD_FAILURE() << "GRAV without density: no error";
  } catch (const framedyn::core::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fmt::format("beam.inp:{}: *DLOAD: expected elements with mass for GRAV (beams whose material has a *DENSITY, or MASS elements), "
                          "found no mass in 'BEAM'", line_of(massless, "GRAV")));
  }
}

}  // namespace

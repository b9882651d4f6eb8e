// Three-node beams (B32, B32R) against closed forms and the two-node elements:
//   - a cantilever under a tip load: Timoshenko deflection PL^3/3EI + PL/(G As);
//   - shear locking of the 3-point rule on slender members, none with 2 points;
//   - refined B32R meshes and refined B31 meshes converge to the same modes;
//   - a curved member (quarter circle) against Castigliano's theorem;
//   - the midside node off the middle: constant-strain states stay exact,
//     outside the quarter points the element is refused;
//   - section forces at stations by statics; the reader's B32/B32R, CalculiX's
//     *BEAM GENERAL SECTION BOX and PIPE, and its refusals (NLGEOM, offsets).
// Line loads and releases on them: test_quadratic_beam_loads.cpp.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/beam_section.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/modal_transient.h"
#include "fem/quadratic_beam_element.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

namespace fem = framedyn::fem;
namespace support = framedyn::testing;
using fem::FrameModel;

constexpr double kPi = 3.14159265358979323846;

// A straight line of `elements` three-node elements from `start` to `end`,
// the midside node of each at `midside` (0.5 = the middle) of its element.
// Node 0 is `start`; the last node is `end`.
FrameModel quadratic_line(const Eigen::Vector3d& start, const Eigen::Vector3d& end, int elements, const fem::SectionProperties& section,
                          bool reduced, double midside = 0.5, const Eigen::Vector3d& n1 = Eigen::Vector3d(0, 0, -1)) {
  FrameModel m;
  const int s = support::add_section(m, section, support::steel(), n1);
  int previous = support::add_node(m, start);
  for (int e = 0; e < elements; ++e) {
    const Eigen::Vector3d a = start + (end - start) * (static_cast<double>(e) / elements);
    const Eigen::Vector3d b = start + (end - start) * (static_cast<double>(e + 1) / elements);
    const int mid = support::add_node(m, a + midside * (b - a));
    const int next = support::add_node(m, b);
    fem::BeamElement beam;
    beam.id = e + 1;
    beam.node_a = previous;
    beam.node_m = mid;
    beam.node_b = next;
    beam.section = s;
    beam.reduced_integration = reduced;
    m.beams.push_back(beam);
    previous = next;
  }
  m.index();
  return m;
}

// Displacement of the last node along `direction`.
double tip_displacement(const FrameModel& m, int dof) {
  const fem::StaticResult r = fem::solve_static(m);
  return r.displacement(fem::kDofsPerNode * (static_cast<int>(m.nodes.size()) - 1) + dof);
}

// Rectangle 0.05 (along n1) x 0.1 (along n2), steel.
fem::SectionProperties rect() { return fem::rectangle_section(0.05, 0.1, 0.3); }

// Timoshenko cantilever under a tip force P along n2 (bending about n1: I11, shear area 2).
double timoshenko_tip(double p, double length, const fem::SectionProperties& s) {
  const fem::Material st = support::steel();
  return p * length * length * length / (3 * st.youngs_modulus * s.i11) + p * length / (st.shear_modulus * s.shear_area_2);
}

TEST(QuadraticBeam, OneElementGivesTheTimoshenkoTipDeflectionOfACantileverUnderATipLoad) {
  // Beam along x, n1 = -z, so n2 = t x n1 = +y. One B32R element is exact
  // (Eq. Q.8): the bending moment is linear, so the exact rotation is
  // quadratic and in the element's space, and the 2-point rule samples the
  // shear strain where its linear part is exact. (The 3-point rule locks:
  // next test.)
  const double length = 2.0, p = 1000.0;
  FrameModel m = quadratic_line({0, 0, 0}, {length, 0, 0}, 1, rect(), true);
  support::clamp_node(m, 0);
  support::add_nodal_force(m, 2, {0, p, 0});
  EXPECT_NEAR(tip_displacement(m, 1), timoshenko_tip(p, length, rect()), 1e-10 * timoshenko_tip(p, length, rect()));
}

TEST(QuadraticBeam, ThreePointRuleLocksAtThreeQuartersOfTheSlenderCantileverDeflectionAndRefinementRemovesIt) {
  // Full integration makes the shear strain (quadratic) vanish at three points
  // of a slender element, i.e. everywhere: theta = w' is then linear and the
  // curvature constant. Minimising (1/2) EI kappa^2 L - P kappa L^2 / 2 gives
  // kappa = PL/2EI and w = PL^3/4EI: three quarters of PL^3/3EI. The
  // shear flexibility of a real section adds terms of order EI/(G As L^2)
  // ~ (h/L)^2: at L/h = 1000, a few 1e-6. Refining the mesh removes the
  // locking at the rate of the element's shear constraint, (h/L)^2.
  const double p = 1000.0, length = 100.0;  // L/h = 1000
  {
    FrameModel m = quadratic_line({0, 0, 0}, {length, 0, 0}, 1, rect(), false);
    support::clamp_node(m, 0);
    support::add_nodal_force(m, 2, {0, p, 0});
    EXPECT_NEAR(tip_displacement(m, 1) / timoshenko_tip(p, length, rect()), 0.75, 1e-4);
  }
  double previous_error = 0.0;
  for (int n : {2, 4, 8, 16}) {
    double ratio[2];
    for (int k = 0; k < 2; ++k) {
      FrameModel m = quadratic_line({0, 0, 0}, {10.0, 0, 0}, n, rect(), k == 0);  // L/h = 100
      support::clamp_node(m, 0);
      support::add_nodal_force(m, static_cast<int>(m.nodes.size()) - 1, {0, p, 0});
      ratio[k] = tip_displacement(m, 1) / timoshenko_tip(p, 10.0, rect());
    }
    SCOPED_TRACE(n);
    EXPECT_NEAR(ratio[0], 1.0, 1e-8);  // B32R: exact at the nodes on every mesh
    const double error = 1.0 - ratio[1];
    EXPECT_GT(error, 0.0);  // B32 is too stiff ...
    if (previous_error > 0.0) {
      EXPECT_GT(previous_error / error, 3.5);  // ... by (h/L)^2: / 4 per halving
    }
    previous_error = error;
  }
}

// Three-node and two-node Timoshenko meshes of the same inclined cantilever.
FrameModel inclined_cantilever(int elements, bool quadratic) {
  const Eigen::Vector3d start(0.2, -0.1, 0.3), direction = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  const double length = 3.0;
  const Eigen::Vector3d n1(0.0, 1.0, -1.0);  // oblique, not along the axis
  const fem::SectionProperties s = fem::rectangle_section(0.06, 0.1, 0.3);
  if (quadratic) {
    FrameModel m = quadratic_line(start, start + length * direction, elements, s, true, 0.5, n1);
    support::clamp_node(m, 0);
    return m;
  }
  FrameModel m;
  const int sec = support::add_section(m, s, support::steel(), n1);
  const int first = support::add_node(m, start);
  support::add_beam_line(m, first, start + length * direction, elements, sec, fem::BeamTheory::timoshenko);
  m.index();
  support::clamp_node(m, 0);
  return m;
}

std::vector<double> frequencies(const FrameModel& m, int count) {
  fem::ModalOptions o;
  o.mode_count = count;
  const fem::ModalResult r = fem::compute_modes(m, o);
  std::vector<double> f;
  for (const fem::Mode& mode : r.modes) f.push_back(mode.frequency_hz);
  return f;
}

TEST(QuadraticBeam, RefinedB32RAndRefinedB31MeshesOfAnInclinedCantileverConvergeToTheSameModes) {
  // The limit of both meshes is the Timoshenko beam. B31 (exact static
  // stiffness, Przemieniecki's consistent mass) converges as h^2; the
  // quadratic element as h^4 in frequency (Lagrange quadratics, consistent
  // mass). Richardson extrapolation of two B31 meshes (n, 2n) removes the
  // h^2 term, leaving the h^4 one: the extrapolated B31 and B32R limits agree
  // to the size of the next terms, estimated from the B31 meshes themselves.
  const int count = 8;
  const std::vector<double> q = frequencies(inclined_cantilever(32, true), count);
  const std::vector<double> l1 = frequencies(inclined_cantilever(64, false), count);
  const std::vector<double> l2 = frequencies(inclined_cantilever(128, false), count);
  const std::vector<double> q_coarse = frequencies(inclined_cantilever(16, true), count);
  for (int i = 0; i < count; ++i) {
    SCOPED_TRACE(i + 1);
    const double extrapolated = (4.0 * l2[i] - l1[i]) / 3.0;
    // Quadratic meshes: error(16) ~ 16 error(32); their difference bounds the error of 32 by (q16 - q32)/15.
    const double q_error = std::abs(q_coarse[i] - q[i]) / 15.0;
    const double l_error = std::abs(l2[i] - l1[i]) / 3.0 / 4.0;  // next term of the B31 series, at most a quarter of the removed one
    EXPECT_NEAR(q[i], extrapolated, 2.0 * (q_error + l_error) + 1e-9 * q[i]);
  }
}

TEST(QuadraticBeam, QuarterCircleCantileverOfCurvedElementsMatchesCastigliano) {
  // A quarter circle of radius R in the x-y plane, clamped at (R, 0, 0), free
  // at (0, R, 0), loaded at the free end by F along y (across the tangent
  // there). At angle phi: M = -F R cos(phi), N = F cos(phi), V = -F sin(phi)
  // (signs drop out of the squares). Castigliano:
  //   delta_y = F (pi / 4) (R^3 / (E I) + R / (E A) + R / (G As)).
  // Curved three-node elements (midside node on the arc) converge to it as
  // the parabolas approach the circle.
  const double radius = 2.0, f = 500.0;
  const fem::SectionProperties s = rect();  // n1 = -z: in-plane bending about n1 (I11), shear along n2
  const fem::Material st = support::steel();
  const double exact = f * kPi / 4.0 * (radius * radius * radius / (st.youngs_modulus * s.i11) + radius / (st.youngs_modulus * s.area) +
                                        radius / (st.shear_modulus * s.shear_area_2));
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    FrameModel m;
    const int sec = support::add_section(m, s, st, {0, 0, -1});
    auto at = [&](double phi) { return Eigen::Vector3d(radius * std::cos(phi), radius * std::sin(phi), 0.0); };
    int previous_node = support::add_node(m, at(0.0));
    for (int e = 0; e < n; ++e) {
      const double p0 = kPi / 2 * e / n, p1 = kPi / 2 * (e + 1) / n;
      fem::BeamElement b;
      b.id = e + 1;
      b.node_a = previous_node;
      b.node_m = support::add_node(m, at(0.5 * (p0 + p1)));
      b.node_b = support::add_node(m, at(p1));
      b.section = sec;
      b.reduced_integration = true;
      m.beams.push_back(b);
      previous_node = b.node_b;
    }
    m.index();
    support::clamp_node(m, 0);
    support::add_nodal_force(m, previous_node, {0, f, 0});
    const double error = std::abs(tip_displacement(m, 1) / exact - 1.0);
    SCOPED_TRACE(n);
    if (previous > 0.0) {
      EXPECT_GT(previous / error, 8.0);  // at least third order in h (measured: fourth, 9e-5 at n = 4)
    }
    if (n == 16) {
      EXPECT_LT(error, 1e-6);  // fourth order from 9e-5 at n = 4 predicts 3.5e-7
    }
    previous = error;
  }
}

TEST(QuadraticBeam, MidsideNodeOffTheMiddleKeepsUniformStretchAndTwistExactAndIsRefusedOutsideTheQuarterPoints) {
  // With the midside node at 0.4 L the map s(xi) is quadratic, so the exact
  // u = N s / EA and twist = T s / GJ (quadratic in xi) are in the element's
  // space: the tip values are exact. At 0.2 L, ds/dxi changes sign inside the
  // element (the quarter points are at 0.25 L and 0.75 L): refused.
  const double length = 1.5, n = 2.0e5, t = 300.0;
  const fem::SectionProperties s = rect();
  const fem::Material st = support::steel();
  for (bool reduced : {false, true}) {
    FrameModel m = quadratic_line({0, 0, 0}, {0, 0, length}, 1, s, reduced, 0.4, {1, 0, 0});
    support::clamp_node(m, 0);
    support::add_nodal_force(m, 1, {0, 0, 0});
    support::add_nodal_force(m, 2, {0, 0, n});
    support::add_nodal_moment(m, 2, {0, 0, t});
    const fem::StaticResult r = fem::solve_static(m);
    EXPECT_NEAR(r.displacement(6 * 2 + 2), n * length / (st.youngs_modulus * s.area), 1e-10 * n * length / (st.youngs_modulus * s.area));
    EXPECT_NEAR(r.displacement(6 * 2 + 5), t * length / (st.shear_modulus * s.torsion_constant),
                1e-10 * t * length / (st.shear_modulus * s.torsion_constant));
    // The midside node moves as its place along the bar says: 0.4 of the tip.
    EXPECT_NEAR(r.displacement(6 * 1 + 2), 0.4 * r.displacement(6 * 2 + 2), 1e-10 * r.displacement(6 * 2 + 2));
  }
  FrameModel bad = quadratic_line({0, 0, 0}, {0, 0, length}, 1, s, true, 0.2, {1, 0, 0});
  support::clamp_node(bad, 0);
  try {
    fem::assemble(bad, fem::make_dof_map(bad));
    ADD_FAILURE() << "a folded element was assembled";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("beam element 1: its midside node is not between the quarter points"), std::string::npos) << e.what();
  }
}

TEST(QuadraticBeam, TipLoadRampedOverTwentyPeriodsGivesTheStaticTimoshenkoDeflectionInATransient) {
  // Transient response by mode superposition (all modes, no damping) of a
  // B32R cantilever whose tip load rises linearly over tau = 20 periods of
  // its first mode and then holds. The mode i left ringing after the ramp has
  // amplitude u_i |sin(w_i tau / 2)| / (w_i tau / 2) <= 2 u_i / (w_i tau), so
  // the tip stays within 2 / (w_1 tau) = 1 / (20 pi) = 1.6 % of the static
  // Timoshenko deflection (Eq. Q.8) from the end of the ramp on.
  const double length = 2.0, p = 1000.0;
  FrameModel m = quadratic_line({0, 0, 0}, {length, 0, 0}, 8, rect(), true);
  support::clamp_node(m, 0);
  const int tip = static_cast<int>(m.nodes.size()) - 1;
  const fem::FrameDynamics frame(m);
  const fem::ModalBasis basis = frame.all_modes();
  const double omega1 = std::sqrt(basis.eigenvalues(0)), tau = 20.0 * 2.0 * kPi / omega1;
  fem::TransientInput in;
  const int steps = 2000;  // 100 steps per period of mode 1; the recurrence is exact for piecewise-linear loads
  in.times = Eigen::VectorXd::LinSpaced(steps + 1, 0.0, 1.5 * tau);
  in.distribution.resize(m.dof_count(), 1);
  in.distribution.insert(fem::kDofsPerNode * tip + 1, 0) = 1.0;
  in.components.resize(1, steps + 1);
  for (int k = 0; k <= steps; ++k) in.components(0, k) = p * std::min(1.0, in.times(k) / tau);
  fem::ModalTransientOptions o;
  o.damping = fem::ModalDamping::ratio(0.0);
  o.initial = fem::InitialState::rest;
  const fem::TransientResult r = fem::modal_transient(frame, basis, in, o);
  const double exact = timoshenko_tip(p, length, rect());
  double worst = 0.0;
  for (int k = 0; k <= steps; ++k)
    if (in.times(k) >= tau) worst = std::max(worst, std::abs(r.displacement(fem::kDofsPerNode * tip + 1, k) / exact - 1.0));
  EXPECT_LT(worst, 1.0 / (20.0 * kPi));
  EXPECT_GT(worst, 0.0);
}

TEST(QuadraticBeam, SectionForcesAtStationsOfATipLoadedCantileverFollowStatics) {
  // Beam along x, n1 = -z, n2 = +y; tip force P along +y at x = L. A cut at x
  // carries Vz = P (along n2) and the moment of P about the cut,
  // (L - x) e_x x P e_y = P (L - x) e_z = -P (L - x) n1: My = -P (L - x).
  // Statics holds at every station, the midside node's included.
  const double length = 2.0, p = 800.0;
  FrameModel m = quadratic_line({0, 0, 0}, {length, 0, 0}, 2, rect(), true);
  support::clamp_node(m, 0);
  support::add_nodal_force(m, 4, {0, p, 0});
  const fem::StaticResult r = fem::solve_static(m);
  const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 5);
  ASSERT_EQ(st.size(), 10u);
  for (const fem::StationResult& x : st) {
    const double global_x = x.point.x();
    SCOPED_TRACE(global_x);
    EXPECT_NEAR(x.x, global_x - (x.element_id - 1) * 1.0, 1e-12);  // distance from the element's node a
    EXPECT_NEAR(x.forces.vz, p, 1e-9 * p);
    EXPECT_NEAR(x.forces.my, -p * (length - global_x), 1e-9 * p * length);
    EXPECT_NEAR(x.forces.n, 0.0, 1e-9 * p);
    EXPECT_NEAR(x.forces.vy, 0.0, 1e-9 * p);
    EXPECT_NEAR(x.forces.t, 0.0, 1e-9 * p * length);
    EXPECT_NEAR(x.forces.mz, 0.0, 1e-9 * p * length);
  }
  // The root moment is the reaction: M = P L.
  EXPECT_NEAR(r.reaction(5), -p * length, 1e-9 * p * length);
}

TEST(QuadraticBeam, ElementMassIsRhoALongTheArcAndItsAxialRotaryInertiaRhoIpL) {
  // Rigid translation r and rigid rotation about the axis: r^T M r is the
  // element's mass rho A L and its rotary inertia about the axis rho Ip L
  // (a straight element, midside off the middle) for both mass formulations.
  const fem::SectionProperties s = rect();
  const double length = 1.2, rho = support::steel().density;
  const FrameModel m = quadratic_line({0, 0, 0}, {length, 0, 0}, 1, s, true, 0.45);
  const fem::SectionGeometry g = fem::section_geometry(m, 0, fem::BeamTheory::timoshenko);
  for (fem::MassFormulation f : {fem::MassFormulation::consistent, fem::MassFormulation::lumped}) {
    const fem::Matrix18d mm = fem::quadratic_beam_mass(m, m.beams[0], g, f);
    fem::Vector18d ux = fem::Vector18d::Zero(), rx = fem::Vector18d::Zero();
    for (int i = 0; i < 3; ++i) {
      ux(6 * i) = 1.0;
      rx(6 * i + 3) = 1.0;  // nodes on the x axis: no translation from a rotation about it
    }
    EXPECT_NEAR(ux.dot(mm * ux), rho * s.area * length, 1e-12 * rho * s.area * length);
    EXPECT_NEAR(rx.dot(mm * rx), rho * s.polar_moment() * length, 1e-12 * rho * s.polar_moment() * length);
  }
}

TEST(QuadraticBeam, ReaderBuildsB32AndB32RAndCalculixBoxAndPipeGeneralSections) {
  // CalculiX's *BEAM GENERAL SECTION, SECTION=PIPE (r outer radius, t wall)
  // and BOX (a, b, t1..t4) read as *BEAM SECTION with that shape; the
  // constants against hand formulas: pipe A = pi (ro^2 - ri^2),
  // I = pi (ro^4 - ri^4) / 4, J = 2 I; equal-wall box A = ab - (a-2t)(b-2t),
  // I11 = (a b^3 - (a-2t)(b-2t)^3) / 12, Bredt J = 4 Am^2 t / (2 (a-t) + 2 (b-t)).
  const std::string deck =
      "** units: m-N-s\n"
      "*NODE\n1, 0, 0, 0\n2, 0.5, 0, 0\n3, 1, 0, 0\n4, 1.5, 0, 0\n5, 2, 0, 0\n"
      "*ELEMENT, TYPE=B32R, ELSET=P\n1, 1, 2, 3\n"
      "*ELEMENT, TYPE=B32, ELSET=B\n2, 3, 4, 5\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n"
      "*BEAM GENERAL SECTION, ELSET=P, MATERIAL=STEEL, SECTION=PIPE\n0.11, 0.01\n0.7071, 0.7071, 0\n"
      "*BEAM GENERAL SECTION, ELSET=B, MATERIAL=STEEL, SECTION=BOX\n0.1, 0.2, 0.01, 0.01, 0.01, 0.01\n0, 0, 1\n"
      "*BOUNDARY\n1, 1, 6\n";
  const FrameModel m = fem::read_inp_text(deck, "deck.inp", ".");
  ASSERT_EQ(m.beams.size(), 2u);
  EXPECT_TRUE(m.beams[0].is_quadratic());
  EXPECT_TRUE(m.beams[0].reduced_integration);
  EXPECT_FALSE(m.beams[1].reduced_integration);
  EXPECT_EQ(m.nodes[static_cast<std::size_t>(m.beams[0].node_m)].id, 2);
  const fem::SectionProperties& pipe = m.sections[static_cast<std::size_t>(m.beams[0].section)].properties;
  const double ro = 0.11, ri = 0.10;
  EXPECT_NEAR(pipe.area, kPi * (ro * ro - ri * ri), 1e-12 * pipe.area);
  EXPECT_NEAR(pipe.i11, kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4, 1e-12 * pipe.i11);
  EXPECT_NEAR(pipe.torsion_constant, kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 2, 1e-12 * pipe.torsion_constant);
  const fem::SectionProperties& box = m.sections[static_cast<std::size_t>(m.beams[1].section)].properties;
  const double a = 0.1, b = 0.2, t = 0.01;
  EXPECT_NEAR(box.area, a * b - (a - 2 * t) * (b - 2 * t), 1e-12 * box.area);
  EXPECT_NEAR(box.i11, (a * b * b * b - (a - 2 * t) * std::pow(b - 2 * t, 3)) / 12, 1e-12 * box.i11);
  EXPECT_NEAR(box.i22, (b * a * a * a - (b - 2 * t) * std::pow(a - 2 * t, 3)) / 12, 1e-12 * box.i22);
  const double am = (a - t) * (b - t);
  EXPECT_NEAR(box.torsion_constant, 4 * am * am * t / (2 * (a - t) + 2 * (b - t)), 1e-12 * box.torsion_constant);
}

void expect_input_error(const std::string& deck, const std::string& fragment) {
  try {
    fem::read_inp_text(deck, "deck.inp", ".");
    ADD_FAILURE() << "no error for a deck that should fail with: " << fragment;
  } catch (const framedyn::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(QuadraticBeam, ReaderRefusesFoldedElementsAndNonlinearSteps) {
  const std::string head =
      "** units: m-N-s\n"
      "*NODE\n1, 0, 0, 0\n2, 0.1, 0, 0\n3, 1, 0, 0\n"
      "*ELEMENT, TYPE=B32, ELSET=E\n1, 1, 2, 3\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n";
  expect_input_error(head + "*BEAM SECTION, ELSET=E, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n",
                     "deck.inp:7: *ELEMENT: expected a valid three-node beam (end, midside, end), found element 1 on nodes 1, 2, 3: its "
                     "midside node is not between the quarter points");
  const std::string good = "** units: m-N-s\n*NODE\n1, 0, 0, 0\n2, 0.5, 0, 0\n3, 1, 0, 0\n*ELEMENT, TYPE=B32, ELSET=E\n1, 1, 2, 3\n"
                           "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n";
  expect_input_error(good + "*BEAM SECTION, ELSET=E, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n*BOUNDARY\n1, 1, 6\n*STEP, NLGEOM\n*STATIC\n*END STEP\n",
                     "deck.inp:15: *STEP: expected a linear step (framedyn is a linear, small-displacement code");
  // A member along z with the default n1 = (0, 0, -1): no section plane.
  expect_input_error("** units: m-N-s\n*NODE\n1, 0, 0, 0\n2, 0, 0, 0.5\n3, 0, 0, 1\n*ELEMENT, TYPE=B32R, ELSET=E\n1, 1, 2, 3\n"
                     "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*BEAM SECTION, ELSET=E, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n",
                     "deck.inp:7: *ELEMENT: expected a valid three-node beam (end, midside, end), found element 1 on nodes 1, 2, 3: "
                     "orientation direction n1 is parallel to the element axis");
  // Zero offsets are the default and accepted; NLGEOM=NO is a linear step.
  EXPECT_NO_THROW(fem::read_inp_text(good + "*BEAM SECTION, ELSET=E, MATERIAL=STEEL, SECTION=RECT, OFFSET1=0\n0.05, 0.1\n*BOUNDARY\n1, 1, 6\n"
                                            "*STEP, NLGEOM=NO\n*STATIC\n*END STEP\n",
                                     "deck.inp", "."));
}

}  // namespace

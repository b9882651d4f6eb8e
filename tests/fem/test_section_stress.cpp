// The stress over the section (fem/section_stress.h, docs/theory/fem.md
// section 20) against hand formulas and tables nobody tuned:
//  - a closed thin-walled box under torque: Bredt-Batho T / (2 A_m t);
//  - solid rectangles under torque: Saint-Venant's tau_max = T / (alpha l s^2)
//    with alpha tabulated (Timoshenko & Goodier, Table 7; Roark Table 10.1);
//  - circle and tube under torque: T r / J; a thin tube against Bredt;
//  - transverse shear: 1.5 V / A for the rectangle, V Q / (I t_w) at the web
//    centre and junctions of an I, zero at its flange tips; the box's webs;
//  - von Mises and the largest principal stress at a point with known N, T, M;
//  - a cantilever under a tip torque and a tip load through the static solver.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fem/beam_section.h"
#include "fem/inp_reader.h"
#include "fem/section_forces.h"
#include "fem/section_stress.h"
#include "fem/static_analysis.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

const fem::SectionPoint& named(const std::vector<fem::SectionPoint>& points, const std::string& name) {
  for (const fem::SectionPoint& p : points)
    if (p.name == name) return p;
  throw std::runtime_error("no section point " + name);
}

fem::SectionForces forces(double n, double vy, double vz, double t, double my, double mz) {
  fem::SectionForces f;
  f.n = n;
  f.vy = vy;
  f.vz = vz;
  f.t = t;
  f.my = my;
  f.mz = mz;
  return f;
}

double shear_at(const fem::SectionProperties& s, const std::string& name, const fem::SectionForces& f) {
  return fem::point_stress(s, named(fem::section_points(s), name), f).shear;
}

// ------------------------------------------------------------------ torsion

// A 4 x 6 in box with 0.25 in walls on the long sides and 0.375 in on the
// short ones: A_m = (4 - 0.25) (6 - 0.375) on the midlines, tau = T / (2 A_m t)
// in each wall, and counter-clockwise for a positive T. Round-off only.
TEST(ClosedThinWalledBox, TorqueGivesBredtBathoShearTOver2AmTInEveryWall) {
  const double a = 4.0, b = 6.0, tw = 0.25, tf = 0.375, torque = 1.0e4;  // in, lbf in (any consistent units)
  const fem::SectionProperties s = fem::box_section(a, b, tw, tf, tw, tf);
  const double am = (a - tw) * (b - tf);
  const fem::SectionForces f = forces(0, 0, 0, torque, 0, 0);
  const std::vector<fem::SectionPoint> pts = fem::section_points(s);
  ASSERT_EQ(pts.size(), 8u);
  EXPECT_LT(rel(shear_at(s, "mid-side +1", f), torque / (2 * am * tw)), 1e-13);
  EXPECT_LT(rel(shear_at(s, "mid-side -1", f), torque / (2 * am * tw)), 1e-13);
  EXPECT_LT(rel(shear_at(s, "mid-side +2", f), torque / (2 * am * tf)), 1e-13);
  EXPECT_LT(rel(shear_at(s, "mid-side -2", f), torque / (2 * am * tf)), 1e-13);
  // A corner is reported in its thinner wall: the larger stress.
  EXPECT_LT(rel(shear_at(s, "corner +1+2", f), torque / (2 * am * tw)), 1e-13);
  // Counter-clockwise: up the +1 wall, along -1 on the +2 wall.
  EXPECT_GT(named(pts, "mid-side +1").shear_per_torque.y(), 0.0);
  EXPECT_LT(named(pts, "mid-side +2").shear_per_torque.x(), 0.0);
}

// Saint-Venant: tau_max = T / (alpha l s^2) at the middle of the long sides,
// alpha from the three-figure tables (l/s = 1: 0.208, 2: 0.246, 10: 0.312);
// the tables round to 0.0005, so the series must land within 0.0006 of them.
// The square's short and long sides carry the same stress; the corners none.
TEST(SolidRectangle, TorqueGivesSaintVenantTauMaxOfTheTabulatedAlpha) {
  const double s_side = 0.02, torque = 50.0;  // m, N m
  for (const auto& [ratio, alpha] : {std::pair{1.0, 0.208}, {2.0, 0.246}, {10.0, 0.312}}) {
    const double l = ratio * s_side;
    const fem::SectionProperties s = fem::rectangle_section(l, s_side, 0.3);  // long side along 1
    const fem::SectionForces f = forces(0, 0, 0, torque, 0, 0);
    const double tau_max = shear_at(s, "mid-side +2", f);  // the middle of a long side (x2 = +-s/2)
    const double alpha_series = torque / (tau_max * l * s_side * s_side);
    std::printf("l/s = %g: alpha = %.5f (table %.3f); short side's middle %.4f tau_max\n", ratio, alpha_series, alpha,
                shear_at(s, "mid-side +1", f) / tau_max);
    EXPECT_NEAR(alpha_series, alpha, 6e-4) << ratio;
    EXPECT_EQ(shear_at(s, "corner +1+2", f), 0.0);
    // The same section turned (long side along 2) has the same largest stress, now on the sides x1 = +-a/2.
    const fem::SectionProperties turned = fem::rectangle_section(s_side, l, 0.3);
    EXPECT_LT(rel(shear_at(turned, "mid-side +1", f), tau_max), 1e-13);
  }
  const fem::SectionProperties square = fem::rectangle_section(0.03, 0.03, 0.3);
  const fem::SectionForces f = forces(0, 0, 0, torque, 0, 0);
  EXPECT_LT(rel(shear_at(square, "mid-side +1", f), shear_at(square, "mid-side +2", f)), 1e-12);
}

// Circle and tube: tau = T r / J on the outer surface, the same at all eight
// points; a thin tube (t / r_m = 1/19.5) against Bredt, T / (2 pi r_m^2 t),
// which differs from the exact value by less than t / r_m.
TEST(RoundSections, TorqueGivesTROverJAtEveryPoint) {
  const double r = 0.03, torque = 120.0;
  const fem::SectionForces f = forces(0, 0, 0, torque, 0, 0);
  const fem::SectionProperties circ = fem::circle_section(r, 0.3);
  for (const fem::SectionPoint& p : fem::section_points(circ))
    EXPECT_LT(rel(fem::point_stress(circ, p, f).shear, torque * r / (kPi * r * r * r * r / 2)), 1e-13) << p.name;
  const double ro = 0.05, wall = 0.0025, rm = ro - wall / 2;
  const fem::SectionProperties pipe = fem::pipe_section(ro, wall, 0.3);
  const double j = kPi * (std::pow(ro, 4) - std::pow(ro - wall, 4)) / 2;
  for (const fem::SectionPoint& p : fem::section_points(pipe))
    EXPECT_LT(rel(fem::point_stress(pipe, p, f).shear, torque * ro / j), 1e-13) << p.name;
  const double bredt = torque / (2 * kPi * rm * rm * wall);
  std::printf("thin tube t/r_m = %.4f: T r_o / J over Bredt %.4f\n", wall / rm, (torque * ro / j) / bredt);
  EXPECT_LT(rel(torque * ro / j, bredt), wall / rm);
}

// ---------------------------------------------------------- transverse shear

// Rectangle: tau = 1.5 V / A at the neutral axis, zero at the faces.
TEST(SolidRectangle, TransverseShearIsParabolicWithPeak1Point5VOverA) {
  const double a = 0.04, b = 0.1, v = 3000.0;
  const fem::SectionProperties s = fem::rectangle_section(a, b, 0.3);
  const fem::SectionForces along2 = forces(0, 0, v, 0, 0, 0), along1 = forces(0, v, 0, 0, 0, 0);
  EXPECT_LT(rel(shear_at(s, "mid-side +1", along2), 1.5 * v / (a * b)), 1e-13);
  EXPECT_EQ(shear_at(s, "mid-side +2", along2), 0.0);
  EXPECT_EQ(shear_at(s, "corner +1+2", along2), 0.0);
  EXPECT_LT(rel(shear_at(s, "mid-side -2", along1), 1.5 * v / (a * b)), 1e-13);
  // Circle 4 V / (3 A), thin-walled tube 2 V / A, at the neutral axis.
  const fem::SectionProperties circ = fem::circle_section(0.02, 0.3);
  EXPECT_LT(rel(shear_at(circ, "angle 0", along2), 4 * v / (3 * kPi * 0.02 * 0.02)), 1e-13);
  EXPECT_LT(rel(shear_at(circ, "angle 90", along1), 4 * v / (3 * kPi * 0.02 * 0.02)), 1e-13);
  const fem::SectionProperties pipe = fem::pipe_section(0.05, 0.003, 0.3);
  EXPECT_LT(rel(shear_at(pipe, "angle 180", along2), 2 * v / pipe.area), 1e-13);
  EXPECT_NEAR(shear_at(pipe, "angle 90", along2), 0.0, 1e-9 * v / pipe.area);
}

// An IPE 300-like I (h 300, b 150, t_f 10.7, t_w 7.1 mm) under V along 2:
// Gere's V Q / (I t_w) with Q = b t_f (h - t_f)/2 at the junction and
// + t_w (h/2 - t_f)^2 / 2 at the web centre; zero at the flange tips.
TEST(ISection, TransverseShearFollowsVQOverIt) {
  const double h = 0.3, b = 0.15, tf = 0.0107, tw = 0.0071, v = 1.0e5;
  const fem::SectionProperties s = fem::i_section(h, b, b, tf, tf, tw);
  const double i = b * h * h * h / 12 - (b - tw) * std::pow(h - 2 * tf, 3) / 12;
  ASSERT_LT(rel(s.i11, i), 1e-12);
  const fem::SectionForces f = forces(0, 0, v, 0, 0, 0);
  const double q_flange = b * tf * (h - tf) / 2, q_centre = q_flange + tw * (h / 2 - tf) * (h / 2 - tf) / 2;
  std::printf("I web centre %.4g MPa (V / A_web %.4g MPa)\n", shear_at(s, "web centre", f) / 1e6, v / (tw * (h - 2 * tf)) / 1e6);
  EXPECT_LT(rel(shear_at(s, "web centre", f), v * q_centre / (i * tw)), 1e-12);
  EXPECT_LT(rel(shear_at(s, "top flange-web junction", f), v * q_flange / (i * tw)), 1e-12);
  EXPECT_LT(rel(shear_at(s, "bottom flange-web junction", f), v * q_flange / (i * tw)), 1e-12);
  for (const char* tip : {"top flange tip +1", "top flange tip -1", "bottom flange tip +1", "bottom flange tip -1"}) EXPECT_EQ(shear_at(s, tip, f), 0.0) << tip;
  // Open walls under torque: T t / J on the wall faces (the flange tips T t_f / J, the web T t_w / J).
  const fem::SectionForces torque = forces(0, 0, 0, 40.0, 0, 0);
  EXPECT_LT(rel(shear_at(s, "top flange tip +1", torque), 40.0 * tf / s.torsion_constant), 1e-13);
  EXPECT_LT(rel(shear_at(s, "web centre", torque), 40.0 * tw / s.torsion_constant), 1e-13);
  // Both at once: on one face of the web they add (Eq. 20.9).
  EXPECT_LT(rel(shear_at(s, "web centre", forces(0, 0, v, 40.0, 0, 0)), v * q_centre / (i * tw) + 40.0 * tw / s.torsion_constant), 1e-12);
}

// A channel (h 200, b 75, t_f 11.4, t_w 8.5 mm) under V along 2: the same
// V Q / (I t_w) at the web centre, Q of a flange b t_f (h - t_f)/2 and the
// half web; the flange tips carry none (the shear-centre offset is not modelled).
TEST(ChannelSection, TransverseShearAtTheWebCentreIsVQOverIt) {
  const double h = 0.2, b = 0.075, tf = 0.0114, tw = 0.0085, v = 5.0e4;
  const fem::SectionProperties s = fem::channel_section(h, b, tf, tw);
  const double i = b * h * h * h / 12 - (b - tw) * std::pow(h - 2 * tf, 3) / 12;
  const fem::SectionForces f = forces(0, 0, v, 0, 0, 0);
  const double q = b * tf * (h - tf) / 2 + tw * (h / 2 - tf) * (h / 2 - tf) / 2;
  EXPECT_LT(rel(shear_at(s, "web centre", f), v * q / (i * tw)), 1e-12);
  EXPECT_EQ(shear_at(s, "flange tip +2", f), 0.0);
  EXPECT_EQ(shear_at(s, "flange tip -2", f), 0.0);
}

// The box's webs under V along 2 (symmetric box): the closed cell's flow is
// zero on the axis of symmetry, so at the neutral axis tau = V Q / (I 2 t)
// with Q the midline half-section's first moment; the flanges' middles carry none.
TEST(ClosedThinWalledBox, ShearForceGivesVQOverI2tInTheWebs) {
  const double a = 0.1, b = 0.2, t = 0.006, v = 2.0e4;
  const fem::SectionProperties s = fem::box_section(a, b, t, t, t, t);
  const double w = a - t, hh = b - t;  // midline widths
  const double q = t * w * hh / 2 + 2 * t * (hh / 2) * (hh / 4);  // the flange (w t at hh/2) and two half webs above the axis
  const fem::SectionForces f = forces(0, 0, v, 0, 0, 0);
  EXPECT_LT(rel(shear_at(s, "mid-side +1", f), v * q / (s.i11 * 2 * t)), 1e-12);
  EXPECT_LT(rel(shear_at(s, "mid-side -1", f), shear_at(s, "mid-side +1", f)), 1e-12);
  EXPECT_NEAR(shear_at(s, "mid-side +2", f), 0.0, 1e-9 * v / s.area);
  // Along the webs in the direction of V.
  EXPECT_GT(fem::point_stress(s, named(fem::section_points(s), "mid-side +1"), f).shear, 0.0);
  EXPECT_GT(named(fem::section_points(s), "mid-side +1").shear_per_vz.y(), 0.0);
  EXPECT_GT(named(fem::section_points(s), "mid-side -1").shear_per_vz.y(), 0.0);
}

// ---------------------------------------------------------- combined stress

// A 20 mm radius bar with N = 10 kN, My = 200 N m, T = 150 N m: at the top
// point (x2 = r) sigma = N/A + My r / I11, tau = T r / J;
// von Mises sqrt(sigma^2 + 3 tau^2), principal sigma/2 + sqrt(sigma^2/4 + tau^2).
TEST(CombinedStress, VonMisesAndPrincipalStressAtAPointWithKnownNTM) {
  const double r = 0.02, n = 1.0e4, my = 200.0, t = 150.0;
  const fem::SectionProperties s = fem::circle_section(r, 0.3);
  const double area = kPi * r * r, i = kPi * std::pow(r, 4) / 4, j = 2 * i;
  const double sigma = n / area + my * r / i, tau = t * r / j;  // 7.96 + 31.83 MPa, 11.94 MPa
  const fem::PointStress p = fem::point_stress(s, named(fem::section_points(s), "angle 90"), forces(n, 0, 0, t, my, 0));
  EXPECT_LT(rel(p.normal, sigma), 1e-13);
  EXPECT_LT(rel(p.shear, tau), 1e-13);
  EXPECT_LT(rel(p.von_mises, std::sqrt(sigma * sigma + 3 * tau * tau)), 1e-13);
  EXPECT_LT(rel(p.max_principal, sigma / 2 + std::sqrt(sigma * sigma / 4 + tau * tau)), 1e-13);
  // Pure shear: von Mises sqrt(3) tau, principal tau; pure compression: |sigma| and 0.
  EXPECT_LT(rel(fem::combine_stresses(0.0, 5.0).von_mises, std::sqrt(3.0) * 5.0), 1e-15);
  EXPECT_EQ(fem::combine_stresses(0.0, 5.0).max_principal, 5.0);
  EXPECT_EQ(fem::combine_stresses(-7.0, 0.0).von_mises, 7.0);
  EXPECT_EQ(fem::combine_stresses(-7.0, 0.0).max_principal, 0.0);
}

// A steel box cantilever along X (L = 2 m, n1 = +Y so local 2 = +Z) under a
// tip load P along +Z and a tip torque T about +X, through the static solver
// (4 B31 elements): at the root My = -P L, Vz = P, T. The root's section
// points against hand values: flanges sigma = -+P L (b/2) / I11 with Bredt's
// T / (2 A_m t); webs sigma = 0 with Bredt's +- V Q / (I 2t). Exact for a
// cantilever at every mesh (nodal forces), so round-off only.
TEST(SectionStressThroughTheSolver, BoxCantileverUnderTipTorqueAndLoadHasHandStressesAtTheRoot) {
  const double L = 2.0, a = 0.1, b = 0.15, t = 0.005, P = 5.0e3, T = 2.0e3;
  std::string deck = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= 4; ++i) deck += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, L * i / 4);
  deck += "*ELEMENT, TYPE=B31, ELSET=BEAM\n";
  for (int i = 1; i <= 4; ++i) deck += fmt::format("{}, {}, {}\n", i, i, i + 1);
  deck += fmt::format("*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=BOX\n{}, {}, {}, {}, {}, {}\n0, 1, 0\n", a, b, t, t, t, t);
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n*BOUNDARY\n1, ENCASTRE\n";
  deck += fmt::format("*STEP\n*STATIC\n*CLOAD\n5, 3, {}\n5, 4, {}\n*END STEP\n", P, T);
  const fem::FrameModel m = fem::read_inp_text(deck, "box.inp", ".");
  const fem::StaticResult r = fem::solve_static(m);
  const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
  const fem::SectionForces& root = st[0].forces;
  ASSERT_LT(rel(root.my, -P * L), 1e-10);
  ASSERT_LT(rel(root.vz, P), 1e-10);
  ASSERT_LT(rel(root.t, T), 1e-10);
  const fem::SectionProperties& s = m.sections[0].properties;
  const std::vector<fem::SectionPoint> pts = fem::section_points(s);
  const double am = (a - t) * (b - t), bredt = T / (2 * am * t);
  const double w = a - t, hh = b - t, web = P * (t * w * hh / 2 + t * hh * hh / 4) / (s.i11 * 2 * t);
  const double flange_sigma = P * L * (b / 2) / s.i11;
  const fem::PointStress top = fem::point_stress(s, named(pts, "mid-side +2"), root);
  const fem::PointStress plus1 = fem::point_stress(s, named(pts, "mid-side +1"), root);
  const fem::PointStress minus1 = fem::point_stress(s, named(pts, "mid-side -1"), root);
  std::printf("root: top flange sigma %.4g MPa tau %.4g MPa; webs tau %.4g and %.4g MPa\n", top.normal / 1e6, top.shear / 1e6, plus1.shear / 1e6,
              minus1.shear / 1e6);
  EXPECT_LT(rel(top.normal, -flange_sigma), 1e-9);  // the load bends the tip up: the top is in compression
  EXPECT_LT(rel(fem::point_stress(s, named(pts, "mid-side -2"), root).normal, flange_sigma), 1e-9);
  EXPECT_LT(rel(top.shear, bredt), 1e-9);
  EXPECT_LT(rel(top.von_mises, std::sqrt(flange_sigma * flange_sigma + 3 * bredt * bredt)), 1e-9);
  EXPECT_NEAR(plus1.normal, 0.0, 1e-9 * flange_sigma);
  // Torsion runs up the +1 web and down the -1 web; the shear force's flow runs up both.
  EXPECT_LT(rel(plus1.shear, bredt + web), 1e-9);
  EXPECT_LT(rel(minus1.shear, std::abs(bredt - web)), 1e-9);
  EXPECT_LT(rel(fem::point_stress(s, named(pts, "corner +1+2"), root).normal, -flange_sigma), 1e-9);
}

}  // namespace

// Line loads (*DLOAD) and member-end releases (*RELEASE) on three-node beams
// (B32, B32R) against closed forms (Roark; any strength-of-materials text),
// w the load per length, L the span:
//   cantilever:              root shear w L, root moment w L^2/2, and at the
//                            middle M = w (L/2)^2 / 2 (statics: exact on any mesh);
//   clamped-clamped:         end moments w L^2/12, midspan w L^2/24;
//   propped cantilever:      the propped end's reaction 3 w L/8, root moment w L^2/8;
//   gravity on a frame:      the reactions carry the weight rho A g (total length);
//   radial load on an arc:   the resultant of P2 (along t x n1) over a quarter
//                            circle of radius R is q R (1, 1) inwards, exactly,
//                            whatever the elements' approximation of the circle
//                            (n2 ds = dx x n1 integrates to the chord x n1).
// The meshes are read from .inp text, so the reader's *DLOAD and *RELEASE on
// three-node beams, the consistent loads and the recovery are checked together.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fem/frame_model.h"
#include "fem/inp_reader.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;

const std::string kSteel = "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n";

// A straight span along X of `elements` three-node elements of TYPE=`type`
// (midside nodes at the middle), nodes 1..2n+1, ELSET=BEAM, NSET TIP = the
// last node, a 0.05 x 0.1 steel rectangle with n1 = (0, 0, -1), and `extra`.
std::string span_deck(const std::string& type, double length, int elements, const std::string& extra) {
  std::string s = "** units: m-N-s\n*NODE\n";
  for (int i = 0; i <= 2 * elements; ++i) s += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, length * i / (2 * elements));
  s += "*ELEMENT, TYPE=" + type + ", ELSET=BEAM\n";
  for (int e = 1; e <= elements; ++e) s += fmt::format("{}, {}, {}, {}\n", e, 2 * e - 1, 2 * e, 2 * e + 1);
  s += fmt::format("*NSET, NSET=TIP\n{}\n", 2 * elements + 1);
  return s + kSteel + "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 0, -1\n" + extra;
}

fem::FrameModel read(const std::string& text) { return fem::read_inp_text(text, "beam.inp", "."); }

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The recovered section forces of element `element` (1-based) at its station `station` of `per_element`.
fem::SectionForces at(const std::vector<fem::StationResult>& st, int element, int station, int per_element) {
  return st.at(static_cast<std::size_t>((element - 1) * per_element + station)).forces;
}

// A cantilever is statically determinate: the element's nodal forces K u - p
// at its nodes follow from equilibrium alone, so the recovered root shear and
// moment and the moment at the middle are exact (round-off) on any mesh, and
// the load along local -n1 (PZ with n1 = -Z) bends about n2 (Mz).
TEST(QuadraticBeamLoads, CantileverUnderUniformLoadHasRootMomentWL2Over2) {
  const double L = 2.0, w = 1500.0;
  for (const char* type : {"B32", "B32R"})
    for (int n : {1, 2, 4}) {
      const fem::FrameModel m = read(span_deck(type, L, n, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\nBEAM, PZ, {}\n", w)));
      const fem::StaticResult r = fem::solve_static(m);
      // Reactions R = K u - f: round-off of the order of cond(K) eps (K's entries span EA/h to E I/h).
      EXPECT_LT(rel(-r.reaction(2), w * L), 1e-10) << type << " " << n;
      EXPECT_LT(rel(r.reaction(4), w * L * L / 2), 1e-10) << type << " " << n;  // the support turns it back about +Y
      const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 5);
      const fem::SectionForces root = at(st, 1, 0, 5), tip = at(st, n, 4, 5);
      std::printf("%s, %d elements: root M %.3e, root V %.3e (relative errors)\n", type, n, rel(std::abs(root.mz), w * L * L / 2),
                  rel(std::abs(root.vy), w * L));
      EXPECT_LT(rel(std::abs(root.mz), w * L * L / 2), 1e-10) << type << " " << n;
      EXPECT_LT(rel(std::abs(root.vy), w * L), 1e-10) << type << " " << n;
      EXPECT_NEAR(tip.mz, 0.0, 1e-10 * w * L * L);
      // Every station of every element: M(x) = w (L - x)^2 / 2 for the free part beyond the cut.
      for (const fem::StationResult& s : st) {
        const double free = L - s.point.x();
        EXPECT_NEAR(std::abs(s.forces.mz), w * free * free / 2, 1e-10 * w * L * L) << type << " " << n << " x = " << s.point.x();
      }
    }
}

// GRAV and P1 on a cantilever give the same as the equal PZ: the weight rho A g
// along -Z, P1 along n1 = -Z.
TEST(QuadraticBeamLoads, GravityAndP1OnACantileverEqualTheEquivalentGlobalLoad) {
  const double L = 2.0, g = 9.81, w = 7850 * 0.05 * 0.1 * g;
  for (const char* type : {"B32", "B32R"}) {
    const fem::StaticResult pz = fem::solve_static(read(span_deck(type, L, 2, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\nBEAM, PZ, {:.17g}\n", -w))));
    const fem::StaticResult grav = fem::solve_static(read(span_deck(type, L, 2, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\n, GRAV, {}, 0, 0, -1\n", g))));
    const fem::StaticResult p1 = fem::solve_static(read(span_deck(type, L, 2, fmt::format("*BOUNDARY\n1, ENCASTRE\n*DLOAD\nBEAM, P1, {:.17g}\n", w))));
    EXPECT_LT(rel(grav.reaction(2), w * L), 1e-10) << type;
    EXPECT_LT((grav.displacement - pz.displacement).norm(), 1e-12 * pz.displacement.norm()) << type;
    EXPECT_LT((p1.displacement - pz.displacement).norm(), 1e-12 * pz.displacement.norm()) << type;
  }
}

// A clamped-clamped span: the end moment is the redundant, found by the
// elements' stiffness (the moments elsewhere follow by statics). Measured:
// B32R gives w L^2/12 to round-off on 2 and 4 elements, because with 2-point
// integration the element is nodally exact for a Timoshenko beam under a
// uniform load (its bending strain is linear and the 2-point rule integrates
// M kappa exactly); B32 with the 3-point rule locks in shear, but here
// symmetrically in every element, so the redundant comes out the same
// (compatibility: the integral of M/EI over the span vanishes).
TEST(QuadraticBeamLoads, ClampedClampedUniformLoadHasEndMomentsWL2Over12AndMidspanWL2Over24) {
  const double L = 3.0, w = 2500.0;
  for (const char* type : {"B32", "B32R"})
    for (int n : {2, 4}) {
      const fem::FrameModel m =
          read(span_deck(type, L, n, fmt::format("*BOUNDARY\n1, ENCASTRE\nTIP, ENCASTRE\n*DLOAD\nBEAM, PZ, {}\n", w)));
      const fem::StaticResult r = fem::solve_static(m);
      const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
      const double end = at(st, 1, 0, 3).mz, mid = at(st, n / 2, 2, 3).mz, far = at(st, n, 2, 3).mz;
      std::printf("%s, %d elements: end moment %.3e, midspan %.3e, far end %.3e (relative errors)\n", type, n, rel(std::abs(end), w * L * L / 12),
                  rel(std::abs(mid), w * L * L / 24), rel(std::abs(far), w * L * L / 12));
      EXPECT_LT(rel(std::abs(end), w * L * L / 12), 1e-9) << type << " " << n;
      EXPECT_LT(rel(std::abs(far), w * L * L / 12), 1e-9) << type << " " << n;
      EXPECT_LT(rel(std::abs(mid), w * L * L / 24), 1e-9) << type << " " << n;
      EXPECT_LT(end * mid, 0.0) << "hogging at the ends, sagging at the middle";
      EXPECT_LT(rel(r.reaction(4), w * L * L / 12), 1e-9) << type << " " << n;
    }
}

// A propped cantilever: both end nodes clamped, the last element's end S2
// released in bending about n2 (M2), so that end is a pin. The redundant
// (the prop's reaction) depends on the shear flexibility: with
// phi = E I / (G As L^2), compatibility of the tip deflection gives
//   R = w L (1/8 + phi/2) / (1/3 + phi)   (3 w L/8 for phi = 0),
// the clamp's reaction w L - R and moment w L^2/2 - R L.
// B32R is nodally exact for a uniform load (its 2-point rule integrates the
// linear bending and shear strains' energy exactly), so it gives R to
// round-off on 2 and 4 elements. B32's 3-point rule enforces zero shear
// strain at three points of a slender element: theta = w' there, so the
// curvature is constant per element (the element behaves as a C1 quadratic
// Kirchhoff element; one element under a tip load gives 3/4 of P L^3/3EI)
// and the redundant converges at least as h^2: its error falls by a factor of
// at least 4 per halving of the elements (measured 2.18e-2, 4.95e-3, 1.03e-3
// on 2, 4, 8 elements: factors 4.4 and 4.8, the locking easing as h / depth falls).
TEST(QuadraticBeamLoads, ProppedCantileverByAReleaseHasReaction3WLOver8) {
  const double L = 3.0, w = 2500.0;
  for (const char* type : {"B32", "B32R"}) {
    std::vector<double> errors;
    for (int n : {2, 4, 8}) {
      const fem::FrameModel m = read(span_deck(
          type, L, n, fmt::format("*BOUNDARY\n1, ENCASTRE\nTIP, ENCASTRE\n*RELEASE\n{}, S2, M2\n*DLOAD\nBEAM, PZ, {}\n", n, w)));
      // Load along n1: shear along n1 (As1), bending about n2 (I22).
      const fem::SectionProperties& sec = m.sections[0].properties;
      const double phi = m.sections[0].material.youngs_modulus * sec.i22 / (m.sections[0].material.shear_modulus * sec.shear_area_1 * L * L);
      const double prop = w * L * (1.0 / 8 + phi / 2) / (1.0 / 3 + phi);
      const fem::StaticResult r = fem::solve_static(m);
      const int tip = 6 * 2 * n;
      const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
      const double e_prop = rel(-r.reaction(tip + 2), prop), e_clamp = rel(-r.reaction(2), w * L - prop),
                   e_moment = rel(std::abs(at(st, 1, 0, 3).mz), w * L * L / 2 - prop * L);
      std::printf("%s, %d elements: phi %.3e, prop %.6f of 3wL/8; errors: prop %.3e, clamp reaction %.3e, clamp moment %.3e\n", type, n, phi,
                  prop / (3 * w * L / 8), e_prop, e_clamp, e_moment);
      errors.push_back(e_prop);
      if (std::string(type) == "B32R") {
        EXPECT_LT(e_prop, 1e-10) << n;
        EXPECT_LT(e_clamp, 1e-10) << n;
        EXPECT_LT(e_moment, 1e-10) << n;
      }
      EXPECT_NEAR(r.reaction(tip + 4), 0.0, 1e-9 * w * L * L) << "the released end carries no moment";
      EXPECT_NEAR(at(st, n, 2, 3).mz, 0.0, 1e-9 * w * L * L) << "the released end carries no moment";
      // The recovery is in equilibrium with the reactions whatever the discretisation error.
      EXPECT_NEAR(std::abs(at(st, 1, 0, 3).mz), std::abs(r.reaction(4)), 1e-10 * w * L * L);
    }
    if (std::string(type) == "B32") {
      EXPECT_LT(errors[0], 0.025) << "2 elements";
      for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_GT(errors[k - 1] / errors[k], 4.0) << "at least second order in h";
    }
  }
}

// GRAV on a portal frame of B32 elements (columns of height H at X = 0 and W,
// a beam across their tops, two elements per member, bases clamped): the
// vertical reactions sum to the weight rho A g (2 H + W) = 3,850.4 N, the
// horizontal ones to zero, and their moment about the Y axis balances the
// weight's (rho A g (H W + W^2/2)).
TEST(QuadraticBeamLoads, GravityOnABeamFrameIsItsHandComputedWeightInTheReactions) {
  const double H = 3.0, W = 4.0, g = 9.81, wpl = 7850 * 0.05 * 0.1 * g;
  const std::string deck =
      "** units: m-N-s\n*NODE\n1, 0, 0, 0\n2, 0, 0, 0.75\n3, 0, 0, 1.5\n4, 0, 0, 2.25\n5, 0, 0, 3\n"
      "6, 1, 0, 3\n7, 2, 0, 3\n8, 3, 0, 3\n9, 4, 0, 3\n10, 4, 0, 2.25\n11, 4, 0, 1.5\n12, 4, 0, 0.75\n13, 4, 0, 0\n"
      "*ELEMENT, TYPE=B32, ELSET=FRAME\n1, 1, 2, 3\n2, 3, 4, 5\n3, 5, 6, 7\n4, 7, 8, 9\n5, 9, 10, 11\n6, 11, 12, 13\n" +
      kSteel + "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 1, 0\n*BOUNDARY\n1, ENCASTRE\n13, ENCASTRE\n"
      "*STEP\n*STATIC\n*DLOAD\nFRAME, GRAV, 9.81, 0, 0, -1\n*END STEP\n";
  const fem::FrameModel m = read(deck);
  const fem::StaticResult r = fem::solve_static(m);
  const double weight = wpl * (2 * H + W);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (int node : {0, 12}) {
    const Eigen::Vector3d f = r.reaction.segment<3>(6 * node), mm = r.reaction.segment<3>(6 * node + 3);
    force += f;
    moment += mm + m.nodes[static_cast<std::size_t>(node)].position.cross(f);
  }
  std::printf("portal frame: reactions %.6f N against the weight %.6f N\n", force.z(), weight);
  EXPECT_NEAR(weight, 3850.425, 1e-3);  // the hand value in the comment
  EXPECT_LT(rel(force.z(), weight), 1e-12);
  EXPECT_NEAR(force.x(), 0.0, 1e-12 * weight);
  EXPECT_NEAR(force.y(), 0.0, 1e-12 * weight);
  EXPECT_LT(rel(moment.y(), -wpl * (H * W + W * W / 2)), 1e-12);
}

// A quarter circle of radius R (one clamped end, 2 and 4 curved elements
// whose nodes lie on the circle) under P2 = q: n1 = -Z, so n2 = t x n1 points
// to the centre and turns along each element. The resultant q R (1, 1)
// towards the centre is exact on any such mesh; the support holds it, and the
// recovered section forces at the clamp equal the reactions there.
TEST(QuadraticBeamLoads, RadialP2OnAQuarterCircleHasTheResultantQRTimesRoot2) {
  const double R = 2.0, q = 800.0;
  for (const char* type : {"B32", "B32R"})
    for (int n : {2, 4}) {
      std::string deck = "** units: m-N-s\n*NODE\n";
      for (int i = 0; i <= 2 * n; ++i) {
        const double th = 0.5 * kPi * i / (2 * n);
        deck += fmt::format("{}, {:.17g}, {:.17g}, 0\n", i + 1, R * std::cos(th), R * std::sin(th));
      }
      deck += "*ELEMENT, TYPE=" + std::string(type) + ", ELSET=ARC\n";
      for (int e = 1; e <= n; ++e) deck += fmt::format("{}, {}, {}, {}\n", e, 2 * e - 1, 2 * e, 2 * e + 1);
      deck += kSteel + "*BEAM SECTION, ELSET=ARC, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 0, -1\n*BOUNDARY\n1, ENCASTRE\n" +
              fmt::format("*DLOAD\nARC, P2, {}\n", q);
      const fem::FrameModel m = read(deck);
      const fem::StaticResult r = fem::solve_static(m);
      const Eigen::Vector3d reaction = r.reaction.segment<3>(0);
      std::printf("%s, %d elements: arc reaction (%.12g, %.12g, %.3g) against q R = %.12g\n", type, n, reaction.x(), reaction.y(), reaction.z(), q * R);
      EXPECT_LT((reaction - Eigen::Vector3d(q * R, q * R, 0.0)).norm(), 1e-10 * q * R) << type << " " << n;
      // The clamp's section forces (station 0) are the reactions there, seen in
      // the element's local axes at its end: equal in magnitude.
      const std::vector<fem::StationResult> st = fem::recover_stations(m, r.displacement, 3);
      const fem::SectionForces root = at(st, 1, 0, 3);
      EXPECT_NEAR(Eigen::Vector3d(root.n, root.vy, root.vz).norm(), reaction.norm(), 1e-10 * q * R);
      EXPECT_NEAR(Eigen::Vector3d(root.t, root.my, root.mz).norm(), r.reaction.segment<3>(3).norm(), 1e-10 * q * R * R);
    }
}

}  // namespace

// The stress state over a beam's cross-section: at a set of points of each
// section shape, the normal stress from N, My, Mz (as fem/section_forces'
// fibers) and the shear stress from the torque T and the shear forces Vy, Vz,
// then von Mises and the largest principal stress. Theory:
// docs/theory/fem.md section 20, Eqs. (20.1)-(20.9).
//
// Section axes and signs as fem/beam_section.h and fem/section_forces.h:
// (1, 2, t) right-handed, Vy along 1, Vz along 2, T about t, stresses on the
// positive face of the cut. A shear stress is a vector (tau_1, tau_2) in the
// section's plane; a positive T turns it counter-clockwise (from +1 to +2).
//
// Shear from torsion (Eqs. 20.2-20.5): Saint-Venant's series for the solid
// rectangle (largest at the middle of the long sides, the short sides' middle
// from the same series, zero at corners); T r / J for the circle and the tube
// (exact for both, on the outer surface); Bredt-Batho q = T / (2 A_m) on the
// box's wall midlines; T t / J on the faces of the open thin walls of I and
// channel sections. Shear from Vy, Vz (Eqs. 20.6-20.8): tau = V Q / (I b),
// parabolic over the rectangle (1.5 V / A at the neutral axis), 4 V / (3 A)
// on the circle's neutral axis, 2 V / A on the tube's; the thin-walled shear
// flow of the box (the closed cell's constant flow from zero twist), of the
// I (zero at flange tips) and of the channel.
//
// Sections given by constants only (GENERAL) have no points.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "fem/beam_section.h"
#include "fem/section_forces.h"

namespace framedyn::fem {

// A point of the section with the shear stress each unit force gives there.
struct SectionPoint {
  std::string name;                  // e.g. "corner +1+2", "mid-side +2", "web centre", "top flange tip +1"
  Eigen::Vector2d position;          // (x1, x2) from the centroid, m: where the normal stress is taken
  Eigen::Vector2d shear_per_torque = Eigen::Vector2d::Zero();  // (tau_1, tau_2) per unit T, Pa / (N m)
  Eigen::Vector2d shear_per_vy = Eigen::Vector2d::Zero();      // per unit Vy (along 1), Pa / N
  Eigen::Vector2d shear_per_vz = Eigen::Vector2d::Zero();      // per unit Vz (along 2), Pa / N
  // An open thin wall's torsional shear is +-T t / J on its two faces: the
  // point stands for the face where it adds to the shear force's, so
  // |tau| = |tau_V| + |tau_T| (Eq. 20.9); elsewhere |tau_V + tau_T|.
  bool open_wall = false;
};

// The points of a section: corners and mid-sides of RECT and BOX; eight
// points round CIRC and PIPE (outer surface); flange tips, flange centres,
// flange-web junctions (in the web) and web centre of I and CHANNEL (and the
// channel's two back corners); none for GENERAL.
std::vector<SectionPoint> section_points(const SectionProperties& section);

struct PointStress {
  double normal = 0.0;         // sigma, Pa (Eq. 20.1)
  double shear = 0.0;          // |tau|, Pa
  double von_mises = 0.0;      // sqrt(sigma^2 + 3 tau^2), Pa (Eq. 20.10)
  double max_principal = 0.0;  // sigma / 2 + sqrt(sigma^2 / 4 + tau^2), Pa (Eq. 20.11)
};

PointStress point_stress(const SectionProperties& section, const SectionPoint& point, const SectionForces& forces);
// At every point of `points` (from section_points(section)).
std::vector<PointStress> point_stresses(const SectionProperties& section, const std::vector<SectionPoint>& points, const SectionForces& forces);
// The same from sigma and |tau|: von Mises and the largest principal stress.
PointStress combine_stresses(double normal, double shear);

// The signed shear stress at a point (docs/theory/fatigue.md Eq. F.26), the input of a shear fatigue count:
// every unit response of a point (per T, Vy, Vz) acts along the same line, the wall's
// or surface's tangent (shear on a free surface is tangent to it), so the shear is the
// signed component tau . d along the point's direction d: the first non-zero of
// shear_per_torque, shear_per_vy, shear_per_vz, normalised (zero where none is, as at a
// rectangle's corners). An open thin wall's two faces see tau_V + tau_T and tau_V - tau_T;
// elsewhere the two are the same. |face| or |other_face| is PointStress::shear.
Eigen::Vector2d shear_direction(const SectionPoint& point);
struct SignedShear {
  double face = 0.0;        // Pa: tau_V + tau_T along shear_direction
  double other_face = 0.0;  // Pa: tau_V - tau_T on an open wall's other face, else = face
};
SignedShear signed_shear(const SectionPoint& point, const SectionForces& forces);

// Saint-Venant torsion of a solid rectangle: the shear stress at the middle
// of its long sides (the largest) and of its short sides, per unit torque,
// Pa / (N m), from the series of the Prandtl stress function (Eqs. 20.2, 20.3).
struct RectangleTorsionShear {
  double long_side_middle = 0.0;
  double short_side_middle = 0.0;
};
RectangleTorsionShear rectangle_torsion_shear(double a, double b);

}  // namespace framedyn::fem

// Cross-section constants of beam sections, from the shape or given directly.
//
// Local section axes follow Abaqus/CalculiX: 1 is the orientation direction
// n1, 2 is n2 = t x n1 (t the beam axis). I11 = integral of x2^2 dA (bending
// about axis 1, deflection along 2); I22 = integral of x1^2 dA. Shear areas
// A_s1, A_s2 carry shear force along 1 and 2 (Timoshenko; Cowper's factors for
// solid sections, the wall area parallel to the shear for thin-walled ones).
// Torsion: Saint-Venant constant J (series solution for solid rectangles,
// exact for circles and pipes, Bredt's formula for closed thin-walled boxes,
// sum of b t^3 / 3 for open thin-walled I and channel sections).
// See docs/theory/fem.md, section "Sections".
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace framedyn::fem {

struct SectionProperties {
  std::string shape;                  // "RECT", "BOX", "PIPE", "CIRC", "I", "CHANNEL", "GENERAL"
  std::vector<double> dimensions;     // as given, SI (for reports and VTU)
  double area = 0.0;                  // A, m^2
  double i11 = 0.0;                   // m^4, about local 1
  double i22 = 0.0;                   // m^4, about local 2
  double i12 = 0.0;                   // m^4, product (GENERAL sections only)
  double torsion_constant = 0.0;      // J, m^4
  double shear_area_1 = 0.0;          // m^2, shear along local 1
  double shear_area_2 = 0.0;          // m^2, shear along local 2
  // Fibers where normal stress is reported, (x1, x2) from the centroid, m:
  // the corners of rectangular outlines, eight points round circular ones.
  std::vector<Eigen::Vector2d> stress_points;

  double polar_moment() const { return i11 + i22; }
};

// Solid rectangle: a along local 1, b along local 2 (Abaqus RECT: a, b).
SectionProperties rectangle_section(double a, double b, double poisson_ratio);
// Closed thin-walled box (Abaqus BOX: a, b outer widths along 1 and 2; wall
// thicknesses t1 (wall at +x1), t2 (at +x2), t3 (at -x1), t4 (at -x2)).
SectionProperties box_section(double a, double b, double t1, double t2, double t3, double t4);
// Solid circle of radius r (Abaqus CIRC: r).
SectionProperties circle_section(double radius, double poisson_ratio);
// Solid ellipse with semi-axes a along local 1 and b along local 2 (CalculiX's
// two-value CIRC line; docs/theory/fem.md section 23, Eqs. 23.1-23.3):
// A = pi a b, I11 = pi a b^3 / 4, I22 = pi a^3 b / 4, J = pi a^3 b^3 / (a^2 + b^2).
// Shape "CIRC" with dimensions {a, b}; a == b is circle_section(a).
SectionProperties ellipse_section(double a, double b, double poisson_ratio);
// Circular tube (Abaqus PIPE: outer radius r, wall thickness t).
SectionProperties pipe_section(double outer_radius, double wall, double poisson_ratio);
// I section (Abaqus I: l, h, b1, b2, t1, t2, t3; height h along local 2, bottom
// flange b1 x t1, top flange b2 x t2, web t3). The beam axis is placed at the
// section centroid; the offset l is not modelled (see docs/theory/fem.md).
SectionProperties i_section(double h, double b1, double b2, double t1, double t2, double t3);
// Channel, a framedyn extension (CHANNEL: h, b, tf, tw): height h along local 2,
// flanges b x tf, web tw; the web lies at -x1, flanges open towards +x1. Axis
// at the centroid; the shear-centre offset is not modelled.
SectionProperties channel_section(double h, double b, double tf, double tw);
// Constants given directly (Abaqus *BEAM GENERAL SECTION, SECTION=GENERAL:
// A, I11, I12, I22, J). Shear areas are taken equal to A.
SectionProperties general_section(double area, double i11, double i12, double i22, double torsion_constant);

// Saint-Venant torsion constant of a solid a x b rectangle (series solution).
double rectangle_torsion_constant(double a, double b);

}  // namespace framedyn::fem

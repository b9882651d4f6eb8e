// Beam element matrices (Przemieniecki, Theory of Matrix Structural Analysis,
// 1968, ch. 5 and 11). See docs/theory/fem.md.
#include "fem/beam_element.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::fem {

Eigen::Matrix3d beam_local_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& n1_direction) {
  Eigen::Vector3d t = b - a;
  const double length = t.norm();
  if (!(length > 0.0)) throw std::invalid_argument("element has zero length");
  t /= length;
  const double n1_norm = n1_direction.norm();
  if (!(n1_norm > 0.0)) throw std::invalid_argument("orientation direction n1 is zero");
  Eigen::Vector3d n2 = t.cross(n1_direction / n1_norm);
  if (n2.norm() < 1e-6) throw std::invalid_argument("orientation direction n1 is parallel to the element axis");
  n2.normalize();
  const Eigen::Vector3d n1 = n2.cross(t);
  Eigen::Matrix3d r;
  r.row(0) = t.transpose();
  r.row(1) = n1.transpose();
  r.row(2) = n2.transpose();
  return r;
}

namespace {

// Bending block for (deflection, slope) at both ends, slope = d(deflection)/dx.
Eigen::Matrix4d bending_stiffness(double ei, double length, double phi) {
  const double L = length, c = ei / ((1.0 + phi) * L * L * L);
  Eigen::Matrix4d k;
  k << 12, 6 * L, -12, 6 * L,
       6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,
       -12, -6 * L, 12, -6 * L,
       6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L;
  return c * k;
}

Eigen::Matrix4d bending_mass(double rho_a, double rho_i, double length, double phi, bool rotary_inertia) {
  const double L = length, p = phi, d = (1.0 + p) * (1.0 + p);
  const double m11 = 13.0 / 35 + 7.0 / 10 * p + 1.0 / 3 * p * p;
  const double m12 = (11.0 / 210 + 11.0 / 120 * p + 1.0 / 24 * p * p) * L;
  const double m13 = 9.0 / 70 + 3.0 / 10 * p + 1.0 / 6 * p * p;
  const double m14 = -(13.0 / 420 + 3.0 / 40 * p + 1.0 / 24 * p * p) * L;
  const double m22 = (1.0 / 105 + 1.0 / 60 * p + 1.0 / 120 * p * p) * L * L;
  const double m24 = -(1.0 / 140 + 1.0 / 60 * p + 1.0 / 120 * p * p) * L * L;
  Eigen::Matrix4d m;
  m << m11, m12, m13, m14,
       m12, m22, -m14, m24,
       m13, -m14, m11, -m12,
       m14, m24, -m12, m22;
  m *= rho_a * L / d;
  if (rotary_inertia) {
    const double r11 = 6.0 / 5, r12 = (1.0 / 10 - 1.0 / 2 * p) * L;
    const double r22 = (2.0 / 15 + 1.0 / 6 * p + 1.0 / 3 * p * p) * L * L;
    const double r24 = (-1.0 / 30 - 1.0 / 6 * p + 1.0 / 6 * p * p) * L * L;
    Eigen::Matrix4d r;
    r << r11, r12, -r11, r12,
         r12, r22, -r12, r24,
         -r11, -r12, r11, -r12,
         r12, r24, -r12, r22;
    m += rho_i / (d * L) * r;
  }
  return m;
}

double shear_parameter(const BeamElementData& e, double i, double shear_area) {
  if (e.theory == BeamTheory::euler_bernoulli) return 0.0;
  if (!(shear_area > 0.0) || !(e.shear_modulus > 0.0)) return 0.0;
  return 12.0 * e.youngs_modulus * i / (e.shear_modulus * shear_area * e.length * e.length);
}

// Local DOF indices of the two bending planes: deflection v with slope
// theta_z (plane x-y, bending about n2, I22), and deflection w with slope
// -theta_y (plane x-z, bending about n1, I11).
constexpr int kPlaneXY[4] = {1, 5, 7, 11};
constexpr int kPlaneXZ[4] = {2, 4, 8, 10};
constexpr double kSignXY[4] = {1, 1, 1, 1};
constexpr double kSignXZ[4] = {1, -1, 1, -1};

void scatter(Matrix12d& target, const Eigen::Matrix4d& block, const int (&idx)[4], const double (&sign)[4]) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) target(idx[r], idx[c]) += sign[r] * sign[c] * block(r, c);
}

}  // namespace

namespace {

Matrix12d unreleased_stiffness(const BeamElementData& e) {
  const double L = e.length, E = e.youngs_modulus, G = e.shear_modulus;
  const SectionProperties& s = e.section;
  Matrix12d k = Matrix12d::Zero();
  const double ea = E * s.area / L, gj = G * s.torsion_constant / L;
  k(0, 0) = k(6, 6) = ea;
  k(0, 6) = k(6, 0) = -ea;
  k(3, 3) = k(9, 9) = gj;
  k(3, 9) = k(9, 3) = -gj;
  scatter(k, bending_stiffness(E * s.i22, L, shear_parameter(e, s.i22, s.shear_area_1)), kPlaneXY, kSignXY);
  scatter(k, bending_stiffness(E * s.i11, L, shear_parameter(e, s.i11, s.shear_area_2)), kPlaneXZ, kSignXZ);
  return k;
}

}  // namespace

Matrix12d beam_release_transformation(const BeamElementData& e) {
  if (e.released == 0) return Matrix12d::Identity();
  return release_transformation(unreleased_stiffness(e), e.released);
}

Matrix12d beam_local_stiffness(const BeamElementData& e) {
  const Matrix12d k = unreleased_stiffness(e);
  if (e.released == 0) return k;
  const Matrix12d t = release_transformation(k, e.released);
  return t.transpose() * k * t;
}

Vector12d beam_local_uniform_load(const BeamElementData& e, const Eigen::Vector3d& q) {
  const double L = e.length;
  Vector12d p = Vector12d::Zero();
  p(0) = p(6) = q.x() * L / 2;
  // Plane x-y: deflection v, slope theta_z.
  p(1) = p(7) = q.y() * L / 2;
  p(5) = q.y() * L * L / 12;
  p(11) = -q.y() * L * L / 12;
  // Plane x-z: deflection w, slope -theta_y.
  p(2) = p(8) = q.z() * L / 2;
  p(4) = -q.z() * L * L / 12;
  p(10) = q.z() * L * L / 12;
  if (e.released == 0) return p;
  return beam_release_transformation(e).transpose() * p;
}

namespace {

Matrix12d unreleased_mass(const BeamElementData& e, MassFormulation formulation) {
  const double L = e.length, rho = e.density;
  const SectionProperties& s = e.section;
  Matrix12d m = Matrix12d::Zero();
  if (formulation == MassFormulation::lumped) {
    const double half = rho * s.area * L / 2.0;
    for (int node = 0; node < 2; ++node) {
      const int o = 6 * node;
      m(o, o) = m(o + 1, o + 1) = m(o + 2, o + 2) = half;
      m(o + 3, o + 3) = rho * s.polar_moment() * L / 2.0;
      m(o + 4, o + 4) = rho * s.i11 * L / 2.0;
      m(o + 5, o + 5) = rho * s.i22 * L / 2.0;
    }
    return m;
  }
  const double axial = rho * s.area * L / 6.0, torsion = rho * s.polar_moment() * L / 6.0;
  m(0, 0) = m(6, 6) = 2 * axial;
  m(0, 6) = m(6, 0) = axial;
  m(3, 3) = m(9, 9) = 2 * torsion;
  m(3, 9) = m(9, 3) = torsion;
  const bool rotary = e.theory == BeamTheory::timoshenko || e.bending_rotary_inertia;
  scatter(m, bending_mass(rho * s.area, rho * s.i22, L, shear_parameter(e, s.i22, s.shear_area_1), rotary), kPlaneXY, kSignXY);
  scatter(m, bending_mass(rho * s.area, rho * s.i11, L, shear_parameter(e, s.i11, s.shear_area_2), rotary), kPlaneXZ, kSignXZ);
  return m;
}

}  // namespace

Matrix12d beam_local_mass(const BeamElementData& e, MassFormulation formulation) {
  const Matrix12d m = unreleased_mass(e, formulation);
  if (e.released == 0) return m;
  const Matrix12d t = beam_release_transformation(e);
  return t.transpose() * m * t;
}

Matrix12d beam_transformation(const Eigen::Matrix3d& r) {
  Matrix12d t = Matrix12d::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r;
  return t;
}

SectionGeometry section_geometry(const FrameModel& model, int section, BeamTheory theory) {
  const SectionAssignment& sa = model.sections.at(static_cast<std::size_t>(section));
  SectionGeometry g;
  g.data.youngs_modulus = sa.material.youngs_modulus;
  g.data.shear_modulus = sa.material.shear_modulus;
  g.data.density = sa.material.density;
  g.data.section = sa.properties;
  g.data.theory = theory;
  g.data.bending_rotary_inertia = sa.bending_rotary_inertia;
  if (sa.properties.i12 != 0.0) {
    // Principal axes: the angle that makes the product of inertia vanish.
    const SectionProperties& s = sa.properties;
    const double angle = 0.5 * std::atan2(-2.0 * s.i12, s.i11 - s.i22);
    const double c = std::cos(angle), sn = std::sin(angle);
    const double mean = 0.5 * (s.i11 + s.i22), half_diff = 0.5 * (s.i11 - s.i22);
    g.data.section.i11 = mean + half_diff * std::cos(2 * angle) - s.i12 * std::sin(2 * angle);
    g.data.section.i22 = mean - half_diff * std::cos(2 * angle) + s.i12 * std::sin(2 * angle);
    g.data.section.i12 = 0.0;
    for (Eigen::Vector2d& p : g.data.section.stress_points) p = Eigen::Vector2d(c * p.x() + sn * p.y(), -sn * p.x() + c * p.y());
    g.principal_angle = angle;
  }
  return g;
}

Eigen::Matrix3d element_axes(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section) {
  const SectionAssignment& sa = model.sections[static_cast<std::size_t>(beam.section)];
  const Eigen::Vector3d& a = model.nodes[static_cast<std::size_t>(beam.node_a)].position;
  const Eigen::Vector3d& b = model.nodes[static_cast<std::size_t>(beam.node_b)].position;
  Eigen::Matrix3d axes = beam_local_axes(a, b, sa.n1_direction);
  if (section.principal_angle != 0.0) {
    const double c = std::cos(section.principal_angle), sn = std::sin(section.principal_angle);
    const Eigen::Vector3d n1 = axes.row(1), n2 = axes.row(2);
    axes.row(1) = (c * n1 + sn * n2).transpose();
    axes.row(2) = (-sn * n1 + c * n2).transpose();
  }
  return axes;
}

BeamGeometry beam_geometry(const FrameModel& model, const BeamElement& beam) {
  const SectionGeometry s = section_geometry(model, beam.section, beam.theory);
  BeamGeometry g;
  g.axes = element_axes(model, beam, s);
  g.data = s.data;
  g.data.released = beam.released;
  g.data.length = (model.nodes.at(static_cast<std::size_t>(beam.node_b)).position -
                   model.nodes.at(static_cast<std::size_t>(beam.node_a)).position).norm();
  return g;
}

}  // namespace framedyn::fem

// Three-node Timoshenko beam (B32, B32R); see quadratic_beam_element.h and
// docs/theory/fem.md, "Three-node beams".
#include "fem/quadratic_beam_element.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/member_releases.h"

namespace framedyn::fem {

namespace {

struct Rule {
  int count;
  double points[3];
  double weights[3];
};

// Gauss-Legendre rules on [-1, 1].
const Rule kTwoPoint{2, {-0.57735026918962576451, 0.57735026918962576451, 0.0}, {1.0, 1.0, 0.0}};
const Rule kThreePoint{3, {-0.77459666924148337704, 0.0, 0.77459666924148337704}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};

// Six-point rule for arc lengths of curved elements (|x,xi| is not a polynomial there).
constexpr double kSixPoints[6] = {-0.93246951420315202781, -0.66120938646626451366, -0.23861918608319690863,
                                  0.23861918608319690863,  0.66120938646626451366,  0.93246951420315202781};
constexpr double kSixWeights[6] = {0.17132449237917034504, 0.36076157304813860757, 0.46791393457269104739,
                                   0.46791393457269104739, 0.36076157304813860757, 0.17132449237917034504};

Eigen::Vector3d shape(double xi) { return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)}; }
Eigen::Vector3d shape_derivative(double xi) { return {xi - 0.5, -2.0 * xi, xi + 0.5}; }

std::array<int, 3> element_nodes(const BeamElement& beam) { return {beam.node_a, beam.node_m, beam.node_b}; }

Eigen::Vector3d node_position(const FrameModel& model, int node) { return model.nodes[static_cast<std::size_t>(node)].position; }

// dx/dxi at xi.
Eigen::Vector3d tangent_vector(const FrameModel& model, const BeamElement& beam, double xi) {
  const Eigen::Vector3d dn = shape_derivative(xi);
  const auto nodes = element_nodes(beam);
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) d += dn(i) * node_position(model, nodes[static_cast<std::size_t>(i)]);
  return d;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

// Arc length from xi = -1 to xi.
double arc_length_to(const FrameModel& model, const BeamElement& beam, double xi) {
  const double half = 0.5 * (xi + 1.0);
  double s = 0.0;
  for (int g = 0; g < 6; ++g) s += kSixWeights[g] * half * tangent_vector(model, beam, -1.0 + half * (kSixPoints[g] + 1.0)).norm();
  return s;
}

// B (6 x 18): nodal DOFs (global) -> local generalised strains
// (axial strain, shear 1, shear 2, twist, curvature about 1, curvature about 2).
Eigen::Matrix<double, 6, 18> strain_matrix(const QuadraticBeamPoint& p, double xi) {
  const Eigen::Vector3d n = shape(xi), dn = shape_derivative(xi) / p.jacobian;
  const Eigen::Matrix3d& r = p.axes;
  const Eigen::Matrix3d r_t_cross = r * skew(r.row(0).transpose());
  Eigen::Matrix<double, 6, 18> b = Eigen::Matrix<double, 6, 18>::Zero();
  for (int i = 0; i < 3; ++i) {
    b.block<3, 3>(0, 6 * i) = dn(i) * r;
    b.block<3, 3>(0, 6 * i + 3) = n(i) * r_t_cross;
    b.block<3, 3>(3, 6 * i + 3) = dn(i) * r;
  }
  return b;
}

Eigen::Matrix<double, 6, 1> section_stiffness(const BeamElementData& d) {
  const SectionProperties& s = d.section;
  const double e = d.youngs_modulus, g = d.shear_modulus;
  Eigen::Matrix<double, 6, 1> k;
  k << e * s.area, g * s.shear_area_1, g * s.shear_area_2, g * s.torsion_constant, e * s.i11, e * s.i22;
  return k;
}

}  // namespace

std::array<int, 18> quadratic_beam_dofs(const BeamElement& beam) {
  std::array<int, 18> d{};
  const auto nodes = element_nodes(beam);
  for (std::size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 6; ++k) d[6 * i + static_cast<std::size_t>(k)] = kDofsPerNode * nodes[i] + k;
  return d;
}

QuadraticBeamPoint quadratic_beam_point(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section, double xi) {
  QuadraticBeamPoint p;
  const Eigen::Vector3d n = shape(xi);
  const auto nodes = element_nodes(beam);
  p.position = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) p.position += n(i) * node_position(model, nodes[static_cast<std::size_t>(i)]);
  const Eigen::Vector3d d = tangent_vector(model, beam, xi);
  p.jacobian = d.norm();
  if (!(p.jacobian > 0.0)) throw std::invalid_argument(fmt::format("the element's mapping folds (ds/dxi = 0 at xi = {:g})", xi));
  // beam_local_axes takes two points on the tangent line.
  const SectionAssignment& sa = model.sections[static_cast<std::size_t>(beam.section)];
  p.axes = beam_local_axes(Eigen::Vector3d::Zero(), d, sa.n1_direction);
  if (section.principal_angle != 0.0) {
    const double c = std::cos(section.principal_angle), sn = std::sin(section.principal_angle);
    const Eigen::Vector3d n1 = p.axes.row(1), n2 = p.axes.row(2);
    p.axes.row(1) = (c * n1 + sn * n2).transpose();
    p.axes.row(2) = (-sn * n1 + c * n2).transpose();
  }
  return p;
}

void check_quadratic_beam_geometry(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section) {
  const Eigen::Vector3d& a = node_position(model, beam.node_a);
  const Eigen::Vector3d& b = node_position(model, beam.node_b);
  const Eigen::Vector3d& m = node_position(model, beam.node_m);
  if ((b - a).norm() == 0.0) throw std::invalid_argument("its end nodes are at the same point");
  if ((m - a).norm() == 0.0 || (m - b).norm() == 0.0) throw std::invalid_argument("its midside node is at an end node");
  // dx/dxi is linear in xi: it keeps its direction (and never vanishes) from
  // end to end if the end tangents make an angle below 90 degrees. For a
  // straight element this holds exactly when the midside node lies strictly
  // between the quarter points.
  const Eigen::Vector3d ta = tangent_vector(model, beam, -1.0), tb = tangent_vector(model, beam, 1.0);
  if (!(ta.dot(tb) > 1e-9 * ta.norm() * tb.norm()))
    throw std::invalid_argument(
        "its midside node is not between the quarter points of its ends, or the element turns by 90 degrees or more "
        "(the isoparametric mapping folds; place the midside node near the middle of the member)");
  // n1 must not lie along the tangent anywhere: at the Gauss points the
  // matrices use and on a fine comb of points in between (stations).
  for (const Rule* rule : {&kTwoPoint, &kThreePoint})
    for (int g = 0; g < rule->count; ++g) (void)quadratic_beam_point(model, beam, section, rule->points[g]);
  for (int k = 0; k <= 32; ++k) (void)quadratic_beam_point(model, beam, section, -1.0 + k / 16.0);
}

double quadratic_beam_length(const FrameModel& model, const BeamElement& beam) { return arc_length_to(model, beam, 1.0); }

namespace {

Matrix18d unreleased_stiffness(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section) {
  const Rule& rule = beam.reduced_integration ? kTwoPoint : kThreePoint;
  const Eigen::Matrix<double, 6, 1> d = section_stiffness(section.data);
  Matrix18d k = Matrix18d::Zero();
  for (int g = 0; g < rule.count; ++g) {
    const double xi = rule.points[g];
    const QuadraticBeamPoint p = quadratic_beam_point(model, beam, section, xi);
    const Eigen::Matrix<double, 6, 18> b = strain_matrix(p, xi);
    k.noalias() += b.transpose() * d.asDiagonal() * b * (p.jacobian * rule.weights[g]);
  }
  return 0.5 * (k + k.transpose());
}

// The line load at xi, global components.
Eigen::Vector3d line_load_at(const FrameModel& model, const BeamElement& beam, const BeamLineLoad& load, double xi) {
  if (load.section.isZero(0.0)) return load.global;
  // The section's axes as written (not principal), as for P1/P2 on two-node beams.
  const Eigen::Matrix3d axes =
      beam_local_axes(Eigen::Vector3d::Zero(), tangent_vector(model, beam, xi), model.sections[static_cast<std::size_t>(beam.section)].n1_direction);
  return load.global + load.section(0) * axes.row(1).transpose() + load.section(1) * axes.row(2).transpose();
}

Matrix18d unreleased_mass(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section, MassFormulation formulation) {
  const BeamElementData& e = section.data;
  const double rho_a = e.density * e.section.area;
  const Eigen::Vector3d rho_i(e.density * e.section.polar_moment(), e.density * e.section.i11, e.density * e.section.i22);
  Matrix18d m = Matrix18d::Zero();
  // Both rules integrate N_i N_j J exactly on a straight element; the mass is
  // taken with three points for B32 and B32R alike.
  for (int g = 0; g < kThreePoint.count; ++g) {
    const double xi = kThreePoint.points[g];
    const QuadraticBeamPoint p = quadratic_beam_point(model, beam, section, xi);
    const double w = p.jacobian * kThreePoint.weights[g];
    const Eigen::Matrix3d rotary = p.axes.transpose() * rho_i.asDiagonal() * p.axes;
    const Eigen::Vector3d n = shape(xi);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (formulation == MassFormulation::lumped && i != j) continue;
        // Lumped: row sums, sum_j N_i N_j = N_i.
        const double nn = formulation == MassFormulation::lumped ? n(i) : n(i) * n(j);
        m.block<3, 3>(6 * i, 6 * j).diagonal().array() += rho_a * nn * w;
        m.block<3, 3>(6 * i + 3, 6 * j + 3) += rotary * (nn * w);
      }
  }
  return 0.5 * (m + m.transpose());
}

}  // namespace

Matrix18d quadratic_beam_release_transformation(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section) {
  if (beam.released == 0) return Matrix18d::Identity();
  // Q: the end nodes' rotations into the local axes at their end.
  Matrix18d q = Matrix18d::Identity();
  q.block<3, 3>(3, 3) = quadratic_beam_point(model, beam, section, -1.0).axes;
  q.block<3, 3>(15, 15) = quadratic_beam_point(model, beam, section, 1.0).axes;
  std::vector<int> released;  // local DOFs 6 end + 3..5 -> element DOFs 3..5 (node a), 15..17 (node b)
  for (int end = 0; end < 2; ++end)
    for (int k = kReleaseTorsion; k <= kReleaseM2; ++k)
      if (beam.released & release_bit(end, k)) released.push_back(12 * end + k);
  const Eigen::MatrixXd k_end = q * unreleased_stiffness(model, beam, section) * q.transpose();
  const Matrix18d t = release_transformation(k_end, released, beam.released);
  return q.transpose() * t * q;
}

Matrix18d quadratic_beam_stiffness(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section) {
  const Matrix18d k = unreleased_stiffness(model, beam, section);
  if (beam.released == 0) return k;
  const Matrix18d g = quadratic_beam_release_transformation(model, beam, section);
  const Matrix18d kr = g.transpose() * k * g;
  return 0.5 * (kr + kr.transpose());
}

Matrix18d quadratic_beam_mass(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section, MassFormulation formulation) {
  const Matrix18d m = unreleased_mass(model, beam, section, formulation);
  if (beam.released == 0) return m;
  const Matrix18d g = quadratic_beam_release_transformation(model, beam, section);
  const Matrix18d mr = g.transpose() * m * g;
  return 0.5 * (mr + mr.transpose());
}

Vector18d quadratic_beam_consistent_load(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section,
                                         const BeamLineLoad& load) {
  Vector18d p = Vector18d::Zero();
  if (load.is_zero()) return p;
  for (int g = 0; g < 6; ++g) {
    const double xi = kSixPoints[g];
    const Eigen::Vector3d q = line_load_at(model, beam, load, xi) * (tangent_vector(model, beam, xi).norm() * kSixWeights[g]);
    const Eigen::Vector3d n = shape(xi);
    for (int i = 0; i < 3; ++i) p.segment<3>(6 * i) += n(i) * q;
  }
  if (beam.released == 0) return p;
  return quadratic_beam_release_transformation(model, beam, section).transpose() * p;
}

std::vector<StationResult> quadratic_beam_stations(const FrameModel& model, const BeamElement& beam, const Eigen::VectorXd& u, int stations,
                                                   const BeamLineLoad& load) {
  const SectionGeometry section = section_geometry(model, beam.section, BeamTheory::timoshenko);
  const std::array<int, 18> dofs = quadratic_beam_dofs(beam);
  Vector18d ue;
  for (int i = 0; i < 18; ++i) ue(i) = u(dofs[static_cast<std::size_t>(i)]);
  // Forces the nodes exert on the element, global components (with the line
  // load, the element's own load is taken off: K u - p).
  const Vector18d f = quadratic_beam_stiffness(model, beam, section) * ue - quadratic_beam_consistent_load(model, beam, section, load);
  const double length = quadratic_beam_length(model, beam);
  const double midside = arc_length_to(model, beam, 0.0);
  const auto nodes = element_nodes(beam);
  std::vector<StationResult> out;
  double xi = -1.0;
  for (int s = 0; s < stations; ++s) {
    const double target = length * static_cast<double>(s) / (stations - 1);
    // xi at arc length `target` (Newton on s(xi), monotonic since J > 0).
    if (s == 0) xi = -1.0;
    else if (s == stations - 1) xi = 1.0;
    else
      for (int it = 0; it < 50; ++it) {
        const double step = (arc_length_to(model, beam, xi) - target) / tangent_vector(model, beam, xi).norm();
        xi = std::clamp(xi - step, -1.0, 1.0);
        if (std::abs(step) < 1e-14) break;
      }
    const QuadraticBeamPoint p = quadratic_beam_point(model, beam, section, xi);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    // Nodes on the a-side of the cut: a, and the midside node once past it.
    const int on_a_side = target > midside * (1.0 + 1e-12) ? 2 : 1;
    for (int i = 0; i < on_a_side; ++i) {
      const Eigen::Vector3d fi = f.segment<3>(6 * i), mi = f.segment<3>(6 * i + 3);
      force += fi;
      moment += mi + (node_position(model, nodes[static_cast<std::size_t>(i)]) - p.position).cross(fi);
    }
    // The line load on the part from node a to the cut (xi from -1 to the cut's).
    if (!load.is_zero() && xi > -1.0) {
      const double half = 0.5 * (xi + 1.0);
      for (int g = 0; g < 6; ++g) {
        const double xg = -1.0 + half * (kSixPoints[g] + 1.0);
        const Eigen::Vector3d q = line_load_at(model, beam, load, xg) * (tangent_vector(model, beam, xg).norm() * kSixWeights[g] * half);
        Eigen::Vector3d at = Eigen::Vector3d::Zero();
        const Eigen::Vector3d n = shape(xg);
        for (int i = 0; i < 3; ++i) at += n(i) * node_position(model, nodes[static_cast<std::size_t>(i)]);
        force += q;
        moment += (at - p.position).cross(q);
      }
    }
    // The cut's positive face (outward normal +t) carries minus the forces on the part before it.
    const Eigen::Vector3d fl = -(p.axes * force), ml = -(p.axes * moment);
    StationResult r;
    r.element_id = beam.id;
    r.station = s;
    r.x = target;
    r.point = p.position;
    r.forces.n = fl(0);
    r.forces.vy = fl(1);
    r.forces.vz = fl(2);
    r.forces.t = ml(0);
    r.forces.my = ml(1);
    r.forces.mz = ml(2);
    r.fiber_stress = fiber_stresses(section.data.section, r.forces);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace framedyn::fem

// Stress at section points by shape; see section_stress.h. Formulas:
// Timoshenko & Goodier, Theory of Elasticity, section 109 (rectangle torsion
// series); Bredt-Batho and the thin-walled shear flow (Megson, Aircraft
// Structures, chapters 17-18); Gere, Mechanics of Materials (V Q / I b).
#include "fem/section_stress.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace framedyn::fem {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCatalan = 0.915965594177219015054603514932;  // sum_k (-1)^k / (2k+1)^2

std::string signed_axis(double v, int axis) { return fmt::format("{}{}", v >= 0.0 ? "+" : "-", axis); }

SectionPoint point(std::string name, double x1, double x2) {
  SectionPoint p;
  p.name = std::move(name);
  p.position = {x1, x2};
  return p;
}

// A straight wall of a thin-walled closed cell on its midline, from p0 to p1 (counter-clockwise round the cell).
struct Wall {
  Eigen::Vector2d p0, p1;
  double t = 0.0;
  double length() const { return (p1 - p0).norm(); }
  Eigen::Vector2d direction() const { return (p1 - p0) / length(); }
};

// Shear flow of a single closed cell under a unit shear force along `axis`
// (0: Vy with I22 and x1; 1: Vz with I11 and x2), positive along each wall's
// direction, at each wall's start, middle and end. Open at the first wall's
// start: q_b(s) = -(1/I) int_0^s x t ds (Eq. 20.7); then the constant flow
// q_0 = -oint q_b / t ds / oint ds / t that leaves the cell untwisted (Eq.
// 20.8). q_b is quadratic along a wall, so Simpson's rule integrates it exactly.
std::vector<std::array<double, 3>> closed_cell_shear_flow(const std::vector<Wall>& walls, int axis, double inertia) {
  std::vector<std::array<double, 3>> q;
  double q_start = 0.0, q_over_t = 0.0, one_over_t = 0.0;
  for (const Wall& w : walls) {
    const double l = w.length(), x0 = w.p0(axis), x1 = w.p1(axis), xm = 0.5 * (x0 + x1);
    const double qm = q_start - w.t * 0.5 * l * 0.5 * (x0 + xm) / inertia;
    const double qe = q_start - w.t * l * xm / inertia;
    q.push_back({q_start, qm, qe});
    q_over_t += l / 6.0 * (q_start + 4.0 * qm + qe) / w.t;
    one_over_t += l / w.t;
    q_start = qe;
  }
  const double q0 = -q_over_t / one_over_t;
  for (auto& v : q)
    for (double& x : v) x += q0;
  return q;
}

std::vector<SectionPoint> rectangle_points(const SectionProperties& s) {
  const double a = s.dimensions[0], b = s.dimensions[1];
  std::vector<SectionPoint> out;
  for (const Eigen::Vector2d& c : s.stress_points) out.push_back(point("corner " + signed_axis(c.x(), 1) + signed_axis(c.y(), 2), c.x(), c.y()));
  // Torsion: the long sides' middles carry the largest stress (Eq. 20.2), the short sides' (Eq. 20.3); tangent, counter-clockwise.
  const RectangleTorsionShear torsion = rectangle_torsion_shear(a, b);
  const double on_sides_along_1 = a >= b ? torsion.long_side_middle : torsion.short_side_middle;  // the sides x2 = +-b/2, of length a
  const double on_sides_along_2 = a >= b ? torsion.short_side_middle : torsion.long_side_middle;  // the sides x1 = +-a/2, of length b
  // Transverse shear: 1.5 V / A at the neutral axis, zero at the faces (Eq. 20.6).
  const double peak = 1.5 / s.area;
  for (const double sign : {1.0, -1.0}) {
    SectionPoint p = point("mid-side " + signed_axis(sign, 1), sign * a / 2, 0.0);
    p.shear_per_torque = {0.0, sign * on_sides_along_2};
    p.shear_per_vz = {0.0, peak};
    out.push_back(p);
    SectionPoint q = point("mid-side " + signed_axis(sign, 2), 0.0, sign * b / 2);
    q.shear_per_torque = {-sign * on_sides_along_1, 0.0};
    q.shear_per_vy = {peak, 0.0};
    out.push_back(q);
  }
  return out;
}

std::vector<SectionPoint> box_points(const SectionProperties& s) {
  const double a = s.dimensions[0], b = s.dimensions[1], t1 = s.dimensions[2], t2 = s.dimensions[3], t3 = s.dimensions[4], t4 = s.dimensions[5];
  // The outline's centre from the centroid (the stress points are the outline's corners).
  const Eigen::Vector2d centre = 0.5 * (s.stress_points[0] + s.stress_points[2]);
  const double xr = centre.x() + a / 2 - t1 / 2, xl = centre.x() - a / 2 + t3 / 2;
  const double xt = centre.y() + b / 2 - t2 / 2, xb = centre.y() - b / 2 + t4 / 2;
  // Counter-clockwise from the corner at (+1, -2): the walls at +x1, +x2, -x1, -x2.
  const std::vector<Wall> walls = {{{xr, xb}, {xr, xt}, t1}, {{xr, xt}, {xl, xt}, t2}, {{xl, xt}, {xl, xb}, t3}, {{xl, xb}, {xr, xb}, t4}};
  const double enclosed = (xr - xl) * (xt - xb);  // A_m
  const auto vy = closed_cell_shear_flow(walls, 0, s.i22);
  const auto vz = closed_cell_shear_flow(walls, 1, s.i11);
  // The stress in wall w at its start (0), middle (1) or end (2): q / t along the wall (Eqs. 20.4, 20.7).
  const auto in_wall = [&](SectionPoint& p, std::size_t w, int at) {
    const Eigen::Vector2d e = walls[w].direction() / walls[w].t;
    p.shear_per_torque = e / (2.0 * enclosed);
    p.shear_per_vy = vy[w][static_cast<std::size_t>(at)] * e;
    p.shear_per_vz = vz[w][static_cast<std::size_t>(at)] * e;
  };
  std::vector<SectionPoint> out;
  // Outline corners (as stress_points): each in the thinner of its two walls (the larger shear), the wall along 2 on a tie.
  // Corner k of stress_points: (+,+) ends wall 0 / starts wall 1; (-,+) ends 1 / starts 2; (-,-) ends 2 / starts 3; (+,-) ends 3 / starts 0.
  const std::array<std::pair<std::size_t, std::size_t>, 4> corner_walls = {{{0, 1}, {2, 1}, {2, 3}, {0, 3}}};
  for (std::size_t k = 0; k < 4; ++k) {
    const Eigen::Vector2d& c = s.stress_points[k];
    SectionPoint p = point("corner " + signed_axis(c.x() - centre.x(), 1) + signed_axis(c.y() - centre.y(), 2), c.x(), c.y());
    const auto [along2, along1] = corner_walls[k];
    const std::size_t w = walls[along1].t < walls[along2].t ? along1 : along2;
    // Wall w's end or start at this corner.
    const bool at_end = (k == 0 && w == 0) || (k == 1 && w == 1) || (k == 2 && w == 2) || (k == 3 && w == 3);
    in_wall(p, w, at_end ? 2 : 0);
    out.push_back(p);
  }
  const std::array<std::pair<std::string, Eigen::Vector2d>, 4> mids = {{{"+1", {centre.x() + a / 2, centre.y()}},
                                                                        {"+2", {centre.x(), centre.y() + b / 2}},
                                                                        {"-1", {centre.x() - a / 2, centre.y()}},
                                                                        {"-2", {centre.x(), centre.y() - b / 2}}}};
  for (std::size_t w = 0; w < 4; ++w) {
    SectionPoint p = point("mid-side " + mids[w].first, mids[w].second.x(), mids[w].second.y());
    in_wall(p, w, 1);
    out.push_back(p);
  }
  return out;
}

// Eight points round a circle of radius r on the outer surface: torsion T r / J, the neutral axis's shear
// `peak_over_area` V / A, tangent to the surface, its component along V as V Q / (I b) at that chord (Eq. 20.6).
std::vector<SectionPoint> round_points(const SectionProperties& s, double r, double peak_over_area) {
  std::vector<SectionPoint> out;
  for (int k = 0; k < 8; ++k) {
    const double c = std::cos(k * kPi / 4), sn = std::sin(k * kPi / 4);
    SectionPoint p = point(fmt::format("angle {}", 45 * k), r * c, r * sn);
    p.shear_per_torque = r / s.torsion_constant * Eigen::Vector2d(-sn, c);
    p.shear_per_vz = peak_over_area / s.area * c * Eigen::Vector2d(-sn, c);
    p.shear_per_vy = peak_over_area / s.area * sn * Eigen::Vector2d(sn, -c);
    out.push_back(p);
  }
  return out;
}

// Eight points round an ellipse of semi-axes a (along 1) and b (along 2)
// (docs/theory/fem.md section 23): the Saint-Venant torsion shear of the
// ellipse, 2 T / (pi a b) sqrt(x1^2/a^4 + x2^2/b^4) tangent to the outline
// (Eq. 23.4), and the transverse shear whose component along V is V Q / (I w)
// = 4 V / (3 A) (1 - (x/semi-axis)^2) at the chord through the point (the
// ellipse is a stretched circle), tangent to the outline (Eq. 23.5).
std::vector<SectionPoint> elliptic_points(const SectionProperties& s, double a, double b) {
  std::vector<SectionPoint> out;
  const double peak = 4.0 / 3.0 / s.area;
  for (int k = 0; k < 8; ++k) {
    const double c = std::cos(k * kPi / 4), sn = std::sin(k * kPi / 4);
    const double x1 = a * c, x2 = b * sn;
    SectionPoint p = point(fmt::format("angle {}", 45 * k), x1, x2);
    const Eigen::Vector2d tangent = Eigen::Vector2d(-a * sn, b * c).normalized();
    p.shear_per_torque = 2.0 / (kPi * a * b) * std::sqrt(x1 * x1 / (a * a * a * a) + x2 * x2 / (b * b * b * b)) * tangent;
    p.shear_per_vz = peak * c * Eigen::Vector2d(-a * sn / b, c);
    p.shear_per_vy = peak * sn * Eigen::Vector2d(sn, -b * c / a);
    out.push_back(p);
  }
  return out;
}

// Open thin walls (Eq. 20.9): the wall's torsional shear T t / J along it.
SectionPoint open_wall_point(std::string name, double x1, double x2, const Eigen::Vector2d& along, double t, double j) {
  SectionPoint p = point(std::move(name), x1, x2);
  p.open_wall = true;
  p.shear_per_torque = t / j * along;
  return p;
}

std::vector<SectionPoint> i_points(const SectionProperties& s) {
  const double b1 = s.dimensions[1], b2 = s.dimensions[2], t1 = s.dimensions[3], t2 = s.dimensions[4], t3 = s.dimensions[5];
  const double top = s.stress_points[0].y(), bottom = s.stress_points[2].y();  // outer faces of the flanges from the centroid
  const double j = s.torsion_constant;
  const Eigen::Vector2d e1(1.0, 0.0), e2(0.0, 1.0);
  std::vector<SectionPoint> out;
  for (const double sign : {1.0, -1.0}) out.push_back(open_wall_point("top flange tip " + signed_axis(sign, 1), sign * b2 / 2, top, e1, t2, j));
  for (const double sign : {1.0, -1.0}) out.push_back(open_wall_point("bottom flange tip " + signed_axis(sign, 1), sign * b1 / 2, bottom, e1, t1, j));
  // Flange centres: Vy's flow from both tips, Q = t b^2 / 8 (Eq. 20.7); Vz's flow splits there (zero).
  SectionPoint top_centre = open_wall_point("top flange centre", 0.0, top, e1, t2, j);
  top_centre.shear_per_vy = b2 * b2 / (8.0 * s.i22) * e1;
  SectionPoint bottom_centre = open_wall_point("bottom flange centre", 0.0, bottom, e1, t1, j);
  bottom_centre.shear_per_vy = b1 * b1 / (8.0 * s.i22) * e1;
  out.push_back(top_centre);
  out.push_back(bottom_centre);
  // In the web: V Q / (I11 t_web) with Q of the flange beyond (Eq. 20.6); at the centroid the web above is added.
  const double q_top = b2 * t2 * (top - t2 / 2), q_bottom = b1 * t1 * (-bottom - t1 / 2);
  SectionPoint top_junction = open_wall_point("top flange-web junction", 0.0, top - t2, e2, t3, j);
  top_junction.shear_per_vz = q_top / (s.i11 * t3) * e2;
  SectionPoint bottom_junction = open_wall_point("bottom flange-web junction", 0.0, bottom + t1, e2, t3, j);
  bottom_junction.shear_per_vz = q_bottom / (s.i11 * t3) * e2;
  SectionPoint centre = open_wall_point("web centre", 0.0, 0.0, e2, t3, j);
  centre.shear_per_vz = (q_top + t3 * (top - t2) * (top - t2) / 2) / (s.i11 * t3) * e2;
  out.push_back(top_junction);
  out.push_back(bottom_junction);
  out.push_back(centre);
  return out;
}

std::vector<SectionPoint> channel_points(const SectionProperties& s) {
  const double h = s.dimensions[0], b = s.dimensions[1], tf = s.dimensions[2], tw = s.dimensions[3];
  const double back = s.stress_points[1].x(), tip = s.stress_points[0].x();  // -x_c and b - x_c
  const double j = s.torsion_constant;
  const Eigen::Vector2d e1(1.0, 0.0), e2(0.0, 1.0);
  std::vector<SectionPoint> out;
  for (const double sign : {1.0, -1.0}) out.push_back(open_wall_point("flange tip " + signed_axis(sign, 2), tip, sign * h / 2, e1, tf, j));
  // Back corners, in the flange at the web: the flange's flow from its tip to the web's face (Eq. 20.7).
  const double qz_flange = tf * (b - tw) * (h - tf) / 2, qy_flange = tf * ((tip * tip) - (back + tw) * (back + tw)) / 2;
  for (const double sign : {1.0, -1.0}) {
    SectionPoint p = open_wall_point("back corner " + signed_axis(sign, 2), back, sign * h / 2, e1, tf, j);
    p.shear_per_vz = sign * qz_flange / (s.i11 * tf) * e1;
    p.shear_per_vy = qy_flange / (s.i22 * tf) * e1;
    out.push_back(p);
  }
  // In the web: the whole flange's first moments; Vy's flow turns down the web from the top flange and up from the bottom one.
  const double qz_web = b * tf * (h - tf) / 2, qy_web = tf * (tip * tip - back * back) / 2;
  for (const double sign : {1.0, -1.0}) {
    SectionPoint p = open_wall_point("flange-web junction " + signed_axis(sign, 2), back + tw / 2, sign * (h / 2 - tf), e2, tw, j);
    p.shear_per_vz = qz_web / (s.i11 * tw) * e2;
    p.shear_per_vy = sign * qy_web / (s.i22 * tw) * e2;
    out.push_back(p);
  }
  SectionPoint centre = open_wall_point("web centre", back + tw / 2, 0.0, e2, tw, j);
  centre.shear_per_vz = (qz_web + tw * (h / 2 - tf) * (h / 2 - tf) / 2) / (s.i11 * tw) * e2;
  out.push_back(centre);
  return out;
}

}  // namespace

RectangleTorsionShear rectangle_torsion_shear(double a, double b) {
  // Prandtl's stress function for the rectangle (Timoshenko & Goodier, section 109), sides s <= l:
  //   tau(long side middle)  = (T s / J) [1 - 8/pi^2 sum_{n odd} 1 / (n^2 cosh(n pi l / 2s))]
  //   tau(short side middle) = (T s / J) 8/pi^2 sum_{n odd} (-1)^((n-1)/2) tanh(n pi l / 2s) / n^2
  // the latter summed as Catalan's constant less the exponentially small 1 - tanh terms.
  const double l = std::max(a, b), s = std::min(a, b);
  const double j = rectangle_torsion_constant(a, b);
  double long_sum = 0.0, short_defect = 0.0;
  for (int n = 1; n < 400; n += 2) {
    const double x = n * kPi * l / (2.0 * s);
    const double term = x > 700.0 ? 0.0 : 1.0 / (n * n * std::cosh(x));
    const double one_minus_tanh = x > 350.0 ? 0.0 : 2.0 / (std::exp(2.0 * x) + 1.0);
    long_sum += term;
    short_defect += ((n - 1) / 2 % 2 == 0 ? 1.0 : -1.0) * one_minus_tanh / (n * n);
    if (term < 1e-18 * long_sum && one_minus_tanh < 1e-18) break;
  }
  const double factor = 8.0 / (kPi * kPi);
  return {s / j * (1.0 - factor * long_sum), s / j * factor * (kCatalan - short_defect)};
}

std::vector<SectionPoint> section_points(const SectionProperties& s) {
  if (s.shape == "RECT") return rectangle_points(s);
  if (s.shape == "BOX") return box_points(s);
  if (s.shape == "CIRC" && s.dimensions.size() == 2) return elliptic_points(s, s.dimensions[0], s.dimensions[1]);
  if (s.shape == "CIRC") return round_points(s, s.dimensions[0], 4.0 / 3.0);
  if (s.shape == "PIPE") return round_points(s, s.dimensions[0], 2.0);  // thin-walled tube: 2 V / A at the neutral axis
  if (s.shape == "I") return i_points(s);
  if (s.shape == "CHANNEL") return channel_points(s);
  return {};  // GENERAL: constants only, no outline
}

PointStress combine_stresses(double normal, double shear) {
  PointStress out;
  out.normal = normal;
  out.shear = shear;
  out.von_mises = std::sqrt(normal * normal + 3.0 * shear * shear);
  out.max_principal = 0.5 * normal + std::sqrt(0.25 * normal * normal + shear * shear);
  return out;
}

PointStress point_stress(const SectionProperties& s, const SectionPoint& p, const SectionForces& f) {
  // Eq. (20.1), as fem::fiber_stresses.
  const double sigma = f.n / s.area + f.my * p.position.y() / s.i11 - f.mz * p.position.x() / s.i22;
  const Eigen::Vector2d from_forces = f.vy * p.shear_per_vy + f.vz * p.shear_per_vz;
  const Eigen::Vector2d from_torque = f.t * p.shear_per_torque;
  const double tau = p.open_wall ? from_forces.norm() + from_torque.norm() : (from_forces + from_torque).norm();
  return combine_stresses(sigma, tau);
}

Eigen::Vector2d shear_direction(const SectionPoint& p) {
  for (const Eigen::Vector2d* v : {&p.shear_per_torque, &p.shear_per_vy, &p.shear_per_vz})
    if (v->norm() > 0.0) return v->normalized();
  return Eigen::Vector2d::Zero();
}

SignedShear signed_shear(const SectionPoint& p, const SectionForces& f) {
  // fatigue.md Eq. F.26: the components along d; exact because every unit response lies along d.
  const Eigen::Vector2d d = shear_direction(p);
  const double from_forces = d.dot(f.vy * p.shear_per_vy + f.vz * p.shear_per_vz);
  const double from_torque = d.dot(f.t * p.shear_per_torque);
  if (p.open_wall) return {from_forces + from_torque, from_forces - from_torque};
  return {from_forces + from_torque, from_forces + from_torque};
}

std::vector<PointStress> point_stresses(const SectionProperties& s, const std::vector<SectionPoint>& points, const SectionForces& f) {
  std::vector<PointStress> out;
  out.reserve(points.size());
  for (const SectionPoint& p : points) out.push_back(point_stress(s, p, f));
  return out;
}

}  // namespace framedyn::fem

// Section constants by shape. Formulas: Timoshenko & Goodier (rectangle
// torsion series), Bredt (closed thin walls), Cowper 1966 (shear factors).
#include "fem/beam_section.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::fem {

namespace {

constexpr double kPi = 3.14159265358979323846;

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be positive");
}

std::vector<Eigen::Vector2d> corners(double half1, double half2) {
  return {{half1, half2}, {-half1, half2}, {-half1, -half2}, {half1, -half2}};
}

std::vector<Eigen::Vector2d> circle_points(double r) {
  std::vector<Eigen::Vector2d> pts;
  for (int k = 0; k < 8; ++k) pts.emplace_back(r * std::cos(k * kPi / 4), r * std::sin(k * kPi / 4));
  return pts;
}

}  // namespace

double rectangle_torsion_constant(double a, double b) {
  // J = a b^3 / 3 [1 - 192/pi^5 (b/a) sum_{n odd} tanh(n pi a / 2b) / n^5], b <= a.
  const double longer = std::max(a, b), shorter = std::min(a, b);
  double sum = 0.0;
  for (int n = 1; n < 200; n += 2) {
    const double term = std::tanh(n * kPi * longer / (2.0 * shorter)) / std::pow(n, 5);
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return longer * shorter * shorter * shorter / 3.0 * (1.0 - 192.0 / std::pow(kPi, 5) * (shorter / longer) * sum);
}

SectionProperties rectangle_section(double a, double b, double nu) {
  require_positive(a, "RECT width a");
  require_positive(b, "RECT height b");
  SectionProperties s;
  s.shape = "RECT";
  s.dimensions = {a, b};
  s.area = a * b;
  s.i11 = a * b * b * b / 12.0;
  s.i22 = b * a * a * a / 12.0;
  s.torsion_constant = rectangle_torsion_constant(a, b);
  const double k = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);  // Cowper
  s.shear_area_1 = s.shear_area_2 = k * s.area;
  s.stress_points = corners(a / 2, b / 2);
  return s;
}

SectionProperties box_section(double a, double b, double t1, double t2, double t3, double t4) {
  require_positive(a, "BOX width a");
  require_positive(b, "BOX height b");
  for (double t : {t1, t2, t3, t4}) require_positive(t, "BOX wall thickness");
  if (t1 + t3 >= a || t2 + t4 >= b) throw std::invalid_argument("BOX walls thicker than the box");
  SectionProperties s;
  s.shape = "BOX";
  s.dimensions = {a, b, t1, t2, t3, t4};
  // Exact for the outline minus the hole (walls of unequal thickness shift the
  // centroid; the constants are taken about the centroid).
  const double inner1 = a - t1 - t3, inner2 = b - t2 - t4;
  const double c_hole1 = (t3 - t1) / 2.0, c_hole2 = (t4 - t2) / 2.0;  // hole centre from outline centre
  const double area_out = a * b, area_in = inner1 * inner2;
  s.area = area_out - area_in;
  const double c1 = -area_in * c_hole1 / s.area, c2 = -area_in * c_hole2 / s.area;  // centroid
  s.i11 = a * b * b * b / 12.0 + area_out * c2 * c2 - (inner1 * inner2 * inner2 * inner2 / 12.0 + area_in * (c_hole2 - c2) * (c_hole2 - c2));
  s.i22 = b * a * a * a / 12.0 + area_out * c1 * c1 - (inner2 * inner1 * inner1 * inner1 / 12.0 + area_in * (c_hole1 - c1) * (c_hole1 - c1));
  // Bredt: J = 4 Am^2 / (sum of wall lengths / thickness), on the wall midlines.
  const double mid1 = a - (t1 + t3) / 2.0, mid2 = b - (t2 + t4) / 2.0;
  const double am = mid1 * mid2;
  s.torsion_constant = 4.0 * am * am / (mid2 / t1 + mid1 / t2 + mid2 / t3 + mid1 / t4);
  s.shear_area_1 = mid1 * (t2 + t4);  // flanges (walls at +-x2) carry shear along 1
  s.shear_area_2 = mid2 * (t1 + t3);  // webs carry shear along 2
  s.stress_points = {{a / 2 - c1, b / 2 - c2}, {-a / 2 - c1, b / 2 - c2}, {-a / 2 - c1, -b / 2 - c2}, {a / 2 - c1, -b / 2 - c2}};
  return s;
}

SectionProperties circle_section(double r, double nu) {
  require_positive(r, "CIRC radius");
  SectionProperties s;
  s.shape = "CIRC";
  s.dimensions = {r};
  s.area = kPi * r * r;
  s.i11 = s.i22 = kPi * r * r * r * r / 4.0;
  s.torsion_constant = kPi * r * r * r * r / 2.0;
  const double k = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);  // Cowper
  s.shear_area_1 = s.shear_area_2 = k * s.area;
  s.stress_points = circle_points(r);
  return s;
}

SectionProperties ellipse_section(double a, double b, double nu) {
  require_positive(a, "CIRC semi-axis along 1");
  require_positive(b, "CIRC semi-axis along 2");
  SectionProperties s;
  s.shape = "CIRC";
  s.dimensions = {a, b};
  s.area = kPi * a * b;
  s.i11 = kPi * a * b * b * b / 4.0;  // about local 1: the extent b along 2 bends
  s.i22 = kPi * a * a * a * b / 4.0;
  s.torsion_constant = kPi * a * a * a * b * b * b / (a * a + b * b);
  // Cowper's factor of the circle for both directions: exact for a = b, an
  // approximation otherwise (the shear deformation of a slender beam is small).
  const double k = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
  s.shear_area_1 = s.shear_area_2 = k * s.area;
  for (int i = 0; i < 8; ++i) s.stress_points.emplace_back(a * std::cos(i * kPi / 4), b * std::sin(i * kPi / 4));
  return s;
}

SectionProperties pipe_section(double ro, double t, double nu) {
  require_positive(ro, "PIPE outer radius");
  require_positive(t, "PIPE wall thickness");
  if (t > ro) throw std::invalid_argument("PIPE wall thicker than its radius");
  const double ri = ro - t;
  SectionProperties s;
  s.shape = "PIPE";
  s.dimensions = {ro, t};
  s.area = kPi * (ro * ro - ri * ri);
  s.i11 = s.i22 = kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
  s.torsion_constant = 2.0 * s.i11;
  // Cowper's factor for a hollow circle, m = ri/ro.
  const double m = ri / ro, m2 = m * m;
  const double k = 6.0 * (1.0 + nu) * (1.0 + m2) * (1.0 + m2) /
                   ((7.0 + 6.0 * nu) * (1.0 + m2) * (1.0 + m2) + (20.0 + 12.0 * nu) * m2);
  s.shear_area_1 = s.shear_area_2 = k * s.area;
  s.stress_points = circle_points(ro);
  return s;
}

SectionProperties i_section(double h, double b1, double b2, double t1, double t2, double t3) {
  require_positive(h, "I height h");
  for (double v : {b1, b2, t1, t2, t3}) require_positive(v, "I flange or web dimension");
  if (t1 + t2 >= h) throw std::invalid_argument("I flanges thicker than the section height");
  if (t3 > std::min(b1, b2)) throw std::invalid_argument("I web wider than a flange");
  SectionProperties s;
  s.shape = "I";
  s.dimensions = {h, b1, b2, t1, t2, t3};
  const double hw = h - t1 - t2;  // clear web height
  // Parts measured from the bottom face: bottom flange, web, top flange.
  const double a_bot = b1 * t1, a_web = t3 * hw, a_top = b2 * t2;
  const double y_bot = t1 / 2, y_web = t1 + hw / 2, y_top = h - t2 / 2;
  s.area = a_bot + a_web + a_top;
  const double yc = (a_bot * y_bot + a_web * y_web + a_top * y_top) / s.area;
  s.i11 = b1 * t1 * t1 * t1 / 12 + a_bot * (y_bot - yc) * (y_bot - yc) + t3 * hw * hw * hw / 12 +
          a_web * (y_web - yc) * (y_web - yc) + b2 * t2 * t2 * t2 / 12 + a_top * (y_top - yc) * (y_top - yc);
  s.i22 = t1 * b1 * b1 * b1 / 12 + hw * t3 * t3 * t3 / 12 + t2 * b2 * b2 * b2 / 12;
  s.torsion_constant = (b1 * t1 * t1 * t1 + b2 * t2 * t2 * t2 + hw * t3 * t3 * t3) / 3.0;
  s.shear_area_2 = h * t3;                         // web
  s.shear_area_1 = 5.0 / 6.0 * (a_bot + a_top);    // flanges as rectangles
  s.stress_points = {{b2 / 2, h - yc}, {-b2 / 2, h - yc}, {-b1 / 2, -yc}, {b1 / 2, -yc}};
  return s;
}

SectionProperties channel_section(double h, double b, double tf, double tw) {
  require_positive(h, "CHANNEL height h");
  require_positive(b, "CHANNEL flange width b");
  require_positive(tf, "CHANNEL flange thickness");
  require_positive(tw, "CHANNEL web thickness");
  if (2 * tf >= h || tw >= b) throw std::invalid_argument("CHANNEL walls thicker than the section");
  SectionProperties s;
  s.shape = "CHANNEL";
  s.dimensions = {h, b, tf, tw};
  const double hw = h - 2 * tf;
  const double a_fl = b * tf, a_web = tw * hw;
  s.area = 2 * a_fl + a_web;
  // x1 measured from the outer face of the web.
  const double x_c = (2 * a_fl * b / 2 + a_web * tw / 2) / s.area;
  s.i11 = b * h * h * h / 12 - (b - tw) * hw * hw * hw / 12;
  s.i22 = 2 * (tf * b * b * b / 12 + a_fl * (b / 2 - x_c) * (b / 2 - x_c)) + hw * tw * tw * tw / 12 +
          a_web * (tw / 2 - x_c) * (tw / 2 - x_c);
  s.torsion_constant = (2 * b * tf * tf * tf + hw * tw * tw * tw) / 3.0;
  s.shear_area_2 = h * tw;
  s.shear_area_1 = 5.0 / 6.0 * 2 * a_fl;
  s.stress_points = {{b - x_c, h / 2}, {-x_c, h / 2}, {-x_c, -h / 2}, {b - x_c, -h / 2}};
  return s;
}

SectionProperties general_section(double area, double i11, double i12, double i22, double j) {
  require_positive(area, "GENERAL section area A");
  require_positive(i11, "GENERAL section I11");
  require_positive(i22, "GENERAL section I22");
  require_positive(j, "GENERAL section J");
  if (i12 * i12 >= i11 * i22) throw std::invalid_argument("GENERAL section with I12^2 >= I11 I22 is not positive definite");
  SectionProperties s;
  s.shape = "GENERAL";
  s.dimensions = {area, i11, i12, i22, j};
  s.area = area;
  s.i11 = i11;
  s.i22 = i22;
  s.i12 = i12;
  s.torsion_constant = j;
  s.shear_area_1 = s.shear_area_2 = area;
  return s;
}

}  // namespace framedyn::fem

// The 2-D machine's frame mass properties (Appendix C); see machine_2d.h and
// docs/theory/rigid.md.
#include "rigid/machine_2d.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::rigid {

FrameMassProperties frame_mass_properties(const Frame2D& frame, const Cab2D& cab) {
  FrameMassProperties f;
  const double tube_mass = frame.mass_per_length * frame.length;  // rho FLT (errata to Eq. C.2)
  const double tube_x = frame.front_end + frame.length / 2.0;
  double sum_m = tube_mass, sum_mx = tube_mass * tube_x, sum_mz = 0.0;  // the tube lies on Z = 0
  for (const AddedMass& a : frame.added_masses) {
    sum_m += a.mass;
    sum_mx += a.mass * a.position.x();
    sum_mz += a.mass * a.position.y();
  }
  if (!(sum_m > 0.0)) throw std::invalid_argument("the frame has no mass");
  f.mass = sum_m;
  f.cg = {sum_mx / sum_m, sum_mz / sum_m};
  f.inertia = tube_mass * (frame.length * frame.length / 12.0 + std::pow(tube_x - f.cg.x(), 2) + f.cg.y() * f.cg.y());
  for (const AddedMass& a : frame.added_masses) f.inertia += a.inertia + a.mass * (a.position - f.cg).squaredNorm();
  // Eq. C.3: the reference height includes the cab, whose X motion the frame carries.
  f.reference = {f.cg.x(), (sum_mz + cab.mass * cab.cg.y()) / (sum_m + cab.mass)};
  return f;
}

}  // namespace framedyn::rigid

// Mass properties of the 3-D machine's rigid parts (Appendix F, Eqs. F.1-F.12);
// see machine_3d.h and docs/theory/rigid.md, section 10.
#include "rigid/machine_3d.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::rigid {

Eigen::Matrix3d inertia_tensor(double ixx, double iyy, double izz, double pxy, double pxz, double pyz) {
  Eigen::Matrix3d i;
  i << ixx, -pxy, -pxz, -pxy, iyy, -pyz, -pxz, -pyz, izz;
  return i;
}

RigidPart3D combine(const std::vector<RigidPart3D>& parts, const std::string& name) {
  RigidPart3D c;
  c.name = name;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const RigidPart3D& p : parts) {
    c.mass += p.mass;
    moment += p.mass * p.cg;
  }
  if (!(c.mass > 0.0)) throw std::invalid_argument(name + ": no mass");
  c.cg = moment / c.mass;
  for (const RigidPart3D& p : parts) {
    const Eigen::Vector3d r = p.cg - c.cg;
    // Parallel axes with products: I += I_p + m (|r|^2 1 - r r^T)  (Eqs. F.3, F.5-F.12 as one tensor sum).
    c.inertia += p.inertia + p.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return c;
}

}  // namespace framedyn::rigid

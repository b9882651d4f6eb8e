// Assembly of K and M from beam elements, point masses and springs.
#include "fem/assembly.h"

#include "fem/quadratic_beam_element.h"
#include "fem/solver_counters.h"

#include <fmt/format.h>

#include <exception>
#include <optional>
#include <thread>
#include <stdexcept>

namespace framedyn::fem {

DofMap make_dof_map(const FrameModel& model) {
  DofMap map;
  const int n = model.dof_count();
  std::vector<char> constrained(static_cast<std::size_t>(n), 0);
  for (const Constraint& c : model.constraints) {
    const int g = kDofsPerNode * c.node + c.dof;
    if (!constrained[static_cast<std::size_t>(g)]) {
      constrained[static_cast<std::size_t>(g)] = 1;
      map.constrained_dofs.push_back(g);
    }
  }
  map.links = rigid_link_constraints(model);
  map.free_index.assign(static_cast<std::size_t>(n), -1);
  map.free_dofs.reserve(static_cast<std::size_t>(n) - map.constrained_dofs.size() - map.links.slaves.size());
  for (int g = 0; g < n; ++g)
    if (!constrained[static_cast<std::size_t>(g)] && !map.links.is_slave(g)) {
      map.free_index[static_cast<std::size_t>(g)] = static_cast<int>(map.free_dofs.size());
      map.free_dofs.push_back(g);
    }
  return map;
}

Eigen::VectorXd expand_free(const DofMap& dofs, const Eigen::VectorXd& u_free, const Eigen::VectorXd& prescribed) {
  Eigen::VectorXd all = prescribed;
  for (int e = 0; e < dofs.free_count(); ++e) all(dofs.free_dofs[static_cast<std::size_t>(e)]) = u_free(e);
  fill_slave_dofs(dofs.links, all);
  return all;
}

Eigen::VectorXd restrict_load(const DofMap& dofs, const Eigen::VectorXd& f_all) {
  Eigen::VectorXd folded = f_all;
  fold_slave_forces(dofs.links, folded);
  Eigen::VectorXd out(dofs.free_count());
  for (int e = 0; e < dofs.free_count(); ++e) out(e) = folded(dofs.free_dofs[static_cast<std::size_t>(e)]);
  return out;
}

namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

struct ElementMatrices {
  Matrix12d stiffness, mass;
  std::array<int, 12> dofs;
};

// Element data for a loop over all beams: the section part computed once
// per (section, theory), the length and axes per element.
class ElementGeometries {
 public:
  explicit ElementGeometries(const FrameModel& model) : model_(model) {}
  const BeamGeometry& operator()(const BeamElement& beam) {
    const std::size_t key = 2 * static_cast<std::size_t>(beam.section) + (beam.theory == BeamTheory::timoshenko ? 1 : 0);
    if (key >= sections_.size()) sections_.resize(key + 1);
    if (!sections_[key]) sections_[key] = section_geometry(model_, beam.section, beam.theory);
    const SectionGeometry& s = *sections_[key];
    try {
      current_.axes = element_axes(model_, beam, s);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("beam element {}: {}", beam.id, e.what()));
    }
    return fill(s, beam);
  }

 private:
  const BeamGeometry& fill(const SectionGeometry& s, const BeamElement& beam) {
    const BeamElementData& d = s.data;
    current_.data.youngs_modulus = d.youngs_modulus;
    current_.data.shear_modulus = d.shear_modulus;
    current_.data.density = d.density;
    current_.data.theory = d.theory;
    current_.data.bending_rotary_inertia = d.bending_rotary_inertia;
    current_.data.released = beam.released;
    current_.data.section.area = d.section.area;
    current_.data.section.i11 = d.section.i11;
    current_.data.section.i22 = d.section.i22;
    current_.data.section.torsion_constant = d.section.torsion_constant;
    current_.data.section.shear_area_1 = d.section.shear_area_1;
    current_.data.section.shear_area_2 = d.section.shear_area_2;
    current_.data.length = (model_.nodes[static_cast<std::size_t>(beam.node_b)].position -
                            model_.nodes[static_cast<std::size_t>(beam.node_a)].position).norm();
    return current_;
  }
  const FrameModel& model_;
  std::vector<std::optional<SectionGeometry>> sections_;
  BeamGeometry current_;
};

// Section data of three-node elements (always Timoshenko), computed once per
// section; element errors name the element.
class QuadraticSections {
 public:
  explicit QuadraticSections(const FrameModel& model) : model_(model) {}
  const SectionGeometry& operator()(const BeamElement& beam) {
    const std::size_t key = static_cast<std::size_t>(beam.section);
    if (key >= sections_.size()) sections_.resize(key + 1);
    if (!sections_[key]) sections_[key] = section_geometry(model_, beam.section, BeamTheory::timoshenko);
    try {
      check_quadratic_beam_geometry(model_, beam, *sections_[key]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("beam element {}: {}", beam.id, e.what()));
    }
    return *sections_[key];
  }

 private:
  const FrameModel& model_;
  std::vector<std::optional<SectionGeometry>> sections_;
};

std::array<int, 12> element_dofs(const BeamElement& beam) {
  std::array<int, 12> d{};
  for (int i = 0; i < 6; ++i) {
    d[static_cast<std::size_t>(i)] = kDofsPerNode * beam.node_a + i;
    d[static_cast<std::size_t>(6 + i)] = kDofsPerNode * beam.node_b + i;
  }
  return d;
}

// The equations a global DOF acts on and with which factor: its own equation
// (factor 1) if free, its free masters' (Eq. R.1 coefficients) if a slave of a
// rigid link or a distributing coupling, none if constrained. Returns the count
// (at most kMaxSlaveMasters).
int equation_terms(const DofMap& dofs, int g, std::array<int, kMaxSlaveMasters>& eq, std::array<double, kMaxSlaveMasters>& factor) {
  const int f = dofs.free_index[static_cast<std::size_t>(g)];
  if (f >= 0) {
    eq[0] = f;
    factor[0] = 1.0;
    return 1;
  }
  if (!dofs.links.is_slave(g)) return 0;
  const SlaveDof& s = dofs.links.slaves[static_cast<std::size_t>(dofs.links.slave_of[static_cast<std::size_t>(g)])];
  int n = 0;
  for (int k = 0; k < s.count; ++k) {
    const int fm = dofs.free_index[static_cast<std::size_t>(s.master[static_cast<std::size_t>(k)])];
    if (fm < 0) continue;  // a supported master: its part is in the prescribed displacement
    eq[static_cast<std::size_t>(n)] = fm;
    factor[static_cast<std::size_t>(n++)] = s.coefficient[static_cast<std::size_t>(k)];
  }
  return n;
}

// T^T m T scattered (Eq. R.2) for elements that touch slave DOFs.
template <int N>
void scatter_linked(Triplets& out, const Eigen::Matrix<double, N, N>& m, const std::array<int, N>& global, const DofMap& dofs, Storage storage) {
  std::array<std::array<int, kMaxSlaveMasters>, N> eq;
  std::array<std::array<double, kMaxSlaveMasters>, N> factor;
  std::array<int, N> count;
  for (int i = 0; i < N; ++i)
    count[static_cast<std::size_t>(i)] = equation_terms(dofs, global[static_cast<std::size_t>(i)], eq[static_cast<std::size_t>(i)], factor[static_cast<std::size_t>(i)]);
  for (int c = 0; c < N; ++c)
    for (int r = 0; r < N; ++r) {
      const double v = m(r, c);
      if (v == 0.0) continue;
      for (int kc = 0; kc < count[static_cast<std::size_t>(c)]; ++kc)
        for (int kr = 0; kr < count[static_cast<std::size_t>(r)]; ++kr) {
          const int fr = eq[static_cast<std::size_t>(r)][static_cast<std::size_t>(kr)], fc = eq[static_cast<std::size_t>(c)][static_cast<std::size_t>(kc)];
          if (storage == Storage::lower && fr < fc) continue;
          out.emplace_back(fr, fc, factor[static_cast<std::size_t>(r)][static_cast<std::size_t>(kr)] * v * factor[static_cast<std::size_t>(c)][static_cast<std::size_t>(kc)]);
        }
    }
}

template <int N>
void scatter(Triplets& out, const Eigen::Matrix<double, N, N>& m, const std::array<int, N>& global, const DofMap& dofs, Storage storage) {
  if (!dofs.links.empty())
    for (int i = 0; i < N; ++i)
      if (dofs.links.is_slave(global[static_cast<std::size_t>(i)])) return scatter_linked<N>(out, m, global, dofs, storage);
  for (int c = 0; c < N; ++c) {
    const int fc = dofs.free_index[static_cast<std::size_t>(global[static_cast<std::size_t>(c)])];
    if (fc < 0) continue;
    for (int r = 0; r < N; ++r) {
      const int fr = dofs.free_index[static_cast<std::size_t>(global[static_cast<std::size_t>(r)])];
      if (fr < 0) continue;
      if (storage == Storage::lower && fr < fc) continue;
      const double v = m(r, c);
      if (v != 0.0) out.emplace_back(fr, fc, v);
    }
  }
}

SparseMatrix from_triplets(int n, Triplets& t) {
  SparseMatrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  Triplets().swap(t);
  m.makeCompressed();
  return m;
}

// K (stiffness) or M on the free DOFs, element by element.
SparseMatrix build(const FrameModel& model, const DofMap& dofs, const AssemblyOptions& options, bool stiffness) {
  const std::size_t per_element = options.storage == Storage::lower ? 78 : 144;
  Triplets t;
  t.reserve(per_element * model.beams.size() + 36 * model.point_masses.size() + 4 * model.springs.size());
  ElementGeometries geometry(model);
  QuadraticSections quadratic(model);
  for (const BeamElement& beam : model.beams) {
    if (beam.is_quadratic()) {
      const SectionGeometry& s = quadratic(beam);
      const Matrix18d global = stiffness ? quadratic_beam_stiffness(model, beam, s) : quadratic_beam_mass(model, beam, s, options.mass);
      scatter<18>(t, global, quadratic_beam_dofs(beam), dofs, options.storage);
      continue;
    }
    const BeamGeometry& g = geometry(beam);
    const Matrix12d tr = beam_transformation(g.axes);
    const Matrix12d local = stiffness ? beam_local_stiffness(g.data) : beam_local_mass(g.data, options.mass);
    const Matrix12d global = tr.transpose() * local * tr;
    scatter<12>(t, global, element_dofs(beam), dofs, options.storage);
  }
  if (stiffness) {
    for (const Spring& s : model.springs) {
      const int ga = kDofsPerNode * s.node_a + s.dof_a;
      if (s.node_b < 0) {
        scatter<1>(t, Eigen::Matrix<double, 1, 1>::Constant(s.stiffness), {ga}, dofs, options.storage);
      } else {
        Eigen::Matrix2d k;
        k << s.stiffness, -s.stiffness, -s.stiffness, s.stiffness;
        scatter<2>(t, k, {ga, kDofsPerNode * s.node_b + s.dof_b}, dofs, options.storage);
      }
    }
  } else {
    for (const PointMass& pm : model.point_masses) {
      Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
      m.topLeftCorner<3, 3>().diagonal().setConstant(pm.mass);
      m.bottomRightCorner<3, 3>() = pm.rotary_inertia;
      std::array<int, 6> d{};
      for (int i = 0; i < 6; ++i) d[static_cast<std::size_t>(i)] = kDofsPerNode * pm.node + i;
      scatter<6>(t, m, d, dofs, options.storage);
    }
  }
  return from_triplets(dofs.free_count(), t);
}

}  // namespace

FreeSystem assemble(const FrameModel& model, const DofMap& dofs, const AssemblyOptions& options) {
  internal::count_system_assembly();
  FreeSystem sys;
  // K and M one after the other, so only one triplet list is alive at a time.
  // K and M are independent: build them on two threads (each writes only its
  // own matrix, so the result does not depend on scheduling). An exception in
  // the mass thread is carried over and rethrown here.
  std::exception_ptr mass_error;
  std::thread mass_thread([&] {
    try {
      sys.mass = build(model, dofs, options, false);
    } catch (...) {
      mass_error = std::current_exception();
    }
  });
  try {
    sys.stiffness = build(model, dofs, options, true);
  } catch (...) {
    mass_thread.join();
    throw;
  }
  mass_thread.join();
  if (mass_error) std::rethrow_exception(mass_error);
  return sys;
}

SparseMatrix assemble_mass(const FrameModel& model, const DofMap& dofs, const AssemblyOptions& options) {
  internal::count_mass_assembly();
  return build(model, dofs, options, false);
}

Eigen::VectorXd internal_force(const FrameModel& model, const Eigen::VectorXd& u) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  ElementGeometries geometry(model);
  QuadraticSections quadratic(model);
  for (const BeamElement& beam : model.beams) {
    if (beam.is_quadratic()) {
      const auto d = quadratic_beam_dofs(beam);
      Vector18d ue;
      for (int i = 0; i < 18; ++i) ue(i) = u(d[static_cast<std::size_t>(i)]);
      const Vector18d fe = quadratic_beam_stiffness(model, beam, quadratic(beam)) * ue;
      for (int i = 0; i < 18; ++i) f(d[static_cast<std::size_t>(i)]) += fe(i);
      continue;
    }
    const BeamGeometry& g = geometry(beam);
    const Matrix12d tr = beam_transformation(g.axes);
    const auto d = element_dofs(beam);
    Vector12d ue;
    for (int i = 0; i < 12; ++i) ue(i) = u(d[static_cast<std::size_t>(i)]);
    const Vector12d fe = tr.transpose() * (beam_local_stiffness(g.data) * (tr * ue));
    for (int i = 0; i < 12; ++i) f(d[static_cast<std::size_t>(i)]) += fe(i);
  }
  for (const Spring& s : model.springs) {
    const int ga = kDofsPerNode * s.node_a + s.dof_a;
    if (s.node_b < 0) {
      f(ga) += s.stiffness * u(ga);
    } else {
      const int gb = kDofsPerNode * s.node_b + s.dof_b;
      const double force = s.stiffness * (u(ga) - u(gb));
      f(ga) += force;
      f(gb) -= force;
    }
  }
  return f;
}

std::vector<int> massless_dofs(const FrameModel& model, const DofMap& dofs, const SparseMatrix& mass_ff) {
  (void)model;
  std::vector<int> out;
  const Eigen::VectorXd diag = mass_ff.diagonal();
  for (int i = 0; i < diag.size(); ++i)
    if (!(diag(i) > 0.0)) out.push_back(dofs.free_dofs[static_cast<std::size_t>(i)]);
  return out;
}

Eigen::MatrixXd rigid_body_vectors(const FrameModel& model, const Eigen::Vector3d& p) {
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(model.dof_count(), 6);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const Eigen::Vector3d d = model.nodes[i].position - p;
    const int o = kDofsPerNode * static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {
      r(o + k, k) = 1.0;       // translation
      r(o + 3 + k, 3 + k) = 1.0;  // rotation
    }
    // Translation of the node from a small rotation theta about p: theta x d.
    const Eigen::Vector3d ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
    r.block<3, 1>(o, 3) = ex.cross(d);
    r.block<3, 1>(o, 4) = ey.cross(d);
    r.block<3, 1>(o, 5) = ez.cross(d);
  }
  return r;
}

}  // namespace framedyn::fem

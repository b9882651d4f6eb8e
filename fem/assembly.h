// Sparse assembly of the frame's stiffness K and mass M over the free DOFs
// (fixed and prescribed DOFs eliminated), and the element-by-element
// internal force K u used for reactions and equilibrium checks.
#pragma once

#include <Eigen/Sparse>

#include <vector>

#include "fem/beam_element.h"
#include "fem/frame_model.h"
#include "fem/rigid_links.h"

namespace framedyn::fem {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Numbering of the free DOFs: free_index[g] is the equation number of global
// DOF g, or -1 if g is constrained or a slave of a rigid link (rigid_links.h:
// its value follows from its reference node's DOFs by `links`).
struct DofMap {
  std::vector<int> free_index;
  std::vector<int> free_dofs;         // equation number -> global DOF
  std::vector<int> constrained_dofs;  // global DOFs with a *BOUNDARY, in order
  RigidLinkConstraints links;         // slave rows of u = T u_m (empty without rigid links)
  int free_count() const { return static_cast<int>(free_dofs.size()); }
};

// Throws RigidLinkError (a std::invalid_argument) for a rigid link that cannot be used.
DofMap make_dof_map(const FrameModel& model);

// All-DOF vector from free-DOF values: u_f at the free DOFs, `prescribed`
// (all DOFs) at the constrained ones, then the slaves of rigid links (Eq. R.3).
Eigen::VectorXd expand_free(const DofMap& dofs, const Eigen::VectorXd& u_free, const Eigen::VectorXd& prescribed);
// T^T f restricted to the free DOFs: an all-DOF load vector on the equations,
// loads on slave nodes carried to their reference nodes (Eq. R.2).
Eigen::VectorXd restrict_load(const DofMap& dofs, const Eigen::VectorXd& f_all);

enum class Storage {
  lower,  // lower triangle only: what CHOLMOD and Spectra read; half the memory
  full,   // both triangles (tests, general products)
};

struct AssemblyOptions {
  MassFormulation mass = MassFormulation::consistent;
  Storage storage = Storage::lower;
};

// K_ff and M_ff on the free DOFs (with rigid links, T^T K T and T^T M T on
// the masters, Eq. R.2 of rigid_links.h). Throws std::invalid_argument naming
// the element for a zero-length element or a bad orientation.
struct FreeSystem {
  SparseMatrix stiffness;
  SparseMatrix mass;
};
FreeSystem assemble(const FrameModel& model, const DofMap& dofs, const AssemblyOptions& options = {});
// M_ff alone (rigid-body mass bookkeeping: no stiffness is built).
SparseMatrix assemble_mass(const FrameModel& model, const DofMap& dofs, const AssemblyOptions& options = {});

// f = K u over all DOFs (u and f of length model.dof_count()), element by element.
Eigen::VectorXd internal_force(const FrameModel& model, const Eigen::VectorXd& u);

// Global DOFs (constrained ones excluded) whose diagonal mass is zero.
std::vector<int> massless_dofs(const FrameModel& model, const DofMap& dofs, const SparseMatrix& mass_ff);

// Rigid-body displacement vectors of the six directions (x, y, z, rx, ry, rz
// about `reference_point`) on all DOFs, as columns of a dof_count x 6 matrix.
Eigen::MatrixXd rigid_body_vectors(const FrameModel& model, const Eigen::Vector3d& reference_point);

}  // namespace framedyn::fem

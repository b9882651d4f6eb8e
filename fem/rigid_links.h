// Rigid links (*RIGID BODY, *MPC BEAM) as a master-slave transformation.
//
// A slave node s of a link with reference node r moves with r's small rigid
// motion (docs/theory/fem.md, "Rigid links", Eqs. (R.1)-(R.5)):
//     u_s = u_r + theta_r x (x_s - x_r),   theta_s = theta_r.          (R.1)
// Every slave DOF is thus a combination of at most four reference DOFs, and
// the whole displacement vector is u = T u_m (u_m: the DOFs that are not
// slaves). K, M and loads are reduced as T^T K T, T^T M T, T^T f (R.2);
// results are expanded by u = T u_m (R.3); the forces the links carry are
// folded back onto the reference nodes by T^T, which is how the reactions at
// a supported reference node include the loads and inertia of its slaves (R.4).
// Slave DOFs are neither free nor constrained: DofMap numbers only the
// masters, and a *BOUNDARY on a slave DOF is refused (it would overconstrain
// the link).
// A distributing coupling (FrameModel::distributing_couplings, Eqs. R.6-R.8)
// is one more kind of slave row: each of its reference node's six DOFs is a
// combination of the mounts' translations (up to 3 x kMaxCouplingMounts masters).
#pragma once

#include <Eigen/Dense>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::fem {

// At most this many masters per slave DOF: a coupling's mounts' translations.
inline constexpr int kMaxSlaveMasters = 3 * kMaxCouplingMounts;

// One slave DOF: u[dof] = sum_k coefficient[k] u[master[k]], k < count.
struct SlaveDof {
  int dof = 0;                       // global DOF
  int count = 0;
  std::array<int, kMaxSlaveMasters> master{};       // global DOFs of the reference node (or of the mounts)
  std::array<double, kMaxSlaveMasters> coefficient{};
};

// The rows of T that are not identity rows.
struct RigidLinkConstraints {
  std::vector<SlaveDof> slaves;      // in order of global DOF
  std::vector<int> slave_of;         // global DOF -> index into slaves, or -1 (empty when there are no links)
  bool empty() const { return slaves.empty(); }
  bool is_slave(int global_dof) const { return !slave_of.empty() && slave_of[static_cast<std::size_t>(global_dof)] >= 0; }
};

// A rigid link that cannot be used: which link (index into model.rigid_links)
// and what was expected and found, for the reader's message.
class RigidLinkError : public std::invalid_argument {
 public:
  RigidLinkError(int link, std::string expected, std::string found);
  int link() const { return link_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  int link_;
  std::string expected_, found_;
};

// A distributing coupling that cannot be used (index into model.distributing_couplings).
class DistributingCouplingError : public std::invalid_argument {
 public:
  DistributingCouplingError(int coupling, const std::string& source, std::string expected, std::string found);
  int coupling() const { return coupling_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  int coupling_;
  std::string expected_, found_;
};

// Builds T's slave rows from model.rigid_links and model.distributing_couplings.
// Throws RigidLinkError for a node index out of range, a slave that is its own
// reference, a node slave of two links, a chain (a reference node that is a
// slave of another link), or a *BOUNDARY on a slave DOF; DistributingCouplingError
// for a distributing coupling that is not 1..kMaxCouplingMounts distinct mounts
// with positive weights off one line, or whose nodes are tied otherwise.
RigidLinkConstraints rigid_link_constraints(const FrameModel& model);

// The rows of Eqs. R.6-R.8 for one coupling: rows[k] (k = 0..5, the reference
// node's ux..rz) times the mounts' translations stacked [u_1; u_2; ...].
// Throws std::invalid_argument for mounts on one line (or all at one point).
Eigen::MatrixXd distributing_coupling_rows(const FrameModel& model, const DistributingCoupling& coupling);

// u = T u_m on all-DOF vectors (Eq. R.3): each slave entry is set from its
// masters' entries (free or prescribed), in place. Columns of a matrix each.
void fill_slave_dofs(const RigidLinkConstraints& links, Eigen::VectorXd& u);
void fill_slave_dofs_columns(const RigidLinkConstraints& links, Eigen::MatrixXd& u);

// f <- T^T f on all-DOF vectors (Eq. R.2): each slave entry is added to its
// masters with the slave's coefficients and then zeroed.
void fold_slave_forces(const RigidLinkConstraints& links, Eigen::VectorXd& f);

}  // namespace framedyn::fem

// Transient response of a frame to time-dependent nodal loads by mode
// superposition: modal damping (per mode or Rayleigh), integration of the
// decoupled modal equations that is exact for piecewise-linear load
// histories, and the mode-displacement or mode-acceleration method (static
// correction with the full flexibility for the modes left out). Supports are
// the model's constraints; a model without constraints is free-free and is
// analysed with inertia relief, and so is a partially supported one (its
// supports leave some rigid motions free, fem/rigid_body_modes.h) on the
// motions left free. With `include_rigid_motion` the free rigid motions are
// integrated too (q'' + alpha q' = r^T F, exact for piecewise-linear loads)
// and added to the elastic response. Theory: docs/theory/fem.md, "Transient
// response by mode superposition", Eqs. (T.1)-(T.12), and section 19.
//
// Vectors on "free DOFs" follow DofMap's equation numbering; vectors on "all
// DOFs" follow FrameModel (6 per node: ux uy uz rx ry rz), SI units.
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <memory>
#include <vector>

#include "core/work_share.h"
#include "fem/assembly.h"
#include "fem/modal_analysis.h"
#include "fem/sparse_cholesky.h"

namespace framedyn::fem {

// Modal damping: a ratio per mode (one value applies to every mode), or
// Rayleigh C = alpha M + beta K, for which zeta_i = alpha / (2 omega_i) + beta omega_i / 2 (Eq. T.3).
struct ModalDamping {
  std::vector<double> ratios{0.0};  // zeta, per elastic mode in order; the last value repeats
  bool rayleigh = false;
  double alpha = 0.0;               // 1/s
  double beta = 0.0;                // s

  static ModalDamping ratio(double zeta) { return ModalDamping{{zeta}, false, 0.0, 0.0}; }
  static ModalDamping rayleigh_damping(double alpha, double beta) { return ModalDamping{{0.0}, true, alpha, beta}; }
  // c_i = 2 zeta_i omega_i (1/s) of the i-th mode used (circular frequency omega, rad/s).
  double coefficient(int mode, double omega) const;
  // zeta_i; infinite for a rigid-body mode with Rayleigh alpha > 0.
  double ratio_of(int mode, double omega) const;
};

// Exact one-step update of q'' + c q' + k q = p(t) over [0, h] for p linear
// between p0 and p1 (Eq. T.5):  [q1, v1] = a [q0, v0] + b0 p0 + b1 p1.
// Any k >= 0, c >= 0: oscillatory, critically or over-damped, rigid-body (k = 0).
struct PiecewiseLinearStep {
  Eigen::Matrix2d a;
  Eigen::Vector2d b0, b1;
};
PiecewiseLinearStep piecewise_linear_step(double k, double c, double h);

// The few distinct steps of a time grid, remembered by their exact (k, c, h): a grid of rounded times
// t_k = k dt has steps that differ by an ulp or two of t (past t = 4 s for dt = 0.5 ms more than the
// 1e-12 h the integrators take as "the same step"), so without it a long record recomputes the matrix
// exponential nearly every step. step() returns exactly piecewise_linear_step(k, c, h).
inline constexpr std::size_t kRememberedSteps = 32;
class StepMemo {
 public:
  const PiecewiseLinearStep& step(double k, double c, double h);

 private:
  struct Entry {
    double k, c, h;
    PiecewiseLinearStep step;
  };
  std::vector<Entry> entries_;
  PiecewiseLinearStep last_{};
};

namespace internal {
// The closed-form recurrence of Nigam & Jennings (1969) for 0 <= zeta < 1,
// omega > 0 (Eq. T.6); equal to piecewise_linear_step to round-off. Its
// coefficients lose digits to cancellation when omega h << 1, which is why
// piecewise_linear_step evaluates the same update by an augmented matrix exponential.
PiecewiseLinearStep nigam_jennings_step(double omega, double zeta, double h);
// exp(A) of a small dense matrix by scaling and squaring of a Taylor series.
Eigen::Matrix4d expm(const Eigen::Matrix4d& a);
}  // namespace internal

// Modes on the free DOFs.
struct ModalBasis {
  Eigen::VectorXd eigenvalues;      // omega^2, rad^2/s^2, ascending (0 for rigid-body modes)
  Eigen::MatrixXd shapes;           // free DOFs x modes, M-orthonormal
  std::vector<bool> rigid_body;
  int elastic_count() const;
};
// From compute_modes' result (its shapes restricted to the free DOFs).
ModalBasis modal_basis(const DofMap& dofs, const ModalResult& modes);

enum class ResponseMethod {
  mode_displacement,  // u = Phi q (Eq. T.7)
  mode_acceleration,  // u = Phi q + G F - Phi Lambda^-1 Phi^T F (Eq. T.8)
};

// The assembled frame with its static solver, shared by the modal and the
// direct transient solvers. Free-free (no constraints): inertia relief with
// statically determinate auxiliary supports (Eqs. T.9-T.11). Keeps a
// reference to the model, which must outlive it. The solves share work
// buffers: one object is not for concurrent calls (make one per thread).
class FrameDynamics {
 public:
  explicit FrameDynamics(const FrameModel& model, MassFormulation mass = MassFormulation::consistent);
  // A free-free frame with its auxiliary supports chosen by the caller: six
  // global DOFs (node * 6 + dof) that hold it statically determinately (e.g.
  // where the machine holds it: coupling's supports: axle_pins). Inertia relief
  // leaves no reaction at any statically determinate support, so the elastic
  // response is the same as with the 3-2-1 choice, to solver round-off
  // (docs/theory/coupling.md, section 12). Throws NumericalError when the
  // model is not free-free or the six DOFs leave a rigid motion free.
  FrameDynamics(const FrameModel& model, const std::vector<int>& auxiliary_dofs, MassFormulation mass = MassFormulation::consistent);
  ~FrameDynamics();
  FrameDynamics(const FrameDynamics&) = delete;
  FrameDynamics& operator=(const FrameDynamics&) = delete;

  const FrameModel& model() const { return model_; }
  const DofMap& dofs() const { return dofs_; }
  const FreeSystem& system() const { return system_; }  // lower triangles
  bool free_free() const { return free_free_; }
  // Rigid motions the supports leave free: 6 free-free, 0 supported, between
  // for a partially supported frame (auxiliary supports and relief as for a
  // free-free one, on those motions; docs/theory/fem.md, section 19).
  int rigid_count() const { return static_cast<int>(rigid_.cols()); }

  // All modes by a dense generalised eigensolution (small models: the cost grows as n^3).
  ModalBasis all_modes() const;

  // Restriction of an all-DOF load-distribution matrix to the free DOFs,
  // relieved (Eq. T.9: F_rel = F - M R R^T F, R the M-orthonormal rigid-body
  // vectors) when the frame is free-free.
  // `relieved` false: the loads as they are (the free rigid motions then move under them).
  Eigen::MatrixXd free_loads(const SparseMatrix& distribution, bool relieved = true) const;
  Eigen::VectorXd relieve(const Eigen::VectorXd& f_free) const;
  // The elastic static response G f (Eq. T.10): K^-1 f for a supported frame;
  // for a free-free frame the solution on the auxiliary supports with the
  // rigid-body part removed (f must be self-equilibrated: relieve it first).
  Eigen::VectorXd static_response(const Eigen::VectorXd& f_free) const;
  // Reactions at the auxiliary supports for load f (zero for a self-equilibrated f; Eq. T.11).
  Eigen::VectorXd auxiliary_reactions(const Eigen::VectorXd& f_free) const;
  // Equation numbers of the auxiliary supports (free-free: the 3-2-1 choice;
  // partially supported: one per free rigid motion, Eq. 19.3; else none).
  const std::vector<int>& auxiliary_supports() const { return auxiliary_; }
  // M-orthonormal free rigid motions on the free DOFs (0 columns for a supported frame).
  const Eigen::MatrixXd& rigid_vectors() const { return rigid_; }
  // Removes the rigid-body part: u - R R^T M u (free-free), else u.
  Eigen::VectorXd elastic_part(const Eigen::VectorXd& u_free) const;
  // Free-DOF vector to all DOFs (zero at constrained DOFs).
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const;
  Eigen::VectorXd mass_times(const Eigen::VectorXd& x) const;
  Eigen::VectorXd stiffness_times(const Eigen::VectorXd& x) const;

 private:
  void set_up(const std::vector<int>& auxiliary_dofs);
  void set_up_partial_supports(const Eigen::MatrixXd& rigid_free);
  const FrameModel& model_;
  DofMap dofs_;
  FreeSystem system_;
  bool free_free_ = false;
  std::vector<int> auxiliary_;
  Eigen::MatrixXd rigid_, mass_rigid_;
  std::unique_ptr<SparseCholesky> static_solver_;
};

// A load history on the frame: F(t_k) = distribution * components.col(k), linear between the times.
struct TransientInput {
  Eigen::VectorXd times;        // s, strictly increasing, at least two
  SparseMatrix distribution;    // all DOFs x components
  Eigen::MatrixXd components;   // components x times (N, N m)
};

enum class InitialState {
  rest,    // u = v = 0 at the first time (the load is switched on as a step)
  static_equilibrium,  // u = G F(t_0), v = 0 (a machine already running under its weight)
};

struct ModalTransientOptions {
  ResponseMethod method = ResponseMethod::mode_displacement;
  ModalDamping damping = ModalDamping::ratio(0.02);
  int mode_count = -1;          // elastic modes used, lowest first; -1: all of the basis
  int output_interval = 1;      // keep every n-th time of the input (the first always)
  InitialState initial = InitialState::static_equilibrium;
  // Integrate the free rigid motions under the unrelieved loads (Eq. 19.7)
  // and add them to the displacement; false: the elastic part under the
  // relieved loads (inertia relief), as for a free-free frame.
  bool include_rigid_motion = false;
  // No output before this time (s): the grid stays every output_interval-th input time from the
  // first, its earlier times are integrated through and not kept (a duty cycle's lead-in).
  double outputs_from = -std::numeric_limits<double>::infinity();
  // Idle workers of a pool may take columns of the displacement (the same numbers without).
  core::WorkShare* share = nullptr;
};

struct TransientResult {
  Eigen::VectorXd times;             // output times, s
  // all DOFs x outputs (m, rad); the elastic part for a free-free or partially
  // supported frame, unless the rigid motion was included
  Eigen::MatrixXd displacement;
  Eigen::MatrixXd modal_coordinates; // elastic modes used x outputs (modal methods; m kg^0.5)
  Eigen::VectorXd frequencies_hz;    // of the elastic modes used
  Eigen::VectorXd damping_ratios;    // of the elastic modes used
  Eigen::MatrixXd rigid_coordinates; // free rigid motions x outputs, when included (M-orthonormal coordinates)
};

// Throws std::invalid_argument for inconsistent sizes, fewer than two times
// or non-increasing times.
TransientResult modal_transient(const FrameDynamics& frame, const ModalBasis& basis, const TransientInput& input,
                                const ModalTransientOptions& options);

}  // namespace framedyn::fem

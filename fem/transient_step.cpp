// Transient steps of a deck (*MODAL DYNAMIC, *DYNAMIC); see transient_step.h.
#include "fem/transient_step.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "fem/direct_integration.h"
#include "fem/static_analysis.h"

namespace framedyn::fem {

namespace {

using core::InputError;

const AnalysisStep& transient_step(const FrameModel& deck, std::size_t step_index, const std::string& deck_name) {
  const AnalysisStep& s = deck.steps.at(step_index);
  if (!s.transient)  // CLI-49
    throw InputError({deck_name, 0, "*STEP"}, "a *MODAL DYNAMIC or *DYNAMIC step", fmt::format("step {} (*{})", s.number, s.procedure));
  return s;
}

// The factors of the load components at time t: constant first, then the amplitudes by name.
double factor(const FrameModel& deck, const std::string& amplitude, double t) {
  return amplitude.empty() ? 1.0 : deck.amplitudes.at(amplitude).at(t);
}

}  // namespace

TransientInput transient_step_loads(const FrameModel& deck, std::size_t step_index) {
  const AnalysisStep& s = deck.steps.at(step_index);
  const TransientSettings& t = s.transient.value();
  // Components: "" (constant nodal loads and the beams' line loads), then each amplitude used.
  std::vector<std::string> names{""};
  for (const std::string& a : s.load_amplitudes)
    if (!a.empty() && std::find(names.begin(), names.end(), a) == names.end()) names.push_back(a);
  FrameModel part = with_step(deck, step_index);
  std::vector<Eigen::VectorXd> columns;
  for (const std::string& name : names) {
    part.loads.clear();
    for (std::size_t i = 0; i < s.loads.size(); ++i)
      if (s.load_amplitudes[i] == name) part.loads.push_back(s.loads[i]);
    part.element_loads = name.empty() ? s.element_loads : std::vector<ElementLoad>{};
    columns.push_back(applied_loads(part));
  }
  TransientInput in;
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (int i = 0; i < columns[c].size(); ++i)
      if (columns[c](i) != 0.0) entries.emplace_back(i, static_cast<int>(c), columns[c](i));
  in.distribution.resize(deck.dof_count(), static_cast<int>(columns.size()));
  in.distribution.setFromTriplets(entries.begin(), entries.end());

  // Times (Eq. 22.2): the grid k dt, the last one the period, and the
  // amplitudes' points strictly inside the period that are not on the grid
  // (closer than 1e-9 dt to a grid time: that grid time stands for them).
  const double dt = t.time_increment, period = t.time_period;
  const long n = static_cast<long>(std::ceil(period / dt * (1.0 - 1e-12)));
  std::vector<double> times;
  for (long k = 0; k < n; ++k) times.push_back(static_cast<double>(k) * dt);
  times.push_back(period);
  for (std::size_t c = 1; c < names.size(); ++c)
    for (double p : deck.amplitudes.at(names[c]).times)
      if (p > 0.0 && p < period) {
        const double k = std::round(p / dt);
        if (std::abs(p - k * dt) > 1e-9 * dt) times.push_back(p);
      }
  std::sort(times.begin(), times.end());
  in.times = Eigen::Map<const Eigen::VectorXd>(times.data(), static_cast<Eigen::Index>(times.size()));
  in.components.resize(static_cast<Eigen::Index>(names.size()), in.times.size());
  for (Eigen::Index k = 0; k < in.times.size(); ++k)
    for (std::size_t c = 0; c < names.size(); ++c) in.components(static_cast<Eigen::Index>(c), k) = factor(deck, names[c], in.times(k));
  return in;
}

TransientStepResult run_transient_step(const FrameModel& deck, std::size_t step_index, const std::string& deck_name) {
  const AnalysisStep& s = transient_step(deck, step_index, deck_name);
  const TransientSettings& settings = *s.transient;
  TransientStepResult r;
  r.step = s.number;
  r.procedure = s.procedure;
  const FrameModel model = with_step(deck, step_index);
  const TransientInput input = transient_step_loads(deck, step_index);
  FrameDynamics frame(model);

  if (s.procedure == "DYNAMIC") {
    NewmarkOptions o;
    o.initial = InitialState::rest;
    o.include_rigid_motion = true;
    r.scheme = fmt::format("Newmark average acceleration (alpha-method with alpha = 0), fixed increment {:g} s", settings.time_increment);
    r.response = direct_transient(frame, input, o);
    return r;
  }

  // *MODAL DYNAMIC: the modes of the nearest *FREQUENCY step before it, with the same supports.
  std::size_t f = step_index;
  while (f > 0 && deck.steps[f - 1].procedure != "FREQUENCY") --f;
  if (f == 0)  // INP-73
    throw InputError({deck_name, 0, "*MODAL DYNAMIC"}, "a *FREQUENCY step before the *MODAL DYNAMIC step (its modes are the basis)",
                     fmt::format("none before step {}", s.number));
  const AnalysisStep& freq = deck.steps[f - 1];
  auto same = [](const std::vector<Constraint>& a, const std::vector<Constraint>& b) {
    std::map<std::pair<int, int>, double> ma, mb;
    for (const Constraint& c : a) ma[{c.node, c.dof}] = c.value;
    for (const Constraint& c : b) mb[{c.node, c.dof}] = c.value;
    return ma == mb;
  };
  if (!same(freq.constraints, s.constraints))  // INP-78
    throw InputError({deck_name, 0, "*MODAL DYNAMIC"},
                     fmt::format("the supports of *FREQUENCY step {} in *MODAL DYNAMIC step {} (its modes are the basis)", freq.number, s.number),
                     freq.constraints.size() != s.constraints.size()
                         ? fmt::format("{} supported DOFs there, {} here", freq.constraints.size(), s.constraints.size())
                         : fmt::format("as many supported DOFs ({}), not the same ones", s.constraints.size()));
  r.frequency_step = freq.number;
  ModalOptions mo;
  mo.mode_count = freq.requested_modes.value_or(1);  // CalculiX's default: one eigenvalue
  const int free = frame.dofs().free_count();
  mo.mode_count = std::max(1, std::min(mo.mode_count, free - 1));  // the eigensolver needs fewer than the free DOFs
  const ModalResult modes = compute_modes(model, mo);
  const ModalBasis basis = modal_basis(frame.dofs(), modes);

  ModalTransientOptions o;
  o.method = ResponseMethod::mode_displacement;  // as CalculiX: no static correction
  o.initial = InitialState::rest;
  o.include_rigid_motion = true;
  const int rigid = static_cast<int>(basis.rigid_body.size()) - basis.elastic_count();
  if (settings.rayleigh) {
    o.damping = ModalDamping::rayleigh_damping(settings.rayleigh_alpha, settings.rayleigh_beta);
  } else {
    // Eq. (22.3): CalculiX numbers all modes of the *FREQUENCY step, rigid ones first.
    std::vector<double> ratios(static_cast<std::size_t>(std::max(basis.elastic_count(), 1)), 0.0);
    for (int j = 0; j < basis.elastic_count(); ++j)
      for (const ModalDampingRange& range : settings.damping_ranges)
        if (j + rigid + 1 >= range.first_mode && j + rigid + 1 <= range.last_mode) ratios[static_cast<std::size_t>(j)] = range.ratio;
    o.damping.ratios = ratios;
    o.damping.rayleigh = false;
  }
  r.scheme = fmt::format("mode superposition over {} modes of step {} (mode displacement, exact for piecewise-linear loads), "
                         "output every {:g} s",
                         static_cast<int>(basis.rigid_body.size()), freq.number, settings.time_increment);
  r.response = modal_transient(frame, basis, input, o);
  return r;
}

}  // namespace framedyn::fem

// A transient step of an input deck run as the deck defines it: *MODAL
// DYNAMIC (mode superposition over the modes of the deck's *FREQUENCY step
// before it, *MODAL DAMPING as CalculiX defines it) or *DYNAMIC (direct
// integration by Newmark's average-acceleration rule), the loads scaled by
// their *AMPLITUDE (constant without one), from rest, for the step's time
// period at its time increment. Theory: docs/theory/fem.md section 22,
// Eqs. (22.1)-(22.4).
#pragma once

#include <string>

#include "fem/frame_model.h"
#include "fem/modal_transient.h"

namespace framedyn::fem {

struct TransientStepResult {
  int step = 0;                  // the step's number in the deck (1, 2, ...)
  std::string procedure;         // "MODAL DYNAMIC" or "DYNAMIC"
  std::string scheme;            // how it was integrated, for the outputs
  int frequency_step = 0;        // *MODAL DYNAMIC: the *FREQUENCY step whose modes were used
  TransientResult response;      // displacements on all DOFs at the output times, SI
};

// The load history of a transient step (Eq. 22.1): one component per
// amplitude (constant loads and the beams' line loads together as one
// component of factor 1), at the step's time grid 0, dt, 2 dt, ... up to the
// period, with the amplitudes' own points inside it added so that the load
// is exactly piecewise linear between the times.
TransientInput transient_step_loads(const FrameModel& deck, std::size_t step_index);

// Runs deck.steps[step_index]. Throws core::InputError (naming the deck's
// step) for a step that is not transient, a *MODAL DYNAMIC step without a
// *FREQUENCY step before it or with other supports than that step's.
TransientStepResult run_transient_step(const FrameModel& deck, std::size_t step_index, const std::string& deck_name);

}  // namespace framedyn::fem

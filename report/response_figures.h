// PNG figures of a forced response (`framedyn run --figures`), the thesis's
// Chapter V time histories: plow force magnitude (Figure 11) and angle
// (Figure 12), the blade's vertical motion, the digging chain force (Figure 17).
#pragma once

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "coupling/rigid_study.h"

namespace framedyn::report {

// Throws report::PlotError, before a long run, if gnuplot cannot be run.
void require_gnuplot();

// Writes the figures the response has into `folder` and returns their file
// names (none without a response). Values in the study's units.
std::vector<std::string> write_response_figures(const coupling::RigidStudy& study, const coupling::RigidResults& results,
                                                const core::ResultsFolder& folder);

}  // namespace framedyn::report

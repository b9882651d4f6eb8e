// The outputs of `framedyn static`: displacements.csv, reactions.csv,
// section_forces.csv (with fiber stresses), static.vtu and summary.json (key
// "frame": the peaks, the force sums, the residual and the free rigid motions,
// docs/theory/fem.md section 19), in the mesh's units with the units from core/units.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fem/frame_model.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"

namespace framedyn::report {

// What the run was asked (summary.json's input entry, the stations per element).
struct StaticRun {
  std::string mesh_path;
  int stations = 3;  // section-force stations per element, ends included (as recovered)
  // Appended to every file name ("_step2": displacements_step2.csv, ...) for
  // one step of a deck with several static steps; empty otherwise.
  std::string file_suffix = {};
  int step = 0;  // that step's number (summary.json's "step"), 0: none
};

// The figures summary.json and the console report, in the mesh's units.
struct StaticPeaks {
  double max_displacement = 0.0;  // the largest translation's magnitude
  int max_displacement_node = 0;  // mesh node number
  double peak_fiber_stress = 0.0;  // the largest |fiber stress| at any station
  int peak_fiber_stress_element = 0;
  Eigen::Vector3d applied_force_sum = Eigen::Vector3d::Zero();   // all nodes
  Eigen::Vector3d reaction_force_sum = Eigen::Vector3d::Zero();  // the constrained nodes
};

StaticPeaks static_peaks(const fem::FrameModel& model, const fem::StaticResult& result, const std::vector<fem::StationResult>& stations);

// `stations` from fem::recover_stations(model, result.displacement, run.stations).
void write_static_results(const fem::FrameModel& model, const fem::StaticResult& result, const std::vector<fem::StationResult>& stations,
                          const StaticRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report

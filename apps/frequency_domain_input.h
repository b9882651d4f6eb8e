// What `framedyn harmonic` and `framedyn random` share: the mesh, its loads
// as the load pattern, the modes, the damping ratio, the output set, and the
// options that choose them. Thin: it reads, checks and calls fem/.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "fem/modal_analysis.h"
#include "fem/modal_frequency_response.h"

namespace framedyn::apps {

struct FrequencyDomainOptions {
  MeshInput mesh;
  double damping_ratio = 0.0;
  int modes = 0;               // 0: the mesh's *FREQUENCY count, else 20
  std::string output_set;      // node set for the tables; empty: all nodes
  int step = 0;                // --step: the input step whose loads and supports are used; 0: the only step with loads
  bool static_correction = true;
  bool figures = true;
  std::string out;
  ProgressFlags progress;
  // Registers mesh, --damping-ratio, --modes, --output-set, --step, --no-static-correction, --no-figures, --out, -v, -q.
  void add_to(CLI::App& cmd, const std::string& default_out_suffix);
  std::string out_dir() const;

 private:
  std::string suffix_;
};

// The frame, ready for a frequency-domain analysis.
struct FrequencyDomainFrame {
  std::unique_ptr<fem::FrameModel> model;       // owned here: frame keeps a reference to it
  std::unique_ptr<fem::FrameDynamics> frame;
  fem::ModalResult modes;
  fem::ModalBasis basis;
  Eigen::VectorXd load;                          // the load pattern on all DOFs (fem::applied_loads), SI
  std::vector<int> output_nodes;                 // node indices of --output-set, or all nodes
  fem::FrequencyResponseOptions response;
  int step = 0;                                  // the input step used (its number); 0: a deck without *STEP
};

// Reads the mesh, takes the step --step names (or the deck's only step with
// loads) and solves for the modes. Throws InputError for a mesh without loads
// (`analysis` names the command), a --step the deck does not have, a deck with
// several steps with loads and no --step, an unknown --output-set or more
// --modes than the frame has free DOFs.
FrequencyDomainFrame prepare_frequency_domain(const FrequencyDomainOptions& options, const std::string& analysis, Progress& progress);

}  // namespace framedyn::apps

// The outputs of `framedyn harmonic` (frf.csv, frf.png, fiber_stress.png) and
// `framedyn random` (response_psd.csv, rms.csv, response_psd.png,
// stress_psd.png), each with its summary.json (key "frame": the modes used
// and the peaks of the response, where and at which frequency), in the mesh's
// units with the units from core/units.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fem/frame_model.h"
#include "fem/harmonic_response.h"
#include "fem/load_psd.h"
#include "fem/modal_analysis.h"
#include "fem/random_response.h"

namespace framedyn::report {

// What the run was asked (summary.json's input entry) and what it writes.
struct FrequencyResponseRun {
  std::string mesh_path;
  double damping_ratio = 0.0;
  std::string output_set;  // the tables' node set; empty: all nodes
  std::string psd_path;    // random: the load PSD's file
  bool figures = true;     // the PNG figures (gnuplot)
  std::vector<int> output_nodes;  // node indices of the tables' rows
  int step = 0;                   // the input step whose loads are the amplitudes; 0: a deck without *STEP
};

// Where the harmonic response peaks: the largest translation amplitude's node,
// direction and frequency, and (if the frame has stress points) the largest
// fiber-stress amplitude's frequency.
struct HarmonicPeaks {
  int node = 0;  // mesh node number
  std::string dof;
  double frequency_hz = 0.0;
  bool has_stress = false;
  double stress_frequency_hz = 0.0;
};
HarmonicPeaks harmonic_peaks(const fem::FrameModel& model, const fem::HarmonicResult& result);

// frf.csv, the figures if asked (`stage("figures")` before them) and
// summary.json; returns the figures' file names.
std::vector<std::string> write_harmonic_results(const fem::FrameModel& model, const fem::HarmonicResult& result, const fem::ModalResult& modes,
                                                const FrequencyResponseRun& run, const core::ResultsFolder& folder,
                                                const std::function<void(const std::string&)>& stage = {});

// Where the random response peaks: the largest translation PSD's node,
// direction and frequency, the largest translation RMS's node and direction,
// the largest fiber-stress PSD's frequency, and the load factor's RMS over the band.
struct RandomPeaks {
  int psd_node = 0;  // mesh node numbers
  std::string psd_dof;
  double psd_frequency_hz = 0.0;
  int rms_node = 0;
  std::string rms_dof;
  bool has_stress = false;
  double stress_frequency_hz = 0.0;
  double load_factor_rms = 0.0;
};
RandomPeaks random_peaks(const fem::FrameModel& model, const fem::RandomResult& result);

// response_psd.csv, rms.csv, the figures if asked (`stage("figures")` before
// them) and summary.json; returns the figures' file names.
std::vector<std::string> write_random_results(const fem::FrameModel& model, const fem::RandomResult& result, const fem::LoadPsd& psd,
                                              const fem::ModalResult& modes, const FrequencyResponseRun& run, const core::ResultsFolder& folder,
                                              const std::function<void(const std::string&)>& stage = {});

}  // namespace framedyn::report

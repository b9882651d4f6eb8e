// CalculiX (ccx) as a peer code for tests and benchmarks.
//
// Runs the CalculiX solver on the same beam mesh that framedyn analyses, so a
// test can compare eigenfrequencies or static displacements with an
// independent program. The caller writes the model data (*NODE, *ELEMENT,
// *BEAM SECTION, *MATERIAL, *BOUNDARY, ...; no *STEP) to an .inp file; these
// functions add one analysis step, run `ccx` in a working directory and read
// the results back from the .dat file. Standard library and POSIX only.
//
// What CalculiX does with B31 beams (it expands them into C3D8I bricks), how
// far its results lie from beam theory and which tolerances a comparison can
// justify are in docs/calculix_peer.md. In short: bending modes agree with a
// Timoshenko beam to about 1 % once (k h)^2 is small, twist modes run 6-10 %
// high, and meshes refined far below the section depth grow spurious
// section-distortion modes.
//
// Note for test code inside `namespace framedyn`: this header declares
// `framedyn::testing`, which hides GoogleTest's `::testing` there; write
// `::testing::Test` in such code.

#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace framedyn::testing {

// True if an executable named `ccx` is found in a directory listed in PATH.
bool calculix_available();

// What one CalculiX run produced.
struct CalculixResult {
  // Eigenfrequencies in Hz (CalculiX's "cycles/time" column, i.e. Hz when the
  // model is in seconds), ascending, one per requested mode. A rigid-body mode
  // whose eigenvalue came out slightly negative is reported as 0.
  std::vector<double> frequencies_hz;
  // Wall-clock time of the ccx process, in seconds.
  double wall_seconds = 0.0;
  // Peak resident set size of the ccx process, in KiB (from wait4's rusage).
  long peak_rss_kib = 0;
  // Full text of the job's .dat file.
  std::string dat_text;
  // Static runs only: displacement (U1, U2, U3) of each requested node, in
  // the global frame and the model's length unit, keyed by node id.
  std::map<int, std::array<double, 3>> displacements;
  // Transient runs only: the end time of every increment (s, ascending) and,
  // per increment, the displacements (U1, U2, U3) of the requested nodes.
  std::vector<double> history_times;
  std::vector<std::map<int, std::array<double, 3>>> history;
};

// Natural frequencies of a model. Writes `workdir`/job.inp (created if need
// be) as
//     *INCLUDE, INPUT=<absolute model path>
//     *STEP
//     *FREQUENCY
//     <n_modes>
//     *END STEP
// runs `ccx -i job` there (output in `workdir`/ccx.log) and parses the
// eigenvalue table of job.dat.
// Throws std::invalid_argument if the model file does not exist or
// n_modes < 1, and std::runtime_error (with the tail of the log) if ccx is
// not found, fails, reports an *ERROR, prints fewer than n_modes eigenvalues,
// or returns spurious negative eigenvalues (which CalculiX 2.20 does without
// warning when n_modes is large for a small model; ask for fewer modes).
CalculixResult run_calculix_frequency(const std::string& model_inp_path,
                                      int n_modes,
                                      const std::string& workdir);

// Linear static response. Writes `workdir`/job.inp as
//     *INCLUDE, INPUT=<absolute model path>
//     *NSET, NSET=FRAMEDYN_PEER_OUT      (the ids in node_ids)
//     *STEP
//     *STATIC
//     <load_lines>                       (e.g. "*CLOAD\n11, 3, -100.\n")
//     *NODE PRINT, NSET=FRAMEDYN_PEER_OUT
//     U
//     *END STEP
// runs ccx and returns the displacements of exactly the nodes in node_ids.
// Only nodes of the caller's model can be asked for: the nodes CalculiX
// generates when it expands beams are never printed. Throws as
// run_calculix_frequency does, and std::runtime_error if a requested node is
// missing from the output.
CalculixResult run_calculix_static(const std::string& model_inp_path,
                                   const std::string& load_lines,
                                   const std::vector<int>& node_ids,
                                   const std::string& workdir);

// A deck of several static steps: `step_bodies[k]` is the text between the
// k-th *STEP and *END STEP (*STATIC and its loads; CalculiX carries loads over
// from step to step). Returns, per step, the displacements of node_ids, as
// run_calculix_static does for one step.
std::vector<std::map<int, std::array<double, 3>>> run_calculix_static_steps(const std::string& model_inp_path,
                                                                            const std::vector<std::string>& step_bodies,
                                                                            const std::vector<int>& node_ids,
                                                                            const std::string& workdir);

// A transient step (*DYNAMIC, run by direct integration of the expanded
// brick model). Writes `workdir`/job.inp as
//     *INCLUDE, INPUT=<absolute model path>   (with its *AMPLITUDEs)
//     *NSET, NSET=FRAMEDYN_PEER_OUT           (the ids in node_ids)
//     *STEP, INC=1000000
//     <procedure_lines>                       (e.g. "*DYNAMIC, DIRECT, ALPHA=0\n2.5e-4, 0.1\n")
//     <load_lines>                            (e.g. "*CLOAD, AMPLITUDE=RAMP\n21, 3, -10.\n")
//     *NODE PRINT, NSET=FRAMEDYN_PEER_OUT
//     U
//     *END STEP
// and returns the displacement history of node_ids (history_times, history).
// CalculiX 2.20's *MODAL DYNAMIC step crashes on expanded beams (B31 and
// B32, docs/calculix_peer.md), so the modal procedure cannot be compared.
// Throws as run_calculix_static does.
CalculixResult run_calculix_dynamic(const std::string& model_inp_path, const std::string& procedure_lines,
                                    const std::string& load_lines, const std::vector<int>& node_ids,
                                    const std::string& workdir);

}  // namespace framedyn::testing

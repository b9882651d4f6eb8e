// Options shared by the commands that read a mesh: the file and its units.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::apps {

struct MeshInput {
  std::string path;
  std::string units;    // empty: take the mesh's "** units:" line
  std::string dialect;  // --inp-dialect: "abaqus", "calculix"; empty: Abaqus's reading, with a warning where they differ
  void add_options(CLI::App& cmd);
  // The reader's warnings (a CIRC section read without --inp-dialect) are
  // printed on stderr here and kept in the model's reader_warnings, which
  // every command's writer lists in summary.json.
  fem::FrameModel load() const;
};

// Node indices of the node set `set` (--output-set; any case), all nodes when
// `set` is empty. Throws InputError naming the mesh's sets for an unknown one.
std::vector<int> output_set_nodes(const fem::FrameModel& model, const std::string& mesh_path, const std::string& set);
// Indices into model.beams of the beams of the element set `set`
// (--element-set; any case), every beam when `set` is empty. Throws InputError
// (CLI-77) naming the mesh's sets with beams for an unknown set or one
// without beams.
std::vector<int> output_set_beams(const fem::FrameModel& model, const std::string& mesh_path, const std::string& set);

}  // namespace framedyn::apps

// Options shared by the commands that read a mesh: the file and its units.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "fem/frame_model.h"

namespace framedyn::apps {

struct MeshInput {
  std::string path;
  std::string units;  // empty: take the mesh's "** units:" line
  void add_options(CLI::App& cmd);
  fem::FrameModel load() const;
};

}  // namespace framedyn::apps

// Mesh file and unit options; see mesh_input.h.
#include "apps/mesh_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "apps/progress.h"
#include "core/error.h"
#include "fem/inp_reader.h"

namespace framedyn::apps {

void MeshInput::add_options(CLI::App& cmd) {
  cmd.add_option("mesh", path, "Frame mesh (.inp, Abaqus/CalculiX beam subset)")->required();
  cmd.add_option("--units", units,
                 "Unit system of the mesh: in-lbf-s, m-N-s (SI) or mm-N-s. Needed unless the mesh has a line '** units: NAME'");
  cmd.add_option("--inp-dialect", dialect,
                 "How to read lines CalculiX and Abaqus read differently (SECTION=CIRC: radius for abaqus, diameter for calculix); "
                 "default: abaqus, with a warning")
      ->check(CLI::Validator(
          [](std::string& s) { return s == "abaqus" || s == "calculix" ? std::string() : "expected abaqus or calculix, found '" + s + "'"; }, ""));
}

fem::FrameModel MeshInput::load(std::vector<core::Warning>* warnings) const {
  fem::InpReadOptions o;
  if (!units.empty()) o.units = units;
  if (dialect == "abaqus") o.dialect = fem::InpDialect::abaqus;
  if (dialect == "calculix") o.dialect = fem::InpDialect::calculix;
  std::vector<core::Warning> own;
  o.warnings = warnings ? warnings : &own;
  fem::FrameModel model = fem::read_inp(path, o);
  for (const core::Warning& w : own)
    if (!quiet_console()) fmt::print(stderr, "framedyn: warning [{}]: {}\n", w.code, w.message);
  return model;
}

std::vector<int> output_set_nodes(const fem::FrameModel& model, const std::string& mesh_path, const std::string& set) {
  if (!set.empty()) {
    std::string name = set;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    const auto it = model.node_sets.find(name);
    if (it == model.node_sets.end()) {
      std::string known;
      for (const auto& [known_set, nodes] : model.node_sets) known += (known.empty() ? "" : ", ") + known_set;
      throw core::InputError({mesh_path, 0, "--output-set"},
                             fmt::format("a node set of the mesh ({})", known.empty() ? std::string("it defines none") : known), "'" + set + "'");
    }
    return it->second;
  }
  std::vector<int> all;
  for (int n = 0; n < static_cast<int>(model.nodes.size()); ++n) all.push_back(n);
  return all;
}

}  // namespace framedyn::apps

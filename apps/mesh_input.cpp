// Mesh file and unit options; see mesh_input.h.
#include "apps/mesh_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "apps/command_line.h"
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

fem::FrameModel MeshInput::load() const {
  fem::InpReadOptions o;
  if (!units.empty()) o.units = units;
  if (dialect == "abaqus") o.dialect = fem::InpDialect::abaqus;
  if (dialect == "calculix") o.dialect = fem::InpDialect::calculix;
  fem::FrameModel model = fem::read_inp(path, o);
  for (const core::Warning& w : model.reader_warnings) print_warning(w);
  return model;
}

namespace {

// Set names are stored upper case (fem/frame_model.h).
std::string upper(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

}  // namespace

std::vector<int> output_set_nodes(const fem::FrameModel& model, const std::string& mesh_path, const std::string& set) {
  if (!set.empty()) {
    const auto it = model.node_sets.find(upper(set));
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

std::vector<int> output_set_beams(const fem::FrameModel& model, const std::string& mesh_path, const std::string& set) {
  std::vector<int> beams;
  if (set.empty()) {
    for (int b = 0; b < static_cast<int>(model.beams.size()); ++b) beams.push_back(b);
    return beams;
  }
  const auto it = model.element_sets.find(upper(set));
  if (it != model.element_sets.end())
    for (int id : it->second)
      if (const int b = model.beam_index(id); b >= 0) beams.push_back(b);
  std::sort(beams.begin(), beams.end());
  beams.erase(std::unique(beams.begin(), beams.end()), beams.end());
  if (beams.empty()) {  // CLI-77
    std::string known;
    for (const auto& [known_set, ids] : model.element_sets)
      if (std::any_of(ids.begin(), ids.end(), [&](int id) { return model.beam_index(id) >= 0; })) known += (known.empty() ? "" : ", ") + known_set;
    throw core::InputError(command_line("--element-set"),
                           fmt::format("an element set of {} with beam elements ({})", mesh_path, known.empty() ? std::string("it has none") : known),
                           "'" + set + "'" + (it == model.element_sets.end() ? "" : " (no beam elements)"));
  }
  return beams;
}

}  // namespace framedyn::apps

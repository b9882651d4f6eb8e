// Mesh file and unit options; see mesh_input.h.
#include "apps/mesh_input.h"

#include "fem/inp_reader.h"

namespace framedyn::apps {

void MeshInput::add_options(CLI::App& cmd) {
  cmd.add_option("mesh", path, "Frame mesh (.inp, Abaqus/CalculiX beam subset)")->required();
  cmd.add_option("--units", units,
                 "Unit system of the mesh: in-lbf-s, m-N-s (SI) or mm-N-s. Needed unless the mesh has a line '** units: NAME'");
}

fem::FrameModel MeshInput::load() const {
  fem::InpReadOptions o;
  if (!units.empty()) o.units = units;
  return fem::read_inp(path, o);
}

}  // namespace framedyn::apps

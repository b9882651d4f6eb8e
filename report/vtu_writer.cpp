// ASCII VTU writer (VTK XML UnstructuredGrid, cell type 3 = VTK_LINE for
// two-node beams, 21 = VTK_QUADRATIC_EDGE for three-node beams).
#include "report/vtu_writer.h"

#include <fmt/format.h>

#include <stdexcept>

#include "report/csv_writer.h"

namespace framedyn::report {

namespace {

void write_field(std::string& out, const VtuField& f, std::size_t count) {
  if (f.values.size() != count * static_cast<std::size_t>(f.components))
    throw std::logic_error(fmt::format("VTU field {} has {} values for {} entries", f.name, f.values.size(), count));
  out += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", f.name, f.components);
  for (std::size_t i = 0; i < count; ++i) {
    out += "         ";
    for (int c = 0; c < f.components; ++c) out += " " + core::format_number(f.values[i * static_cast<std::size_t>(f.components) + static_cast<std::size_t>(c)]);
    out += "\n";
  }
  out += "        </DataArray>\n";
}

}  // namespace

std::string vtu_document(const fem::FrameModel& model, double length_scale, const std::vector<VtuField>& point_fields,
                         const std::vector<VtuField>& cell_fields) {
  const std::size_t np = model.nodes.size(), nc = model.beams.size();
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <UnstructuredGrid>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", np, nc);
  out += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const fem::Node& n : model.nodes) {
    const Eigen::Vector3d x = n.position * length_scale;
    out += fmt::format("          {} {} {}\n", core::format_number(x.x()), core::format_number(x.y()), core::format_number(x.z()));
  }
  out += "        </DataArray>\n      </Points>\n";
  out += "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  // Three-node beams are VTK_QUADRATIC_EDGE (21): end, end, midside.
  for (const fem::BeamElement& b : model.beams)
    out += b.is_quadratic() ? fmt::format("          {} {} {}\n", b.node_a, b.node_b, b.node_m) : fmt::format("          {} {}\n", b.node_a, b.node_b);
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const fem::BeamElement& b : model.beams) out += fmt::format("          {}\n", offset += b.is_quadratic() ? 3 : 2);
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const fem::BeamElement& b : model.beams) out += b.is_quadratic() ? "          21\n" : "          3\n";
  out += "        </DataArray>\n      </Cells>\n";
  out += "      <PointData>\n";
  {
    VtuField ids{"node_id", 1, {}};
    for (const fem::Node& n : model.nodes) ids.values.push_back(n.id);
    write_field(out, ids, np);
  }
  for (const VtuField& f : point_fields) write_field(out, f, np);
  out += "      </PointData>\n      <CellData>\n";
  {
    VtuField ids{"element_id", 1, {}}, sec{"section", 1, {}};
    for (const fem::BeamElement& b : model.beams) {
      ids.values.push_back(b.id);
      sec.values.push_back(b.section);
    }
    write_field(out, ids, nc);
    write_field(out, sec, nc);
  }
  for (const VtuField& f : cell_fields) write_field(out, f, nc);
  out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace framedyn::report

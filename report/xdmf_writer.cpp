// XDMF 3 + HDF5 time series (see xdmf_writer.h). The HDF5 file is written
// through HDF5's C API without compression or chunking (contiguous datasets
// write at disk speed); the XDMF file is text written by ResultsFolder.
#include "report/xdmf_writer.h"

#include <hdf5.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <tuple>
#include <stdexcept>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/number_text.h"

namespace framedyn::report {

namespace {

// Text safe inside an XML attribute value.
std::string xml_attribute(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("cannot write the HDF5 file: " + what);
}

}  // namespace

std::string hdf5_dataset_name(const std::string& field_name) {
  std::string name = field_name.substr(0, field_name.find(" ["));
  for (char& c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
  return name.empty() ? std::string("field") : name;
}

struct XdmfSeries::State {
  const core::ResultsFolder* folder = nullptr;
  std::string name, h5_file;
  std::filesystem::path h5_path;
  hid_t file = -1;
  std::size_t points = 0, cells = 0;
  std::string topology, geometry;  // the first grid's XML
  std::string grids;               // every grid's XML
  std::string mesh_attributes;     // node_id, element_id, section
  int steps = 0, planned = 0;
  std::vector<std::pair<std::string, hid_t>> series;  // per field its dataset (all steps), in the order of the first add()

  // No NaN or infinity reaches the file (as ResultsFolder::write_text checks
  // every text file): the message names the array, the entry and the component.
  void refuse_non_finite(const std::vector<double>& values, int components, const std::string& what) const {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw core::NumericalError(fmt::format(
            "{}: {}, entry {}, component {} (both counted from 0) is {}: the computation broke down before this output (a NaN or an infinity), "
            "and framedyn writes no file with non-finite numbers, so the run stops here. Check the inputs this quantity depends on for zero, "
            "missing or extreme values, and the response for a divergence",
            h5_file, what, i / static_cast<std::size_t>(components), i % static_cast<std::size_t>(components), std::isnan(values[i]) ? "NaN" : "infinite"));
  }

  // Creation properties without modification times, so that two runs write
  // the same bytes (HDF5 stamps objects with their creation time by default).
  hid_t timeless(hid_t kind) const {
    const hid_t p = H5Pcreate(kind);
    H5Pset_obj_track_times(p, 0);
    return p;
  }

  void group(const char* path) {
    const hid_t properties = timeless(H5P_GROUP_CREATE);
    const hid_t g = H5Gcreate2(file, path, H5P_DEFAULT, properties, H5P_DEFAULT);
    H5Pclose(properties);
    if (g < 0) throw std::runtime_error(fmt::format("cannot write the HDF5 file {}: cannot create {}", h5_path.string(), path));
    H5Gclose(g);
  }

  // A dataset of `rows` x `columns` values (columns 1: a 1-D dataset) at `path`.
  void write(const std::string& path, hid_t type, const void* data, std::size_t rows, int columns) {
    const hsize_t dims[2] = {rows, static_cast<hsize_t>(columns)};
    const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
    const hid_t properties = timeless(H5P_DATASET_CREATE);
    const hid_t set = H5Dcreate2(file, path.c_str(), type, space, H5P_DEFAULT, properties, H5P_DEFAULT);
    H5Pclose(properties);
    H5Sclose(space);
    if (set < 0) throw std::runtime_error(fmt::format("cannot write the HDF5 file {}: cannot create {}", h5_path.string(), path));
    const herr_t status = rows == 0 ? 0 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
    H5Dclose(set);
    check(status, fmt::format("{}: {}", h5_path.string(), path));
  }

  // The XDMF DataItem naming dataset `path` of `rows` x `columns` values.
  std::string item(const std::string& path, std::size_t rows, int columns, const char* number_type, int precision) const {
    const std::string dims = columns == 1 ? std::to_string(rows) : fmt::format("{} {}", rows, columns);
    return fmt::format("<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">{}:{}</DataItem>", dims, number_type,
                       precision, h5_file, path);
  }

  // Field f at the current step: row `steps` of its dataset (steps x count x
  // components, created at the first step), named in the grid's XML as a slab.
  void field(const VtuField& f, const char* center, std::size_t count, std::string& xml) {
    if (f.values.size() != count * static_cast<std::size_t>(f.components))
      throw std::logic_error(fmt::format("XDMF field {} has {} values for {} entries", f.name, f.values.size(), count));
    refuse_non_finite(f.values, f.components, fmt::format("{} of step {}", f.name, steps + 1));
    const std::string path = fmt::format("/{}/{}", center[0] == 'N' ? "point" : "cell", hdf5_dataset_name(f.name));
    const int rank = f.components == 1 ? 2 : 3;
    const hsize_t dims[3] = {static_cast<hsize_t>(planned), count, static_cast<hsize_t>(f.components)};
    auto at = std::find_if(series.begin(), series.end(), [&](const auto& e) { return e.first == path; });
    if (at == series.end()) {
      if (steps != 0) throw std::logic_error("XDMF field " + f.name + " appears after the first step");
      const hid_t space = H5Screate_simple(rank, dims, nullptr);
      const hid_t properties = timeless(H5P_DATASET_CREATE);
      const hid_t set = H5Dcreate2(file, path.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, properties, H5P_DEFAULT);
      H5Pclose(properties);
      H5Sclose(space);
      if (set < 0) throw std::runtime_error(fmt::format("cannot write the HDF5 file {}: cannot create {}", h5_path.string(), path));
      series.emplace_back(path, set);
      at = std::prev(series.end());
    }
    const hsize_t start[3] = {static_cast<hsize_t>(steps), 0, 0}, block[3] = {1, count, static_cast<hsize_t>(f.components)};
    const hid_t file_space = H5Dget_space(at->second);
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, block, nullptr);
    const hid_t memory = H5Screate_simple(rank, block, nullptr);
    const herr_t status = H5Dwrite(at->second, H5T_NATIVE_DOUBLE, memory, file_space, H5P_DEFAULT, f.values.data());
    H5Sclose(memory);
    H5Sclose(file_space);
    check(status, fmt::format("{}: {}", h5_path.string(), path));
    // The row as XDMF 3's HDF5 controller names a slab (what libXdmf3 itself
    // writes and ParaView's Xdmf3 readers read): file:dataset|start:stride:count:dimensions.
    const std::string shape = f.components == 1 ? std::to_string(count) : fmt::format("{} {}", count, f.components);
    const std::string slab = f.components == 1 ? fmt::format("{} 0:1 1:1 {}:{} {}", steps, count, planned, count)
                                               : fmt::format("{} 0 0:1 1 1:1 {} {}:{} {} {}", steps, count, f.components, planned, count, f.components);
    xml += fmt::format(
        "        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n"
        "          <DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:{}|{}</DataItem>\n        </Attribute>\n",
        xml_attribute(f.name), f.components == 3 ? "Vector" : "Scalar", center, shape, h5_file, path, slab);
  }
};

XdmfSeries::XdmfSeries(const core::ResultsFolder& folder, const std::string& name, const fem::FrameModel& model, double length_scale, int steps)
    : s_(std::make_unique<State>()) {
  State& s = *s_;
  s.planned = steps;
  s.folder = &folder;
  s.name = name;
  s.h5_file = name + ".h5";
  s.h5_path = folder.path_of(s.h5_file);
  s.points = model.nodes.size();
  s.cells = model.beams.size();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions below, not HDF5's stack dump on stderr
  {
    auto gate = core::hold_output_gate();  // created inside the registered partial folder, whole or not at all
    s.file = H5Fcreate(s.h5_path.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, H5P_DEFAULT);
  }
  if (s.file < 0) throw std::runtime_error("cannot create the HDF5 file " + s.h5_path.string());

  for (const char* g : {"/mesh", "/point", "/cell"}) s.group(g);
  std::vector<double> xyz;
  std::vector<long long> node_ids, element_ids, sections;
  xyz.reserve(3 * s.points);
  for (const fem::Node& n : model.nodes) {
    for (int d = 0; d < 3; ++d) xyz.push_back(n.position(d) * length_scale);
    node_ids.push_back(n.id);
  }
  s.refuse_non_finite(xyz, 3, "the node coordinates");
  bool linear = false, quadratic = false;
  for (const fem::BeamElement& b : model.beams) {
    (b.is_quadratic() ? quadratic : linear) = true;
    element_ids.push_back(b.id);
    sections.push_back(b.section);
  }
  // Connectivity: node indices (0-based, the order of /mesh/geometry).
  std::vector<long long> topology;
  for (const fem::BeamElement& b : model.beams) {
    if (linear && quadratic) topology.insert(topology.end(), b.is_quadratic() ? std::initializer_list<long long>{34} : std::initializer_list<long long>{2, 2});
    topology.push_back(b.node_a);
    topology.push_back(b.node_b);
    if (b.is_quadratic()) topology.push_back(b.node_m);
  }
  s.write("/mesh/geometry", H5T_NATIVE_DOUBLE, xyz.data(), s.points, 3);
  s.write("/mesh/node_id", H5T_NATIVE_LLONG, node_ids.data(), s.points, 1);
  s.write("/mesh/element_id", H5T_NATIVE_LLONG, element_ids.data(), s.cells, 1);
  s.write("/mesh/section", H5T_NATIVE_LLONG, sections.data(), s.cells, 1);
  if (linear && quadratic) {  // XDMF Mixed: per cell its type (2 Polyline + node count, 34 Edge_3) and nodes
    s.write("/mesh/topology", H5T_NATIVE_LLONG, topology.data(), topology.size(), 1);
    s.topology = fmt::format("        <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">\n          {}\n        </Topology>\n", s.cells,
                             s.item("/mesh/topology", topology.size(), 1, "Int", 8));
  } else {
    const int per = quadratic ? 3 : 2;
    s.write("/mesh/topology", H5T_NATIVE_LLONG, topology.data(), s.cells, per);
    s.topology = fmt::format("        <Topology TopologyType=\"{}\" NumberOfElements=\"{}\"{}>\n          {}\n        </Topology>\n",
                             quadratic ? "Edge_3" : "Polyline", s.cells, quadratic ? "" : " NodesPerElement=\"2\"",
                             s.item("/mesh/topology", s.cells, per, "Int", 8));
  }
  s.geometry = fmt::format("        <Geometry GeometryType=\"XYZ\">\n          {}\n        </Geometry>\n", s.item("/mesh/geometry", s.points, 3, "Float", 8));
  for (const auto& [label, path, center, count] :
       {std::tuple{"node_id", "/mesh/node_id", "Node", s.points}, std::tuple{"element_id", "/mesh/element_id", "Cell", s.cells},
        std::tuple{"section", "/mesh/section", "Cell", s.cells}})
    s.mesh_attributes += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"{}\">\n          {}\n        </Attribute>\n", label,
                                     center, s.item(path, count, 1, "Int", 8));
}

XdmfSeries::~XdmfSeries() {
  if (!s_) return;
  for (const auto& e : s_->series) H5Dclose(e.second);
  if (s_->file >= 0) H5Fclose(s_->file);
}

void XdmfSeries::add(double time, const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields) {
  State& s = *s_;
  if (s.steps >= s.planned) throw std::logic_error(fmt::format("XDMF series {}: more than the {} steps planned", s.name, s.planned));
  std::string xml = fmt::format("      <Grid Name=\"{}\" GridType=\"Uniform\">\n", xml_attribute(s.name));
  // The first grid holds the mesh; the others include it (FEniCS's xpointer).
  // and its node_id, element_id and section attributes (the light data of a
  // step is then its time and its fields only).
  xml += fmt::format("        <Time Value=\"{}\" />\n", core::format_number(time));
  xml += s.steps == 0 ? s.topology + s.geometry + s.mesh_attributes
                      : "        <xi:include xpointer=\"xpointer(/Xdmf/Domain/Grid/Grid[1]/*[self::Topology or self::Geometry or "
                        "@Name='node_id' or @Name='element_id' or @Name='section'])\" />\n";
  for (const VtuField& f : point_fields) s.field(f, "Node", s.points, xml);
  for (const VtuField& f : cell_fields) s.field(f, "Cell", s.cells, xml);
  xml += "      </Grid>\n";
  s.grids += xml;
  ++s.steps;
}

void XdmfSeries::finish() {
  State& s = *s_;
  if (s.steps != s.planned) throw std::logic_error(fmt::format("XDMF series {}: {} steps written of the {} planned", s.name, s.steps, s.planned));
  for (const auto& e : s.series) H5Dclose(e.second);
  s.series.clear();
  const herr_t closed = H5Fclose(s.file);
  s.file = -1;
  check(closed, s.h5_path.string());
  std::string xdmf = "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n  <Domain>\n";
  xdmf += fmt::format("    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", xml_attribute(s.name));
  xdmf += s.grids;
  xdmf += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  s.folder->write_text(s.name + ".xdmf", xdmf);
}

}  // namespace framedyn::report

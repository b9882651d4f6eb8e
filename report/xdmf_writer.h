// ParaView output in one pair of files per series: XDMF 3 (the .xdmf, XML
// light data: what each grid is and where its arrays lie) and HDF5 (the .h5,
// the heavy data), as FEniCS writes it: Xdmf Version="3.0", a Domain holding
// one Grid GridType="Collection" CollectionType="Temporal", one Uniform grid
// per time whose Topology and Geometry the first grid defines and the others
// xi:include. The mesh is stored once (/mesh), each field once for all times
// (/point/<field>, /cell/<field>: steps x count x components), each time's
// grid naming its row as a slab (file.h5:/dataset|start:stride:count:dimensions,
// libXdmf3's own notation): a few large datasets write far
// faster than one small dataset per field and time.
// Beams are XDMF Polyline (two nodes) or Edge_3 (three: end, end, midside,
// as VTK_QUADRATIC_EDGE), a mesh with both a Mixed topology.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fem/frame_model.h"
#include "report/vtu_writer.h"

namespace framedyn::report {

// A time series written step by step: the HDF5 file <name>.h5 is created in
// the results folder at construction (mesh, node and element ids, sections),
// holds `steps` rows per field, filled one per add(), and finish() closes it and writes
// <name>.xdmf. Not thread-safe (HDF5's serial library): call from one thread.
class XdmfSeries {
 public:
  // `length_scale` turns SI coordinates into output units (1 / metres per unit).
  XdmfSeries(const core::ResultsFolder& folder, const std::string& name, const fem::FrameModel& model, double length_scale, int steps);
  ~XdmfSeries();  // closes the HDF5 file if finish() was not reached (an exception)
  XdmfSeries(const XdmfSeries&) = delete;
  XdmfSeries& operator=(const XdmfSeries&) = delete;

  // The next time (for mode shapes: the mode number) with its fields; every
  // step carries the fields of the first (std::logic_error otherwise).
  void add(double time, const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields);
  void finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

// The name of a field's HDF5 dataset: the field name up to its unit
// ("displacement [in]" -> "displacement"), other characters than letters,
// digits, '_', '-' and '.' replaced by '_'.
std::string hdf5_dataset_name(const std::string& field_name);

}  // namespace framedyn::report

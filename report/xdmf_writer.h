// ParaView output in one pair of files per series: XDMF 3 (the .xdmf, XML
// light data: what each grid is and where its arrays lie) and HDF5 (the .h5,
// the heavy data), as FEniCS writes it: Xdmf Version="3.0", a Domain holding
// one Grid GridType="Collection" CollectionType="Temporal", one Uniform grid
// per time whose Topology and Geometry the first grid defines and the others
// xi:include. The mesh is stored once (/mesh), each time's fields under
// /step_NNNNN; point fields with 1 or 3 components, cell fields likewise.
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
// grows by one group per add(), and finish() closes it and writes
// <name>.xdmf. Not thread-safe (HDF5's serial library): call from one thread.
class XdmfSeries {
 public:
  // `length_scale` turns SI coordinates into output units (1 / metres per unit).
  XdmfSeries(const core::ResultsFolder& folder, const std::string& name, const fem::FrameModel& model, double length_scale);
  ~XdmfSeries();  // closes the HDF5 file if finish() was not reached (an exception)
  XdmfSeries(const XdmfSeries&) = delete;
  XdmfSeries& operator=(const XdmfSeries&) = delete;

  // One time (for mode shapes: the mode number) with its fields; every step
  // should carry the same field names for ParaView to follow them in time.
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

// VTK unstructured-grid (.vtu, ASCII XML) output of a frame mesh for
// ParaView: nodes as points, beam elements as lines, with any number of
// point fields (displacements, mode shapes) and cell fields (section forces).
// Values are written in the model's input units (the caller converts).
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::report {

struct VtuField {
  std::string name;             // e.g. "mode_01_translation [in]"
  int components = 1;           // 1 or 3
  std::vector<double> values;   // size = components * (points or cells)
};

// `length_scale` turns SI coordinates into output units (1 / metres per unit).
std::string vtu_document(const fem::FrameModel& model, double length_scale, const std::vector<VtuField>& point_fields,
                         const std::vector<VtuField>& cell_fields);

}  // namespace framedyn::report

// The frame transient study's outputs (coupling/frame_study.h runs it): the
// CSV tables, the ParaView time series and the summary's "frame" object, every
// number in the study's units with the unit from core/units' tables.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

#include "core/results_folder.h"
#include "coupling/frame_study.h"
#include "report/plot.h"

namespace framedyn::report {

// frame_modes.csv; with element-set outputs frame_rails_envelope.csv,
// frame_rails_series.csv and frame_sections_<name>.csv (history); per
// node-set output frame_nodes_<name>.csv; the ParaView series of
// request.paraview: frame_response.xdmf + frame_response.h5 (xdmf) or
// frame_response.pvd + frame_response_NNNNN.vtu (vtu); in the study's units.
void write_frame_outputs(const coupling::FrameStudyResults& results, const coupling::FrameStudyRequest& request, const core::ResultsFolder& folder,
                         const std::function<void(int, int)>& written = {});  // written(files done, files in all)
// The summary's "frame" object as JSON text: modes[i].frequency_hz,
// peak_bending_moment.<element output> (left_rail / right_rail in the
// pipeline), peak_normal_stress (value + unit, where and when),
// bending_share, outputs.<name> (every output set's peaks).
nlohmann::ordered_json frame_summary(const coupling::FrameStudyResults& results, const coupling::FrameStudyRequest& request);

// The total (static + dynamic) von Mises stress over time at the top `count`
// hot spots by steady peak von Mises (docs/theory/coupling.md section 10), one
// series each, named by output, X and section point; the title says where
// steady operation starts. No series when there are no hot spots.
LinePlot hot_spot_stress_figure(const coupling::FrameStudyResults& results, const core::UnitSystem& units, int count = 3);
std::string frame_summary_json(const coupling::FrameStudyResults& results, const coupling::FrameStudyRequest& request);  // frame_summary(...).dump(2)

}  // namespace framedyn::report

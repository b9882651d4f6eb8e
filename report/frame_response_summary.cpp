// summary.json of `framedyn frame-response`; see frame_response_summary.h.
#include "report/frame_response_summary.h"

#include "report/fatigue_outputs.h"
#include "report/frame_outputs.h"
#include "report/run_outputs.h"

namespace framedyn::report {

nlohmann::ordered_json frame_response_summary(const std::string& study, const coupling::FrameStudyResults& r, const coupling::FrameStudyRequest& q,
                                              const std::function<void(const core::Warning&)>& console) {
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "frame-response"}};
  j["input"] = {{"study", study}, {"name", q.name}, {"units", q.units.name()}, {"loads", q.loads ? q.loads->string() : std::string()}};
  j["frame"] = frame_summary(r, q);
  if (r.life) j["fatigue"] = fatigue_summary(r, q);
  add_warnings(j, coupling::frame_warnings(r, q), console);
  return j;
}

}  // namespace framedyn::report

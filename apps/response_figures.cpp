// Response figures for `framedyn run --figures`; see response_figures.h.
#include "apps/response_figures.h"

#include <algorithm>

#include "core/plot.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

const coupling::Series* find_series(const coupling::RigidResults& r, const std::string& name) {
  const auto it = std::find_if(r.series.begin(), r.series.end(), [&](const coupling::Series& s) { return s.name == name; });
  return it == r.series.end() ? nullptr : &*it;
}

struct Figure {
  std::string file, series, title, y_label, legend;
  rigid::Attachment attachment;  // drawn for this attachment only
};

}  // namespace

void require_gnuplot() {
  if (!core::gnuplot_available())
    throw core::PlotError("--figures needs gnuplot (Debian package gnuplot-nox, installed by ./install-deps.sh), and 'gnuplot' cannot be run");
}

std::vector<std::string> write_response_figures(const coupling::RigidStudy& study, const coupling::RigidResults& r, const core::ResultsFolder& folder) {
  std::vector<std::string> written;
  const std::vector<double>& time = r.trajectory.time;
  if (!study.response || time.empty()) return written;
  const core::UnitSystem& u = study.units;
  const std::vector<Figure> figures = {
      {"plow_force_magnitude.png", "plow_force_signed_magnitude", "Plow force magnitude (thesis Figure 11)", "plow force magnitude",
       "plow force, positive while the blade moves forward", rigid::Attachment::plow},
      {"plow_force_angle.png", "plow_force_angle_deg", "Plow force angle (thesis Figure 12)", "plow force angle", "angle of the plow force resultant", rigid::Attachment::plow},
      {"blade_vertical_motion.png", "blade_z", "Plow blade vertical motion", "blade vertical displacement", "blade point, up positive", rigid::Attachment::plow},
      {"chain_force.png", "chain_force", "Digging chain force (thesis Figure 17)", "chain force", "chain force", rigid::Attachment::chain},
  };
  for (const Figure& f : figures) {
    const coupling::Series* s = find_series(r, f.series);
    if (f.attachment != study.machine.attachment) continue;
    if (!s || s->values.size() != time.size() || time.empty()) continue;
    core::LinePlot plot;
    plot.title = f.title + ": " + study.name;
    plot.x_label = "time";
    plot.x_unit = "s";
    plot.y_label = f.y_label;
    // The angle series is in degrees already (dimensionless in the results).
    plot.y_unit = s->quantity == Quantity::dimensionless ? "deg" : u.label(s->quantity);
    core::PlotSeries ps{f.legend, time, {}};
    ps.y.reserve(s->values.size());
    for (double v : s->values) ps.y.push_back(u.from_si(v, s->quantity));
    plot.series.push_back(std::move(ps));
    core::write_png(plot, folder.path_of(f.file));
    written.push_back(f.file);
  }
  return written;
}

}  // namespace framedyn::apps

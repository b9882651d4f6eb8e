// Response figures for `framedyn run --figures`; see response_figures.h.
#include "report/response_figures.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "report/plot.h"

namespace framedyn::report {

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

// Thesis Figures 13-16 (plow) and 18-21 (chain): the resultants along the
// frame at three instants of the last shaker cycle (or of the last 0.06 s),
// and the rail's top-fiber stress at the output point nearest X = 36 in.
void add_frame_figures(const coupling::RigidStudy& study, const coupling::RigidResults& r, const core::ResultsFolder& folder,
                       std::vector<std::string>& written) {
  const core::UnitSystem& u = study.units;
  const coupling::StressResultants& sr = *r.resultants;
  const std::vector<double>& time = r.trajectory.time;
  const double period = study.attachment() == rigid::Attachment::plow && study.shaker_frequency() > 0
                            ? 1.0 / study.shaker_frequency()
                            : 0.06;
  const bool plow = study.attachment() == rigid::Attachment::plow;
  std::vector<std::size_t> instants;
  for (double fraction : {1.0, 2.0 / 3.0, 1.0 / 3.0}) {
    const double t = time.back() - fraction * period;
    std::size_t best = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
      if (std::abs(time[i] - t) < std::abs(time[best] - t)) best = i;
    instants.push_back(best);
  }
  std::vector<double> x;
  for (double v : sr.output_x) x.push_back(u.from_si(v, Quantity::length));
  struct Along {
    const char* file;
    const char* what;
    int figure_plow, figure_chain;
    const std::vector<std::vector<double>>* values;
    Quantity q;
  };
  const std::vector<Along> along = {{"frame_axial_resultant.png", "axial resultant SRX", 13, 18, &sr.srx, Quantity::force},
                                    {"frame_shear_resultant.png", "shear resultant SRZ", 14, 19, &sr.srz, Quantity::force},
                                    {"frame_bending_resultant.png", "bending resultant SRMY", 15, 20, &sr.srmy, Quantity::moment}};
  for (const Along& a : along) {
    report::LinePlot plot;
    plot.title = std::string(a.what) + " along the frame (thesis Figure " + std::to_string(plow ? a.figure_plow : a.figure_chain) + ")";
    plot.x_label = "X, rearward from the front axle";
    plot.x_unit = u.label(Quantity::length);
    plot.y_label = a.what;
    plot.y_unit = u.label(a.q);
    for (std::size_t i : instants) {
      report::PlotSeries ps{"t = " + std::to_string(time[i]).substr(0, 6) + " s", x, {}};
      for (double v : (*a.values)[i]) ps.y.push_back(u.from_si(v, a.q));
      plot.series.push_back(std::move(ps));
    }
    report::write_png(plot, folder.path_of(a.file));
    written.push_back(a.file);
  }
  if (!r.rail_top_stress.empty()) {
    std::size_t k = 0;
    for (std::size_t j = 0; j < sr.output_x.size(); ++j)
      if (std::abs(sr.output_x[j] - 0.9144) < std::abs(sr.output_x[k] - 0.9144)) k = j;  // 36 in, midway between the axles
    report::LinePlot plot;
    plot.title = std::string("Rail top-fiber stress at X = ") + std::to_string(u.from_si(sr.output_x[k], Quantity::length)).substr(0, 5) + " " +
                 u.label(Quantity::length) + " (thesis Figure " + (plow ? "16" : "21") + ")";
    plot.x_label = "time";
    plot.x_unit = u.label(Quantity::time);
    plot.y_label = "normal stress at the top of one rail";
    plot.y_unit = u.label(Quantity::stress);
    report::PlotSeries ps{"top fiber, tension positive", time, {}};
    for (const auto& row : r.rail_top_stress) ps.y.push_back(u.from_si(row[k], Quantity::stress));
    plot.series.push_back(std::move(ps));
    report::write_png(plot, folder.path_of("rail_stress_x36.png"));
    written.push_back("rail_stress_x36.png");
  }
}

}  // namespace

void require_gnuplot() {
  if (!report::gnuplot_available())
    throw report::PlotError("--figures needs gnuplot (Debian package gnuplot-nox, installed by ./install-deps.sh), and 'gnuplot' cannot be run");
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
    if (f.attachment != study.attachment()) continue;
    if (!s || s->values.size() != time.size() || time.empty()) continue;
    report::LinePlot plot;
    plot.title = f.title + ": " + study.name;
    plot.x_label = "time";
    plot.x_unit = u.label(Quantity::time);
    plot.y_label = f.y_label;
    // The angle series is in degrees already (dimensionless in the results).
    plot.y_unit = u.label(s->quantity == Quantity::dimensionless ? Quantity::angle_degrees : s->quantity);
    report::PlotSeries ps{f.legend, time, {}};
    ps.y.reserve(s->values.size());
    for (double v : s->values) ps.y.push_back(u.from_si(v, s->quantity));
    plot.series.push_back(std::move(ps));
    report::write_png(plot, folder.path_of(f.file));
    written.push_back(f.file);
  }
  if (r.resultants) add_frame_figures(study, r, folder, written);
  return written;
}

}  // namespace framedyn::report

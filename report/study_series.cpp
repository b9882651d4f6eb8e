// A study run's series as arrays; see study_series.h.
#include "report/study_series.h"

#include <fmt/format.h>

#include "core/number_text.h"
#include "report/study_run_details.h"

namespace framedyn::report {

namespace {

using core::Quantity;

NamedSeries convert(const std::string& name, const core::UnitSystem& u, Quantity q, const std::vector<double>& si) {
  NamedSeries s{name, u.label(q), {}};
  const double f = 1.0 / u.to_si_factor(q);
  s.values.reserve(si.size());
  for (double v : si) s.values.push_back(v * f);
  return s;
}

template <class Results>
void rigid_response(const Results& r, const core::UnitSystem& u, StudySeries& out) {
  const rigid::Trajectory& tr = r.trajectory;
  out.time = tr.time;
  for (std::size_t c = 0; c < r.coordinates.size(); ++c) {
    std::vector<double> q;
    q.reserve(tr.q.size());
    for (const Eigen::VectorXd& state : tr.q) q.push_back(state(static_cast<Eigen::Index>(c)));
    out.coordinates.push_back(convert(r.coordinates[c], u, r.coordinate_quantities[c], q));
  }
  for (const coupling::Series& s : r.series) out.recovered.push_back(convert(s.name, u, s.quantity, s.values));
}

void load_points(const coupling::LoadHistory& h, const core::UnitSystem& u, StudySeries& out) {
  static const char* kComponents[6] = {"FX", "FY", "FZ", "MX", "MY", "MZ"};
  for (const coupling::LoadPointHistory& p : h.points)
    for (int k = 0; k < 6; ++k) {
      const Eigen::VectorXd col = p.values.col(k);
      out.frame_loads.push_back(convert(p.name + "." + kComponents[k], u, k < 3 ? Quantity::force : Quantity::moment,
                                        std::vector<double>(col.data(), col.data() + col.size())));
    }
}

void frame_transient(const coupling::FrameStudyResults& f, const core::UnitSystem& u, StudySeries& out) {
  const Eigen::VectorXd& t = f.response.times;
  out.frame_time.assign(t.data(), t.data() + t.size());
  const double lf = 1.0 / u.to_si_factor(Quantity::length), mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
  for (const coupling::RailRecovery& rail : f.rails) {
    const Eigen::VectorXd& m = rail.series_bending_moment;
    const Eigen::VectorXd& s = rail.series_normal_stress;
    out.rail_series.push_back(convert(rail.spec.name + ".bending_moment", u, Quantity::moment, std::vector<double>(m.data(), m.data() + m.size())));
    out.rail_series.push_back(convert(rail.spec.name + ".normal_stress", u, Quantity::stress, std::vector<double>(s.data(), s.data() + s.size())));
    RailEnvelope e;
    e.rail = rail.spec.name;
    e.length_unit = u.label(Quantity::length), e.moment_unit = u.label(Quantity::moment), e.stress_unit = u.label(Quantity::stress);
    for (std::size_t k = 0; k < rail.station_points.size(); ++k) {
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      e.x.push_back(rail.station_points[k].x() * lf), e.y.push_back(rail.station_points[k].y() * lf), e.z.push_back(rail.station_points[k].z() * lf);
      e.bending_moment.push_back(rail.envelope_bending_moment(i) * mf);
      e.normal_stress.push_back(rail.envelope_normal_stress(i) * sf);
    }
    out.rail_envelopes.push_back(std::move(e));
  }
  const std::vector<fem::SectionForces>* statics = f.static_forces.empty() ? nullptr : &f.static_forces;
  for (const coupling::HotSpot& h : f.hot_spots.by_von_mises) {
    const coupling::StressStation& st = f.stress.stations[h.station];
    HotSpotHistory hs;
    hs.x = st.point.x() * lf;
    hs.length_unit = u.label(Quantity::length), hs.stress_unit = u.label(Quantity::stress);
    hs.name = fmt::format("{} X={} {}", st.set, core::format_number(hs.x), h.point_name);
    for (const fem::PointStress& p : coupling::point_stress_history(f.stress, h.station, h.point, statics)) {
      hs.von_mises.push_back(p.von_mises * sf);
      hs.normal_stress.push_back(p.normal * sf);
    }
    out.hot_spots.push_back(std::move(hs));
  }
}

void numbers_of(const nlohmann::ordered_json& j, const std::string& path, std::vector<SummaryNumber>& out) {
  if (j.is_object()) {
    if (j.contains("value") && j["value"].is_number() && j.size() <= 2 && (j.size() == 1 || (j.contains("unit") && j["unit"].is_string()))) {
      out.push_back({path, j.contains("unit") ? j["unit"].get<std::string>() : std::string(), j["value"].get<double>()});
      return;
    }
    for (const auto& [key, value] : j.items()) numbers_of(value, path.empty() ? key : path + "." + key, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) numbers_of(j[i], path + "[" + std::to_string(i) + "]", out);
  } else if (j.is_number() && !j.is_boolean()) {
    out.push_back({path, std::string(), j.get<double>()});
  }
}

}  // namespace

std::vector<SummaryNumber> summary_numbers(const nlohmann::ordered_json& summary) {
  std::vector<SummaryNumber> out;
  numbers_of(summary, "", out);
  return out;
}

StudySeries study_series(const StudyRun& run) {
  StudySeries out;
  if (!run.details) return out;
  const StudyRunDetails& d = *run.details;
  if (d.study && d.results) {
    const core::UnitSystem& u = d.study->units;
    const coupling::RigidResults& r = *d.results;
    out.units = u.name();
    rigid_response(r, u, out);
    for (const coupling::FrameLoad2D& l : r.frame_loads_2d) {
      std::vector<double> fx, fz;
      for (const Eigen::Vector2d& f : l.force) fx.push_back(f.x()), fz.push_back(f.y());
      out.frame_loads.push_back(convert(l.name + ".FX", u, Quantity::force, fx));
      out.frame_loads.push_back(convert(l.name + ".FZ", u, Quantity::force, fz));
      out.frame_loads.push_back(convert(l.name + ".MY", u, Quantity::moment, l.moment));
    }
    if (!r.rail_top_stress.empty())
      for (std::size_t p = 0; p < r.rail_top_stress.front().size(); ++p) {
        std::vector<double> s;
        for (const std::vector<double>& sample : r.rail_top_stress) s.push_back(sample[p]);
        const double x = d.study->frame_output ? d.study->frame_output->points[p] / u.to_si_factor(Quantity::length) : 0.0;
        out.rail_stress.push_back(convert("rail_top_stress.X=" + core::format_number(x), u, Quantity::stress, s));
      }
    if (r.frame_loads_3d) {
      load_points(r.frame_loads_3d->points, u, out);
      load_points(r.frame_loads_3d->direct, u, out);
    }
    if (d.frame) frame_transient(*d.frame, u, out);
  }
  return out;
}

}  // namespace framedyn::report

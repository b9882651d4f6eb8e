// Stress histories and hot spots; see hot_spots.h.
#include "coupling/hot_spots.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "coupling/output_sets.h"

namespace framedyn::coupling {

namespace {

constexpr double kTie = 1e-6;  // relative: values this close count as equal (round-off differs between CPUs)

fem::SectionForces sum(const fem::SectionForces& a, const fem::SectionForces& b) {
  fem::SectionForces s;
  s.n = a.n + b.n;
  s.vy = a.vy + b.vy;
  s.vz = a.vz + b.vz;
  s.t = a.t + b.t;
  s.my = a.my + b.my;
  s.mz = a.mz + b.mz;
  return s;
}

// One station's stresses over time: per point, the steady and start-up peaks
// of the total von Mises stress and the steady range of the total normal stress.
struct PointRecord {
  double steady_peak = -std::numeric_limits<double>::infinity();
  Eigen::Index steady_time = -1;
  double startup_peak = -std::numeric_limits<double>::infinity();
  Eigen::Index startup_time = -1;
  double range = 0.0;
  double vm_static = 0.0;
};

}  // namespace

Eigen::Index stable_argmax(const std::vector<double>& v) {
  double m = -std::numeric_limits<double>::infinity();
  for (double x : v) m = std::max(m, x);
  if (!(m > -std::numeric_limits<double>::infinity())) return -1;
  const double threshold = m - kTie * std::abs(m);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] >= threshold) return static_cast<Eigen::Index>(i);
  return -1;
}

fem::SectionForces StressHistories::forces_at(std::size_t s, Eigen::Index j) const {
  const Eigen::Index r = 6 * static_cast<Eigen::Index>(s);
  fem::SectionForces f;
  f.n = forces(r, j);
  f.vy = forces(r + 1, j);
  f.vz = forces(r + 2, j);
  f.t = forces(r + 3, j);
  f.my = forces(r + 4, j);
  f.mz = forces(r + 5, j);
  return f;
}

StressHistories stress_histories(const fem::FrameModel& model, const Eigen::VectorXd& times, const std::vector<SetHistory>& sets,
                                 core::WorkShare* share) {
  StressHistories h;
  h.times = times;
  for (const fem::SectionAssignment& a : model.sections) {
    h.sections.push_back(a.properties);
    h.points.push_back(fem::section_points(a.properties));
  }
  std::size_t total = 0;
  for (const SetHistory& set : sets) total += set.element_ids.size();
  h.forces.resize(6 * static_cast<Eigen::Index>(total), times.size());
  for (const SetHistory& set : sets) {
    const Eigen::Index ns = static_cast<Eigen::Index>(set.element_ids.size());
    const bool table = set.values != nullptr;
    if (table ? set.values->rows() != ns * times.size() || set.values->cols() < 6 : !set.displacement || set.displacement->cols() != times.size())
      throw std::invalid_argument("the section-force history of " + set.name + " does not match its stations and times");
    const Eigen::Index offset = static_cast<Eigen::Index>(h.stations.size());
    for (Eigen::Index k = 0; k < ns; ++k) {
      const std::size_t i = static_cast<std::size_t>(k);
      const int b = model.beam_index(set.element_ids[i]);
      if (b < 0) throw std::invalid_argument("element " + std::to_string(set.element_ids[i]) + " of " + set.name + " is not a beam");
      h.stations.push_back({set.name, set.element_ids[i], set.station_index[i], set.points[i], model.beams[static_cast<std::size_t>(b)].section});
    }
    if (!table) {  // straight from the displacements: each (time, station) once, on any of the share's threads
      for_section_forces(model, *set.displacement, set.element_set, set.stations, false, share,
                         [&](Eigen::Index j, Eigen::Index k, const fem::SectionForces& f, double) {
                           if (k >= ns) throw std::invalid_argument("the stations of " + set.name + " do not match its element set");
                           float* to = &h.forces(6 * (offset + k), j);
                           to[0] = static_cast<float>(f.n), to[1] = static_cast<float>(f.vy), to[2] = static_cast<float>(f.vz);
                           to[3] = static_cast<float>(f.t), to[4] = static_cast<float>(f.my), to[5] = static_cast<float>(f.mz);
                         });
      continue;
    }
    core::for_ranges(share, static_cast<std::size_t>(times.size()), 256, [&](std::size_t begin, std::size_t end) {
      for (Eigen::Index j = static_cast<Eigen::Index>(begin); j < static_cast<Eigen::Index>(end); ++j)
        for (Eigen::Index k = 0; k < ns; ++k)
          for (Eigen::Index c = 0; c < 6; ++c) h.forces(6 * (offset + k) + c, j) = static_cast<float>((*set.values)(j * ns + k, c));
    });
  }
  return h;
}

SteadyWindow steady_window(std::optional<double> rigid_reached_at, std::optional<double> study_steady_from, const Eigen::VectorXd& times) {
  if (rigid_reached_at) return {*rigid_reached_at, "rigid-body model's steady report"};
  if (study_steady_from) return {*study_steady_from, "frame.steady_from"};
  const double t0 = times.size() ? times(0) : 0.0, t1 = times.size() ? times(times.size() - 1) : 0.0;
  return {0.5 * (t0 + t1), "last half of the record"};
}

std::vector<fem::PointStress> point_stress_history(const StressHistories& h, std::size_t station, int point,
                                                   const std::vector<fem::SectionForces>* static_forces) {
  const std::size_t sec = static_cast<std::size_t>(h.stations.at(station).section);
  const fem::SectionPoint& at = h.points.at(sec).at(static_cast<std::size_t>(point));
  const fem::SectionForces fs = static_forces && !static_forces->empty() ? static_forces->at(station) : fem::SectionForces{};
  std::vector<fem::PointStress> out;
  out.reserve(static_cast<std::size_t>(h.times.size()));
  for (Eigen::Index j = 0; j < h.times.size(); ++j) out.push_back(fem::point_stress(h.sections[sec], at, sum(fs, h.forces_at(station, j))));
  return out;
}

HotSpotReport find_hot_spots(const StressHistories& h, const SteadyWindow& window, int count, const std::vector<fem::SectionForces>* static_forces,
                             core::WorkShare* share) {
  if (static_forces && !static_forces->empty() && static_forces->size() != h.stations.size())
    throw std::invalid_argument("the static section forces do not match the stress histories' stations");
  HotSpotReport out;
  out.window = window;
  out.memory_bytes = h.bytes();
  const Eigen::Index nt = h.times.size();
  // Steady from `from` on; a time within round-off of it counts as steady.
  const double edge = window.from - 1e-9 * std::max(1.0, std::abs(window.from));
  std::vector<bool> steady(static_cast<std::size_t>(nt));
  for (Eigen::Index j = 0; j < nt; ++j) {
    steady[static_cast<std::size_t>(j)] = h.times(j) >= edge;
    (steady[static_cast<std::size_t>(j)] ? out.steady_times : out.startup_times) += 1;
  }
  const double none = -std::numeric_limits<double>::infinity();
  std::vector<HotSpot> best_vm(h.stations.size()), best_range(h.stations.size()), best_startup(h.stations.size());
  std::vector<double> station_vm(h.stations.size(), none), station_range(h.stations.size(), none), station_startup(h.stations.size(), none);
  // Each station's entries on their own (any share of the stations: the same report); ranked below.
  core::for_ranges(share, h.stations.size(), 8, [&](std::size_t begin, std::size_t end) {
  std::vector<double> steady_vm, startup_vm;  // one point's von Mises over the steady times and over the others
  for (std::size_t s = begin; s < end; ++s) {
    const int sec = h.stations[s].section;
    const fem::SectionProperties& props = h.sections[static_cast<std::size_t>(sec)];
    const std::vector<fem::SectionPoint>& points = h.points[static_cast<std::size_t>(sec)];
    if (points.empty()) continue;  // a GENERAL section: no points
    const fem::SectionForces fs = static_forces && !static_forces->empty() ? (*static_forces)[s] : fem::SectionForces{};
    std::vector<PointRecord> rec(points.size());
    std::vector<double> steady_peaks(points.size(), none), ranges(points.size(), none), startup_peaks(points.size(), none);
    for (std::size_t p = 0; p < points.size(); ++p) {
      PointRecord& r = rec[p];
      r.vm_static = fem::point_stress(props, points[p], fs).von_mises;
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      steady_vm.assign(static_cast<std::size_t>(nt), none);
      startup_vm.assign(static_cast<std::size_t>(nt), none);
      for (Eigen::Index j = 0; j < nt; ++j) {
        const fem::PointStress ps = fem::point_stress(props, points[p], sum(fs, h.forces_at(s, j)));
        const std::size_t jj = static_cast<std::size_t>(j);
        if (steady[jj]) {
          steady_vm[jj] = ps.von_mises;
          lo = std::min(lo, ps.normal);
          hi = std::max(hi, ps.normal);
        } else {
          startup_vm[jj] = ps.von_mises;
        }
      }
      r.steady_time = stable_argmax(steady_vm);
      if (r.steady_time >= 0) r.steady_peak = steady_vm[static_cast<std::size_t>(r.steady_time)];
      r.startup_time = stable_argmax(startup_vm);
      if (r.startup_time >= 0) r.startup_peak = startup_vm[static_cast<std::size_t>(r.startup_time)];
      r.range = hi >= lo ? hi - lo : 0.0;
      steady_peaks[p] = r.steady_peak;
      ranges[p] = hi >= lo ? r.range : none;
      startup_peaks[p] = r.startup_peak;
    }
    const auto spot = [&](Eigen::Index p, Eigen::Index j, double value) {
      HotSpot x;
      x.station = s;
      x.point = static_cast<int>(p);
      x.point_name = points[static_cast<std::size_t>(p)].name;
      x.von_mises_static = rec[static_cast<std::size_t>(p)].vm_static;
      x.von_mises_total = value;
      x.time = h.times(j);
      x.von_mises_dynamic = fem::point_stress(props, points[static_cast<std::size_t>(p)], h.forces_at(s, j)).von_mises;
      return x;
    };
    const Eigen::Index pv = stable_argmax(steady_peaks), pr = stable_argmax(ranges), pu = stable_argmax(startup_peaks);
    if (pv >= 0) {
      const PointRecord& r = rec[static_cast<std::size_t>(pv)];
      best_vm[s] = spot(pv, r.steady_time, r.steady_peak);
      station_vm[s] = r.steady_peak;
    }
    if (pr >= 0) {
      const PointRecord& r = rec[static_cast<std::size_t>(pr)];
      best_range[s] = r.steady_time >= 0 ? spot(pr, r.steady_time, r.steady_peak) : HotSpot{};
      station_range[s] = r.range;
    }
    if (pu >= 0) {
      const PointRecord& r = rec[static_cast<std::size_t>(pu)];
      best_startup[s] = spot(pu, r.startup_time, r.startup_peak);
      station_startup[s] = r.startup_peak;
    }
    // Each station's entries carry the steady range of their point and the start-up peak of theirs.
    for (HotSpot* x : {&best_vm[s], &best_range[s], &best_startup[s]}) {
      const PointRecord& r = rec[static_cast<std::size_t>(x->point)];
      x->station = s;
      x->normal_stress_range = r.range;
      x->range_point = x->point;
      x->startup_peak_von_mises = r.startup_peak > none ? r.startup_peak : 0.0;
      x->startup_time = r.startup_time >= 0 ? h.times(r.startup_time) : 0.0;
    }
  }
  });
  // Rank: greedily the largest remaining, ties to the lowest station index.
  const auto rank = [&](std::vector<double> values, const std::vector<HotSpot>& spots) {
    std::vector<HotSpot> ranked;
    for (int k = 0; k < count; ++k) {
      const Eigen::Index i = stable_argmax(values);
      if (i < 0) break;
      ranked.push_back(spots[static_cast<std::size_t>(i)]);
      values[static_cast<std::size_t>(i)] = none;
    }
    return ranked;
  };
  if (out.steady_times > 0) {
    out.by_von_mises = rank(station_vm, best_vm);
    out.by_normal_range = rank(station_range, best_range);
    if (!out.by_von_mises.empty()) out.steady_peak = out.by_von_mises.front();
  }
  if (out.startup_times > 0) {
    const Eigen::Index i = stable_argmax(station_startup);
    if (i >= 0) out.startup_peak = best_startup[static_cast<std::size_t>(i)];
  }
  // The whole record's peak: the larger of the two (start-up first on a tie: it comes first in time).
  const bool startup_wins = out.startup_times > 0 && (out.steady_times == 0 || out.startup_peak.von_mises_total >=
                                                                                    out.steady_peak.von_mises_total * (1.0 - kTie));
  out.peak = startup_wins ? out.startup_peak : out.steady_peak;
  return out;
}

}  // namespace framedyn::coupling

// A duty cycle: read, run every scenario's pipeline, combine the life maps; see duty_cycle.h.
#include "coupling/duty_cycle.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "coupling/rigid_study.h"

namespace framedyn::coupling {

DutyCycleRequest read_duty_cycle(const std::string& file) { return read_duty_cycle(load_yaml_file(file), file); }

DutyCycleRequest read_duty_cycle(const YAML::Node& doc, const std::string& file) {
  const core::UnitSystem si = core::UnitSystem::si();
  YamlMap top(doc, "", file, &si);
  top.allow_only({"framedyn_study", "name", "model", "units", "scenarios", "fatigue"});
  DutyCycleRequest q;
  q.file = file;
  q.name = top.text_or("name", std::filesystem::path(file).stem().string());
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  const std::vector<YamlMap> scenarios = top.list_of_maps("scenarios");
  if (scenarios.empty()) throw top.error("scenarios", "a list of scenarios {name, study, hours}", top.has("scenarios") ? "an empty list" : "no scenarios");
  std::set<std::string> names;
  for (const YamlMap& s : scenarios) {
    s.allow_only({"name", "study", "hours"});
    DutyCycleScenarioSpec spec;
    spec.name = s.text("name");
    if (!names.insert(spec.name).second) throw s.error("name", "a scenario name used once", "'" + spec.name + "' again");
    const std::filesystem::path p(s.text("study"));
    spec.study = p.is_absolute() ? p : dir / p;
    spec.hours = s.positive("hours", core::Quantity::dimensionless);
    spec.where = s.location("study");
    spec.where.key = s.path() + ".study";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(spec.study, ec))
      throw core::InputError(spec.where, "a study file (a path relative to the duty-cycle file)", "'" + spec.study.string() + "', no such file");
    q.scenarios.push_back(spec);
  }
  // The details are assessed the same way in every scenario: one fatigue block for the cycle
  // (its hours, if given, are replaced by each scenario's).
  if (top.has("fatigue")) {
    const YamlMap f = top.map("fatigue");
    q.fatigue = read_fatigue_block(f);
  } else {
    q.fatigue.where = top.location("");
    q.fatigue.where.key = "fatigue";
  }
  return q;
}

namespace {

// One scenario's pipeline with the cycle's fatigue block (its hours the scenario's).
DutyCycleScenarioResult run_scenario(const DutyCycleRequest& q, const DutyCycleScenarioSpec& spec, core::WorkShare* share) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string model = study_model(spec.study.string()); model != "rigid_3d")
    throw core::InputError(spec.where, "a 3-D study (model: rigid_3d) with a response and a frame_response block", "'" + spec.study.string() + "', model " + model);
  const RigidStudy study = read_rigid_study(spec.study.string());
  if (!study.frame_response || !study.response)
    throw core::InputError(spec.where, "a 3-D study (model: rigid_3d) with a response and a frame_response block",
                           "'" + spec.study.string() + "', without " + (study.response ? "frame_response" : "analysis.response"));
  FrameStudyRequest request = *study.frame_response;
  request.fatigue = q.fatigue;
  request.fatigue->hours = spec.hours;
  request.paraview = ParaviewOutput::none;  // the cycle writes its own outputs; a scenario's ParaView series is its own run's business
  request.window_lead_in_decay = q.lead_in_decay;  // the steady window alone: what the life map reads
  for (RailSpec& rail : request.rails) rail.history = false;  // no section-force tables: the stresses from the displacements
  RigidResults r = run_rigid_study(study);
  // The loads taken over from the vehicle model's results, which the cycle keeps nothing else of.
  const LoadHistory loads = all_frame_loads(std::move(*r.frame_loads_3d)), static_loads = all_frame_loads(std::move(*r.static_frame_loads_3d));
  DutyCycleScenarioResult s{spec.name, spec.hours, study.name, 0.0, run_frame_study(request, &loads, &static_loads, r.steady.operation.reached_at, nullptr, share), request};
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace

DutyCycleResults run_duty_cycle(const DutyCycleRequest& q, const std::function<void(const std::string&)>& stage, int threads) {
  const std::size_t n = q.scenarios.size();
  std::size_t workers = threads > 0 ? static_cast<std::size_t>(threads) : std::max(1u, std::thread::hardware_concurrency());
  workers = std::max<std::size_t>(1, std::min(workers, n));
  // Each scenario's result or error in its slot; the next scenario handed out in the file's order.
  std::vector<std::optional<DutyCycleScenarioResult>> done(n);
  std::vector<std::exception_ptr> failed(n);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex progress;
  // A worker with no scenario left takes chunks of the others' frame studies (stations, output times)
  // until every worker is out of scenarios: the longest scenario does not finish alone. The same
  // numbers on any number of workers (core/work_share.h).
  core::WorkShare share;
  std::atomic<std::size_t> idle{0};  // workers out of scenarios (changed before share.wake(), read under its lock)
  const auto work = [&]() {
    for (std::size_t i = next++; i < n && !stop; i = next++) {
      const DutyCycleScenarioSpec& spec = q.scenarios[i];
      if (stage) {
        const std::lock_guard<std::mutex> lock(progress);
        stage(fmt::format("scenario {} ({})", spec.name, spec.study.string()));
      }
      try {
        done[i] = run_scenario(q, spec, workers > 1 ? &share : nullptr);
      } catch (...) {
        failed[i] = std::current_exception();
        stop = true;  // the scenarios after it would not have run one at a time either
      }
    }
    if (workers > 1) {
      ++idle;
      share.wake();
      share.help([&] { return idle == workers; });
    }
  };
  if (workers == 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }
  DutyCycleResults out;
  out.scenarios.reserve(n);  // moved in, never copied (a scenario's results hold its stress histories)
  for (std::size_t i = 0; i < n; ++i) {
    if (failed[i]) std::rethrow_exception(failed[i]);
    if (!done[i]) continue;  // not run: an earlier scenario failed (rethrown above)
    DutyCycleScenarioResult& s = *done[i];
    const DutyCycleScenarioSpec& spec = q.scenarios[i];
    // The same stations in every scenario: the same mesh, outputs and stations per element.
    if (!out.scenarios.empty()) {
      const StressHistories& a = out.scenarios.front().frame.stress;
      const StressHistories& b = s.frame.stress;
      bool same = a.stations.size() == b.stations.size();
      for (std::size_t k = 0; same && k < a.stations.size(); ++k)
        same = a.stations[k].element_id == b.stations[k].element_id && a.stations[k].station == b.stations[k].station && a.stations[k].set == b.stations[k].set &&
               a.points[static_cast<std::size_t>(a.stations[k].section)].size() == b.points[static_cast<std::size_t>(b.stations[k].section)].size();
      if (!same)
        throw core::InputError(spec.where,
                               fmt::format("a frame_response with the same mesh, element-set outputs and stations as scenario {} ({} stations)",
                                           out.scenarios.front().name, a.stations.size()),
                               fmt::format("{} stations", b.stations.size()) + (a.stations.size() == b.stations.size() ? " at other elements or stations" : ""));
    }
    out.scenarios.push_back(std::move(s));
  }
  std::vector<DutyScenario> parts;
  for (const DutyCycleScenarioResult& s : out.scenarios) parts.push_back({s.name, s.hours, &*s.frame.life});
  out.life = combine_duty_cycle(parts);
  return out;
}

}  // namespace framedyn::coupling

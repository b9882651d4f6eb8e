// The MPI engine; see mpi_engine.h. The messages: manager -> worker a run index
// (tag kWork) or -1 (kWork: stop); worker -> manager a row as JSON text (tag
// kResult). The manager polls with MPI_Iprobe and a 1 ms sleep so that it does
// not spin a core that a worker needs.
#include "batch/mpi_engine.h"

#include "core/results_folder.h"
#include "coupling/frame_model_cache.h"

#include <cstdlib>

#ifdef FRAMEDYN_WITH_MPI
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>
#endif

namespace framedyn::batch {

#ifndef FRAMEDYN_WITH_MPI

int mpi_world_size() { return 1; }
bool mpi_is_manager() { return true; }
BatchCounts run_batch_mpi(const BatchDesign& design, const BatchOptions& options) { return run_batch(design, options); }

#else

namespace {

constexpr int kWork = 1, kResult = 2;

bool launched_by_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK"); }

int g_size = 0, g_rank = 0;

void finalize() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

nlohmann::json to_json(const RunRecord& r) {
  return {{"index", r.index}, {"parameters", r.parameters}, {"outputs", r.outputs}, {"units", r.output_units}, {"done", r.done}, {"message", r.message}};
}

RunRecord from_json(const nlohmann::json& j) {
  RunRecord r;
  r.index = j["index"].get<std::size_t>();
  r.parameters = j["parameters"].get<std::vector<std::string>>();
  r.outputs = j["outputs"].get<std::vector<std::string>>();
  r.output_units = j["units"].get<std::vector<std::string>>();
  r.done = j["done"].get<bool>();
  r.message = j["message"].get<std::string>();
  r.present = true;
  return r;
}

}  // namespace

int mpi_world_size() {
  if (g_size == 0) {
    g_size = 1;
    if (launched_by_mpirun()) {
      MPI_Init(nullptr, nullptr);
      std::atexit(finalize);
      MPI_Comm_size(MPI_COMM_WORLD, &g_size);
      MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    }
  }
  return g_size;
}

bool mpi_is_manager() { return mpi_world_size() == 1 || g_rank == 0; }

BatchCounts run_batch_mpi(const BatchDesign& design, const BatchOptions& options) {
  const int size = mpi_world_size();
  if (size == 1) return run_batch(design, options);
  const std::vector<std::vector<double>> samples = design_samples(design);  // every rank draws the same samples
  if (g_rank != 0) {
    // A worker: no console of its own (the manager reports), and never the results folder.
    std::fflush(stdout);
    if (!std::freopen("/dev/null", "w", stdout)) return {};
    keep_freed_memory_for_next_runs();
    coupling::FrameModelCache models;  // this worker's frame models: built by its first run, reused by the next
    for (;;) {
      long long index = -1;
      MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (index < 0) return {};
      const std::string text = to_json(run_sample(design, static_cast<std::size_t>(index), samples[static_cast<std::size_t>(index)], std::nullopt,
                                                  options.reuse_models ? &models : nullptr)).dump();
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
    }
  }
  core::check_results_target(options.out, batch_inputs(design));
  std::vector<RunRecord> rows = starting_rows(design, options, samples.size());
  BatchCounts counts;
  counts.total = samples.size();
  std::vector<std::size_t> todo;
  for (const RunRecord& r : rows)
    if (r.present) ++counts.skipped;
    else todo.push_back(r.index);
  const std::size_t every = options.checkpoint_runs > 0 ? options.checkpoint_runs : std::max<std::size_t>(1, samples.size() / 20);
  std::size_t handed = 0, finished = 0, since = 0;
  int busy = 0;
  const auto hand_out = [&](int worker) {
    long long index = handed < todo.size() ? static_cast<long long>(todo[handed++]) : -1;
    MPI_Send(&index, 1, MPI_LONG_LONG, worker, kWork, MPI_COMM_WORLD);
    if (index >= 0) ++busy;
  };
  for (int w = 1; w < size; ++w) hand_out(w);
  while (busy > 0) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kResult, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    int length = 0;
    MPI_Get_count(&st, MPI_CHAR, &length);
    std::string text(static_cast<std::size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, st.MPI_SOURCE, kResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    --busy;
    RunRecord r = from_json(nlohmann::json::parse(text));
    rows[r.index] = std::move(r);
    ++finished;
    if (options.progress) options.progress(finished, todo.size());
    hand_out(st.MPI_SOURCE);
    if (++since >= every && finished < todo.size()) {
      since = 0;
      write_batch_folder(design, rows, options);
    }
  }
  if (options.stage) options.stage("writing results");
  write_batch_folder(design, rows, options);
  for (const RunRecord& r : rows) {
    counts.done += r.present && r.done;
    counts.failed += r.present && !r.done;
  }
  return counts;
}

#endif

}  // namespace framedyn::batch

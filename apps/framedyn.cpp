// framedyn: the command-line program. Parses the command line, runs one
// subcommand, and turns every error into one clear message and a non-zero
// exit status (1 for bad input, 2 for a numerical failure, 3 for anything else).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <functional>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "core/error.h"
#include "core/results_folder.h"

int main(int argc, char** argv) {
  framedyn::core::install_interrupt_cleanup();  // before any thread starts
  CLI::App app{"framedyn " FRAMEDYN_VERSION ": rigid-body and beam finite-element dynamics of off-road machine frames"};
  app.set_version_flag("--version", std::string("framedyn ") + FRAMEDYN_VERSION);
  app.require_subcommand(1);
  std::function<int()> run;
  framedyn::apps::add_modes_command(app, run);
  framedyn::apps::add_static_command(app, run);
  framedyn::apps::add_run_command(app, run);
  framedyn::apps::add_sweep_command(app, run);
  framedyn::apps::add_frame_response_command(app, run);
  framedyn::apps::add_harmonic_command(app, run);
  framedyn::apps::add_random_command(app, run);
  framedyn::apps::add_transient_command(app, run);
  framedyn::apps::add_rainflow_command(app, run);
  framedyn::apps::add_batch_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0: CLI11 prints them.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    // Every other parse error is bad input: one line in framedyn's own form
    // and status 1, like every other input error (docs/errors.md, CLI rows).
    const CLI::App* command = app.get_subcommands().empty() ? nullptr : app.get_subcommands().front();
    fmt::print(stderr, "framedyn: error: {}\n", framedyn::apps::command_line_message(e, command, argc > 1 ? argv[1] : ""));
    return 1;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    const int status = run();
    // Every run ends with what it cost: wall time and peak resident memory.
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    if (!framedyn::apps::quiet_console())
      fmt::print("run time {:.2f} s, peak memory {:.0f} MiB\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               usage.ru_maxrss / 1024.0);
    return status;
  } catch (const framedyn::core::InputError& e) {
    fmt::print(stderr, "framedyn: error: {}\n", e.what());
    return 1;
  } catch (const framedyn::core::NumericalError& e) {
    fmt::print(stderr, "framedyn: numerical failure: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "framedyn: error: {}\n", e.what());
    return 3;
  }
}

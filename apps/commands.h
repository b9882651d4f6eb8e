// The framedyn program's subcommands. Each registers its options on the CLI
// and runs; apps/ only parses, calls the library, prints and writes files.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace framedyn::apps {

// Registers the subcommand; `run` is set to the function that executes it.
void add_modes_command(CLI::App& app, std::function<int()>& run);
void add_static_command(CLI::App& app, std::function<int()>& run);
void add_run_command(CLI::App& app, std::function<int()>& run);
void add_sweep_command(CLI::App& app, std::function<int()>& run);
void add_frame_response_command(CLI::App& app, std::function<int()>& run);  // frame_response_command.cpp
void add_harmonic_command(CLI::App& app, std::function<int()>& run);        // harmonic_command.cpp
void add_random_command(CLI::App& app, std::function<int()>& run);          // random_command.cpp
void add_rainflow_command(CLI::App& app, std::function<int()>& run);        // rainflow_command.cpp
void add_transient_command(CLI::App& app, std::function<int()>& run);       // transient_command.cpp
void add_batch_command(CLI::App& app, std::function<int()>& run);           // batch_command.cpp (issue 19)

}  // namespace framedyn::apps

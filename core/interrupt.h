// Interrupts (SIGINT, SIGTERM, SIGHUP) that leave nothing behind.
//
// The signals are blocked in every thread and taken by one thread of their
// own (sigwait), so the clean-up runs as ordinary code, never inside a signal
// handler. Everything that creates a file framedyn may have to take back, or
// starts a child process, does so while holding the output gate
// (hold_output_gate) and registers what it made: a temporary path
// (register_temporary) or a child (register_child). On a signal the clean-up
// thread takes the gate, so no file is half-created and no rename is half-done
// while it works, and keeps it until the process ends: it kills and reaps the
// registered children, removes the registered paths, prints one line and
// exits with status 128 + signal. Nothing a writer does after that can run.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <mutex>

namespace framedyn::core {

// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (threads started
// later inherit that) and starts the clean-up thread. Call first in main.
void install_interrupt_cleanup();

// The lock every file creation, child start and rename of results holds.
// Recursive: a commit holding it may call code that takes it again.
std::unique_lock<std::recursive_mutex> hold_output_gate();

// A path (folder or file) the clean-up removes with everything in it. Call
// with the gate held, before or right after creating it.
void register_temporary(const std::filesystem::path& path);
void unregister_temporary(const std::filesystem::path& path);

// A child process the clean-up kills (SIGKILL) and reaps. Call with the gate
// held, in the same hold as the spawn; unregister in the hold that reaps it.
void register_child(pid_t pid);
void unregister_child(pid_t pid);

// A results folder now complete in place (call with the gate held): an
// interrupt after this says so instead of "no results written".
void note_results_written(const std::filesystem::path& folder);

}  // namespace framedyn::core

// libFuzzer harness for the load-history reader (coupling/load_history.h).
// Any input must either parse into a history whose times increase and whose
// values are all finite — and then write back and re-read to the same
// numbers to 10 significant digits — or be refused with core::InputError
// naming file and line. Anything else is a finding. Seeds: tests/fuzz/seeds/loads.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "coupling/load_history.h"

namespace {

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "load-history reader: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  framedyn::coupling::LoadHistory history;
  try {
    history = framedyn::coupling::parse_load_history(text, "fuzz.csv");
  } catch (const framedyn::core::InputError&) {
    return 0;  // the expected outcome for bad input
  }
  for (int k = 1; k < history.time_count(); ++k)
    if (!(history.times(k) > history.times(k - 1))) finding("accepted times that do not increase");
  for (const auto& point : history.points) {
    if (!point.location.allFinite()) finding("accepted a non-finite location");
    if (!point.values.allFinite()) finding("accepted a non-finite load");
    if (point.values.rows() != history.time_count()) finding("accepted a ragged history");
  }
  // What was accepted writes and reads back.
  const auto units = framedyn::core::UnitSystem::si();
  try {
    const auto again = framedyn::coupling::parse_load_history(framedyn::coupling::format_load_history(history, units), "again.csv");
    if (again.time_count() != history.time_count() || again.points.size() != history.points.size()) finding("round trip changed the shape");
  } catch (const framedyn::core::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    finding("its own output was refused");
  }
  return 0;
}

// A user-defined S-N curve from a YAML file (docs/theory/fatigue.md section 3, F.4-F.8;
// docs/user-guide.md "S-N curve files"), for `framedyn rainflow --curve FILE.yaml` and the
// fatigue block's `details[i].curve`:
//   name: weld toe, company data       # required: the curve's name in every result
//   units: MPa                         # the ranges' stress unit (core/stress_unit.h); MPa by default
//   # exactly one of:
//   points: [[1e5, 200], [1e7, 50]]    # [N, S]: N rising, S falling, interpolated log-log
//   slope_below: 22                    # (points only) m below the last point; a cut-off without it
//   basquin: {C: 2e12, m: 3}           # N = C S^-m, S in `units` (C in units^m)
//   reference: {range: 90, cycles: 2e6}  # a point of the curve, with
//   slopes: [3, 5]                     # m from the reference on, changing at
//   knees: [1e7]                       # these cycles (one fewer than slopes, rising, beyond the reference)
//   cut_off: 1e8                       # (optional) cycles beyond which no damage
// Errors name the file, line and key (STUDY-161 .. STUDY-164).
#pragma once

#include <string>

#include "fatigue/sn_curve.h"

namespace framedyn::coupling {

fatigue::SnCurve read_sn_curve_file(const std::string& file);

}  // namespace framedyn::coupling

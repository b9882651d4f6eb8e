// docs/errors.md, row by row: every bad-input case the table lists is run
// through the framedyn program as a user would, and must
//   - exit with status 1 and print exactly one line, "framedyn: error: " and
//     the message docs/errors.md gives for that row (word for word);
//   - name the file (or the command line), then the line and/or the key;
//   - say what was expected and what was found (rows of the "expected ...,
//     found ..." form; a few, like a missing file, say what is wrong instead);
//   - leave the run's folder as it was: no results folder, no partial one.
// And the IDs of docs/errors.md's bad-input tables are exactly the IDs tested
// here, so that the document and the tests cannot drift apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::testing::framedyn;
using framedyn::testing::read_file;
using framedyn::testing::RunResult;
using framedyn::testing::TempDir;

const fs::path kErrorsDoc = fs::path(FRAMEDYN_SOURCE_DIR) / "docs" / "errors.md";

// ------------------------------------------------------------------ inputs

// A two-element cantilever along X, clamped at node 1, loaded at node 3:
// `framedyn static frame.inp` runs (checked below), so each error comes
// from its row's edit alone.
const std::string kMesh = R"(** units: m-N-s
*NODE, NSET=ALL
1, 0, 0, 0
2, 1, 0, 0
3, 2, 0, 0
*ELEMENT, TYPE=B31, ELSET=FRAME
1, 1, 2
2, 2, 3
*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT
0.05, 0.1
*MATERIAL, NAME=STEEL
*ELASTIC
2.1e11, 0.3
*DENSITY
7850
*BOUNDARY
1, ENCASTRE
*STEP
*STATIC
*CLOAD
3, 3, 1000.
*END STEP
)";

// A 2-D plow study (modes and two shaker cycles of response) that `framedyn run` runs.
const std::string kStudy2D = R"(framedyn_study: 1
name: error table, 2-D
units: in-lbf-s
model: rigid_2d
attachment: plow
ground: {slope_deg: 0, forward_speed: 6}
frame:
  uniform_section: {front_end: -25, length: 105, weight_per_length: 5.39}
  added_masses:
    - {name: engine, weight: 850, radius_of_gyration: 14, position: [40, 14]}
    - {name: rear_axle, weight: 900, radius_of_gyration: 12, position: [72, -14]}
cab:
  weight: 650
  radius_of_gyration: 16
  position: [36, 32]
  front_mount: {position: [20, 3], stiffness: 1630, damping: 5}
  rear_mount: {position: [52, 3], stiffness: 1630, damping: 5}
tires:
  front:
    contact: [0, -26]
    normal: {stiffness: 5000, damping: 15}
    tractive: {stiffness: 3600, damping: 15}
  rear:
    contact: [72, -26]
    normal: {stiffness: 6000, damping: 15}
    tractive: {stiffness: 4000, damping: 15}
plow:
  weight: 2800
  radius_of_gyration: 14
  cg: [114, -14]
  linkage:
    upper_pivot: [82, 6]
    lower_pivot: [82, -10]
    upper_joint: [112, 4]
    lower_joint: [114, -12]
  blade_point: [118, -44]
  shaker: {point: [113, -2], force: 26530, frequency_hz: 18.33}
  bounce_tire: {point: [130, -26], stiffness: 1500, damping: 5}
  lift_cylinder: {frame_point: [66, 24], arm_point: [96, 5], stiffness: 20000, damping: 40}
soil: {stiffness: 40000, damping: 300, stiffness_reduction: 0, damping_reduction: 0.25}
frame_output:
  points: [-25, 0, 36, 80]
analysis:
  modes: true
  fixed_coordinates: [x]
  response: {duration: 0.12, output_interval: 0.001, method: rk4, rk4_step: 0.0005}
)";

// A 3-D machine without attachment (no soil, no plow) that `framedyn run` runs.
const std::string kStudy3D = R"(framedyn_study: 1
name: error table, 3-D
units: in-lbf-s
model: rigid_3d
attachment: none
frame:
  parts:
    - {name: frame_structure, weight: 565.6, position: [27.5, 0, 0], radii_of_gyration: [14, 30.3, 33.5]}
    - {name: engine, weight: 850, position: [40, 0, 14], radii_of_gyration: [12, 14, 14]}
  reel_and_carrier: {weight: 450, position: [-32, 0, 18], radii_of_gyration: [12, 12, 12], attachment: [-25, 0, 0]}
  rear_axle:
    weight: 900
    position: [72, 0, -14]
    radii_of_gyration: [22, 12, 22]
    pin: [72, 0, 0]
    leveling_cylinder: [68, 15, 0]
front_axle:
  weight: 650
  position: [0, 0, -14]
  radii_of_gyration: [22, 10, 22]
  pin: [0, 0, 0]
cab:
  weight: 650
  position: [36, 0, 32]
  radii_of_gyration: [16, 16, 16]
  mounts:
    - {name: FL, position: [20, -15, 0], x: {stiffness: 245}, y: {stiffness: 266}, z: {stiffness: 815}}
    - {name: FR, position: [20, 15, 0], x: {stiffness: 245}, y: {stiffness: 266}, z: {stiffness: 815}}
    - {name: RL, position: [52, -15, 0], x: {stiffness: 245}, y: {stiffness: 266}, z: {stiffness: 815}}
    - {name: RR, position: [52, 15, 0], x: {stiffness: 245}, y: {stiffness: 266}, z: {stiffness: 815}}
tires:
  front:
    steering_deg: 0
    left:  {contact: [0, -30, -26], vertical: {stiffness: 2500}, longitudinal: {stiffness: 1800}, lateral: {stiffness: 1800}}
    right: {contact: [0, 30, -26], vertical: {stiffness: 2500}, longitudinal: {stiffness: 1800}, lateral: {stiffness: 1800}}
  rear:
    steering_deg: 0
    left:  {contact: [72, -30, -26], vertical: {stiffness: 3000}, longitudinal: {stiffness: 2000}, lateral: {stiffness: 2000}}
    right: {contact: [72, 30, -26], vertical: {stiffness: 3000}, longitudinal: {stiffness: 2000}, lateral: {stiffness: 2000}}
analysis:
  modes: true
)";

// A frame transient study on the shipped frame (copied in as frame.inp) with
// a load history at two of its load points; `framedyn frame-response` runs it.
const std::string kFrameStudy = R"(framedyn_study: 1
name: error table, frame
units: in-lbf-s
model: frame_transient
frame:
  mesh: frame.inp
  loads: loads.csv
  supports: fixed_rear_end
  modes: 4
  method: mode_displacement
  damping: {modal_ratio: 0.02}
  output_interval: 0.001
  stations: 3
  outputs:
    left_rail: {element_set: LEFT_RAIL}
    right_rail: {element_set: RIGHT_RAIL}
)";

const std::string kLoads = R"(# framedyn load history, version 1
# units: in-lbf-s
# point P25_FRONT_AXLE_PIN 0 0 0
# point P28_CAB_MOUNT_FL 20 -15 0
time [s],P25_FRONT_AXLE_PIN.FX [lbf],P25_FRONT_AXLE_PIN.FY [lbf],P25_FRONT_AXLE_PIN.FZ [lbf],P25_FRONT_AXLE_PIN.MX [lbf*in],P25_FRONT_AXLE_PIN.MY [lbf*in],P25_FRONT_AXLE_PIN.MZ [lbf*in],P28_CAB_MOUNT_FL.FX [lbf],P28_CAB_MOUNT_FL.FY [lbf],P28_CAB_MOUNT_FL.FZ [lbf],P28_CAB_MOUNT_FL.MX [lbf*in],P28_CAB_MOUNT_FL.MY [lbf*in],P28_CAB_MOUNT_FL.MZ [lbf*in]
0,0,0,0,0,0,0,0,0,0,0,0,0
0.001,10,0,-300,0,0,0,0,0,50,0,0,0
0.002,20,0,-310,0,0,0,0,0,40,0,0,0
)";

std::string shipped_frame() { return read_file(fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "r100_frame.inp"); }

// `text` with `from` replaced once by `to`; an edit that does not apply is a
// broken row, not a passing one.
std::string edit(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("edit: no '" + from + "' in the base input");
  return text.substr(0, at) + to + text.substr(at + from.size());
}

int line_of(const std::string& text, const std::string& marker) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(marker) != std::string::npos) return n;
  throw std::logic_error("no line contains '" + marker + "'");
}

// ------------------------------------------------------------------ rows

struct Row {
  std::string id;
  std::vector<std::pair<std::string, std::string>> files;  // written into the run's folder
  std::string args;    // the command line after "framedyn"
  std::string where;   // how the message must begin: "frame.inp:12: *NODE", "study.yaml: frame.loads", "command line: --modes"
  bool expected_found = true;  // the message reads "expected ..., found ..."
};

std::ostream& operator<<(std::ostream& os, const Row& r) { return os << r.id; }

// Where in `file` (with text `text`): "file:LINE: key" with the line of `marker`.
std::string at(const std::string& file, const std::string& text, const std::string& marker, const std::string& key) {
  return file + ":" + std::to_string(line_of(text, marker)) + (key.empty() ? "" : ": " + key);
}

Row mesh_row(const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key,
             const std::string& command = "static frame.inp --out results -q") {
  const std::string text = edit(kMesh, from, to);
  return {id, {{"frame.inp", text}}, command, marker.empty() ? "frame.inp: " + key : at("frame.inp", text, marker, key)};
}

Row study_row(const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key,
              const std::string& base = kStudy2D) {
  const std::string text = edit(base, from, to);
  return {id, {{"study.yaml", text}}, "run study.yaml --out results -q", marker.empty() ? "study.yaml: " + key : at("study.yaml", text, marker, key)};
}

// kStudy3D with a frame_response on the shipped frame (copied in as frame.inp) and a response, `from` edited to `to`.
const std::string kStructurePart = "{name: frame_structure, weight: 565.6, position: [27.5, 0, 0], radii_of_gyration: [14, 30.3, 33.5]}";
Row structure_row(const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key) {
  const std::string text = edit(edit(kStudy3D, from, to), "analysis:\n",
                                "frame_response: {mesh: frame.inp}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
  return {id, {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q", at("study.yaml", text, marker, key)};
}

// kStudy3D's engine with `mounts` (coupling/frame_parts.h) and a frame_response on the shipped frame, free-free.
const std::string kEngine = "{name: engine, weight: 850, position: [40, 0, 14], radii_of_gyration: [12, 14, 14]}";
Row mounts_row(const std::string& id, const std::string& mounts, const std::string& key) {
  const std::string text =
      edit(edit(edit(kStudy3D, kStructurePart, "{name: frame_structure, from: frame_mesh}"), kEngine,
                "{name: engine, weight: 850, position: [40, 0, 14], radii_of_gyration: [12, 14, 14], mounts: " + mounts + "}"),
           "analysis:\n", "frame_response: {mesh: frame.inp, supports: none}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
  return {id, {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q", at("study.yaml", text, "name: engine", key)};
}

Row frame_row(const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key) {
  const std::string text = edit(kFrameStudy, from, to);
  return {id,
          {{"study.yaml", text}, {"frame.inp", shipped_frame()}, {"loads.csv", kLoads}},
          "frame-response study.yaml --out results",
          marker.empty() ? "study.yaml: " + key : at("study.yaml", text, marker, key)};
}

Row loads_row(const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key) {
  const std::string text = edit(kLoads, from, to);
  return {id,
          {{"study.yaml", kFrameStudy}, {"frame.inp", shipped_frame()}, {"loads.csv", text}},
          "frame-response study.yaml --out results",
          marker.empty() ? "loads.csv: " + key : at("loads.csv", text, marker, key)};
}

Row cli_row(const std::string& id, const std::string& args, const std::string& where, bool expected_found = true) {
  return {id, {{"frame.inp", kMesh}, {"study.yaml", kStudy2D}}, args, where, expected_found};
}

// A duty cycle's head (coupling/duty_cycle.h); the rows add its scenarios.
const std::string kDutyCycle = "framedyn_study: 1\nname: error table, duty cycle\nmodel: duty_cycle\n";

// A stress history for `framedyn rainflow` (a time column and one stress column in MPa).
const std::string kSeries = "time [s],sg1 [MPa]\n0,10\n0.1,50\n0.2,-20\n0.3,40\n";

std::vector<Row> rows() {
  const std::string kSection = "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n";
  const std::string kData = "*BOUNDARY\n";  // extra keywords go before the supports
  std::vector<Row> r = {
      // ---- .inp meshes (fem/inp_reader.cpp)
      mesh_row("INP-01", kData, "*SURFACE, NAME=TOP\n" + kData, "*SURFACE", "*SURFACE"),
      mesh_row("INP-02", "*NODE, NSET=ALL", "*NODE, NSETT=ALL", "*NODE", "*NODE"),
      mesh_row("INP-03", "*ELEMENT, TYPE=B31, ELSET=FRAME", "*ELEMENT, ELSET=FRAME", "*ELEMENT", "*ELEMENT"),
      mesh_row("INP-04", "TYPE=B31", "TYPE=S4R", "*ELEMENT", "*ELEMENT"),
      mesh_row("INP-05", "2, 1, 0, 0", "2, 1.0m, 0, 0", "2, 1.0m", "*NODE"),
      mesh_row("INP-06", "SECTION=RECT\n0.05, 0.1\n", "SECTION=BOX\n0.05, 0.1\n", "0.05", "*BEAM SECTION"),
      mesh_row("INP-07", "3, 2, 0, 0", "3, 1, 0, 0", "2, 2, 3", "*ELEMENT"),
      mesh_row("INP-08", "2, 2, 3", "2, 2, 2", "2, 2, 2", "*ELEMENT"),
      mesh_row("INP-09", "2, 2, 3", "2, 2, 9", "2, 2, 9", "*ELEMENT"),
      mesh_row("INP-10", "1, ENCASTRE", "7, ENCASTRE", "7, ENCASTRE", "*BOUNDARY"),
      mesh_row("INP-11", "3, 3, 1000.", "8, 3, 1000.", "8, 3, 1000.", "*CLOAD"),
      mesh_row("INP-12", "1, ENCASTRE", "SUPPORT, ENCASTRE", "SUPPORT, ENCASTRE", "*BOUNDARY"),
      mesh_row("INP-13", "*BEAM SECTION, ELSET=FRAME,", "*BEAM SECTION, ELSET=FRAMES,", "*BEAM SECTION", "*BEAM SECTION"),
      mesh_row("INP-14", "MATERIAL=STEEL", "MATERIAL=STEAL", "*BEAM SECTION", "*BEAM SECTION"),
      mesh_row("INP-15", "0.05, 0.1\n", "0.05, 0\n", "0.05, 0", "*BEAM SECTION"),
      mesh_row("INP-16", kSection, "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=BOX\n0.1, 0.1, 0.06, 0.06, 0.06, 0.06\n", "*BEAM SECTION",
               "*BEAM SECTION"),
      mesh_row("INP-17", kSection, "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, DENSITY=7850\n0, 1e-6, 0, 1e-6, 2e-6\n0, 0, -1\n2.1e11, 8.1e10\n",
               "*BEAM GENERAL SECTION", "*BEAM GENERAL SECTION"),
      mesh_row("INP-18", "2.1e11, 0.3", "-2.1e11, 0.3", "-2.1e11", "*ELASTIC"),
      mesh_row("INP-19", "2.1e11, 0.3", "2.1e11, 0.7", "2.1e11, 0.7", "*ELASTIC"),
      mesh_row("INP-20", "7850", "-7850", "-7850", "*DENSITY"),
      mesh_row("INP-21", kData, "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PM\n-5\n" + kData, "-5", "*MASS"),
      mesh_row("INP-22", kData, "*ELEMENT, TYPE=SPRING1, ELSET=K\n11, 3\n*SPRING, ELSET=K\n3\n-1e5\n" + kData, "-1e5", "*SPRING"),
      mesh_row("INP-23", kData, "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n12, 3\n*ROTARY INERTIA, ELSET=RI\n-1, 1, 1\n" + kData, "*ROTARY INERTIA",
               "*ROTARY INERTIA"),
      mesh_row("INP-24", "1, ENCASTRE", "1, 7", "1, 7", "*BOUNDARY"),
      mesh_row("INP-25", "3, 3, 1000.", "3, 9, 1000.", "3, 9, 1000.", "*CLOAD"),
      mesh_row("INP-26", "3, 2, 0, 0", "2, 2, 0, 0", "2, 2, 0, 0", "*NODE"),
      mesh_row("INP-27", "** units: m-N-s\n", "", "", "units"),
      mesh_row("INP-28", "** units: m-N-s", "** units: ft-lbf-s", "** units:", "** units:"),
      mesh_row("INP-29", "*STEP\n", "** units: mm-N-s\n*STEP\n", "** units: mm-N-s", "** units:"),
      mesh_row("INP-30", "*CLOAD\n3, 3, 1000.\n", "", "", "*CLOAD"),
      mesh_row("INP-31", "7850\n", "7850\n*ELASTIC\n2.0e11, 0.3\n", "2.0e11", "*ELASTIC"),
      mesh_row("INP-32", kData, "*ELEMENT, TYPE=B31\n3, 1, 3\n" + kData, "3, 1, 3", "*ELEMENT"),
      mesh_row("INP-33", "0.05, 0.1\n", "0.05, 0.1\n1, 0, 0\n", "*ELEMENT, TYPE=B31", "*ELEMENT"),
      mesh_row("INP-34", "*NODE, NSET=ALL", "*INCLUDE, INPUT=nodes.inp\n*NODE, NSET=ALL", "*INCLUDE", "*INCLUDE"),
      mesh_row("INP-36", "*NODE, NSET=ALL", "1, 0, 0, 0\n*NODE, NSET=ALL", "1, 0, 0, 0", ""),
      mesh_row("INP-37", "*STATIC\n", "*FREQUENCY\n0\n", "*FREQUENCY", "*FREQUENCY", "modes frame.inp --out results -q"),
      mesh_row("INP-38", "*ELASTIC\n2.1e11, 0.3\n", "", "*MATERIAL", "*MATERIAL"),
      mesh_row("INP-39", "** units: m-N-s", "** units: m-N-s", "** units:", "** units:", "static frame.inp --units in-lbf-s --out results -q"),
      {"INP-40", {}, "static nothere.inp --out results -q", "nothere.inp", false},
      // numbers within the file's range whose element matrices overflow (found by reading the reader against its fuzz harness)
      mesh_row("INP-41", "0.05, 0.1\n", "1e200, 1e200\n", "1, 1, 2", "*ELEMENT"),
      // three-node beams and CalculiX decks (issue 13)
      mesh_row("INP-42", "*STEP\n", "*STEP, NLGEOM\n", "*STEP, NLGEOM", "*STEP"),
      mesh_row("INP-44", "2, 1, 0, 0\n3, 2, 0, 0\n*ELEMENT, TYPE=B31, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n",
               "2, 0.2, 0, 0\n3, 2, 0, 0\n*ELEMENT, TYPE=B32, ELSET=FRAME\n1, 1, 2, 3\n", "1, 1, 2, 3", "*ELEMENT"),
      mesh_row("INP-45", "*ELEMENT, TYPE=B31, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n", "*ELEMENT, TYPE=B32R, ELSET=FRAME\n1, 1, 2, 1\n", "1, 1, 2, 1",
               "*ELEMENT"),
      // distributed loads, end releases, section options (issue 13)
      mesh_row("INP-46", kData, "*DLOAD\nFRAME, P3, 100.\n" + kData, "P3", "*DLOAD"),
      mesh_row("INP-47", kData, "*DLOAD\nFRAME, GRAV, 9.81, 0, 0, 0\n" + kData, "GRAV", "*DLOAD"),
      mesh_row("INP-48", "*DENSITY\n7850\n" + kData, "*DLOAD\n, GRAV, 9.81, 0, 0, -1\n" + kData, ", GRAV", "*DLOAD"),
      mesh_row("INP-49", kData, "*RELEASE\n2, S3, M1\n" + kData, "S3", "*RELEASE"),
      mesh_row("INP-50", kData, "*RELEASE\n2, S1, T\n2, S2, T\n" + kData, "S2, T", "*RELEASE"),
      mesh_row("INP-51", kData, "*TRANSVERSE SHEAR STIFFNESS\n1e8, 1e8\n" + kData, "*TRANSVERSE", "*TRANSVERSE SHEAR STIFFNESS"),
      mesh_row("INP-52", "SECTION=RECT", "SECTION=RECT, RAYLEIGH=YES", "*BEAM SECTION", "*BEAM SECTION"),
      // rigid links (fem/rigid_links.cpp, through the reader)
      mesh_row("INP-55", kData, "*NODE\n4, 0, 0, 0.5\n*NSET, NSET=ARM\n4\n*RIGID BODY, NSET=ARM, REF NODE=1\n*BOUNDARY\n4, 1\n" + kData,
               "*RIGID BODY, NSET=ARM, REF NODE=1", "*RIGID BODY"),
      mesh_row("INP-56", kData, "*NODE\n4, 2, 0, 0.5\n*MPC\nBEAM, 4, 3\nBEAM, 4, 2\n" + kData, "BEAM, 4, 2", "*MPC"),
      mesh_row("INP-57", kData, "*NODE\n4, 2, 0, 0.5\n5, 2, 0, 1\n*MPC\nBEAM, 4, 3\nBEAM, 5, 4\n" + kData, "BEAM, 5, 4", "*MPC"),
      mesh_row("INP-58", kData, "*NODE\n4, 2, 0, 0.5\n*NSET, NSET=ARM\n4\n*RIGID BODY, NSET=ARM, REF NODE=9\n" + kData,
               "*RIGID BODY, NSET=ARM, REF NODE=9", "*RIGID BODY"),
      mesh_row("INP-59", kData, "*NODE\n4, 2, 0, 0.5\n*NSET, NSET=ARM\n4\n*RIGID BODY, NSET=ARM, REF NODE=3, ROT NODE=5\n" + kData,
               "*RIGID BODY, NSET=ARM, REF NODE=3, ROT NODE=5", "*RIGID BODY"),
      mesh_row("INP-60", kData, "*MPC\nTIE, 3, 2\n" + kData, "TIE, 3, 2", "*MPC"),
      // multi-step decks and offsets (issue 13)
      mesh_row("INP-61", "*END STEP\n", "*END STEP\n*CLOAD, OP=MOD\n3, 2, 500.\n*STEP\n*STATIC\n*END STEP\n", "*CLOAD, OP=MOD", "*CLOAD"),
      mesh_row("INP-63", "*CLOAD\n3, 3", "*CLOAD, OP=ADD\n3, 3", "*CLOAD, OP=ADD", "*CLOAD"),
      mesh_row("INP-64", "*STATIC\n", "*STATIC\n*FREQUENCY\n5\n", "*FREQUENCY", "*FREQUENCY"),
      mesh_row("INP-67", "*CLOAD\n3, 3", "*BOUNDARY\n2, 3, 3\n*BOUNDARY, OP=NEW\n1, 1, 6\n*CLOAD\n3, 3", "*BOUNDARY, OP=NEW", "*BOUNDARY"),
      mesh_row("INP-68", kData, "*AMPLITUDE, NAME=RAMP, TIME=TOTAL TIME\n0, 0, 1, 1\n" + kData, "*AMPLITUDE", "*AMPLITUDE"),
      mesh_row("INP-69", "*STATIC\n", "*STEADY STATE DYNAMICS\n", "*STEADY STATE DYNAMICS", "*STEADY STATE DYNAMICS"),
      // transient steps of a deck (issue 13): fem/inp_reader.cpp, fem/transient_step.cpp, apps/transient_command.cpp
      mesh_row("INP-70", kData, "*AMPLITUDE, NAME=RAMP\n0, 0, 1\n" + kData, "0, 0, 1", "*AMPLITUDE"),
      mesh_row("INP-71", "*CLOAD\n3, 3", "*CLOAD, AMPLITUDE=RAMP\n3, 3", "3, 3, 1000.", "*CLOAD"),
      mesh_row("INP-72", "*STATIC\n", "*DYNAMIC\n0.25\n", "0.25", "*DYNAMIC"),
      mesh_row("INP-73", "*STATIC\n", "*MODAL DYNAMIC\n0.01, 0.1\n", "", "*MODAL DYNAMIC", "transient frame.inp --out results -q"),
      mesh_row("INP-74", "*STATIC\n", "*STATIC\n*MODAL DAMPING\n1, 5, 0.02\n", "*MODAL DAMPING", "*MODAL DAMPING"),
      mesh_row("INP-75", "*STATIC\n", "*DYNAMIC, ALPHA=-0.05\n0.01, 0.1\n", "*DYNAMIC", "*DYNAMIC"),
      mesh_row("INP-76", "*CLOAD\n3, 3, 1000.\n", "*DLOAD, AMPLITUDE=RAMP\nFRAME, PZ, 100.\n", "*DLOAD", "*DLOAD"),
      mesh_row("INP-77", "*STATIC\n*CLOAD\n", "*STATIC\n*AMPLITUDE, NAME=RAMP\n0, 0, 1, 1\n*CLOAD, AMPLITUDE=RAMP\n", "*STEP", "*STEP"),
      mesh_row("INP-78", "*STEP\n*STATIC\n", "*STEP\n*FREQUENCY\n2\n*END STEP\n*STEP\n*MODAL DYNAMIC\n0.01, 0.1\n*BOUNDARY\n2, 2\n", "",
               "*MODAL DYNAMIC", "transient frame.inp --out results -q"),
      mesh_row("INP-66", "*END STEP\n", "*END STEP\n*STEP\n*STATIC\n*CLOAD, OP=NEW\n*END STEP\n", "", "*CLOAD"),
  };
  // INP-39: the mesh says m-N-s, the command line in-lbf-s.
  for (Row& row : r) {
    // Errors on a keyword line above, or a data line below, a line that is easier to find.
    if (row.id == "INP-31") row.where = "frame.inp:" + std::to_string(line_of(row.files[0].second, "2.0e11") - 1) + ": *ELASTIC";
    if (row.id == "INP-33") row.where = at("frame.inp", row.files[0].second, "1, 1, 2", "*ELEMENT");
    if (row.id == "INP-34") row.expected_found = false;
    if (row.id == "INP-37") row.where = "frame.inp:" + std::to_string(line_of(row.files[0].second, "*FREQUENCY") + 1) + ": *FREQUENCY";
  }

  const std::vector<Row> studies = {
      // ---- 2-D rigid-body studies (coupling/rigid_study.cpp, study_blocks.cpp, yaml_input.cpp)
      study_row("STUDY-01", "contact: [72, -26]", "contact: [72, -26]]", "contact: [72, -26]]", ""),
      study_row("STUDY-02", "name: error table, 2-D\n", "name: error table, 2-D\ncolour: red\n", "colour", "colour"),
      study_row("STUDY-03", "stiffness: 1630, damping: 5}\n  rear_mount", "stiffness: 1630, dampng: 5}\n  rear_mount", "dampng", "cab.front_mount.dampng"),
      study_row("STUDY-04", "    contact: [0, -26]\n", "", "    normal: {stiffness: 5000", "tires.front.contact"),
      study_row("STUDY-05", "normal: {stiffness: 6000", "normal: {stiffness: stiff", "stiffness: stiff", "tires.rear.normal.stiffness"),
      study_row("STUDY-06", "blade_point: [118, -44]", "blade_point: 118", "blade_point: 118", "plow.blade_point"),
      study_row("STUDY-07", "ground: {slope_deg: 0, forward_speed: 6}", "ground: 6", "ground: 6", "ground"),
      study_row("STUDY-08", "  modes: true", "  modes: often", "modes: often", "analysis.modes"),
      study_row("STUDY-09", "stiffness: 1500, damping: 5}", "stiffness: -1500, damping: 5}", "stiffness: -1500", "plow.bounce_tire.stiffness"),
      study_row("STUDY-10", "tractive: {stiffness: 3600, damping: 15}", "tractive: {stiffness: 3600, damping: -15}", "damping: -15", "tires.front.tractive.damping"),
      study_row("STUDY-11", "  weight: 650\n", "  weight: -650\n", "weight: -650", "cab.weight"),
      study_row("STUDY-12", "  weight: 650\n", "  weight: 650\n  mass: 1.7\n", "  weight: 650", "cab"),
      study_row("STUDY-13", "  weight: 2800\n", "", "  radius_of_gyration: 14", "plow"),
      study_row("STUDY-14", "damping_reduction: 0.25", "damping_reduction: 1.25", "damping_reduction: 1.25", "soil.damping_reduction"),
      study_row("STUDY-15", "stiffness_reduction: 0,", "stiffness_reduction: -0.1,", "stiffness_reduction: -0.1", "soil.stiffness_reduction"),
      study_row("STUDY-16", "duration: 0.12", "duration: 0", "duration: 0", "analysis.response.duration"),
      study_row("STUDY-17", "output_interval: 0.001", "output_interval: -0.001", "output_interval: -0.001", "analysis.response.output_interval"),
      study_row("STUDY-18", "rk4_step: 0.0005", "rk4_step: 0", "rk4_step: 0", "analysis.response.rk4_step"),
      study_row("STUDY-19", "rk4_step: 0.0005", "rk4_step: 0.0003", "rk4_step: 0.0003", "analysis.response.rk4_step"),
      study_row("STUDY-20", "rk4_step: 0.0005}", "rk4_step: 0.0005, relative_tolerance: 0.5}", "relative_tolerance", "analysis.response.relative_tolerance"),
      study_row("STUDY-21", "units: in-lbf-s", "units: furlong-stone-fortnight", "units: furlong", "units"),
      study_row("STUDY-22", "framedyn_study: 1", "framedyn_study: 2", "framedyn_study: 2", "framedyn_study"),
      study_row("STUDY-23", "model: rigid_2d", "model: rigid_4d", "model: rigid_4d", "model"),
      study_row("STUDY-24", "attachment: plow", "attachment: harrow", "attachment: harrow", "attachment"),
      study_row("STUDY-83", "attachment: plow", "attachment: plow\ncontacts: rigid", "contacts: rigid", "contacts"),
      // No bounce tire: the plow behind the rear axle tips the machine backward off its front tire.
      study_row("STUDY-84", "bounce_tire: {point: [130, -26], stiffness: 1500, damping: 5}", "bounce_tire: {point: [130, -26], stiffness: 0, damping: 5}", "",
                "contacts"),
      study_row("STUDY-25", "attachment: plow", "attachment: chain", "  weight: 2800", "plow"),
      study_row("STUDY-26", "upper_joint: [112, 4]", "upper_joint: [130, -13]", "    upper_pivot", "plow.linkage"),
      study_row("STUDY-27", "arm_point: [96, 5]", "arm_point: [66, 24]", "arm_point: [66, 24]", "plow.lift_cylinder.arm_point"),
      study_row("STUDY-28", "weight_per_length: 5.39}\n  added_masses:\n    - {name: engine, weight: 850, radius_of_gyration: 14, position: [40, 14]}\n    - {name: rear_axle, weight: 900, radius_of_gyration: 12, position: [72, -14]}\n",
                "weight_per_length: 0}\n", "weight_per_length: 0", "frame.uniform_section.weight_per_length"),
      study_row("STUDY-29", "points: [-25, 0, 36, 80]", "points: [-25, 0, 36, 800]", "points:", "frame_output.points"),
      study_row("STUDY-30", "fixed_coordinates: [x]", "fixed_coordinates: [x, phi]", "fixed_coordinates", "analysis.fixed_coordinates"),
      study_row("STUDY-31", "  radius_of_gyration: 16", "  radius_of_gyration: 0", "radius_of_gyration: 0", "cab.radius_of_gyration"),
      study_row("STUDY-32", "length: 105", "length: 0", "length: 0", "frame.uniform_section.length"),
      study_row("STUDY-33", "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: {kind: square, amplitude: 1}\n", "kind: square",
                "tires.front.normal_input.kind"),
      study_row("STUDY-34", "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: {kind: table, times: [0, 0.2, 0.1], values: [0, 1, 0]}\n",
                "kind: table", "tires.front.normal_input.times"),
      study_row("STUDY-35", "  modes: true\n", "  modes: true\n  modal_soil: wet\n", "modal_soil: wet", "analysis.modal_soil"),
      study_row("STUDY-36", "analysis:\n", "calibration: {parameters: [cab.stiffness], targets: [{frequency_hz: 2}]}\nanalysis:\n", "calibration",
                "calibration.parameters"),
      study_row("STUDY-74", "analysis:\n", "calibration: {fit_labels: true, parameters: [cab.inertia], targets: [{frequency_hz: 2}]}\nanalysis:\n",
                "calibration", "calibration.fit_labels"),
      study_row("STUDY-75", "analysis:\n",
                "calibration: {parameters: [cab.front_mount.stiffness, cab.rear_mount.stiffness], targets: [{frequency_hz: 6}]}\nanalysis:\n",
                "calibration", "calibration.parameters"),
      study_row("STUDY-76", "analysis:\n",
                "calibration: {parameters: [cab.inertia], targets: [{frequency_hz: 6}], bounds: [{parameter: cab.inertia, upper: 1e9}]}\nanalysis:\n",
                "calibration", "calibration.bounds[0].reason"),
      study_row("STUDY-77", "analysis:\n",
                "calibration: {parameters: [cab.inertia], targets: [{frequency_hz: 6}], bounds: [{parameter: cab.inertia, upper: 1, reason: r}]}\nanalysis:\n",
                "calibration", "calibration.bounds[0].parameter"),
      study_row("STUDY-78", "analysis:\n", "calibration: {parameters: [cab.inertia, cab.inertia], targets: [{frequency_hz: 6}, {frequency_hz: 7}]}\nanalysis:\n",
                "calibration", "calibration.parameters"),
      study_row("STUDY-100", "analysis:\n",
                "calibration: {parameters: [cab.inertia], targets: [{frequency_hz: 6, shape: {components: [{coordinate: theta_q, value: 1}]}}]}\nanalysis:\n",
                "calibration", "calibration.targets[0].shape.components[0].coordinate"),
      study_row("STUDY-101", "analysis:\n",
                "calibration: {parameters: [cab.inertia], targets: [{frequency_hz: 6, shape: {components: [{coordinate: z, frame_point: [40, 10], value: 1}]}}]}\nanalysis:\n",
                "calibration", "calibration.targets[0].shape.components[0].coordinate"),
      study_row("STUDY-136", "analysis:\n", "calibration: {pair_with: in_plane, parameters: [cab.mounts.z.stiffness], targets: [{frequency_hz: 3}]}\nanalysis:\n",
                "calibration", "calibration.pair_with", kStudy3D),
      study_row("STUDY-137", "analysis:\n", "calibration: {pair_with: symmetric_modes, parameters: [cab.inertia], targets: [{frequency_hz: 6}]}\nanalysis:\n",
                "calibration", "calibration.pair_with"),
      study_row("STUDY-167", "radius_of_gyration: 14, position: [40, 14]}", "radius_of_gyration: 14, position: [40, 14], dimensions: {length: 10, height: 10}}",
                "name: engine", "frame.added_masses[0].dimensions"),
      study_row("STUDY-146", "  rear_mount: {position: [52, 3], stiffness: 1630, damping: 5}\ntires:",
                "  rear_mount: {position: [52, 3], stiffness: 1630, damping: 5}\n  dimensions: {length: 30}\ntires:", "dimensions: {length: 30}",
                "cab.dimensions"),
      study_row("STUDY-168", "radius_of_gyration: 14, position: [40, 14]}", "radius_of_gyration: 14, position: [40, 14], dimensions: {}}", "name: engine",
                "frame.added_masses[0].dimensions"),
      study_row("STUDY-169", "radius_of_gyration: 14, position: [40, 14]}", "radius_of_gyration: 14, position: [40, 14], distributed: true}", "name: engine",
                "frame.added_masses[0].distributed"),
      study_row("STUDY-138", "analysis:\n",
                "calibration: {pair_with: symmetric_modes, parameters: [cab.mounts.z.stiffness], targets: [{frequency_hz: 3}]}\nanalysis:\n",
                "calibration", "calibration.pair_with", edit(kStudy3D, "position: [40, 0, 14]", "position: [40, 10, 14]")),
      study_row("STUDY-79", "analysis:\n",
                "calibration: {parameters: [cab.inertia], targets: [{frequency_hz: 6}], bounds: [{parameter: cab.mass, upper: 9, reason: r}]}\nanalysis:\n",
                "calibration", "calibration.bounds[0].parameter"),
      study_row("STUDY-80", "analysis:\n",
                "calibration: {parameters: [cab.mass], targets: [{frequency_hz: 6}], bounds: [{parameter: cab.mass, dimensions: [1, 1, 1]}]}\nanalysis:\n",
                "calibration", "calibration.bounds[0].dimensions"),
      // ---- 3-D rigid-body studies (coupling/study_machine_3d.cpp)
      study_row("STUDY-37", "pin: [72, 0, 0]", "pin: [72, 0]", "pin: [72, 0]", "frame.rear_axle.pin", kStudy3D),
      study_row("STUDY-38", "  front:\n    steering_deg: 0", "  front:\n    steering_deg: 95", "steering_deg: 95", "tires.front.steering_deg", kStudy3D),
      study_row("STUDY-39", "leveling_cylinder: [68, 15, 0]", "leveling_cylinder: [68, 0, 0]", "leveling_cylinder", "frame.rear_axle.leveling_cylinder",
                kStudy3D),
      study_row("STUDY-40", "    - {name: RR, position: [52, 15, 0], x: {stiffness: 245}, y: {stiffness: 266}, z: {stiffness: 815}}\n", "", "- {name: FL",
                "cab.mounts", kStudy3D),
      study_row("STUDY-41", "radii_of_gyration: [22, 10, 22]", "radii_of_gyration: [22, -10, 22]", "radii_of_gyration: [22, -10", "front_axle.radii_of_gyration",
                kStudy3D),
      study_row("STUDY-42", "analysis:\n", "frame_response: {mesh: frame.inp, loads: loads.csv}\nanalysis:\n", "frame_response", "frame_response.loads",
                kStudy3D),
      study_row("STUDY-43", "analysis:\n", "frame_response: {mesh: frame.inp}\nanalysis:\n", "frame_response", "frame_response", kStudy3D),
      // ---- frame transient studies (coupling/frame_study.cpp)
      frame_row("STUDY-44", "  stations: 3\n", "  stations: 3\n  mthod: direct\n", "mthod", "frame.mthod"),
      frame_row("STUDY-45", "  mesh: frame.inp\n", "", "  loads:", "frame.mesh"),
      frame_row("STUDY-46", "mesh: frame.inp", "mesh: frame_v2.inp", "mesh:", "frame.mesh"),
      frame_row("STUDY-47", "supports: fixed_rear_end", "supports: pinned", "supports:", "frame.supports"),
      [] {  // supports: axle_pins on a mesh without the rear axle pin's node set (docs/theory/coupling.md section 12)
        const std::string text = edit(kFrameStudy, "supports: fixed_rear_end", "supports: axle_pins");
        return Row{"STUDY-126",
                   {{"study.yaml", text}, {"frame.inp", edit(shipped_frame(), "*NSET, NSET=P26_REAR_AXLE_PIN\n50\n", "")}, {"loads.csv", kLoads}},
                   "frame-response study.yaml --out results", at("study.yaml", text, "supports:", "frame.supports")};
      }(),
      frame_row("STUDY-48", "method: mode_displacement", "method: modal", "method:", "frame.method"),
      frame_row("STUDY-49", "modes: 4", "modes: 0", "modes:", "frame.modes"),
      frame_row("STUDY-50", "modal_ratio: 0.02", "modal_ratio: 1.5", "damping:", "frame.damping.modal_ratio"),
      frame_row("STUDY-51", "method: mode_displacement", "method: direct", "damping:", "frame.damping"),
      frame_row("STUDY-52", "output_interval: 0.001", "output_interval: 0", "output_interval:", "frame.output_interval"),
      frame_row("STUDY-53", "stations: 3", "stations: 1", "stations:", "frame.stations"),
      frame_row("STUDY-155", "  stations: 3\n", "  stations: 3\n  inp_dialect: ccx\n", "inp_dialect:", "frame.inp_dialect"),
      frame_row("STUDY-150", "  stations: 3\n", "  stations: 3\n  sections: {RAILZ: {t1: 0.3}}\n", "sections:", "frame.sections.RAILZ"),
      frame_row("STUDY-151", "  stations: 3\n", "  stations: 3\n  sections: {RAILS: {r: 0.3}}\n", "sections:", "frame.sections.RAILS.r"),
      frame_row("STUDY-152", "  stations: 3\n", "  stations: 3\n  sections: {RAILS: {t1: 0}}\n", "sections:", "frame.sections.RAILS.t1"),
      frame_row("STUDY-153", "  stations: 3\n", "  stations: 3\n  sections: {RAILS: {t2: 2.8}}\n", "sections:", "frame.sections.RAILS.t2"),
      frame_row("STUDY-154", "  stations: 3\n", "  stations: 3\n  sections: {RAILS: {t1: 0.3}, rails: {t3: 0.3}}\n", "sections:", "frame.sections.rails"),
      frame_row("STUDY-54", "supports: fixed_rear_end", "supports: fixed_rear_end\n  support_set: BACK", "support_set: BACK", "frame.support_set"),
      frame_row("STUDY-55", "modes: 4", "modes: 100000", "modes: 100000", "frame.modes"),
      frame_row("STUDY-56", "damping: {modal_ratio: 0.02}", "damping: {rayleigh: {alpha: -1, beta: 0}}", "damping:", "frame.damping.rayleigh.alpha"),
      frame_row("STUDY-57", "model: frame_transient", "model: rigid_2d", "model:", "model"),
      // ---- ISO 8608 rough ground under a tire (coupling/study_blocks.cpp)
      study_row("STUDY-125", "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: {kind: road, class: J, speed: 80}\n", "kind: road",
                "tires.front.normal_input.class"),
      study_row("STUDY-141", "    left:  {contact: [72, -30, -26], vertical: {stiffness: 3000}",
                "    left:  {contact: [-10, -30, -26], vertical_input: {kind: road, class: D, speed: 78.74}, vertical: {stiffness: 3000}", "vertical_input:",
                "tires.rear.left.vertical_input", kStudy3D),
      study_row("STUDY-160", "    contact: [72, -26]\n", "    contact: [-10, -26]\n    normal_input: {kind: road, class: D, speed: 78.74}\n", "normal_input:",
                "tires.rear.normal_input"),
      // ---- the frame pipeline asked of the 2-D model (docs/theory/coupling.md section 17)
      study_row("STUDY-142", "name: error table, 2-D\n", "name: error table, 2-D\nframe_response: {mesh: frame.inp}\n", "frame_response:", "frame_response"),
      // A feature of one model in a study of the other, refused with the reason (issue 15).
      study_row("STUDY-139", "name: error table, 3-D\n", "name: error table, 3-D\nframe_output: {points: [0]}\n", "frame_output:", "frame_output", kStudy3D),
      // (STUDY-140, soil_line refused in 3-D, is retired: the 3-D soil anchors stream with the soil.)
      // ---- duty cycles (coupling/duty_cycle.cpp)
      Row{"STUDY-123", {{"study.yaml", kDutyCycle + "scenarios: []\n"}}, "run study.yaml --out results -q", at("study.yaml", kDutyCycle + "scenarios: []\n", "scenarios", "scenarios")},
      Row{"STUDY-124", {{"study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n"}}, "run study.yaml --out results -q",
          at("study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n", "plowing.yaml", "scenarios[0].study")},
      Row{"STUDY-129", {{"study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n  - {name: plowing, study: plowing.yaml, hours: 10}\n"},
                        {"plowing.yaml", "framedyn_study: 1\nmodel: rigid_3d\n"}},
          "run study.yaml --out results -q",
          at("study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n  - {name: plowing, study: plowing.yaml, hours: 10}\n",
             "hours: 10", "scenarios[1].name")},
      Row{"STUDY-130", {{"study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n"},
                        {"plowing.yaml", "framedyn_study: 1\nmodel: rigid_2d\n"}},
          "run study.yaml --out results -q",
          at("study.yaml", kDutyCycle + "scenarios:\n  - {name: plowing, study: plowing.yaml, hours: 50}\n", "plowing.yaml", "scenarios[0].study")},
      // ---- the fatigue life map (coupling/frame_fatigue.cpp)
      frame_row("STUDY-114", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {code: AWS}\n", "fatigue:", "frame.fatigue.code"),
      frame_row("STUDY-115", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {default: FAT7l}\n", "fatigue:", "frame.fatigue.default"),
      frame_row("STUDY-116", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {mean_stress: gerber}\n", "fatigue:", "frame.fatigue.mean_stress"),
      frame_row("STUDY-117", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {mean_stress: goodman}\n", "fatigue:", "frame.fatigue.mean_stress"),
      frame_row("STUDY-118", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {ultimate_strength: 58000}\n", "fatigue:", "frame.fatigue.ultimate_strength"),
      frame_row("STUDY-119", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue: {code: EN1993, thickness_exponent: 0.3}\n", "fatigue:", "frame.fatigue.thickness_exponent"),
      frame_row("STUDY-165", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue:\n    details: [{element_set: LEFT_RAIL, class: FAT80, curve: weld.yaml}]\n", "details:", "frame.fatigue.details[0].curve"),
      frame_row("STUDY-120", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue:\n    details: [{element_set: LEFT_RAILS, class: FAT80}]\n", "details:", "frame.fatigue.details[0].element_set"),
      frame_row("STUDY-121", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  fatigue:\n    details: [{element_set: CROSS_MEMBERS, class: FAT80}]\n", "details:", "frame.fatigue.details[0].element_set"),
      frame_row("STUDY-122", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n" "  steady_from: 1\n  fatigue: {hours: 100}\n", "fatigue:", "frame.fatigue"),
      study_row("STUDY-58", "soil: {stiffness: 40000,", "soil: {stiffness: 1e308,", "soil: {stiffness: 1e308", "soil.stiffness"),
      // names that label frame loads and sweep parameters
      study_row("STUDY-59", "{name: rear_axle,", "{name: engine,", "{name: engine, weight: 900", "frame.added_masses[1].name"),
      study_row("STUDY-60", "{name: rear_axle,", "{name: front_tire,", "{name: front_tire,", "frame.added_masses[1].name"),
      study_row("STUDY-61", "{name: RR,", "{name: RL,", "{name: RL, position: [52, 15", "cab.mounts[3].name", kStudy3D),
      study_row("STUDY-62", "{name: engine, weight: 850, position: [40, 0, 14]", "{name: frame_structure, weight: 850, position: [40, 0, 14]",
                "{name: frame_structure, weight: 850", "frame.parts[1].name", kStudy3D),
      // error branches no row had tested, found by replaying the study fuzz corpus through a coverage build (docs/fuzzing.md)
      study_row("STUDY-63", "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: {kind: table, times: [0, 0.1, 0.2], values: [0, 1]}\n",
                "kind: table", "tires.front.normal_input.values"),
      study_row("STUDY-64", "weight_per_length: 5.39}", "weight_per_length: 5.39, mass_per_length: 0.014}", "uniform_section:", "frame.uniform_section"),
      study_row("STUDY-65", "  position: [0, 0, -14]\n  radii_of_gyration: [22, 10, 22]", "  position: [0, 0, 0]\n  radii_of_gyration: [0, 10, 22]",
                "  weight: 650", "front_axle", kStudy3D),
      frame_row("STUDY-66", "damping: {modal_ratio: 0.02}", "damping: {modal_ratio: 0.02, rayleigh: {alpha: 1, beta: 0}}", "damping:", "frame.damping"),
      // output sets and supports by set name (issue 13)
      frame_row("STUDY-67", "{element_set: LEFT_RAIL}", "{element_set: LEFT_RAILS}", "{element_set: LEFT_RAILS}", "frame.outputs.left_rail.element_set"),
      frame_row("STUDY-68", "    right_rail: {element_set: RIGHT_RAIL}\n", "    right_rail: {element_set: RIGHT_RAIL}\n    axle: {node_set: FRONT_AXLE}\n",
                "{node_set: FRONT_AXLE}", "frame.outputs.axle.node_set"),
      frame_row("STUDY-69", "{element_set: LEFT_RAIL}", "{element_set: LEFT_RAIL, node_set: LEFT_RAIL_NODES}", "left_rail:", "frame.outputs.left_rail"),
      frame_row("STUDY-70", "  supports: fixed_rear_end\n", "", "  mesh:", "frame.supports"),
      frame_row("STUDY-71", "supports: fixed_rear_end", "supports: clamped", "supports:", "frame.supports"),
      frame_row("STUDY-72", "    left_rail:", "    left rail:", "left rail:", "frame.outputs.left rail"),
      frame_row("STUDY-73", "supports: fixed_rear_end", "supports: none\n  support_set: REAR_END", "support_set:", "frame.support_set"),
      study_row("STUDY-81", "  radius_of_gyration: 16\n  position: [36, 32]", "  radius_of_gyration: 16\n  position: [36, 32]\n  radius_of_gyration: 18",
                "radius_of_gyration: 18", "cab.radius_of_gyration"),
      frame_row("STUDY-82", "units: in-lbf-s", "units: m-N-s", "mesh:", "frame.mesh"),
      frame_row("STUDY-90", "  stations: 3\n", "  stations: 3\n  mesh_loads: gravity\n", "mesh_loads:", "frame.mesh_loads"),
      frame_row("STUDY-102", "  stations: 3\n", "  stations: 3\n  stress_histories: yes\n", "stress_histories:", "frame.stress_histories"),
      frame_row("OUT-06", "  stations: 3\n", "  stations: 3\n  paraview: vtk\n", "paraview:", "frame.paraview"),
      frame_row("OUT-07", "  stations: 3\n", "  stations: 3\n  pvd: true\n  paraview: xdmf\n", "pvd:", "frame.pvd"),
      // ---- the frame structure's mass from the frame mesh (coupling/frame_mass_source.cpp)
      study_row("STUDY-96", kStructurePart, "{name: frame_structure, from: frame_mesh}", "from: frame_mesh", "frame.parts[0].from", kStudy3D),
      structure_row("STUDY-97", kStructurePart, "{name: tubes, weight: 565.6, position: [27.5, 0, 0], radii_of_gyration: [14, 30.3, 33.5]}",
                    "name: tubes", "frame.parts"),
      structure_row("STUDY-98", kStructurePart, kStructurePart, "name: frame_structure", "frame.parts[0]"),
      study_row("STUDY-99", kStructurePart, "{name: frame_structure, from: mesh}", "from: mesh", "frame.parts[0].from", kStudy3D),
      [] {  // the mesh's own loads with the dead load on: gravity twice
        const std::string text = edit(kStudy3D, "analysis:\n",
                                      "frame_response: {mesh: frame.inp, mesh_loads: constant}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
        return Row{"STUDY-106", {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q",
                   at("study.yaml", text, "mesh_loads", "frame_response.mesh_loads")};
      }(),
      [] {  // a support to compare that the pipeline does not know
        const std::string text = edit(kStudy3D, "analysis:\n",
                                      "frame_response: {mesh: frame.inp, compare_supports: [clamp]}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
        return Row{"STUDY-127", {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q",
                   at("study.yaml", text, "compare_supports", "frame_response.compare_supports")};
      }(),
      [] {  // the run's own support compared with itself
        const std::string text = edit(kStudy3D, "analysis:\n",
                                      "frame_response: {mesh: frame.inp, supports: none, compare_supports: [fixed_rear_end, none]}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
        return Row{"STUDY-128", {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q",
                   at("study.yaml", text, "compare_supports", "frame_response.compare_supports")};
      }(),
      // ---- a frame part's mounts on the frame mesh (coupling/study_machine_3d.cpp, frame_parts.cpp)
      mounts_row("STUDY-110", "[12, left]", "frame.parts[1].mounts[1]"),
      mounts_row("STUDY-111", "[12, 34, 14, 99]", "frame.parts[1].mounts[3]"),
      mounts_row("STUDY-112", "[12, 13, 14]", "frame.parts[1].mounts"),
      mounts_row("STUDY-113", "[12, 34, [31, -15, 0]]", "frame.parts[1].mounts[2]"),
      [] {  // mounts on the part the mesh models (its own tubes)
        const std::string text = edit(edit(kStudy3D, kStructurePart,
                                           "{name: frame_structure, from: frame_mesh, weight: 565.6, position: [30.7, 0, 0], "
                                           "radii_of_gyration: [12, 34, 36], mounts: [12, 34]}"),
                                      "analysis:\n", "frame_response: {mesh: frame.inp, supports: none}\nanalysis:\n  response: {duration: 0.01, output_interval: 0.001}\n");
        return Row{"STUDY-107", {{"study.yaml", text}, {"frame.inp", shipped_frame()}}, "run study.yaml --out results -q",
                   at("study.yaml", text, "name: frame_structure", "frame.parts[0].mounts")};
      }(),
  };
  for (Row row : studies) {
    // A value in a flow map is on its key's line: the markers above find it.
    if (row.id == "STUDY-50") row.where = at("study.yaml", row.files[0].second, "modal_ratio", "frame.damping.modal_ratio");
    if (row.id == "STUDY-56") row.where = at("study.yaml", row.files[0].second, "alpha", "frame.damping.rayleigh.alpha");
    r.push_back(row);
  }

  const std::vector<Row> loads = {
      // ---- load-history files (coupling/load_history.cpp, frame_study.cpp)
      loads_row("LOADS-01", "# framedyn load history, version 1", "time [s],FX", "time [s],FX", ""),
      loads_row("LOADS-02", "version 1", "version 2", "version 2", "version"),
      loads_row("LOADS-03", "# units: in-lbf-s", "# units: ft-lbf-s", "# units", "units"),
      loads_row("LOADS-04", "P25_FRONT_AXLE_PIN.FZ [lbf]", "P25_FRONT_AXLE_PIN.FZ [N]", "time [s]", "column 4 (P25_FRONT_AXLE_PIN.FZ)"),
      loads_row("LOADS-05", "# point P28_CAB_MOUNT_FL 20 -15 0", "# point P28_CAB_MOUNT_FL 20 -15", "# point P28", "point"),
      loads_row("LOADS-06", "# point P28_CAB_MOUNT_FL 20 -15 0", "# point P28_CAB_MOUNT_FL 20 left 0", "# point P28", "point P28_CAB_MOUNT_FL"),
      loads_row("LOADS-07", "# point P28_CAB_MOUNT_FL 20 -15 0", "# point P25_FRONT_AXLE_PIN 20 -15 0", "# point P25_FRONT_AXLE_PIN 20",
                "point P25_FRONT_AXLE_PIN"),
      loads_row("LOADS-08", "P25_FRONT_AXLE_PIN.MX [lbf*in],", "", "time [s]", "column 5"),
      loads_row("LOADS-09", "P28_CAB_MOUNT_FL.FX [lbf]", "P29_CAB_MOUNT_FR.FX [lbf]", "time [s]", "column 8"),
      loads_row("LOADS-10", "0.001,10,0,-300,0,0,0,0,0,50,0,0,0", "0.001,10,0,-300,0,0,0,0,0,50,0,0", "0.001,", ""),
      loads_row("LOADS-11", "0.001,10,0,-300", "0.001,10,0,heavy", "0.001,", "column 4 (P25_FRONT_AXLE_PIN.FZ [lbf])"),
      loads_row("LOADS-12", "0.001,10,0,-300", "0.001,10,0,nan", "0.001,", "column 4 (P25_FRONT_AXLE_PIN.FZ [lbf])"),
      loads_row("LOADS-13", "0.002,20", "0.001,20", "0.001,20", "column 1 (time [s])"),
      loads_row("LOADS-14", "0,0,0,0,0,0,0,0,0,0,0,0,0\n0.001,10,0,-300,0,0,0,0,0,50,0,0,0\n0.002,20,0,-310,0,0,0,0,0,40,0,0,0\n", "", "", ""),
      loads_row("LOADS-15", "0.001,10,0,-300,0,0,0,0,0,50,0,0,0\n0.002,20,0,-310,0,0,0,0,0,40,0,0,0\n", "", "", "rows"),
      loads_row("LOADS-16", "# point P25_FRONT_AXLE_PIN 0 0 0", "# point P25_FRONT_AXLE_PIN 0 0 -500", "# point P25", "point P25_FRONT_AXLE_PIN"),
      loads_row("LOADS-17", "# point P25_FRONT_AXLE_PIN 0 0 0\n# point P28_CAB_MOUNT_FL 20 -15 0\n", "", "time [s]", "point"),
      {"LOADS-18", {{"study.yaml", kFrameStudy}, {"frame.inp", shipped_frame()}, {"loads.csv", kLoads}}, "frame-response study.yaml --loads nothere.csv --out results",
       "nothere.csv", false},
      loads_row("LOADS-19", "0.001,10,0,-300", "0.001,10,0,-1e308", "0.001,10,0,-1e308", "column 4 (P25_FRONT_AXLE_PIN.FZ [lbf])"),
      loads_row("LOADS-20", "0.001,10,0,-300", "0.001,10,0,-8e299", "0.001,10,0,-8e299", "column 4 (P25_FRONT_AXLE_PIN.FZ [lbf])"),
      // ---- the mesh's loads in a static solve of a frame on one pin (apps/static_command.cpp, fem/partial_supports.cpp)
      {"LOADS-21", {{"frame.inp", edit(kMesh, "1, ENCASTRE\n", "1, 1, 3\n")}}, "static frame.inp --out results -q", "frame.inp: *CLOAD"},
  };
  for (Row row : loads) {
    if (row.id == "LOADS-14") row.where = "loads.csv:" + std::to_string(line_of(row.files[2].second, "time [s]") + 1);
    r.push_back(row);
  }

  const std::string sweep = "sweep study.yaml --no-figures --out results -q ";
  const std::vector<Row> cli = {
      // ---- the command line (apps/*.cpp)
      cli_row("CLI-01", "", "command line"),
      cli_row("CLI-02", "mode frame.inp", "command line"),
      cli_row("CLI-03", "static frame.inp --no-such-option", "command line"),
      cli_row("CLI-04", "static --out results", "command line: mesh"),
      cli_row("CLI-05", "modes frame.inp --modes 0 --out results", "command line: --modes"),
      cli_row("CLI-61", "modes frame.inp --paraview vtk --out results", "command line: --paraview"),
      cli_row("CLI-06", "modes frame.inp --modes ten --out results", "command line: --modes"),
      cli_row("CLI-07", "modes frame.inp --shift -1 --out results", "command line: --shift"),
      cli_row("CLI-08", "static frame.inp --stations 1 --out results", "command line: --stations"),
      cli_row("CLI-09", "static frame.inp --units feet --out results", "frame.inp: --units"),
      cli_row("CLI-10", "static frame.inp --out", "command line: --out"),
      cli_row("CLI-11", sweep + "-p soil.damping --values 100,200 --jobs 0", "command line: --jobs"),
      cli_row("CLI-12", sweep + "-p soil.viscosity --values 100,200", "study.yaml:40: soil.viscosity"),
      cli_row("CLI-13", sweep + "-p soil.damping --values 100,-200", ""),
      cli_row("CLI-14", sweep + "-p soil.damping --values 100,lots", "command line: --values"),
      cli_row("CLI-15", sweep + "-p cab.front_mount --values 0,2", "study.yaml:16: cab.front_mount"),
      cli_row("CLI-16", sweep + "-p soil.damping", "command line: --values"),
      cli_row("CLI-17", "run nothere.yaml --out results", "nothere.yaml", false),
      {"CLI-18", {{"study.yaml", kFrameStudy}}, "run study.yaml --out results", "", true},
      {"CLI-19", {{"study.yaml", kFrameStudy}}, sweep + "-p frame.damping.modal_ratio --values 0.01", "", true},
      {"CLI-20", {{"study.yaml", edit(kStudy2D, "  response: {duration: 0.12, output_interval: 0.001, method: rk4, rk4_step: 0.0005}\n", "")}},
       sweep + "-p soil.damping --values 100", "study.yaml: analysis.response", true},
      // ---- framedyn harmonic and framedyn random (apps/harmonic_command.cpp, apps/frequency_domain_input.cpp, fem/load_psd.cpp)
      cli_row("CLI-21", "harmonic frame.inp -f 200:5:100 -z 0.02 --no-figures --out results", "command line: --frequencies"),
      cli_row("CLI-22", "harmonic frame.inp -f 5-200 -z 0.02 --no-figures --out results", "command line: --frequencies"),
      cli_row("CLI-23", "harmonic frame.inp -f 5:200:1 -z 0.02 --no-figures --out results", "command line: --frequencies"),
      cli_row("CLI-24", "harmonic frame.inp -f 5:200:100 -z 1.5 --no-figures --out results", "command line: --damping-ratio"),
      cli_row("CLI-25", "harmonic frame.inp -f 5:200:100 -z 0.02 --modes 12 --no-figures --out results", "command line: --modes"),
      cli_row("CLI-26", "harmonic frame.inp -f 5:200:100 -z 0.02 --output-set TIP --no-figures --out results", "frame.inp: --output-set"),
      {"CLI-27", {{"frame.inp", edit(kMesh, "*CLOAD\n3, 3, 1000.\n", "")}}, "harmonic frame.inp -f 5:200:100 -z 0.02 --no-figures --out results",
       "frame.inp: *CLOAD", true},
      // ---- the step of a multi-step deck (apps/frequency_domain_input.cpp)
      cli_row("CLI-57", "harmonic frame.inp -f 5:200:100 -z 0.02 --step 2 --no-figures --out results", "command line: --step"),
      {"CLI-58", {{"frame.inp", edit(kMesh, "*END STEP\n", "*END STEP\n*STEP\n*STATIC\n*CLOAD\n2, 2, 500.\n*END STEP\n")}},
       "harmonic frame.inp -f 5:200:100 -z 0.02 --no-figures --out results", "command line: --step", true},
      {"CLI-59", {{"frame.inp", edit(kMesh, "*END STEP\n", "*END STEP\n*STEP\n*STATIC\n*CLOAD, OP=NEW\n*END STEP\n")}},
       "harmonic frame.inp -f 5:200:100 -z 0.02 --step 2 --no-figures --out results", "frame.inp: *CLOAD", true},
      cli_row("CLI-28", "random frame.inp --psd nothere.csv -z 0.02 --no-figures --out results", "nothere.csv", false),
      {"CLI-29", {{"frame.inp", kMesh}, {"psd.csv", "frequency [Hz],psd [1/Hz]\n5,0.01\n50;0.02\n500,0.01\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --no-figures --out results", "psd.csv:3", true},
      {"CLI-30", {{"frame.inp", kMesh}, {"psd.csv", "frequency,psd\n5,0.01\n500,0.01\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --no-figures --out results", "psd.csv:1: header", true},
      {"CLI-31", {{"frame.inp", kMesh}, {"psd.csv", "frequency [Hz],psd [1/Hz]\n5,0.01\n500,0.01\n50,0.02\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --no-figures --out results", "psd.csv:4: frequency [Hz]", true},
      {"CLI-32", {{"frame.inp", kMesh}, {"psd.csv", "frequency [Hz],psd [1/Hz]\n5,0.01\n500,0\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --no-figures --out results", "psd.csv:3: psd [1/Hz]", true},
      cli_row("CLI-36", "static frame.inp --inertia-relief --out results -q", "command line: --inertia-relief"),
      // ---- random response of a frame free to move rigidly (apps/random_command.cpp)
      {"CLI-39", {{"frame.inp", edit(kMesh, "1, ENCASTRE\n", "1, 1, 3\n")}, {"psd.csv", "frequency [Hz],psd [1/Hz]\n5,0.01\n500,0.01\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --no-figures --out results", "frame.inp: *BOUNDARY", true},
      {"CLI-40", {{"frame.inp", kMesh}, {"psd.csv", "frequency [Hz],psd [1/Hz]\n5,0.01\n500,0.01\n"}},
       "random frame.inp --psd psd.csv -z 0.02 --inertia-relief --no-figures --out results", "command line: --inertia-relief", true},
      // ---- progress and verbosity (apps/progress.cpp, apps/command_line.cpp)
      cli_row("CLI-38", "static frame.inp --out results -v -q", "command line: --quiet"),
      // ---- framedyn rainflow (fatigue/stress_series.cpp, apps/rainflow_command.cpp)
      cli_row("CLI-41", "rainflow nothere.csv --out results", "nothere.csv", false),
      {"CLI-42", {{"series.csv", kSeries}}, "rainflow series.csv --column strain --out results", "series.csv:1: --column", true},
      {"CLI-43", {{"series.csv", edit(kSeries, "sg1 [MPa]", "sg1 [bar]")}}, "rainflow series.csv --out results", "series.csv:1: sg1 [bar]", true},
      {"CLI-44", {{"series.csv", edit(kSeries, "0.2,-20", "0.2,-2O")}}, "rainflow series.csv --out results", "series.csv:4: sg1 [MPa]", true},
      {"CLI-45", {{"series.csv", edit(kSeries, "0.3,40", "0.1,40")}}, "rainflow series.csv --out results", "series.csv:5: time [s]", true},
      {"CLI-46", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT --out results", "command line: --sn", true},
      {"CLI-47", {{"series.csv", edit(kSeries, "0.1,50", "0.1")}}, "rainflow series.csv --out results", "series.csv:3", true},
      {"CLI-49", {{"frame.inp", kMesh}}, "transient frame.inp --step 1 --out results -q", "command line: --step", true},
      {"CLI-50", {{"frame.inp", kMesh}}, "transient frame.inp --out results -q", "command line: --step", true},
      cli_row("CLI-51", "static frame.inp --inp-dialect nastran --out results -q", "command line: --inp-dialect"),
      {"CLI-77", {{"frame.inp", edit(kMesh, "*STATIC\n", "*DYNAMIC\n0.01, 0.1\n")}}, "transient frame.inp --element-set RAILS --out results -q",
       "command line: --element-set", true},
      cli_row("CLI-78", "transient frame.inp --paraview vtu --out results -q", "command line: --paraview"),
      {"CLI-48", {{"series.csv", edit(edit(kSeries, "sg1 [MPa]", "sg1 [MPa],sg2 [MPa]"), "0,10", "0,10,12")}}, "rainflow series.csv --out results",
       "series.csv:1: --column", true},
      // ---- framedyn rainflow's options (apps/rainflow_command.cpp)
      {"CLI-60", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --mean-stress gerber --out results", "command line: --mean-stress", true},
      {"CLI-62", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --mean-stress goodman --out results", "command line: --mean-stress", true},
      {"CLI-63", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --mean-stress goodman --ultimate high --out results", "command line: --ultimate", true},
      {"CLI-64", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --ultimate 400 --out results", "command line: --ultimate", true},
      {"CLI-65", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --thickness 0 --out results", "command line: --thickness", true},
      {"CLI-66", {{"series.csv", kSeries}}, "rainflow series.csv --curve basquin:2e12:3 --thickness 40 --out results", "command line: --thickness", true},
      {"CLI-67", {{"series.csv", kSeries}}, "rainflow series.csv --curve points:1e5:200 --out results", "command line: --curve", true},
      {"STUDY-161", {{"series.csv", kSeries}, {"curve.yaml", "name: both\npoints: [[1e5, 200], [1e7, 50]]\nbasquin: {C: 2e12, m: 3}\n"}},
       "rainflow series.csv --curve curve.yaml --out results", "curve.yaml:1", true},
      {"STUDY-162", {{"series.csv", kSeries}, {"curve.yaml", "name: in bar\nunits: bar\nbasquin: {C: 2e12, m: 3}\n"}},
       "rainflow series.csv --curve curve.yaml --out results", "curve.yaml:2: units", true},
      {"STUDY-163", {{"series.csv", kSeries}, {"curve.yaml", "name: rising\npoints:\n  - [1e5, 200]\n  - [1e7, 250]\n"}},
       "rainflow series.csv --curve curve.yaml --out results", "curve.yaml:4: points[1]", true},
      {"STUDY-164", {{"series.csv", kSeries}, {"curve.yaml", "name: knees\nreference: {range: 90}\nslopes: [3, 5]\nknees: []\n"}},
       "rainflow series.csv --curve curve.yaml --out results", "curve.yaml:4: knees", true},
      {"CLI-68", {{"series.csv", kSeries}}, "rainflow series.csv --sn FAT90 --curve basquin:2e12:3 --out results", "command line: --curve", true},
      {"CLI-69", {{"series.csv", kSeries}}, "rainflow series.csv --thickness 40 --out results", "command line: --thickness", true},
  };
  for (Row row : cli) {
    if (row.id == "CLI-18") row.where = at("study.yaml", kFrameStudy, "model:", "model");
    if (row.id == "CLI-19") row.where = at("study.yaml", kFrameStudy, "model:", "model");
    if (row.id == "CLI-13") row.where = at("study.yaml", kStudy2D, "soil: {", "soil.damping");  // the study reader's own message
    r.push_back(row);
  }

  // ---- design files of framedyn batch (batch/design.cpp, apps/batch_command.cpp); a parameter key the study
  // does not have is refused by coupling/study_key_path with Study.set's message (PY-01 to PY-05; BATCH-03/04 retired)
  const std::string kDesign =
      "framedyn_batch: 1\nstudy: study.yaml\nsampling: {method: latin_hypercube, samples: 4, seed: 1}\nparameters:\n"
      "  - {key: soil.damping, distribution: uniform, low: 150, high: 450}\noutputs:\n  - rigid.response.peak_cutting_force\n";
  const auto design_row = [&](const std::string& id, const std::string& from, const std::string& to, const std::string& marker, const std::string& key) {
    const std::string text = edit(kDesign, from, to);
    return Row{id, {{"study.yaml", kStudy2D}, {"design.yaml", text}}, "batch design.yaml --out results -q", at("design.yaml", text, marker, key)};
  };
  const std::vector<Row> batch = {
      design_row("BATCH-01", "framedyn_batch: 1", "framedyn_batch: 2", "framedyn_batch", "framedyn_batch"),
      design_row("BATCH-02", "latin_hypercube", "sobol", "sampling:", "sampling.method"),
      design_row("BATCH-05", "high: 450", "high: 100", "high: 100", "parameters[0].high"),
      design_row("BATCH-06", "uniform", "beta", "beta", "parameters[0].distribution"),
      design_row("BATCH-07", "distribution: uniform, low: 150, high: 450", "values: [1, 2]", "values:", "parameters[0].values"),
      design_row("BATCH-08", "outputs:\n  - rigid.response.peak_cutting_force\n", "outputs: []\n", "outputs:", "outputs"),
      {"CLI-54", {{"study.yaml", kStudy2D}, {"design.yaml", kDesign}}, "batch design.yaml --out results --threads -1 -q", "command line: --threads"},
      {"CLI-55", {{"study.yaml", kStudy2D}, {"design.yaml", kDesign}}, "batch design.yaml --out results --checkpoint -2 -q", "command line: --checkpoint"},
      {"CLI-56", {{"study.yaml", kStudy2D}, {"design.yaml", kDesign}}, "batch design.yaml --out results --resume -q", "command line: --resume"},
      {"OUT-08",
       {{"study.yaml", kStudy2D},
        {"design.yaml", kDesign},
        {"results/.framedyn-manifest", "# framedyn results manifest 1\nruns.csv\nsummary.json\n"},
        {"results/summary.json", "{}\n"},
        {"results/runs.csv", "index,soil.stiffness [in-lbf-s],rigid.response.peak_cutting_force [lbf],status,message\n"}},
       "batch design.yaml --out results --resume -q",
       "results/runs.csv:1"},
  };
  r.insert(r.end(), batch.begin(), batch.end());

  // ---- the results folder (core/results_folder.cpp): framedyn replaces only a folder it wrote
  const std::string manifest = "# framedyn results manifest 1\nsummary.json\n";
  const std::vector<Row> out = {
      {"OUT-01", {{"study.yaml", kStudy2D}, {"precious.txt", "the user's notes\n"}}, "run study.yaml --out precious.txt -q", "command line: --out"},
      {"OUT-02", {{"study.yaml", kStudy2D}, {"results/notes.txt", "the user's notes\n"}}, "run study.yaml --out results -q", "command line: --out"},
      {"OUT-03",
       {{"study.yaml", kStudy2D}, {"results/.framedyn-manifest", manifest}, {"results/summary.json", "{}\n"}, {"results/notes.txt", "the user's notes\n"}},
       "run study.yaml --out results -q",
       "command line: --out"},
      {"OUT-04", {{"study.yaml", kStudy2D}}, "run study.yaml --out . -q", "command line: --out"},
      {"OUT-05", {{"inputs/study.yaml", kStudy2D}}, "run inputs/study.yaml --out inputs -q", "command line: --out"},
  };
  r.insert(r.end(), out.begin(), out.end());
  return r;
}

// ------------------------------------------------------------------ docs/errors.md

// Row ID -> the message cell's code span (with `\|` back to `|`), from the
// bad-input tables: every table row before the "## Numerical faults" section.
std::map<std::string, std::string> documented_messages() {
  std::map<std::string, std::string> out;
  std::istringstream in(read_file(kErrorsDoc));
  const std::regex row(R"(^\| *([A-Z]+-[0-9]+) *\|)");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("## Numerical faults", 0) == 0) break;
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    // The message is the last cell's code span.
    const std::size_t end = line.rfind('`'), begin = end == std::string::npos ? end : line.rfind('`', end - 1);
    std::string message = begin == std::string::npos ? std::string() : line.substr(begin + 1, end - begin - 1);
    for (std::size_t p = message.find("\\|"); p != std::string::npos; p = message.find("\\|", p)) message.replace(p, 2, "|");
    EXPECT_EQ(out.count(m[1]), 0u) << m[1] << " twice in docs/errors.md";
    out[m[1]] = message;
  }
  return out;
}

TEST(ErrorTable, DocumentedIdsAreExactlyTheTestedIds) {
  std::set<std::string> documented, tested;
  for (const auto& [id, message] : documented_messages()) documented.insert(id);
  for (const Row& row : rows()) EXPECT_TRUE(tested.insert(row.id).second) << row.id << " twice in the test table";
  EXPECT_FALSE(documented.empty()) << kErrorsDoc;
  for (const std::string& id : documented) EXPECT_EQ(tested.count(id), 1u) << id << " is in docs/errors.md but no test produces it";
  for (const std::string& id : tested) EXPECT_EQ(documented.count(id), 1u) << id << " is tested but not in docs/errors.md";
}

// The base inputs are good: each row's error comes from its edit alone.
TEST(ErrorTable, BaseInputsRun) {
  TempDir dir("framedyn_test_error_table");
  dir.write("frame.inp", kMesh);
  EXPECT_EQ(framedyn(dir, "static frame.inp --out mesh_results -q").status, 0);
  EXPECT_TRUE(fs::is_regular_file(dir / "mesh_results" / "summary.json"));
  dir.write("study2d.yaml", kStudy2D);
  EXPECT_EQ(framedyn(dir, "run study2d.yaml --out results_2d -q").status, 0);
  EXPECT_TRUE(fs::is_regular_file(dir / "results_2d" / "response.csv"));
  dir.write("study3d.yaml", kStudy3D);
  EXPECT_EQ(framedyn(dir, "run study3d.yaml --out results_3d -q").status, 0);
  EXPECT_TRUE(fs::is_regular_file(dir / "results_3d" / "rigid_modes.csv"));
  dir.write("frame_study.yaml", kFrameStudy);
  dir.write("frame.inp", shipped_frame());
  dir.write("loads.csv", kLoads);
  const RunResult f = framedyn(dir, "frame-response frame_study.yaml --out results_frame");
  EXPECT_EQ(f.status, 0) << f.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "results_frame" / "frame_rails_envelope.csv"));
  const RunResult s = framedyn(dir, "sweep study2d.yaml -p soil.damping --values 200,300 --no-figures --out results_sweep -q");
  EXPECT_EQ(s.status, 0) << s.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "results_sweep" / "sweep.csv"));
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(fs::relative(e.path(), dir).string());
  return names;
}

class ErrorTableRow : public ::testing::TestWithParam<Row> {};

TEST_P(ErrorTableRow, FailsWithTheDocumentedMessageAndWritesNothing) {
  const Row& row = GetParam();
  static const std::map<std::string, std::string> documented = documented_messages();
  TempDir dir("framedyn_test_error_table");
  for (const auto& [name, text] : row.files) dir.write(name, text);
  const std::set<std::string> before = entries(dir.path());
  const RunResult r = framedyn(dir, row.args);
  const std::string prefix = "framedyn: error: ";
  ASSERT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  ASSERT_FALSE(r.err.empty());
  const std::string message = r.err.substr(prefix.size(), r.err.size() - prefix.size() - 1);
  std::printf("| %s | `%s`\n", row.id.c_str(), message.c_str());  // the table's message column, as run
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_EQ(message.find('\n'), std::string::npos) << "more than one line:\n" << r.err;
  // Where: the file (or the command line), then the line and/or the key.
  EXPECT_EQ(message.rfind(row.where + ": ", 0), 0u) << "expected the message to begin with '" << row.where << ": ':\n" << message;
  EXPECT_TRUE(std::regex_search(row.where, std::regex(R"(^[^:]+(:[0-9]+)?(: .+)?$)"))) << row.where;
  if (row.expected_found) {
    EXPECT_NE(message.find(": expected "), std::string::npos) << message;
    EXPECT_NE(message.find(", found "), std::string::npos) << message;
  }
  // As docs/errors.md says, word for word.
  const auto doc = documented.find(row.id);
  ASSERT_NE(doc, documented.end()) << row.id << " is not in docs/errors.md";
  EXPECT_EQ(message, doc->second) << row.id;
  // Nothing written: no results folder, whole or partial.
  EXPECT_EQ(entries(dir.path()), before);
}

INSTANTIATE_TEST_SUITE_P(Docs, ErrorTableRow, ::testing::ValuesIn(rows()), [](const ::testing::TestParamInfo<Row>& info) {
  std::string name = info.param.id;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

}  // namespace

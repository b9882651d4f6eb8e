// Tests of the .inp reader (fem/inp_reader.h): every keyword it accepts, with
// what it produces, and every error path, with the file, line and keyword the
// message must name. Section constants are checked against hand formulas
// written out here, not against fem/beam_section.cpp.
#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "core/error.h"
#include "fem/beam_element.h"
#include "fem/frame_model.h"
#include "fem/inp_reader.h"
#include "fem/section_stress.h"

namespace {

namespace fs = std::filesystem;
using framedyn::core::InputError;
using framedyn::fem::BeamTheory;
using framedyn::fem::FrameModel;
using framedyn::fem::InpReadOptions;
using framedyn::fem::read_inp;
using framedyn::fem::read_inp_text;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254;                 // m
constexpr double kPoundForce = 4.4482216152605;  // N
const std::string kDeckName = "deck.inp";

// ------------------------------------------------------------------ helpers

// A fresh directory, removed at the end of the test.
// A fresh directory per test (tests/support/temp_dir.h).
class TempDir : public framedyn::testing::TempDir {
 public:
  TempDir() : framedyn::testing::TempDir("framedyn_test_inp_reader") {}
};

FrameModel read(const std::string& text, const InpReadOptions& options = {}) {
  return read_inp_text(text, kDeckName, fs::temp_directory_path(), options);
}

InpReadOptions with_units(const std::string& name) {
  InpReadOptions o;
  o.units = name;
  return o;
}

std::string trimmed(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

// 1-based number of the one line of `text` that reads `line` (ignoring
// surrounding blanks); "@N" means line N. Fails the test unless exactly one
// line matches.
int line_of(const std::string& text, const std::string& line) {
  if (line.empty()) return 0;
  if (line[0] == '@') return std::stoi(line.substr(1));
  std::istringstream in(text);
  std::string l;
  int number = 0, found = 0, matches = 0;
  while (std::getline(in, l)) {
    ++number;
    if (trimmed(l) == line) {
      found = number;
      ++matches;
    }
  }
  if (matches != 1) ADD_FAILURE() << "test deck has " << matches << " lines reading '" << line << "'";
  return found;
}

// `run` must throw core::InputError located at file:line (line 0: no line)
// under `key`, whose message starts with that location and contains every
// fragment.
::testing::AssertionResult throws_input_error(const std::function<void()>& run, const std::string& file, int line,
                                               const std::string& key, const std::vector<std::string>& fragments) {
  try {
    run();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    std::string prefix = file;
    if (line > 0) prefix += ":" + std::to_string(line);
    if (!key.empty()) prefix += ": " + key;
    prefix += ": ";
    if (msg.rfind(prefix, 0) != 0)
      return ::testing::AssertionFailure() << "message does not start with '" << prefix << "': " << msg;
    if (e.where().file != file || e.where().line != line || e.where().key != key)
      return ::testing::AssertionFailure() << "where() is (" << e.where().file << ", " << e.where().line << ", " << e.where().key
                                           << "), expected (" << file << ", " << line << ", " << key << ")";
    for (const std::string& f : fragments)
      if (msg.find(f) == std::string::npos) return ::testing::AssertionFailure() << "message lacks '" << f << "': " << msg;
    return ::testing::AssertionSuccess() << msg;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception (" << typeid(e).name() << "): " << e.what();
  }
  return ::testing::AssertionFailure() << "no exception";
}

bool near_rel(double actual, double expected, double tol) {
  return std::abs(actual - expected) <= tol * std::abs(expected);
}
#define EXPECT_REL(actual, expected, tol) \
  EXPECT_PRED3(near_rel, (actual), (expected), (tol))

// Building blocks of small decks (SI).
const std::string kUnits = "** units: m-N-s\n";
const std::string kNodes =
    "*NODE, NSET=ALL\n"
    "1, 0, 0, 0\n"
    "2, 1, 0, 0\n"
    "3, 2, 0, 0\n";
const std::string kBeams =
    "*ELEMENT, TYPE=B31, ELSET=FRAME\n"
    "1, 1, 2\n"
    "2, 2, 3\n";
const std::string kSection =
    "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n"
    "0.1, 0.2\n";
const std::string kSteel =
    "*MATERIAL, NAME=STEEL\n"
    "*ELASTIC\n"
    "2.1e11, 0.3\n"
    "*DENSITY\n"
    "7850\n";
const std::string kMesh = kUnits + kNodes + kBeams;        // no section
const std::string kModel = kMesh + kSection + kSteel;    // a complete model

// One beam from (0,0,0) to `end` with the given section block (keyword and data lines).
std::string one_beam(const std::string& section_block, const std::string& end = "1, 0, 0") {
  return kUnits + "*NODE\n1, 0, 0, 0\n2, " + end + "\n*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n" + section_block + kSteel;
}

const framedyn::fem::SectionProperties& section_of(const FrameModel& m) { return m.sections.at(0).properties; }

// ------------------------------------------------------------------ keywords

TEST(InpReader, ReadsACompleteSmallModel) {
  const FrameModel m = read(kModel);
  ASSERT_EQ(m.nodes.size(), 3u);
  ASSERT_EQ(m.beams.size(), 2u);
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.units.name(), "m-N-s");
  EXPECT_FALSE(m.requested_modes.has_value());
  EXPECT_TRUE(m.point_masses.empty());
  EXPECT_TRUE(m.springs.empty());
  EXPECT_TRUE(m.constraints.empty());
  EXPECT_TRUE(m.loads.empty());
  EXPECT_EQ(m.sections[0].element_set, "FRAME");
  EXPECT_EQ(m.beams[0].section, 0);
  EXPECT_EQ(m.beams[1].section, 0);
}

// strtod reports an underflow (1e-310, a subnormal) as ERANGE, as it does an
// overflow; only the overflow is not a number. Same class as the load-history
// round trip fuzz_load_history_reader found.
TEST(InpReader, ReadsANumberThatUnderflowsToASubnormal) {
  const FrameModel m = read(kUnits + "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 1e-310, 0\n3, 2, 0, 0\n" + kBeams + kSection + kSteel);
  ASSERT_EQ(m.nodes.size(), 3u);
  EXPECT_GT(m.nodes[1].position.y(), 0.0);
  EXPECT_LT(m.nodes[1].position.y(), 2.2250738585072014e-308);
}

TEST(InpReader, HeadingTextIsIgnored) {
  const FrameModel m = read("*HEADING\nA frame, with commas, 1, 2, 3\n4, 5, 6\n" + kModel);
  EXPECT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.beams.size(), 2u);
}

TEST(InpReader, NodesWithNsetAndMissingCoordinates) {
  const FrameModel m = read(kUnits +
                            "*NODE, NSET=N\n"
                            "10, 1.5\n"
                            "20, 1, 2\n"
                            "30, 1, 2, 3\n"
                            "40, , 5\n"
                            "50, 1.0D1, -2.5e-1, +3\n"
                            "*NODE\n"
                            "5, 7, 8, 9\n");
  ASSERT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.nodes[0].id, 10);
  EXPECT_EQ(m.nodes[0].position, Eigen::Vector3d(1.5, 0, 0));
  EXPECT_EQ(m.nodes[1].position, Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(m.nodes[2].position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(m.nodes[3].position, Eigen::Vector3d(0, 5, 0));
  EXPECT_EQ(m.nodes[4].position, Eigen::Vector3d(10, -0.25, 3));  // Fortran D exponent
  EXPECT_EQ(m.nodes[5].id, 5);
  EXPECT_EQ(m.node_index(30), 2);
  EXPECT_EQ(m.node_index(5), 5);
  EXPECT_EQ(m.node_index(6), -1);
  ASSERT_EQ(m.node_sets.count("N"), 1u);
  EXPECT_EQ(m.node_sets.at("N"), (std::vector<int>{0, 1, 2, 3, 4}));  // indices, not ids
}

TEST(InpReader, BeamElementsB31AndB33WithElset) {
  const FrameModel m = read(kUnits + kNodes +
                            "*ELEMENT, TYPE=B31, ELSET=TIM\n"
                            "1, 1, 2\n"
                            "*ELEMENT, TYPE=B33, ELSET=EB\n"
                            "2, 3, 2\n"
                            "*ELSET, ELSET=ALLB\nTIM, EB\n"
                            "*BEAM SECTION, ELSET=ALLB, MATERIAL=STEEL, SECTION=CIRC\n0.05\n" +
                            kSteel);
  ASSERT_EQ(m.beams.size(), 2u);
  EXPECT_EQ(m.beams[0].id, 1);
  EXPECT_EQ(m.beams[0].theory, BeamTheory::timoshenko);
  EXPECT_EQ(m.beams[0].node_a, 0);
  EXPECT_EQ(m.beams[0].node_b, 1);
  EXPECT_EQ(m.beams[1].id, 2);
  EXPECT_EQ(m.beams[1].theory, BeamTheory::euler_bernoulli);
  EXPECT_EQ(m.beams[1].node_a, 2);
  EXPECT_EQ(m.beams[1].node_b, 1);
  EXPECT_EQ(m.beam_index(2), 1);
  EXPECT_EQ(m.element_sets.at("TIM"), std::vector<int>{1});
  EXPECT_EQ(m.element_sets.at("EB"), std::vector<int>{2});
  EXPECT_EQ(m.element_sets.at("ALLB"), (std::vector<int>{1, 2}));
}

TEST(InpReader, ElementDataLinesContinueAfterATrailingComma) {
  const FrameModel m = read(kUnits + kNodes +
                            "*ELEMENT, TYPE=B31, ELSET=FRAME\n"
                            "1,\n"
                            "1,\n"
                            "2\n"
                            "2, 2,\n"
                            "   3\n" +
                            kSection + kSteel);
  ASSERT_EQ(m.beams.size(), 2u);
  EXPECT_EQ(m.beams[0].id, 1);
  EXPECT_EQ(m.beams[0].node_a, 0);
  EXPECT_EQ(m.beams[0].node_b, 1);
  EXPECT_EQ(m.beams[1].id, 2);
  EXPECT_EQ(m.beams[1].node_a, 1);
  EXPECT_EQ(m.beams[1].node_b, 2);
}

TEST(InpReader, MassAndRotaryInertiaElements) {
  const FrameModel m = read(kModel +
                            "*ELEMENT, TYPE=MASS, ELSET=PM\n"
                            "10, 3\n"
                            "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n"
                            "11, 3\n"
                            "12, 1\n"
                            "*MASS, ELSET=PM\n"
                            "25.5\n"
                            "*ROTARY INERTIA, ELSET=RI\n"
                            "4, 5, 6, 0.5, 0.25, -0.125\n");
  ASSERT_EQ(m.point_masses.size(), 2u);
  const auto& pm = m.point_masses[0];
  EXPECT_EQ(pm.element_id, 10);
  EXPECT_EQ(pm.node, 2);
  EXPECT_DOUBLE_EQ(pm.mass, 25.5);
  Eigen::Matrix3d j;
  j << 4, 0.5, 0.25, 0.5, 5, -0.125, 0.25, -0.125, 6;
  EXPECT_EQ(pm.rotary_inertia, j);  // ROTARYI at the same node adds to the point mass
  const auto& ri = m.point_masses[1];
  EXPECT_EQ(ri.element_id, 12);
  EXPECT_EQ(ri.node, 0);
  EXPECT_EQ(ri.mass, 0.0);
  EXPECT_EQ(ri.rotary_inertia, j);
  EXPECT_EQ(m.element_sets.at("PM"), std::vector<int>{10});
  EXPECT_EQ(m.element_sets.at("RI"), (std::vector<int>{11, 12}));
}

TEST(InpReader, RotaryInertiaWithThreeValuesIsDiagonal) {
  const FrameModel m = read(kModel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 2\n*ROTARY INERTIA, ELSET=RI\n1, 2, 3\n");
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_EQ(m.point_masses[0].rotary_inertia, Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
}

TEST(InpReader, Spring1ToGroundAndSpring2BetweenNodes) {
  const FrameModel m = read(kModel +
                            "*ELEMENT, TYPE=SPRING1, ELSET=S1\n"
                            "20, 3\n"
                            "*ELEMENT, TYPE=SPRING2, ELSET=S2\n"
                            "21, 1, 3\n"
                            "*ELEMENT, TYPE=SPRING2, ELSET=S3\n"
                            "22, 2, 3\n"
                            "*SPRING, ELSET=S1\n"
                            "2\n"
                            "1.5e6\n"
                            "*SPRING, ELSET=S2\n"
                            "1, 3\n"
                            "2.5e5\n"
                            "*SPRING, ELSET=S3\n"
                            "6, 4\n"
                            "3e4\n");
  ASSERT_EQ(m.springs.size(), 3u);
  const auto& s1 = m.springs[0];
  EXPECT_EQ(s1.element_id, 20);
  EXPECT_EQ(s1.node_a, 2);
  EXPECT_EQ(s1.dof_a, 1);
  EXPECT_LT(s1.node_b, 0);
  EXPECT_DOUBLE_EQ(s1.stiffness, 1.5e6);
  const auto& s2 = m.springs[1];
  EXPECT_EQ(s2.element_id, 21);
  EXPECT_EQ(s2.node_a, 0);
  EXPECT_EQ(s2.dof_a, 0);
  EXPECT_EQ(s2.node_b, 2);
  EXPECT_EQ(s2.dof_b, 2);
  EXPECT_DOUBLE_EQ(s2.stiffness, 2.5e5);
  const auto& s3 = m.springs[2];
  EXPECT_EQ(s3.dof_a, 5);
  EXPECT_EQ(s3.dof_b, 3);
  EXPECT_DOUBLE_EQ(s3.stiffness, 3e4);
}

TEST(InpReader, PropertyOnASetThatListsAnElementTwice) {
  // Repeating a set adds to it; listing an element twice is not a second *MASS.
  const FrameModel m = read(kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*ELSET, ELSET=PM\n10\n*MASS, ELSET=PM\n2.0\n");
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_DOUBLE_EQ(m.point_masses[0].mass, 2.0);
  EXPECT_EQ(m.element_sets.at("PM"), std::vector<int>{10});
}

TEST(InpReader, NsetAndElsetPlain) {
  const FrameModel m = read(kModel +
                            "*NSET, NSET=ENDS\n"
                            "3, 1\n"
                            "*NSET, NSET=ENDS\n"  // repeating a set adds to it
                            "2, 1\n"
                            "*ELSET, ELSET=FIRST\n"
                            "1,\n");
  EXPECT_EQ(m.node_sets.at("ENDS"), (std::vector<int>{0, 1, 2}));  // sorted indices, each once
  EXPECT_EQ(m.node_sets.at("ALL"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(m.element_sets.at("FIRST"), std::vector<int>{1});
  EXPECT_EQ(m.element_sets.at("FRAME"), (std::vector<int>{1, 2}));
}

TEST(InpReader, SetsWithSetNamesAsMembers) {
  const FrameModel m = read(kUnits +
                            "*NODE\n1, 0\n2, 1\n3, 2\n4, 3\n5, 4\n"
                            "*NSET, NSET=A\n1, 2\n"
                            "*NSET, NSET=B\n5\n"
                            "*NSET, NSET=AB\nA, b, 4\n"
                            "*ELEMENT, TYPE=B31, ELSET=E1\n1, 1, 2\n"
                            "*ELEMENT, TYPE=B31, ELSET=E2\n2, 2, 3\n3, 3, 4\n"
                            "*ELSET, ELSET=E12\ne1, E2\n"
                            "*BEAM SECTION, ELSET=E12, MATERIAL=STEEL, SECTION=CIRC\n0.05\n" +
                            kSteel);
  EXPECT_EQ(m.node_sets.at("AB"), (std::vector<int>{0, 1, 3, 4}));
  EXPECT_EQ(m.element_sets.at("E12"), (std::vector<int>{1, 2, 3}));
  for (const auto& b : m.beams) EXPECT_EQ(b.section, 0);
}

TEST(InpReader, SetsWithGenerate) {
  std::string nodes = "*NODE\n";
  for (int i = 1; i <= 10; ++i) nodes += std::to_string(i) + ", " + std::to_string(i) + "\n";
  const FrameModel m = read(kUnits + nodes +
                            "*NSET, NSET=ODD, GENERATE\n"
                            "1, 9, 2\n"
                            "*NSET, NSET=RANGE, generate\n"
                            "4, 6\n"
                            "10, 10, 5\n"
                            "*ELEMENT, TYPE=B31\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
                            "*ELSET, ELSET=E, GENERATE\n"
                            "1, 4, 3\n"
                            "*ELSET, ELSET=ALLE, GENERATE\n1, 4\n"
                            "*BEAM SECTION, ELSET=ALLE, MATERIAL=STEEL, SECTION=CIRC\n0.05\n" +
                            kSteel);
  EXPECT_EQ(m.node_sets.at("ODD"), (std::vector<int>{0, 2, 4, 6, 8}));
  EXPECT_EQ(m.node_sets.at("RANGE"), (std::vector<int>{3, 4, 5, 9}));
  EXPECT_EQ(m.element_sets.at("E"), (std::vector<int>{1, 4}));
  EXPECT_EQ(m.element_sets.at("ALLE"), (std::vector<int>{1, 2, 3, 4}));
}

// ------------------------------------------------------------------ sections

TEST(InpReader, RectSectionAgainstHandFormulasAndRoark) {
  // a along local 1, b along local 2; J against Roark's approximation
  // J = A B^3 (1/3 - 0.21 (B/A)(1 - B^4 / (12 A^4))), A >= B, within 0.5 %.
  const std::vector<std::pair<double, double>> cases = {{0.1, 0.2}, {0.2, 0.1}, {0.1, 0.1}, {0.3, 0.05}, {0.02, 0.2}};
  for (const auto& [a, b] : cases) {
    SCOPED_TRACE("RECT " + std::to_string(a) + " x " + std::to_string(b));
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=RECT\n" + std::to_string(a) + ", " +
                                       std::to_string(b) + "\n"));
    const auto& s = section_of(m);
    EXPECT_EQ(s.shape, "RECT");
    EXPECT_REL(s.area, a * b, 1e-14);
    EXPECT_REL(s.i11, a * b * b * b / 12, 1e-14);
    EXPECT_REL(s.i22, b * a * a * a / 12, 1e-14);
    const double big = std::max(a, b), small = std::min(a, b);
    const double roark = big * std::pow(small, 3) * (1.0 / 3 - 0.21 * (small / big) * (1 - std::pow(small, 4) / (12 * std::pow(big, 4))));
    EXPECT_REL(s.torsion_constant, roark, 0.005);
    // Cowper's shear factor for a rectangle, nu = 0.3.
    const double k = 10 * 1.3 / (12 + 11 * 0.3);
    EXPECT_REL(s.shear_area_1, k * a * b, 1e-14);
    EXPECT_REL(s.shear_area_2, k * a * b, 1e-14);
  }
}

TEST(InpReader, BoxSectionAgainstHandFormulasAndBredt) {
  {
    SCOPED_TRACE("equal walls");
    const double a = 0.1, b = 0.2, t = 0.01;
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=BOX\n0.1, 0.2, 0.01, 0.01, 0.01, 0.01\n"));
    const auto& s = section_of(m);
    EXPECT_EQ(s.shape, "BOX");
    EXPECT_REL(s.area, a * b - (a - 2 * t) * (b - 2 * t), 1e-12);
    EXPECT_REL(s.i11, (a * b * b * b - (a - 2 * t) * std::pow(b - 2 * t, 3)) / 12, 1e-12);
    EXPECT_REL(s.i22, (b * a * a * a - (b - 2 * t) * std::pow(a - 2 * t, 3)) / 12, 1e-12);
    // Bredt on the midlines: J = 4 Am^2 t / perimeter.
    const double am = (a - t) * (b - t), perimeter = 2 * ((a - t) + (b - t));
    EXPECT_REL(s.torsion_constant, 4 * am * am * t / perimeter, 1e-12);
  }
  {
    SCOPED_TRACE("unequal walls");
    // a = 0.12 along 1, b = 0.2 along 2; t1 at +x1, t2 at +x2, t3 at -x1, t4 at -x2.
    const double a = 0.12, b = 0.2, t1 = 0.01, t2 = 0.02, t3 = 0.005, t4 = 0.015;
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=BOX\n0.12, 0.2, 0.01, 0.02, 0.005, 0.015\n"));
    const auto& s = section_of(m);
    // Outline minus hole; hole from x1 = -a/2 + t3 to a/2 - t1, x2 = -b/2 + t4 to b/2 - t2.
    const double h1 = a - t1 - t3, h2 = b - t2 - t4;
    const double hc1 = (-a / 2 + t3 + a / 2 - t1) / 2, hc2 = (-b / 2 + t4 + b / 2 - t2) / 2;
    const double area = a * b - h1 * h2;
    const double c1 = -h1 * h2 * hc1 / area, c2 = -h1 * h2 * hc2 / area;
    const double i11 = a * b * b * b / 12 + a * b * c2 * c2 - (h1 * h2 * h2 * h2 / 12 + h1 * h2 * (hc2 - c2) * (hc2 - c2));
    const double i22 = b * a * a * a / 12 + a * b * c1 * c1 - (h2 * h1 * h1 * h1 / 12 + h1 * h2 * (hc1 - c1) * (hc1 - c1));
    EXPECT_REL(s.area, area, 1e-12);
    EXPECT_REL(s.i11, i11, 1e-12);
    EXPECT_REL(s.i22, i22, 1e-12);
    // Bredt: midline widths; walls at +-x1 have length m2, walls at +-x2 length m1.
    const double m1 = a - (t1 + t3) / 2, m2 = b - (t2 + t4) / 2;
    EXPECT_REL(s.torsion_constant, 4 * (m1 * m2) * (m1 * m2) / (m2 / t1 + m1 / t2 + m2 / t3 + m1 / t4), 1e-12);
  }
}

TEST(InpReader, PipeAndCircSectionsExact) {
  {
    const double r = 0.05, t = 0.004, ri = r - t;
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=PIPE\n0.05, 0.004\n"));
    const auto& s = section_of(m);
    EXPECT_EQ(s.shape, "PIPE");
    EXPECT_REL(s.area, kPi * (r * r - ri * ri), 1e-13);
    EXPECT_REL(s.i11, kPi * (std::pow(r, 4) - std::pow(ri, 4)) / 4, 1e-13);
    EXPECT_REL(s.i22, kPi * (std::pow(r, 4) - std::pow(ri, 4)) / 4, 1e-13);
    EXPECT_REL(s.torsion_constant, kPi * (std::pow(r, 4) - std::pow(ri, 4)) / 2, 1e-13);
  }
  {
    const double r = 0.03;
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CIRC\n0.03\n"));
    const auto& s = section_of(m);
    EXPECT_EQ(s.shape, "CIRC");
    EXPECT_REL(s.area, kPi * r * r, 1e-13);
    EXPECT_REL(s.i11, kPi * std::pow(r, 4) / 4, 1e-13);
    EXPECT_REL(s.i22, kPi * std::pow(r, 4) / 4, 1e-13);
    EXPECT_REL(s.torsion_constant, kPi * std::pow(r, 4) / 2, 1e-13);
    EXPECT_REL(s.shear_area_1, 6 * 1.3 / (7 + 6 * 0.3) * kPi * r * r, 1e-13);
  }
}

TEST(InpReader, TwoValuesOnACircLineAreAnEllipseWithItsClosedFormConstants) {
  // CalculiX's beammix: CIRC a, b. Abaqus reading: semi-axes a (along 1), b
  // (along 2): A = pi a b, I11 = pi a b^3 / 4, I22 = pi a^3 b / 4,
  // J = pi a^3 b^3 / (a^2 + b^2) (docs/theory/fem.md, Eqs. 23.1-23.3).
  const double a = 0.03, b = 0.05;
  const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CIRC\n0.03, 0.05\n"));
  const std::vector<framedyn::core::Warning>& warnings = m.reader_warnings;
  const auto& s = section_of(m);
  EXPECT_EQ(s.shape, "CIRC");
  EXPECT_REL(s.area, kPi * a * b, 1e-13);
  EXPECT_REL(s.i11, kPi * a * b * b * b / 4, 1e-13);
  EXPECT_REL(s.i22, kPi * a * a * a * b / 4, 1e-13);
  EXPECT_REL(s.torsion_constant, kPi * std::pow(a * b, 3) / (a * a + b * b), 1e-13);
  // No dialect given: one warning naming the set and both readings.
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].code, "circ_radius_or_diameter");
  EXPECT_NE(warnings[0].message.find("ELSET B"), std::string::npos);
  EXPECT_NE(warnings[0].message.find("semi-axes 0.03, 0.05"), std::string::npos);
  // Prandtl's shear of the ellipse at the ends of the axes: 2 T / (pi a b^2) at
  // (0, b) and 2 T / (pi a^2 b) at (a, 0) (Eq. 23.4); the bending stress
  // M c / I at the same points.
  const std::vector<framedyn::fem::SectionPoint> points = framedyn::fem::section_points(s);
  ASSERT_EQ(points.size(), 8u);
  framedyn::fem::SectionForces torque;
  torque.t = 100.0;
  EXPECT_REL(framedyn::fem::point_stress(s, points[2], torque).shear, 2 * 100.0 / (kPi * a * b * b), 1e-12);  // angle 90: (0, b)
  EXPECT_REL(framedyn::fem::point_stress(s, points[0], torque).shear, 2 * 100.0 / (kPi * a * a * b), 1e-12);  // angle 0: (a, 0)
  EXPECT_NEAR(points[2].position.y(), b, 1e-15);
  EXPECT_NEAR(points[0].position.x(), a, 1e-15);
  // Transverse shear along 2 at the neutral axis (x2 = 0): 4 V / (3 A), as for a circle.
  framedyn::fem::SectionForces shear;
  shear.vz = 1000.0;
  EXPECT_REL(framedyn::fem::point_stress(s, points[0], shear).shear, 4 * 1000.0 / (3 * kPi * a * b), 1e-12);
}

TEST(InpReader, TheCalculixDialectReadsCircValuesAsDiametersAndWarnsNothing) {
  // CalculiX 2.20 reads CIRC's value as the diameter (docs/theory/fem.md section 23).
  InpReadOptions o;
  o.dialect = framedyn::fem::InpDialect::calculix;
  const double r = 0.015;
  const FrameModel circle = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CIRC\n0.03\n"), o);
  EXPECT_REL(section_of(circle).i11, kPi * std::pow(r, 4) / 4, 1e-13);
  const FrameModel ellipse = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CIRC\n0.03, 0.05\n"), o);
  EXPECT_REL(section_of(ellipse).area, kPi * 0.015 * 0.025, 1e-13);
  EXPECT_TRUE(circle.reader_warnings.empty());
  EXPECT_TRUE(ellipse.reader_warnings.empty());
  o.dialect = framedyn::fem::InpDialect::abaqus;  // said explicitly: the radius, no warning
  const FrameModel abaqus = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CIRC\n0.03\n"), o);
  EXPECT_REL(section_of(abaqus).i11, kPi * std::pow(0.03, 4) / 4, 1e-13);
  EXPECT_TRUE(abaqus.reader_warnings.empty());
}

TEST(InpReader, ISectionAgainstHandFormulas) {
  // Abaqus I: l, h, b1, b2, t1, t2, t3. Unequal flanges; l = 0 is valid (l is not used).
  const double h = 0.3, b1 = 0.2, b2 = 0.15, t1 = 0.02, t2 = 0.015, t3 = 0.01;
  for (const std::string l : {"0", "0.15", "-0.05"}) {
    SCOPED_TRACE("l = " + l);
    const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=I\n" + l + ", 0.3, 0.2, 0.15, 0.02, 0.015, 0.01\n"));
    const auto& s = section_of(m);
    EXPECT_EQ(s.shape, "I");
    const double hw = h - t1 - t2;
    const double area = b1 * t1 + b2 * t2 + hw * t3;
    EXPECT_REL(s.area, area, 1e-13);
    // Centroid from the bottom face, then parallel-axis sums.
    const double yc = (b1 * t1 * t1 / 2 + hw * t3 * (t1 + hw / 2) + b2 * t2 * (h - t2 / 2)) / area;
    const double i11 = b1 * std::pow(t1, 3) / 12 + b1 * t1 * std::pow(t1 / 2 - yc, 2) + t3 * std::pow(hw, 3) / 12 +
                       hw * t3 * std::pow(t1 + hw / 2 - yc, 2) + b2 * std::pow(t2, 3) / 12 + b2 * t2 * std::pow(h - t2 / 2 - yc, 2);
    EXPECT_REL(s.i11, i11, 1e-12);
    EXPECT_REL(s.i22, (t1 * std::pow(b1, 3) + t2 * std::pow(b2, 3) + hw * std::pow(t3, 3)) / 12, 1e-12);
    EXPECT_REL(s.torsion_constant, (b1 * std::pow(t1, 3) + b2 * std::pow(t2, 3) + hw * std::pow(t3, 3)) / 3, 1e-12);
  }
}

TEST(InpReader, ChannelSectionAgainstHandFormulas) {
  // CHANNEL: h (along 2), b (flange width along 1), tf, tw.
  const double h = 0.2, b = 0.08, tf = 0.01, tw = 0.006;
  const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=CHANNEL\n0.2, 0.08, 0.01, 0.006\n"));
  const auto& s = section_of(m);
  EXPECT_EQ(s.shape, "CHANNEL");
  const double hw = h - 2 * tf;
  const double area = 2 * b * tf + hw * tw;
  EXPECT_REL(s.area, area, 1e-13);
  EXPECT_REL(s.i11, (b * std::pow(h, 3) - (b - tw) * std::pow(hw, 3)) / 12, 1e-12);
  const double xc = (2 * b * tf * b / 2 + hw * tw * tw / 2) / area;  // from the web's outer face
  const double i22 = 2 * (tf * std::pow(b, 3) / 12 + b * tf * std::pow(b / 2 - xc, 2)) + hw * std::pow(tw, 3) / 12 +
                     hw * tw * std::pow(tw / 2 - xc, 2);
  EXPECT_REL(s.i22, i22, 1e-12);
  EXPECT_REL(s.torsion_constant, (2 * b * std::pow(tf, 3) + hw * std::pow(tw, 3)) / 3, 1e-12);
}

TEST(InpReader, OrientationLineGivesTheLocalAxes) {
  // Element along (1, 1, 0); n1 given as (1, 0, 1), not perpendicular to the axis.
  const FrameModel m = read(one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.2\n1, 0, 1\n", "1, 1, 0"));
  EXPECT_EQ(m.sections[0].n1_direction, Eigen::Vector3d(1, 0, 1));
  const auto g = framedyn::fem::beam_geometry(m, m.beams[0]);
  const Eigen::Vector3d t = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d n1_raw(1, 0, 1);
  const Eigen::Vector3d n1 = (n1_raw - n1_raw.dot(t) * t).normalized();
  const Eigen::Vector3d n2 = t.cross(n1);
  EXPECT_NEAR((g.axes.row(0).transpose() - t).norm(), 0.0, 1e-14);
  EXPECT_NEAR((g.axes.row(1).transpose() - n1).norm(), 0.0, 1e-14);
  EXPECT_NEAR((g.axes.row(2).transpose() - n2).norm(), 0.0, 1e-14);
  EXPECT_NEAR((g.axes * g.axes.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-14);
  EXPECT_NEAR(g.axes.determinant(), 1.0, 1e-14);
  EXPECT_NEAR(g.data.length, std::sqrt(2.0), 1e-15);
}

TEST(InpReader, DefaultOrientationIsMinusZ) {
  const FrameModel m = read(kModel);
  EXPECT_EQ(m.sections[0].n1_direction, Eigen::Vector3d(0, 0, -1));
  const auto g = framedyn::fem::beam_geometry(m, m.beams[0]);
  EXPECT_NEAR((g.axes.row(0).transpose() - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.axes.row(1).transpose() - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.axes.row(2).transpose() - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-15);  // t x n1
}

TEST(InpReader, GeneralSectionWithDensityAndPrincipalAxes) {
  const double A = 0.01, I11 = 4e-6, I12 = 1e-6, I22 = 2e-6, J = 3e-6;
  const FrameModel m = read(kUnits + "*NODE\n1, 0, 0, 0\n2, 2, 0, 0\n*ELEMENT, TYPE=B33, ELSET=G\n1, 1, 2\n"
                            "*BEAM GENERAL SECTION, ELSET=G, SECTION=GENERAL, DENSITY=7800\n"
                            "0.01, 4e-6, 1e-6, 2e-6, 3e-6\n"
                            "0, 1, 0\n"
                            "2.0e11, 8.0e10\n");
  ASSERT_EQ(m.sections.size(), 1u);
  const auto& sa = m.sections[0];
  EXPECT_EQ(sa.properties.shape, "GENERAL");
  EXPECT_DOUBLE_EQ(sa.properties.area, A);
  EXPECT_DOUBLE_EQ(sa.properties.i11, I11);
  EXPECT_DOUBLE_EQ(sa.properties.i12, I12);
  EXPECT_DOUBLE_EQ(sa.properties.i22, I22);
  EXPECT_DOUBLE_EQ(sa.properties.torsion_constant, J);
  EXPECT_DOUBLE_EQ(sa.material.youngs_modulus, 2.0e11);
  EXPECT_DOUBLE_EQ(sa.material.shear_modulus, 8.0e10);
  EXPECT_DOUBLE_EQ(sa.material.density, 7800);
  EXPECT_EQ(sa.n1_direction, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(m.beams[0].theory, BeamTheory::euler_bernoulli);

  // Principal axes: the second-moment tensor of the section, built in the
  // given axes (n1, n2) with I12 = integral x1 x2 dA, has no product in the
  // axes beam_geometry returns, and its diagonal there is the new I22, I11.
  const auto g = framedyn::fem::beam_geometry(m, m.beams[0]);
  const Eigen::Vector3d t(1, 0, 0), n1(0, 1, 0), n2 = t.cross(n1);
  const Eigen::Matrix3d C = I22 * n1 * n1.transpose() + I12 * (n1 * n2.transpose() + n2 * n1.transpose()) + I11 * n2 * n2.transpose();
  const Eigen::Vector3d p1 = g.axes.row(1).transpose(), p2 = g.axes.row(2).transpose();
  EXPECT_NEAR((g.axes.row(0).transpose() - t).norm(), 0.0, 1e-15);
  EXPECT_NEAR((p2 - t.cross(p1)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(p1.dot(C * p2), 0.0, 1e-20);
  EXPECT_EQ(g.data.section.i12, 0.0);
  EXPECT_REL(g.data.section.i11, p2.dot(C * p2), 1e-12);
  EXPECT_REL(g.data.section.i22, p1.dot(C * p1), 1e-12);
  const double mean = (I11 + I22) / 2, radius = std::hypot((I11 - I22) / 2, I12);
  EXPECT_REL(std::max(g.data.section.i11, g.data.section.i22), mean + radius, 1e-12);
  EXPECT_REL(std::min(g.data.section.i11, g.data.section.i22), mean - radius, 1e-12);
  EXPECT_DOUBLE_EQ(g.data.density, 7800);
}

TEST(InpReader, GeneralSectionWithoutDensityAndWithoutProductKeepsAxes) {
  const FrameModel m = read(kMesh +
                            "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n"
                            "0.01, 4e-6, 0, 2e-6, 3e-6\n"
                            "0, 0, -1\n"
                            "2.0e11, 8.0e10, 1.2e-5\n");
  EXPECT_EQ(m.sections[0].material.density, 0.0);
  const auto g = framedyn::fem::beam_geometry(m, m.beams[0]);
  EXPECT_DOUBLE_EQ(g.data.section.i11, 4e-6);
  EXPECT_DOUBLE_EQ(g.data.section.i22, 2e-6);
  EXPECT_NEAR((g.axes.row(1).transpose() - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-15);
}

TEST(InpReader, MaterialElasticAndDensity) {
  const FrameModel m = read(kMesh +
                            "*BEAM SECTION, ELSET=FRAME, MATERIAL=alu, SECTION=CIRC\n0.02\n"
                            "*MATERIAL, NAME=Alu\n"
                            "*ELASTIC, TYPE=ISOTROPIC\n"
                            "7.0e10, 0.33, 20.0\n"
                            "*DENSITY\n"
                            "2700, 20.0\n"
                            "*MATERIAL, NAME=UNUSED\n"
                            "*ELASTIC, TYPE=ISO\n"
                            "1e9, 0.2\n");
  const auto& mat = m.sections[0].material;
  EXPECT_EQ(mat.name, "ALU");
  EXPECT_DOUBLE_EQ(mat.youngs_modulus, 7.0e10);
  EXPECT_DOUBLE_EQ(mat.poisson_ratio, 0.33);
  EXPECT_REL(mat.shear_modulus, 7.0e10 / (2 * 1.33), 1e-15);
  EXPECT_DOUBLE_EQ(mat.density, 2700);
}

TEST(InpReader, MaterialWithoutDensityHasZeroDensity) {
  const FrameModel m = read(kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0\n");
  EXPECT_EQ(m.sections[0].material.density, 0.0);
  EXPECT_DOUBLE_EQ(m.sections[0].material.shear_modulus, 1e11);
}

// ------------------------------------------------------------------ supports and loads

TEST(InpReader, BoundaryForms) {
  const FrameModel m = read(kModel +
                            "*NSET, NSET=ENDS\n1, 3\n"
                            "*BOUNDARY\n"
                            "1, 2\n"            // one DOF
                            "2, 1, 3\n"         // a range
                            "3, 4, 4, 0.01\n"   // a prescribed rotation
                            "3, 1, , 0.002\n"   // empty last DOF: first only
                            "ENDS, PINNED\n"
                            "ends, encastre\n"
                            "2, 6, 6\n");
  using C = framedyn::fem::Constraint;
  std::vector<std::tuple<int, int, double>> got;
  for (const C& c : m.constraints) got.emplace_back(c.node, c.dof, c.value);
  // One entry per DOF, in the order of first definition, with the last value
  // (a DOF defined again takes the new value: node 3's rotation 4 and its
  // prescribed 0.002 along 1 are fixed to 0 by the PINNED and ENCASTRE lines).
  const std::vector<std::tuple<int, int, double>> want = {
      {0, 1, 0.0},                                                            // 1, 2
      {1, 0, 0.0}, {1, 1, 0.0}, {1, 2, 0.0},                                  // 2, 1, 3
      {2, 3, 0.0},                                                            // 3, 4, 4, 0.01, then ENCASTRE
      {2, 0, 0.0},                                                            // 3, 1, , 0.002, then PINNED
      {0, 0, 0.0}, {0, 2, 0.0}, {2, 1, 0.0}, {2, 2, 0.0},                     // PINNED (new DOFs)
      {0, 3, 0.0}, {0, 4, 0.0}, {0, 5, 0.0}, {2, 4, 0.0}, {2, 5, 0.0},        // ENCASTRE (new DOFs)
      {1, 5, 0.0}};
  EXPECT_EQ(got, want);
}

TEST(InpReader, CloadOnNodeAndSet) {
  const FrameModel m = read(kModel +
                            "*NSET, NSET=TIPS\n2, 3\n"
                            "*CLOAD\n"
                            "3, 2, -1500.5\n"
                            "TIPS, 6, 25\n"
                            "1, 1, 1.0e3\n");
  ASSERT_EQ(m.loads.size(), 4u);
  EXPECT_EQ(m.loads[0].node, 2);
  EXPECT_EQ(m.loads[0].dof, 1);
  EXPECT_DOUBLE_EQ(m.loads[0].value, -1500.5);
  EXPECT_EQ(m.loads[1].node, 1);
  EXPECT_EQ(m.loads[1].dof, 5);
  EXPECT_DOUBLE_EQ(m.loads[1].value, 25);
  EXPECT_EQ(m.loads[2].node, 2);
  EXPECT_EQ(m.loads[2].dof, 5);
  EXPECT_EQ(m.loads[3].node, 0);
  EXPECT_EQ(m.loads[3].dof, 0);
  EXPECT_DOUBLE_EQ(m.loads[3].value, 1000);
}

// ------------------------------------------------------------------ *INCLUDE

TEST(InpReader, IncludeRelativeAndNested) {
  TempDir dir;
  dir.write("parts/nodes.inp", "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n*INCLUDE, INPUT=more/elements.inp\n");
  dir.write("parts/more/elements.inp", kBeams);
  dir.write("materials.inp", kSteel);
  const fs::path main = dir.write("model/main.inp",
                                  kUnits + "*INCLUDE, INPUT=../parts/nodes.inp\n" + kSection + "*include, input=\"../materials.inp\"\n");
  const FrameModel m = read_inp(main);
  EXPECT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.beams.size(), 2u);
  EXPECT_DOUBLE_EQ(m.sections[0].material.youngs_modulus, 2.1e11);
  // From text, *INCLUDE paths are relative to base_dir.
  const FrameModel t = read_inp_text(kUnits + "*INCLUDE, INPUT=parts/nodes.inp\n" + kSection + "*INCLUDE, INPUT=materials.inp\n",
                                     "memory", dir.path());
  EXPECT_EQ(t.beams.size(), 2u);
  // An absolute path works from anywhere.
  const FrameModel a = read(kUnits + "*INCLUDE, INPUT=" + (dir.path() / "parts/nodes.inp").string() + "\n" + kSection + kSteel);
  EXPECT_EQ(a.beams.size(), 2u);
}

TEST(InpReader, IncludedFileMayCarryTheUnitsComment) {
  TempDir dir;
  dir.write("units.inp", "** units: mm-N-s\n");
  const FrameModel m = read_inp_text("*INCLUDE, INPUT=units.inp\n*NODE\n1, 1000, 0, 0\n", "memory", dir.path());
  EXPECT_EQ(m.units.name(), "mm-N-s");
  EXPECT_DOUBLE_EQ(m.nodes[0].position.x(), 1.0);
}

// ------------------------------------------------------------------ steps

TEST(InpReader, FrequencyStepGivesRequestedModes) {
  const FrameModel m = read(kModel +
                            "*STEP, NAME=modal, PERTURBATION, INC=100\n"  // INC: read and ignored
                            "*FREQUENCY, SOLVER=LANCZOS, STORAGE=YES\n"
                            "12\n"
                            "*NODE PRINT, NSET=ALL\n"
                            "U\n"
                            "*EL PRINT, ELSET=FRAME\n"
                            "S\n"
                            "*NODE FILE\nU\n"
                            "*EL FILE\nS, E\n"
                            "*OUTPUT, FIELD\n"
                            "*NODE OUTPUT\nU\n"
                            "*ELEMENT OUTPUT, ELSET=FRAME\nS\n"
                            "*END STEP\n");
  ASSERT_TRUE(m.requested_modes.has_value());
  EXPECT_EQ(*m.requested_modes, 12);
}

TEST(InpReader, StaticStepWithLoadsInside) {
  const FrameModel m = read(kModel +
                            "*BOUNDARY\n1, ENCASTRE\n"
                            "*STEP\n"
                            "*STATIC, SOLVER=SPOOLES\n"
                            "1., 1.\n"
                            "*CLOAD\n3, 3, -100\n"
                            "*NODE PRINT, NSET=ALL\nU, RF\n"
                            "*END STEP\n");
  EXPECT_FALSE(m.requested_modes.has_value());
  EXPECT_EQ(m.constraints.size(), 6u);
  ASSERT_EQ(m.loads.size(), 1u);
  EXPECT_DOUBLE_EQ(m.loads[0].value, -100);
}

TEST(InpReader, FrequencyWithoutDataLineLeavesTheCountUnset) {
  const FrameModel m = read(kModel + "*STEP\n*FREQUENCY\n*END STEP\n");
  EXPECT_FALSE(m.requested_modes.has_value());
}

// ------------------------------------------------------------------ syntax

TEST(InpReader, KeywordsAndParametersAreCaseInsensitive) {
  const FrameModel m = read("** Units: SI\n"
                            "*node, nset=all\n1, 0, 0, 0\n2, 1, 0, 0\n"
                            "*Element, Type=b33, Elset=Frame\n1, 1, 2\n"
                            "*beam section, elset=frame, material=steel, section=rect\n0.1, 0.2\n"
                            "*Material, Name=Steel\n*elastic, type=isotropic\n2.1e11, 0.3\n*Density\n7850\n"
                            "*nset, nset=tip\n2\n"
                            "*Boundary\nall, Encastre\n"
                            "*cload\nTIP, 2, 10\n"
                            "*step\n*frequency\n4\n*end step\n");
  EXPECT_EQ(m.beams.at(0).theory, BeamTheory::euler_bernoulli);
  EXPECT_EQ(m.beams.at(0).section, 0);
  EXPECT_EQ(m.node_sets.count("ALL"), 1u);
  EXPECT_EQ(m.node_sets.count("TIP"), 1u);
  EXPECT_EQ(m.constraints.size(), 12u);
  EXPECT_EQ(m.loads.size(), 1u);
  EXPECT_EQ(m.requested_modes, std::optional<int>(4));
  EXPECT_EQ(m.units.name(), "m-N-s");
}

TEST(InpReader, CommentsBlankLinesIndentationAndCrlf) {
  std::string deck = "** a comment at the top\r\n"
                     "** units: m-N-s\r\n"
                     "\r\n"
                     "   *NODE, NSET=ALL\r\n"
                     "** between data lines\r\n"
                     "  1, 0, 0, 0  \r\n"
                     "\t2, 1, 0, 0\r\n"
                     "   ** indented comment\r\n"
                     "*ELEMENT, TYPE=B31, ELSET=FRAME\r\n"
                     "1, 1,\r\n"
                     "** a comment inside a continued element line\r\n"
                     "2\r\n" +
                     kSection + kSteel + "**\n** last line is a comment without newline";
  const FrameModel m = read(deck);
  ASSERT_EQ(m.nodes.size(), 2u);
  EXPECT_EQ(m.nodes[1].position, Eigen::Vector3d(1, 0, 0));
  ASSERT_EQ(m.beams.size(), 1u);
  EXPECT_EQ(m.beams[0].node_b, 1);
}

TEST(InpReader, KeywordLineContinuation) {
  const FrameModel m = read(kMesh +
                            "*BEAM SECTION, ELSET=FRAME,\n"
                            "** a comment between the two halves\n"
                            "MATERIAL=STEEL,\n"
                            " SECTION=PIPE\n"
                            "0.05, 0.005\n"
                            "*MATERIAL,\nNAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n");
  EXPECT_EQ(section_of(m).shape, "PIPE");
  EXPECT_EQ(m.sections[0].material.name, "STEEL");
}

TEST(InpReader, UnitsCommentAndOption) {
  const std::string deck = kNodes;  // no units comment
  EXPECT_EQ(read(deck, with_units("in-lbf-s")).units.name(), "in-lbf-s");
  EXPECT_EQ(read(deck, with_units("SI")).units.name(), "m-N-s");
  EXPECT_EQ(read("** units: in-lbf-s\n" + deck).units.name(), "in-lbf-s");
  EXPECT_EQ(read("**UNITS:mm-N-s\n" + deck).units.name(), "mm-N-s");
  // The option and the comment may both be given if they agree (SI is m-N-s).
  EXPECT_EQ(read("** units: m-N-s\n" + deck, with_units("SI")).units.name(), "m-N-s");
  EXPECT_EQ(read("** units: in-lbf-s\n" + deck, with_units("in-lbf-s")).units.name(), "in-lbf-s");
  // The same comment twice is fine.
  EXPECT_EQ(read("** units: in-lbf-s\n" + deck + "** units: in-lbf-s\n").units.name(), "in-lbf-s");
  // Other comments that mention units are just comments.
  EXPECT_EQ(read("** the units: are given below\n** units: mm-N-s\n" + deck).units.name(), "mm-N-s");
}

// ------------------------------------------------------------------ unit conversion

TEST(InpReader, InchPoundSecondConvertsToSI) {
  const double mass_unit = kPoundForce / kInch;  // lbf s^2 / in, in kg
  const std::string deck =
      "** units: in-lbf-s\n"
      "*NODE\n1, 0, 0, 0\n2, 10, 20, 30\n"
      "*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
      "*ELEMENT, TYPE=B31, ELSET=G\n2, 2, 1\n"
      "*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=RECT\n2, 4\n0, 0, -1\n"
      "*BEAM GENERAL SECTION, ELSET=G, SECTION=GENERAL, DENSITY=7.3e-4\n"
      "3, 5, 1, 4, 6\n1, 0, 0\n2.9e7, 1.1e7\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n3.0e7, 0.3\n*DENSITY\n7.35e-4\n"
      "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 2\n*MASS, ELSET=PM\n0.5\n"
      "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 2\n*ROTARY INERTIA, ELSET=RI\n2, 3, 4\n"
      "*ELEMENT, TYPE=SPRING1, ELSET=KT\n12, 1\n*SPRING, ELSET=KT\n3\n1000\n"
      "*ELEMENT, TYPE=SPRING1, ELSET=KR\n13, 1\n*SPRING, ELSET=KR\n5\n2000\n"
      "*BOUNDARY\n1, 2, 2, 0.5\n1, 5, 5, 0.01\n"
      "*CLOAD\n2, 3, 100\n2, 4, 250\n";
  const FrameModel m = read(deck);
  EXPECT_EQ(m.units.name(), "in-lbf-s");
  // Coordinates.
  EXPECT_REL(m.nodes[1].position.x(), 10 * kInch, 1e-15);
  EXPECT_REL(m.nodes[1].position.y(), 20 * kInch, 1e-15);
  EXPECT_REL(m.nodes[1].position.z(), 30 * kInch, 1e-15);
  // Material: E in psi, density in lbf s^2/in^4; G from E.
  const auto& steel = m.sections[0].material;
  EXPECT_REL(steel.youngs_modulus, 3.0e7 * kPoundForce / (kInch * kInch), 1e-14);
  EXPECT_REL(steel.shear_modulus, 3.0e7 * kPoundForce / (kInch * kInch) / 2.6, 1e-14);
  EXPECT_REL(steel.density, 7.35e-4 * mass_unit / std::pow(kInch, 3), 1e-14);
  EXPECT_NEAR(steel.density, 7854.87, 0.01);  // 7.35e-4 lbf s^2/in^4 is steel's 7855 kg/m^3
  // Section dimensions.
  const auto& rect = m.sections[0].properties;
  EXPECT_REL(rect.dimensions.at(0), 2 * kInch, 1e-15);
  EXPECT_REL(rect.dimensions.at(1), 4 * kInch, 1e-15);
  EXPECT_REL(rect.area, 8 * kInch * kInch, 1e-14);
  EXPECT_REL(rect.i11, 2.0 * 64 / 12 * std::pow(kInch, 4), 1e-14);
  EXPECT_REL(rect.i22, 4.0 * 8 / 12 * std::pow(kInch, 4), 1e-14);
  // General section: A, I, J, E, G and DENSITY.
  const auto& gen = m.sections[1];
  EXPECT_REL(gen.properties.area, 3 * kInch * kInch, 1e-14);
  EXPECT_REL(gen.properties.i11, 5 * std::pow(kInch, 4), 1e-14);
  EXPECT_REL(gen.properties.i12, 1 * std::pow(kInch, 4), 1e-14);
  EXPECT_REL(gen.properties.i22, 4 * std::pow(kInch, 4), 1e-14);
  EXPECT_REL(gen.properties.torsion_constant, 6 * std::pow(kInch, 4), 1e-14);
  EXPECT_REL(gen.material.youngs_modulus, 2.9e7 * kPoundForce / (kInch * kInch), 1e-14);
  EXPECT_REL(gen.material.shear_modulus, 1.1e7 * kPoundForce / (kInch * kInch), 1e-14);
  EXPECT_REL(gen.material.density, 7.3e-4 * mass_unit / std::pow(kInch, 3), 1e-14);
  // Point mass and rotary inertia.
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_REL(m.point_masses[0].mass, 0.5 * mass_unit, 1e-14);
  EXPECT_NEAR(m.point_masses[0].mass, 87.56, 0.01);  // 0.5 lbf s^2/in = 87.56 kg
  EXPECT_REL(m.point_masses[0].rotary_inertia(1, 1), 3 * mass_unit * kInch * kInch, 1e-14);
  // Springs: lbf/in and lbf in/rad.
  ASSERT_EQ(m.springs.size(), 2u);
  EXPECT_REL(m.springs[0].stiffness, 1000 * kPoundForce / kInch, 1e-14);
  EXPECT_REL(m.springs[1].stiffness, 2000 * kPoundForce * kInch, 1e-14);
  // Prescribed displacement in inches, rotation in radians (unchanged).
  ASSERT_EQ(m.constraints.size(), 2u);
  EXPECT_REL(m.constraints[0].value, 0.5 * kInch, 1e-15);
  EXPECT_DOUBLE_EQ(m.constraints[1].value, 0.01);
  // Force in lbf, moment in lbf in.
  ASSERT_EQ(m.loads.size(), 2u);
  EXPECT_REL(m.loads[0].value, 100 * kPoundForce, 1e-15);
  EXPECT_REL(m.loads[1].value, 250 * kPoundForce * kInch, 1e-15);
}

TEST(InpReader, MillimetreNewtonSecondConvertsToSI) {
  const std::string deck =
      "** units: mm-N-s\n"
      "*NODE\n1, 0, 0, 0\n2, 1500, 0, 0\n"
      "*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
      "*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=PIPE\n50, 5\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n*DENSITY\n7.85e-9\n"
      "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 2\n*MASS, ELSET=PM\n0.25\n"
      "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 2\n*ROTARY INERTIA, ELSET=RI\n1000, 2000, 3000\n"
      "*ELEMENT, TYPE=SPRING2, ELSET=K\n12, 1, 2\n*SPRING, ELSET=K\n2, 2\n500\n"
      "*ELEMENT, TYPE=SPRING2, ELSET=KR\n13, 1, 2\n*SPRING, ELSET=KR\n6, 6\n1e6\n"
      "*BOUNDARY\n1, 1, 1, 2.5\n"
      "*CLOAD\n2, 2, 10\n2, 6, 3000\n";
  const FrameModel m = read(deck);
  EXPECT_EQ(m.units.name(), "mm-N-s");
  EXPECT_REL(m.nodes[1].position.x(), 1.5, 1e-15);
  const auto& s = m.sections[0];
  EXPECT_REL(s.material.youngs_modulus, 2.1e11, 1e-14);
  EXPECT_REL(s.material.density, 7850, 1e-12);  // tonne/mm^3
  const double ro = 0.05, ri = 0.045;
  EXPECT_REL(s.properties.area, kPi * (ro * ro - ri * ri), 1e-12);
  EXPECT_REL(s.properties.i11, kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4, 1e-12);
  EXPECT_REL(m.point_masses[0].mass, 250, 1e-14);                   // tonne
  EXPECT_REL(m.point_masses[0].rotary_inertia(0, 0), 1.0, 1e-14);  // t mm^2 = 1e-3 kg m^2
  EXPECT_REL(m.springs[0].stiffness, 5e5, 1e-14);                   // N/mm
  EXPECT_REL(m.springs[1].stiffness, 1e3, 1e-14);                   // N mm/rad
  EXPECT_REL(m.constraints[0].value, 2.5e-3, 1e-14);
  EXPECT_REL(m.loads[0].value, 10, 1e-15);
  EXPECT_REL(m.loads[1].value, 3, 1e-14);  // N mm
}

TEST(InpReader, UnitsOptionOverridesWhenTheFileHasNone) {
  const FrameModel m = read(kNodes, with_units("in-lbf-s"));
  EXPECT_REL(m.nodes[1].position.x(), kInch, 1e-15);
  const FrameModel n = read(kNodes, with_units("mm-N-s"));
  EXPECT_REL(n.nodes[1].position.x(), 1e-3, 1e-15);
}

TEST(InpReader, ReadsTheShippedFrame) {
  const FrameModel m = read_inp(fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "r100_frame.inp");
  EXPECT_EQ(m.units.name(), "in-lbf-s");
  EXPECT_EQ(m.nodes.size(), 51u);
  EXPECT_EQ(m.beams.size(), 61u);
  EXPECT_EQ(m.element_sets.count("LEFT_RAIL"), 1u);
  EXPECT_EQ(m.element_sets.count("RIGHT_RAIL"), 1u);
  for (const auto& b : m.beams) EXPECT_GE(b.section, 0);
}

// ------------------------------------------------------------------ errors, table-driven

struct ErrorCase {
  std::string name;
  std::string deck;
  std::string line;  // the line the message must point at (trimmed text, or "@N"); "" for none
  std::string key;   // the keyword the message names
  std::vector<std::string> fragments;
  std::optional<std::string> units_option = std::nullopt;
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

std::string mass_at_node3(const std::string& set = "PM") {
  return "*ELEMENT, TYPE=MASS, ELSET=" + set + "\n10, 3\n*MASS, ELSET=" + set + "\n5.0\n";
}

std::string nul_deck() {
  std::string d = kUnits + "*NODE\n1, 0, 0";
  d += '\0';
  d += ", 0\n";
  return d;
}

std::string frame_with_section(const std::string& section_block) { return kMesh + section_block + kSteel; }

const std::string kRectOnFrame = "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=";

std::vector<ErrorCase> error_cases() {
  return {
      // ---- keywords and parameters
      {"UnknownKeyword", kModel + "*SURFACE, NAME=S\n", "*SURFACE, NAME=S", "*SURFACE", {"expected a keyword framedyn reads", "found *SURFACE"}},
      // ---- distributing couplings (DCOUP3D + *DISTRIBUTING COUPLING; fem/rigid_links.h, Eqs. R.6-R.8)
      {"DistributingCouplingElementWithoutCoupling", kModel + "*NODE\n9, 1, 1, 0\n*ELEMENT, TYPE=DCOUP3D, ELSET=C\n9, 9\n", "9, 9", "*ELEMENT",
       {"expected a *DISTRIBUTING COUPLING for element 9 of type DCOUP3D", "found none"}},
      {"DistributingCouplingMountsOnOneLine",
       kModel + "*NODE\n9, 1, 1, 0\n*ELEMENT, TYPE=DCOUP3D, ELSET=C\n9, 9\n*DISTRIBUTING COUPLING, ELSET=C\n1, 1\n2, 1\n3, 1\n",
       "*DISTRIBUTING COUPLING, ELSET=C", "*DISTRIBUTING COUPLING", {"expected mounts that do not all lie on one line", "found nodes 1, 2, 3"}},
      {"DistributingCouplingNegativeWeight",
       kModel + "*NODE\n9, 1, 1, 0\n*ELEMENT, TYPE=DCOUP3D, ELSET=C\n9, 9\n*DISTRIBUTING COUPLING, ELSET=C\n1, -1\n", "1, -1",
       "*DISTRIBUTING COUPLING", {"expected a positive weight", "found -1"}},
      {"UnknownKeywordInsideStep", kModel + "*STEP\n*TEMPERATURE\n1, 100.\n*END STEP\n", "*TEMPERATURE", "*TEMPERATURE", {"found *TEMPERATURE"}},
      {"UnknownParameter", kUnits + "*NODE, NSETT=A\n1, 0, 0, 0\n", "*NODE, NSETT=A", "*NODE", {"expected one of the parameters NSET", "found parameter NSETT"}},
      {"UnknownParameterOnElement", kUnits + kNodes + "*ELEMENT, TYPE=B31, ELSET=E, SECTION=X\n1, 1, 2\n", "*ELEMENT, TYPE=B31, ELSET=E, SECTION=X", "*ELEMENT", {"TYPE, ELSET", "found parameter SECTION"}},
      {"ParameterOnBoundary", kModel + "*BOUNDARY, AMPLITUDE=A\n1, ENCASTRE\n", "*BOUNDARY, AMPLITUDE=A", "*BOUNDARY", {"found parameter AMPLITUDE"}},
      {"ParameterOnCload", kModel + "*CLOAD, TOTAL=YES\n3, 2, 1.0\n", "*CLOAD, TOTAL=YES", "*CLOAD", {"found parameter TOTAL"}},
      {"ParameterOnDensity", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY, TEMP=20\n7850\n", "*DENSITY, TEMP=20", "*DENSITY", {"found parameter TEMP"}},
      {"ParameterWithoutName", kUnits + "*NODE, =A\n1, 0, 0, 0\n", "*NODE, =A", "*NODE", {"expected a parameter NAME or NAME=VALUE", "found '=A'"}},
      {"ParameterTwice", kUnits + "*NODE, NSET=A, nset=B\n1, 0, 0, 0\n", "*NODE, NSET=A, nset=B", "*NODE", {"each parameter once", "parameter NSET twice"}},
      {"MissingRequiredParameter", kUnits + kNodes + "*ELEMENT, ELSET=E\n1, 1, 2\n", "*ELEMENT, ELSET=E", "*ELEMENT", {"expected TYPE=...", "found no TYPE parameter"}},
      {"EmptyRequiredParameter", kModel + "*NSET, NSET=\n1\n", "*NSET, NSET=", "*NSET", {"found no NSET parameter"}},
      {"EmptyNsetOnNode", kUnits + "*NODE, NSET=\n1, 0, 0, 0\n", "*NODE, NSET=", "*NODE", {"found no NSET parameter"}},
      {"SectionWithoutMaterialParameter", frame_with_section("*BEAM SECTION, ELSET=FRAME, SECTION=RECT\n0.1, 0.2\n"), "*BEAM SECTION, ELSET=FRAME, SECTION=RECT", "*BEAM SECTION", {"found no MATERIAL parameter"}},
      {"MaterialWithoutName", kModel + "*MATERIAL\n", "*MATERIAL", "*MATERIAL", {"found no NAME parameter"}},
      {"MassWithoutElset", kModel + "*ELEMENT, TYPE=MASS\n10, 3\n*MASS\n5.0\n", "*MASS", "*MASS", {"found no ELSET parameter"}},
      // ---- structure
      {"DataLineBeforeAnyKeyword", kUnits + "5, 0, 0, 0\n" + kNodes, "5, 0, 0, 0", "", {"expected a keyword line (starting with *) first", "found '5, 0, 0, 0'"}},
      {"NulByte", nul_deck(), "@3", "", {"found a NUL byte"}},
      {"EmptyMesh", "** units: SI\n*HEADING\nnothing here\n", "", "*NODE", {"expected a mesh with nodes and beam elements", "found none"}},
      {"EmptyText", "** units: SI\n", "", "*NODE", {"expected a mesh with nodes and beam elements"}},
      // ---- *NODE
      {"NodeWithoutCoordinates", kUnits + "*NODE\n4\n", "4", "*NODE", {"expected node number, x[, y[, z]]", "found '4'"}},
      {"NodeWithFourCoordinates", kUnits + "*NODE\n4, 1, 2, 3, 4\n", "4, 1, 2, 3, 4", "*NODE", {"node number, x[, y[, z]]"}},
      {"NodeNumberZero", kUnits + "*NODE\n0, 1, 2, 3\n", "0, 1, 2, 3", "*NODE", {"expected a positive node number", "found 0"}},
      {"NodeNumberNegative", kUnits + "*NODE\n-3, 1, 2, 3\n", "-3, 1, 2, 3", "*NODE", {"a positive node number", "found -3"}},
      {"NodeNumberText", kUnits + "*NODE\nA1, 0, 0, 0\n", "A1, 0, 0, 0", "*NODE", {"node number (an integer)", "found 'A1'"}},
      {"NodeNumberDecimal", kUnits + "*NODE\n1.0, 0, 0, 0\n", "1.0, 0, 0, 0", "*NODE", {"node number (an integer)", "found '1.0'"}},
      {"NodeNumberTooLarge", kUnits + "*NODE\n99999999999, 0, 0, 0\n", "99999999999, 0, 0, 0", "*NODE", {"(an integer)", "'99999999999'"}},
      {"NodeNumberEmpty", kUnits + "*NODE\n, 1, 2, 3\n", ", 1, 2, 3", "*NODE", {"node number (an integer)", "found an empty field"}},
      {"DuplicateNode", kUnits + "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n1, 5, 0, 0\n", "1, 5, 0, 0", "*NODE", {"expected a new node number", "found node 1 again (first at deck.inp:3: *NODE)"}},
      {"DuplicateNodeInAnotherBlock", kModel + "*NODE\n3, 9, 9, 9\n", "3, 9, 9, 9", "*NODE", {"node 3 again (first at deck.inp:5: *NODE)"}},
      {"CoordinateText", kUnits + "*NODE\n1, 0, abc, 0\n", "1, 0, abc, 0", "*NODE", {"a coordinate (a finite number)", "found 'abc'"}},
      {"CoordinateTwoDecimalPoints", kUnits + "*NODE\n1, 1.0.0, 0, 0\n", "1, 1.0.0, 0, 0", "*NODE", {"(a finite number)", "found '1.0.0'"}},
      {"CoordinateTrailingText", kUnits + "*NODE\n1, 1.5m, 0, 0\n", "1, 1.5m, 0, 0", "*NODE", {"found '1.5m'"}},
      {"CoordinateInf", kUnits + "*NODE\n1, inf, 0, 0\n", "1, inf, 0, 0", "*NODE", {"(a finite number)", "found 'inf'"}},
      {"CoordinateNan", kUnits + "*NODE\n1, 0, NaN, 0\n", "1, 0, NaN, 0", "*NODE", {"found 'NaN'"}},
      {"CoordinateOverflow", kUnits + "*NODE\n1, 1e999, 0, 0\n", "1, 1e999, 0, 0", "*NODE", {"found '1e999'"}},
      // ---- *ELEMENT
      {"ElementTypeC3D8", kUnits + kNodes + "*ELEMENT, TYPE=C3D8\n1, 1, 2, 3, 1, 2, 3, 1, 2\n", "*ELEMENT, TYPE=C3D8", "*ELEMENT", {"expected TYPE=B31, B32, B32R, B33, MASS, ROTARYI, SPRING1, SPRING2 or DCOUP3D", "found TYPE=C3D8"}},
      {"ElementB32WithTwoNodes", kUnits + kNodes + "*ELEMENT, TYPE=B32\n1, 1, 2\n", "1, 1, 2", "*ELEMENT", {"expected element number and 3 node number(s) for B32", "found '1, 1, 2'"}},
      {"ElementB32RWithARepeatedNode", kUnits + kNodes + "*ELEMENT, TYPE=B32R\n1, 1, 2, 1\n", "1, 1, 2, 1", "*ELEMENT", {"expected three different nodes (end, midside, end)", "found element 1 on nodes 1, 2, 1"}},
      {"ElementTypeLowerCase", kUnits + kNodes + "*ELEMENT, TYPE=t3d2\n1, 1, 2\n", "*ELEMENT, TYPE=t3d2", "*ELEMENT", {"found TYPE=T3D2"}},
      {"BeamWithOneNode", kUnits + kNodes + "*ELEMENT, TYPE=B31\n7, 1\n", "7, 1", "*ELEMENT", {"expected element number and 2 node number(s) for B31", "found '7, 1'"}},
      {"BeamWithFourNodes", kUnits + kNodes + "*ELEMENT, TYPE=B33\n7, 1, 2, 3, 1\n", "7, 1, 2, 3, 1", "*ELEMENT", {"2 node number(s) for B33"}},
      {"MassWithTwoNodes", kUnits + kNodes + "*ELEMENT, TYPE=MASS\n7, 1, 2\n", "7, 1, 2", "*ELEMENT", {"1 node number(s) for MASS"}},
      {"RotaryiWithTwoNodes", kUnits + kNodes + "*ELEMENT, TYPE=ROTARYI\n7, 1, 2\n", "7, 1, 2", "*ELEMENT", {"1 node number(s) for ROTARYI"}},
      {"Spring1WithTwoNodes", kUnits + kNodes + "*ELEMENT, TYPE=SPRING1\n7, 1, 2\n", "7, 1, 2", "*ELEMENT", {"1 node number(s) for SPRING1"}},
      {"Spring2WithOneNode", kUnits + kNodes + "*ELEMENT, TYPE=SPRING2\n7, 1\n", "7, 1", "*ELEMENT", {"2 node number(s) for SPRING2"}},
      {"BeamWithOrientationNode", kUnits + kNodes + "*ELEMENT, TYPE=B31\n7, 1, 2, 3\n", "7, 1, 2, 3", "*ELEMENT", {"give the orientation on the *BEAM SECTION line", "found a third, orientation node in '7, 1, 2, 3'"}},
      {"ContinuedBeamLineWithOrientationNode", kUnits + kNodes + "*ELEMENT, TYPE=B31\n7, 1,\n2, 3\n", "7, 1,", "*ELEMENT", {"a third, orientation node in '7, 1,2, 3'"}},
      {"ElementNumberZero", kUnits + kNodes + "*ELEMENT, TYPE=B31\n0, 1, 2\n", "0, 1, 2", "*ELEMENT", {"expected a positive element number", "found 0"}},
      {"ElementNumberDecimal", kUnits + kNodes + "*ELEMENT, TYPE=B31\n1.5, 1, 2\n", "1.5, 1, 2", "*ELEMENT", {"element number (an integer)", "found '1.5'"}},
      {"ElementNumberEmpty", kUnits + kNodes + "*ELEMENT, TYPE=B31\n, 1, 2\n", ", 1, 2", "*ELEMENT", {"element number (an integer)", "found an empty field"}},
      {"ElementNodeText", kUnits + kNodes + "*ELEMENT, TYPE=B31\n7, 1, two\n", "7, 1, two", "*ELEMENT", {"node number (an integer)", "found 'two'"}},
      {"DuplicateElement", kUnits + kNodes + "*ELEMENT, TYPE=B31\n1, 1, 2\n1, 2, 3\n", "1, 2, 3", "*ELEMENT", {"expected a new element number", "found element 1 again (first at deck.inp:7: *ELEMENT)"}},
      {"DuplicateElementOfAnotherType", kModel + "*ELEMENT, TYPE=MASS\n2, 3\n", "2, 3", "*ELEMENT", {"found element 2 again"}},
      {"ElementFromNodeToItself", kUnits + kNodes + "*ELEMENT, TYPE=B31\n7, 2, 2\n", "7, 2, 2", "*ELEMENT", {"expected two different nodes", "found element 7 from node 2 to itself"}},
      {"Spring2FromNodeToItself", kUnits + kNodes + "*ELEMENT, TYPE=SPRING2\n7, 3, 3\n", "7, 3, 3", "*ELEMENT", {"two different nodes"}},
      {"ZeroLengthElement", kUnits + "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 0, 0\n*ELEMENT, TYPE=B31, ELSET=FRAME\n7, 2, 3\n" + kSection + kSteel, "7, 2, 3", "*ELEMENT", {"expected an element of nonzero length", "found element 7: nodes 2 and 3 at the same point"}},
      {"UndefinedNodeInElement", kUnits + kNodes + "*ELEMENT, TYPE=B31, ELSET=FRAME\n7, 1, 9\n" + kSection + kSteel, "7, 1, 9", "*ELEMENT", {"expected a node defined by *NODE", "found node 9"}},
      {"UndefinedNodeInMassElement", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 12\n*MASS, ELSET=PM\n1.0\n", "10, 12", "*ELEMENT", {"found node 12"}},
      // ---- sets
      {"UndefinedNodeInNset", kModel + "*NSET, NSET=SUP\n1, 2\n9\n", "9", "*NSET", {"expected a node defined by *NODE", "found node 9"}},
      {"UndefinedNodeInNsetGenerate", kModel + "*NSET, NSET=G, GENERATE\n1, 5\n", "1, 5", "*NSET", {"found node 4"}},
      {"UndefinedNodeThroughASubset", kModel + "*NSET, NSET=BAD\n2, 77\n*NSET, NSET=OUTER\nBAD\n", "2, 77", "*NSET", {"found node 77"}},
      {"UndefinedElementInElset", kModel + "*ELSET, ELSET=X\n1, 99\n", "1, 99", "*ELSET", {"elements defined by *ELEMENT", "found element 99"}},
      {"UndefinedSetAsNsetMember", kModel + "*NSET, NSET=A\n1, LATER\n*NSET, NSET=LATER\n2\n", "1, LATER", "*NSET", {"a node number or a defined *NSET", "found 'LATER'"}},
      {"UndefinedSetAsElsetMember", kModel + "*ELSET, ELSET=A\nNOPE\n", "NOPE", "*ELSET", {"expected a defined *ELSET", "found 'NOPE'"}},
      {"NodeSetNameInElset", kModel + "*ELSET, ELSET=A\nALL\n", "ALL", "*ELSET", {"expected a defined *ELSET", "found 'ALL'"}},
      {"GenerateLastBeforeFirst", kModel + "*NSET, NSET=G, GENERATE\n5, 1\n", "5, 1", "*NSET", {"expected first <= last and a positive increment", "found '5, 1'"}},
      {"GenerateZeroIncrement", kModel + "*NSET, NSET=G, GENERATE\n1, 3, 0\n", "1, 3, 0", "*NSET", {"a positive increment", "found '1, 3, 0'"}},
      {"GenerateNegativeIncrement", kModel + "*ELSET, ELSET=G, GENERATE\n1, 2, -1\n", "1, 2, -1", "*ELSET", {"a positive increment"}},
      {"GenerateOneField", kModel + "*NSET, NSET=G, GENERATE\n1\n", "1", "*NSET", {"expected first, last[, increment] with GENERATE", "found '1'"}},
      {"GenerateFourFields", kModel + "*NSET, NSET=G, GENERATE\n1, 3, 1, 1\n", "1, 3, 1, 1", "*NSET", {"first, last[, increment] with GENERATE"}},
      {"GenerateHugeRange", kModel + "*NSET, NSET=G, GENERATE\n1, 2000000000\n", "1, 2000000000", "*NSET", {"a range of at most 1e7 members"}},
      // fuzz_inp_reader's timeout: a large range named again and again doubles the set with every line.
      // fuzz_inp_reader: a set naming itself in its own definition (the size check must not create it early).
      {"SetNamingItselfInItsOwnDefinition", kModel + "*NSET, NSET=S\n1\n2, S\n", "2, S", "*NSET", {"a node number or a defined *NSET", "'S'"}},
      {"SetNamingItselfGrowsPastTheLimit", kModel + "*NSET, NSET=G, GENERATE\n1, 4000000\n*NSET, NSET=H\nG, G\nG, G, G\n", "G, G, G", "*NSET",
       {"a set of at most 1e7 members (node *NSET H)", "20000000 members by this line"}},
      {"GenerateText", kModel + "*NSET, NSET=G, GENERATE\n1, x\n", "1, x", "*NSET", {"last number (an integer)", "found 'x'"}},
      {"GenerateIncrementDecimal", kModel + "*NSET, NSET=G, GENERATE\n1, 3, 0.5\n", "1, 3, 0.5", "*NSET", {"increment (an integer)"}},
      // ---- *BEAM SECTION
      {"BeamWithoutSection", kUnits + kNodes + kBeams + "*ELEMENT, TYPE=B31\n3, 1, 3\n" + kSection + kSteel, "3, 1, 3", "*ELEMENT", {"expected a *BEAM SECTION for every beam element", "found element 3 has none"}},
      {"ElementInTwoSections", kModel + "*ELSET, ELSET=FIRST\n1\n*BEAM SECTION, ELSET=FIRST, MATERIAL=STEEL, SECTION=CIRC\n0.05\n", "*BEAM SECTION, ELSET=FIRST, MATERIAL=STEEL, SECTION=CIRC", "*BEAM SECTION", {"expected one section per element", "found element 1 already has the section of ELSET FRAME"}},
      {"SectionOnMassElement", kModel + mass_at_node3() + "*BEAM SECTION, ELSET=PM, MATERIAL=STEEL, SECTION=CIRC\n0.05\n", "*BEAM SECTION, ELSET=PM, MATERIAL=STEEL, SECTION=CIRC", "*BEAM SECTION", {"expected beam elements (B31, B32, B32R, B33) in ELSET PM", "found element 10 of type MASS"}},
      {"GeneralSectionOnSpringElement", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=K\n10, 3\n*SPRING, ELSET=K\n1\n1e3\n*BEAM GENERAL SECTION, ELSET=K, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n1, 1\n", "*BEAM GENERAL SECTION, ELSET=K, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"found element 10 of type SPRING1"}},
      {"SectionOnUndefinedElset", frame_with_section("*BEAM SECTION, ELSET=FRAMES, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.2\n"), "*BEAM SECTION, ELSET=FRAMES, MATERIAL=STEEL, SECTION=RECT", "*BEAM SECTION", {"expected ELSET naming a defined element set", "found FRAMES"}},
      {"GeneralSectionOnUndefinedElset", kMesh + "*BEAM GENERAL SECTION, ELSET=NONE, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n1, 1\n", "*BEAM GENERAL SECTION, ELSET=NONE, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"found NONE"}},
      {"UnknownSectionType", frame_with_section(kRectOnFrame + "HEX\n0.1\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=HEX", "*BEAM SECTION", {"expected SECTION=RECT, BOX, PIPE, CIRC, I or CHANNEL", "found SECTION=HEX"}},
      {"ArbitrarySectionNotSupported", frame_with_section(kRectOnFrame + "ARBITRARY\n0.1\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=ARBITRARY", "*BEAM SECTION", {"found SECTION=ARBITRARY"}},
      {"GeneralSectionOfWrongKind", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=RECT\n0.1, 0.2\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=RECT", "*BEAM GENERAL SECTION", {"expected SECTION=GENERAL", "found SECTION=RECT"}},
      {"RectWithThreeDimensions", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2, 0.3\n"), "0.1, 0.2, 0.3", "*BEAM SECTION", {"expected the 1 or 2 dimensions of a RECT section (1 to 2 values)", "found 3 values in '0.1, 0.2, 0.3'"}},
      {"BoxWithFiveDimensions", frame_with_section(kRectOnFrame + "BOX\n0.1, 0.2, 0.01, 0.01, 0.01\n"), "0.1, 0.2, 0.01, 0.01, 0.01", "*BEAM SECTION", {"the 6 dimensions of a BOX section"}},
      {"PipeWithOneDimension", frame_with_section(kRectOnFrame + "PIPE\n0.1\n"), "0.1", "*BEAM SECTION", {"the 2 dimensions of a PIPE section"}},
      {"CircWithThreeDimensions", frame_with_section(kRectOnFrame + "CIRC\n0.1, 0.2, 0.3\n"), "0.1, 0.2, 0.3", "*BEAM SECTION", {"the 1 or 2 dimensions of a CIRC section"}},
      {"IWithSixDimensions", frame_with_section(kRectOnFrame + "I\n0.3, 0.2, 0.2, 0.02, 0.02, 0.01\n"), "0.3, 0.2, 0.2, 0.02, 0.02, 0.01", "*BEAM SECTION", {"the 7 dimensions of a I section"}},
      {"ChannelWithThreeDimensions", frame_with_section(kRectOnFrame + "CHANNEL\n0.2, 0.08, 0.01\n"), "0.2, 0.08, 0.01", "*BEAM SECTION", {"the 4 dimensions of a CHANNEL section"}},
      {"SectionDimensionText", frame_with_section(kRectOnFrame + "RECT\n0.1, wide\n"), "0.1, wide", "*BEAM SECTION", {"(a finite number)", "found 'wide'"}},
      {"SectionDimensionZero", frame_with_section(kRectOnFrame + "RECT\n0.1, 0\n"), "0.1, 0", "*BEAM SECTION", {"expected positive section dimensions", "found '0.1, 0'"}},
      {"SectionDimensionEmpty", frame_with_section(kRectOnFrame + "RECT\n0.1, ,\n"), "0.1, ,", "*BEAM SECTION", {"positive section dimensions"}},
      {"SectionDimensionNegative", frame_with_section(kRectOnFrame + "PIPE\n-0.05, 0.01\n"), "-0.05, 0.01", "*BEAM SECTION", {"positive section dimensions"}},
      {"IFlangeThicknessZero", frame_with_section(kRectOnFrame + "I\n0.15, 0.3, 0.2, 0.2, 0, 0.02, 0.01\n"), "0.15, 0.3, 0.2, 0.2, 0, 0.02, 0.01", "*BEAM SECTION", {"positive section dimensions"}},
      {"SectionWithoutDataLine", frame_with_section(kRectOnFrame + "RECT\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT", "*BEAM SECTION", {"expected a data line with the 2 dimensions of RECT", "found none"}},
      {"SectionWithThreeDataLines", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2\n0, 0, -1\n7, 7\n"), "7, 7", "*BEAM SECTION", {"at most two data lines (dimensions, orientation)", "found '7, 7'"}},
      {"BoxWallsThickerThanTheBox", frame_with_section(kRectOnFrame + "BOX\n0.1, 0.2, 0.06, 0.01, 0.05, 0.01\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=BOX", "*BEAM SECTION", {"expected a valid BOX section", "BOX walls thicker than the box"}},
      {"BoxWallsThickerAlong2", frame_with_section(kRectOnFrame + "BOX\n0.1, 0.2, 0.01, 0.1, 0.01, 0.1\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=BOX", "*BEAM SECTION", {"BOX walls thicker than the box"}},
      {"PipeWallThickerThanRadius", frame_with_section(kRectOnFrame + "PIPE\n0.05, 0.06\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=PIPE", "*BEAM SECTION", {"expected a valid PIPE section", "PIPE wall thicker than its radius"}},
      {"IFlangesThickerThanHeight", frame_with_section(kRectOnFrame + "I\n0.1, 0.2, 0.1, 0.1, 0.1, 0.1, 0.01\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=I", "*BEAM SECTION", {"expected a valid I section", "I flanges thicker than the section height"}},
      {"IWebWiderThanFlange", frame_with_section(kRectOnFrame + "I\n0.1, 0.2, 0.1, 0.1, 0.01, 0.01, 0.15\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=I", "*BEAM SECTION", {"I web wider than a flange"}},
      {"ChannelWallsThickerThanSection", frame_with_section(kRectOnFrame + "CHANNEL\n0.2, 0.1, 0.1, 0.01\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=CHANNEL", "*BEAM SECTION", {"expected a valid CHANNEL section", "CHANNEL walls thicker than the section"}},
      {"ChannelWebWiderThanFlange", frame_with_section(kRectOnFrame + "CHANNEL\n0.2, 0.05, 0.01, 0.06\n"), "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=CHANNEL", "*BEAM SECTION", {"CHANNEL walls thicker than the section"}},
      {"OrientationWithTwoComponents", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2\n0, 1\n"), "0, 1", "*BEAM SECTION", {"the local 1-direction n1 (three components) (3 values)", "found 2 values in '0, 1'"}},
      {"OrientationText", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2\n0, up, 0\n"), "0, up, 0", "*BEAM SECTION", {"found 'up'"}},
      {"ZeroOrientationVector", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2\n0, 0, 0\n"), "0, 0, 0", "*BEAM SECTION", {"expected a nonzero local 1-direction", "found 0, 0, 0"}},
      {"OrientationParallelToAxis", frame_with_section(kRectOnFrame + "RECT\n0.1, 0.2\n-2, 0, 0\n"), "1, 1, 2", "*ELEMENT", {"expected a valid beam orientation", "element 1: orientation direction n1 is parallel to the element axis"}},
      {"DefaultOrientationParallelToAxis", kUnits + "*NODE\n1, 0, 0, 0\n2, 0, 0, 3\n*ELEMENT, TYPE=B31, ELSET=FRAME\n5, 1, 2\n" + kSection + kSteel, "5, 1, 2", "*ELEMENT", {"element 5: orientation direction n1 is parallel to the element axis"}},
      // ---- *BEAM GENERAL SECTION
      {"GeneralSectionTwoDataLines", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"expected three data lines (A, I11, I12, I22, J; the local 1-direction; E, G)", "found 2 data lines"}},
      {"GeneralSectionFourConstants", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n1, 1, 0, 1\n0, 0, -1\n1, 1\n", "1, 1, 0, 1", "*BEAM GENERAL SECTION", {"A, I11, I12, I22, J (5 values)", "found 4 values"}},
      {"GeneralSectionOneModulus", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n2e11\n", "2e11", "*BEAM GENERAL SECTION", {"E, G[, thermal expansion] (2 to 3 values)", "found 1 values"}},
      {"GeneralSectionZeroModulus", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n0, 8e10\n", "0, 8e10", "*BEAM GENERAL SECTION", {"expected E > 0 and G > 0", "found '0, 8e10'"}},
      {"GeneralSectionNegativeShearModulus", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n1, 1, 0, 1, 1\n0, 0, -1\n2e11, -8e10\n", "2e11, -8e10", "*BEAM GENERAL SECTION", {"E > 0 and G > 0"}},
      {"GeneralSectionNegativeDensity", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, DENSITY=-1\n1, 1, 0, 1, 1\n0, 0, -1\n2e11, 8e10\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, DENSITY=-1", "*BEAM GENERAL SECTION", {"expected a density >= 0", "found -1"}},
      {"GeneralSectionDensityText", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, DENSITY=heavy\n1, 1, 0, 1, 1\n0, 0, -1\n2e11, 8e10\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, DENSITY=heavy", "*BEAM GENERAL SECTION", {"DENSITY (a finite number)", "found 'heavy'"}},
      {"GeneralSectionZeroArea", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n0, 1e-6, 0, 1e-6, 1e-6\n0, 0, -1\n2e11, 8e10\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"expected a valid GENERAL section", "GENERAL section area A must be positive"}},
      {"GeneralSectionNegativeJ", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n0.01, 1e-6, 0, 1e-6, -1e-6\n0, 0, -1\n2e11, 8e10\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"GENERAL section J must be positive"}},
      {"GeneralSectionNotPositiveDefinite", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n0.01, 1e-6, 2e-6, 1e-6, 1e-6\n0, 0, -1\n2e11, 8e10\n", "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL", "*BEAM GENERAL SECTION", {"a valid GENERAL section", "I12^2 >= I11 I22 is not positive definite"}},
      {"GeneralSectionZeroOrientation", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL\n0.01, 1e-6, 0, 1e-6, 1e-6\n0, 0, 0\n2e11, 8e10\n", "0, 0, 0", "*BEAM GENERAL SECTION", {"a nonzero local 1-direction"}},
      {"GeneralSectionUnknownParameter", kMesh + "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, MATERIAL=STEEL\n0.01, 1e-6, 0, 1e-6, 1e-6\n0, 0, -1\n2e11, 8e10\n" + kSteel, "*BEAM GENERAL SECTION, ELSET=FRAME, SECTION=GENERAL, MATERIAL=STEEL", "*BEAM GENERAL SECTION", {"ELSET, SECTION, DENSITY", "found parameter MATERIAL"}},
      // ---- materials
      {"MaterialMissing", kMesh + "*BEAM SECTION, ELSET=FRAME, MATERIAL=ALU, SECTION=RECT\n0.1, 0.2\n" + kSteel, "*BEAM SECTION, ELSET=FRAME, MATERIAL=ALU, SECTION=RECT", "*BEAM SECTION", {"expected MATERIAL naming a defined *MATERIAL", "found ALU"}},
      {"MaterialWithoutElastic", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*DENSITY\n7850\n", "*MATERIAL, NAME=STEEL", "*MATERIAL", {"expected an *ELASTIC definition for material STEEL", "found none"}},
      {"MaterialWithDataLine", kModel + "*MATERIAL, NAME=X\n1.0\n", "1.0", "*MATERIAL", {"expected no data lines", "found '1.0'"}},
      {"MaterialDefinedTwice", kModel + "*MATERIAL, NAME=steel\n*ELASTIC\n1e9, 0.3\n", "*MATERIAL, NAME=steel", "*MATERIAL", {"expected a new material name", "found STEEL again"}},
      {"PoissonRatioHalf", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.5\n", "2.1e11, 0.5", "*ELASTIC", {"expected Poisson's ratio between -1 and 0.5", "found 0.5"}},
      {"PoissonRatioMinusOne", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, -1\n", "2.1e11, -1", "*ELASTIC", {"Poisson's ratio between -1 and 0.5", "found -1"}},
      {"YoungsModulusZero", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n0, 0.3\n", "0, 0.3", "*ELASTIC", {"expected Young's modulus E > 0", "found 0"}},
      {"YoungsModulusNegative", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n-2.1e11, 0.3\n", "-2.1e11, 0.3", "*ELASTIC", {"Young's modulus E > 0", "found -2"}},
      {"YoungsModulusText", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\nstiff, 0.3\n", "stiff, 0.3", "*ELASTIC", {"E, nu[, temperature] (a finite number)", "found 'stiff'"}},
      {"ElasticWithOneValue", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11\n", "2.1e11", "*ELASTIC", {"expected E, nu[, temperature] (2 to 3 values)", "found 1 values in '2.1e11'"}},
      {"ElasticWithoutDataLine", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n*DENSITY\n7850\n", "*ELASTIC", "*ELASTIC", {"expected one data line: E, nu", "found 0 data lines"}},
      {"ElasticWithTwoDataLines", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n2.0e11, 0.3\n", "*ELASTIC", "*ELASTIC", {"one data line: E, nu", "found 2 data lines"}},
      {"ElasticOrthotropic", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC, TYPE=ORTHO\n1, 2, 3, 4, 5, 6, 7, 8\n9\n", "*ELASTIC, TYPE=ORTHO", "*ELASTIC", {"expected TYPE=ISOTROPIC", "found TYPE=ORTHO"}},
      {"ElasticBeforeAnyMaterial", kMesh + kSection + "*ELASTIC, TYPE=ISO\n2.1e11, 0.3\n" + kSteel, "*ELASTIC, TYPE=ISO", "*ELASTIC", {"expected a *MATERIAL before *ELASTIC", "found none"}},
      {"ElasticAfterAnotherKeyword", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*NSET, NSET=X\n1\n*ELASTIC, TYPE=ISO\n2.1e11, 0.3\n", "*ELASTIC, TYPE=ISO", "*ELASTIC", {"a *MATERIAL before *ELASTIC"}},
      {"DensityBeforeAnyMaterial", kMesh + kSection + "*DENSITY\n7800\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n", "*DENSITY", "*DENSITY", {"expected a *MATERIAL before *DENSITY", "found none"}},
      {"NegativeDensity", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n-7850\n", "-7850", "*DENSITY", {"expected a density >= 0", "found -7850"}},
      {"DensityWithTwoDataLines", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n7850\n7800\n", "*DENSITY", "*DENSITY", {"expected one data line: density", "found 2 data lines"}},
      {"DensityWithThreeValues", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n7850, 20, 1\n", "7850, 20, 1", "*DENSITY", {"density[, temperature] (1 to 2 values)"}},
      // ---- *BOUNDARY and *CLOAD
      {"UndefinedNodeInBoundary", kModel + "*BOUNDARY\n9, 1, 3\n", "9, 1, 3", "*BOUNDARY", {"expected a node defined by *NODE", "found node 9"}},
      {"UndefinedSetInBoundary", kModel + "*BOUNDARY\nSUPPORT, ENCASTRE\n", "SUPPORT, ENCASTRE", "*BOUNDARY", {"expected a node number or a defined *NSET", "found 'SUPPORT'"}},
      {"ElementSetInBoundary", kModel + "*BOUNDARY\nFRAME, 1\n", "FRAME, 1", "*BOUNDARY", {"a node number or a defined *NSET", "found 'FRAME'"}},
      {"BoundaryDofZero", kModel + "*BOUNDARY\n1, 0\n", "1, 0", "*BOUNDARY", {"expected a degree of freedom 1-6", "found 0"}},
      {"BoundaryDofSeven", kModel + "*BOUNDARY\n1, 1, 7\n", "1, 1, 7", "*BOUNDARY", {"a degree of freedom 1-6", "found 7"}},
      {"BoundaryLastBeforeFirst", kModel + "*BOUNDARY\n1, 4, 2\n", "1, 4, 2", "*BOUNDARY", {"expected last DOF >= first DOF", "found '1, 4, 2'"}},
      {"BoundaryDofWord", kModel + "*BOUNDARY\n1, FIXED\n", "1, FIXED", "*BOUNDARY", {"expected a DOF number or ENCASTRE or PINNED", "found 'FIXED'"}},
      {"BoundaryEncastreWithMoreFields", kModel + "*BOUNDARY\n1, ENCASTRE, 3\n", "1, ENCASTRE, 3", "*BOUNDARY", {"expected node or set, ENCASTRE", "found '1, ENCASTRE, 3'"}},
      {"BoundaryOneField", kModel + "*BOUNDARY\n1\n", "1", "*BOUNDARY", {"expected node or set, first DOF[, last DOF[, value]]", "found '1'"}},
      {"BoundaryFiveFields", kModel + "*BOUNDARY\n1, 1, 1, 0, 0\n", "1, 1, 1, 0, 0", "*BOUNDARY", {"node or set, first DOF[, last DOF[, value]]"}},
      {"BoundaryValueText", kModel + "*BOUNDARY\n1, 1, 1, small\n", "1, 1, 1, small", "*BOUNDARY", {"a prescribed displacement (a finite number)", "found 'small'"}},
      {"UndefinedNodeInCload", kModel + "*CLOAD\n9, 2, 100.\n", "9, 2, 100.", "*CLOAD", {"found node 9"}},
      {"UndefinedSetInCload", kModel + "*CLOAD\nTIP, 2, 1.0\n", "TIP, 2, 1.0", "*CLOAD", {"a node number or a defined *NSET", "found 'TIP'"}},
      {"CloadDofSeven", kModel + "*CLOAD\n3, 7, 1.0\n", "3, 7, 1.0", "*CLOAD", {"a degree of freedom 1-6", "found 7"}},
      {"CloadDofText", kModel + "*CLOAD\n3, y, 1.0\n", "3, y, 1.0", "*CLOAD", {"a degree of freedom 1-6 (an integer)", "found 'y'"}},
      {"CloadTwoFields", kModel + "*CLOAD\n3, 2\n", "3, 2", "*CLOAD", {"expected node or set, DOF, magnitude", "found '3, 2'"}},
      {"CloadEmptyMagnitude", kModel + "*CLOAD\n3, 2, ,\n", "3, 2, ,", "*CLOAD", {"a load magnitude (a number)", "found an empty field"}},
      {"CloadMagnitudeNan", kModel + "*CLOAD\n3, 2, nan\n", "3, 2, nan", "*CLOAD", {"a load magnitude (a finite number)", "found 'nan'"}},
      // ---- *MASS, *ROTARY INERTIA, *SPRING
      {"MassOnBeamElement", kModel + "*MASS, ELSET=FRAME\n5.0\n", "*MASS, ELSET=FRAME", "*MASS", {"expected MASS elements in ELSET FRAME", "found element 1 of type B31"}},
      {"MassOnUndefinedElset", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PMX\n5.0\n", "*MASS, ELSET=PMX", "*MASS", {"expected ELSET naming a defined element set", "found PMX"}},
      {"RotaryInertiaOnMassElement", kModel + mass_at_node3() + "*ROTARY INERTIA, ELSET=PM\n1, 1, 1\n", "*ROTARY INERTIA, ELSET=PM", "*ROTARY INERTIA", {"expected ROTARYI elements in ELSET PM", "found element 10 of type MASS"}},
      {"SpringOnMassElement", kModel + mass_at_node3() + "*SPRING, ELSET=PM\n1\n1e3\n", "*SPRING, ELSET=PM", "*SPRING", {"expected SPRING elements in ELSET PM", "found element 10 of type MASS"}},
      {"MassElementWithoutMass", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n", "10, 3", "*ELEMENT", {"expected a *MASS, *ROTARY INERTIA or *SPRING for element 10 of type MASS", "found none"}},
      {"RotaryiElementWithoutInertia", kModel + "*ELEMENT, TYPE=ROTARYI\n11, 3\n", "11, 3", "*ELEMENT", {"for element 11 of type ROTARYI", "found none"}},
      {"SpringElementWithoutSpring", kModel + "*ELEMENT, TYPE=SPRING1\n12, 3\n", "12, 3", "*ELEMENT", {"for element 12 of type SPRING1"}},
      {"TwoMassesOnOneElement", kModel + mass_at_node3() + "*ELSET, ELSET=PM2\n10\n*MASS, ELSET=PM2\n6.0\n", "*MASS, ELSET=PM2", "*MASS", {"expected one property per element", "found element 10 twice"}},
      {"MassZero", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PM\n0\n", "0", "*MASS", {"expected a positive mass", "found 0"}},
      {"MassTwoValues", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PM\n5, 6\n", "5, 6", "*MASS", {"expected the mass (1 values)", "found 2 values"}},
      {"MassWithoutDataLine", kModel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PM\n", "*MASS, ELSET=PM", "*MASS", {"expected one data line: mass", "found 0 data lines"}},
      {"NegativeRotaryInertia", kModel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 3\n*ROTARY INERTIA, ELSET=RI\n1, 1, 1, 2, 0, 0\n", "*ROTARY INERTIA, ELSET=RI", "*ROTARY INERTIA", {"expected a positive semi-definite rotary inertia", "found a negative principal value"}},
      {"NegativeRotaryInertiaDiagonal", kModel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 3\n*ROTARY INERTIA, ELSET=RI\n-1, 1, 1\n", "*ROTARY INERTIA, ELSET=RI", "*ROTARY INERTIA", {"a negative principal value"}},
      {"RotaryInertiaTwoValues", kModel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 3\n*ROTARY INERTIA, ELSET=RI\n1, 1\n", "1, 1", "*ROTARY INERTIA", {"I11, I22, I33[, I12, I13, I23] (3 to 6 values)", "found 2 values"}},
      {"RotaryInertiaTwoDataLines", kModel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 3\n*ROTARY INERTIA, ELSET=RI\n1, 1, 1\n1, 1, 1\n", "*ROTARY INERTIA, ELSET=RI", "*ROTARY INERTIA", {"expected one data line: I11, I22, I33", "found 2 data lines"}},
      {"Spring2MixingTranslationAndRotation", kModel + "*ELEMENT, TYPE=SPRING2, ELSET=S\n10, 2, 3\n*SPRING, ELSET=S\n1, 4\n1e6\n", "*SPRING, ELSET=S", "*SPRING", {"expected two translations or two rotations", "found a translation and a rotation"}},
      {"Spring2WithOneDof", kModel + "*ELEMENT, TYPE=SPRING2, ELSET=S\n10, 2, 3\n*SPRING, ELSET=S\n1\n1e6\n", "*SPRING, ELSET=S", "*SPRING", {"expected two DOFs for SPRING2 elements", "found 1"}},
      {"Spring1WithTwoDofs", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n1, 2\n1e6\n", "*SPRING, ELSET=S", "*SPRING", {"expected one DOF for SPRING1 elements", "found 2"}},
      {"SpringWithThreeDofs", kModel + "*ELEMENT, TYPE=SPRING2, ELSET=S\n10, 2, 3\n*SPRING, ELSET=S\n1, 2, 3\n1e6\n", "1, 2, 3", "*SPRING", {"expected one DOF (SPRING1) or two (SPRING2)", "found '1, 2, 3'"}},
      {"SpringDofNine", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n9\n1e6\n", "9", "*SPRING", {"a degree of freedom 1-6", "found 9"}},
      {"SpringOneDataLine", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n1\n", "*SPRING, ELSET=S", "*SPRING", {"expected two data lines: the DOF(s), then the stiffness", "found 1 data lines"}},
      {"SpringStiffnessZero", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n1\n0\n", "0", "*SPRING", {"expected a positive stiffness", "found 0"}},
      {"SpringStiffnessText", kModel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n1\nstiff\n", "stiff", "*SPRING", {"the spring stiffness (a finite number)", "found 'stiff'"}},
      // ---- steps
      {"LoadBetweenSteps", kModel + "*STEP\n*STATIC\n*END STEP\n*CLOAD\n3, 2, 1\n*STEP\n*STATIC\n*END STEP\n", "*CLOAD", "*CLOAD", {"expected *CLOAD inside a *STEP", "found it between two steps"}},
      {"AmplitudeInTotalTime", "*AMPLITUDE, NAME=A1, TIME=TOTAL TIME\n0, 0, 1, 1\n" + kModel, "*AMPLITUDE, NAME=A1, TIME=TOTAL TIME", "*AMPLITUDE", {"expected TIME=STEP TIME", "found TIME=TOTAL TIME on *AMPLITUDE, NAME=A1"}},
      {"AmplitudeSmoothStep", "*AMPLITUDE, NAME=A1, DEFINITION=SMOOTH STEP\n0, 0, 1, 1\n" + kModel, "*AMPLITUDE, NAME=A1, DEFINITION=SMOOTH STEP", "*AMPLITUDE", {"expected DEFINITION=TABULAR", "found DEFINITION=SMOOTH STEP"}},
      {"AmplitudeOddCount", "*AMPLITUDE, NAME=A1\n0, 0, 1\n" + kModel, "0, 0, 1", "*AMPLITUDE", {"expected time, value pairs", "found 3 numbers (an odd count)"}},
      {"AmplitudeBackInTime", "*AMPLITUDE, NAME=A1\n0, 0, 1, 1, 0.5, 2\n" + kModel, "0, 0, 1, 1, 0.5, 2", "*AMPLITUDE", {"found *AMPLITUDE, NAME=A1 going back in time"}},
      {"AmplitudeUnknownName", kModel + "*STEP\n*DYNAMIC\n0.01, 0.1\n*CLOAD, AMPLITUDE=B\n3, 2, 1\n*END STEP\n", "3, 2, 1", "*CLOAD", {"AMPLITUDE= naming an *AMPLITUDE of the deck (it defines none)", "found AMPLITUDE=B"}},
      {"AmplitudeInAStaticStep", "*AMPLITUDE, NAME=A1\n0, 0, 1, 1\n" + kModel + "*STEP\n*STATIC\n*CLOAD, AMPLITUDE=A1\n3, 2, 1\n*END STEP\n", "*STEP", "*STEP", {"expected AMPLITUDE= on loads of *MODAL DYNAMIC and *DYNAMIC steps only", "found AMPLITUDE=A1 on a load of step 1 (*STATIC)"}},
      {"AmplitudeOnDload", kModel + "*STEP\n*DYNAMIC\n0.01, 0.1\n*DLOAD, AMPLITUDE=A1\nFRAME, PZ, 1\n*END STEP\n", "*DLOAD, AMPLITUDE=A1", "*DLOAD", {"expected a *DLOAD constant in its step", "found AMPLITUDE=A1"}},
      {"DynamicWithoutDataLine", kModel + "*STEP\n*DYNAMIC\n*END STEP\n", "*DYNAMIC", "*DYNAMIC", {"expected a data line: time increment, time period", "found none"}},
      {"DynamicIncrementLongerThanPeriod", kModel + "*STEP\n*DYNAMIC\n1, 0.5\n*END STEP\n", "1, 0.5", "*DYNAMIC", {"0 < increment <= period", "found '1, 0.5'"}},
      {"DynamicExplicit", kModel + "*STEP\n*DYNAMIC, EXPLICIT\n0.01, 0.1\n*END STEP\n", "*DYNAMIC, EXPLICIT", "*DYNAMIC", {"framedyn has no explicit integration", "found EXPLICIT"}},
      {"ModalDynamicSteadyState", kModel + "*STEP\n*MODAL DYNAMIC, STEADY STATE\n0.01, 0.1\n*END STEP\n", "*MODAL DYNAMIC, STEADY STATE", "*MODAL DYNAMIC", {"found STEADY STATE"}},
      {"ModalDampingInAStaticStep", kModel + "*STEP\n*STATIC\n*MODAL DAMPING\n1, 2, 0.02\n*END STEP\n", "*MODAL DAMPING", "*MODAL DAMPING", {"expected *MODAL DAMPING in a *MODAL DYNAMIC step", "found it in step 1 (*STATIC)"}},
      {"ModalDampingRatioOfOne", kModel + "*STEP\n*MODAL DYNAMIC\n0.01, 0.1\n*MODAL DAMPING\n1, 2, 1.0\n*END STEP\n", "1, 2, 1.0", "*MODAL DAMPING", {"a damping ratio 0 <= zeta < 1"}},
      {"SteadyStateDynamicsStepIsNamed", kModel + "*STEP\n*STATIC\n*END STEP\n*STEP\n*STEADY STATE DYNAMICS\n1, 100\n*END STEP\n", "*STEADY STATE DYNAMICS", "*STEADY STATE DYNAMICS", {"expected *STATIC, *FREQUENCY, *MODAL DYNAMIC or *DYNAMIC as the step's procedure", "found *STEADY STATE DYNAMICS in step 2"}},
      {"BoundaryOpNewOnALaterCardOfTheStep", kModel + "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 3\n*BOUNDARY, OP=NEW\n1, 1, 6\n*END STEP\n", "*BOUNDARY, OP=NEW", "*BOUNDARY",
       {"expected OP=NEW on the first *BOUNDARY of its step only", "found OP=NEW on *BOUNDARY card 2 of step 1"}},
      {"CloadOpUnknown", kModel + "*STEP\n*STATIC\n*CLOAD, OP=ADD\n3, 2, 1\n*END STEP\n", "*CLOAD, OP=ADD", "*CLOAD", {"expected OP=MOD or OP=NEW", "found OP=ADD"}},
      {"TwoProceduresInOneStep", kModel + "*STEP\n*STATIC\n*FREQUENCY\n5\n*END STEP\n", "*FREQUENCY", "*FREQUENCY", {"expected one procedure (*STATIC, *FREQUENCY, *MODAL DYNAMIC or *DYNAMIC) per *STEP", "found *STATIC and *FREQUENCY in step 1"}},
      {"StepInsideStep", kModel + "*STEP\n*STEP, NAME=INNER\n*END STEP\n", "*STEP, NAME=INNER", "*STEP", {"expected *END STEP before the next *STEP"}},
      {"StepWithoutEndStep", kModel + "*STEP, NAME=ONLY\n*STATIC\n*CLOAD\n3, 2, 1\n", "*STEP, NAME=ONLY", "*STEP", {"expected *END STEP at the end of the step", "found end of file"}},
      {"EndStepWithoutStep", kModel + "*END STEP\n", "*END STEP", "*END STEP", {"expected a *STEP before *END STEP"}},
      {"EndStepWithParameter", kModel + "*STEP\n*END STEP, NAME=X\n", "*END STEP, NAME=X", "*END STEP", {"expected no parameters", "found parameter NAME"}},
      {"StepWithUnknownParameter", kModel + "*STEP, UNSYMM=YES\n*STATIC\n*END STEP\n", "*STEP, UNSYMM=YES", "*STEP", {"one of the parameters NAME, PERTURBATION, NLGEOM, INC", "found parameter UNSYMM"}},
      {"StepWithNlgeom", kModel + "*STEP, NLGEOM\n*STATIC\n*END STEP\n", "*STEP, NLGEOM", "*STEP", {"expected a linear step (framedyn is a linear, small-displacement code", "found NLGEOM"}},
      {"StepWithNlgeomYes", kModel + "*STEP, NLGEOM=YES\n*STATIC\n*END STEP\n", "*STEP, NLGEOM=YES", "*STEP", {"expected a linear step", "found NLGEOM=YES"}},
      {"FrequencyOutsideStep", kModel + "*FREQUENCY\n10\n", "*FREQUENCY", "*FREQUENCY", {"expected *FREQUENCY inside a *STEP", "found it outside"}},
      {"StaticOutsideStep", kModel + "*STATIC\n", "*STATIC", "*STATIC", {"expected *STATIC inside a *STEP", "found it outside"}},
      {"FrequencyZeroModes", kModel + "*STEP\n*FREQUENCY\n0\n*END STEP\n", "0", "*FREQUENCY", {"expected at least 1 eigenvalue", "found 0"}},
      {"FrequencyModesText", kModel + "*STEP\n*FREQUENCY\nten\n*END STEP\n", "ten", "*FREQUENCY", {"the number of eigenvalues (an integer)", "found 'ten'"}},
      {"FrequencyUnknownParameter", kModel + "*STEP\n*FREQUENCY, NORMALIZATION=MASS\n5\n*END STEP\n", "*FREQUENCY, NORMALIZATION=MASS", "*FREQUENCY", {"SOLVER, STORAGE", "found parameter NORMALIZATION"}},
      {"StaticUnknownParameter", kModel + "*STEP\n*STATIC, DIRECT\n*END STEP\n", "*STATIC, DIRECT", "*STATIC", {"one of the parameters SOLVER", "found parameter DIRECT"}},
      // ---- values finite in the file whose SI values or element matrices are not (found by fuzz_inp_reader)
      {"SectionWhoseAreaOverflows", frame_with_section(kRectOnFrame + "RECT\n1e200, 1e200\n"), "1, 1, 2", "*ELEMENT", {"expected element stiffness and mass within the range of floating point", "found element 1: length 1 m", "A inf m^2", "(section of ELSET FRAME)"}},
      {"StiffnessBeyondTheRangeOfDouble", kMesh + kSection + "*MATERIAL, NAME=STEEL\n*ELASTIC\n1e307, 0.3\n", "1, 1, 2", "*ELEMENT", {"entries of at most 1e300 in SI units", "E 1e+307 Pa"}},
      {"ElementTooShortForItsStiffness", one_beam("*BEAM SECTION, ELSET=B, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.2\n", "1e-110, 0, 0"), "1, 1, 2", "*ELEMENT", {"within the range of floating point", "length 1e-110 m"}},
      {"MassThatOverflowsInSi", "** units: in-lbf-s\n" + kNodes + kBeams + kSection + kSteel + "*ELEMENT, TYPE=MASS, ELSET=PM\n10, 3\n*MASS, ELSET=PM\n1e307\n", "*MASS, ELSET=PM", "*MASS", {"expected a mass of magnitude at most 1e300 in SI units", "found 1e+307 (inf in SI units)"}},
      {"SpringThatOverflowsInSi", "** units: in-lbf-s\n" + kNodes + kBeams + kSection + kSteel + "*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 3\n*SPRING, ELSET=S\n1\n1e307\n", "*SPRING, ELSET=S", "*SPRING", {"expected a spring stiffness of magnitude at most 1e300 in SI units"}},
      {"RotaryInertiaThatOverflowsInSi", "** units: in-lbf-s\n" + kNodes + kBeams + kSection + kSteel + "*ELEMENT, TYPE=ROTARYI, ELSET=RI\n11, 3\n*ROTARY INERTIA, ELSET=RI\n1e308, 1, 1\n", "*ROTARY INERTIA, ELSET=RI", "*ROTARY INERTIA", {"expected a rotary inertia of magnitude at most 1e300 in SI units"}},
      {"LoadThatOverflowsInSi", "** units: in-lbf-s\n" + kNodes + kBeams + kSection + kSteel + "*STEP\n*STATIC\n*CLOAD\n3, 2, 1e308\n*END STEP\n", "3, 2, 1e308", "*CLOAD", {"expected a load of magnitude at most 1e300 in SI units", "found 1e+308 (inf in SI units)"}},
      // ---- units
      {"MissingUnits", kNodes, "", "units", {"expected a unit system: --units in-lbf-s|m-N-s|mm-N-s, or a line '** units: NAME'", "found neither"}},
      {"ConflictingUnitsOption", kModel, "** units: m-N-s", "** units:", {"expected the unit system given on the command line (in-lbf-s)", "found m-N-s"}, "in-lbf-s"},
      {"ConflictingUnitsComments", kModel + "** units: mm-N-s\n", "** units: mm-N-s", "** units:", {"expected the same unit system as deck.inp:1: ** units: (m-N-s)", "found mm-N-s"}},
      {"UnknownUnitsInComment", "** units: furlong-stone-fortnight\n" + kNodes, "** units: furlong-stone-fortnight", "** units:", {"expected in-lbf-s, m-N-s (or SI) or mm-N-s", "found 'furlong-stone-fortnight'"}},
      {"EmptyUnitsComment", "** units:\n" + kNodes, "** units:", "** units:", {"in-lbf-s, m-N-s (or SI) or mm-N-s", "found ''"}},
      {"UnknownUnitsOption", kNodes, "", "--units", {"expected in-lbf-s, m-N-s (or SI) or mm-N-s", "found 'feet'"}, "feet"},
      {"UnknownUnitsOptionWithComment", kModel, "", "--units", {"found 'ft-lbf-s'"}, "ft-lbf-s"},
      {"UnknownUnitsCommentWithOption", "** units: inch\n" + kNodes, "** units: inch", "** units:", {"found 'inch'"}, "in-lbf-s"},
  };
}

class InpReaderError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(InpReaderError, NamesFileLineAndKeyword) {
  const ErrorCase& c = GetParam();
  InpReadOptions o;
  o.units = c.units_option;
  const int line = line_of(c.deck, c.line);
  // Every message of the table says what was expected and what was found.
  std::vector<std::string> fragments = c.fragments;
  fragments.push_back(": expected ");
  fragments.push_back(", found ");
  EXPECT_TRUE(throws_input_error([&] { read(c.deck, o); }, kDeckName, line, c.key, fragments));
}

INSTANTIATE_TEST_SUITE_P(Deck, InpReaderError, ::testing::ValuesIn(error_cases()),
                         [](const ::testing::TestParamInfo<ErrorCase>& info) { return info.param.name; });

TEST(InpReaderErrors, CaseNamesAreUnique) {
  std::set<std::string> names;
  for (const ErrorCase& c : error_cases()) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

// ------------------------------------------------------------------ errors with files

TEST(InpReaderErrors, IncludeOfAMissingFile) {
  TempDir dir;
  const std::string text = kUnits + "*INCLUDE, INPUT=parts/missing.inp\n" + kNodes;
  EXPECT_TRUE(throws_input_error([&] { read_inp_text(text, "main.inp", dir.path()); }, "main.inp", 2, "*INCLUDE",
                                 {"cannot open", (dir.path() / "parts/missing.inp").string(), "(no such file)"}));
}

TEST(InpReaderErrors, IncludeOfADirectory) {
  TempDir dir;
  fs::create_directories(dir.path() / "parts");
  const std::string text = kUnits + "*INCLUDE, INPUT=parts\n" + kNodes;
  EXPECT_TRUE(throws_input_error([&] { read_inp_text(text, "main.inp", dir.path()); }, "main.inp", 2, "*INCLUDE",
                                 {"cannot open", (dir.path() / "parts").string(), "a directory"}));
  EXPECT_TRUE(throws_input_error([&] { read_inp(dir.path() / "parts"); }, (dir.path() / "parts").string(), 0, "", {"a directory"}));
}

TEST(InpReaderErrors, IncludeOfAFileThatExistsButCannotBeOpened) {
  // A UNIX socket exists but cannot be opened as a file (also for root, who
  // would read a file without read permission).
  TempDir dir;
  const fs::path sock = dir.path() / "socket.inp";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  ASSERT_LT(sock.string().size(), sizeof(addr.sun_path));
  std::strncpy(addr.sun_path, sock.c_str(), sizeof(addr.sun_path) - 1);
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)), 0);
  EXPECT_TRUE(throws_input_error([&] { read_inp_text(kUnits + "*INCLUDE, INPUT=socket.inp\n", "main.inp", dir.path()); }, "main.inp", 2,
                                 "*INCLUDE", {"cannot open " + sock.string(), "(permission?)"}));
  ::close(fd);
}

TEST(InpReaderErrors, MissingTopLevelFile) {
  TempDir dir;
  const fs::path p = dir.path() / "nothere.inp";
  EXPECT_TRUE(throws_input_error([&] { read_inp(p); }, p.string(), 0, "", {"cannot open", "(no such file)"}));
}

TEST(InpReaderErrors, IncludeCycle) {
  TempDir dir;
  const fs::path a = dir.write("a.inp", kUnits + "*INCLUDE, INPUT=sub/b.inp\n" + kNodes);
  const fs::path b = dir.write("sub/b.inp", "** b\n*INCLUDE, INPUT=../a.inp\n");
  EXPECT_TRUE(throws_input_error([&] { read_inp(a); }, b.string(), 2, "*INCLUDE", {"includes itself"}));
  // From text, the cycle is found one level later (the text itself is not a file).
  EXPECT_TRUE(throws_input_error([&] { read_inp_text("*INCLUDE, INPUT=a.inp\n", "text", dir.path()); }, b.string(), 2, "*INCLUDE",
                                 {"includes itself"}));
}

TEST(InpReaderErrors, IncludeOfItself) {
  TempDir dir;
  const fs::path a = dir.write("self.inp", kUnits + "*INCLUDE, INPUT=./self.inp\n");
  EXPECT_TRUE(throws_input_error([&] { read_inp(a); }, a.string(), 2, "*INCLUDE", {"the file", "includes itself"}));
}

TEST(InpReaderErrors, IncludeNestedTooDeep) {
  TempDir dir;
  for (int i = 0; i < 20; ++i) dir.write("f" + std::to_string(i) + ".inp", "*INCLUDE, INPUT=f" + std::to_string(i + 1) + ".inp\n");
  dir.write("f20.inp", kUnits + kNodes);
  EXPECT_NO_THROW(read_inp(dir.path() / "f4.inp"));  // 16 levels are fine
  // f0 -> f1 -> ... : the 18th file is refused at the *INCLUDE line of f16.
  EXPECT_TRUE(throws_input_error([&] { read_inp(dir.path() / "f0.inp"); }, (dir.path() / "f16.inp").string(), 1, "*INCLUDE",
                                 {"*INCLUDE nested more than 16 deep"}));
}

TEST(InpReaderErrors, IncludeWithoutInput) {
  EXPECT_TRUE(throws_input_error([&] { read(kUnits + "*INCLUDE\n"); }, kDeckName, 2, "*INCLUDE", {"expected INPUT=file name", "found no INPUT parameter"}));
  EXPECT_TRUE(throws_input_error([&] { read(kUnits + "*INCLUDE, INPUT=\n"); }, kDeckName, 2, "*INCLUDE", {"found no INPUT parameter"}));
}

TEST(InpReaderErrors, IncludeWithAnotherParameter) {
  EXPECT_TRUE(throws_input_error([&] { read(kUnits + "*INCLUDE, INPUT=a.inp, PASSWORD=x\n"); }, kDeckName, 2, "*INCLUDE",
                                 {"expected only the parameter INPUT", "found PASSWORD"}));
}

TEST(InpReaderErrors, KeywordThatStartsLikeInclude) {
  EXPECT_TRUE(throws_input_error([&] { read(kUnits + "*INCLUDES, INPUT=a.inp\n"); }, kDeckName, 2, "*INCLUDES",
                                 {"expected a known keyword", "found *INCLUDES"}));
}

TEST(InpReaderErrors, ErrorInAnIncludedFileNamesThatFile) {
  TempDir dir;
  const fs::path part = dir.write("part.inp", "** nodes\n*NODE\n1, 0, 0, 0\n2, x, 0, 0\n");
  EXPECT_TRUE(throws_input_error([&] { read_inp_text(kUnits + "*INCLUDE, INPUT=part.inp\n", "main.inp", dir.path()); }, part.string(), 4,
                                 "*NODE", {"found 'x'"}));
  // And a file's line numbers count its comment and blank lines.
  const fs::path main = dir.write("main.inp", kUnits + "\n** comment\n\n*NODE\n1, 0, 0, 0\n1, 1, 0, 0\n");
  EXPECT_TRUE(throws_input_error([&] { read_inp(main); }, main.string(), 7, "*NODE", {"node 1 again (first at " + main.string() + ":6: *NODE)"}));
}

TEST(InpReaderErrors, ConflictingUnitsInAnIncludedFile) {
  TempDir dir;
  const fs::path part = dir.write("part.inp", "** units: in-lbf-s\n");
  EXPECT_TRUE(throws_input_error([&] { read_inp_text(kUnits + kNodes + "*INCLUDE, INPUT=part.inp\n", "main.inp", dir.path()); },
                                 part.string(), 1, "** units:", {"the same unit system as main.inp:1: ** units: (m-N-s)", "found in-lbf-s"}));
}

TEST(InpReaderErrors, MissingUnitsNamesTheFile) {
  TempDir dir;
  const fs::path p = dir.write("nounits.inp", kNodes);
  EXPECT_TRUE(throws_input_error([&] { read_inp(p); }, p.string(), 0, "units", {"found neither"}));
  EXPECT_TRUE(throws_input_error([&] { read_inp_text("", "empty.inp", dir.path()); }, "empty.inp", 0, "units", {"found neither"}));
}

TEST(InpReaderErrors, InputErrorCarriesTheLocation) {
  try {
    read(kModel + "*BOUNDARY\n1, 9\n");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, kDeckName);
    EXPECT_EQ(e.where().line, line_of(kModel + "*BOUNDARY\n1, 9\n", "1, 9"));
    EXPECT_EQ(e.where().key, "*BOUNDARY");
    EXPECT_EQ(std::string(e.what()), "deck.inp:" + std::to_string(e.where().line) + ": *BOUNDARY: expected a degree of freedom 1-6, found 9");
  }
}

}  // namespace

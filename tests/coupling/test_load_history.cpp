// The load-history file: exact format, round trip, and every error the strict reader reports.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "coupling/load_history.h"
#include "tests/support/temp_dir.h"

namespace {

using framedyn::core::InputError;
using framedyn::core::UnitSystem;
using framedyn::coupling::LoadHistory;
using framedyn::coupling::parse_load_history;

const std::string kHeader1 =
    "time [s],P24_REEL.FX [lbf],P24_REEL.FY [lbf],P24_REEL.FZ [lbf],P24_REEL.MX [lbf*in],P24_REEL.MY [lbf*in],"
    "P24_REEL.MZ [lbf*in]";

std::string one_point_file(const std::string& rows) {
  return "# framedyn load history, version 1\n# units: in-lbf-s\n# point P24_REEL -25 0 0\n" + kHeader1 + "\n" + rows;
}

// Parses and returns the InputError's message ("" if none was thrown).
std::string error_of(const std::string& text) {
  try {
    parse_load_history(text, "loads.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

LoadHistory two_point_history() {
  LoadHistory h;
  h.times.resize(3);
  h.times << 0.0, 0.01, 0.02;
  for (int p = 0; p < 2; ++p) {
    framedyn::coupling::LoadPointHistory lp;
    lp.name = p == 0 ? "P24_REEL" : "P27_LEVELING_CYLINDER";
    lp.location = p == 0 ? Eigen::Vector3d(-0.635, 0.0, 0.0) : Eigen::Vector3d(1.7272, 0.381, 0.0);
    lp.values.resize(3, 6);
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 6; ++c) lp.values(k, c) = std::sin(1.0 + k + 7 * c + 50 * p) * (c < 3 ? 1e3 : 1e2) * 1.2345678901234;
    h.points.push_back(lp);
  }
  return h;
}

TEST(LoadHistoryFile, WriterProducesTheExactFormat) {
  LoadHistory h;
  h.times.resize(2);
  h.times << 0.0, 0.5;
  framedyn::coupling::LoadPointHistory lp;
  lp.name = "P24_REEL";
  const UnitSystem in = UnitSystem::from_name("in-lbf-s");
  lp.location = Eigen::Vector3d(in.to_si(-25, framedyn::core::Quantity::length), 0, 0);
  lp.values = Eigen::MatrixXd::Zero(2, 6);
  lp.values(1, 2) = in.to_si(100.0, framedyn::core::Quantity::force);
  lp.values(1, 4) = in.to_si(-2500.0, framedyn::core::Quantity::moment);
  h.points.push_back(lp);
  const std::string expected = one_point_file("0,0,0,0,0,0,0\n0.5,0,0,100,0,-2500,0\n");
  EXPECT_EQ(framedyn::coupling::format_load_history(h, in), expected);
}

TEST(LoadHistoryFile, RoundTripKeepsTenSignificantDigits) {
  const LoadHistory h = two_point_history();
  framedyn::testing::TempDir dir;
  for (const char* units : {"in-lbf-s", "m-N-s", "mm-N-s"}) {
    const auto path = dir / (std::string(units) + ".csv");
    framedyn::coupling::write_load_history(path, h, UnitSystem::from_name(units));
    const LoadHistory back = framedyn::coupling::read_load_history(path);
    ASSERT_EQ(back.points.size(), 2u);
    ASSERT_EQ(back.times.size(), 3);
    EXPECT_EQ(back.points[1].name, "P27_LEVELING_CYLINDER");
    // 10 significant digits in the file, then a unit conversion: relative error <= 5e-10 plus round-off.
    for (std::size_t p = 0; p < 2; ++p) {
      EXPECT_LE((back.points[p].location - h.points[p].location).norm(), 6e-10 * h.points[p].location.norm()) << units;
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 6; ++c)
          EXPECT_NEAR(back.points[p].values(k, c), h.points[p].values(k, c), 6e-10 * std::abs(h.points[p].values(k, c)))
              << units;
    }
    EXPECT_NEAR(back.times(1), 0.01, 1e-18);
    // A second round trip reproduces the file byte for byte.
    EXPECT_EQ(framedyn::coupling::format_load_history(back, UnitSystem::from_name(units)),
              framedyn::coupling::format_load_history(framedyn::coupling::parse_load_history(
                  framedyn::coupling::format_load_history(back, UnitSystem::from_name(units)), "x"), UnitSystem::from_name(units)));
  }
}

TEST(LoadHistoryFile, ComponentMatrixStacksPointsInFileOrder) {
  const LoadHistory h = two_point_history();
  const Eigen::MatrixXd m = h.component_matrix();
  ASSERT_EQ(m.rows(), 12);
  EXPECT_EQ(m(6 + 4, 2), h.points[1].values(2, 4));
  EXPECT_EQ(h.components_at(1), m.col(1));
}

TEST(LoadHistoryReader, ConvertsInchPoundToSi) {
  const LoadHistory h = parse_load_history(one_point_file("0,1,2,3,4,5,6\n"), "loads.csv");
  EXPECT_NEAR(h.points[0].location.x(), -25 * 0.0254, 1e-15);
  EXPECT_NEAR(h.points[0].values(0, 0), 4.4482216152605, 1e-13);
  EXPECT_NEAR(h.points[0].values(0, 3), 4 * 4.4482216152605 * 0.0254, 1e-13);
}

TEST(LoadHistoryReader, RejectsUnknownVersionWithLine) {
  const std::string e = error_of("# framedyn load history, version 2\n# units: in-lbf-s\n");
  EXPECT_NE(e.find("loads.csv:1"), std::string::npos) << e;
  EXPECT_NE(e.find("version 1"), std::string::npos) << e;
  EXPECT_NE(e.find("'2'"), std::string::npos) << e;
  EXPECT_NE(error_of("time [s],x\n").find("a framedyn load-history file"), std::string::npos);
}

TEST(LoadHistoryReader, RejectsUnknownUnitSystem) {
  const std::string e = error_of("# framedyn load history, version 1\n# units: furlong\n");
  EXPECT_NE(e.find("loads.csv:2: units"), std::string::npos) << e;
  EXPECT_NE(e.find("'furlong'"), std::string::npos) << e;
}

TEST(LoadHistoryReader, RejectsUnitLabelThatDisagreesWithHeader) {
  std::string text = one_point_file("0,1,2,3,4,5,6\n");
  text.replace(text.find("P24_REEL.FZ [lbf]"), 17, "P24_REEL.FZ [N]");
  const std::string e = error_of(text);
  EXPECT_NE(e.find("loads.csv:4: column 4 (P24_REEL.FZ)"), std::string::npos) << e;
  EXPECT_NE(e.find("[lbf]"), std::string::npos) << e;
  EXPECT_NE(e.find("in-lbf-s"), std::string::npos) << e;
  EXPECT_NE(e.find("'P24_REEL.FZ [N]'"), std::string::npos) << e;
}

TEST(LoadHistoryReader, RejectsMissingComponent) {
  std::string text = one_point_file("0,1,2,3,4,5\n");
  text.replace(text.find(",P24_REEL.MY [lbf*in]"), 21, "");
  const std::string e = error_of(text);
  EXPECT_NE(e.find("loads.csv:4: column 6"), std::string::npos) << e;
  EXPECT_NE(e.find("'P24_REEL.MY [lbf*in]'"), std::string::npos) << e;
  EXPECT_NE(e.find("missing component"), std::string::npos) << e;
  EXPECT_NE(e.find("'P24_REEL.MZ [lbf*in]'"), std::string::npos) << e;
  // The last component missing: the header ends early.
  std::string text2 = one_point_file("0,1,2,3,4,5\n");
  text2.replace(text2.find(",P24_REEL.MZ [lbf*in]"), 21, "");
  const std::string e2 = error_of(text2);
  EXPECT_NE(e2.find("column 7"), std::string::npos) << e2;
  EXPECT_NE(e2.find("the end of the header"), std::string::npos) << e2;
}

TEST(LoadHistoryReader, RejectsColumnOfUndeclaredPoint) {
  std::string text = one_point_file("0,1,2,3,4,5,6,7\n");
  text.replace(text.find("\n0,1"), 1, ",P99.FX [lbf]\n");
  const std::string e = error_of(text);
  EXPECT_NE(e.find("column 8"), std::string::npos) << e;
  EXPECT_NE(e.find("'P99.FX [lbf]'"), std::string::npos) << e;
}

TEST(LoadHistoryReader, RejectsNonIncreasingTime) {
  const std::string e = error_of(one_point_file("0,1,2,3,4,5,6\n0.1,1,2,3,4,5,6\n0.1,1,2,3,4,5,6\n"));
  EXPECT_NE(e.find("loads.csv:7: column 1 (time [s])"), std::string::npos) << e;
  EXPECT_NE(e.find("a time after 0.1 s"), std::string::npos) << e;
}

TEST(LoadHistoryReader, RejectsNanAndInfinity) {
  const std::string e = error_of(one_point_file("0,1,2,nan,4,5,6\n"));
  EXPECT_NE(e.find("loads.csv:5: column 4 (P24_REEL.FZ [lbf])"), std::string::npos) << e;
  EXPECT_NE(e.find("a finite number"), std::string::npos) << e;
  EXPECT_NE(e.find("'nan'"), std::string::npos) << e;
  const std::string e2 = error_of(one_point_file("0,1,2,3,4,5,-inf\n"));
  EXPECT_NE(e2.find("column 7 (P24_REEL.MZ [lbf*in])"), std::string::npos) << e2;
  const std::string e3 = error_of(one_point_file("0,1,2,3,4,5,1e999\n"));
  EXPECT_NE(e3.find("a number"), std::string::npos) << e3;
  const std::string e4 = error_of(one_point_file("0,1,2,x3,4,5,6\n"));
  EXPECT_NE(e4.find("expected a number, found 'x3'"), std::string::npos) << e4;
}

// Found by fuzz_load_history_reader: 1e308 lbf is finite but overflows to
// inf in newtons; 1.7976931348e308 is finite but rounds past the largest
// double when written back at 10 significant digits.
TEST(LoadHistoryReader, RejectsMagnitudesThatOverflowInSiOrWhenWritten) {
  const std::string e = error_of(one_point_file("0,1e308,2,3,4,5,6\n"));
  EXPECT_NE(e.find("loads.csv:5: column 2 (P24_REEL.FX [lbf])"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a number of magnitude at most 1e300, found '1e308'"), std::string::npos) << e;
  const std::string e2 = error_of(one_point_file("-1.7976931348e308,1,2,3,4,5,6\n"));
  EXPECT_NE(e2.find("loads.csv:5: column 1 (time [s])"), std::string::npos) << e2;
  const std::string e3 = error_of(
      "# framedyn load history, version 1\n# units: SI\n# point A 1 1.7976931348e308 3\n"
      "time [s],A.FX [N],A.FY [N],A.FZ [N],A.MX [N*m],A.MY [N*m],A.MZ [N*m]\n0,1,2,3,4,5,6\n");
  EXPECT_NE(e3.find("loads.csv:3: point A: expected a coordinate y of magnitude at most 1e300"), std::string::npos) << e3;
  EXPECT_EQ(error_of(one_point_file("0,2e299,2,3,4,5,-1e300\n")), "");  // 8.9e299 N, 1.1e299 N m
}

// Found by fuzz_load_history_reader with its dictionary (the round trip): a
// load within 1e300 in the file's units but not in SI (8e299 lbf is 3.6e300
// N) was accepted, and the same history written in SI was then refused. The
// limit holds in both; what is accepted writes back in SI and reads again.
TEST(LoadHistoryReader, RejectsMagnitudesBeyondTheLimitInSiAndWhatIsAcceptedRoundTrips) {
  const std::string e = error_of(one_point_file("0,1,2,-8e299,4,5,6\n"));  // -8e299 lbf x 4.44822 N/lbf
  EXPECT_NE(e.find("loads.csv:5: column 4 (P24_REEL.FZ [lbf]): expected a number of magnitude at most 1e300 in SI units, found '-8e299' (-3.55858e+300 N in SI units)"),
            std::string::npos)
      << e;
  const LoadHistory h = parse_load_history(one_point_file("0,1,2,-2.2e299,4,5,9e299\n"), "loads.csv");  // -9.8e299 N, 1.0e299 N m
  const std::string written = framedyn::coupling::format_load_history(h, UnitSystem::si());
  const LoadHistory again = parse_load_history(written, "again.csv");
  ASSERT_EQ(again.points.size(), 1u);
  EXPECT_NEAR(again.points[0].values(0, 2), h.points[0].values(0, 2), 1e-9 * std::abs(h.points[0].values(0, 2)));
  EXPECT_NEAR(again.points[0].values(0, 5), h.points[0].values(0, 5), 1e-9 * std::abs(h.points[0].values(0, 5)));
}

// Found by fuzz_load_history_reader (the round trip): -9.2e-308 lbf*in is
// -1.04e-308 N m in SI, below the smallest normal double; the writer wrote it
// and strtod reports the underflow as ERANGE, which the reader refused as "not
// a number". An underflow is a number: read as it is, and the round trip holds.
TEST(LoadHistoryReader, ReadsNumbersThatUnderflowToSubnormalsAndTheirRoundTrip) {
  const LoadHistory h = parse_load_history(one_point_file("0,1,2,3,-9.2e-308,5,1e-320\n"), "loads.csv");
  EXPECT_LT(std::abs(h.points[0].values(0, 3)), 2.2250738585072014e-308);  // subnormal in SI
  EXPECT_LT(h.points[0].values(0, 3), 0.0);
  const LoadHistory again = parse_load_history(framedyn::coupling::format_load_history(h, UnitSystem::si()), "again.csv");
  EXPECT_NEAR(again.points[0].values(0, 3), h.points[0].values(0, 3), 1e-9 * std::abs(h.points[0].values(0, 3)));
  EXPECT_EQ(error_of(one_point_file("0,1,2,3,4,5,1e999\n")).find("expected a number, found '1e999'") != std::string::npos, true);
}

// Found by fuzz_load_history_reader (the round trip): times that differ only
// past the 10th significant digit are one time in the written file.
TEST(LoadHistoryReader, RejectsTimesEqualToTenSignificantDigits) {
  const std::string e = error_of(one_point_file("1,1,2,3,4,5,6\n1.00000000001,1,2,3,4,5,6\n"));
  EXPECT_NE(e.find("loads.csv:6: column 1 (time [s])"), std::string::npos) << e;
  EXPECT_NE(e.find("differs from the previous one, 1 s, in the first 10 significant digits"), std::string::npos) << e;
  EXPECT_NE(e.find("found '1.00000000001'"), std::string::npos) << e;
  EXPECT_EQ(error_of(one_point_file("1,1,2,3,4,5,6\n1.000000001,1,2,3,4,5,6\n")), "");
}

TEST(LoadHistoryReader, RejectsRaggedRows) {
  const std::string e = error_of(one_point_file("0,1,2,3,4,5,6\n0.1,1,2,3,4,5\n"));
  EXPECT_NE(e.find("loads.csv:6"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 7 values (as the header), found 6 values"), std::string::npos) << e;
  const std::string e2 = error_of(one_point_file("0,1,2,3,4,5,6,7\n"));
  EXPECT_NE(e2.find("found 8 values"), std::string::npos) << e2;
}

TEST(LoadHistoryReader, RejectsFileWithoutPointsOrRows) {
  EXPECT_NE(error_of("# framedyn load history, version 1\n# units: SI\ntime [s]\n").find("at least one '# point"), std::string::npos);
  EXPECT_NE(error_of(one_point_file("")).find("at least one row"), std::string::npos);
  EXPECT_NE(error_of("# framedyn load history, version 1\n# units: SI\n# point A 1 2\n").find("three coordinates"),
            std::string::npos);
  EXPECT_NE(error_of("# framedyn load history, version 1\n# units: SI\n# point A 1 2 3\n# point A 1 2 3\n").find("declared once"),
            std::string::npos);
}

}  // namespace

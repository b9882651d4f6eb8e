// PNG line plots through gnuplot (report/plot.h): the image is a real PNG of the
// requested size, the same plot gives the same bytes, and bad plots or a
// missing or failing gnuplot are clear errors. Tests that draw are skipped
// only when gnuplot is absent (install-deps.sh installs gnuplot-nox).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.h"
#include "report/plot.h"
#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::uint32_t big_endian(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}

// One period of a sine in 101 points, with a second series: a legend of two.
report::LinePlot sine_plot() {
  report::LinePlot p;
  p.title = "Shaker force, one cycle (operator's test)";  // a quote in a title must survive gnuplot's quoting
  p.x_label = "time";
  p.x_unit = "s";
  p.y_label = "force";
  p.y_unit = "lbf";
  p.width = 640;
  p.height = 400;
  report::PlotSeries a{"horizontal_force", {}, {}}, b{"vertical force", {}, {}};
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 1833.0;
    a.x.push_back(t);
    a.y.push_back(26530 * std::cos(2 * M_PI * 18.33 * t));
    b.x.push_back(t);
    b.y.push_back(26530 * std::sin(2 * M_PI * 18.33 * t));
  }
  p.series = {a, b};
  return p;
}

#define SKIP_WITHOUT_GNUPLOT() \
  if (!report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)"

TEST(LinePlot, WritesAPngWithTheSignatureAndTheRequestedSize) {
  SKIP_WITHOUT_GNUPLOT();
  testing::TempDir dir("framedyn_test_plot");
  const fs::path png = dir / "sine.png";
  report::write_png(sine_plot(), png);
  const std::string bytes = read_bytes(png);
  ASSERT_GT(bytes.size(), 33u);
  // PNG signature (ISO/IEC 15948, 5.2), then the IHDR chunk: length 13, type, width, height.
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(big_endian(bytes, 8), 13u);
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(big_endian(bytes, 16), 640u);
  EXPECT_EQ(big_endian(bytes, 20), 400u);
  // Nothing left behind but the image.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(LinePlot, SamePlotTwiceGivesIdenticalBytes) {
  SKIP_WITHOUT_GNUPLOT();
  testing::TempDir dir("framedyn_test_plot");
  report::LinePlot p = sine_plot();
  p.mark_points = true;
  report::write_png(p, dir / "a.png");
  report::write_png(p, dir / "b.png");
  EXPECT_EQ(read_bytes(dir / "a.png"), read_bytes(dir / "b.png"));
}

TEST(LinePlot, SinglePointAndConstantSeriesAreDrawn) {
  // A sweep of one value, or a figure that does not change, is still a plot.
  SKIP_WITHOUT_GNUPLOT();
  testing::TempDir dir("framedyn_test_plot");
  report::LinePlot p = sine_plot();
  p.mark_points = true;
  p.series = {{"one value", {300.0}, {0.84}}, {"constant", {100, 200, 300}, {1.0, 1.0, 1.0}}};
  report::write_png(p, dir / "one.png");
  EXPECT_EQ(read_bytes(dir / "one.png").substr(1, 3), "PNG");
}

TEST(LinePlot, BadPlotsAreInputErrorsBeforeGnuplotRuns) {
  testing::TempDir dir("framedyn_test_plot");
  const fs::path png = dir / "bad.png";
  const auto expect_error = [&](const report::LinePlot& p, const std::string& expected) {
    try {
      report::write_png(p, png, "/nonexistent/gnuplot");  // never reached for a bad plot
      ADD_FAILURE() << "no error for: " << expected;
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(p.title), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(png));
  };
  report::LinePlot none = sine_plot();
  none.series.clear();
  expect_error(none, "at least one series");
  report::LinePlot empty = sine_plot();
  empty.series[1].x.clear();
  empty.series[1].y.clear();
  expect_error(empty, "an empty series");
  report::LinePlot ragged = sine_plot();
  ragged.series[0].y.pop_back();
  expect_error(ragged, "101 x and 100 y values");
  report::LinePlot nan = sine_plot();
  nan.series[0].y[7] = std::numeric_limits<double>::quiet_NaN();
  expect_error(nan, "finite values in series 'horizontal_force'");
  report::LinePlot tiny = sine_plot();
  tiny.width = 10;
  expect_error(tiny, "100 to 10000 pixels");
  report::LinePlot log = sine_plot();  // a sine crosses zero: no logarithmic y axis for it
  log.log_y = true;
  expect_error(log, "positive values on a logarithmic axis in series 'horizontal_force'");
}

TEST(LinePlot, LogarithmicAxesForSpectra) {
  report::LinePlot p = sine_plot();
  EXPECT_EQ(report::gnuplot_script(p, "/tmp/d.csv", "/tmp/p.png").find("\nset logscale"), std::string::npos);
  p.log_x = true;
  p.log_y = true;
  const std::string s = report::gnuplot_script(p, "/tmp/d.csv", "/tmp/p.png");
  EXPECT_NE(s.find("set logscale x"), std::string::npos) << s;
  EXPECT_NE(s.find("set logscale y"), std::string::npos) << s;
}

TEST(LinePlot, MissingGnuplotIsAClearError) {
  testing::TempDir dir("framedyn_test_plot");
  EXPECT_FALSE(report::gnuplot_available("/nonexistent/gnuplot"));
  try {
    report::write_png(sine_plot(), dir / "x.png", "/nonexistent/gnuplot");
    FAIL() << "no error without gnuplot";
  } catch (const report::PlotError& e) {
    EXPECT_NE(std::string(e.what()).find("gnuplot-nox"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(LinePlot, FailingGnuplotIsAClearError) {
  // `false` stands in for a gnuplot that rejects the script: exit status 1, no image.
  testing::TempDir dir("framedyn_test_plot");
  try {
    report::write_png(sine_plot(), dir / "x.png", "false");
    FAIL() << "no error from a failing gnuplot";
  } catch (const report::PlotError& e) {
    EXPECT_NE(std::string(e.what()).find("exit status 1"), std::string::npos) << e.what();
  }
}

TEST(LinePlot, ScriptLabelsBothAxesWithUnitsAndEveryLegend) {
  const std::string s = report::gnuplot_script(sine_plot(), "/tmp/d.csv", "/tmp/p.png");
  EXPECT_NE(s.find("set xlabel 'time [s]'"), std::string::npos) << s;
  EXPECT_NE(s.find("set ylabel 'force [lbf]'"), std::string::npos) << s;
  EXPECT_NE(s.find("set title 'Shaker force, one cycle (operator''s test)'"), std::string::npos) << s;
  EXPECT_NE(s.find("title 'horizontal_force'"), std::string::npos) << s;
  EXPECT_NE(s.find("title 'vertical force'"), std::string::npos) << s;
  EXPECT_NE(s.find("noenhanced"), std::string::npos) << "underscores in names must not become subscripts";
  EXPECT_EQ(s.find("time("), std::string::npos) << "no date in the picture";
}

}  // namespace
}  // namespace framedyn

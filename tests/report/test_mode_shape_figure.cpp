// Mode-shape figures (report/mode_shape_figure.h): the drawing scale makes a
// mode's largest translation a tenth of the model's size, whatever the
// shape's normalisation; the figure has three views per mode with equal axes,
// one segment per two-node member and two per three-node one; a frame seen
// edge on gets a range in lengths instead of round-off; the image is a PNG of
// the figure's size; `framedyn modes --figures` writes mode_shapes.png.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "fem/modal_analysis.h"
#include "report/mode_shape_figure.h"
#include "report/plot.h"
#include "tests/support/beam_meshes.h"
#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;

// A 2 m steel cantilever along X, clamped at X = 0, in 8 elements.
fem::FrameModel cantilever() {
  testing::StraightBeamSpec spec;
  spec.length = 2.0;
  spec.elements = 8;
  spec.material = testing::steel();
  spec.section = fem::rectangle_section(0.04, 0.06, 0.3);
  fem::FrameModel m = testing::straight_beam(spec);
  testing::clamp_node(m, 0);
  return m;
}

TEST(ModeShapeFigure, LargestTranslationIsATenthOfTheModelSizeWhateverTheNormalisation) {
  const fem::FrameModel m = cantilever();
  fem::ModalOptions mo;
  mo.mode_count = 3;
  const fem::ModalResult r = fem::compute_modes(m, mo);
  for (double factor : {1.0, 1e-6, 250.0}) {
    double scale = 0.0;
    const std::vector<Eigen::Vector3d> x = report::deformed_positions(m, factor * r.shapes.col(0), &scale);
    double largest = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) largest = std::max(largest, (x[i] - m.nodes[i].position).norm());
    EXPECT_NEAR(largest, 0.1 * 2.0, 1e-12) << "factor " << factor;  // the model is 2 m long
    // The first bending mode of a cantilever moves most at its free tip.
    EXPECT_NEAR((x.back() - m.nodes.back().position).norm(), largest, 1e-12);
  }
  // A shape with no translation (a pure twist) is drawn undeformed.
  Eigen::VectorXd twist = Eigen::VectorXd::Zero(m.dof_count());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) twist(fem::kDofsPerNode * static_cast<Eigen::Index>(i) + 3) = 1.0;
  double scale = 1.0;
  const std::vector<Eigen::Vector3d> same = report::deformed_positions(m, twist, &scale);
  EXPECT_EQ(scale, 0.0);
  for (std::size_t i = 0; i < same.size(); ++i) EXPECT_EQ(same[i], m.nodes[i].position);
}

TEST(ModeShapeFigure, ThreeEqualAxisViewsPerModeWithOneSegmentPerMember) {
  const fem::FrameModel m = cantilever();
  fem::ModalOptions mo;
  mo.mode_count = 5;
  const fem::ModalResult r = fem::compute_modes(m, mo);
  std::vector<double> hz;
  for (const fem::Mode& mode : r.modes) hz.push_back(mode.frequency_hz);
  const report::PanelFigure f = report::mode_shape_figure(m, r.shapes, hz, "cantilever", 4);
  ASSERT_EQ(f.rows, 4);
  ASSERT_EQ(f.columns, 3);
  ASSERT_EQ(f.panels.size(), 12u);
  EXPECT_NO_THROW(report::check_figure(f));
  for (const report::LinePlot& p : f.panels) {
    EXPECT_TRUE(p.equal_axes) << p.title;
    ASSERT_EQ(p.series.size(), 2u);
    for (const report::PlotSeries& s : p.series) {
      EXPECT_TRUE(s.segments);
      EXPECT_EQ(s.x.size(), 2 * m.beams.size()) << p.title;  // two points per member
    }
  }
  EXPECT_NE(f.panels[0].title.find(fmt::format("{:.4g} Hz", hz[0])), std::string::npos) << f.panels[0].title;
  // A straight beam along X seen from its end (Y-Z) is a point in the
  // undeformed state: the end view of a mode in one plane, and the plan or
  // side view of the other plane, are flat and get a range of a fifth of the
  // model size (2 m) either side of the drawing.
  int ranged = 0;
  for (const report::LinePlot& p : f.panels)
    for (const auto& range : {p.x_range, p.y_range})
      if (range) {
        EXPECT_NEAR((*range)[1] - (*range)[0], 2 * 0.2 * 2.0, 1e-12) << p.title;
        ++ranged;
      }
  EXPECT_GT(ranged, 0);
  const std::string script = report::gnuplot_script(f, "/tmp/d.csv", "/tmp/p.png");
  EXPECT_NE(script.find("set multiplot layout 4,3"), std::string::npos) << script;
  EXPECT_NE(script.find("set size ratio -1"), std::string::npos);
  EXPECT_NE(script.find("index 23 using 1:2"), std::string::npos) << "24 series, blocks 0 to 23";
}

TEST(ModeShapeFigure, ThreeNodeBeamsAreDrawnThroughTheirMidsideNode) {
  fem::FrameModel m = cantilever();
  // Make every element a three-node beam with its midside node at the middle.
  for (fem::BeamElement& b : m.beams) {
    b.node_m = testing::add_node(m, 0.5 * (m.nodes[static_cast<std::size_t>(b.node_a)].position + m.nodes[static_cast<std::size_t>(b.node_b)].position));
    b.theory = fem::BeamTheory::timoshenko;
  }
  Eigen::MatrixXd shape = Eigen::MatrixXd::Zero(m.dof_count(), 1);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) shape(fem::kDofsPerNode * static_cast<Eigen::Index>(i) + 2, 0) = m.nodes[i].position.x();
  const report::PanelFigure f = report::mode_shape_figure(m, shape, {10.0}, "three-node", 4);
  ASSERT_EQ(f.panels.size(), 3u);
  EXPECT_EQ(f.panels[1].series[1].x.size(), 4 * m.beams.size());
}

TEST(ModeShapeFigure, ModesCommandDrawsTheFigureAsAPngOfItsSize) {
  if (!report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  testing::TempDir dir("framedyn_test_mode_shape_figure");
  // The portal frame has no supports: six rigid-body modes, then four elastic ones to draw.
  const auto r = testing::framedyn(dir, "modes " + testing::quote((fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "portal_frame.inp").string()) +
                                            " --modes 10 --figures --out out -q");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(dir / "out" / "mode_shapes.png", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  auto big_endian = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  EXPECT_EQ(big_endian(16), 1500u);               // width
  EXPECT_EQ(big_endian(20), 4u * 330u);           // four modes, a row each
}

}  // namespace
}  // namespace framedyn

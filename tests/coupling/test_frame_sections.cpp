// Frame section dimensions as study keys (coupling/frame_sections.h; issue 19):
// a changed wall thickness gives the section, the modes and the frame mass the
// closed forms give for the new box, through a study, a batch design and the
// frame-model cache alike.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "batch/design.h"
#include "batch/engine.h"
#include "coupling/frame_model_cache.h"
#include "coupling/frame_sections.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "coupling/study_key_path.h"
#include "coupling/yaml_input.h"
#include "fem/modal_analysis.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using namespace framedyn;
using framedyn::testing::TempDir;

const fs::path kExamples = fs::path(FRAMEDYN_SOURCE_DIR) / "examples";
constexpr double kInch = 0.0254;

// A 2 m cantilever of a square steel box (a = b = 100 mm, walls 5 mm) along X,
// ten Euler-Bernoulli elements: its bending frequencies go as sqrt(E I / (rho A)).
std::string cantilever_mesh() {
  std::string text = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= 10; ++i) text += std::to_string(i + 1) + ", " + std::to_string(0.2 * i) + ", 0, 0\n";
  text += "*ELEMENT, TYPE=B33, ELSET=TUBE\n";
  for (int i = 1; i <= 10; ++i) text += std::to_string(i) + ", " + std::to_string(i) + ", " + std::to_string(i + 1) + "\n";
  text += "*BEAM SECTION, ELSET=TUBE, MATERIAL=STEEL, SECTION=BOX\n0.1, 0.1, 0.005, 0.005, 0.005, 0.005\n0, 0, -1\n"
          "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n*BOUNDARY\n1, ENCASTRE\n";
  return text;
}

coupling::SectionOverride walls(const std::string& set, const std::vector<std::pair<std::string, double>>& dims) {
  coupling::SectionOverride o;
  o.element_set = set;
  o.where = {"study.yaml", 0, "frame.sections." + set};
  for (const auto& [name, value] : dims) o.dimensions.push_back({name, value, {"study.yaml", 0, "frame.sections." + set + "." + name}});
  return o;
}

double first_frequency(const fem::FrameModel& model) {
  fem::ModalOptions o;
  o.mode_count = 2;
  return fem::compute_modes(model, o).modes.at(0).frequency_hz;
}

TEST(FrameSections, WallThicknessScalesTheBendingFrequencyAsTheSquareRootOfIOverA) {
  TempDir dir;
  coupling::FrameStudyRequest q;
  q.file = "study.yaml";
  q.mesh = dir.write("tube.inp", cantilever_mesh());
  q.supports = coupling::FrameSupports::mesh_boundary;
  const double f0 = first_frequency(coupling::read_frame_mesh(q));
  q.sections = {walls("tube", {{"t1", 0.008}, {"t2", 0.008}, {"t3", 0.008}, {"t4", 0.008}})};  // set names without regard to case
  const fem::FrameModel thick = coupling::read_frame_mesh(q);
  // Closed forms of the square box: A = a^2 - (a - 2t)^2, I = (a^4 - (a - 2t)^4) / 12.
  const auto area = [](double a, double t) { return a * a - std::pow(a - 2 * t, 2); };
  const auto inertia = [](double a, double t) { return (std::pow(a, 4) - std::pow(a - 2 * t, 4)) / 12.0; };
  ASSERT_EQ(thick.sections.size(), 1u);
  EXPECT_NEAR(thick.sections[0].properties.area / area(0.1, 0.008), 1.0, 1e-14);
  EXPECT_NEAR(thick.sections[0].properties.i11 / inertia(0.1, 0.008), 1.0, 1e-14);
  const double expected = std::sqrt((inertia(0.1, 0.008) / area(0.1, 0.008)) / (inertia(0.1, 0.005) / area(0.1, 0.005)));
  const double ratio = first_frequency(thick) / f0;
  RecordProperty("frequency_ratio_error", fmt::format("{:.3g}", ratio / expected - 1.0));
  EXPECT_NEAR(ratio, expected, 1e-9);
  EXPECT_LT(expected, 0.98);  // thicker walls bring the radius of gyration sqrt(I/A) in: 2.9 % lower, a change the check can see
}

TEST(FrameSections, OverrideRewritesOnlyTheSetsDataLine) {
  const std::string mesh = cantilever_mesh();
  const std::string out = coupling::apply_section_overrides(mesh, "tube.inp", {walls("TUBE", {{"t1", 0.0075}})}, core::UnitSystem::si());
  std::string expected = mesh;
  const std::string old_line = "0.1, 0.1, 0.005, 0.005, 0.005, 0.005\n";
  expected.replace(expected.find(old_line), old_line.size(), "0.1, 0.1, 0.0075, 0.005, 0.005, 0.005\n");
  EXPECT_EQ(out, expected);
}

// The offset-plowing pipeline's rails (BOX 6 x 3 in, walls 0.25 in): a thicker
// side wall t1 adds rho L dA to the vehicle model's frame structure, the mesh being
// its mass source, with dA = dt1 (b - t2 - t4) and L the rails' length.
TEST(FrameSections, RailWallChangesTheVehicleFrameMassByDensityTimesLengthTimesAreaChange) {
  const fs::path file = kExamples / "offset_plowing.yaml";
  const YAML::Node base = coupling::load_yaml_file(file.string());
  const auto structure_mass = [&](double t1) {
    YAML::Node doc = YAML::Clone(base);
    coupling::set_study_number(doc, "frame_response.sections.RAILS.t1", t1, file.string());
    const coupling::RigidStudy s = coupling::read_rigid_study(doc, file.string());
    for (const rigid::RigidPart3D& p : s.machine_3d().frame.parts)
      if (p.name == "frame_structure") return p.mass;
    ADD_FAILURE() << "no frame_structure part";
    return 0.0;
  };
  const coupling::RigidStudy s0 = coupling::read_rigid_study(base, file.string());
  const fem::FrameModel mesh = coupling::read_frame_mesh(*s0.frame_response);
  double length = 0.0, density = 0.0;
  for (int id : mesh.element_sets.at("RAILS")) {
    const fem::BeamElement& b = mesh.beams[static_cast<std::size_t>(mesh.beam_index(id))];
    length += (mesh.nodes[static_cast<std::size_t>(b.node_b)].position - mesh.nodes[static_cast<std::size_t>(b.node_a)].position).norm();
    density = mesh.sections[static_cast<std::size_t>(b.section)].material.density;
  }
  EXPECT_NEAR(length, 2 * 105 * kInch, 1e-12);  // both rails, X = -25 to 80 in
  const double m0 = structure_mass(0.25), m1 = structure_mass(0.3125);
  const double d_area = (0.3125 - 0.25) * (3.0 - 0.25 - 0.25) * kInch * kInch;
  RecordProperty("mass_change_error", fmt::format("{:.3g}", (m1 - m0) / (density * length * d_area) - 1.0));
  EXPECT_NEAR((m1 - m0) / (density * length * d_area), 1.0, 1e-10);
}

// A grid design over the rails' side wall (the pipeline cut to 0.05 s): the
// frame model's total mass (summary frame.total_mass) steps by
// rho L dA from run to run, and each worker builds one frame model per wall
// and reuses it for the other runs of that wall.
TEST(FrameSections, BatchGridOverRailWallStepsTheFrameMassByTheClosedFormAndBuildsOneModelPerWall) {
  TempDir dir;
  const fs::path study = kExamples / "offset_plowing.yaml";
  const fs::path design_file = dir.write("design.yaml", "framedyn_batch: 1\nstudy: " + study.string() +
                                                            "\nsampling: {method: grid}\nparameters:\n"
                                                            "  - {key: frame_response.sections.RAILS.t1, values: [0.25, 0.3125, 0.375]}\n"
                                                            "  - {key: soil.damping, values: [250, 300]}\n"
                                                            "  - {key: analysis.response.duration, values: [0.05]}\n"
                                                            "outputs: [frame.total_mass]\n");
  const batch::BatchDesign design = batch::read_batch_design(design_file.string());
  const std::vector<std::vector<double>> samples = batch::design_samples(design);
  ASSERT_EQ(samples.size(), 6u);
  coupling::FrameModelCache cache;
  std::vector<double> mass;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const batch::RunRecord row = batch::run_sample(design, i, samples[i], std::nullopt, &cache);
    ASSERT_TRUE(row.done) << row.message;
    ASSERT_EQ(row.outputs.size(), 1u);
    EXPECT_EQ(row.output_units[0], "lbf*s^2/in");
    mass.push_back(std::stod(row.outputs[0]));
    // The same row without the cache: reuse changes no number.
    if (i == 1 || i == 3) {
      EXPECT_EQ(batch::run_sample(design, i, samples[i]).outputs, row.outputs);
    }
  }
  EXPECT_EQ(cache.builds(), 3u);   // one per wall
  EXPECT_EQ(cache.reuses(), 3u);   // the second damping of each wall
  // rho in lbf*s^2/in^4 (the mesh's 0.2836 lb/in^3 steel over g = 386.09 in/s^2) from the mesh itself.
  const coupling::RigidStudy s = coupling::read_rigid_study(coupling::load_yaml_file(study.string()), study.string());
  const fem::FrameModel mesh = coupling::read_frame_mesh(*s.frame_response);
  const double density_in = mesh.sections[0].material.density / s.units.to_si_factor(core::Quantity::density);
  const double step = density_in * (2 * 105.0) * 0.0625 * (3.0 - 0.5);  // rho L dt1 (b - t2 - t4), lbf*s^2/in
  // Cells carry 10 significant digits: each mass (about 6.4) to 5e-10.
  EXPECT_EQ(mass[0], mass[1]);  // the soil does not change the frame
  EXPECT_NEAR(mass[2] - mass[0], step, 1e-9);
  EXPECT_NEAR(mass[4] - mass[2], step, 1e-9);
  EXPECT_GT(step, 1e-3);
}

TEST(FrameSections, CacheKeyTellsDialectsAndSectionValuesApart) {
  coupling::FrameStudyRequest q;
  q.file = "study.yaml";
  q.mesh = kExamples / ".." / "meshes" / "r100_frame.inp";
  const std::string plain = coupling::frame_build_key(q);
  q.inp_dialect = fem::InpDialect::calculix;
  const std::string calculix = coupling::frame_build_key(q);
  q.inp_dialect = fem::InpDialect::abaqus;
  const std::string abaqus = coupling::frame_build_key(q);
  q.sections = {walls("RAILS", {{"t1", 0.3125}})};
  const std::string thick = coupling::frame_build_key(q);
  q.sections = {walls("RAILS", {{"t1", 0.3125000000000001}})};
  const std::string thicker = coupling::frame_build_key(q);
  EXPECT_FALSE(plain.empty());
  EXPECT_NE(plain, calculix);
  EXPECT_NE(plain, abaqus);
  EXPECT_NE(calculix, abaqus);
  EXPECT_NE(abaqus, thick);
  EXPECT_NE(thick, thicker);
}

}  // namespace

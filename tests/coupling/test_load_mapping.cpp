// Load points onto the frame mesh: the nodal loads keep the resultant force
// and the moment about any point, whichever way the point is attached.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "coupling/load_mapping.h"
#include "fem/inp_reader.h"

namespace {

using framedyn::coupling::LoadPointLocation;

// Resultant force and moment about q of the nodal loads f (all DOFs).
Eigen::Matrix<double, 6, 1> resultant(const framedyn::fem::FrameModel& model, const Eigen::VectorXd& f, const Eigen::Vector3d& q) {
  Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const Eigen::Vector3d force = f.segment<3>(6 * static_cast<Eigen::Index>(i));
    r.head<3>() += force;
    r.tail<3>() += f.segment<3>(6 * static_cast<Eigen::Index>(i) + 3) + (model.nodes[i].position - q).cross(force);
  }
  return r;
}

Eigen::Matrix<double, 6, 1> point_resultant(const Eigen::Matrix<double, 6, 1>& p, const Eigen::Vector3d& at, const Eigen::Vector3d& q) {
  Eigen::Matrix<double, 6, 1> r;
  r.head<3>() = p.head<3>();
  r.tail<3>() = p.tail<3>() + (at - q).cross(Eigen::Vector3d(p.head<3>()));
  return r;
}

framedyn::fem::FrameModel r100() {
  return framedyn::fem::read_inp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
}

TEST(LoadMapping, PointOnItsNodeSetNodeIsAppliedAtThatNode) {
  const auto model = r100();
  const Eigen::Vector3d p(-25 * 0.0254, 0, 0);  // P24_REEL is node 45 at X = -25 in, Y = 0
  const auto map = framedyn::coupling::map_load_points(model, {{"P24_REEL", p}});
  ASSERT_TRUE(map.points[0].at_node);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(map.points[0].nodes[0])].id, 45);
  EXPECT_EQ(map.distribution.nonZeros(), 6);
}

// Every off-mesh way (spider to the set's nodes, spider to nearest nodes,
// a single-node rigid link, collinear nodes) keeps force and moment to round-off.
TEST(LoadMapping, OffsetPointsKeepResultantForceAndMomentAboutAnyPoint) {
  auto model = r100();
  // A three-node set on the front plate (collinear along Y) to exercise the collinear case.
  model.node_sets["FRONT_PLATE"] = {model.node_index(1), model.node_index(45), model.node_index(23)};
  model.node_sets["ONE_NODE"] = {model.node_index(50)};
  const std::vector<LoadPointLocation> points = {
      {"P24_REEL", Eigen::Vector3d(-0.70, 0.05, 0.30)},        // off its single node: rigid link
      {"FRONT_PLATE", Eigen::Vector3d(-0.70, 0.10, 0.25)},     // collinear spider
      {"CAB", Eigen::Vector3d(0.9, 0.2, 0.5)},                 // no set: 3 nearest nodes
      {"one_node", Eigen::Vector3d(1.80, 0.0, -0.2)},          // lower-case name, set of one node
  };
  const auto map = framedyn::coupling::map_load_points(model, points);
  EXPECT_FALSE(map.points[0].at_node);
  EXPECT_TRUE(map.points[1].from_node_set);
  EXPECT_FALSE(map.points[2].from_node_set);
  EXPECT_EQ(map.points[2].nodes.size(), 3u);
  for (std::size_t j = 0; j < points.size(); ++j) {
    Eigen::Matrix<double, 6, 1> p;
    p << 1234.5, -567.8, 910.1, 111.2, -222.3, 333.4;  // N, N m
    Eigen::VectorXd comps = Eigen::VectorXd::Zero(map.distribution.cols());
    comps.segment<6>(6 * static_cast<Eigen::Index>(j)) = p;
    const Eigen::VectorXd f = map.distribution * comps;
    for (const Eigen::Vector3d& q : std::vector<Eigen::Vector3d>{Eigen::Vector3d::Zero(), Eigen::Vector3d(3.0, -2.0, 1.0), points[j].location}) {
      const auto got = resultant(model, f, q), want = point_resultant(p, points[j].location, q);
      // Round-off: loads ~1e3 N with arms ~3 m; 1e-12 relative to |F| * 3 m.
      EXPECT_LE((got - want).cwiseAbs().maxCoeff(), 1e-12 * 3.0 * p.norm()) << points[j].name;
    }
  }
}

TEST(LoadMapping, SpiderOfNonCollinearNodesCarriesMomentAsForcesOnly) {
  const std::vector<Eigen::Vector3d> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2}};
  const Eigen::MatrixXd b = framedyn::coupling::spider_distribution(Eigen::Vector3d(0.3, 0.4, 0.5), x);
  for (int i = 0; i < 4; ++i) EXPECT_LE((b.block<3, 6>(6 * i + 3, 0).cwiseAbs().maxCoeff()), 1e-14);
}

TEST(LoadMapping, EmptyNodeSetIsAnInputError) {
  auto model = r100();
  model.node_sets["EMPTY"] = {};
  EXPECT_THROW(framedyn::coupling::map_load_points(model, {{"EMPTY", Eigen::Vector3d::Zero()}}), framedyn::core::InputError);
}

}  // namespace

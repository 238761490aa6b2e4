// The body builder on implicit shapes (ergo/body/layer_builder.h), checked against what is
// known without the code: the volume of a spherical shell and where its surfaces are.
#include <cmath>

#include <gtest/gtest.h>

#include "ergo/body/layer_builder.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOuter = 0.1, kCore = 0.07;  // m: a 3 cm layer on a 10 cm ball

ImplicitLayer SphericalShell(double outer, double core) {
  ImplicitLayer layer;
  layer.outer = [outer](const Eigen::Vector3d& p) { return p.norm() - outer; };
  layer.core = [core](const Eigen::Vector3d& p) { return p.norm() - core; };
  layer.bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.2 * outer),
                                     Eigen::Vector3d::Constant(1.2 * outer));
  return layer;
}

BuiltLayer BuildShell(double edge_length) {
  BuilderOptions options;
  options.edge_length = edge_length;
  return BuildLayerFromImplicit(SphericalShell(kOuter, kCore), options, "shell");
}

double ShellVolume() { return 4.0 / 3.0 * kPi * (std::pow(kOuter, 3) - std::pow(kCore, 3)); }

// Coarse h = 2 cm (~1.5k vertices) and fine h = 1 cm (~10k vertices, ~2 s).
TEST(Body, ImplicitShellVolumeConvergesToTheAnalyticVolume) {
  const double coarse = std::abs(BuildShell(0.02).report.layer_volume / ShellVolume() - 1);
  const BuiltLayer fine_layer = BuildShell(0.01);
  const double fine = std::abs(fine_layer.report.layer_volume / ShellVolume() - 1);
  EXPECT_LT(fine, 0.02);
  EXPECT_LT(fine, coarse);
  // The volume the report gives is the sum of the tets'.
  double volume = 0;
  const TetMesh& mesh = fine_layer.mesh;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::Vector3d p0 = mesh.vertices.row(mesh.tets(t, 0));
    volume += (Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 1))) - p0)
                  .dot((Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 2))) - p0)
                           .cross(Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 3))) - p0)) /
              6;
  }
  EXPECT_NEAR(fine_layer.report.layer_volume, volume, 1e-12);
}

TEST(Body, ImplicitShellAttachesExactlyTheCoreSurface) {
  const BuiltLayer layer = BuildShell(0.012);
  const TetMesh& mesh = layer.mesh;
  const double facet_distance = layer.report.facet_distance;
  ASSERT_EQ(layer.attached.size(), static_cast<size_t>(mesh.vertices.rows()));
  // Mesh_3 puts surface vertices on the surface by bisection (to relative_error_bound =
  // 1e-5 of the bounding sphere radius, 2.1e-6 m here); perturbation moves them along it.
  // The facet distance (1.2 mm) is the bound asked for; the 1e-9 m slack covers rounding.
  const double bisection = 1e-5 * 0.12 * std::sqrt(3.0);
  const TetBoundary boundary = ExtractBoundary(mesh);
  std::vector<bool> on_boundary(mesh.vertices.rows(), false);
  for (Eigen::Index s = 0; s < boundary.surface_to_tet.size(); ++s)
    on_boundary[boundary.surface_to_tet[s]] = true;
  int attached = 0, skin = 0;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const double radius = mesh.vertices.row(v).norm();
    if (layer.attached[v]) {
      ++attached;
      EXPECT_LE(std::abs(radius - kCore), facet_distance + 1e-9) << "vertex " << v;
      EXPECT_LE(std::abs(radius - kCore), bisection);
    } else if (on_boundary[v]) {
      ++skin;  // a boundary vertex that is not attached is on the skin
      EXPECT_LE(std::abs(radius - kOuter), bisection) << "vertex " << v;
    } else {
      EXPECT_GT(radius, kCore - 1e-9);
      EXPECT_LT(radius, kOuter + 1e-9);
    }
  }
  EXPECT_EQ(attached, layer.report.attached_vertex_count);
  EXPECT_EQ(skin, layer.report.skin_vertex_count);
  EXPECT_GT(attached, 100);
  EXPECT_EQ(layer.report.core_components, 1);
  EXPECT_EQ(layer.report.skin_components, 1);
  EXPECT_LE(layer.report.max_attached_offset, bisection);
  // The measured thickness is the 3 cm between the spheres (up to the facets' sag).
  EXPECT_NEAR(layer.report.min_thickness, kOuter - kCore, facet_distance);
  // Depth field: measured from each vertex's nearest skin point.
  EXPECT_NEAR(layer.vertex_depth.minCoeff(), kOuter - kCore, 2 * facet_distance);
  EXPECT_NEAR(layer.vertex_depth.maxCoeff(), kOuter - kCore, 2 * facet_distance);
}

TEST(Body, ImplicitShellTetsArePositiveAndOfSaneQuality) {
  const BuiltLayer layer = BuildShell(0.015);
  const TetQuality& q = layer.report.quality;
  EXPECT_EQ(q.non_positive_count, 0);
  EXPECT_GT(q.min_volume, 0);
  // Perturbation targets 15°; Mesh_3's radius-edge bound 2 keeps the rest well shaped.
  EXPECT_GT(q.min_dihedral_degrees, 10);
  EXPECT_LT(q.max_dihedral_degrees, 170);
  EXPECT_GT(q.min_radius_ratio, 0.1);
  EXPECT_GT(q.mean_radius_ratio, 0.7);
  // Edges come out at most about the target.
  EXPECT_LT(q.mean_edge_length, 0.015);
  EXPECT_GT(q.mean_edge_length, 0.5 * 0.015);
  // Same seed, same mesh.
  const BuiltLayer again = BuildShell(0.015);
  EXPECT_EQ(again.mesh.vertices, layer.mesh.vertices);
  EXPECT_EQ(again.mesh.tets, layer.mesh.tets);
}

TEST(Body, ImplicitBuilderRefusesBadShapes) {
  BuilderOptions options;
  options.edge_length = 0.02;
  // Core poking out of the body.
  ImplicitLayer off_centre = SphericalShell(kOuter, kCore);
  off_centre.core = [](const Eigen::Vector3d& p) {
    return (p - Eigen::Vector3d(0.06, 0, 0)).norm() - 0.07;
  };
  try {
    BuildLayerFromImplicit(off_centre, options, "offset core");
    FAIL() << "a core outside the body was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "offset core");
    EXPECT_NE(error.problem().find("not inside"), std::string::npos) << error.what();
  }
  // No layer: the core fills the body.
  EXPECT_THROW(BuildLayerFromImplicit(SphericalShell(kOuter, kOuter), options, "full"), InputError);
  // No core.
  ImplicitLayer no_core = SphericalShell(kOuter, kCore);
  no_core.core = [](const Eigen::Vector3d&) { return 1.0; };
  EXPECT_THROW(BuildLayerFromImplicit(no_core, options, "no core"), InputError);
  // A layer 4 mm thick at an edge length of 2 cm.
  EXPECT_THROW(BuildLayerFromImplicit(SphericalShell(kOuter, kOuter - 0.004), options, "thin"),
               InputError);
  // Bad options.
  options.edge_length = 0;
  EXPECT_THROW(BuildLayerFromImplicit(SphericalShell(kOuter, kCore), options, "h"), InputError);
  options.edge_length = 1e-5;  // billions of tets
  EXPECT_THROW(BuildLayerFromImplicit(SphericalShell(kOuter, kCore), options, "h"), InputError);
}

}  // namespace
}  // namespace ergo

// The body builder on a user's skin surface with depth and stiffness samples
// (ergo/body/layer_builder.h): an icosphere whose core must come out as the concentric
// sphere, interpolated depths that honour the samples, an open scan that gets capped.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/layer_builder.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.1;  // m

// Coarse enough to run in a few seconds: icosphere with 1280 triangles (edges ~1.5 cm),
// target tet edge 1.5 cm.
BuilderOptions Options() {
  BuilderOptions options;
  options.edge_length = 0.015;
  return options;
}

TriMesh Skin() { return MakeIcosphere(kRadius, 3); }

// Six depth samples on the axes' poles of the sphere: 1.5 to 4 cm.
PointSamples PoleSamples(const double (&values)[6]) {
  PointSamples samples;
  samples.points.resize(6, 3);
  samples.values.resize(6);
  for (int i = 0; i < 6; ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p[i / 2] = i % 2 ? -kRadius : kRadius;
    samples.points.row(i) = p.transpose();
    samples.values[i] = values[i];
  }
  samples.source = "poles";
  return samples;
}

TEST(Body, SurfaceWithConstantDepthHasAConcentricSphericalCore) {
  const double depth = 0.03;
  const BuiltLayer layer =
      BuildLayerFromSurface(Skin(), SampleInterpolant::Constant(depth), Options(), "icosphere");
  // The core is the set of points deeper than 3 cm below the (faceted) skin: the layer's
  // volume is the skin's volume minus a ball of radius ≈ R − depth. The icosphere's facets
  // sag by up to ~1 mm, so allow 3 %.
  const double core_radius = kRadius - depth;
  const double expected = EnclosedVolume(Skin()) - 4.0 / 3.0 * kPi * std::pow(core_radius, 3);
  EXPECT_NEAR(layer.report.layer_volume / expected, 1.0, 0.03);
  int attached = 0;
  for (Eigen::Index v = 0; v < layer.mesh.vertices.rows(); ++v) {
    if (!layer.attached[v]) continue;
    ++attached;
    // Deeper than R − depth below a facet's plane means at most R − depth from the centre,
    // and at least R·cos(facet half-angle) − depth; 1.5 mm covers both here.
    EXPECT_NEAR(layer.mesh.vertices.row(v).norm(), core_radius, 1.5e-3);
  }
  EXPECT_GT(attached, 50);
  EXPECT_EQ(layer.report.core_components, 1);
  EXPECT_TRUE(layer.report.notes.empty()) << layer.report.notes.front();
  EXPECT_EQ(layer.report.quality.non_positive_count, 0);
  EXPECT_NEAR(layer.vertex_depth.minCoeff(), depth, 1e-15);
  EXPECT_NEAR(layer.vertex_depth.maxCoeff(), depth, 1e-15);
}

TEST(Body, SurfaceWithDepthSamplesFollowsTheInterpolatedDepth) {
  if (testing::SanitizedBuild())
    GTEST_SKIP() << "two minutes of Mesh_3 under the sanitizers; Body.SurfaceWithConstantDepth* "
                    "runs the same builder";
  const double values[6] = {0.015, 0.04, 0.02, 0.035, 0.025, 0.03};
  const PointSamples samples = PoleSamples(values);
  const SampleInterpolant depth = SampleInterpolant::Fit(samples);
  // Exact at the samples (the interpolant evaluated where it was measured).
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(depth(samples.points.row(i).transpose()), values[i], 1e-10 * values[i]);
  }
  const BuiltLayer layer = BuildLayerFromSurface(Skin(), depth, Options(), "icosphere");
  // Each attached vertex is depth(π(p)) below the skin, π(p) its nearest skin point: it
  // lies on the core surface {d(p) = depth(π(p))} up to the bisection accuracy
  // (1e-5 × bounding radius ≈ 2e-6 m) — except where π jumps from one facet to the next
  // (on the skin's medial axis), where the core surface has a step of about
  // |∇depth| · 2·depth·sin(θ/2), θ ≈ 10° between neighbouring facets here: < 1 mm. Such
  // vertices are few; all are within the facet distance.
  const SurfaceDistance skin(Skin());
  double worst = 0;
  int off_surface = 0;
  for (Eigen::Index v = 0; v < layer.mesh.vertices.rows(); ++v) {
    if (!layer.attached[v]) continue;
    const SurfaceDistance::Closest closest = skin.Nearest(layer.mesh.vertices.row(v).transpose());
    const double offset = std::abs(closest.distance - depth(closest.point));
    worst = std::max(worst, offset);
    if (offset > 3e-6) ++off_surface;
  }
  EXPECT_LT(worst, layer.report.facet_distance);
  EXPECT_LT(off_surface, layer.report.attached_vertex_count / 20);
  EXPECT_NEAR(layer.report.max_attached_offset, worst, 0.1 * worst + 1e-6);
  // At the mesh vertex nearest each pole the depth field is about that pole's sample (the
  // spline's slope is below 0.3 there and the vertex within a few mm of the pole).
  for (int i = 0; i < 6; ++i) {
    Eigen::Index nearest = 0;
    const double offset =
        (layer.mesh.vertices.rowwise() - samples.points.row(i)).rowwise().norm().minCoeff(&nearest);
    EXPECT_LT(offset, 0.01);
    EXPECT_NEAR(layer.vertex_depth[nearest], values[i], 0.3 * offset + 1e-12) << i;
  }
  EXPECT_NEAR(layer.report.min_thickness, 0.015, 2e-3);
  EXPECT_GE(layer.vertex_depth.minCoeff(), 0.015);
  EXPECT_LE(layer.vertex_depth.maxCoeff(), 0.04);
}

TEST(Body, StiffnessSamplesGiveEachTetItsColumnsValue) {
  if (testing::SanitizedBuild())
    GTEST_SKIP() << "a minute and a half of Mesh_3 under the sanitizers; "
                    "Body.SurfaceWithConstantDepth* runs the same builder";
  const BuiltLayer layer =
      BuildLayerFromSurface(Skin(), SampleInterpolant::Constant(0.03), Options(), "icosphere");
  const double values[6] = {5e3, 15e3, 8e3, 12e3, 10e3, 6e3};
  const PointSamples samples = PoleSamples(values);
  const SampleInterpolant stiffness = SampleInterpolant::Fit(samples);
  const Eigen::VectorXd E = InterpolateOntoTets(layer, stiffness);
  ASSERT_EQ(E.size(), layer.mesh.tets.rows());
  EXPECT_GE(E.minCoeff(), 5e3);
  EXPECT_LE(E.maxCoeff(), 15e3);
  // The tet right under each sample (the nearest centroid to the pole, at most ~1 edge
  // length away on the skin) has about the sample's value: the spline's slope is about
  // (15−5) kPa over the 0.14 m between poles, so within 1.5 kPa.
  for (int i = 0; i < 6; ++i) {
    Eigen::Index best = 0;
    double best_distance = 1e9;
    for (Eigen::Index t = 0; t < layer.mesh.tets.rows(); ++t) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
        centroid += layer.mesh.vertices.row(layer.mesh.tets(t, k)).transpose() / 4;
      const double d = (centroid - samples.points.row(i).transpose()).norm();
      if (d < best_distance) {
        best_distance = d;
        best = t;
      }
    }
    EXPECT_NEAR(E[best], values[i], 1.5e3) << "sample " << i;
  }
}

TEST(Body, OpenScanIsCappedAndBuilt) {
  // A scan that ends in a cut: the icosphere without its triangles above z = 0.06.
  const TriMesh sphere = Skin();
  TriMesh scan;
  scan.vertices = sphere.vertices;
  std::vector<Eigen::Vector3i> kept;
  for (Eigen::Index f = 0; f < sphere.triangles.rows(); ++f) {
    double z = 0;
    for (int k = 0; k < 3; ++k) z += sphere.vertices(sphere.triangles(f, k), 2) / 3;
    if (z < 0.06) kept.push_back(sphere.triangles.row(f).transpose());
  }
  // Drop the vertices no triangle uses any more.
  std::vector<int> id(sphere.vertices.rows(), -1);
  int count = 0;
  for (const auto& f : kept)
    for (int k = 0; k < 3; ++k)
      if (id[f[k]] < 0) id[f[k]] = count++;
  scan.vertices.resize(count, 3);
  for (Eigen::Index v = 0; v < sphere.vertices.rows(); ++v)
    if (id[v] >= 0) scan.vertices.row(id[v]) = sphere.vertices.row(v);
  scan.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f)
    for (int k = 0; k < 3; ++k) scan.triangles(f, k) = id[kept[f][k]];

  const BuiltLayer layer =
      BuildLayerFromSurface(scan, SampleInterpolant::Constant(0.025), Options(), "scan.obj");
  ASSERT_FALSE(layer.report.notes.empty());
  EXPECT_NE(layer.report.notes.front().find("cap"), std::string::npos)
      << layer.report.notes.front();
  EXPECT_EQ(layer.report.core_components, 1);
  EXPECT_GT(layer.report.attached_vertex_count, 20);
  // Nothing of the body is above the cut (up to the facet distance).
  EXPECT_LT(layer.mesh.vertices.col(2).maxCoeff(), 0.06 + 0.01);
}

TEST(Body, SurfaceBuilderRefusesImpossibleInput) {
  // Depth beyond the middle of the body: the core vanishes.
  try {
    BuildLayerFromSurface(Skin(), SampleInterpolant::Constant(0.11), Options(), "ball.stl");
    FAIL() << "a vanished core was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "ball.stl");
    EXPECT_NE(error.problem().find("vanishes"), std::string::npos) << error.what();
  }
  // A layer thinner than an edge length.
  try {
    BuildLayerFromSurface(Skin(), SampleInterpolant::Constant(0.005), Options(), "ball.stl");
    FAIL() << "a 5 mm layer at 15 mm edges was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "depth");
  }
  // Two overlapping balls in one file: self-intersecting.
  TriMesh twin = Skin();
  const TriMesh other = MakeIcosphere(kRadius, 3, Eigen::Vector3d(0.05, 0, 0));
  const Eigen::Index n = twin.vertices.rows(), f = twin.triangles.rows();
  twin.vertices.conservativeResize(2 * n, 3);
  twin.vertices.bottomRows(n) = other.vertices;
  twin.triangles.conservativeResize(2 * f, 3);
  twin.triangles.bottomRows(f) = other.triangles.array() + static_cast<int>(n);
  try {
    BuildLayerFromSurface(twin, SampleInterpolant::Constant(0.03), Options(), "twin.off");
    FAIL() << "a self-intersecting surface was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "twin.off");
    EXPECT_NE(error.problem().find("intersect"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ergo

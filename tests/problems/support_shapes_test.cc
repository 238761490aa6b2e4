// The generated supports' geometry: the bevelled block (chair, sole) and the Boolean
// operations behind the mouse and the negative images.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "problems/mesh_booleans.h"
#include "problems/profile_block.h"
#include "tests/problems/scenario_checks.h"

namespace ergo {
namespace {

// A Boolean's raw result: closed, manifold, outward, no self-intersection; zero-area
// triangles along the cut are expected (they are remeshed before use).
void ExpectClosedManifold(const TriMesh& mesh, const std::string& name) {
  MeshCheckOptions options;
  options.require_closed = true;
  const MeshCheckReport report = CheckTriMesh(mesh, name, options);
  for (const MeshIssue& issue : report.issues) {
    if (issue.code == "degenerate-triangles") continue;
    EXPECT_EQ(issue.severity, Severity::kNote) << report.FullReport();
    EXPECT_NE(issue.code, "self-intersection-not-checked") << report.FullReport();
  }
}

TEST(Problems, BevelledBlockIsClosedWithTheArcsVolume) {
  ProfileBlock block;  // the chair's: 0.5 × 0.2 × 0.5 m, 6 cm arc
  block.top_spacing = 0.01;
  const TriMesh mesh = MakeProfileBlock(block);
  ExpectValidSupport(mesh, "block");
  // Box minus the corner the quarter arc removes: r²(1 − π/4) per unit width (the arc's ten
  // chords cut off r²/2 (θ − sin θ) each, θ ≈ 9°: 1.3e-4 relative at this spacing).
  const double r = block.front_radius;
  const double exact = block.width * (0.2 * 0.5 - r * r * (1 - M_PI / 4));
  EXPECT_NEAR(EnclosedVolume(mesh) / exact, 1.0, 3e-4);
  // The top is a grid of the spacing; the designed rule takes the top and the arc only.
  int top = 0, designed = 0;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
    if (!OnProfileBlockTop(block, p)) continue;
    ++designed;
    top += std::abs(p.y()) < 1e-12;
    // On the flat top or on the arc.
    const Eigen::Vector2d axis(block.front_z - r, -r);
    const bool on_arc = std::abs((Eigen::Vector2d(p.z(), p.y()) - axis).norm() - r) < 1e-12;
    EXPECT_TRUE(std::abs(p.y()) < 1e-12 || on_arc) << p.transpose();
  }
  const int columns = static_cast<int>(std::ceil(block.width / block.top_spacing)) - 1;
  EXPECT_EQ(designed % columns, 0);
  EXPECT_GT(top, 0.8 * designed);
  // A flat block (the sole) is a box.
  ProfileBlock sole{0.11, -0.14, 0.14, -0.02, 0, 0, 0.005, 0.01};
  const TriMesh slab = MakeProfileBlock(sole);
  ExpectValidSupport(slab, "sole");
  EXPECT_NEAR(EnclosedVolume(slab), 0.11 * 0.28 * 0.02, 1e-12);
  sole.front_radius = 0.03;  // taller than the slab
  EXPECT_THROW(MakeProfileBlock(sole), InputError);
}

TEST(Problems, UnionAndDifferenceOfClosedSurfacesHaveTheAnalyticVolume) {
  // Two unit-ish spheres overlapping: V = V1 + V2 − lens.
  const double r1 = 0.05, r2 = 0.04, d = 0.06;
  const TriMesh a = MakeIcosphere(r1, 5);
  const TriMesh b = MakeIcosphere(r2, 5, Eigen::Vector3d(d, 0, 0));
  const BooleanResult joined = MeshUnion(a, b, "spheres");
  ExpectClosedManifold(joined.mesh, "union");
  const double lens = M_PI * std::pow(r1 + r2 - d, 2) *
                      (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) /
                      (12 * d);
  const double exact = 4.0 / 3.0 * M_PI * (std::pow(r1, 3) + std::pow(r2, 3)) - lens;
  // The icospheres' facets lose ~0.2 % of the volume.
  EXPECT_NEAR(EnclosedVolume(joined.mesh) / exact, 1.0, 5e-3);
  // The cut is the circle where the spheres meet: x = (d² + r1² − r2²) / 2d.
  ASSERT_FALSE(joined.cut.empty());
  const double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);
  for (const auto& segment : joined.cut) EXPECT_NEAR(segment.first.x(), x, 2e-4);

  // A box minus a sphere poking into its top.
  const TriMesh box = MakeBox(Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0, 0.1),
                              Eigen::Vector3i(8, 4, 8));
  const TriMesh ball = MakeIcosphere(0.05, 5, Eigen::Vector3d(0, 0.02, 0));
  const BooleanResult carved = MeshDifference(box, ball, "box - ball");
  ExpectClosedManifold(carved.mesh, "difference");
  const double h = 0.03;  // cap height below y = 0
  const double cap = M_PI * h * h * (3 * 0.05 - h) / 3;
  EXPECT_NEAR((EnclosedVolume(carved.mesh) - (0.008 * 0.5 - cap)) / cap, 0.0, 1e-2);

  // Isotropic remeshing keeps the shape and reaches the target edge length.
  const TriMesh remeshed = RemeshIsotropic(joined.mesh, {}, 0.006, 3);
  ExpectValidSupport(remeshed, "remeshed union");
  EXPECT_NEAR(EnclosedVolume(remeshed) / EnclosedVolume(joined.mesh), 1.0, 5e-3);

  // An open operand is refused with a message.
  TriMesh open = a;
  open.triangles.conservativeResize(open.triangles.rows() - 1, 3);
  EXPECT_THROW(MeshUnion(open, b, "open"), InputError);
}

}  // namespace
}  // namespace ergo

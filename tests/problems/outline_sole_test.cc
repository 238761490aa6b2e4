#include "problems/outline_sole.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "problems/shoe_scenario.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// An ellipse-shaped "foot" (a flattened ellipsoid resting on y = 0): its footprint is the
// ellipse of its lowest 3 cm, so the fitted sole's outline is that ellipse grown by the
// margin — checkable without the code: the top's area against the offset ellipse's, the
// extent along each axis, a closed outward surface with a flat bottom.
TEST(Problems, OutlineSoleFollowsAnEllipticFootprintGrownByTheMargin) {
  TriMesh egg = MakeIcosphere(1.0, 4);
  const double a = 0.05, c = 0.12, b = 0.04;  // semi-axes x, z, and the height's
  for (Eigen::Index i = 0; i < egg.vertices.rows(); ++i) {
    egg.vertices(i, 0) *= a;
    egg.vertices(i, 1) = b * (egg.vertices(i, 1) + 1);  // lowest point at y = 0
    egg.vertices(i, 2) *= c;
  }
  OutlineSoleOptions options;
  options.margin = 0.01;
  options.footprint_height = 0.2;  // the whole ellipsoid: its footprint is the full ellipse
  options.top_spacing = 0.008;
  options.wall_spacing = 0.008;
  const OutlineSole sole = MakeOutlineSole(egg, options);
  MeshCheckOptions check;
  check.require_closed = true;
  const MeshCheckReport report = CheckTriMesh(sole.mesh, "fitted sole", check);
  EXPECT_EQ(report.Worst(), Severity::kNote) << report.FullReport();
  EXPECT_GT(EnclosedVolume(sole.mesh), 0);  // outward
  // Extent: the ellipse plus the margin, to within the raster (2 mm) and the outline's
  // chords (8 mm chords on a ≥ 6 cm radius of curvature sag < 0.2 mm).
  const Eigen::RowVector3d lo = sole.mesh.vertices.colwise().minCoeff();
  const Eigen::RowVector3d hi = sole.mesh.vertices.colwise().maxCoeff();
  EXPECT_NEAR(hi.x(), a + options.margin, 0.003);
  EXPECT_NEAR(-lo.x(), a + options.margin, 0.003);
  EXPECT_NEAR(hi.z(), c + options.margin, 0.003);
  EXPECT_NEAR(lo.y(), -options.thickness, 1e-12);
  EXPECT_NEAR(hi.y(), 0, 1e-12);
  // Volume = thickness × the offset ellipse's area, π a c + 2 m · perimeter-ish + π m²
  // (Steiner's formula for a convex parallel set: A + P m + π m²).
  const double h = std::pow((a - c) / (a + c), 2);
  const double perimeter = M_PI * (a + c) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));  // Ramanujan
  const double m = options.margin;
  const double area = M_PI * a * c + perimeter * m + M_PI * m * m;
  EXPECT_NEAR(EnclosedVolume(sole.mesh) / options.thickness, area, 0.03 * area);
  // The designed top is the y = 0 face, edges about the spacing.
  int top = 0;
  for (Eigen::Index v = 0; v < sole.mesh.vertices.rows(); ++v) {
    if (sole.top[v]) {
      ++top;
      EXPECT_EQ(sole.mesh.vertices(v, 1), 0);
    }
  }
  EXPECT_GT(top, static_cast<int>(0.5 * area / (options.top_spacing * options.top_spacing)));
}

// The shoe's fitted sole: narrower than the rectangle at the arch and the heel, and the quick
// shoe still stands on it (a converged, balanced equilibrium).
TEST(Problems, ShoeWithAFootprintSoleIsClosedAndSmallerThanTheRectangle) {
  // Two quick-shoe builds; the outline itself is covered under the sanitizers above.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "two quick-shoe builds";
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  const Scenario rectangle = MakeShoeScenario(options);
  options.footprint_outline = true;
  const Scenario fitted = MakeShoeScenario(options);
  MeshCheckOptions check;
  check.require_closed = true;
  EXPECT_EQ(CheckTriMesh(fitted.support, "fitted", check).Worst(), Severity::kNote);
  const double fitted_area = EnclosedVolume(fitted.support) / options.sole_thickness;
  const double rectangle_area = EnclosedVolume(rectangle.support) / options.sole_thickness;
  std::cout << "sole area: fitted " << fitted_area << " m^2, rectangle " << rectangle_area
            << " m^2\n";
  EXPECT_LT(fitted_area, 0.9 * rectangle_area);
  EXPECT_THROW(MakeOutlineSole(TriMesh(), OutlineSoleOptions()), InputError);
}

}  // namespace
}  // namespace ergo

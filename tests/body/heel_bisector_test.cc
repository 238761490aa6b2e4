#include "ergo/body/heel_bisector.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/axis_map.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

constexpr double kDegree = M_PI / 180;

// A foot-sized ellipsoid (8 cm wide, 6 cm high, 26 cm long) standing on y = 0, its heel at
// the smallest z, sheared across by `lean` (dx/dy). The icosphere is symmetric under x → −x,
// so every horizontal slice's outline is centred on the shear: the bisector's lean is exact.
TriMesh LeaningHeel(double lean) {
  TriMesh heel = MakeIcosphere(1.0, 4);
  heel.vertices.col(0) *= 0.04;
  heel.vertices.col(1) *= 0.03;
  heel.vertices.col(2) *= 0.13;
  heel.vertices.col(1).array() -= heel.vertices.col(1).minCoeff();
  heel.vertices.col(0) += lean * heel.vertices.col(1);
  return heel;
}

// Known answer: a heel sheared so that its outline's mid-points lean by 5 degrees reads 5
// degrees, everted when the lean is towards the medial side and inverted when away from it;
// the fit's residual is round-off (the mid-points lie on the line).
TEST(HeelBisector, AShearedHeelReadsItsLeanEvertedTowardsTheMedialSide) {
  const double lean = std::tan(5 * kDegree);
  const TriMesh heel = LeaningHeel(lean);
  const HeelBisector medial_plus = MeasureHeelBisector(heel, true, +1, {}, "test");
  EXPECT_NEAR(medial_plus.eversion, 5 * kDegree, 1e-12);
  EXPECT_NEAR(medial_plus.lean, lean, 1e-12);
  EXPECT_LT(medial_plus.rms_residual, 1e-12);
  // The heel's lowest skin within the rear 12 % is 10.6 mm up the ellipsoid and its top there
  // 49.4 mm: slices at 16.6, 18.6, ..., 46.6 mm above the former.
  EXPECT_EQ(medial_plus.slices, 16);
  const HeelBisector medial_minus = MeasureHeelBisector(heel, true, -1, {}, "test");
  EXPECT_NEAR(medial_minus.eversion, -5 * kDegree, 1e-12);
  // The same heel read from the other end of z finds the ellipsoid's other end: the same lean.
  EXPECT_NEAR(MeasureHeelBisector(heel, false, +1, {}, "test").eversion, 5 * kDegree, 1e-12);
  // Upright: no lean.
  EXPECT_NEAR(MeasureHeelBisector(LeaningHeel(0), true, +1, {}, "test").eversion, 0, 1e-12);
}

// A heel lower than the lowest slice (a 3 mm slab) cannot be bisected: a clear error naming
// the source, not a NaN.
TEST(HeelBisector, AHeelTooLowToSliceIsRefused) {
  const TriMesh slab = MakeBox(Eigen::Vector3d(-0.04, 0, -0.13), Eigen::Vector3d(0.04, 0.003, 0.13),
                               Eigen::Vector3i(4, 1, 10));
  try {
    MeasureHeelBisector(slab, true, 1, {}, "slab.obj");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slab.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("too few"), std::string::npos) << e.what();
  }
}

// The shipped scan (FIND template, a left foot at rest, medial side −x): its heel stands
// within 2 degrees of upright as scanned (README "Scans": a foot at rest, where standing
// adults' heels are about 6 degrees everted).
TEST(HeelBisector, TheShippedScansHeelStandsAboutUpright) {
  const std::string dir = testing::RealScanDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/real-scans is not present";
  TriMesh skin = ReadTriMesh(dir + "/foot_find_template.obj", ReadOptions());
  ApplyAxisMap(ParseAxisMap("y,z,x", "--axes"), &skin.vertices);
  const HeelBisector bisector = MeasureHeelBisector(skin, true, -1, {}, "scan");
  std::cout << "FIND heel: " << bisector.eversion / kDegree << " deg everted, " << bisector.slices
            << " slices, rms " << 1e3 * bisector.rms_residual << " mm\n";
  EXPECT_EQ(bisector.slices, 23);
  EXPECT_LT(std::abs(bisector.eversion), 2 * kDegree);
}

}  // namespace
}  // namespace ergo

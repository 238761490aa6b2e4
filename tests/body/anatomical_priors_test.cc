#include "ergo/body/anatomical_priors.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "ergo/body/tissue_fields.h"
#include "ergo/mesh/axis_map.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// The shipped real scan (FIND template foot: z up, its length along x), in ergo's frame.
TriMesh ScannedFoot() {
  const std::string dir = testing::RealScanDir();
  if (dir.empty()) return TriMesh();
  TriMesh skin = ReadTriMesh(dir + "/foot_find_template.obj", ReadOptions());
  ApplyAxisMap(ParseAxisMap("y,z,x", "--axes"), &skin.vertices);
  return skin;
}

const Landmark& Find(const AnatomicalPriors& priors, const std::string& name) {
  for (const Landmark& mark : priors.landmarks)
    if (mark.name == name) return mark;
  ADD_FAILURE() << "no landmark " << name;
  return priors.landmarks.front();
}

// The documented ranges (ergo/body/README.md "Anatomical priors") at the detected landmarks:
// heel pad 16–19 mm, metatarsal-head pad about 15 mm (13–17 mm allowed: the bones' height
// minus the skin's, which at the ball's lowest point is within a millimetre of the floor),
// the medial arch deeper than the ball (its core is the bones' underside, well above the
// skin), the toes all tissue (the core cut before them); moduli 45 kPa heel, 53–62 kPa metatarsal
// heads.
TEST(Body, FootPriorsOnTheShippedScanAreInTheirDocumentedRanges) {
  const TriMesh skin = ScannedFoot();
  if (skin.vertices.rows() == 0) GTEST_SKIP() << "../shared/real-scans is not present";
  AnatomyOptions options;
  options.anatomy = Anatomy::kFoot;
  const AnatomicalPriors priors = ComputeAnatomicalPriors(skin, options, "scan");
  std::cout << priors.summary << "\n";
  EXPECT_NEAR(priors.length, 0.270, 0.005);  // SOURCES.md: 0.270 m long
  const Landmark& heel = Find(priors, "heel");
  const Landmark& ball = Find(priors, "ball");
  const Landmark& arch = Find(priors, "medial arch");
  const Landmark& toe = Find(priors, "toe tip");
  EXPECT_GE(heel.depth, 0.016);
  EXPECT_LE(heel.depth, 0.019);
  EXPECT_GE(ball.depth, 0.013);
  EXPECT_LE(ball.depth, 0.017);
  EXPECT_GT(arch.depth, ball.depth);
  // The toes are tissue: the core is cut away before the toe tip, after the ball.
  ASSERT_TRUE(static_cast<bool>(priors.core_limit));
  EXPECT_GT(priors.core_limit(toe.point), 0.02);
  EXPECT_LT(priors.core_limit(ball.point), 0);
  // The toes' height above the weight-bearing line, recomputed from its definition: the least
  // height of the skin past the core's cut above the line through the heel's and the ball's
  // lowest skin (the landmarks). This scan's toes are held up (a foot at rest; README "Scans").
  auto along = [&](const Eigen::Vector3d& p) {
    return priors.length_direction * (p.z() - priors.start_z) / priors.length;
  };
  double toes = INFINITY;
  for (Eigen::Index i = 0; i < skin.vertices.rows(); ++i) {
    const Eigen::Vector3d p = skin.vertices.row(i).transpose();
    if (priors.core_limit(p) <= 0) continue;
    const double floor = heel.point.y() + (along(p) - along(heel.point)) /
                                              (along(ball.point) - along(heel.point)) *
                                              (ball.point.y() - heel.point.y());
    toes = std::min(toes, p.y() - floor);
  }
  EXPECT_NEAR(priors.toe_clearance, toes, 1e-12);
  EXPECT_GT(priors.toe_clearance, 0.005);
  EXPECT_NE(priors.summary.find("toes held up"), std::string::npos) << priors.summary;
  EXPECT_NEAR(heel.youngs_modulus, 45e3, 1e3);
  EXPECT_GE(ball.youngs_modulus, 53e3);
  EXPECT_LE(ball.youngs_modulus, 62e3);
  // Landmarks in order along the foot, from the heel.
  const double dir = priors.length_direction;
  EXPECT_LT(dir * (heel.point.z() - priors.start_z), dir * (arch.point.z() - priors.start_z));
  EXPECT_LT(dir * (arch.point.z() - priors.start_z), dir * (ball.point.z() - priors.start_z));
  EXPECT_LT(dir * (ball.point.z() - priors.start_z), dir * (toe.point.z() - priors.start_z));
  // The landmarks are samples of the interpolated field: exact there (the spline
  // interpolates; the clamp to the samples' range cannot bite at a sample).
  TissueFieldInputs inputs;
  inputs.anatomy = options;
  const TissueFields fields = MakeTissueFields(skin, inputs, "scan");
  for (const Landmark* mark : {&heel, &ball, &arch})
    EXPECT_NEAR(fields.depth(mark->point), mark->depth, 1e-9) << mark->name;
  // The fat pads stiffen (Erdemir et al. 2006's alpha), the arch's muscle does not.
  EXPECT_EQ(heel.stiffening_exponent, 6.82);
  EXPECT_NEAR(ball.stiffening_exponent, 6.82, 1e-9);
  EXPECT_NEAR(arch.stiffening_exponent, 2.0, 0.5);
  ASSERT_TRUE(fields.stiffening_exponent.has_value());
  for (const Landmark* mark : {&heel, &ball, &arch}) {
    EXPECT_NEAR((*fields.stiffening_exponent)(mark->point), mark->stiffening_exponent, 1e-9)
        << mark->name;
  }
}

// Given the other heel end or foot side, the frame follows the flags.
TEST(Body, FootPriorsFollowTheGivenHeelEndAndSide) {
  const TriMesh skin = ScannedFoot();
  if (skin.vertices.rows() == 0) GTEST_SKIP() << "../shared/real-scans is not present";
  AnatomyOptions options;
  options.anatomy = Anatomy::kFoot;
  const AnatomicalPriors detected = ComputeAnatomicalPriors(skin, options, "scan");
  options.heel_end = detected.length_direction > 0 ? HeelEnd::kMinZ : HeelEnd::kMaxZ;
  const AnatomicalPriors given = ComputeAnatomicalPriors(skin, options, "scan");
  EXPECT_EQ(given.length_direction, detected.length_direction);
  EXPECT_NEAR(Find(given, "heel").depth, Find(detected, "heel").depth, 1e-12);
}

// A measured sample replaces the priors within the override radius, and only there.
TEST(Body, MeasuredSamplesReplaceThePriorsNearThem) {
  PointSamples prior;
  prior.points.resize(3, 3);
  prior.points << 0, 0, 0, 0.01, 0, 0, 0.1, 0, 0;
  prior.values.resize(3);
  prior.values << 0.02, 0.02, 0.02;
  PointSamples measured;
  measured.points.resize(1, 3);
  measured.points << 0.005, 0, 0;
  measured.values.resize(1);
  measured.values << 0.03;
  measured.lines = {7};
  const PointSamples merged = OverridePriorSamples(prior, measured, 0.02);
  ASSERT_EQ(merged.points.rows(), 2);
  EXPECT_DOUBLE_EQ(merged.points(0, 0), 0.1);  // the far prior sample is kept
  EXPECT_DOUBLE_EQ(merged.values[1], 0.03);    // the measurement added
  EXPECT_EQ(merged.lines[1], 7);
  const SampleInterpolant field = SampleInterpolant::Fit(merged);
  EXPECT_NEAR(field(Eigen::Vector3d(0.005, 0, 0)), 0.03, 1e-12);
}

// A part with no ankle (an ellipsoid) cannot say where its heel is: a clear error, with the
// flag that settles it; likewise a constant depth given beside the priors.
TEST(Body, AmbiguousFeetAndConflictingFlagsAreRefused) {
  TriMesh egg = MakeIcosphere(1.0, 3);
  for (Eigen::Index i = 0; i < egg.vertices.rows(); ++i)
    egg.vertices.row(i) = egg.vertices.row(i).cwiseProduct(Eigen::RowVector3d(0.05, 0.04, 0.13));
  AnatomyOptions options;
  options.anatomy = Anatomy::kFoot;
  try {
    ComputeAnatomicalPriors(egg, options, "egg.obj");
    ADD_FAILURE() << "an ellipsoid got a heel";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "egg.obj");
    EXPECT_NE(e.fix().find("--heel_end"), std::string::npos) << e.what();
  }
  TissueFieldInputs inputs;
  inputs.anatomy.anatomy = Anatomy::kSeat;
  inputs.depth = 0.02;
  EXPECT_THROW(MakeTissueFields(egg, inputs, "egg.obj"), InputError);
  EXPECT_THROW(ParseAnatomy("knee", "--anatomy"), InputError);
}

}  // namespace
}  // namespace ergo

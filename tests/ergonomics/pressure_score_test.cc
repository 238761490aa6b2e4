// ScorePressures (ergo/ergonomics/pressure_score.h): ζ's value holds the halves its flag
// says, and its partials are the derivatives of that value — against central differences of
// ζ with the contact springs re-found at every perturbed shape, with respect to the body's
// vertex positions (support fixed) and to the support's vertices (body fixed, the vertex
// areas following). A tilted hollow cube pressed 1–3 mm into a block with a bump, the two
// meshes not matching; one-way and two-way contact, both sides scored and the skin's alone.
// Measured agreement 6e-11–6e-10 (bound 1e-5); partials of the other flag's ζ miss by 0.5–10.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ergo/contact/support.h"
#include "ergo/contact/surface_contact.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/pressure_score.h"
#include "ergo/ergonomics/score_gradient.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

constexpr double kStiffness = 1e8;  // κ, Pa/m: 1 mm of penetration is 100 kPa

Eigen::VectorXd Flat(const Vertices& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}

Vertices Unflat(const Eigen::VectorXd& x) {
  return Eigen::Map<const Vertices>(x.data(), x.size() / 3, 3);
}

struct Scene {
  LayeredBody body;
  TriMesh support;
};

Scene MakeScene() {
  // Tilted 3° about x and 2° about z, its bottom's centre 1 mm above the block's flat top: the
  // bump (3 mm high, under the centre) and one corner sink a few millimetres in, and contact
  // ends inside the face, so springs start and stop within the patch.
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(0.052, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(0.035, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  LayeredBody body = testing::MakeHollowCubeBody(0.1, 6, 1e4, 0.45, LayeredBodyOptions(),
                                                 Eigen::Vector3d(0.004, 0.051, -0.003), tilt);
  TriMesh support = MakeHeightfieldBlock(
      {-0.1, -0.03, -0.1}, {0.1, 0, 0.1}, {13, 1, 13},
      [](double x, double z) { return 0.003 * std::exp(-(x * x + z * z) / (0.03 * 0.03)); });
  return {std::move(body), std::move(support)};
}

struct Case {
  bool two_way;
  bool score_support_side;
};

class ErgonomicsPressureScore : public ::testing::TestWithParam<Case> {
 protected:
  ErgonomicsPressureScore()
      : scene_(MakeScene()),
        evaluator_(scene_.body, scene_.support, PressureCostOptions()),
        options_{kStiffness, 0.5, GetParam().two_way} {}

  // The pressures at body vertex positions `body_positions` on the support with vertices
  // `support_vertices`, springs found afresh.
  ContactPressures Pressures(const Vertices& body_positions, const Vertices& support_vertices,
                             bool with_hessian) const {
    Support support(scene_.support);
    support.UpdateVertices(support_vertices);
    SurfaceContact contact(scene_.body.skin().RestSurface(scene_.body.rest().vertices),
                           scene_.body.skin().vertices, scene_.body.skin().rest_areas, options_);
    SurfaceContacts contacts;
    contact.Evaluate(body_positions, support, with_hessian, nullptr, &contacts);
    return evaluator_.Evaluate(std::move(contacts), support.vertex_areas());
  }

  double Value(const Vertices& body_positions, const Vertices& support_vertices) const {
    return ScorePressures(Pressures(body_positions, support_vertices, false), scene_.body,
                          GetParam().score_support_side, false)
        .value;
  }

  Scene scene_;
  ContactPressureEvaluator evaluator_;
  SurfaceContactOptions options_;
};

TEST_P(ErgonomicsPressureScore, ValueHoldsTheFlaggedHalvesAndPartialsAreItsDerivatives) {
  const bool both = GetParam().score_support_side;
  const Vertices& body_at = scene_.body.rest().vertices;
  const Vertices& support_at = scene_.support.vertices;
  const ContactPressures pressures = Pressures(body_at, support_at, true);
  ASSERT_GT(pressures.contacts.skin.size(), 5);
  ASSERT_GT(pressures.contacts.support.size(), 5);
  ASSERT_GT(pressures.support.cost, 0);

  // The value: the skin's half, plus the support's where scored; both halves reported.
  const PressureScore value_only = ScorePressures(pressures, scene_.body, both, false);
  EXPECT_EQ(value_only.human, pressures.human.cost);
  EXPECT_EQ(value_only.support, pressures.support.cost);
  EXPECT_EQ(value_only.value,
            both ? pressures.human.cost + pressures.support.cost : pressures.human.cost);
  EXPECT_FALSE(value_only.has_partials);
  EXPECT_EQ(value_only.partials.body.rows(), 0);

  const PressureScore score = ScorePressures(pressures, scene_.body, both, true);
  ASSERT_TRUE(score.has_partials);
  EXPECT_EQ(score.value, value_only.value);
  ASSERT_EQ(score.partials.body.rows(), body_at.rows());
  ASSERT_EQ(score.partials.support.position.rows(), support_at.rows());
  ASSERT_EQ(score.partials.support.area.size(), support_at.rows());

  const std::vector<double> steps = testing::StepSweep(1e-5, 5);  // 10 µm … 1 nm
  std::string report;
  {  // ∂ζ/∂(body positions), the support fixed.
    const Eigen::VectorXd gradient = Flat(score.partials.body);
    ASSERT_GT(gradient.norm(), 0);
    const double error = testing::WorstGradientError(
        [&](const Eigen::VectorXd& x) { return Value(Unflat(x), support_at); }, gradient,
        Flat(body_at), 1e-6 * gradient.norm(), steps, 6, 0, 7, &report);
    EXPECT_LT(error, 1e-5) << report;
  }
  {  // ∂ζ/∂(support shape), the body fixed: positions directly and through the vertex areas.
    const Eigen::VectorXd gradient =
        Flat(score.partials.support.position +
             ChainSupportAreas(score.partials.support.area, scene_.support));
    ASSERT_GT(gradient.norm(), 0);
    const double error = testing::WorstGradientError(
        [&](const Eigen::VectorXd& x) { return Value(body_at, Unflat(x)); }, gradient,
        Flat(support_at), 1e-6 * gradient.norm(), steps, 6, 0, 11, &report);
    EXPECT_LT(error, 1e-5) << report;
  }
}

INSTANTIATE_TEST_SUITE_P(ContactModelsAndSides, ErgonomicsPressureScore,
                         ::testing::Values(Case{false, true}, Case{false, false}, Case{true, true},
                                           Case{true, false}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.two_way ? "two_way" : "one_way") +
                                  (info.param.score_support_side ? "_both_sides" : "_skin_side");
                         });

}  // namespace
}  // namespace ergo

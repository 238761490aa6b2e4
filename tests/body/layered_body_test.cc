#include "ergo/body/layered_body.h"

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

TEST(Body, HollowCubeHasHandComputedVolumesMassesAndCentre) {
  LayeredBodyOptions options;
  options.tissue_density = 1000;
  options.core_density = 2000;
  const Eigen::Vector3d centre(0.3, -0.2, 0.1);
  const LayeredBody body = testing::MakeHollowCubeBody(0.3, 3, 1e4, 0.45, options, centre);
  // Layer: 0.3³ − 0.1³ = 0.026 m³; core 0.001 m³ at the cube's centre.
  EXPECT_NEAR(body.layer_volume(), 0.026, 1e-15);
  EXPECT_NEAR(body.vertex_mass().sum(), 26.0, 1e-12);
  EXPECT_NEAR(body.core_volume(), 0.001, 1e-15);
  EXPECT_NEAR(body.core_mass(), 2.0, 1e-12);
  EXPECT_LT((body.core_centre() - centre).norm(), 1e-15);
  // Solid cube inertia about its centre: m a²/6 on the diagonal.
  EXPECT_LT((body.core_inertia() - Eigen::Matrix3d::Identity() * 2.0 * 0.01 / 6).norm(), 1e-15);
  EXPECT_LT((body.TotalLoad() - Eigen::Vector3d(0, -9.81 * 28.0, 0)).norm(), 1e-10);
}

TEST(Body, SkinIsTheOuterBoundaryWithItsRestArea) {
  const LayeredBody body = testing::MakeHollowCubeBody(0.3, 3, 1e4, 0.45, {});
  // Outer box: 6 faces of 3x3 cells, 2 triangles each; total area 6 · 0.09.
  EXPECT_EQ(body.skin().triangles.rows(), 6 * 9 * 2);
  EXPECT_NEAR(body.skin().rest_areas.sum(), 0.54, 1e-14);
  for (Eigen::Index i = 0; i < body.skin().vertices.size(); ++i)
    EXPECT_FALSE(body.attached()[body.skin().vertices[i]]);
}

TEST(Body, RefusesADegenerateRestTetNamingIt) {
  TetMesh mesh = MakeTetGrid({0, 0, 0}, {1, 1, 1}, {1, 1, 1});
  std::swap(mesh.tets(2, 0), mesh.tets(2, 1));  // inverted
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(6, 1e4);
  material.poisson_ratio = Eigen::VectorXd::Constant(6, 0.4);
  std::vector<bool> attached(8, false);
  attached[0] = true;
  LayeredBodyOptions options;
  options.core_mass = 1;
  try {
    LayeredBody::Create(mesh, attached, material, options, "test body");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "tet 2");
    EXPECT_NE(error.problem().find("rest volume"), std::string::npos);
  }
}

TEST(Body, RefusesABodyWithoutAttachedVerticesOrWithBadMaterial) {
  const TetMesh mesh = MakeTetGrid({0, 0, 0}, {1, 1, 1}, {1, 1, 1});
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(6, 1e4);
  material.poisson_ratio = Eigen::VectorXd::Constant(6, 0.4);
  EXPECT_THROW(LayeredBody::Create(mesh, std::vector<bool>(8, false), material, {}), InputError);
  std::vector<bool> attached(8, false);
  attached[0] = true;
  material.poisson_ratio[3] = 0.5;
  EXPECT_THROW(LayeredBody::Create(mesh, attached, material, {}), InputError);
  material.poisson_ratio[3] = 0.4;
  material.stiffening_exponent = Eigen::VectorXd::Constant(5, 2.0);  // one short
  EXPECT_THROW(LayeredBody::Create(mesh, attached, material, {}), InputError);
  material.stiffening_exponent = Eigen::VectorXd::Constant(6, 6.82);
  material.stiffening_exponent[4] = 1.0;  // softening is outside the law's range
  try {
    LayeredBody::Create(mesh, attached, material, {}, "test body");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "tet 4");
    EXPECT_NE(error.problem().find("stiffening exponent"), std::string::npos);
  }
}

TEST(Body, CoreLockParsesNamesAndRefusesASingleLockedRotation) {
  const CoreLock chair = ParseCoreLock("tx,tz");
  EXPECT_EQ(chair.FreeComponents(), (std::vector<int>{1, 3, 4, 5}));
  EXPECT_EQ(chair.ToString(), "tx,tz");
  const CoreLock shoe = ParseCoreLock("tx,tz,rx,ry");
  EXPECT_EQ(shoe.FreeComponents(), (std::vector<int>{1, 5}));
  EXPECT_EQ(ParseCoreLock("none").FreeCount(), 6);
  EXPECT_THROW(ParseCoreLock("tx,tq"), InputError);
  EXPECT_THROW(ParseCoreLock("rx"), InputError);
}

}  // namespace
}  // namespace ergo

#include "ergo/material/rotation_variant_svd.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "tests/material/material_test_util.h"

namespace ergo {
namespace {

void ExpectValidSignedSvd(const Eigen::Matrix3d& f) {
  const SignedSvd3 svd = RotationVariantSvd(f);
  const double scale = std::max(f.norm(), 1e-300);
  EXPECT_LE((svd.u * svd.sigma.asDiagonal() * svd.v.transpose() - f).norm(), 1e-14 * scale) << f;
  EXPECT_TRUE((svd.u.transpose() * svd.u).isIdentity(1e-14)) << f;
  EXPECT_TRUE((svd.v.transpose() * svd.v).isIdentity(1e-14)) << f;
  EXPECT_NEAR(svd.u.determinant(), 1.0, 1e-14);
  EXPECT_NEAR(svd.v.determinant(), 1.0, 1e-14);
  const double slack = 1e-14 * svd.sigma(0);
  EXPECT_GE(svd.sigma(0) + slack, svd.sigma(1)) << f;
  EXPECT_GE(svd.sigma(1) + slack, std::abs(svd.sigma(2))) << f;
  EXPECT_GE(svd.sigma(1), 0.0);
  const double det = f.determinant();
  if (std::abs(det) > 1e-12 * std::pow(scale, 3)) {
    EXPECT_EQ(svd.sigma(2) < 0, det < 0) << f;
  }
}

TEST(Material, SignedSvdReconstructsWithProperRotations) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int sample = 0; sample < 2000; ++sample) {
    Eigen::Vector3d sigma;
    for (int i = 0; i < 3; ++i) sigma(i) = std::pow(10.0, 2 - 8 * unit(rng));
    switch (sample % 5) {
      case 1:
        sigma(1) = sigma(0) * (1 + 1e-10 * unit(rng));
        break;  // cluster
      case 2:
        sigma(1) = sigma(2) = sigma(0);
        break;  // triple
      case 3:
        sigma(2) = 0;
        break;  // rank 2
      case 4:
        sigma(1) = sigma(2) = 0;
        break;  // rank 1
      default:
        break;
    }
    if (sample % 2) sigma(2) = -sigma(2);
    ExpectValidSignedSvd(material_testing::DeformationWithStretches(sigma, rng));
  }
  ExpectValidSignedSvd(Eigen::Matrix3d::Zero());
  ExpectValidSignedSvd(Eigen::Matrix3d::Identity());
  ExpectValidSignedSvd(-Eigen::Matrix3d::Identity());
  ExpectValidSignedSvd(Eigen::Vector3d(2, -3, 0.5).asDiagonal());
}

TEST(Material, SignedSvdRecoversSmallStretchesToRelativeAccuracy) {
  // Graded columns (F = R diag(s)) keep relative accuracy of tiny stretches: one-sided
  // Jacobi works on F, not on F^T F.
  std::mt19937 rng(2);
  const Eigen::Matrix3d r = material_testing::RandomRotation(rng);
  const SignedSvd3 svd = RotationVariantSvd(r * Eigen::Vector3d(1.0, 1e-5, -1e-9).asDiagonal());
  EXPECT_NEAR(svd.sigma(0), 1.0, 1e-15);
  EXPECT_NEAR(svd.sigma(1), 1e-5, 1e-18);
  EXPECT_NEAR(svd.sigma(2), -1e-9, 1e-21);
}

}  // namespace
}  // namespace ergo

#include "ergo/material/rotation_variant_svd.h"

#include <cmath>
#include <utility>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>

namespace ergo {
namespace {

// Columns of B = F V are orthogonal to this relative level after the polish; below it
// a further rotation cannot change F - U S V^T beyond round-off.
constexpr double kOrthogonalityTolerance = 1e-15;
// The closed-form eigenvectors of F^T F are already accurate except inside clusters of
// close eigenvalues; one or two sweeps of one-sided Jacobi fix those. Four is a cap.
constexpr int kMaxPolishSweeps = 4;
// After scaling F to max |F_ij| = 1 (so sigma1 >= 1), a second column whose part
// orthogonal to the first is below this is round-off: F has numerical rank one.
constexpr double kRankOneTolerance = 64 * 2.220446049250313e-16;

// One-sided Jacobi rotation of columns p, q of b (and of v) that makes them orthogonal
// (Hestenes' method). Returns false if they already were.
bool OrthogonaliseColumns(int p, int q, Eigen::Matrix3d* b, Eigen::Matrix3d* v) {
  const double alpha = b->col(p).squaredNorm();
  const double beta = b->col(q).squaredNorm();
  const double gamma = b->col(p).dot(b->col(q));
  if (gamma * gamma <= kOrthogonalityTolerance * kOrthogonalityTolerance * alpha * beta) {
    return false;
  }
  // Jacobi rotation diagonalising the Gram matrix [[alpha, gamma], [gamma, beta]];
  // the smaller root t = tan(theta) keeps |theta| <= pi/4.
  const double zeta = (beta - alpha) / (2.0 * gamma);
  const double t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::sqrt(1.0 + zeta * zeta));
  const double c = 1.0 / std::sqrt(1.0 + t * t);
  const double s = c * t;
  for (Eigen::Matrix3d* m : {b, v}) {
    const Eigen::Vector3d mp = m->col(p);
    const Eigen::Vector3d mq = m->col(q);
    m->col(p) = c * mp - s * mq;
    m->col(q) = s * mp + c * mq;
  }
  return true;
}

// Swaps columns i, j of b and v, negating one of them so that det V keeps its sign.
void SwapColumns(int i, int j, Eigen::Matrix3d* b, Eigen::Matrix3d* v, Eigen::Vector3d* norms) {
  b->col(i).swap(b->col(j));
  v->col(i).swap(v->col(j));
  b->col(j) = -b->col(j);
  v->col(j) = -v->col(j);
  std::swap((*norms)(i), (*norms)(j));
}

}  // namespace

SignedSvd3 RotationVariantSvd(const Eigen::Matrix3d& f) {
  DCHECK(f.allFinite()) << "RotationVariantSvd of a non-finite F:\n" << f;
  SignedSvd3 out;
  const double scale = f.cwiseAbs().maxCoeff();
  if (scale == 0.0) {
    out.u.setIdentity();
    out.v.setIdentity();
    out.sigma.setZero();
    return out;
  }
  // Scaling makes every threshold below relative and keeps F^T F away from under/overflow.
  const Eigen::Matrix3d a = f * (1.0 / scale);

  // Right singular vectors from the closed-form eigenvectors of A^T A (ascending order).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(a.transpose() * a);
  // The closed-form eigenvectors lose orthogonality (~1e-8) inside eigenvalue clusters:
  // re-orthonormalise (Gram-Schmidt, third column by cross product so det V = +1).
  Eigen::Matrix3d v;
  v.col(0) = eigen.eigenvectors().col(2).normalized();
  v.col(1) = eigen.eigenvectors().col(1) - v.col(0).dot(eigen.eigenvectors().col(1)) * v.col(0);
  v.col(1).normalize();
  v.col(2) = v.col(0).cross(v.col(1));
  Eigen::Matrix3d b = a * v;

  // Polish: squaring A loses relative accuracy of small stretches and closed-form
  // eigenvectors are inaccurate in eigenvalue clusters; one-sided Jacobi on B = A V works
  // on A itself and restores both (Demmel & Veselic 1992).
  for (int sweep = 0; sweep < kMaxPolishSweeps; ++sweep) {
    bool rotated = OrthogonaliseColumns(0, 1, &b, &v);
    rotated |= OrthogonaliseColumns(0, 2, &b, &v);
    rotated |= OrthogonaliseColumns(1, 2, &b, &v);
    if (!rotated) break;
  }

  // Sort columns by decreasing norm (each swap keeps det V = +1).
  Eigen::Vector3d norms = b.colwise().squaredNorm();
  if (norms(0) < norms(1)) SwapColumns(0, 1, &b, &v, &norms);
  if (norms(1) < norms(2)) SwapColumns(1, 2, &b, &v, &norms);
  if (norms(0) < norms(1)) SwapColumns(0, 1, &b, &v, &norms);

  // U from the orthogonal columns of B; its third column is u0 x u1, so U is a proper
  // rotation and the sign of det F lands on sigma3.
  const double sigma0 = std::sqrt(norms(0));  // >= 1 after scaling
  const Eigen::Vector3d u0 = b.col(0) * (1.0 / sigma0);
  Eigen::Vector3d u1 = b.col(1) - u0.dot(b.col(1)) * u0;
  double sigma1 = u1.norm();
  if (sigma1 > kRankOneTolerance) {
    u1 *= 1.0 / sigma1;
  } else {
    // Rank one: any unit vector orthogonal to u0 will do.
    Eigen::Index axis;
    u0.cwiseAbs().minCoeff(&axis);
    u1 = u0.cross(Eigen::Vector3d::Unit(axis)).normalized();
    sigma1 = 0.0;
  }
  const Eigen::Vector3d u2 = u0.cross(u1);
  const double sigma2 = sigma1 == 0.0 ? 0.0 : u2.dot(b.col(2));

  out.u.col(0) = u0;
  out.u.col(1) = u1;
  out.u.col(2) = u2;
  out.v = v;
  out.sigma = scale * Eigen::Vector3d(sigma0, sigma1, sigma2);
  return out;
}

}  // namespace ergo

// ContactSet: the penalty springs of a whole point set against a closed surface at one
// configuration (paper §3.5, Eq. 10): every listed point strictly inside the surface gets
// E = k‖p − π(p)‖² towards its closest point, with the sliding-anchor gradient and Hessian
// over the point and the feature's surface vertices (the cross blocks are ∂f/∂x, needed by
// the adjoint gradient). Used both ways: skin vertices against the support (the
// equilibrium's uni-directional contact) and support vertices against the deformed skin
// (the cost's bi-directional half, §4.1, Fig. 4). Units: m, N/m, N, J.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "ergo/contact/support.h"

namespace ergo {

// One point in contact.
struct Contact {
  int point = -1;              // index into the evaluated point set
  SupportPoint anchor;         // closest surface point and its feature (surface vertex ids)
  double stiffness = 0;        // k of this spring, N/m
  SlidingAnchorEnergy spring;  // E, ∂E/∂(p, x_feature), ∂²E (if requested)
  double penetration() const { return std::sqrt(anchor.squared_distance); }
  // Force on the point, −∂E/∂p, N.
  Eigen::Vector3d force() const { return -spring.gradient.head<3>(); }
};

struct ContactSet {
  std::vector<Contact> contacts;  // ordered by point index
  double energy = 0;              // Σ E, J
  double max_penetration = 0;     // m
  int size() const { return static_cast<int>(contacts.size()); }
  // Σ of the forces on the points, N.
  Eigen::Vector3d TotalForce() const;
};

// Evaluates points(i) for every i in `indices` against `surface`, point i's spring with
// stiffness stiffness[i] (N/m; one entry per point, i.e. size points.rows(); points with
// k = 0 are skipped), in parallel, deterministically. `hints`, if given, holds one
// SupportPoint per point index (size points.rows()): it seeds each query with the previous
// anchor and is updated for points found in contact.
ContactSet EvaluateContacts(const Support& surface, const Vertices& points,
                            const Eigen::VectorXi& indices, const Eigen::VectorXd& stiffness,
                            bool with_hessian, std::vector<SupportPoint>* hints = nullptr);

// The same with one stiffness k (N/m) for every point.
ContactSet EvaluateContacts(const Support& surface, const Vertices& points,
                            const Eigen::VectorXi& indices, double stiffness, bool with_hessian,
                            std::vector<SupportPoint>* hints = nullptr);

}  // namespace ergo

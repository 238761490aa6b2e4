// TotalPotential: the energy whose minimum is the static contact equilibrium (paper Eq. 9):
// elastic + gravity + external wrench (the body's ReducedSystem) + uni-directional penalty
// contact of every skin vertex against a rigid support (Eq. 10), with its gradient in the
// reduced coordinates (minus the residual of Eq. 7) and its Hessian K̂. Newton, the Ceres
// cross-check and the adjoint gradient all evaluate this one object, so forces reported
// anywhere are the forces the solver used (DESIGN.md §6).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/reduced_system.h"
#include "ergo/contact/contact_set.h"
#include "ergo/contact/support.h"

namespace ergo {

class TotalPotential {
 public:
  struct Evaluation {
    Vertices positions;              // all tet-mesh vertices, m
    ContactSet contacts;             // skin vertices inside the support
    ReducedSystem::Evaluation body;  // body terms; contact added; Hessian in body.hessian
    Eigen::VectorXd gradient;        // ∂E/∂y (reduced), N and N·m
    double energy = 0;               // J
    double assembly_seconds = 0;     // elastic assembly + reduction
    double contact_seconds = 0;      // collision detection + springs
  };

  // Keeps a reference to `body` (must outlive this). k > 0 in N/m.
  TotalPotential(const LayeredBody& body, double contact_stiffness);

  const ReducedSystem& system() const { return system_; }
  const LayeredBody& body() const { return system_.body(); }
  double contact_stiffness() const { return stiffness_; }
  void set_contact_stiffness(double k);

  // Energy only (for line searches). `hints`: per tet-mesh vertex previous anchors.
  double Energy(const BodyState& state, const Support& support,
                std::vector<SupportPoint>* hints = nullptr) const;

  // Energy, reduced gradient and (with_hessian) K̂ of the given kind, with the contact set.
  void Evaluate(const BodyState& state, const Support& support, HessianKind kind, bool with_hessian,
                std::vector<SupportPoint>* hints, Evaluation* evaluation) const;

  // Residual norm used for convergence: sqrt(Σ forces² + Σ (torques / L)²) with L the
  // core's lever length (largest attached-vertex distance from the core centre), so that
  // torques are measured as the equivalent force at the core's rim. N.
  double ResidualNorm(const Eigen::VectorXd& gradient) const;
  double lever_length() const { return lever_length_; }

 private:
  ReducedSystem system_;
  double stiffness_;
  double lever_length_ = 1;
};

}  // namespace ergo

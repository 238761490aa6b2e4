// TotalPotential: the energy whose minimum is the static contact equilibrium (paper Eq. 9):
// elastic + gravity + external wrench (the body's ReducedSystem) + the area-weighted
// penalty contact between the body's skin and a rigid support (Eq. 10, both ways:
// ergo/contact/surface_contact.h), with its gradient in the reduced coordinates (minus the
// residual of Eq. 7) and its Hessian K̂. Newton, the Ceres cross-check and the adjoint
// gradient all evaluate this one object, so forces reported anywhere are the forces the
// solver used (DESIGN.md §6).
//
// Hessians: a skin spring adds the 3x3 block of its skin vertex; a support spring (a support
// vertex inside the skin) adds the block over the skin vertices its anchor slides on —
// exact for HessianKind::kExact (the adjoint), projected to positive semi-definite spring by
// spring for kProjectedPsd (Newton's fallback), as IPC's per-pair projection.
//
// Not thread-safe on one object (the skin's search tree moves with every evaluation): one
// per thread; copies are independent.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/reduced_system.h"
#include "ergo/contact/support.h"
#include "ergo/contact/surface_contact.h"

namespace ergo {

class TotalPotential {
 public:
  struct Evaluation {
    Vertices positions;              // all tet-mesh vertices, m
    SurfaceContacts contacts;        // both kinds of spring and the per-vertex forces
    ReducedSystem::Evaluation body;  // body terms; contact added; Hessian in body.hessian
    Eigen::VectorXd gradient;        // ∂E/∂y (reduced), N and N·m
    double energy = 0;               // J
    double assembly_seconds = 0;     // elastic assembly + reduction
    double contact_seconds = 0;      // collision detection + springs
  };

  // Keeps a reference to `body` (must outlive this). options.stiffness = κ > 0, Pa/m.
  TotalPotential(const LayeredBody& body, const SurfaceContactOptions& options);

  const ReducedSystem& system() const { return system_; }
  const LayeredBody& body() const { return system_.body(); }
  // κ, Pa/m.
  double contact_stiffness() const { return contact_.stiffness(); }
  void set_contact_stiffness(double kappa) { contact_.set_stiffness(kappa); }
  const SurfaceContact& contact() const { return contact_; }

  // Energy only (for line searches). `hints`: per tet-mesh vertex previous anchors.
  double Energy(const BodyState& state, const Support& support,
                std::vector<SupportPoint>* hints = nullptr) const;

  // Energy, reduced gradient and (with_hessian) K̂ of the given kind, with the contacts.
  // with_support_samples = false leaves out the one-way contact's score-only support samples
  // (a Newton iteration needs none of them); AddSupportSamples fills them in later.
  void Evaluate(const BodyState& state, const Support& support, HessianKind kind, bool with_hessian,
                std::vector<SupportPoint>* hints, Evaluation* evaluation,
                bool with_support_samples = true) const;
  // The support samples an Evaluate left out, at its positions (their time in contact_seconds).
  void AddSupportSamples(const Support& support, bool with_hessian, Evaluation* evaluation) const;

  // Residual norm used for convergence: sqrt(Σ forces² + Σ (torques / L)²) with L the
  // core's lever length (largest attached-vertex distance from the core centre), so that
  // torques are measured as the equivalent force at the core's rim. N.
  double ResidualNorm(const Eigen::VectorXd& gradient) const;
  double lever_length() const { return lever_length_; }

 private:
  ReducedSystem system_;
  mutable SurfaceContact contact_;  // its skin tree follows the evaluated state
  double lever_length_ = 1;
};

// The body-side Hessian block of a support spring (a support vertex inside the skin): over
// its anchor's skin vertices, in Feature order (3n x 3n), exact or projected to PSD.
Eigen::MatrixXd SkinFeatureHessian(const Contact& support_spring, bool project_psd);

}  // namespace ergo

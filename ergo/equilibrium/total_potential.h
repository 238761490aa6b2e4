// TotalPotential: the energy whose minimum is the static contact equilibrium (paper Eq. 9):
// elastic + gravity + external wrench (the body's ReducedSystem) + the area-weighted
// penalty contact between the body's skin and the support (Eq. 10, both ways:
// ergo/contact/surface_contact.h), with its gradient in the reduced coordinates (minus the
// residual of Eq. 7) and its Hessian K̂. Newton, the Ceres cross-check and the adjoint
// gradient all evaluate this one object, so forces reported anywhere are the forces the
// solver used (DESIGN.md §6).
//
// The support is rigid, or soft (paper §4.3): an ElasticPart whose held base stays put and
// whose free vertices are the last block of y = (u^F, q, u^S). A soft support adds its own
// energy (elastic, optional weight), its contact is always two-way (the support's springs
// push too: otherwise its vertices between the skin's would rise into the tissue
// unresisted), and contact acts on both sides: the skin's springs pull
// on the support's feature vertices, the support's springs on its own vertices, and K̂ gains
// the support's block and the contact's cross blocks (body DOFs × support DOFs, through B for
// skin vertices on the core). Those cross blocks follow the contact set, so the soft pattern
// changes between evaluations (SparseCholesky::AnalyzeIfChanged); the rigid pattern never does.
//
// Hessians: a skin spring adds the 3x3 block of its skin vertex; a support spring (a support
// vertex inside the skin) adds the block over the skin vertices its anchor slides on —
// exact for HessianKind::kExact (the adjoint), projected to positive semi-definite spring by
// spring for kProjectedPsd (Newton's fallback), as IPC's per-pair projection. With a soft
// support each spring's whole block (point and feature) is used, projected as one.
//
// Not thread-safe on one object (the skin's search tree and a soft support's deformed
// surface move with every evaluation): one per thread; copies are independent.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "ergo/body/elastic_part.h"
#include "ergo/body/reduced_system.h"
#include "ergo/contact/support.h"
#include "ergo/contact/surface_contact.h"

namespace ergo {

class TotalPotential {
 public:
  struct Evaluation {
    Vertices positions;               // all body tet-mesh vertices, m
    Vertices support_positions;       // a soft support's tet-mesh vertices, m (empty: rigid)
    SurfaceContacts contacts;         // both kinds of spring and the per-vertex forces
    ReducedSystem::Evaluation body;   // body terms; contact added; its K̂ block in body.hessian
    ElasticPart::Evaluation support;  // a soft support's own terms plus its contact forces
    SparseMatrix coupled_hessian;     // with a soft support: the whole K̂
    Eigen::VectorXd gradient;         // ∂E/∂y (reduced), N and N·m
    double energy = 0;                // J
    double assembly_seconds = 0;      // elastic assembly + reduction
    double contact_seconds = 0;       // collision detection + springs
    // K̂ over all of y: the body's block alone for a rigid support.
    SparseMatrix& hessian() {
      return support_positions.rows() > 0 ? coupled_hessian : body.hessian;
    }
    const SparseMatrix& hessian() const {
      return support_positions.rows() > 0 ? coupled_hessian : body.hessian;
    }
  };

  // Keeps a reference to `body` (must outlive this). options.stiffness = κ > 0, Pa/m.
  // `soft_support`: the support as a deformable part (null: rigid). Its boundary is then the
  // contact surface, and the Support passed to the evaluations must be that boundary at rest
  // (SoftSupportSurface).
  TotalPotential(const LayeredBody& body, const SurfaceContactOptions& options,
                 std::shared_ptr<const ElasticPart> soft_support = nullptr);
  TotalPotential(const TotalPotential& other) = default;
  TotalPotential& operator=(const TotalPotential&) = delete;

  const ReducedSystem& system() const { return system_; }
  const ReducedLayout& layout() const { return system_.layout(); }
  const LayeredBody& body() const { return system_.body(); }
  const ElasticPart* soft_support() const { return soft_support_.get(); }
  // Another rest shape of the same soft support (same topology and DOFs: a design step).
  void set_soft_support(std::shared_ptr<const ElasticPart> part);
  Eigen::Index size() const { return layout().size(); }
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

  // The surface the skin touched in the last evaluation: `support` itself when rigid, the
  // soft support's deformed boundary otherwise.
  const Support& ContactSurface(const Support& support) const;

  // The state moved by a reduced step (ReducedLayout::Retract).
  BodyState Retract(const BodyState& state, const Eigen::VectorXd& step) const {
    return layout().Retract(state, step);
  }
  // An upper bound on how far the step moves any vertex relative to the other part: the
  // body's largest linearised vertex move plus the soft support's largest, m.
  double LargestMove(const BodyState& state, const Vertices& positions,
                     const Eigen::VectorXd& step) const;
  // α·M̂ added to a K̂ of this potential: the body's reduced lumped mass and the soft
  // support's vertex masses (ReducedSystem::AddScaledMass).
  void AddScaledMass(double alpha, const BodyState& state, const Vertices& positions,
                     SparseMatrix* hessian) const;
  // M̂ alone, upper triangle (for scaling regularisations).
  SparseMatrix Mass(const BodyState& state, const Vertices& positions) const;

  // The rest-shape term of a soft support's design gradient (paper Eq. 22–23): zᵀ ∂G/∂X, the
  // change of the reduced residual G = ∂E/∂y contracted with an adjoint vector z (size()),
  // per unit of the soft support's rest positions X, every deformed position held fixed
  // (so the held base, whose positions are its rest positions, must not be designed). Terms:
  // the foam's element forces and weight (ElasticPart::RestShapeAdjoint) and the support
  // springs' stiffness, proportional to their vertices' rest areas. `e`: an evaluation at the
  // state z belongs to. #V_support x 3, N.
  Vertices RestShapeAdjoint(const BodyState& state, const Eigen::VectorXd& z,
                            const Evaluation& e) const;

  // Residual norm used for convergence: sqrt(Σ forces² + Σ (torques / L)²) with L the
  // core's lever length (largest attached-vertex distance from the core centre), so that
  // torques are measured as the equivalent force at the core's rim; a soft support's free
  // vertices' forces count as forces. N.
  double ResidualNorm(const Eigen::VectorXd& gradient) const;
  double lever_length() const { return lever_length_; }

 private:
  // The soft support's vertex positions at `state`, and its boundary moved there.
  Vertices SupportPositions(const BodyState& state) const;
  const Support& MoveSoftSurface(const Vertices& support_positions, const Support& support) const;
  // A soft support's own terms and both sides of every spring: forces into the body's and
  // the support's vertex gradients, the body's Hessian blocks into e->body; returns the
  // support's block and the cross blocks of K̂ as triplets (with_hessian).
  std::vector<Eigen::Triplet<double>> AddSoftSupportTerms(const BodyState& state, HessianKind kind,
                                                          bool with_hessian, Evaluation* e) const;

  ReducedSystem system_;
  mutable SurfaceContact contact_;  // its skin tree follows the evaluated state
  std::shared_ptr<const ElasticPart> soft_support_;
  mutable std::optional<Support> soft_surface_;  // the soft support's deformed boundary
  double lever_length_ = 1;
};

// The body-side Hessian block of a support spring (a support vertex inside the skin): over
// its anchor's skin vertices, in Feature order (3n x 3n), exact or projected to PSD.
Eigen::MatrixXd SkinFeatureHessian(const Contact& support_spring, bool project_psd);

// A soft support's boundary at rest as the Support its evaluations take.
Support SoftSupportSurface(const ElasticPart& part, const std::string& name = "soft support");

}  // namespace ergo

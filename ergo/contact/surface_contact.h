// SurfaceContact: the two-way, area-weighted penalty contact between a deformable body's
// closed skin and a closed support (paper Eq. 10 at the vertices of both surfaces; DESIGN.md
// §8, after IPC Toolkit's convergent formulation). The model's contact pressure is p = κ·g,
// g the local penetration and κ the contact stiffness in Pa/m; its energy ∫ ½κg² dA is
// integrated by vertex quadrature on both surfaces, a share α of it on the skin's vertices
// and 1 − α on the support's: every skin vertex strictly inside the support and every
// support vertex strictly inside the skin gets a sliding-anchor spring E = k‖p − π‖²
// towards the other surface with k = ½ κ α s (skin) or ½ κ (1 − α) s (support), s the
// vertex's barycentric area (the skin's at rest, the support's at its current shape). A
// vertex's spring force is then α p s (or (1 − α) p s): a fraction of its share p·s of the
// pressure field, and p = κg sampled at either surface's vertices does not depend on either
// mesh's resolution.
//
// The share is ½ (IPC's symmetric form) unless the support is much coarser than the skin:
// with r = ā_support/ā_skin (ā the typical vertex areas near the contact), α = r/(r + 4)
// once r > 4 (support spacing over twice the skin's), so that a coarse support vertex inside
// a small contact patch does not weigh its whole area (the master/slave rule of
// node-to-surface contact). Not the other way round: each side's vertex quadrature has its
// own error where the patch is only a few skin vertices wide (rim vertices weigh area that
// is not in contact), and shifting the share with the support's spacing would move the
// equilibrium with it, where a fixed ½ converges as the support is refined. α is fixed per
// problem, so it adds no derivative (ContactSkinShare).
//
// The same springs serve the equilibrium (energy, forces, Hessian blocks) and the score (the
// pressure κg at every vertex of both surfaces, the paper's bi-directional pressures), so the
// score and the physics see one contact. Scoring the total nodal force instead would not do:
// a coarse side's springs load a finer side's vertices in spikes (a skin vertex's reaction
// lands on one small support triangle). Units: m, m², Pa/m, N/m, N, J.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "ergo/contact/contact_set.h"
#include "ergo/contact/support.h"

namespace ergo {

struct SurfaceContactOptions {
  double stiffness = 1e8;  // κ, Pa/m: contact pressure per metre of penetration
  // α, the skin's share of the quadrature, in (0, 1); 0: ContactSkinShare of the skin and of
  // the first support evaluated.
  double skin_share = 0;
  // false: the support's vertices inside the skin are sampled for the score (p = κg there)
  // but exert no force, and the skin's springs carry the whole quadrature (α = 1): the
  // paper's uni-directional equilibrium with its bi-directional score, under one pressure law
  // (the equilibrium's default, EquilibriumOptions::contact_support_springs).
  bool support_springs = true;
};

// α = max(½, r/(r + 4)) (at most 0.99), r = ā_support/ā_skin the ratio of the median
// barycentric vertex areas of the support's vertices flagged in `region` (all if empty) and
// of the skin (`skin_areas`).
double ContactSkinShare(const Eigen::VectorXd& skin_areas, const Eigen::VectorXd& support_areas,
                        const std::vector<bool>& region = {});

// The springs between skin and support at one configuration, and the resulting forces.
struct SurfaceContacts {
  // Skin vertices inside the support: point = body (tet-mesh) vertex id, feature = support
  // vertex ids.
  ContactSet skin;
  // Support vertices inside the skin: point = support vertex id, feature = skin-local ids.
  ContactSet support;
  // Total contact force on every skin vertex (skin-local order) and every support vertex,
  // from both kinds of spring (own spring and reactions of the other side's), N: the forces
  // the equilibrium applies.
  Vertices skin_force;
  Vertices support_force;
  // p·s per vertex with p = κg from the vertex's own spring (0 outside the other surface):
  // its share of the contact pressure field, N (its own spring's force over its side's
  // share). Pressure = load / area. α Σ_skin + (1 − α) Σ_support of the loads is the total
  // contact force's magnitude where all contact normals agree.
  Eigen::VectorXd skin_load;
  Eigen::VectorXd support_load;
  // The fraction of κ·s/2 each side's springs use: α and 1 − α (two-way), or 1 and the ½ of
  // the score-only support samples.
  double skin_share = 0.5, support_share = 0.5;
  bool support_springs = true;  // whether the support springs act in the equilibrium
  // Whether `support` and `support_load` hold the support's samples. Only score-only samples
  // (one-way) may be left out, by an Evaluate that does not need them (a Newton iteration);
  // SurfaceContact::AddSupportSamples fills them in at the same positions.
  bool support_sampled = true;
  double energy = 0;           // J
  double max_penetration = 0;  // m: the skin's, and the support's too when its springs push

  // Springs that push in the equilibrium (one-way, the support's samples are scored only).
  int springs() const { return skin.size() + (support_springs ? support.size() : 0); }
  // Σ of the contact forces on the body, N.
  Eigen::Vector3d TotalForceOnBody() const;
  // Skin vertices inside the support (p > 0).
  int skin_vertices_in_contact() const;
  // Stiffness of the contacts against a rigid translation of the body: Σ over springs of
  // the Hessian block of the body-side variables summed over them (needs the Hessians).
  Eigen::Matrix3d TranslationStiffness() const;
};

class SurfaceContact {
 public:
  // `skin_rest`: the closed skin with skin-local vertex ids; body_ids[l] is the body vertex
  // of skin vertex l; `skin_areas` its rest barycentric areas (m²). Throws InputError if the
  // skin is not a closed, outward, manifold surface (two-way contact needs its inside).
  SurfaceContact(const TriMesh& skin_rest, Eigen::VectorXi body_ids, Eigen::VectorXd skin_areas,
                 const SurfaceContactOptions& options);
  // Copies own their skin tree and query state (one copy per thread).
  SurfaceContact(const SurfaceContact& other);
  SurfaceContact& operator=(const SurfaceContact&) = delete;

  const SurfaceContactOptions& options() const { return options_; }
  double stiffness() const { return options_.stiffness; }
  void set_stiffness(double kappa);
  // α (0 until the first evaluation when it is chosen automatically).
  double skin_share() const { return options_.skin_share; }

  // The springs at body positions `body_positions` (every tet-mesh vertex, #V x 3) against
  // `support`. with_hessian keeps each spring's Hessian. `hints`: per body vertex previous
  // anchors on the support (see EvaluateContacts), may be null. Moves the skin tree to the
  // body's positions: not thread-safe on one object.
  // With one-way contact, with_support_samples = false leaves the score-only support samples
  // out (they change no energy, force or Hessian): out->support_sampled is then false.
  void Evaluate(const Vertices& body_positions, const Support& support, bool with_hessian,
                std::vector<SupportPoint>* hints, SurfaceContacts* out,
                bool with_support_samples = true);
  // Fills in the support's samples that an Evaluate at the same `body_positions` left out
  // (nothing if out->support_sampled): the same samples, bit for bit, as an Evaluate with them.
  void AddSupportSamples(const Vertices& body_positions, const Support& support, bool with_hessian,
                         SurfaceContacts* out);
  // The contact energy only (line searches), J.
  double Energy(const Vertices& body_positions, const Support& support,
                std::vector<SupportPoint>* hints);

  // The skin as last moved to sample the support (the rest skin before the first).
  const Support& skin() const { return skin_; }
  const Eigen::VectorXi& body_ids() const { return body_ids_; }
  const Eigen::VectorXd& skin_areas() const { return skin_areas_; }

 private:
  // Chooses α on first use when it is automatic (0).
  void ChooseSkinShare(const Support& support);
  void MoveSkin(const Vertices& body_positions, const Support& support);
  // The support's springs or samples and their loads (and forces, when they push).
  void SampleSupport(const Vertices& body_positions, const Support& support, bool with_hessian,
                     SurfaceContacts* out);
  ContactSet SupportSprings(const Support& support, bool with_hessian);

  Support skin_;
  Eigen::VectorXi body_ids_;
  Eigen::VectorXd skin_areas_;
  SurfaceContactOptions options_;
  Eigen::Index body_vertex_count_ = 0;
  // Conservative advancement for the support's vertices against the moving skin: a lower
  // bound on each one's distance to the skin (0 = unknown). The skin moves at most the
  // largest skin-vertex displacement between evaluations, and a support vertex by its own
  // displacement when the support changes (a design step), so a vertex whose bound exceeds
  // both is still outside and needs no query.
  Eigen::VectorXd clearance_;
  std::vector<SupportPoint> skin_hints_;  // per support vertex: last closest skin point
  Vertices skin_positions_;               // skin vertex positions the bounds refer to
  Vertices support_positions_;            // support vertex positions the bounds refer to
  std::uint64_t support_shape_ = 0;       // the support shape the bounds refer to
};

}  // namespace ergo

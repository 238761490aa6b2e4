// The two geometric designers the paper compares against (§7–§8; solvers/README.md
// "Baselines" says what was followed and where a choice was made):
//
// Sit & Relax (Leimer et al. 2016): the rigid body's negative-image pressure map — the skin
// pushed `negative_image_depth` into the flat support, pressure κ·penetration — frozen at
// the start; the designed support is raised towards the body's surface (the body resting on
// it), each vertex weighted by that pressure, against a smoothness term (support_fit.h).
//
// Pose to Seat (Leimer et al. 2020): the contact set assumed (every downward-facing skin
// vertex, or those within `contact_distance` of the support with the body resting on it),
// the pressure over it that balances the body's load and moments on its free degrees of
// freedom without elasticity (as even as the balance allows, p ≥ 0, a Ceres least-squares
// problem), and the support fitted to the body with those pressures as weights.
//
// Neither solves an equilibrium: their supports are scored afterwards by ergo's own
// simulation, the body placed afresh, like any design.
#pragma once

#include <string>

#include <ceres/cost_function.h>
#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/design/design_problem.h"
#include "solvers/support_fit.h"

namespace ergo {

struct BaselineOptions {
  double negative_image_depth = 0.05;  // Sit & Relax, m (the paper's 5 cm)
  double contact_distance = 0;         // Pose to Seat, m; 0 = every downward-facing vertex
  double balance_weight = 1e6;         // Pose to Seat: the balance against evenness
  SupportFitOptions fit;
};

struct BaselineDesign {
  std::string method;            // "sit-and-relax" or "pose-to-seat"
  Eigen::VectorXd x;             // the design, in the problem's parameterisation
  SupportFit fit;                // the fitted support and its misfit
  int weighted_vertices = 0;     // designed support vertices with a target
  int contact_vertices = 0;      // Pose to Seat: skin vertices in the assumed contact set
  double balance_residual = 0;   // Pose to Seat: |force and moment imbalance| / |load|
  std::string Describe() const;  // one line
};

BaselineDesign SitAndRelaxDesign(const DesignProblem& problem, const BodyState& start,
                                 const BaselineOptions& options);
BaselineDesign PoseToSeatDesign(const DesignProblem& problem, const BodyState& start,
                                const BaselineOptions& options);

// Pose to Seat's balance: B p + b over the contact set's pressures p (one parameter block
// of size 1 per vertex), B's rows the free force and moment components per unit pressure
// (scaled by the load), b the load's. Public for the GradientChecker test.
class BalanceResidual : public ceres::CostFunction {
 public:
  BalanceResidual(Eigen::MatrixXd B, Eigen::VectorXd b);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::MatrixXd B_;
  Eigen::VectorXd b_;
};

}  // namespace ergo

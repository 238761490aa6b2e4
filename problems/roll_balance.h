// The foot's roll about its length axis when it stands. A scan is not taken standing level,
// and the shoe's core only pitches, so a scanned foot would stand at whatever roll its
// scanner gave it (the FIND template lands on its lateral column: 39 % of the load under the
// midfoot). Standing, the foot rolls until the load's line of action passes through the
// centre of pressure across the foot as well as along it. That roll is found here once, on
// the flat sole, as the root of the equilibrium's unbalanced torque about the length axis;
// the foot then starts every solve at it (placed afresh too) and the lock holds it.
// SI units; y up, the foot's length along z.
#pragma once

#include <functional>
#include <string>

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/contact/surface_contact.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/tri_mesh.h"
#include "problems/scenario_parts.h"

namespace ergo {

// The torque about the core's centre c of every load on the body except the lock's reaction:
// the contact forces at the skin, gravity on the tissue's lumped masses (the core's weight
// acts at c), the external force (at c) and the external torque. At an equilibrium its free
// components vanish and its locked ones are minus the lock's reaction. N·m.
Eigen::Vector3d UnbalancedTorque(const LayeredBody& body, const BodyState& state,
                                 const Vertices& positions, const SurfaceContacts& contacts);

// The body at rest turned by `roll` (rad) about the z axis through its core's centre; for
// roll 0 the rest state itself, bit for bit (a turn by 0 would round c + (p − c) − p). Place
// it with StartAbove (problems/scenario_parts.h).
BodyState RolledRestState(const LayeredBody& body, double roll);

struct RollBalanceOptions {
  static constexpr double kDegree = 3.14159265358979323846 / 180;
  double tolerance = 0.1 * kDegree;  // rad: the bracket's width at which to stop
  double first_step = 4 * kDegree;   // rad: the first trial roll's size
  double max_roll = 30 * kDegree;    // rad: refuse a foot that needs more
  int max_solves = 14;
  std::function<void(const std::string&)> progress;  // one line per solve
};

struct RollBalance {
  double roll = 0;    // rad about +z
  double torque = 0;  // the unbalanced torque about z there, N·m
  int solves = 0;
  bool converged = false;  // the bracket closed to the tolerance or the torque vanished
  BodyState start;         // the start placement at `roll`
  double seconds = 0;
  std::string BriefReport() const;
};

// Finds the roll at which the body, placed `gap` above `support` and solved to equilibrium
// with its lock (the shoe's: pitch only), carries no torque about the length axis: secant
// steps from 0 until the torque changes sign, then the Illinois rule. Throws InputError
// (source `scenario`) when an equilibrium does not converge or no roll within max_roll
// balances the foot.
RollBalance BalanceRoll(const LayeredBody& body, const TriMesh& support, double gap,
                        const EquilibriumOptions& equilibrium, const RollBalanceOptions& options,
                        const std::string& scenario);

}  // namespace ergo

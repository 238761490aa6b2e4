#include "problems/roll_balance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <utility>
#include <vector>

#include "ergo/contact/support.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180;

std::string Format(const char* format, ...) {
  char text[1024];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(text, sizeof text, format, arguments);
  va_end(arguments);
  return text;
}

}  // namespace

Eigen::Vector3d UnbalancedTorque(const LayeredBody& body, const BodyState& state,
                                 const Vertices& positions, const SurfaceContacts& contacts) {
  const Eigen::Vector3d& c = state.centre;
  Eigen::Vector3d torque = body.options().external_torque;
  const Eigen::VectorXi& skin = body.skin().vertices;
  for (Eigen::Index l = 0; l < skin.size(); ++l) {
    const Eigen::Vector3d arm = positions.row(skin[l]).transpose() - c;
    torque += arm.cross(contacts.skin_force.row(l).transpose());
  }
  const Eigen::VectorXd& mass = body.vertex_mass();
  for (Eigen::Index i = 0; i < positions.rows(); ++i)
    torque += (positions.row(i).transpose() - c).cross(mass[i] * body.gravity());
  return torque;
}

BodyState RolledRestState(const LayeredBody& body, double roll) {
  if (roll == 0) return RestState(body);
  return MovedRigidly(body, RestState(body), Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, roll));
}

std::string RollBalance::BriefReport() const {
  return Format(
      "roll %.2f degrees about the length axis (%d equilibria, %.2g N m left, %s, %.0f s)",
      roll / kDegree, solves, torque, converged ? "balanced" : "not balanced", seconds);
}

RollBalance BalanceRoll(const LayeredBody& body, const TriMesh& support, double gap,
                        const EquilibriumOptions& equilibrium, const RollBalanceOptions& options,
                        const std::string& scenario) {
  const auto begin = std::chrono::steady_clock::now();
  const Support surface(support, scenario + " support");
  EquilibriumSolver solver(body, equilibrium);
  const Vertices& rest = body.rest().vertices;
  // The torque that counts as none: 1e-4 of the load acting across the foot's breadth.
  const double negligible =
      1e-4 * body.TotalLoad().norm() * (rest.col(0).maxCoeff() - rest.col(0).minCoeff());

  RollBalance best;
  struct Trial {
    double roll = 0, torque = 0;
    BodyState start;
  };
  std::vector<double> tried;
  auto solve = [&](double roll) {
    tried.push_back(roll);
    Trial trial{roll, 0, StartAbove(body, RolledRestState(body, roll), support, gap, scenario)};
    const EquilibriumResult result = solver.Solve(surface, trial.start);
    ++best.solves;
    if (!result.converged) {
      throw InputError(scenario, "roll balance",
                       Format("the equilibrium at a roll of %.2f degrees did not converge: %s",
                              roll / kDegree, result.message.c_str()),
                       "give the roll (e.g. --shoe_roll=0) or check the body and the load");
    }
    const TotalPotential::Evaluation& last = solver.last_evaluation();
    trial.torque = UnbalancedTorque(body, result.state, last.positions, last.contacts).z();
    if (options.progress) {
      options.progress(Format("roll balance %d: %.3f degrees, torque about the length %.4g N m",
                              best.solves, roll / kDegree, trial.torque));
    }
    return trial;
  };
  auto finish = [&](const Trial& trial, bool converged) {
    best.roll = trial.roll;
    best.torque = trial.torque;
    best.start = trial.start;
    best.converged = converged;
    best.seconds = SecondsSince(begin);
    return best;
  };

  Trial a = solve(0);
  if (std::abs(a.torque) <= negligible) return finish(a, true);
  // Secant steps from 0 and a first trial towards the torque until the torque changes sign.
  // The roll need not be stable: a foot loaded at its core's centre is an inverted pendulum
  // across its width, held by its contact patch's stiffness, so the torque may grow
  // towards the first trial; the secant then turns back.
  Trial b = solve(a.torque > 0 ? options.first_step : -options.first_step);
  while ((b.torque > 0) == (a.torque > 0)) {
    if (std::abs(b.torque) <= negligible) return finish(b, true);
    const double slope = (b.torque - a.torque) / (b.roll - a.roll);
    double roll = b.roll - b.torque / slope;
    if (!std::isfinite(roll)) roll = b.roll;  // a flat secant: counted as stalled below
    roll = std::max(-options.max_roll, std::min(options.max_roll, roll));
    // No root within reach: the secant comes back to a roll already tried (the range's edge
    // again, or a minimum of the torque that does not reach zero).
    const bool stalled = std::any_of(tried.begin(), tried.end(), [&](double earlier) {
      return std::abs(roll - earlier) < options.tolerance;
    });
    if (stalled || best.solves >= options.max_solves) {
      throw InputError(scenario, "roll balance",
                       Format("no roll within %.0f degrees balances the foot (torque %.3g N m "
                              "at %.1f degrees, %.3g at %.1f)",
                              options.max_roll / kDegree, a.torque, a.roll / kDegree, b.torque,
                              b.roll / kDegree),
                       "check the load point and the scan's axes, or give the roll");
    }
    Trial c = solve(roll);
    // Keep the trial nearer the root as the secant's other end.
    if (std::abs(b.torque) < std::abs(a.torque)) a = std::move(b);
    b = std::move(c);
  }
  if (std::abs(b.torque) <= negligible) return finish(b, true);
  // Illinois: regula falsi that halves the retained end's torque when it is kept twice.
  double torque_a = a.torque;
  while (std::abs(b.roll - a.roll) > options.tolerance && best.solves < options.max_solves) {
    const double roll = (a.roll * b.torque - b.roll * torque_a) / (b.torque - torque_a);
    Trial c = solve(roll);
    if (std::abs(c.torque) <= negligible) return finish(c, true);
    if ((c.torque > 0) != (b.torque > 0)) {
      a = std::move(b);
      torque_a = a.torque;
    } else {
      torque_a *= 0.5;
    }
    b = std::move(c);
  }
  const bool closed = std::abs(b.roll - a.roll) <= options.tolerance;
  return finish(std::abs(a.torque) < std::abs(b.torque) ? a : b, closed);
}

}  // namespace ergo

#include "ergo/design/placement_checks.h"

#include "ergo/mesh/blas_threads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>

#include <omp.h>

namespace ergo {
namespace {

constexpr const char* kAxis[3] = {"x", "y", "z"};

// The unit direction of the body's load (down when it has none).
Eigen::Vector3d LoadDirection(const LayeredBody& body) {
  const Eigen::Vector3d load = body.TotalLoad();
  return load.norm() > 0 ? load.normalized() : Eigen::Vector3d(0, -1, 0);
}

}  // namespace

std::vector<Placement> PlacementChecks(const LayeredBody& body, double shift, double angle,
                                       bool with_tilts) {
  const Eigen::Vector3d down = LoadDirection(body);
  // The two world axes least aligned with the load.
  std::array<int, 3> axes = {0, 1, 2};
  std::sort(axes.begin(), axes.end(),
            [&](int a, int b) { return std::abs(down[a]) < std::abs(down[b]); });
  std::vector<Placement> checks;
  char label[64];
  for (int axis : {std::min(axes[0], axes[1]), std::max(axes[0], axes[1])}) {
    for (double sign : {1.0, -1.0}) {
      Placement p;
      Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
      e = (e - e.dot(down) * down).normalized();
      p.shift = sign * shift * e;
      std::snprintf(label, sizeof(label), "%s%+gmm", kAxis[axis], sign * shift * 1e3);
      p.name = label;
      checks.push_back(p);
    }
  }
  if (with_tilts) {
    const std::vector<Placement> tilts = HeldTilts(body, angle);
    checks.insert(checks.end(), tilts.begin(), tilts.end());
  }
  return checks;
}

std::vector<Placement> HeldTilts(const LayeredBody& body, double angle) {
  std::vector<Placement> tilts;
  if (angle == 0) return tilts;
  const Eigen::Vector3d down = LoadDirection(body);
  char label[64];
  // Only the held rotations: a tilt about a free axis re-settles to the centred
  // equilibrium (the scanned foot's ±1° pitch checks scored its centred φ to 3e-4, and
  // each other to 1e-13), while the lock keeps a tilt about a held axis: the posture a
  // person holds a little differently (the foot rolled, the seated body leaning sideways,
  // the hand turned on the mouse).
  for (int axis = 0; axis < 3; ++axis) {
    if (!body.lock().locked[3 + axis]) continue;
    if (std::abs(down[axis]) > 0.5) continue;  // a yaw about the load: no tilt
    for (double sign : {1.0, -1.0}) {
      Placement p;
      p.tilt = sign * angle * Eigen::Vector3d::Unit(axis);
      std::snprintf(label, sizeof(label), "r%s%+gdeg", kAxis[axis], sign * angle * 180 / M_PI);
      p.name = label;
      tilts.push_back(p);
    }
  }
  return tilts;
}

void ForEachInParallel(int count, const std::function<void(int)>& task) {
  const int cores = std::max(1, omp_get_max_threads());
  const int workers = std::max(1, std::min(count, cores));
  const int inner = std::max(1, cores / workers);
  std::atomic<int> next{0};
  auto work = [&] {
    if (workers > 1) omp_set_num_threads(inner);
    for (int i = next++; i < count; i = next++) task(i);
  };
  if (workers == 1) {
    work();
    return;
  }
  // The tasks' equilibria side by side: one BLAS thread each (ergo/mesh/blas_threads.h).
  const SingleThreadedBlas single_threaded_blas;
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& thread : threads) thread.join();
  omp_set_num_threads(cores);
}

std::vector<DesignEvaluation> EvaluatePlacements(const DesignProblem& problem,
                                                 const Eigen::VectorXd& x,
                                                 const std::vector<Placement>& placements,
                                                 const std::atomic<bool>* stop) {
  std::vector<DesignEvaluation> results(placements.size());
  ForEachInParallel(static_cast<int>(placements.size()), [&](int i) {
    if (stop && stop->load()) {
      results[i].message = "interrupted";
      return;
    }
    DesignProblem placed = PlacedProblem(problem, placements[i]);
    results[i] = placed.Evaluate(x, false);
  });
  return results;
}

DesignProblem PlacedProblem(const DesignProblem& problem, const Placement& placement) {
  DesignProblem placed(problem);
  placed.set_placement(DesignPlacement::kFresh);
  placed.set_start(MovedRigidly(problem.body(), problem.start(), placement.shift, placement.tilt));
  return placed;
}

double MeanPlacedPhi(const DesignProblem& problem, const Eigen::VectorXd& x,
                     const std::vector<Placement>& placements, const std::atomic<bool>* stop,
                     EvaluationTiming* timing, std::string* failure) {
  const std::vector<DesignEvaluation> placed = EvaluatePlacements(problem, x, placements, stop);
  if (timing)
    for (const DesignEvaluation& e : placed) *timing += e.timing;
  if (failure) failure->clear();
  double mean = 0;
  for (size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i].ok) {
      if (failure) *failure = placements[i].name + ": " + placed[i].message;
      return std::numeric_limits<double>::quiet_NaN();
    }
    mean += placed[i].phi / static_cast<double>(placed.size());
  }
  return mean;
}

}  // namespace ergo

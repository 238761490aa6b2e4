#include "ergo/ergonomics/pressure_map_alignment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include <glog/logging.h>

namespace ergo {
namespace {

constexpr double kDegree = M_PI / 180;
// Coarse rotations: every 10°, fine enough that the pattern search's first 4° steps reach
// the optimum from the nearest one.
constexpr int kCoarseRotations = 36;
constexpr int kRefinedStarts = 3;
// Pattern search: first and last steps. The last are far below any measurement's precision
// (a plate's pitch is millimetres) and cost a few dozen evaluations more.
constexpr double kFirstAngleStep = 4 * kDegree, kFirstShiftStep = 0.004;
constexpr double kLastAngleStep = 0.005 * kDegree, kLastShiftStep = 5e-6;
constexpr int kMaxEvaluations = 20000;

// The grid nodes lower + h (i, j) covering [lower, upper].
std::vector<Eigen::Vector2d> GridNodes(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper,
                                       double pitch) {
  const int nx = static_cast<int>(std::ceil((upper.x() - lower.x()) / pitch)) + 1;
  const int nz = static_cast<int>(std::ceil((upper.y() - lower.y()) / pitch)) + 1;
  // Callers bound the grid (ergo_validate refuses more than 5 million nodes before any work).
  CHECK_LE(static_cast<double>(nx) * static_cast<double>(nz), 1e8) << "alignment grid too large";
  std::vector<Eigen::Vector2d> nodes;
  nodes.reserve(static_cast<size_t>(nx) * nz);
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) nodes.push_back(lower + pitch * Eigen::Vector2d(i, j));
  return nodes;
}

class AlignmentObjective {
 public:
  AlignmentObjective(const PlanarPressureMap& simulated, const PlanarPressureMap& measured,
                     const AlignmentOptions& options)
      : measured_(measured), options_(options) {
    Eigen::Vector2d lower, upper;
    simulated.Bounds(&lower, &upper);
    for (const Eigen::Vector2d& q : GridNodes(lower, upper, options.grid_pitch)) {
      const double a = Transform(simulated.PressureAt(q));
      if (a > 0) {
        nodes_.push_back(q);
        simulated_values_.push_back(a);
      }
    }
    measured.Bounds(&lower, &upper);
    double measured_sum = 0;
    for (const Eigen::Vector2d& q : GridNodes(lower, upper, options.grid_pitch)) {
      const double b = Transform(measured.PressureAt(q));
      measured_sum += footprint() ? b : b * b;
    }
    double simulated_sum = 0;
    for (double a : simulated_values_) simulated_sum += footprint() ? a : a * a;
    normaliser_ =
        footprint() ? simulated_sum + measured_sum : std::sqrt(simulated_sum * measured_sum);
  }

  // The score of the measured map placed by `motion` (measured frame → simulated frame).
  double operator()(const RigidMotion2d& motion) {
    ++evaluations_;
    if (!(normaliser_ > 0)) return 0;
    const RigidMotion2d inverse = motion.Inverse();
    const Eigen::Matrix2d rotation = inverse.Rotation();
    double overlap = 0;
    for (size_t k = 0; k < nodes_.size(); ++k) {
      const Eigen::Vector2d source = rotation * nodes_[k] + inverse.translation;
      overlap += simulated_values_[k] * Transform(measured_.PressureAt(source));
    }
    return (footprint() ? 2 * overlap : overlap) / normaliser_;
  }
  int evaluations() const { return evaluations_; }

 private:
  bool footprint() const { return options_.score == AlignmentScore::kFootprint; }
  double Transform(double pressure) const {
    if (!footprint()) return std::max(pressure, 0.0);
    return std::clamp(pressure / options_.footprint_threshold, 0.0, 1.0);
  }

  const PlanarPressureMap& measured_;
  AlignmentOptions options_;
  std::vector<Eigen::Vector2d> nodes_;
  std::vector<double> simulated_values_;
  double normaliser_ = 0;
  int evaluations_ = 0;
};

struct Candidate {
  double angle = 0;
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  double score = -1;
};

}  // namespace

const char* AlignmentModeName(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::kNone:
      return "none";
    case AlignmentMode::kTranslation:
      return "translation";
    case AlignmentMode::kRigid:
      return "rigid";
  }
  return "?";
}

bool ParseAlignmentMode(const std::string& name, AlignmentMode* mode) {
  for (AlignmentMode m :
       {AlignmentMode::kNone, AlignmentMode::kTranslation, AlignmentMode::kRigid}) {
    if (name == AlignmentModeName(m)) {
      *mode = m;
      return true;
    }
  }
  return false;
}

const char* AlignmentScoreName(AlignmentScore score) {
  return score == AlignmentScore::kFootprint ? "footprint" : "pressure";
}

bool ParseAlignmentScore(const std::string& name, AlignmentScore* score) {
  for (AlignmentScore s : {AlignmentScore::kFootprint, AlignmentScore::kPressure}) {
    if (name == AlignmentScoreName(s)) {
      *score = s;
      return true;
    }
  }
  return false;
}

Eigen::Vector2d PressureCentroid(const PlanarPressureMap& map) {
  const Eigen::VectorXd force = map.sample_pressure().cwiseMax(0.0).cwiseProduct(map.sample_area());
  const double total = force.sum();
  if (!(total > 0)) return Eigen::Vector2d::Zero();
  return (map.sample_points().transpose() * force) / total;
}

std::string PressureMapAlignment::Describe(const PlanarPressureMap& measured) const {
  const Eigen::Vector2d centre = PressureCentroid(measured);
  const Eigen::Vector2d shift = motion.Apply(centre) - centre;
  std::ostringstream out;
  out << "rotated " << motion.angle / kDegree
      << "° about the measured centre of pressure and shifted (" << 1e3 * shift.x() << ", "
      << 1e3 * shift.y() << ") mm; score " << initial_score << " -> " << score << " ("
      << evaluations << " evaluations)";
  return out.str();
}

PressureMapAlignment AlignPressureMaps(const PlanarPressureMap& simulated,
                                       const PlanarPressureMap& measured,
                                       const AlignmentOptions& options) {
  CHECK_GT(options.grid_pitch, 0);
  if (options.score == AlignmentScore::kFootprint) CHECK_GT(options.footprint_threshold, 0);
  AlignmentObjective objective(simulated, measured, options);
  PressureMapAlignment result;
  result.initial_score = objective(RigidMotion2d());
  result.score = result.initial_score;
  if (options.mode == AlignmentMode::kNone) {
    result.evaluations = objective.evaluations();
    return result;
  }
  const Eigen::Vector2d centre = PressureCentroid(measured);
  const Eigen::Vector2d matched = PressureCentroid(simulated) - centre;
  auto motion_of = [&](const Candidate& c) {
    return RigidMotion2d::About(centre, c.angle, c.shift);
  };
  const bool rigid = options.mode == AlignmentMode::kRigid;

  std::vector<Candidate> starts;
  for (int k = 0; k < (rigid ? kCoarseRotations : 1); ++k) {
    Candidate c;
    c.angle = 2 * M_PI * k / kCoarseRotations;
    c.shift = matched;
    c.score = objective(motion_of(c));
    starts.push_back(c);
  }
  std::sort(starts.begin(), starts.end(),
            [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  starts.resize(std::min<size_t>(starts.size(), kRefinedStarts));

  Candidate best;
  best.score = result.initial_score;  // identity stays when nothing beats it
  for (Candidate current : starts) {
    double angle_step = rigid ? kFirstAngleStep : 0, shift_step = kFirstShiftStep;
    while ((angle_step >= kLastAngleStep || shift_step >= kLastShiftStep) &&
           objective.evaluations() < kMaxEvaluations) {
      bool improved = false;
      const std::array<std::array<double, 3>, 6> moves = {
          {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
      for (const auto& move : moves) {
        if (move[0] != 0 && !rigid) continue;
        Candidate trial = current;
        trial.angle += move[0] * angle_step;
        trial.shift += shift_step * Eigen::Vector2d(move[1], move[2]);
        trial.score = objective(motion_of(trial));
        if (trial.score > current.score) {
          current = trial;
          improved = true;
        }
      }
      if (!improved) {
        angle_step *= 0.5;
        shift_step *= 0.5;
      }
    }
    if (current.score > best.score) best = current;
  }
  if (best.score > result.initial_score) {
    best.angle = std::remainder(best.angle, 2 * M_PI);
    result.motion = motion_of(best);
    result.score = best.score;
  }
  result.evaluations = objective.evaluations();
  return result;
}

}  // namespace ergo

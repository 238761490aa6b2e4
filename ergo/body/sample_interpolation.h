// Scattered measurements over a body part (paper §3.1: layer depth and Young's modulus
// measured at a few dozen points) and their interpolation: a polyharmonic spline
// s(x) = Σ w_i ‖x − x_i‖³ + affine(x), exact at the samples and C², clamped to the
// samples' range. Positions in metres; values in their own unit (m for depth, Pa for E).
// The scheme and its fallbacks are documented in ergo/body/README.md.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Samples as read from a CSV file.
struct PointSamples {
  Vertices points;         // #S x 3, metres
  Eigen::VectorXd values;  // #S
  std::vector<int> lines;  // 1-based source line of each sample, 0 for one from no file
                           // (empty if none came from a file)
  std::string source;      // file name, for messages
};

struct SampleCsvOptions {
  LengthUnit unit = LengthUnit::kMetre;  // unit of x, y, z (and of the value if it is a length)
  bool value_is_length = false;          // depth: true (scaled by `unit`); E: false
  std::string value_name = "value";      // for messages: "depth", "Young's modulus"
  std::string value_unit = "";           // for messages: "m", "Pa"
};

// Reads "x,y,z,value" lines: an optional header line (non-numeric first line), '#'
// comments and blank lines skipped, exactly four finite numbers per line, value > 0.
// Throws InputError naming the file and line otherwise, or when there is no sample.
PointSamples ReadPointSamplesCsv(const std::string& path, const SampleCsvOptions& options);

// The interpolant. Evaluation is const and thread-safe.
class SampleInterpolant {
 public:
  // A constant field (no samples).
  static SampleInterpolant Constant(double value);

  // Fits the spline through the samples. Exact duplicates (same position and value) are
  // merged; two samples closer than 1e-9 of the cloud's extent with different values are
  // an InputError naming both (their lines, when known). Needs at least one sample.
  static SampleInterpolant Fit(const PointSamples& samples);

  // The clamped value at p: min(max(s(p), min sample), max sample).
  double operator()(const Eigen::Vector3d& p) const;
  // s(p) without clamping (for tests of exactness and smoothness).
  double Unclamped(const Eigen::Vector3d& p) const;

  double min_value() const { return min_value_; }
  double max_value() const { return max_value_; }
  int sample_count() const { return static_cast<int>(centres_.rows()); }
  // Dimension of the samples' affine hull that the linear term spans (0..3).
  int hull_dimension() const { return hull_dimension_; }
  // One line: "constant 0.02", or "r³ spline through 6 samples, linear term in 3-D".
  std::string Describe() const;

 private:
  double constant_ = 0;                              // used when there are no centres
  Vertices centres_;                                 // scaled coordinates of the (merged) samples
  Eigen::VectorXd weights_;                          // one per centre
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();  // x' = (x − shift) / scale
  double scale_ = 1;
  Eigen::Matrix<double, 3, Eigen::Dynamic> basis_;  // hull directions (3 x d, columns)
  Eigen::VectorXd polynomial_;                      // 1 + d coefficients
  int hull_dimension_ = 0;
  double min_value_ = 0, max_value_ = 0;
};

}  // namespace ergo

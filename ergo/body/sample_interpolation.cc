#include "ergo/body/sample_interpolation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>
#include <string_view>

#include <glog/logging.h>
#include <Eigen/Dense>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

// Splits a CSV row at commas (semicolons and tabs accepted too), trimming blanks and '\r'.
// Unlike a flag's list (SplitList), a row that ends with a separator has an empty last
// column, so "1,2,3,4," is reported as five columns.
std::vector<std::string> SplitCsv(std::string_view line) {
  std::string row(line);
  std::replace_if(
      row.begin(), row.end(), [](char c) { return c == ';' || c == '\t'; }, ',');
  std::vector<std::string> fields = SplitList(row, ',');
  if (row.empty() || row.back() == ',') fields.emplace_back();
  for (std::string& field : fields) {
    const size_t first = field.find_first_not_of(" \r");
    if (first == std::string::npos) {
      field.clear();
      continue;
    }
    field = field.substr(first, field.find_last_not_of(" \r") - first + 1);
  }
  return fields;
}

std::string Trim(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return std::string(text);
}

std::string Where(const PointSamples& samples, int i) {
  if (i < static_cast<int>(samples.lines.size())) {
    // Line 0: a sample that came from no file (an anatomical prior merged with the file's).
    if (samples.lines[i] > 0) return "line " + std::to_string(samples.lines[i]);
    return "prior sample " + std::to_string(i);
  }
  return "sample " + std::to_string(i);
}

}  // namespace

PointSamples ReadPointSamplesCsv(const std::string& path, const SampleCsvOptions& options) {
  const std::string columns = "x,y,z," + options.value_name;
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error) &&
      std::filesystem::file_size(path, error) == 0) {
    throw InputError(path, "", "the file is empty: no samples",
                     "write one line " + columns + " per sample");
  }
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  const double metres = MetresPerUnit(options.unit);
  std::vector<double> xyz, values;
  std::vector<int> lines;
  bool first = true;
  std::string_view line;
  while (reader.NextLine(&line)) {
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    const std::vector<std::string> fields = SplitCsv(trimmed);
    double number[4];
    bool numeric = fields.size() == 4;
    for (size_t k = 0; numeric && k < 4; ++k) numeric = ParseDouble(fields[k], &number[k]);
    if (first && !numeric) {
      // A header: any non-numeric first line with four fields.
      first = false;
      if (fields.size() != 4) {
        reader.Fail("expected 4 comma-separated columns (" + columns + "), found " +
                        std::to_string(fields.size()),
                    "write one sample per line as " + columns);
      }
      bool any_number = false;
      for (size_t k = 0; k < 4; ++k) any_number = any_number || ParseDouble(fields[k], &number[k]);
      if (!any_number) continue;
    }
    first = false;
    if (fields.size() != 4) {
      reader.Fail("expected 4 comma-separated columns (" + columns + "), found " +
                      std::to_string(fields.size()),
                  "write one sample per line as " + columns);
    }
    static const char* kNames[3] = {"x", "y", "z"};
    for (size_t k = 0; k < 4; ++k) {
      const std::string name = k < 3 ? kNames[k] : options.value_name;
      if (!ParseDouble(fields[k], &number[k])) {
        reader.Fail(name + " " + Quote(fields[k]) + " is not a number",
                    "write plain decimal numbers such as 0.12 or 1.5e-2 (no units)");
      }
      if (!std::isfinite(number[k])) {
        reader.Fail(name + " " + Quote(fields[k]) + " is not finite", "give a finite number");
      }
    }
    if (!(number[3] > 0)) {
      reader.Fail(options.value_name + " " + Quote(fields[3]) + " is not positive",
                  "every " + options.value_name + " must be > 0" +
                      (options.value_unit.empty() ? "" : " (" + options.value_unit + ")"));
    }
    for (int k = 0; k < 3; ++k) xyz.push_back(number[k] * metres);
    values.push_back(options.value_is_length ? number[3] * metres : number[3]);
    lines.push_back(reader.line_number());
  }
  if (values.empty()) {
    throw InputError(path, "", "no samples found",
                     "write at least one line " + columns + " (a header line is optional)");
  }
  PointSamples samples;
  samples.source = path;
  samples.lines = std::move(lines);
  const auto count = static_cast<Eigen::Index>(values.size());
  samples.points = Eigen::Map<const Vertices>(xyz.data(), count, 3);
  samples.values = Eigen::Map<const Eigen::VectorXd>(values.data(), count);
  return samples;
}

SampleInterpolant SampleInterpolant::Constant(double value) {
  SampleInterpolant s;
  s.constant_ = value;
  s.min_value_ = s.max_value_ = value;
  return s;
}

SampleInterpolant SampleInterpolant::Fit(const PointSamples& samples) {
  const Eigen::Index n_in = samples.points.rows();
  CHECK_EQ(samples.values.size(), n_in);
  const std::string source = samples.source.empty() ? "samples" : samples.source;
  if (n_in == 0) throw InputError(source, "", "no samples", "give at least one sample");

  // Scale: centre on the mean, divide by the largest extent, so the linear system does not
  // depend on the unit. The r³ spline space with an affine term is invariant under this
  // similarity, so the interpolant itself is unchanged.
  const Eigen::Vector3d lo = samples.points.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = samples.points.colwise().maxCoeff().transpose();
  const double extent = (hi - lo).maxCoeff();

  // Merge duplicates (within 1e-9 of the extent); conflicting values are a user error.
  std::vector<Eigen::Index> order(static_cast<size_t>(n_in));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return samples.points(a, 0) < samples.points(b, 0);
  });
  const double tolerance = 1e-9 * std::max(extent, 1e-300);
  std::vector<bool> dropped(static_cast<size_t>(n_in), false);
  for (size_t i = 0; i < order.size(); ++i) {
    const Eigen::Index a = order[i];
    if (dropped[a]) continue;
    for (size_t j = i + 1; j < order.size(); ++j) {
      const Eigen::Index b = order[j];
      if (samples.points(b, 0) - samples.points(a, 0) > tolerance) break;
      if (dropped[b] || (samples.points.row(a) - samples.points.row(b)).norm() > tolerance)
        continue;
      const double va = samples.values[a], vb = samples.values[b];
      if (std::abs(va - vb) > 1e-12 * std::max(std::abs(va), std::abs(vb))) {
        std::ostringstream what;
        what << "samples at " << Where(samples, static_cast<int>(std::min(a, b))) << " and "
             << Where(samples, static_cast<int>(std::max(a, b)))
             << " are at the same position but have different values (" << va << ", " << vb << ")";
        throw InputError(source, Where(samples, static_cast<int>(std::max(a, b))), what.str(),
                         "remove one of them or average them into one sample");
      }
      dropped[b] = true;
    }
  }
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < n_in; ++i)
    if (!dropped[i]) kept.push_back(i);
  const auto n = static_cast<Eigen::Index>(kept.size());

  SampleInterpolant s;
  s.min_value_ = samples.values.minCoeff();
  s.max_value_ = samples.values.maxCoeff();
  if (n == 1) {
    s.constant_ = samples.values[kept[0]];
    return s;
  }

  Eigen::VectorXd values(n);
  Vertices x(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    x.row(i) = samples.points.row(kept[i]);
    values[i] = samples.values[kept[i]];
  }
  s.shift_ = x.colwise().mean().transpose();
  s.scale_ = extent;
  for (Eigen::Index i = 0; i < n; ++i) x.row(i) = (x.row(i) - s.shift_.transpose()) / s.scale_;

  // Affine hull of the samples: principal directions with a singular value above 1e-6 of
  // the largest. Coplanar (or collinear) samples get a linear term in their plane (line)
  // only, which keeps the system non-singular and the spline exact.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(x), Eigen::ComputeThinV);
  const Eigen::VectorXd sigma = svd.singularValues();
  int d = 0;
  while (d < sigma.size() && d < 3 && sigma[d] > 1e-6 * sigma[0]) ++d;
  s.hull_dimension_ = d;
  s.basis_ = svd.matrixV().leftCols(d);

  // Saddle-point system [A P; Pᵀ 0] [w; c] = [values; 0], A_ij = r_ij³, P = [1, x·basis].
  // r³ is conditionally positive definite of order 2 and P has full column rank on the
  // samples (by construction of the basis), so the system is non-singular for distinct
  // samples. It is symmetric indefinite: solved by LU with partial pivoting (n ≤ a few
  // hundred, once).
  const Eigen::Index m = n + 1 + d;
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(m, m);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < i; ++j) {
      const double r = (x.row(i) - x.row(j)).norm();
      system(i, j) = system(j, i) = r * r * r;
    }
    system(i, n) = system(n, i) = 1.0;
    for (int k = 0; k < d; ++k) {
      const double t = x.row(i).dot(s.basis_.col(k).transpose());
      system(i, n + 1 + k) = system(n + 1 + k, i) = t;
    }
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  rhs.head(n) = values;
  Eigen::VectorXd solution = system.partialPivLu().solve(rhs);
  const double scale = std::max(values.cwiseAbs().maxCoeff(), 1e-300);
  if (!solution.allFinite() || (system * solution - rhs).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    solution = system.fullPivLu().solve(rhs);
  }
  CHECK(solution.allFinite()) << "sample interpolation system is singular";
  s.centres_ = x;
  s.weights_ = solution.head(n);
  s.polynomial_ = solution.tail(1 + d);
  return s;
}

double SampleInterpolant::Unclamped(const Eigen::Vector3d& p) const {
  if (centres_.rows() == 0) return constant_;
  const Eigen::Vector3d q = (p - shift_) / scale_;
  double value = polynomial_[0];
  for (int k = 0; k < hull_dimension_; ++k) value += polynomial_[k + 1] * q.dot(basis_.col(k));
  for (Eigen::Index i = 0; i < centres_.rows(); ++i) {
    const double r = (q - centres_.row(i).transpose()).norm();
    value += weights_[i] * r * r * r;
  }
  return value;
}

double SampleInterpolant::operator()(const Eigen::Vector3d& p) const {
  return std::clamp(Unclamped(p), min_value_, max_value_);
}

std::string SampleInterpolant::Describe() const {
  std::ostringstream out;
  if (centres_.rows() == 0) {
    out << "constant " << constant_;
  } else {
    out << "r^3 spline through " << centres_.rows() << " samples, linear term in "
        << hull_dimension_ << "-D, clamped to [" << min_value_ << ", " << max_value_ << "]";
  }
  return out.str();
}

}  // namespace ergo

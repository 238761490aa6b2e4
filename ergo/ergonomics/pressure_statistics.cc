#include "ergo/ergonomics/pressure_statistics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

namespace ergo {

std::string PressureStatistics::BriefReport() const {
  std::ostringstream out;
  out << contact_vertices << " contact vertices, peak " << peak << " Pa, p95 " << percentile95
      << " Pa, mean " << mean << " Pa over " << contact_area * 1e4 << " cm², force " << total_force
      << " N";
  return out.str();
}

PressureStatistics ComputePressureStatistics(const Eigen::VectorXd& pressure,
                                             const Eigen::VectorXd& area, int bins,
                                             double histogram_max) {
  CHECK_EQ(pressure.size(), area.size());
  CHECK_GE(bins, 1);
  PressureStatistics s;
  std::vector<double> values;
  for (Eigen::Index i = 0; i < pressure.size(); ++i) {
    if (!(pressure[i] > 0)) continue;
    values.push_back(pressure[i]);
    s.contact_area += area[i];
    s.total_force += pressure[i] * area[i];
  }
  s.contact_vertices = static_cast<int>(values.size());
  const double top = histogram_max > 0
                         ? histogram_max
                         : (values.empty() ? 1.0 : *std::max_element(values.begin(), values.end()));
  s.bin_edges.resize(static_cast<size_t>(bins) + 1);
  for (int b = 0; b <= bins; ++b) s.bin_edges[b] = top * b / bins;
  s.bin_counts.assign(static_cast<size_t>(bins), 0);
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.peak = values.back();
  // Nearest-rank percentile.
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
  s.percentile95 = values[std::max<size_t>(rank, 1) - 1];
  s.mean = s.total_force / s.contact_area;
  for (double p : values) {
    const int b = std::min(bins - 1, static_cast<int>(p / top * bins));
    if (p <= top) ++s.bin_counts[b];
  }
  return s;
}

}  // namespace ergo

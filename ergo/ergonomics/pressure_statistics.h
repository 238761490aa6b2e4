// What a designer reads off a pressure field (paper Fig. 6–9): peak and 95th-percentile
// pressure, contact area, mean pressure and a histogram. Units: Pa, m², N.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace ergo {

struct PressureStatistics {
  int contact_vertices = 0;       // vertices with P > 0
  double peak = 0;                // max P, Pa
  double percentile95 = 0;        // 95th percentile of P over contact vertices, Pa
  double contact_area = 0;        // Σ s_i over contact vertices, m²
  double total_force = 0;         // Σ P_i s_i = Σ ‖f_i‖, N
  double mean = 0;                // total_force / contact_area, Pa
  std::vector<double> bin_edges;  // histogram of P over contact vertices (bins + 1 edges)
  std::vector<int> bin_counts;
  std::string BriefReport() const;
};

// Statistics of pressures P with areas s; `bins` equal bins on [0, histogram_max] (0 =
// up to the peak).
PressureStatistics ComputePressureStatistics(const Eigen::VectorXd& pressure,
                                             const Eigen::VectorXd& area, int bins = 20,
                                             double histogram_max = 0);

}  // namespace ergo

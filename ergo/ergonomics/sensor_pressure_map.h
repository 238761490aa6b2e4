// The pressure map that point sensors measured on the support (paper §6): each location's
// samples are trimmed (trimmed_statistics.h) to a mean p_i; a reference sensor read at the
// same time gives r_i, and the scale α_i with α_i r_i = C for every i takes out the posture's
// drift between the measurements; the normalised readings p_i / r_i are interpolated onto the
// support's top with linearly precise biharmonic weights, each sensor a handle
// (biharmonic_interpolation.h); negative overshoot of the interpolant is set to zero (contact
// cannot pull); and C is chosen so that the map's total force Σ_v s_v p_v over the top's
// vertices equals the load. Without a reference, α_i = C for all i. Since the readings only
// need to be proportional to pressure, C also stands in for the sensors' calibration.
// Pa, m², N.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/ergonomics/biharmonic_interpolation.h"
#include "ergo/ergonomics/sensor_readings.h"
#include "ergo/ergonomics/support_top_surface.h"
#include "ergo/ergonomics/trimmed_statistics.h"

namespace ergo {

struct SensorMapOptions {
  SampleTrim trim;  // default: the paper's 50 of 600 at each end
  double load = 0;  // N, > 0: the total force the map is scaled to
  BiharmonicOptions interpolation;
};

// One location's estimate.
struct SensorEstimate {
  std::string name;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // (x, z), m
  int first_line = 0;
  long samples = 0, kept = 0;
  double mean = 0, standard_deviation = 0;  // trimmed, in the readings' unit
  bool has_reference = false;
  double reference_mean = 1, reference_standard_deviation = 0;
  double pressure = 0;               // α_i p_i = C p_i / r_i, Pa
  double standard_deviation_pa = 0;  // α_i times the trimmed standard deviation, Pa
};

struct SensorPressureMap {
  std::vector<SensorEstimate> sensors;
  Eigen::VectorXd top_pressure;    // per vertex of the SupportTop, Pa, ≥ 0
  double scale = 0;                // C, Pa per unit of the readings (with a reference: per unit
                                   // of value / reference)
  double lowest_interpolated = 0;  // the interpolant's minimum before the clamp, Pa
  double clamped_area = 0;         // top area where the interpolant was negative, m²
  // Spread of the reference means across the locations (standard deviation / mean): how much
  // the posture varied between the measurements (paper Fig. 13); 0 without a reference.
  double reference_variation = 0;
  double total_force = 0;  // Σ_v s_v p_v, N (= the load)

  std::string BriefReport() const;
};

// Throws InputError naming the readings' file and the sensor's line when a location lies off
// the top, its trim leaves no sample, its reference mean is not positive, the layout cannot
// determine a map (fewer than three locations, all on one line, two at one point) or nothing
// was measured.
SensorPressureMap EstimateSensorPressureMap(const SensorReadings& readings, const SupportTop& top,
                                            const SensorMapOptions& options);

}  // namespace ergo

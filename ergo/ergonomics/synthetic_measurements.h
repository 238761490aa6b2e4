// Synthetic measurements of a pressure map taken as the truth: what a pressure plate and a
// point sensor moved over the support (paper §6) would record. They make ergo_validate's
// round trips testable — the comparison must recover the map they were made from — and let a
// user try the tool without a lab.
//   Plate: the map rotated by θ about its centre of pressure and shifted by s, then laid on
//     a plate of square cells of pitch h (a margin of empty cells around it); each cell reads
//     the mean of the map over its area (n × n point samples), plus Gaussian noise of
//     σ = noise · peak on loaded cells, clamped at 0 (a plate never reads below zero).
//   Sensors: a lattice of pitch d over the support's top (its points that lie on the top);
//     at each location `samples` readings gain · β_i · p(q_i) · (1 + ε), β_i ~ N(1, posture)
//     the posture of that measurement, ε ~ N(0, noise); a share `outliers` of the samples is
//     replaced by spikes (0 or three times the reading: a shifted foot, a tugged cable) half
//     low, half high; the reference sensor, fixed at the map's peak, reads
//     reference_gain · β_i · p(q_ref) · (1 + ε') at the same instants.
// Pa, m; readings in the gains' units per Pa.
#pragma once

#include <cstdint>

#include "ergo/ergonomics/planar_pressure_map.h"
#include "ergo/ergonomics/pressure_grid.h"
#include "ergo/ergonomics/rigid_motion_2d.h"
#include "ergo/ergonomics/sensor_readings.h"
#include "ergo/ergonomics/support_top_surface.h"

namespace ergo {

struct SyntheticPlateOptions {
  double pitch = 0.005;                             // h, m
  double rotation = 0;                              // θ, radians
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // s, m
  double noise = 0.02;                              // σ / peak
  int subsamples = 4;                               // n per side of a cell
  int margin_cells = 2;
  uint32_t seed = 1;
};

struct SyntheticPlate {
  PressureGrid grid;           // origin 0: the plate's own frame
  RigidMotion2d plate_to_map;  // the plate's frame → the map's frame (what alignment must find)
};

SyntheticPlate MakeSyntheticPlate(const PlanarPressureMap& truth,
                                  const SyntheticPlateOptions& options);

struct SyntheticSensorOptions {
  double pitch = 0.015;          // d, m
  int samples = 600;             // per location (the paper: 10 Hz for a minute)
  double noise = 0.05;           // relative, per sample
  double posture = 0.10;         // spread of β_i between locations
  double outliers = 0.04;        // share of spiked samples
  double gain = 1e-5;            // reading per Pa (a Tekscan circuit: ~1 V at 100 kPa)
  double reference_gain = 5e-6;  // the reference sensor's, per Pa
  uint32_t seed = 1;
};

// `truth` in the support's frame (x, z). The readings' source is left empty.
SensorReadings MakeSyntheticSensorReadings(const PlanarPressureMap& truth, const SupportTop& top,
                                           const SyntheticSensorOptions& options);

}  // namespace ergo

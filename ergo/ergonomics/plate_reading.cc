#include "ergo/ergonomics/plate_reading.h"

#include <cmath>

#include <glog/logging.h>

namespace ergo {

Eigen::VectorXd ReadOnCells(const PlanarPressureMap& map, const PlanarPoints& centres, double pitch,
                            double angle, int subsamples) {
  CHECK_GT(pitch, 0);
  CHECK_GE(subsamples, 1);
  RigidMotion2d turn;
  turn.angle = angle;
  const Eigen::Matrix2d rotation = turn.Rotation();
  const int n = subsamples;
  Eigen::VectorXd reading(centres.rows());
  for (Eigen::Index i = 0; i < centres.rows(); ++i) {
    const Eigen::Vector2d centre = centres.row(i).transpose();
    double sum = 0;
    for (int b = 0; b < n; ++b) {
      for (int a = 0; a < n; ++a) {
        const Eigen::Vector2d local =
            pitch * Eigen::Vector2d((a + 0.5) / n - 0.5, (b + 0.5) / n - 0.5);
        sum += map.PressureAt(centre + rotation * local);
      }
    }
    reading[i] = sum / (n * n);
  }
  return reading;
}

PressureGrid ReadOnPlate(const PlanarPressureMap& map, const Eigen::Vector2d& corner, double pitch,
                         Eigen::Index rows, Eigen::Index columns, int subsamples) {
  PressureGrid grid;
  grid.pitch = pitch;
  grid.origin = corner;
  PlanarPoints centres(rows * columns, 2);
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index c = 0; c < columns; ++c)
      centres.row(r * columns + c) = grid.CellCentre(r, c).transpose();
  const Eigen::VectorXd reading = ReadOnCells(map, centres, pitch, /*angle=*/0, subsamples);
  // Row-major cells into the rows x columns matrix.
  grid.pressure =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          reading.data(), rows, columns);
  return grid;
}

PressureGrid ReadOnCoveringPlate(const PlanarPressureMap& map, double pitch,
                                 const Eigen::Vector2d& offset, int margin_cells, int subsamples) {
  CHECK_GT(pitch, 0);
  CHECK_GE(margin_cells, 0);
  Eigen::Vector2d lower, upper;
  map.Bounds(&lower, &upper);
  if (!lower.allFinite() || !upper.allFinite()) {
    return ReadOnPlate(map, Eigen::Vector2d::Zero(), pitch, 0, 0, subsamples);
  }
  const Eigen::Vector2d start = lower - offset;  // the first cell's corner before the margin
  const Eigen::Vector2d corner = start - margin_cells * pitch * Eigen::Vector2d::Ones();
  const auto columns =
      static_cast<Eigen::Index>(std::ceil((upper.x() - start.x()) / pitch)) + 2 * margin_cells;
  const auto rows =
      static_cast<Eigen::Index>(std::ceil((upper.y() - start.y()) / pitch)) + 2 * margin_cells;
  return ReadOnPlate(map, corner, pitch, rows, columns, subsamples);
}

bool LoadSeenAlongY(const Eigen::Vector3d& load) {
  constexpr double kCos10Degrees = 0.985;
  const double magnitude = load.norm();
  return magnitude > 0 && -load.y() >= kCos10Degrees * magnitude;
}

PlanarPressureMap SkinMapFromBelow(const LayeredBody& body, const Vertices& positions,
                                   const Eigen::VectorXd& skin_pressure) {
  const Eigen::VectorXd force = skin_pressure.cwiseProduct(body.skin().rest_areas);
  return PlanarPressureMap::FromVertexForces(body.skin().RestSurface(positions), force,
                                             PlanarPressureMap::Facing::kDown);
}

PlatePeak ComputePlatePeak(const PlanarPressureMap& map, const PlatePeakOptions& options) {
  CHECK_GT(options.pitch, 0);
  CHECK_GE(options.phases, 1);
  PlatePeak peak;
  for (int i = 0; i < options.phases; ++i) {
    for (int j = 0; j < options.phases; ++j) {
      const Eigen::Vector2d offset =
          options.pitch / options.phases * Eigen::Vector2d(static_cast<double>(i), j);
      const PressureGrid grid =
          ReadOnCoveringPlate(map, options.pitch, offset, /*margin_cells=*/0, options.subsamples);
      if (grid.pressure.size() == 0) continue;
      Eigen::Index row = 0, column = 0;
      const double largest = grid.pressure.maxCoeff(&row, &column);
      if (largest > peak.pressure) {
        peak.pressure = largest;
        peak.point = grid.CellCentre(row, column);
      }
    }
  }
  return peak;
}

}  // namespace ergo

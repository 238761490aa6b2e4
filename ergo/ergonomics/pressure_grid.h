// A pressure plate's (or an in-shoe system's) reading: a regular grid of square cells of side
// h (the pitch), each holding the mean contact pressure over its cell. Cell (row r, column c)
// is centred at origin + ((c + ½) h, (r + ½) h) in the plate's own frame, seen from above in
// ergo's convention (y up): columns run along +x, rows along +z. Between cell centres the
// field is bilinear, falling to zero one pitch beyond the outer centres, so that its integral
// is exactly the plate's total force Σ p h². Pa, m, N.
#pragma once

#include <Eigen/Core>

namespace ergo {

struct PressureGrid {
  double pitch = 0;                                  // h, m
  Eigen::MatrixXd pressure;                          // rows x columns, Pa
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // corner of cell (0, 0), m

  Eigen::Index rows() const { return pressure.rows(); }
  Eigen::Index columns() const { return pressure.cols(); }
  Eigen::Vector2d CellCentre(Eigen::Index row, Eigen::Index column) const {
    return origin + pitch * Eigen::Vector2d(static_cast<double>(column) + 0.5,
                                            static_cast<double>(row) + 0.5);
  }
  // The bilinear field at q (plate frame), Pa; 0 beyond one pitch outside the outer centres.
  double PressureAt(const Eigen::Vector2d& q) const;
  // Σ p h², N.
  double TotalForce() const { return pressure.sum() * pitch * pitch; }
};

}  // namespace ergo

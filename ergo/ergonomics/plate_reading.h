// What a pressure plate of square cells reads under a pressure map: each cell the map's mean
// over its area (n × n midpoint samples), as plate and in-shoe sensors average over their
// sensels. Used for synthetic plate exports (synthetic_measurements.h) and for the plate peak
// every equilibrium reports beside ergo's own (equilibrium_report.h).
//
// Why a plate peak: ergo's skin pressure is per skin vertex, and where the field is steep (a
// contact's edge, a layer squeezed against the core) its largest value grows as the mesh
// refines; the barefoot peaks in the literature (about 80–100 kPa standing) are the largest
// cell of a plate with sensels of about 5 mm. The largest cell mean is the comparable figure.
// Pa, m.
#pragma once

#include <Eigen/Core>

#include "ergo/body/layered_body.h"
#include "ergo/ergonomics/planar_pressure_map.h"
#include "ergo/ergonomics/pressure_grid.h"

namespace ergo {

// The plate of `rows` x `columns` cells of side `pitch` whose cell (0, 0) has its corner at
// `corner` (the map's frame; the grid's origin is that corner), each cell the mean of the
// map's field over its subsamples² midpoints.
PressureGrid ReadOnPlate(const PlanarPressureMap& map, const Eigen::Vector2d& corner, double pitch,
                         Eigen::Index rows, Eigen::Index columns, int subsamples);

// The plate that covers the map's bounds, its first cell's corner at lower − offset −
// margin_cells·pitch (each axis), with margin_cells empty cells around the bounds.
PressureGrid ReadOnCoveringPlate(const PlanarPressureMap& map, double pitch,
                                 const Eigen::Vector2d& offset, int margin_cells, int subsamples);

// The map read on given cells: cell i is the square of side `pitch` centred at centres.row(i),
// its sides turned by `angle` (radians) from the map's axes (a plate aligned onto the map by a
// rigid motion); each reading the mean of the map over the cell's subsamples² midpoints.
Eigen::VectorXd ReadOnCells(const PlanarPressureMap& map, const PlanarPoints& centres, double pitch,
                            double angle, int subsamples);

struct PlatePeakOptions {
  double pitch = 0.005;  // sensel side, m (emed-class plates: 4 sensels/cm², 5 mm)
  // Where the cells fall on the map moves the largest cell's reading; the peak is the largest
  // over phases² grids offset by multiples of pitch / phases along each axis.
  int phases = 3;
  int subsamples = 4;
};

struct PlatePeak {
  double pressure = 0;                              // Pa; 0 when the map carries none
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // that cell's centre, the map's frame, m
};

// Whether maps seen along y show a load's pressures faithfully: the load within 10° of −y
// (beyond, the projection foreshortens them by more than 1.5 %, 1 − cos 10°).
bool LoadSeenAlongY(const Eigen::Vector3d& load);

// The skin's contact pressures at `positions` (a deformed tet mesh's vertices) as a plate under
// it reads them: per skin vertex the force the solver applied, `skin_pressure` × its rest area
// (ergo's skin pressure is per area at rest), over the area the vertex covers seen from below
// (PlanarPressureMap::FromVertexForces, facing down).
PlanarPressureMap SkinMapFromBelow(const LayeredBody& body, const Vertices& positions,
                                   const Eigen::VectorXd& skin_pressure);

// The largest cell mean over the grids of `options` (CHECKs pitch > 0, phases ≥ 1,
// subsamples ≥ 1).
PlatePeak ComputePlatePeak(const PlanarPressureMap& map, const PlatePeakOptions& options = {});

}  // namespace ergo

// Shape quality of linear tetrahedra: dihedral angles and the radius ratio
// 3·inradius/circumradius (1 for the regular tet, → 0 for slivers and needles). Used to
// report a built body's mesh quality (ergo_body build) and by mesh checks. Angles in
// degrees; the measures are scale-free.
#pragma once

#include <array>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// The six interior dihedral angles (degrees) at the edges (01, 02, 03, 12, 13, 23).
// Zero for a degenerate tet.
std::array<double, 6> DihedralAngles(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& p2, const Eigen::Vector3d& p3);

// 3·r_in/R_circ, signed like the volume: 1 for a regular tet, negative when inverted,
// 0 when degenerate.
double RadiusRatio(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3);

struct TetQuality {
  int tet_count = 0;
  int non_positive_count = 0;       // tets with volume <= 0 (inverted or flat)
  double min_dihedral_degrees = 0;  // over all tets (a regular tet: 70.53°)
  double max_dihedral_degrees = 0;
  double min_radius_ratio = 0;  // worst element
  double mean_radius_ratio = 0;
  double min_volume = 0, max_volume = 0;  // m³
  double mean_edge_length = 0;            // m, over unique edges
  double min_edge_length = 0, max_edge_length = 0;
};

// Quality over every tet of `mesh` (all zero for an empty mesh).
TetQuality MeasureTetQuality(const TetMesh& mesh);

}  // namespace ergo

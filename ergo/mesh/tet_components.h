// Connected components of a tet mesh: vertices sharing a tet are in one component.
#pragma once

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct TetComponents {
  Eigen::VectorXi vertex_component;  // #V: component of each vertex (−1: in no tet)
  int count = 0;                     // components, numbered by their lowest vertex
};

TetComponents LabelTetComponents(const TetMesh& mesh);

}  // namespace ergo

// How a soft support's interior rest positions follow its designed surface (paper §4.3: the
// design moves the rest shape of the support's top; the foam inside must follow without
// folding): the harmonic extension of the designed vertices' displacement over the tet
// mesh's edge graph, every other boundary vertex and every held vertex staying put. Linear in
// the designed displacement, so a design gradient pulls back through its transpose
// (PullBack), which is part of the design gradient. Metres.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/eigen_types.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

class RestExtension {
 public:
  // `designed`: per tet-mesh vertex, moved by the design (boundary vertices, typically the
  // support's top); `fixed`: per vertex, never moved (the held base and the rest of the
  // boundary). Every other vertex is interior and follows: L_II u_I = −L_ID u_D with L the
  // uniform graph Laplacian of the tet edges. CHECKs that no vertex is both.
  RestExtension(const TetMesh& mesh, const std::vector<bool>& designed,
                const std::vector<bool>& fixed);

  // Every vertex's displacement (#V x 3) from the designed vertices' (rows of `designed`,
  // other rows ignored): designed rows as given, fixed rows 0, interior rows harmonic.
  Vertices Extend(const Vertices& designed_displacement) const;

  // The transpose: a gradient over every vertex's rest position (#V x 3) to the designed
  // vertices' (non-designed rows 0): g_D − L_DI L_II⁻¹ g_I.
  Vertices PullBack(const Vertices& gradient) const;

  int interior_count() const { return static_cast<int>(interior_.size()); }

 private:
  std::vector<int> interior_, designed_;
  Eigen::VectorXi interior_index_;  // vertex -> interior row, or -1
  SparseMatrix interior_block_;     // L_II (upper)
  SparseMatrix coupling_;           // L_ID: interior rows x vertex columns (designed only)
  SparseCholesky cholesky_;
};

}  // namespace ergo

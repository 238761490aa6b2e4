#include "ergo/body/tissue_compression.h"

#include <optional>

#include "ergo/material/rotation_variant_svd.h"
#include "ergo/material/tet_element.h"

namespace ergo {

TissueCompression MeasureTissueCompression(const LayeredBody& body, const BodyState& state) {
  const Vertices positions = DeformedPositions(body, state);
  const TetMesh& rest = body.rest();
  TissueCompression out;
  out.threshold = body.material().inversion_threshold;
  for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
    TetPositions x0, x;
    for (int k = 0; k < 4; ++k) {
      x0.col(k) = rest.vertices.row(rest.tets(t, k)).transpose();
      x.col(k) = positions.row(rest.tets(t, k)).transpose();
    }
    const std::optional<TetRestData> data = ComputeTetRestData(x0);
    if (!data) continue;  // a degenerate rest tet: LayeredBody refuses those
    const Eigen::Matrix3d f = DeformationGradient(*data, x);
    const double j = f.determinant();
    const double stretch = RotationVariantSvd(f).sigma(2);  // the smallest, signed
    if (out.worst_tet < 0 || j < out.min_volume_ratio) out.min_volume_ratio = j;
    out.inverted_tets += j <= 0 ? 1 : 0;
    if (stretch < out.threshold) {
      ++out.tets_beyond_threshold;
      out.beyond_threshold_points.push_back(x.rowwise().mean());
    }
    if (out.worst_tet < 0 || stretch < out.min_principal_stretch) {
      out.min_principal_stretch = stretch;
      out.worst_tet = t;
      out.worst_point = x.rowwise().mean();
    }
  }
  return out;
}

}  // namespace ergo

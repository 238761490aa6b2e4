// How hard an equilibrium squeezes the tissue: per tet the volume ratio J = det F and the
// smallest principal stretch σ (signed, < 0 inverted: rotation_variant_svd.h). Below the
// material's inversion threshold ε (0.1: 90 % compression, neo_hookean.h) the energy is a C²
// extension chosen so that Newton survives any F, not a law measured on tissue; a contact
// pressure carried through such tets is the extension's, not the tissue's. The summary of an
// equilibrium reports this, so that a crushed pad is not read as a pressure.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"

namespace ergo {

struct TissueCompression {
  double min_volume_ratio = 1;       // smallest det F over the tets
  double min_principal_stretch = 1;  // smallest signed principal stretch over the tets
  int tets_beyond_threshold = 0;     // tets with a principal stretch below ε
  int inverted_tets = 0;             // tets with det F <= 0
  double threshold = 0.1;            // ε, the material's inversion threshold
  // The tet with the smallest principal stretch: its index and deformed centroid, m.
  Eigen::Index worst_tet = -1;
  Eigen::Vector3d worst_point = Eigen::Vector3d::Zero();
  // The deformed centroid of every tet beyond ε (for pictures), m.
  std::vector<Eigen::Vector3d> beyond_threshold_points;
};

TissueCompression MeasureTissueCompression(const LayeredBody& body, const BodyState& state);

}  // namespace ergo

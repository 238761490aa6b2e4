// The negative-image start (paper §5.1: "subtracting the human body from a flat chair using
// CSG boolean subtraction ... penetrating the human into the chair by 5cm. To remove the
// sharp edges caused by CSG, we use Laplacian smoothing"): the support minus the body's skin
// pushed into it along the load, by CGAL corefinement; the carved region is remeshed to the
// support's resolution and the rim of the cavity smoothed by umbrella-Laplacian iterations
// restricted to a band around the intersection curve. Metres.
#pragma once

#include <string>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct NegativeImageOptions {
  double depth = 0.05;  // how far the skin is pushed in beyond first contact, m (paper: 5 cm)
  // Edge length of the remeshed cavity, m; 0 = the median edge of the support's triangles
  // that the cut crosses.
  double edge_length = 0;
  int remesh_iterations = 3;
  // Vertices within this distance of the intersection curve are smoothed, m.
  double smoothing_radius = 0.015;
  int smoothing_iterations = 10;  // Laplacian steps x ← x − λ L x in the band
  double smoothing_lambda = 0.5;
  double gap = 0.002;  // the body starts this far above the carved support, m
};

struct NegativeImage {
  TriMesh support;       // closed, outward, checked (no self-intersection)
  BodyState start;       // the body just above the cavity
  int cut_segments = 0;  // edges of the intersection curve
  int smoothed_vertices = 0;
  double edge_length = 0;   // used for the remeshing, m
  double rim_rounding = 0;  // largest vertex move by the smoothing, m
  double seconds = 0;

  std::string BriefReport() const;  // one line
};

// Carves the skin of `body` at `contact` (a state in which it touches `support`, e.g. the
// flat start lowered by its gap) moved `depth` further along the load. Throws InputError
// naming `scenario` when the Boolean fails, the result is not a valid support, or the body
// cannot be placed above it.
NegativeImage MakeNegativeImage(const LayeredBody& body, const BodyState& contact,
                                const TriMesh& support, const NegativeImageOptions& options,
                                const std::string& scenario);

}  // namespace ergo

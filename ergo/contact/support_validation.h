// The checks a support surface S must pass before contact can use it (paper §3.5: a vertex
// collides with "the volume enclosed by the supporting surface", so S must enclose one):
// closed, edge- and vertex-manifold, consistently and outward oriented, no degenerate
// triangles, finite coordinates, no self-intersection (ergo/mesh/self_intersection.h, with
// its default work budget: a support whose test runs out of it is refused, not trusted).
#pragma once

#include <string>

#include "ergo/mesh/self_intersection.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Twice a triangle's area over its longest edge squared at or below this is "degenerate"
// (collinear to rounding): its normal, needed for the inside test, does not exist.
inline constexpr double kDegenerateTriangleRatio = 1e-12;

// Throws InputError naming `source` (a file or a description), the offending triangle /
// edge / vertex (for a pinched vertex and a self-intersection also its point in metres), what
// is wrong and the fix. Returns normally if `mesh` can be a support.
// `self_intersection` is the budget of the self-intersection test (its max_pairs is ignored).
void ValidateSupportMesh(const TriMesh& mesh, const std::string& source,
                         const SelfIntersectionOptions& self_intersection = {});

// The same checks on a body's skin as built (contact takes it as a closed surface whose inside
// it can tell): the message says that the mesher pinched or overlapped the skin where two
// parts of the surface (toes, fingers) come closer than the mesh resolves, and what to try.
void ValidateSkinForContact(const TriMesh& skin, const std::string& source);

}  // namespace ergo

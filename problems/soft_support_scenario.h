// A scenario's rigid support made foam (paper §4.3, §5.4): the design then moves the foam's
// rest shape instead of a rigid surface. The foam's boundary (Mesh_3 of the support's solid,
// ergo/body/support_solid.h) becomes the scenario's support mesh; the designed region carries
// over to it; the printed part is the optimised rest shape.
#pragma once

#include <memory>
#include <vector>

#include "ergo/body/elastic_part.h"
#include "ergo/mesh/tri_mesh.h"
#include "problems/scenario.h"

namespace ergo {

// The designed flags of `rigid`'s vertices carried to the vertices of `boundary` (a remesh of
// the same surface): a boundary vertex is designed when the rigid triangle closest to it has
// all three corners designed. Empty `active` (all designed) stays empty.
std::vector<bool> TransferActiveVertices(const TriMesh& rigid, const std::vector<bool>& active,
                                         const TriMesh& boundary);

// Makes `part` (whose boundary remeshes scenario->support) the scenario's soft support: the
// support mesh becomes the part's boundary at rest, the active flags follow it, and the
// description says so.
void UseSoftSupport(std::shared_ptr<const ElasticPart> part, Scenario* scenario);

}  // namespace ergo

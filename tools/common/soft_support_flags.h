// --support_model and the soft support's flags (paper §4.3): the support as a foam part — a
// tet mesh of the support surface (CGAL Mesh_3, ergo/body/support_solid.h) or the user's own
// (--support_tets: .msh, or a TetGen .node/.ele pair; --support_held lists its held vertices)
// — with the neo-Hookean material of
// --support_youngs_modulus and --support_poisson_ratio, its bottom plane held, and its own
// weight when --support_density > 0. A tool gets these flags by calling SoftSupportFromFlags.
#pragma once

#include <memory>
#include <string>

#include "ergo/body/elastic_part.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"
#include "problems/scenario.h"

namespace ergo {

// Whether --support_model is soft (InputError naming it for a word other than rigid / soft).
bool SoftSupportRequested();

// Checks every soft-support flag's range (InputError naming the flag) before any work;
// nothing for --support_model=rigid.
void CheckSoftSupportFlags();

// --support_tets: the user's tet mesh of the soft support, or "" to mesh the surface.
const std::string& SoftSupportTetFile();

// The soft support for a support surface `surface` read from `source` (meshed with
// --soft_support_edge_length at the top and --soft_support_base_edge_length at the base), or the
// tet mesh --support_tets in `unit` when given (then `surface` may be empty). `gravity` is the
// scene's, used when --support_density > 0. *contact_surface receives the part's boundary
// at rest: the support the body touches. Throws InputError naming the flag or file at fault.
std::shared_ptr<const ElasticPart> SoftSupportFromFlags(const TriMesh& surface,
                                                        const std::string& source, LengthUnit unit,
                                                        const Eigen::Vector3d& gravity,
                                                        TriMesh* contact_surface);

// With --support_model=soft, the scenario's support as foam from these flags (meshed from
// its surface, or --support_tets in metres), the design moving its rest shape
// (problems/soft_support_scenario.h); nothing otherwise.
void ApplySoftSupportFlags(Scenario* scenario);

// The soft support's flags for summary.json (model, modulus, ratio, density, mesh source).
std::string DescribeSoftSupportFlags();

}  // namespace ergo

#include "problems/soft_support_scenario.h"

#include <cstdio>
#include <utility>

#include "ergo/body/surface_distance.h"

namespace ergo {

std::vector<bool> TransferActiveVertices(const TriMesh& rigid, const std::vector<bool>& active,
                                         const TriMesh& boundary) {
  if (active.empty()) return {};
  const SurfaceDistance distance(rigid);
  std::vector<bool> out(static_cast<size_t>(boundary.vertices.rows()), false);
  for (Eigen::Index v = 0; v < boundary.vertices.rows(); ++v) {
    const int f = distance.Nearest(boundary.vertices.row(v).transpose()).triangle;
    out[v] = f >= 0 && active[rigid.triangles(f, 0)] && active[rigid.triangles(f, 1)] &&
             active[rigid.triangles(f, 2)];
  }
  return out;
}

void UseSoftSupport(std::shared_ptr<const ElasticPart> part, Scenario* scenario) {
  const TriMesh& boundary = part->boundary().surface;
  scenario->design.active =
      TransferActiveVertices(scenario->support, scenario->design.active, boundary);
  scenario->support = boundary;
  char line[160];
  std::snprintf(line, sizeof line, "; soft support: %lld tets, E %.3g Pa, nu %.2f",
                static_cast<long long>(part->rest().tets.rows()),
                part->material().youngs_modulus.mean(), part->material().poisson_ratio.mean());
  scenario->description += line;
  scenario->design.soft_support = std::move(part);
}

}  // namespace ergo

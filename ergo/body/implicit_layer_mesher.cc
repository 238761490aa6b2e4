// CGAL translation unit: Mesh_3 on a labelled implicit domain (about a minute to compile).
#include "ergo/body/implicit_layer_mesher.h"

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>
#include <glog/logging.h>

#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

// A size bound that varies in space: base · scale(p) (Mesh_3's sizing-field concept).
struct ScaledSize {
  double base;
  std::function<double(const Eigen::Vector3d&)> scale;
  double operator()(const Point& p, int, const Domain::Index&) const {
    const double s = scale(
        Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    CHECK(s > 0) << "the mesh size scale must be positive";
    return base * s;
  }
};

// Inserts the first `count` seeds of each surface as surface vertices of an empty complex.
// Refinement can start only if some restricted facet exists, i.e. some Voronoi vertex
// (dual of a cell) of the seeds lies in the layer; returns whether one does.
bool InitialiseWithSeeds(const std::vector<SurfaceSeed>& skin, const std::vector<SurfaceSeed>& core,
                         size_t count, const Domain& domain, const Domain::Fct& function,
                         Complex* c3t3) {
  Triangulation& tr = c3t3->triangulation();
  const auto weighted = tr.geom_traits().construct_weighted_point_3_object();
  const Domain::Index skin_index = domain.index_from_surface_patch_index(std::make_pair(0, 1));
  const Domain::Index core_index = domain.index_from_surface_patch_index(std::make_pair(1, 2));
  for (const auto* seeds : {&skin, &core}) {
    for (size_t i = 0; i < std::min(count, seeds->size()); ++i) {
      const Eigen::Vector3d& p = (*seeds)[i].point;
      const Triangulation::Vertex_handle v = tr.insert(weighted(Point(p.x(), p.y(), p.z())));
      if (v == Triangulation::Vertex_handle()) continue;
      c3t3->set_dimension(v, 2);
      c3t3->set_index(v, seeds == &core ? core_index : skin_index);
    }
  }
  if (tr.dimension() < 3) return false;
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    if (function(tr.dual(c)) == kLayerRegion) return true;
  }
  return false;
}

}  // namespace

LayerMesherResult MeshImplicitLayer(const RegionFunction& region, const Eigen::AlignedBox3d& bounds,
                                    const std::vector<SurfaceSeed>& seeds,
                                    const LayerMesherCriteria& criteria) {
  CHECK(!bounds.isEmpty());
  CHECK_GT(criteria.facet_size, 0);
  CHECK_GT(criteria.facet_distance, 0);
  CHECK_GT(criteria.cell_size, 0);
  const CGAL::Bbox_3 box(bounds.min().x(), bounds.min().y(), bounds.min().z(), bounds.max().x(),
                         bounds.max().y(), bounds.max().z());
  const Domain::Fct function = [&region](const Point& p) {
    return region(Eigen::Vector3d(p.x(), p.y(), p.z()));
  };
  CGAL::Random random(criteria.seed);

  // Outside and core are both "not meshed"; only the layer (label 1) is. The skin is then
  // the surface patch (0,1) and the core surface (1,2).
  const Domain domain(
      function, box, criteria.relative_error_bound, [](int label) { return label != kLayerRegion; },
      &random);
  namespace params = CGAL::parameters;
  const Criteria mesh_criteria =
      criteria.size_scale
          ? Criteria(params::facet_angle = criteria.facet_angle_degrees,
                     params::facet_size = ScaledSize{criteria.facet_size, criteria.size_scale},
                     params::facet_distance = criteria.facet_distance,
                     params::cell_radius_edge_ratio = criteria.cell_radius_edge_ratio,
                     params::cell_size = ScaledSize{criteria.cell_size, criteria.size_scale})
          : Criteria(params::facet_angle = criteria.facet_angle_degrees,
                     params::facet_size = criteria.facet_size,
                     params::facet_distance = criteria.facet_distance,
                     params::cell_radius_edge_ratio = criteria.cell_radius_edge_ratio,
                     params::cell_size = criteria.cell_size);

  LayerMesherResult result;
  auto start = std::chrono::steady_clock::now();
  // Start from the seeds, as few as will do (each is a vertex of the final mesh): more of
  // them until a Voronoi vertex falls in the layer. CGAL's own random initial points are
  // the last resort.
  std::vector<SurfaceSeed> skin_seeds, core_seeds;
  for (const SurfaceSeed& seed : seeds) (seed.on_core ? core_seeds : skin_seeds).push_back(seed);
  const size_t most = std::max(skin_seeds.size(), core_seeds.size());
  Complex c3t3;
  bool initialised = false;
  for (size_t count = 16;; count *= 4) {
    c3t3.clear();
    result.initial_points =
        static_cast<int>(std::min(count, skin_seeds.size()) + std::min(count, core_seeds.size()));
    initialised = InitialiseWithSeeds(skin_seeds, core_seeds, count, domain, function, &c3t3);
    if (initialised || count >= most) break;
  }
  if (initialised) {
    CGAL::refine_mesh_3(c3t3, domain, mesh_criteria, params::no_perturb(), params::no_exude());
    // Seeds that all lie on a few planes (a slab's gridded top and four base corners) can
    // start a refinement that restricts no cell to the region: start again from CGAL's own
    // initial points.
    if (c3t3.number_of_cells_in_complex() == 0) initialised = false;
  }
  if (!initialised) {
    result.initial_points = 0;
    c3t3 =
        CGAL::make_mesh_3<Complex>(domain, mesh_criteria, params::no_perturb(), params::no_exude());
  }
  result.refine_seconds = SecondsSince(start);
  if (criteria.perturb) {
    start = std::chrono::steady_clock::now();
    CGAL::perturb_mesh_3(c3t3, domain, params::time_limit = criteria.time_limit,
                         params::sliver_bound = criteria.sliver_bound_degrees);
    result.perturb_seconds = SecondsSince(start);
  }
  if (criteria.exude) {
    start = std::chrono::steady_clock::now();
    CGAL::exude_mesh_3(c3t3, params::time_limit = criteria.time_limit,
                       params::sliver_bound = criteria.sliver_bound_degrees);
    result.exude_seconds = SecondsSince(start);
  }

  // Cells of the layer -> TetMesh with compact vertex numbering.
  const Triangulation& tr = c3t3.triangulation();
  std::unordered_map<Triangulation::Vertex_handle, int> id;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector4i> tets;
  const auto vertex_id = [&](Triangulation::Vertex_handle v) {
    const auto [it, inserted] = id.emplace(v, static_cast<int>(points.size()));
    if (inserted) {
      const Point p = tr.geom_traits().construct_point_3_object()(tr.point(v));
      points.emplace_back(p.x(), p.y(), p.z());
    }
    return it->second;
  };
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    if (c3t3.subdomain_index(c) != kLayerRegion) continue;
    Eigen::Vector4i tet;
    for (int k = 0; k < 4; ++k) tet[k] = vertex_id(c->vertex(k));
    tets.push_back(tet);
  }
  result.mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) result.mesh.vertices.row(v) = points[v].transpose();
  result.mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t) {
    Eigen::Vector4i tet = tets[t];
    const Eigen::Vector3d p0 = points[tet[0]];
    const double six_volume =
        (points[tet[1]] - p0).dot((points[tet[2]] - p0).cross(points[tet[3]] - p0));
    if (six_volume < 0) std::swap(tet[2], tet[3]);  // CGAL cells are positive; be sure
    result.mesh.tets.row(t) = tet.transpose();
  }

  // Vertices of restricted facets, by the surface they approximate.
  result.surface_flags.assign(points.size(), 0);
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto patch = c3t3.surface_patch_index(*f);
    const uint8_t flag = patch == std::make_pair(1, 2) ? 2 : patch == std::make_pair(0, 1) ? 1 : 0;
    for (int k = 0; k < 4; ++k) {
      if (k == f->second) continue;
      const auto it = id.find(f->first->vertex(k));
      if (it != id.end()) result.surface_flags[it->second] |= flag;
    }
  }
  return result;
}

}  // namespace ergo

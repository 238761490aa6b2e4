#include "problems/implicit_body.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

#include <glog/logging.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/seconds_since.h"

namespace ergo {

GeneratedBody BuildImplicitBody(const ImplicitBodySpec& spec, const BuilderOptions& builder,
                                const LayeredBodyOptions& load) {
  const auto start = std::chrono::steady_clock::now();
  CHECK(spec.depth && spec.stiffness) << spec.name;
  constexpr int kMaxRegions = 16;
  const int regions = spec.shape.region_count();
  CHECK_LE(regions, kMaxRegions) << spec.name;
  const BlendedShape& shape = spec.shape;
  const RegionField depth = spec.depth;
  ImplicitLayer layer;
  layer.outer = [&shape](const Eigen::Vector3d& p) { return shape.Evaluate(p); };
  layer.core = [&shape, depth](const Eigen::Vector3d& p) {
    double w[kMaxRegions];
    const double f = shape.Evaluate(p, w);
    return f + depth(p, w);
  };
  // One evaluation classifies a point; the core is inside the skin because depth > 0.
  layer.region = [&shape, depth](const Eigen::Vector3d& p) {
    double w[kMaxRegions];
    const double f = shape.Evaluate(p, w);
    if (!(f < 0)) return static_cast<int>(kOutsideRegion);
    return static_cast<int>(f + depth(p, w) < 0 ? kCoreRegion : kLayerRegion);
  };
  layer.bounds = shape.Bounds(0.1 * builder.edge_length + 1e-3);
  const BuiltLayer built = BuildLayerFromImplicit(layer, builder, spec.name);

  GeneratedBody generated;
  generated.report = built.report;
  TissueMaterial material;
  const Eigen::Index tets = built.mesh.tets.rows();
  material.youngs_modulus.resize(tets);
  material.poisson_ratio = Eigen::VectorXd::Constant(tets, spec.poisson_ratio);
  std::vector<double> w(regions);
  for (Eigen::Index t = 0; t < tets; ++t) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      centroid += built.mesh.vertices.row(built.mesh.tets(t, k)).transpose();
    centroid /= 4;
    shape.Evaluate(centroid, w.data());
    material.youngs_modulus[t] = spec.stiffness(centroid, w.data());
  }
  generated.youngs_min = material.youngs_modulus.minCoeff();
  generated.youngs_max = material.youngs_modulus.maxCoeff();

  // Depth agreement over the skin vertices (vertex_depth is measured on the mesh).
  const TetMesh& mesh = built.mesh;
  const std::vector<bool>& attached = built.attached;
  DepthAgreement& agreement = generated.depth;
  std::vector<double> errors;
  const SurfaceDistance& skin = *built.skin;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    // Skin vertices: vertex_depth is their own distance to the core surface.
    if (attached[v]) continue;
    const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
    if (skin.Nearest(p).distance > 1e-9) continue;
    shape.Evaluate(p, w.data());
    const double requested = depth(p, w.data()), achieved = built.vertex_depth[v];
    agreement.mean_requested += requested;
    agreement.mean_achieved += achieved;
    errors.push_back(std::abs(achieved - requested) / requested);
  }
  if (!errors.empty()) {
    const double n = static_cast<double>(errors.size());
    agreement.mean_requested /= n;
    agreement.mean_achieved /= n;
    agreement.within_20_percent =
        std::count_if(errors.begin(), errors.end(), [](double e) { return e <= 0.2; }) / n;
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    agreement.median_relative_error = errors[errors.size() / 2];
  }

  LayeredBodyOptions options = load;
  options.tissue_density = spec.tissue_density;
  options.core_density = spec.tissue_density;
  generated.tissue_mass = spec.tissue_density * built.report.layer_volume;
  if (spec.total_mass >= 0) {
    options.core_mass = spec.total_mass - generated.tissue_mass;
    if (!(options.core_mass > 0)) {
      std::ostringstream what;
      what << "the total mass " << spec.total_mass << " kg is not above the tissue's own mass "
           << generated.tissue_mass << " kg";
      throw InputError(spec.name, "total mass", what.str(), "give a larger total mass");
    }
  } else {
    options.core_mass = -1;
  }
  generated.body = std::make_shared<LayeredBody>(
      LayeredBody::Create(built.mesh, built.attached, material, options, spec.name));
  generated.core_mass = generated.body->core_mass();
  generated.build_seconds = SecondsSince(start);
  return generated;
}

std::string DescribeGeneratedBody(const GeneratedBody& g) {
  std::ostringstream out;
  const LayerBuildReport& r = g.report;
  out << r.vertex_count << " vertices (" << r.skin_vertex_count << " skin, "
      << r.attached_vertex_count << " core), " << r.tet_count << " tets; mass "
      << g.tissue_mass + g.core_mass << " kg (tissue " << g.tissue_mass << ", core " << g.core_mass
      << "); layer " << r.min_thickness * 1e3 << "–" << r.mean_thickness * 1e3
      << " mm (min–mean), requested depth mean " << g.depth.mean_requested * 1e3 << " mm, achieved "
      << g.depth.mean_achieved * 1e3 << " mm (median rel. error " << g.depth.median_relative_error
      << ", " << 100 * g.depth.within_20_percent << " % of the skin within 20 %); E "
      << g.youngs_min << "–" << g.youngs_max << " Pa; min dihedral "
      << r.quality.min_dihedral_degrees << "°, radius ratio min " << r.quality.min_radius_ratio
      << "; built in " << g.build_seconds << " s";
  return out.str();
}

}  // namespace ergo

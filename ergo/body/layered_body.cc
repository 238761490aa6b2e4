#include "ergo/body/layered_body.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

// Volume, centroid and second moment ∫ x xᵀ dV (about the origin) of the solid bounded by
// outward triangles, by the divergence theorem over tets (origin, a, b, c).
struct SolidMoments {
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};

SolidMoments Moments(const Vertices& v, const std::vector<Eigen::Vector3i>& faces,
                     const Eigen::Vector3d& origin) {
  SolidMoments m;
  for (const Eigen::Vector3i& f : faces) {
    const Eigen::Vector3d a = Eigen::Vector3d(v.row(f[0])) - origin;
    const Eigen::Vector3d b = Eigen::Vector3d(v.row(f[1])) - origin;
    const Eigen::Vector3d c = Eigen::Vector3d(v.row(f[2])) - origin;
    const double volume = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    m.volume += volume;
    m.first += volume * s / 4.0;
    m.second += volume / 20.0 *
                (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return m;
}

// True when every undirected edge of `faces` is shared by exactly two faces.
bool IsClosed(const std::vector<Eigen::Vector3i>& faces) {
  std::map<std::pair<int, int>, int> count;
  for (const Eigen::Vector3i& f : faces)
    for (int k = 0; k < 3; ++k) ++count[std::minmax(f[k], f[(k + 1) % 3])];
  for (const auto& [edge, n] : count)
    if (n != 2) return false;
  return !faces.empty();
}

// Z-order (Morton) keys of points quantised to 21 bits per axis over their bounding box.
std::vector<uint64_t> MortonKeys(const Vertices& points) {
  const Eigen::RowVector3d lo = points.colwise().minCoeff();
  const Eigen::RowVector3d extent = (points.colwise().maxCoeff() - lo).cwiseMax(1e-300);
  auto spread = [](uint64_t x) {  // insert two zero bits between the 21 low bits of x
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  std::vector<uint64_t> keys(static_cast<size_t>(points.rows()));
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const Eigen::RowVector3d q =
        ((points.row(v) - lo).array() / extent.array() * 2097151.0).matrix();
    keys[v] = spread(static_cast<uint64_t>(q.x())) | spread(static_cast<uint64_t>(q.y())) << 1 |
              spread(static_cast<uint64_t>(q.z())) << 2;
  }
  return keys;
}

}  // namespace

TriMesh Skin::RestSurface(const Vertices& positions) const {
  TriMesh mesh;
  mesh.vertices.resize(vertices.size(), 3);
  for (Eigen::Index i = 0; i < vertices.size(); ++i)
    mesh.vertices.row(i) = positions.row(vertices[i]);
  mesh.triangles.resize(triangles.rows(), 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) mesh.triangles(f, k) = local_of[triangles(f, k)];
  return mesh;
}

LayeredBody LayeredBody::Create(TetMesh rest, std::vector<bool> attached, TissueMaterial material,
                                const LayeredBodyOptions& options, const std::string& name) {
  ValidateTetMaterial(rest, material, name, "tissue: 5e3–15e3 Pa");
  const Eigen::Index n = rest.vertices.rows(), tet_count = rest.tets.rows();
  if (static_cast<Eigen::Index>(attached.size()) != n) {
    throw InputError(name, "",
                     "the attached-vertex flags have " + std::to_string(attached.size()) +
                         " entries for " + std::to_string(n) + " vertices",
                     "give one flag per tet-mesh vertex");
  }
  ValidateCoreLock(options.lock, name + " lock");

  LayeredBody body;
  body.options_ = options;
  body.material_ = std::move(material);

  std::vector<int> free_list, attached_list;
  body.free_index_ = Eigen::VectorXi::Constant(n, -1);
  for (Eigen::Index v = 0; v < n; ++v)
    (attached[v] ? attached_list : free_list).push_back(static_cast<int>(v));
  // Free DOFs along a Z-order curve of the rest positions: neighbouring vertices get nearby
  // DOF numbers, so one element's Hessian blocks land close together in memory (assembly
  // was bound by cache misses with the mesher's vertex order).
  const std::vector<uint64_t> keys = MortonKeys(rest.vertices);
  std::stable_sort(free_list.begin(), free_list.end(),
                   [&](int a, int b) { return keys[a] < keys[b]; });
  for (size_t i = 0; i < free_list.size(); ++i)
    body.free_index_[free_list[i]] = static_cast<int>(i);
  if (attached_list.empty()) {
    throw InputError(name, "", "no vertex is attached to the rigid core",
                     "mark the inner-surface vertices as attached");
  }
  body.free_vertices_ = Eigen::Map<Eigen::VectorXi>(free_list.data(), free_list.size());
  body.attached_vertices_ = Eigen::Map<Eigen::VectorXi>(attached_list.data(), attached_list.size());

  // Lumped masses: a quarter of each tet's mass on each corner.
  body.vertex_mass_ = Eigen::VectorXd::Zero(n);
  for (Eigen::Index t = 0; t < tet_count; ++t) {
    const double volume = TetVolume(rest, t);
    body.layer_volume_ += volume;
    for (int k = 0; k < 4; ++k)
      body.vertex_mass_[rest.tets(t, k)] += options.tissue_density * volume / 4;
  }

  // Boundary: faces entirely on the core are the core interface, the rest is skin.
  const TetBoundary boundary = ExtractBoundary(rest);
  std::vector<Eigen::Vector3i> core_faces, skin_faces;
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f) {
    Eigen::Vector3i face;
    bool on_core = true;
    for (int k = 0; k < 3; ++k) {
      face[k] = boundary.surface_to_tet[boundary.surface.triangles(f, k)];
      on_core = on_core && attached[face[k]];
    }
    if (on_core) {
      // Outward from the layer means into the core: reverse for the core solid.
      core_faces.emplace_back(face[0], face[2], face[1]);
    } else {
      skin_faces.push_back(face);
    }
  }
  if (skin_faces.empty()) {
    throw InputError(name, "", "every boundary face is on the core: the body has no skin",
                     "attach only the inner surface's vertices");
  }

  // Core centre, volume and inertia from the closed core interface when there is one;
  // otherwise the mass-weighted centroid of the attached vertices.
  const Eigen::Vector3d reference = rest.vertices.colwise().mean().transpose();
  if (IsClosed(core_faces)) {
    const SolidMoments m = Moments(rest.vertices, core_faces, reference);
    if (m.volume > 0) {
      body.core_volume_ = m.volume;
      const Eigen::Vector3d centroid = m.first / m.volume;
      body.core_centre_ = reference + centroid;
      const Eigen::Matrix3d central = m.second - m.volume * centroid * centroid.transpose();
      body.core_inertia_ = central.trace() * Eigen::Matrix3d::Identity() - central;  // per density
    }
  }
  if (body.core_volume_ == 0) {
    double mass = 0;
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    for (int v : attached_list) {
      mass += body.vertex_mass_[v];
      weighted += body.vertex_mass_[v] * rest.vertices.row(v).transpose();
    }
    body.core_centre_ = weighted / mass;
  }
  if (options.core_mass >= 0) {
    body.core_mass_ = options.core_mass;
  } else if (body.core_volume_ > 0) {
    body.core_mass_ = options.core_density * body.core_volume_;
  } else {
    throw InputError(name, "",
                     "the attached vertices do not enclose a core, so its mass is unknown",
                     "give the core mass explicitly (--core_mass)");
  }
  if (body.core_volume_ > 0) {
    body.core_inertia_ *= body.core_mass_ / body.core_volume_;
  } else {
    // No solid to integrate: a ball of the core's mass with the attached vertices' spread.
    double spread = 0;
    for (int v : attached_list)
      spread += (rest.vertices.row(v).transpose() - body.core_centre_).squaredNorm();
    body.core_inertia_ = Eigen::Matrix3d::Identity() * (2.0 / 3.0) * body.core_mass_ * spread /
                         static_cast<double>(attached_list.size());
  }

  // Skin: compact vertex list and rest barycentric areas.
  Skin& skin = body.skin_;
  skin.triangles.resize(static_cast<Eigen::Index>(skin_faces.size()), 3);
  std::vector<int> skin_vertices;
  for (size_t f = 0; f < skin_faces.size(); ++f) {
    skin.triangles.row(f) = skin_faces[f].transpose();
    for (int k = 0; k < 3; ++k) skin_vertices.push_back(skin_faces[f][k]);
  }
  std::sort(skin_vertices.begin(), skin_vertices.end());
  skin_vertices.erase(std::unique(skin_vertices.begin(), skin_vertices.end()), skin_vertices.end());
  skin.vertices = Eigen::Map<Eigen::VectorXi>(skin_vertices.data(), skin_vertices.size());
  skin.local_of = Eigen::VectorXi::Constant(n, -1);
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i)
    skin.local_of[skin.vertices[i]] = static_cast<int>(i);
  skin.rest_areas = BarycentricVertexAreas(skin.RestSurface(rest.vertices));

  body.rest_ = std::move(rest);
  body.attached_ = std::move(attached);
  return body;
}

Eigen::Vector3d LayeredBody::TotalLoad() const {
  return total_mass() * options_.gravity + options_.external_force;
}

void LayeredBody::SetLock(const CoreLock& lock) {
  ValidateCoreLock(lock, "lock");
  options_.lock = lock;
}

void LayeredBody::SetExternalWrench(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  options_.external_force = force;
  options_.external_torque = torque;
}

}  // namespace ergo

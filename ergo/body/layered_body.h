// LayeredBody: the human body part of paper §3.1/§3.3 — a tetrahedral layer of soft tissue
// whose inner-surface ("attached") vertices move rigidly with a bony core. Holds the rest
// mesh, per-tet material, lumped masses, the core's mass and centre, the skin (outer
// boundary, where contact happens) with rest areas, the core's DOF lock mask, gravity and
// the external wrench. SI units: m, kg, Pa, N, N·m.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/core_lock.h"
#include "ergo/body/tissue_material.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct LayeredBodyOptions {
  double tissue_density = 1050.0;  // kg/m³, lumped onto vertices
  // Core mass in kg; negative = core volume (enclosed by the attached surface) times
  // `core_density`.
  double core_mass = -1.0;
  double core_density = 1050.0;
  Eigen::Vector3d gravity = Eigen::Vector3d(0, -9.81, 0);  // paper: gravity is −y
  CoreLock lock;
  Eigen::Vector3d external_force = Eigen::Vector3d::Zero();   // on the core, N
  Eigen::Vector3d external_torque = Eigen::Vector3d::Zero();  // about the core centre, N·m
};

// The skin: boundary triangles of the layer that are not entirely on the core.
struct Skin {
  Triangles triangles;         // indices into the tet-mesh vertices, outward
  Eigen::VectorXi vertices;    // tet-mesh ids of skin vertices, increasing
  Eigen::VectorXi local_of;    // tet-mesh vertex -> index in `vertices`, or -1
  Eigen::VectorXd rest_areas;  // barycentric rest area per skin vertex, m²
  TriMesh RestSurface(const Vertices& positions) const;  // compact TriMesh at positions
};

class LayeredBody {
 public:
  // Validates and derives everything. Throws InputError (source = `name`) when the body
  // cannot be simulated: no attached vertex, a rest tet with non-positive volume, a
  // material value out of range, flags of the wrong size, an unsupported lock.
  static LayeredBody Create(TetMesh rest, std::vector<bool> attached, TissueMaterial material,
                            const LayeredBodyOptions& options, const std::string& name = "body");

  const TetMesh& rest() const { return rest_; }
  const std::vector<bool>& attached() const { return attached_; }
  const TissueMaterial& material() const { return material_; }
  const Eigen::VectorXi& free_vertices() const { return free_vertices_; }
  const Eigen::VectorXi& attached_vertices() const { return attached_vertices_; }
  // Tet-mesh vertex -> index among free vertices (its DOFs are 3i..3i+2), or -1.
  const Eigen::VectorXi& free_index() const { return free_index_; }
  const Eigen::VectorXd& vertex_mass() const { return vertex_mass_; }
  double core_mass() const { return core_mass_; }
  double core_volume() const { return core_volume_; }
  double layer_volume() const { return layer_volume_; }
  double total_mass() const { return vertex_mass_.sum() + core_mass_; }
  const Eigen::Vector3d& core_centre() const { return core_centre_; }    // rest C₀
  const Eigen::Matrix3d& core_inertia() const { return core_inertia_; }  // about C₀
  const Skin& skin() const { return skin_; }
  const LayeredBodyOptions& options() const { return options_; }
  const CoreLock& lock() const { return options_.lock; }
  const Eigen::Vector3d& gravity() const { return options_.gravity; }
  // Weight plus external force: the load the support must carry, N.
  Eigen::Vector3d TotalLoad() const;

  // Changing the load or the lock keeps the mesh and its derived data.
  void SetLock(const CoreLock& lock);
  void SetExternalWrench(const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  void SetGravity(const Eigen::Vector3d& gravity) { options_.gravity = gravity; }

 private:
  LayeredBody() = default;

  TetMesh rest_;
  std::vector<bool> attached_;
  TissueMaterial material_;
  LayeredBodyOptions options_;
  Eigen::VectorXi free_vertices_, attached_vertices_, free_index_;
  Eigen::VectorXd vertex_mass_;
  double core_mass_ = 0, core_volume_ = 0, layer_volume_ = 0;
  Eigen::Vector3d core_centre_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d core_inertia_ = Eigen::Matrix3d::Zero();
  Skin skin_;
};

}  // namespace ergo

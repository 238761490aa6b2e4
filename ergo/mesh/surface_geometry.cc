#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

Eigen::Vector3d Corner(const TriMesh& mesh, Eigen::Index f, int k) {
  return mesh.vertices.row(mesh.triangles(f, k)).transpose();
}

}  // namespace

double EnclosedVolume(const TriMesh& mesh) {
  double volume = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

Eigen::VectorXd TriangleAreas(const TriMesh& mesh) {
  Eigen::VectorXd areas(mesh.triangles.rows());
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d p0 = Corner(mesh, f, 0);
    areas[f] = 0.5 * (Corner(mesh, f, 1) - p0).cross(Corner(mesh, f, 2) - p0).norm();
  }
  return areas;
}

Eigen::VectorXd BarycentricVertexAreas(const TriMesh& mesh) {
  const Eigen::VectorXd areas = TriangleAreas(mesh);
  Eigen::VectorXd vertex_areas = Eigen::VectorXd::Zero(mesh.vertices.rows());
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) vertex_areas[mesh.triangles(f, k)] += areas[f] / 3.0;
  return vertex_areas;
}

Eigen::Matrix3d TriangleAreaGradient(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& p2) {
  // area = |N|/2 with N = (p1-p0)×(p2-p0); ∂area/∂p_k = n × (opposite edge)/2, with the
  // opposite edge oriented counter-clockwise (p_{k+2} - p_{k+1}) and n = N/|N|.
  const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0);
  const double length = normal.norm();
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
  if (length == 0.0) return gradient;
  const Eigen::Vector3d n = normal / length;
  gradient.row(0) = 0.5 * n.cross(p2 - p1).transpose();
  gradient.row(1) = 0.5 * n.cross(p0 - p2).transpose();
  gradient.row(2) = 0.5 * n.cross(p1 - p0).transpose();
  return gradient;
}

Vertices VertexNormals(const TriMesh& mesh) {
  Vertices normals = Vertices::Zero(mesh.vertices.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d p0 = Corner(mesh, f, 0);
    const Eigen::Vector3d weighted = (Corner(mesh, f, 1) - p0).cross(Corner(mesh, f, 2) - p0);
    for (int k = 0; k < 3; ++k) normals.row(mesh.triangles(f, k)) += weighted.transpose();
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0) normals.row(v) /= length;
  }
  return normals;
}

}  // namespace ergo

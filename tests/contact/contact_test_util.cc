#include "tests/contact/contact_test_util.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace ergo::contact_testing {
namespace {

using Eigen::Vector3d;

Vector3d RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Vector3d v;
  do {
    v = Vector3d(normal(rng), normal(rng), normal(rng));
  } while (v.norm() < 1e-3);
  return v.normalized();
}

double Uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

double AngleAt(const Vector3d& at, const Vector3d& a, const Vector3d& b) {
  const Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

std::array<Region, 7> AllRegions() {
  return {Region{FeatureType::kVertex, 0}, Region{FeatureType::kVertex, 1},
          Region{FeatureType::kVertex, 2}, Region{FeatureType::kEdge, 0},
          Region{FeatureType::kEdge, 1},   Region{FeatureType::kEdge, 2},
          Region{FeatureType::kFace, 0}};
}

std::string RegionName(const Region& region) {
  if (region.type == FeatureType::kFace) return "face";
  return std::string(FeatureTypeName(region.type)) + " " + std::to_string(region.index);
}

Triangle RandomTriangle(std::mt19937& rng, double scale) {
  const double degree = M_PI / 180;
  for (;;) {
    const Vector3d centre = 10 * scale * Uniform(rng, 0, 1) * RandomUnit(rng);
    Triangle t;
    for (auto& x : t) x = centre + scale * Uniform(rng, 0.5, 1.0) * RandomUnit(rng);
    bool good = true;
    for (int i = 0; i < 3; ++i) {
      const double angle = AngleAt(t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
      good = good && angle >= 20 * degree && angle <= 120 * degree;
    }
    if (good) return t;
  }
}

Vector3d PointInRegion(std::mt19937& rng, const Triangle& t, const Region& region, double scale) {
  const Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
  const double depth = scale * Uniform(rng, 0.1, 1.0);  // below the plane: inside
  switch (region.type) {
    case FeatureType::kFace: {
      Vector3d b;
      do {
        b = Vector3d(Uniform(rng, 0, 1), Uniform(rng, 0, 1), Uniform(rng, 0, 1));
        b /= b.sum();
      } while (b.minCoeff() < 0.15);
      return b[0] * t[0] + b[1] * t[1] + b[2] * t[2] - depth * n;
    }
    case FeatureType::kEdge: {
      const Vector3d& a = t[region.index];
      const Vector3d& c = t[(region.index + 1) % 3];
      const Vector3d outward = (c - a).cross(n).normalized();  // in-plane, away from the third
      const Vector3d anchor = a + Uniform(rng, 0.15, 0.85) * (c - a);
      return anchor + scale * Uniform(rng, 0.1, 1.0) * outward - depth * n;
    }
    case FeatureType::kVertex: {
      const Vector3d& x = t[region.index];
      const Vector3d u = (t[(region.index + 1) % 3] - x).normalized();
      const Vector3d w = (t[(region.index + 2) % 3] - x).normalized();
      Vector3d v;
      do {  // an in-plane direction well inside the vertex's normal cone
        v = RandomUnit(rng);
        v -= v.dot(n) * n;
        v.normalize();
      } while (!(v.dot(u) < -0.2 && v.dot(w) < -0.2));
      return x + scale * Uniform(rng, 0.1, 1.0) * v - depth * n;
    }
  }
  return Vector3d::Zero();
}

int RegionVertexBlocks(const Region& region, std::array<int, 3>* blocks) {
  switch (region.type) {
    case FeatureType::kVertex:
      *blocks = {1 + region.index, -1, -1};
      return 1;
    case FeatureType::kEdge:
      *blocks = {1 + region.index, 1 + (region.index + 1) % 3, -1};
      return 2;
    case FeatureType::kFace:
      *blocks = {1, 2, 3};
      return 3;
  }
  return 0;
}

TriMesh MakeBevelledBox(const Vector3d& half, double bevel, int subdivisions) {
  // Each corner (signs sx, sy, sz) carries three vertices, pulled in by the bevel along two
  // of the three axes; vertex id = 3 * corner + axis kept at full extent.
  std::vector<Vector3d> vertices;
  const auto corner_id = [](int sx, int sy, int sz) {
    return ((sx > 0) << 2) | ((sy > 0) << 1) | (sz > 0);
  };
  for (int c = 0; c < 8; ++c) {
    const Vector3d s((c >> 2) & 1 ? 1 : -1, (c >> 1) & 1 ? 1 : -1, c & 1 ? 1 : -1);
    for (int axis = 0; axis < 3; ++axis) {
      Vector3d x;
      for (int k = 0; k < 3; ++k) x[k] = s[k] * (k == axis ? half[k] : half[k] - bevel);
      vertices.push_back(x);
    }
  }
  const auto id = [&](int sx, int sy, int sz, int axis) {
    return 3 * corner_id(sx, sy, sz) + axis;
  };
  std::vector<std::vector<int>> polygons;
  const int signs[2] = {-1, 1};
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int s : signs) {  // side faces
      std::vector<int> polygon;
      for (int s1 : signs)
        for (int s2 : signs) {
          int sg[3];
          sg[axis] = s, sg[a1] = s1, sg[a2] = s2;
          polygon.push_back(id(sg[0], sg[1], sg[2], axis));
        }
      polygons.push_back(polygon);
    }
    for (int s1 : signs)  // edge strips parallel to `axis`
      for (int s2 : signs) {
        std::vector<int> polygon;
        for (int s : signs) {
          int sg[3];
          sg[axis] = s, sg[a1] = s1, sg[a2] = s2;
          polygon.push_back(id(sg[0], sg[1], sg[2], a1));
          polygon.push_back(id(sg[0], sg[1], sg[2], a2));
        }
        polygons.push_back(polygon);
      }
  }
  for (int c = 0; c < 8; ++c) polygons.push_back({3 * c, 3 * c + 1, 3 * c + 2});

  // Order each convex polygon counter-clockwise around its outward direction (the
  // polyhedron is convex and centred at the origin), then fan-triangulate.
  std::vector<Eigen::Vector3i> triangles;
  for (auto& polygon : polygons) {
    Vector3d centre = Vector3d::Zero();
    for (int v : polygon) centre += vertices[v];
    centre /= polygon.size();
    const Vector3d out = centre.normalized();
    const Vector3d e1 = (vertices[polygon[0]] - centre).normalized();
    const Vector3d e2 = out.cross(e1);
    std::sort(polygon.begin(), polygon.end(), [&](int a, int b) {
      const Vector3d da = vertices[a] - centre, db = vertices[b] - centre;
      return std::atan2(da.dot(e2), da.dot(e1)) < std::atan2(db.dot(e2), db.dot(e1));
    });
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      triangles.emplace_back(polygon[0], polygon[k], polygon[k + 1]);
  }

  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      vertices.push_back(0.5 * (vertices[a] + vertices[b]));
      const int m = static_cast<int>(vertices.size()) - 1;
      midpoint.emplace(key, m);
      return m;
    };
    std::vector<Eigen::Vector3i> finer;
    for (const auto& t : triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.emplace_back(t[0], ab, ca);
      finer.emplace_back(ab, t[1], bc);
      finer.emplace_back(ca, bc, t[2]);
      finer.emplace_back(ab, bc, ca);
    }
    triangles = std::move(finer);
  }

  TriMesh mesh;
  mesh.vertices.resize(vertices.size(), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v) mesh.vertices.row(v) = vertices[v];
  mesh.triangles.resize(triangles.size(), 3);
  for (std::size_t f = 0; f < triangles.size(); ++f) mesh.triangles.row(f) = triangles[f];
  return mesh;
}

BruteForceClosest BruteForceClosestPoint(const TriMesh& mesh, const Vector3d& p) {
  BruteForceClosest best;
  best.projection.squared_distance = INFINITY;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const TriangleProjection candidate =
        ClosestPointOnTriangle(p, mesh.vertices.row(mesh.triangles(f, 0)).transpose(),
                               mesh.vertices.row(mesh.triangles(f, 1)).transpose(),
                               mesh.vertices.row(mesh.triangles(f, 2)).transpose());
    if (candidate.squared_distance < best.projection.squared_distance) {
      best.projection = candidate;
      best.triangle = static_cast<int>(f);
    }
  }
  return best;
}

double WindingNumber(const TriMesh& mesh, const Vector3d& p) {
  // Sum of signed solid angles (Van Oosterom & Strackee 1983) over 4π.
  double total = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose() - p;
    const Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose() - p;
    const Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose() - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * M_PI);
}

}  // namespace ergo::contact_testing

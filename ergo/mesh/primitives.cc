#include "ergo/mesh/primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include <glog/logging.h>

namespace ergo {
namespace {

using Vec3 = Eigen::Vector3d;

TriMesh FromLists(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& faces) {
  TriMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) mesh.vertices.row(i) = points[i].transpose();
  mesh.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) {
    mesh.triangles.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return mesh;
}

}  // namespace

TriMesh MakeIcosphere(double radius, int subdivisions, const Eigen::Vector3d& centre) {
  CHECK_GT(radius, 0.0);
  CHECK_GE(subdivisions, 0);
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : points) p.normalize();
  std::vector<std::array<int, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      points.push_back((points[a] + points[b]).normalized());
      const int index = static_cast<int>(points.size()) - 1;
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<std::array<int, 3>> refined;
    refined.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      refined.push_back({f[0], ab, ca});
      refined.push_back({f[1], bc, ab});
      refined.push_back({f[2], ca, bc});
      refined.push_back({ab, bc, ca});
    }
    faces.swap(refined);
  }
  for (Vec3& p : points) p = centre + radius * p;
  return FromLists(points, faces);
}

TriMesh MakeBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                const Eigen::Vector3i& cells) {
  CHECK((hi.array() > lo.array()).all()) << "box must have positive extent";
  CHECK((cells.array() >= 1).all());
  // Vertices live on the integer lattice (i, j, k); shared between faces by key.
  std::map<std::array<int, 3>, int> index_of;
  std::vector<Vec3> points;
  auto vertex = [&](const std::array<int, 3>& ijk) {
    auto it = index_of.find(ijk);
    if (it != index_of.end()) return it->second;
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = lo[a] + (hi[a] - lo[a]) * ijk[a] / cells[a];
    points.push_back(p);
    const int index = static_cast<int>(points.size()) - 1;
    index_of.emplace(ijk, index);
    return index;
  };
  std::vector<std::array<int, 3>> faces;
  for (int axis = 0; axis < 3; ++axis) {
    const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Vec3 outward = Vec3::Zero();
      outward[axis] = side == 0 ? -1.0 : 1.0;
      for (int i = 0; i < cells[u_axis]; ++i) {
        for (int j = 0; j < cells[v_axis]; ++j) {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> ijk{};
            ijk[axis] = side == 0 ? 0 : cells[axis];
            ijk[u_axis] = i + di;
            ijk[v_axis] = j + dj;
            return vertex(ijk);
          };
          const int a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          for (std::array<int, 3> tri :
               {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
            const Vec3 n = (points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]);
            if (n.dot(outward) < 0) std::swap(tri[1], tri[2]);
            faces.push_back(tri);
          }
        }
      }
    }
  }
  return FromLists(points, faces);
}

TriMesh MakeHeightfieldBlock(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const Eigen::Vector3i& cells,
                             const std::function<double(double, double)>& height) {
  TriMesh block = MakeBox(lo, hi, cells);
  const double depth = hi.y() - lo.y();
  for (Eigen::Index v = 0; v < block.vertices.rows(); ++v) {
    const double x = block.vertices(v, 0), z = block.vertices(v, 2);
    const double top = hi.y() + height(x, z);
    CHECK_GT(top, lo.y()) << "height field reaches below the block's bottom at (" << x << ", " << z
                          << ")";
    // Stretch every column linearly so the walls follow the top.
    block.vertices(v, 1) = lo.y() + (block.vertices(v, 1) - lo.y()) / depth * (top - lo.y());
  }
  return block;
}

TriMesh MakeTorus(double major, double minor, int major_segments, int minor_segments) {
  CHECK_GT(major, minor);
  CHECK_GT(minor, 0.0);
  CHECK_GE(major_segments, 3);
  CHECK_GE(minor_segments, 3);
  std::vector<Vec3> points;
  for (int i = 0; i < major_segments; ++i) {
    const double u = 2 * M_PI * i / major_segments;
    for (int j = 0; j < minor_segments; ++j) {
      const double v = 2 * M_PI * j / minor_segments;
      points.emplace_back((major + minor * std::cos(v)) * std::cos(u),
                          (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v));
    }
  }
  auto id = [&](int i, int j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < major_segments; ++i) {
    for (int j = 0; j < minor_segments; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      for (std::array<int, 3> tri : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
        // Outward = away from the tube's centre line.
        const Vec3 centroid = (points[tri[0]] + points[tri[1]] + points[tri[2]]) / 3;
        Vec3 axis_point(centroid.x(), centroid.y(), 0);
        axis_point = axis_point.normalized() * major;
        const Vec3 n = (points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]);
        if (n.dot(centroid - axis_point) < 0) std::swap(tri[1], tri[2]);
        faces.push_back(tri);
      }
    }
  }
  return FromLists(points, faces);
}

TetMesh MakeTetGrid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                    const Eigen::Vector3i& cells) {
  CHECK((hi.array() > lo.array()).all()) << "grid must have positive extent";
  CHECK((cells.array() >= 1).all());
  std::array<std::vector<double>, 3> lines;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i <= cells[axis]; ++i)
      lines[axis].push_back(lo[axis] + (hi[axis] - lo[axis]) * i / cells[axis]);
  return MakeRectilinearTetGrid(lines[0], lines[1], lines[2]);
}

TetMesh MakeRectilinearTetGrid(const std::vector<double>& xs, const std::vector<double>& ys,
                               const std::vector<double>& zs) {
  CHECK(xs.size() >= 2 && ys.size() >= 2 && zs.size() >= 2) << "a grid needs two lines per axis";
  for (const std::vector<double>* axis : {&xs, &ys, &zs})
    CHECK(std::is_sorted(axis->begin(), axis->end(), std::less_equal<double>()) &&
          std::adjacent_find(axis->begin(), axis->end()) == axis->end())
        << "grid lines must increase strictly";
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size()),
            nz = static_cast<int>(zs.size());
  TetMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(nx) * ny * nz, 3);
  auto id = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) mesh.vertices.row(id(i, j, k)) << xs[i], ys[j], zs[k];
  // The six monotone lattice paths from corner 000 to corner 111 of each cube.
  const std::array<std::array<int, 3>, 6> orders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  std::vector<std::array<int, 4>> tets;
  tets.reserve(static_cast<size_t>(nx - 1) * (ny - 1) * (nz - 1) * 6);
  for (int k = 0; k + 1 < nz; ++k) {
    for (int j = 0; j + 1 < ny; ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        for (const auto& order : orders) {
          std::array<int, 3> at = {i, j, k};
          std::array<int, 4> tet;
          tet[0] = id(at[0], at[1], at[2]);
          for (int step = 0; step < 3; ++step) {
            ++at[order[step]];
            tet[step + 1] = id(at[0], at[1], at[2]);
          }
          const Vec3 p0 = mesh.vertices.row(tet[0]);
          const double volume = (Vec3(mesh.vertices.row(tet[1])) - p0)
                                    .dot((Vec3(mesh.vertices.row(tet[2])) - p0)
                                             .cross(Vec3(mesh.vertices.row(tet[3])) - p0));
          if (volume < 0) std::swap(tet[2], tet[3]);
          tets.push_back(tet);
        }
      }
    }
  }
  mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
    mesh.tets.row(t) << tets[t][0], tets[t][1], tets[t][2], tets[t][3];
  return mesh;
}

}  // namespace ergo

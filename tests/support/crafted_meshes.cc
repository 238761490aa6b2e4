#include "tests/support/crafted_meshes.h"

#include <cmath>
#include <fstream>

namespace ergo::testing {

void WriteDuplicateTrianglesObj(const std::string& path, int count) {
  std::ofstream out(path, std::ios::binary);
  out << "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\n";
  for (int i = 0; i < count; ++i) out << "f 1 2 3\n";
}

void WriteDuplicateTetsTetGen(const std::string& stem, int count) {
  std::ofstream node(stem + ".node", std::ios::binary);
  node << "4 3 0 0\n1 0 0 0\n2 0.1 0 0\n3 0 0.1 0\n4 0 0 0.1\n";
  std::ofstream ele(stem + ".ele", std::ios::binary);
  ele << count << " 4 0\n";
  for (int i = 1; i <= count; ++i) ele << i << " 1 2 3 4\n";
}

TriMesh ParallelTriangleStack(int count) {
  constexpr double kLeg = 0.1, kGap = 1e-6;
  TriMesh mesh;
  mesh.vertices.resize(3 * count, 3);
  mesh.triangles.resize(count, 3);
  for (int i = 0; i < count; ++i) {
    const double x = i * kGap;
    mesh.vertices.row(3 * i) << x, 0, 0;
    mesh.vertices.row(3 * i + 1) << x + kLeg, 0, kLeg;
    mesh.vertices.row(3 * i + 2) << x, kLeg, 0;
    mesh.triangles.row(i) << 3 * i, 3 * i + 1, 3 * i + 2;
  }
  return mesh;
}

TriMesh SliverDoubleCone(int segments) {
  constexpr double kRadius = 0.05, kHeight = 0.1;
  const double pi = std::acos(-1.0);
  TriMesh mesh;
  mesh.vertices.resize(segments + 2, 3);
  for (int i = 0; i < segments; ++i) {
    const double angle = 2 * pi * i / segments;
    mesh.vertices.row(i) << kRadius * std::cos(angle), kRadius * std::sin(angle), 0;
  }
  const int top = segments, bottom = segments + 1;
  mesh.vertices.row(top) << 0, 0, kHeight;
  mesh.vertices.row(bottom) << 0, 0, -kHeight;
  mesh.triangles.resize(2 * segments, 3);
  for (int i = 0; i < segments; ++i) {
    const int next = (i + 1) % segments;
    mesh.triangles.row(2 * i) << i, next, top;
    mesh.triangles.row(2 * i + 1) << next, i, bottom;
  }
  return mesh;
}

}  // namespace ergo::testing

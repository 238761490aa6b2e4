// Feature: the Voronoi region of a support triangle mesh that holds a contact's anchor —
// a vertex, an edge interior or a face interior (paper Appendix A, the 7 regions of a
// triangle). Within one region the sliding-anchor energy (Eq. 10) is k × squared distance
// to a point, a line or a plane; the feature names that point / line / plane by vertex ids.
#pragma once

#include <array>
#include <ostream>

namespace ergo {

enum class FeatureType { kVertex, kEdge, kFace };

// Number of support vertices spanning a feature: 1, 2 or 3.
constexpr int FeatureVertexCount(FeatureType type) {
  return type == FeatureType::kVertex ? 1 : type == FeatureType::kEdge ? 2 : 3;
}

const char* FeatureTypeName(FeatureType type);

// A feature of the support mesh. `vertices` holds FeatureVertexCount(type) support vertex
// ids, the rest are -1: an edge's two ids are sorted ascending so that an edge is named the
// same whichever of its two triangles reported it; a face keeps its triangle's
// (counter-clockwise, outward) vertex order, which fixes the sign of its normal.
struct Feature {
  FeatureType type = FeatureType::kFace;
  std::array<int, 3> vertices = {-1, -1, -1};

  int size() const { return FeatureVertexCount(type); }
  static Feature Vertex(int i) { return {FeatureType::kVertex, {i, -1, -1}}; }
  // The edge {i, j}, stored sorted.
  static Feature Edge(int i, int j) {
    return {FeatureType::kEdge, {i < j ? i : j, i < j ? j : i, -1}};
  }
  static Feature Face(int a, int b, int c) { return {FeatureType::kFace, {a, b, c}}; }
};

inline bool operator==(const Feature& a, const Feature& b) {
  return a.type == b.type && a.vertices == b.vertices;
}
inline bool operator!=(const Feature& a, const Feature& b) { return !(a == b); }

// "edge(3,17)", for logs and test messages.
std::ostream& operator<<(std::ostream& out, const Feature& feature);

}  // namespace ergo

// Crafted meshes that once made the mesh check quadratic (issue 19): many copies of one
// triangle or tet, a stack of parallel triangles whose bounding boxes all overlap, and a
// closed double cone of slivers (every side triangle's box holds its apex). Written at any
// size, so the benchmark times them at full size and the tests check verdicts on small ones.
#pragma once

#include <string>

#include "ergo/mesh/tri_mesh.h"

namespace ergo::testing {

// OBJ with 3 vertices and `count` copies of the face "f 1 2 3" (8 bytes each).
void WriteDuplicateTrianglesObj(const std::string& path, int count);

// TetGen pair (`stem`.node, `stem`.ele): 4 nodes and `count` copies of one positive tet.
void WriteDuplicateTetsTetGen(const std::string& stem, int count);

// `count` parallel triangles 1 µm apart in the planes x − z = c (0.1 m legs), none touching;
// every box overlaps every other while count·1 µm < 0.1 m. Open surface, no intersection.
TriMesh ParallelTriangleStack(int count);

// A closed, outward, manifold double cone (radius 0.05 m, apexes ±0.1 m) of 2·segments
// sliver triangles; no self-intersection.
TriMesh SliverDoubleCone(int segments);

}  // namespace ergo::testing

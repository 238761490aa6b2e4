// Support: validation of the mesh, closest point and inside test against brute force on
// an icosphere, a bevelled box and a torus, hints, vertex updates, degenerate queries and
// concurrent queries.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/contact/support.h"
#include "ergo/contact/support_validation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "tests/contact/contact_test_util.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

using Eigen::Vector3d;

// ---- Validation ----

// Runs `make` and returns the InputError's message ("" if none was thrown).
template <class F>
std::string InputErrorMessage(F make) {
  try {
    make();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// Two closed spheres of radius 0.2 in one mesh, their centres 0.15 apart: closed, manifold,
// outward, but crossing each other.
TriMesh TwoOverlappingSpheres() {
  TriMesh two = MakeIcosphere(0.2, 2);
  const TriMesh shifted = MakeIcosphere(0.2, 2, Vector3d(0.15, 0, 0));
  const Eigen::Index n = two.vertices.rows(), m = two.triangles.rows();
  two.vertices.conservativeResize(2 * n, 3);
  two.vertices.bottomRows(n) = shifted.vertices;
  two.triangles.conservativeResize(2 * m, 3);
  two.triangles.bottomRows(m) = shifted.triangles.array() + static_cast<int>(n);
  return two;
}

TriMesh TwoTetrahedra(bool share_edge) {
  // Two tetrahedra touching at one vertex (0) or along one edge (0-1).
  TriMesh mesh;
  mesh.vertices.resize(share_edge ? 6 : 7, 3);
  mesh.vertices.row(0) << 0, 0, 0;
  mesh.vertices.row(1) << 1, 0, 0;
  mesh.vertices.row(2) << 0, 1, 0;
  mesh.vertices.row(3) << 0, 0, 1;
  if (share_edge) {
    mesh.vertices.row(4) << 0, -1, 0;
    mesh.vertices.row(5) << 0, 0, -1;
    mesh.triangles.resize(8, 3);
    mesh.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,  //
        0, 5, 1, 0, 1, 4, 0, 4, 5, 1, 5, 4;
  } else {
    mesh.vertices.row(4) << -1, 0, 0;
    mesh.vertices.row(5) << 0, -1, 0;
    mesh.vertices.row(6) << 0, 0, -1;
    mesh.triangles.resize(8, 3);
    mesh.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,  //
        0, 5, 4, 0, 4, 6, 0, 6, 5, 4, 5, 6;
  }
  return mesh;
}

TEST(Contact, SupportRefusesOpenInconsistentAndDegenerateMeshes) {
  const TriMesh sphere = MakeIcosphere(0.2, 2);
  EXPECT_EQ(InputErrorMessage([&] { Support s(sphere, "seat.ply"); }), "");

  TriMesh open = sphere;
  open.triangles.conservativeResize(open.triangles.rows() - 1, 3);
  std::string message = InputErrorMessage([&] { Support s(open, "seat.ply"); });
  EXPECT_NE(message.find("seat.ply:edge ("), std::string::npos) << message;
  EXPECT_NE(message.find("open support"), std::string::npos) << message;

  TriMesh flipped_one = sphere;
  flipped_one.triangles.row(7) = flipped_one.triangles.row(7).reverse().eval();
  message = InputErrorMessage([&] { Support s(flipped_one, "seat.ply"); });
  EXPECT_NE(message.find("inconsistent orientation"), std::string::npos) << message;
  EXPECT_NE(message.find("fix:"), std::string::npos) << message;

  TriMesh inside_out = sphere;
  inside_out.triangles = inside_out.triangles.rowwise().reverse().eval();
  message = InputErrorMessage([&] { Support s(inside_out, "seat.ply"); });
  EXPECT_NE(message.find("inside-out"), std::string::npos) << message;

  TriMesh repeated = sphere;
  repeated.triangles(3, 1) = repeated.triangles(3, 0);
  message = InputErrorMessage([&] { Support s(repeated, "seat.ply"); });
  EXPECT_NE(message.find("seat.ply:triangle 3: degenerate triangle"), std::string::npos) << message;

  TriMesh flat = sphere;  // move a vertex onto the line of two others
  const int a = flat.triangles(0, 0), b = flat.triangles(0, 1), c = flat.triangles(0, 2);
  flat.vertices.row(c) = 0.5 * (flat.vertices.row(a) + flat.vertices.row(b));
  message = InputErrorMessage([&] { Support s(flat, "seat.ply"); });
  EXPECT_NE(message.find("zero area"), std::string::npos) << message;

  message = InputErrorMessage([&] { Support s(TwoTetrahedra(true), "two.ply"); });
  EXPECT_NE(message.find("non-manifold edge"), std::string::npos) << message;
  message = InputErrorMessage([&] { Support s(TwoTetrahedra(false), "two.ply"); });
  EXPECT_NE(message.find("two.ply:vertex 0: non-manifold vertex"), std::string::npos) << message;

  TriMesh out_of_range = sphere;
  out_of_range.triangles(2, 2) = static_cast<int>(sphere.vertices.rows());
  message = InputErrorMessage([&] { Support s(out_of_range, "seat.ply"); });
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;

  TriMesh not_finite = sphere;
  not_finite.vertices(4, 1) = NAN;
  message = InputErrorMessage([&] { Support s(not_finite, "seat.ply"); });
  EXPECT_NE(message.find("vertex 4: non-finite"), std::string::npos) << message;

  // Two overlapping closed spheres in one mesh: closed, manifold, outward — but crossing.
  TriMesh two = TwoOverlappingSpheres();
  const Eigen::Index n = two.vertices.rows() / 2;
  message = InputErrorMessage([&] { Support s(two, "two.ply"); });
  EXPECT_NE(message.find("self-intersecting support: triangles"), std::string::npos) << message;
  EXPECT_NE(message.find(" m) (fix:"), std::string::npos) << message;  // where, in metres
  // Apart, the two spheres are a valid support.
  two.vertices.bottomRows(n).col(0).array() += 1.0;
  EXPECT_EQ(InputErrorMessage([&] { Support s(two, "two.ply"); }), "");

  TriMesh empty;
  message = InputErrorMessage([&] { Support s(empty, "seat.ply"); });
  EXPECT_NE(message.find("at least 4"), std::string::npos) << message;
}

// A built body's skin gets the support's checks with what they mean for a skin: two toes
// meshed into each other (here two skin spheres overlapping, and two touching at one vertex)
// are refused naming the built skin, the finding, and the edge lengths to try; a clean skin
// passes.
TEST(Support, ABuiltSkinThatTouchesItselfIsRefusedWithWhatToTry) {
  EXPECT_EQ(InputErrorMessage([&] { ValidateSkinForContact(MakeIcosphere(0.05, 2), "foot"); }), "");
  const TriMesh two = TwoOverlappingSpheres();
  std::string message =
      InputErrorMessage([&] { ValidateSkinForContact(two, "foot.obj (the built body's skin)"); });
  EXPECT_NE(message.find("foot.obj (the built body's skin):triangles"), std::string::npos)
      << message;
  EXPECT_NE(message.find("self-intersecting"), std::string::npos) << message;
  EXPECT_NE(message.find(" m); the meshed skin touches or overlaps itself"), std::string::npos)
      << message;
  EXPECT_NE(message.find("--edge_length"), std::string::npos) << message;
  message = InputErrorMessage([&] { ValidateSkinForContact(TwoTetrahedra(false), "hand.obj"); });
  EXPECT_NE(message.find("non-manifold vertex"), std::string::npos) << message;
  EXPECT_NE(message.find("(at (0, 0, 0) m)"), std::string::npos) << message;  // the pinch
  EXPECT_NE(message.find("touches or overlaps itself"), std::string::npos) << message;
}

// ---- Brute force ----

struct Shape {
  std::string name;
  TriMesh mesh;
};

std::vector<Shape> Shapes() {
  TriMesh sphere = MakeIcosphere(0.25, 3, Vector3d(0.1, -0.05, 0.3));
  TriMesh box = contact_testing::MakeBevelledBox(Vector3d(0.3, 0.2, 0.1), 0.04, 2);
  box.vertices.rowwise() += Eigen::RowVector3d(-0.2, 0.1, 0.05);
  TriMesh torus = MakeTorus(0.3, 0.1, 48, 24);
  return {{"icosphere", sphere}, {"bevelled box", box}, {"torus", torus}};
}

// Half the queries uniform in the enlarged bounding box, half within ±2 % of the box
// diagonal of a random surface point (where the features are close together).
std::vector<Vector3d> Queries(const TriMesh& mesh, int count, unsigned seed) {
  std::mt19937 rng(seed);
  const Vector3d lo = mesh.vertices.colwise().minCoeff();
  const Vector3d hi = mesh.vertices.colwise().maxCoeff();
  const Vector3d centre = 0.5 * (lo + hi), half = 0.6 * (hi - lo);
  const double diagonal = (hi - lo).norm();
  std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(mesh.triangles.rows()) - 1);
  std::vector<Vector3d> queries;
  for (int i = 0; i < count; ++i) {
    if (i % 2 == 0) {
      queries.push_back(centre + half.cwiseProduct(Vector3d(unit(rng), unit(rng), unit(rng))));
    } else {
      const int f = pick(rng);
      double u = zero_one(rng), v = zero_one(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vector3d a = mesh.vertices.row(mesh.triangles(f, 0));
      const Vector3d b = mesh.vertices.row(mesh.triangles(f, 1));
      const Vector3d c = mesh.vertices.row(mesh.triangles(f, 2));
      queries.push_back(a + u * (b - a) + v * (c - a) +
                        0.02 * diagonal * Vector3d(unit(rng), unit(rng), unit(rng)));
    }
  }
  return queries;
}

// The feature a brute-force projection names, in support vertex ids.
Feature FeatureOf(const TriMesh& mesh, const contact_testing::BruteForceClosest& brute) {
  const auto corner = [&](int c) { return mesh.triangles(brute.triangle, c % 3); };
  switch (brute.projection.type) {
    case FeatureType::kVertex:
      return Feature::Vertex(corner(brute.projection.index));
    case FeatureType::kEdge:
      return Feature::Edge(corner(brute.projection.index), corner(brute.projection.index + 1));
    case FeatureType::kFace:
      return Feature::Face(corner(0), corner(1), corner(2));
  }
  return {};
}

TEST(Contact, ClosestPointAndInsideTestAgreeWithBruteForce) {
  for (const Shape& shape : Shapes()) {
    SCOPED_TRACE(shape.name);
    const Support support(shape.mesh, shape.name);
    int distance_disagreements = 0, feature_disagreements = 0, side_disagreements = 0;
    int inside_count = 0, near_surface = 0;
    SupportPoint previous;
    bool have_previous = false;
    // A quarter of the queries under the sanitizers (each is a brute-force pass).
    const int queries = testing::SanitizedBuild() ? 2500 : 10000;
    for (const Vector3d& p : Queries(shape.mesh, queries, 41)) {
      const contact_testing::BruteForceClosest brute =
          contact_testing::BruteForceClosestPoint(shape.mesh, p);
      const SupportPoint cold = support.ClosestPoint(p);
      const double brute_distance = std::sqrt(brute.projection.squared_distance);
      if (std::abs(std::sqrt(cold.squared_distance) - brute_distance) > 1e-12) {
        ++distance_disagreements;
        ADD_FAILURE() << "distance " << std::sqrt(cold.squared_distance) << " vs brute force "
                      << brute_distance << " at " << p.transpose();
      }
      if (cold.feature != FeatureOf(shape.mesh, brute)) ++feature_disagreements;
      EXPECT_LE((cold.point - brute.projection.point).norm(), 1e-12);

      // A hint (the previous, unrelated answer) does not change the answer.
      if (have_previous) {
        const SupportPoint hinted = support.ClosestPoint(p, &previous);
        EXPECT_EQ(hinted.squared_distance, cold.squared_distance);
        EXPECT_EQ(hinted.feature, cold.feature);
        EXPECT_EQ(hinted.triangle, cold.triangle);
      }
      previous = cold;
      have_previous = true;

      // Inside test against the winding number, except within 1e-12 of the surface.
      if (brute_distance <= 1e-12) {
        ++near_surface;
        continue;
      }
      const bool inside = contact_testing::WindingNumber(shape.mesh, p) > 0.5;
      inside_count += inside;
      if (support.Contains(p) != inside || cold.inside != inside) {
        ++side_disagreements;
        ADD_FAILURE() << "inside " << support.Contains(p) << " vs winding number " << inside
                      << " at " << p.transpose() << " distance " << brute_distance << " feature "
                      << cold.feature;
      }
      const std::optional<SupportPoint> penetration = support.Penetration(p);
      EXPECT_EQ(penetration.has_value(), inside);
      if (penetration) {
        EXPECT_EQ(penetration->squared_distance, cold.squared_distance);
      }
    }
    EXPECT_EQ(distance_disagreements, 0);
    EXPECT_EQ(feature_disagreements, 0);
    EXPECT_EQ(side_disagreements, 0);
    EXPECT_GT(inside_count, queries / 10);  // both sides were exercised
    EXPECT_LT(inside_count, 9000);
    std::printf(
        "[ brute force ] %-12s 10000 queries, %d inside, %d within 1e-12 of S: "
        "0 disagreements\n",
        shape.name.c_str(), inside_count, near_surface);
  }
}

TEST(Contact, UpdateVerticesGivesTheSameAnswersAsAFreshSupport) {
  TriMesh mesh = MakeTorus(0.3, 0.1, 32, 16);
  Support support(mesh, "torus");
  // Deform: squash, shift and wiggle (same connectivity, still a valid torus).
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> wiggle(-2e-3, 2e-3);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    mesh.vertices.row(v) = mesh.vertices.row(v).cwiseProduct(Eigen::RowVector3d(1.1, 0.9, 0.7)) +
                           Eigen::RowVector3d(0.05, 0, -0.02) +
                           Eigen::RowVector3d(wiggle(rng), wiggle(rng), wiggle(rng));
  }
  support.UpdateVertices(mesh.vertices);
  const Support fresh(mesh, "deformed torus");
  EXPECT_EQ(support.mesh().vertices, mesh.vertices);
  for (const Vector3d& p : Queries(mesh, 2000, 9)) {
    const SupportPoint a = support.ClosestPoint(p), b = fresh.ClosestPoint(p);
    EXPECT_EQ(a.squared_distance, b.squared_distance);
    EXPECT_EQ(a.feature, b.feature);
    EXPECT_EQ(a.inside, b.inside);
    EXPECT_EQ(a.squared_distance,
              contact_testing::BruteForceClosestPoint(mesh, p).projection.squared_distance);
  }
}

TEST(Contact, HintsOnlyShortcutWhatTheyProve) {
  // A vertex creeping towards the sphere in small steps, each query hinted with the last
  // full answer: the same answers as without hints.
  const TriMesh sphere_mesh = MakeIcosphere(0.2, 3);
  Support support(sphere_mesh);
  std::mt19937 rng(31);
  std::normal_distribution<double> normal;
  for (int path = 0; path < 200; ++path) {
    const Vector3d direction = Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    SupportPoint last = support.ClosestPoint(0.23 * direction);
    for (double r = 0.23; r > 0.17; r -= 0.0007) {
      const Vector3d p = r * direction + 1e-4 * Vector3d(normal(rng), normal(rng), normal(rng));
      EXPECT_EQ(support.Contains(p, &last), support.Contains(p));
      const std::optional<SupportPoint> hinted = support.Penetration(p, &last);
      const std::optional<SupportPoint> cold = support.Penetration(p);
      ASSERT_EQ(hinted.has_value(), cold.has_value()) << p.transpose();
      if (hinted) {
        EXPECT_EQ(hinted->squared_distance, cold->squared_distance);
        EXPECT_EQ(hinted->feature, cold->feature);
        last = *hinted;
      } else if (path % 2 == 0) {
        last = support.ClosestPoint(p, &last);  // half the paths refresh the hint each step
      }
    }
  }
  // A tracked vertex: the same answers, and most steps need no search at all.
  int searches = 0, steps = 0;
  for (int path = 0; path < 100; ++path) {
    const Vector3d direction = Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    SupportPoint track;
    for (double r = 0.25; r > 0.17; r -= 0.0005) {
      const Vector3d p = r * direction;
      const SupportPoint before = track;
      const std::optional<SupportPoint> tracked = support.TrackPenetration(p, &track);
      const std::optional<SupportPoint> cold = support.Penetration(p);
      ASSERT_EQ(tracked.has_value(), cold.has_value()) << p.transpose();
      if (tracked) {
        EXPECT_EQ(tracked->feature, cold->feature);
      }
      searches += track.query != before.query;
      ++steps;
    }
  }
  EXPECT_LT(searches, steps * 3 / 4);  // the shortcut fires while the vertex is outside

  // A hint from before the support moved proves nothing about the new shape.
  const Vector3d p(0, 0, 0.21);  // 1 cm outside the sphere
  const SupportPoint before = support.ClosestPoint(p);
  ASSERT_FALSE(before.inside);
  support.UpdateVertices(1.1 * sphere_mesh.vertices);  // now p is inside
  EXPECT_TRUE(support.Contains(p, &before));
  ASSERT_TRUE(support.Penetration(p, &before).has_value());
  SupportPoint stale = before;
  EXPECT_TRUE(support.TrackPenetration(p, &stale).has_value());
  EXPECT_NEAR(std::sqrt(support.Penetration(p, &before)->squared_distance), 0.22 - 0.21, 2e-3);
  // And one from another support neither.
  const Support other(MakeIcosphere(0.1, 2));
  const SupportPoint foreign = other.ClosestPoint(p);
  EXPECT_TRUE(support.Contains(p, &foreign));
  // Non-finite points are never inside (a diverging Newton step must not crash the query).
  EXPECT_FALSE(support.Contains(Vector3d(NAN, 0, 0)));
  EXPECT_FALSE(support.Penetration(Vector3d(0, INFINITY, 0)).has_value());
}

TEST(Contact, FeaturePositionsFollowTheFeatureOrder) {
  const TriMesh box = MakeBox(Vector3d(0, 0, 0), Vector3d(1, 1, 1), Eigen::Vector3i(2, 2, 2));
  const Support support(box);
  const SupportPoint s = support.ClosestPoint(Vector3d(0.3, 0.4, 0.9));  // inside, near the top
  ASSERT_EQ(s.feature.type, FeatureType::kFace);
  EXPECT_TRUE(s.inside);
  EXPECT_NEAR(s.squared_distance, 0.01, 1e-15);
  const FeaturePositions x = support.Positions(s.feature);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(x[i], Vector3d(box.vertices.row(s.feature.vertices[i])));
  // The energy of the reported feature is k × the reported squared distance.
  EXPECT_NEAR(EvaluateSlidingAnchor(s.feature.type, Vector3d(0.3, 0.4, 0.9), x, 2.0).energy,
              2.0 * s.squared_distance, 1e-15);
}

// ---- Degenerate queries ----

bool FaceHas(const Feature& feature, int v) {
  return feature.type == FeatureType::kFace &&
         std::count(feature.vertices.begin(), feature.vertices.end(), v) > 0;
}

TEST(Contact, QueriesExactlyOnVerticesAndEdgesAreDeterministic) {
  const TriMesh sphere = MakeIcosphere(0.2, 2);
  const Support support(sphere);
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(sphere.triangles.rows()) - 1);
  for (int v = 0; v < sphere.vertices.rows(); v += 7) {
    const Vector3d p = sphere.vertices.row(v);
    const SupportPoint s = support.ClosestPoint(p);
    // Exactly at a vertex: every incident triangle reports its (closed) face at distance 0;
    // the smallest triangle id wins.
    EXPECT_TRUE(FaceHas(s.feature, v)) << s.feature;
    EXPECT_EQ(s.squared_distance, 0.0);
    EXPECT_EQ(s.point, p);
    EXPECT_FALSE(s.inside);  // on S counts as outside
    EXPECT_FALSE(support.Contains(p));
    EXPECT_FALSE(support.Penetration(p).has_value());
    // The same feature whatever the hint.
    for (int h = 0; h < 5; ++h) {
      SupportPoint hint;
      hint.triangle = pick(rng);
      EXPECT_EQ(support.ClosestPoint(p, &hint).feature, s.feature);
      EXPECT_EQ(support.ClosestPoint(p, &hint).triangle, s.triangle);
    }
  }
  for (int f = 0; f < sphere.triangles.rows(); f += 5) {
    const int a = sphere.triangles(f, 0), b = sphere.triangles(f, 1);
    const Vector3d p = 0.5 * (Vector3d(sphere.vertices.row(a)) + Vector3d(sphere.vertices.row(b)));
    const SupportPoint s = support.ClosestPoint(p);
    EXPECT_TRUE(s.point.allFinite());
    EXPECT_LE(s.squared_distance, 1e-30);
    // On the edge up to the rounding of the midpoint: one of its two faces (or the edge).
    EXPECT_TRUE(s.feature == Feature::Edge(a, b) ||
                (FaceHas(s.feature, a) && FaceHas(s.feature, b)))
        << s.feature;
    for (int h = 0; h < 5; ++h) {
      SupportPoint hint;
      hint.triangle = pick(rng);
      const SupportPoint again = support.ClosestPoint(p, &hint);
      EXPECT_EQ(again.feature, s.feature);
      EXPECT_EQ(again.inside, s.inside);
    }
  }
}

TEST(Contact, CoplanarNeighboursGiveTheirSharedPlane) {
  // Each box side is a grid of coplanar triangles; points above diagonals, grid edges and
  // grid vertices, inside the box, all report the distance to the side and "inside".
  const TriMesh box = MakeBox(Vector3d(0, 0, 0), Vector3d(1, 1, 1), Eigen::Vector3i(4, 4, 4));
  const Support support(box);
  for (double x : {0.3, 0.375, 0.5, 0.625}) {
    for (double y : {0.3, 0.375, 0.5, 0.625}) {
      const Vector3d p(x, y, 0.75);  // 0.25 below the top side, nearer it than any other
      const SupportPoint s = support.ClosestPoint(p);
      EXPECT_NEAR(s.squared_distance, 0.0625, 1e-15) << p.transpose();
      EXPECT_TRUE(s.inside);
      EXPECT_LT((s.point - Vector3d(x, y, 1.0)).norm(), 1e-15);
      // The plane formula (no spurious tangential spring over the grid's edges and vertices,
      // whose Voronoi regions have zero thickness between coplanar triangles).
      EXPECT_EQ(s.feature.type, FeatureType::kFace) << p.transpose() << " " << s.feature;
      const SupportPoint again = support.ClosestPoint(p);
      EXPECT_EQ(again.feature, s.feature);
      EXPECT_NEAR(
          EvaluateSlidingAnchor(s.feature.type, p, support.Positions(s.feature), 1.0).energy,
          0.0625, 1e-15);
    }
  }
}

TEST(Contact, StraightCreasesGiveTheirLine) {
  // Outside a box edge split into four collinear segments, exactly beside a split vertex
  // (whose own region is a zero-thickness slab): the edge, i.e. the line formula.
  const TriMesh box = MakeBox(Vector3d(0, 0, 0), Vector3d(1, 1, 1), Eigen::Vector3i(4, 4, 4));
  const Support support(box);
  for (double x : {0.25, 0.5, 0.75, 0.375}) {
    const Vector3d p(x, -0.3, -0.4);
    const SupportPoint s = support.ClosestPoint(p);
    EXPECT_EQ(s.feature.type, FeatureType::kEdge) << x << " " << s.feature;
    EXPECT_NEAR(s.squared_distance, 0.25, 1e-15);
    EXPECT_FALSE(s.inside);
    const SlidingAnchorEnergy e =
        EvaluateSlidingAnchor(s.feature.type, p, support.Positions(s.feature), 1.0);
    EXPECT_NEAR(e.energy, 0.25, 1e-15);
    // No stiffness along the crease (x).
    EXPECT_NEAR(e.hessian(0, 0), 0.0, 1e-12);
  }
}

TEST(Contact, SliverTrianglesInASupportGiveFiniteAnswers) {
  // A tetrahedron whose base is a sliver (height 1e-10 over a unit edge).
  TriMesh tet;
  tet.vertices.resize(4, 3);
  tet.vertices << 0, 0, 0, 1, 0, 0, 0.5, 1e-10, 0, 0.5, 0.3, 0.8;
  tet.triangles.resize(4, 3);
  tet.triangles << 0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3;
  const Support support(tet, "sliver tetrahedron");
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d p(u(rng), 0.5 * u(rng), 0.8 * u(rng) - 0.1);
    const SupportPoint s = support.ClosestPoint(p);
    EXPECT_TRUE(s.point.allFinite());
    EXPECT_TRUE(std::isfinite(s.squared_distance));
    EXPECT_NE(s.feature, Feature::Face(0, 2, 1));  // never the sliver's face
    EXPECT_EQ(support.ClosestPoint(p).feature, s.feature);
    const auto brute = contact_testing::BruteForceClosestPoint(tet, p);
    EXPECT_NEAR(std::sqrt(s.squared_distance), std::sqrt(brute.projection.squared_distance), 1e-12);
    const SlidingAnchorEnergy e =
        EvaluateSlidingAnchor(s.feature.type, p, support.Positions(s.feature), 1.0);
    EXPECT_TRUE(std::isfinite(e.energy) && e.gradient.allFinite() && e.hessian.allFinite());
  }
}

TEST(Contact, ConcurrentQueriesMatchSequentialOnes) {
  const TriMesh torus = MakeTorus(0.3, 0.1, 48, 24);
  const Support support(torus);
  const std::vector<Vector3d> queries = Queries(torus, 4000, 77);
  std::vector<SupportPoint> sequential;
  for (const Vector3d& p : queries) sequential.push_back(support.ClosestPoint(p));
  std::vector<std::vector<SupportPoint>> parallel(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (const Vector3d& p : queries) parallel[t].push_back(support.ClosestPoint(p));
    });
  }
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < 4; ++t) {
    for (std::size_t i = 0; i < queries.size(); ++i) {
      EXPECT_EQ(parallel[t][i].squared_distance, sequential[i].squared_distance);
      EXPECT_EQ(parallel[t][i].feature, sequential[i].feature);
    }
  }
}

}  // namespace
}  // namespace ergo

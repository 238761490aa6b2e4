// Checks shared by the scenario tests (issue 8): a built scene's support passes the mesh
// check as a closed, manifold, self-intersection-free surface; its body's tets are well
// shaped; the initial equilibrium converges with the contact force balancing the load in
// every unlocked translation; the largest penetration is near the calibrated 0.3 mm.
#pragma once

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/tet_quality.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/mesh_check.h"
#include "problems/scenario.h"
#include "problems/scenario_parts.h"

namespace ergo {

// Tet quality bounds. The quick presets mesh with a 10° sliver bound (perturbation and
// exudation stop once every dihedral angle is above it): measured minimum dihedral angles
// 10.00–10.02° and radius ratios 0.12–0.18 over the three bodies, so 9.5° and 0.1 leave
// room for rounding differences between builds, not for a worse mesher.
inline constexpr double kMinDihedralDegrees = 9.5;
inline constexpr double kMinRadiusRatio = 0.1;

// The support passes the foundation's mesh check as a support (closed required).
inline void ExpectValidSupport(const TriMesh& support, const std::string& name) {
  MeshCheckOptions options;
  options.require_closed = true;
  const MeshCheckReport report = CheckTriMesh(support, name, options);
  EXPECT_EQ(report.Worst(), Severity::kNote) << report.FullReport();
  // The self-intersection test must have run (it is skipped, with a note, on non-manifolds).
  EXPECT_EQ(report.Find("self-intersections"), nullptr) << report.FullReport();
  EXPECT_EQ(report.Find("self-intersection-not-checked"), nullptr) << report.FullReport();
}

// Smallest corner angle (degrees) of the support's triangles, over all of them and over
// those whose corners are all designed. Measured on the quick presets: all ≥ 9.5° (the
// block's side caps where the arc meets the front wall; 26° for the sole, 35° for the
// mouse), designed ≥ 28° (45° on the structured tops, 28–31° after a negative image's
// remeshing and smoothing). The bounds: 8° and 20°.
inline constexpr double kMinSupportAngleDegrees = 8;
inline constexpr double kMinDesignedAngleDegrees = 20;

inline void ExpectWellShapedSupport(const Scenario& scenario) {
  const TriMesh& s = scenario.support;
  double all = 180, designed = 180;
  for (Eigen::Index f = 0; f < s.triangles.rows(); ++f) {
    bool active = true;
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = s.vertices.row(s.triangles(f, k));
      const Eigen::Vector3d b = s.vertices.row(s.triangles(f, (k + 1) % 3));
      const Eigen::Vector3d c = s.vertices.row(s.triangles(f, (k + 2) % 3));
      const double cosine = (b - a).normalized().dot((c - a).normalized());
      smallest = std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI);
      active =
          active && (scenario.design.active.empty() || scenario.design.active[s.triangles(f, k)]);
    }
    all = std::min(all, smallest);
    if (active) designed = std::min(designed, smallest);
  }
  std::cout << scenario.name << " support: smallest angle " << all << "°, designed " << designed
            << "°\n";
  EXPECT_GE(all, kMinSupportAngleDegrees);
  EXPECT_GE(designed, kMinDesignedAngleDegrees);
}

// The body's tet mesh: no inverted or flat tets, and the quality bounds above.
inline void ExpectWellShapedBody(const LayeredBody& body) {
  const TetQuality quality = MeasureTetQuality(body.rest());
  EXPECT_EQ(quality.non_positive_count, 0);
  EXPECT_GE(quality.min_dihedral_degrees, kMinDihedralDegrees);
  EXPECT_GE(quality.min_radius_ratio, kMinRadiusRatio);
  MeshCheckOptions options;
  const MeshCheckReport report = CheckTetMesh(body.rest(), "body", options);
  EXPECT_EQ(report.Worst(), Severity::kNote) << report.FullReport();
}

// Solves the initial equilibrium and checks the force balance: in every translation the
// lock leaves free, the contact force equals the load (weight + external force) to 1e-6 of
// it; locked translations may carry a reaction (the support's sideways push, which the
// frictionless contact cannot balance otherwise and the lock absorbs, as in the paper).
// The largest penetration must lie in [min_penetration, max_penetration] metres.
inline EquilibriumResult ExpectBalancedEquilibrium(const Scenario& scenario, double min_penetration,
                                                   double max_penetration) {
  EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
  const EquilibriumResult result = solver.Solve(Support(scenario.support), scenario.start);
  std::cout << scenario.description << "\n" << result.FullReport() << "\n";
  EXPECT_TRUE(result.converged) << result.FullReport();
  const Eigen::Vector3d load = scenario.body->TotalLoad();
  const Eigen::Vector3d balance = result.contact_force + load;
  int free_translations = 0;
  for (int component : scenario.body->lock().FreeComponents()) {
    if (component >= 3) continue;
    ++free_translations;
    EXPECT_LE(std::abs(balance[component]), 1e-6 * load.norm())
        << "translation " << component << ": contact " << result.contact_force.transpose()
        << " N, load " << load.transpose() << " N";
  }
  EXPECT_GE(free_translations, 1);
  EXPECT_GE(result.max_penetration, min_penetration);
  EXPECT_LE(result.max_penetration, max_penetration);
  EXPECT_GT(result.contact_springs, 10);
  return result;
}

}  // namespace ergo

// The layered indentation law against ergo's own FEM (the correction the calibration would
// need): a 10 mm tissue layer (E = 40 kPa, ν = 0.45, neo-Hookean) bonded to a rigid core —
// a 60 × 60 mm slab — pressed onto a rigid 10 mm sphere by the force the law gives for a
// target indentation δ; the FEM's indentation is the core's travel from first contact, less
// the placement gap and the penalty penetration at the tip. Small-strain theory and the
// finite-strain FEM must agree where the law is meant to hold (δ/h ≤ 0.2, χ ≤ 0.45), and
// the agreement is printed for ergo/calibration/README.md.
#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/body/layer_builder.h"
#include "ergo/calibration/layered_indentation.h"
#include "ergo/equilibrium/calibrate_contact_stiffness.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

constexpr double kYoung = 4e4, kPoisson = 0.45;
constexpr double kDepth = 0.010;    // h: the tissue under the core
constexpr double kTip = 0.010;      // R
constexpr double kHalfSide = 0.03;  // the slab is 2·kHalfSide wide: 6 h, 13 contact radii at 2 mm
constexpr double kWrap = 0.004;     // tissue around the core's sides and top
constexpr double kCoreHeight = 0.008;

// Exact signed distance to an axis-aligned box.
double BoxDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const Eigen::Vector3d q = (p - centre).cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

BuiltLayer BuildSlab(double fine_edge) {
  // Skin's bottom face at y = 0, the layer above it, the core above the layer.
  const Eigen::Vector3d outer_lo(-kHalfSide, 0, -kHalfSide),
      outer_hi(kHalfSide, kDepth + kCoreHeight + kWrap, kHalfSide);
  const Eigen::Vector3d core_lo(-kHalfSide + kWrap, kDepth, -kHalfSide + kWrap),
      core_hi(kHalfSide - kWrap, kDepth + kCoreHeight, kHalfSide - kWrap);
  ImplicitLayer layer;
  layer.outer = [=](const Eigen::Vector3d& p) { return BoxDistance(p, outer_lo, outer_hi); };
  layer.core = [=](const Eigen::Vector3d& p) { return BoxDistance(p, core_lo, core_hi); };
  layer.bounds = Eigen::AlignedBox3d(outer_lo - Eigen::Vector3d::Constant(0.005),
                                     outer_hi + Eigen::Vector3d::Constant(0.005));
  BuilderOptions builder;
  builder.edge_length = 0.005;
  builder.edge_length_field = [=](const Eigen::Vector3d& p) {
    return std::min(0.005, fine_edge + std::max(0.0, p.norm() - 0.006) * 0.4);
  };
  builder.seed = 1;
  return BuildLayerFromImplicit(layer, builder, "indented slab");
}

struct FemIndentation {
  double indentation = 0, penetration = 0;
  int vertices = 0, contacts = 0;
  bool converged = false;
};

FemIndentation Indent(const BuiltLayer& built, double force) {
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(built.mesh.tets.rows(), kYoung);
  material.poisson_ratio = Eigen::VectorXd::Constant(built.mesh.tets.rows(), kPoisson);
  LayeredBodyOptions options;
  options.gravity.setZero();  // the load is F alone
  options.external_force = Eigen::Vector3d(0, -force, 0);
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  const LayeredBody body =
      LayeredBody::Create(built.mesh, built.attached, material, options, "indented slab");
  TriMesh sphere = MakeIcosphere(kTip, 5);  // 10k triangles: facets 0.3 mm across
  for (Eigen::Index v = 0; v < sphere.vertices.rows(); ++v) sphere.vertices(v, 1) -= kTip;
  const Support tip(sphere, "indenter");
  constexpr double kGap = 1e-5;
  const BodyState start = PlaceAboveSupport(body, RestState(body), tip, kGap).state;
  EquilibriumOptions eq;
  eq.contact_stiffness = 1e8;  // a first guess for the calibration
  EquilibriumSolver solver(body, eq);
  SphericalIndenter indenter;
  indenter.radius = kTip;
  indenter.poisson_ratio = kPoisson;
  // Penalty penetration 0.5 % of the indentation the law expects.
  double expected = 0;
  for (double lo = 0, hi = kDepth, k = 0; k < 60; ++k) {
    expected = 0.5 * (lo + hi);
    (LayeredIndentationForce(indenter, kYoung, kDepth, expected).force < force ? lo : hi) =
        expected;
  }
  EquilibriumResult result;
  const CalibrationResult calibration = CalibrateContactStiffness(
      solver, tip, start, 0.005 * expected, CalibrationOptions(), &result);
  FemIndentation fem;
  fem.converged = calibration.converged && result.converged;
  const double travel = start.centre.y() - result.state.centre.y();
  fem.penetration = result.max_penetration;
  fem.indentation = travel - kGap - result.max_penetration;
  fem.vertices = static_cast<int>(body.rest().vertices.rows());
  fem.contacts = result.contact_vertices;
  return fem;
}

TEST(Calibration, LayerLawAgreesWithErgosFemWhereItIsMeantToHold) {
  if (testing::SanitizedBuild()) GTEST_SKIP() << "a Release measurement (25 s)";
  SphericalIndenter indenter;
  indenter.radius = kTip;
  indenter.poisson_ratio = kPoisson;
  // Measured (2026-12-04): E fitted / E at δ = 0.5, 1, 2 mm is 1.132, 1.105, 1.107 at 1.4 mm
  // edges, 1.079, 1.077, 1.089 at 1.0 mm and 1.050, 1.055, 1.072 at 0.7 mm (40 s, not run
  // here): linear tets are stiff, and the gap left as they shrink — a few per cent, growing
  // with δ/h — is the finite-strain stiffening of the neo-Hookean tissue.
  const double fine_edges[] = {0.0014, 0.0010};
  const double targets[] = {0.0005, 0.0010, 0.0020};
  double ratios[2][3];
  for (int f = 0; f < 2; ++f) {
    const BuiltLayer slab = BuildSlab(fine_edges[f]);
    for (int t = 0; t < 3; ++t) {
      const IndentationForce law = LayeredIndentationForce(indenter, kYoung, kDepth, targets[t]);
      const FemIndentation fem = Indent(slab, law.force);
      ASSERT_TRUE(fem.converged);
      // The force the law gives at the FEM's indentation, against the force applied: the
      // modulus a calibration on FEM data would return, relative to the true one.
      const double law_at_fem =
          LayeredIndentationForce(indenter, kYoung, kDepth, fem.indentation).force;
      ratios[f][t] = law.force / law_at_fem;
      const double hertz_ratio =
          law.force / LayeredIndentationForce(indenter, kYoung, INFINITY, fem.indentation).force;
      std::cout << "fine edge " << 1e3 * fine_edges[f] << " mm, " << fem.vertices << " vertices, "
                << fem.contacts << " in contact: delta " << 1e3 * targets[t] << " mm (chi "
                << law.chi << ", delta/h " << targets[t] / kDepth << "), F = " << law.force
                << " N; FEM delta " << 1e3 * fem.indentation << " mm (penetration "
                << 1e6 * fem.penetration << " um); E fitted / E = " << ratios[f][t]
                << " (layer law), " << hertz_ratio << " (Hertz)\n";
      // The layer correction matters: Hertz alone misreads E by 35-85 %.
      EXPECT_GT(std::abs(hertz_ratio - 1), 3 * std::abs(ratios[f][t] - 1)) << targets[t];
    }
  }
  for (int t = 0; t < 3; ++t) {
    // FEM stiffer than the law, less so on the finer mesh, within 10 % at 1 mm edges.
    EXPECT_GT(ratios[1][t], 1) << targets[t];
    EXPECT_LT(ratios[1][t], ratios[0][t]) << targets[t];
    EXPECT_LT(ratios[1][t], 1.10) << targets[t];
  }
}

}  // namespace
}  // namespace ergo

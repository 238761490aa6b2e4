// Indentation of a soft tissue layer by a rigid sphere (paper §3.1: the layer's depth and
// Young's modulus are measured on the subject): the closed-form force–indentation law of a
// linear-elastic layer of thickness h on a rigid base (the bone), Dimitriadis et al. 2002
// (Biophys J 82:2798), the Hertz law times a series in χ = √(Rδ)/h:
//
//   F(δ) = 4E / (3(1 − ν²)) · √R · δ^{3/2} · (1 + c₁χ + c₂χ² + c₃χ³ + c₄χ⁴),
//
// the coefficients from ν and from whether the layer is bonded to the base (tissue on bone:
// bonded) or slides on it. h = ∞ is the Hertz half-space. SI units: m, Pa, N.
// ergo/calibration/README.md gives the coefficients and where the law stops being valid.
#pragma once

#include <Eigen/Core>

namespace ergo {

enum class LayerBase { kBonded, kSliding };

struct SphericalIndenter {
  double radius = 0;            // R, m
  double poisson_ratio = 0.45;  // ν of the tissue, in (−1, 0.5]
  LayerBase base = LayerBase::kBonded;
};

// The series' coefficients c₁..c₄ for ν and the base.
Eigen::Vector4d LayerCorrectionCoefficients(double poisson_ratio, LayerBase base);

// F and its partial derivatives at one indentation.
struct IndentationForce {
  double force = 0;             // N
  double d_youngs_modulus = 0;  // ∂F/∂E, N/Pa
  double d_depth = 0;           // ∂F/∂h, N/m (0 for the half-space)
  double d_indentation = 0;     // ∂F/∂δ, N/m
  double chi = 0;               // √(Rδ)/h
};

// The law at indentation δ ≥ 0 for modulus E > 0 and depth h > 0 (infinity: the Hertz
// half-space).
IndentationForce LayeredIndentationForce(const SphericalIndenter& indenter, double youngs_modulus,
                                         double depth, double indentation);

}  // namespace ergo

// The tissue depth and Young's modulus over a skin surface, from what the user gave: a
// constant, measured samples (x,y,z,value CSV), anatomical priors (anatomical_priors.h), or
// priors with measured samples replacing them near the measurements. One place for
// `ergo_body build` and a scenario's --skin, so both read the same flags the same way.
// Metres, Pa.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/layer_builder.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/body/tissue_material.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct TissueFieldInputs {
  AnatomyOptions anatomy;                // kNone: constants or samples only
  std::optional<double> depth;           // m; not with anatomy
  std::string depth_samples;             // CSV x,y,z,depth (in `unit`)
  std::optional<double> youngs_modulus;  // Pa; not with anatomy
  std::string stiffness_samples;         // CSV x,y,z,E (x,y,z in `unit`, E in Pa)
  LengthUnit unit = LengthUnit::kMetre;
  // The rotation applied to the skin (axis_map.h), applied to the samples' points too.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  // The flags that set these, for messages (ergo_body's; a scenario's --skin names its own).
  std::string depth_flag = "depth", depth_samples_flag = "depth_samples",
              modulus_flag = "youngs_modulus", modulus_samples_flag = "stiffness_samples";
};

struct TissueFields {
  SampleInterpolant depth, youngs_modulus;
  // The tissue's stiffening exponent α (TissueMaterial) where the priors set one other than
  // 2 (the foot's fat pads); empty: neo-Hookean everywhere. Measured moduli keep it (the
  // indentation fit gives E, the small-strain modulus; α is the curve's shape).
  std::optional<SampleInterpolant> stiffening_exponent;
  std::optional<AnatomicalPriors> priors;              // when an anatomy was given
  std::string depth_description, modulus_description;  // for reports
};

// Without anatomy exactly one of depth / depth_samples and one of youngs_modulus /
// stiffness_samples is required; with anatomy the constants are refused and the samples,
// if given, replace the priors within AnatomyOptions::override_radius. Throws InputError
// naming the flag or the file.
TissueFields MakeTissueFields(const TriMesh& skin, const TissueFieldInputs& inputs,
                              const std::string& source);

// The per-tet material of a layer built over the skin: E and α (when given) from the field
// at each tet's nearest skin point, ν constant.
TissueMaterial TissueMaterialOnLayer(const BuiltLayer& layer, const SampleInterpolant& stiffness,
                                     const std::optional<SampleInterpolant>& stiffening_exponent,
                                     double poisson_ratio);

}  // namespace ergo

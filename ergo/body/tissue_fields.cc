#include "ergo/body/tissue_fields.h"

#include <cmath>

#include "ergo/mesh/axis_map.h"
#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

PointSamples ReadSamples(const std::string& path, const TissueFieldInputs& inputs, bool is_length,
                         const std::string& name, const std::string& value_unit) {
  SampleCsvOptions csv;
  csv.unit = inputs.unit;
  csv.value_is_length = is_length;
  csv.value_name = name;
  csv.value_unit = value_unit;
  PointSamples samples = ReadPointSamplesCsv(path, csv);
  ApplyAxisMap(inputs.axes, &samples.points);
  return samples;
}

// One field: a constant, samples, or priors overridden by samples.
SampleInterpolant FieldOf(const std::optional<double>& constant, const std::string& csv,
                          const PointSamples* prior, const TissueFieldInputs& inputs,
                          bool is_length, const std::string& flag, const std::string& csv_flag,
                          const std::string& name, const std::string& value_unit,
                          const std::string& example, std::string* description) {
  if (prior != nullptr) {
    if (constant) {
      throw InputError("--" + flag, "", "a constant " + name + " and --anatomy both set it",
                       "drop --" + flag + " (give measured points with --" + csv_flag + ")");
    }
    if (csv.empty()) {
      *description = prior->source;
      return SampleInterpolant::Fit(*prior);
    }
    const PointSamples measured = ReadSamples(csv, inputs, is_length, name, value_unit);
    *description = prior->source + " with " + std::to_string(measured.points.rows()) +
                   " measured samples from " + csv;
    return SampleInterpolant::Fit(
        OverridePriorSamples(*prior, measured, inputs.anatomy.override_radius));
  }
  if (constant.has_value() == !csv.empty()) {
    throw InputError("--" + flag, "",
                     "give exactly one of --" + flag + ", --" + csv_flag + " and --anatomy",
                     "e.g. --" + flag + "=" + example);
  }
  if (!csv.empty()) {
    *description = csv;
    return SampleInterpolant::Fit(ReadSamples(csv, inputs, is_length, name, value_unit));
  }
  if (!(*constant > 0) || !std::isfinite(*constant)) {
    throw InputError("--" + flag, "", "must be a positive number",
                     "give e.g. --" + flag + "=" + example);
  }
  *description = "constant";
  return SampleInterpolant::Constant(*constant);
}

}  // namespace

TissueFields MakeTissueFields(const TriMesh& skin, const TissueFieldInputs& inputs,
                              const std::string& source) {
  TissueFields fields;
  if (inputs.anatomy.anatomy != Anatomy::kNone)
    fields.priors = ComputeAnatomicalPriors(skin, inputs.anatomy, source);
  const AnatomicalPriors* priors = fields.priors ? &*fields.priors : nullptr;
  fields.depth = FieldOf(inputs.depth, inputs.depth_samples, priors ? &priors->depth : nullptr,
                         inputs, true, inputs.depth_flag, inputs.depth_samples_flag, "depth", "m",
                         "0.02", &fields.depth_description);
  fields.youngs_modulus =
      FieldOf(inputs.youngs_modulus, inputs.stiffness_samples,
              priors ? &priors->youngs_modulus : nullptr, inputs, false, inputs.modulus_flag,
              inputs.modulus_samples_flag, "E", "Pa", "10000", &fields.modulus_description);
  if (priors != nullptr && priors->stiffening_exponent.values.size() != 0 &&
      priors->stiffening_exponent.values.maxCoeff() > 2.0) {
    fields.stiffening_exponent = SampleInterpolant::Fit(priors->stiffening_exponent);
  }
  return fields;
}

TissueMaterial TissueMaterialOnLayer(const BuiltLayer& layer, const SampleInterpolant& stiffness,
                                     const std::optional<SampleInterpolant>& stiffening_exponent,
                                     double poisson_ratio) {
  TissueMaterial material;
  material.youngs_modulus = InterpolateOntoTets(layer, stiffness);
  material.poisson_ratio = Eigen::VectorXd::Constant(layer.mesh.tets.rows(), poisson_ratio);
  if (stiffening_exponent)
    material.stiffening_exponent = InterpolateOntoTets(layer, *stiffening_exponent);
  return material;
}

}  // namespace ergo

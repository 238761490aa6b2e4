// Tissue calibration (ergo/calibration): the layered indentation law and the fit of one
// force–indentation curve, as ergo_calibrate does per measured point.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "ergo/calibration/indentation_fit.h"
#include "ergo/calibration/layered_indentation.h"
#include "ergo/mesh/input_error.h"
#include "python/src/bindings.h"

namespace py = pybind11;

namespace ergo::python {
namespace {

// The indenter from the calls' keyword arguments, checked as ergo_calibrate checks its flags.
SphericalIndenter IndenterArguments(double radius, double poisson_ratio,
                                    const std::string& layer_base) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw InputError("indenter_radius", "", "must be a positive number of metres",
                     "give the tip's radius, e.g. indenter_radius=0.005");
  if (!(poisson_ratio > -1 && poisson_ratio <= 0.5))
    throw InputError("poisson_ratio", "", std::to_string(poisson_ratio) + " is outside (-1, 0.5]",
                     "tissue is nearly incompressible: 0.45-0.5");
  if (layer_base != "bonded" && layer_base != "sliding")
    throw InputError("layer_base", "", "\"" + layer_base + "\" is unknown",
                     "use layer_base=\"bonded\" or \"sliding\"");
  SphericalIndenter indenter;
  indenter.radius = radius;
  indenter.poisson_ratio = poisson_ratio;
  indenter.base = layer_base == "bonded" ? LayerBase::kBonded : LayerBase::kSliding;
  return indenter;
}

double DepthArgument(const py::object& depth) {
  if (depth.is_none()) return std::numeric_limits<double>::infinity();
  const double value = depth.cast<double>();
  if (!(value > 0))
    throw InputError("depth", "", "must be positive metres or None (the half-space)",
                     "give the layer's depth, e.g. depth=0.017");
  return value;
}

py::dict FitDict(const IndentationFit& fit) {
  py::dict result;
  result["converged"] = fit.converged;
  result["message"] = fit.message;
  result["youngs_modulus"] = fit.youngs_modulus;
  result["youngs_modulus_stderr"] = fit.youngs_modulus_stderr;
  result["depth"] = std::isinf(fit.depth) ? py::object(py::none()) : py::float_(fit.depth);
  result["depth_stderr"] = fit.depth_stderr;
  result["depth_at_bound"] = fit.depth_at_bound;
  result["contact_offset"] = fit.contact_offset;
  result["contact_offset_stderr"] = fit.contact_offset_stderr;
  result["rms_residual"] = fit.rms_residual;
  result["relative_rms"] = fit.relative_rms;
  result["max_chi"] = fit.max_chi;
  result["max_strain"] = fit.max_strain;
  result["readings"] = fit.readings;
  result["summary"] = DescribeFit(fit);
  return result;
}

}  // namespace

void BindCalibration(py::module_& m) {
  m.def(
      "indentation_force",
      [](double youngs_modulus, const py::object& depth, const std::vector<double>& indentation,
         double indenter_radius, double poisson_ratio, const std::string& layer_base) {
        const SphericalIndenter indenter =
            IndenterArguments(indenter_radius, poisson_ratio, layer_base);
        if (!(youngs_modulus > 0) || !std::isfinite(youngs_modulus))
          throw InputError("youngs_modulus", "", "must be positive pascals",
                           "e.g. youngs_modulus=45e3");
        const double h = DepthArgument(depth);
        std::vector<double> force;
        for (double delta : indentation) {
          if (!(delta >= 0) || !std::isfinite(delta))
            throw InputError("indentation", "", "holds a value that is not a finite δ ≥ 0",
                             "give indentations in metres from first contact");
          force.push_back(LayeredIndentationForce(indenter, youngs_modulus, h, delta).force);
        }
        return force;
      },
      py::arg("youngs_modulus"), py::arg("depth"), py::arg("indentation"),
      py::arg("indenter_radius"), py::arg("poisson_ratio") = 0.45, py::arg("layer_base") = "bonded",
      "Forces (N) of the layered indentation law (ergo/calibration/README.md) at each\n"
      "indentation (m) of a rigid sphere into a layer of depth `depth` (m; None: the Hertz\n"
      "half-space) and modulus `youngs_modulus` (Pa).");
  m.def(
      "fit_indentation",
      [](const std::vector<double>& indentation, const std::vector<double>& force,
         double indenter_radius, double poisson_ratio, const std::string& layer_base,
         bool fit_depth, const py::object& depth, double max_depth, bool fit_contact_point) {
        if (indentation.size() != force.size())
          throw InputError("force", "",
                           "has " + std::to_string(force.size()) + " values, indentation " +
                               std::to_string(indentation.size()),
                           "give one force per indentation");
        for (size_t i = 0; i < force.size(); ++i) {
          if (!std::isfinite(indentation[i]) || !std::isfinite(force[i]))
            throw InputError("indentation", "reading " + std::to_string(i), "is not finite",
                             "give finite metres and newtons");
        }
        IndentationFitOptions options;
        options.indenter = IndenterArguments(indenter_radius, poisson_ratio, layer_base);
        options.fit_depth = fit_depth;
        options.depth = DepthArgument(depth);
        if (!(max_depth > 0))
          throw InputError("max_depth", "", "must be positive metres", "e.g. max_depth=0.1");
        options.max_depth = max_depth;
        options.fit_contact_point = fit_contact_point;
        IndentationFit fit;
        {
          py::gil_scoped_release release;
          fit = FitIndentationCurve(indentation, force, options);
        }
        return FitDict(fit);
      },
      py::arg("indentation"), py::arg("force"), py::arg("indenter_radius"),
      py::arg("poisson_ratio") = 0.45, py::arg("layer_base") = "bonded",
      py::arg("fit_depth") = false, py::arg("depth") = py::none(), py::arg("max_depth") = 0.1,
      py::arg("fit_contact_point") = false,
      "Young's modulus (and, with fit_depth=True, the layer's depth; with\n"
      "fit_contact_point=True, the logged indentation at first contact) of one point from its\n"
      "force (N) - indentation (m) curve, as ergo_calibrate fits it: a dict with\n"
      "youngs_modulus, depth (None for the half-space), their standard errors, converged,\n"
      "message, relative_rms, max_chi, max_strain, readings and a one-line summary.");
}

}  // namespace ergo::python

// Bodies (build, load, inspect) and one static equilibrium on a support.
#include <iostream>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "ergo/body/body_build.h"
#include "ergo/body/body_directory.h"
#include "ergo/body/body_state.h"
#include "ergo/body/core_lock.h"
#include "ergo/contact/support_validation.h"
#include "ergo/design/static_equilibrium.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "problems/stance_roll.h"
#include "python/src/bindings.h"
#include "python/src/body_handle.h"
#include "python/src/interrupt.h"
#include "python/src/json_to_python.h"

namespace py = pybind11;

namespace ergo::python {
namespace {

Eigen::Vector3d Vector3(const py::handle& value, const char* argument) {
  try {
    const std::vector<double> v = value.cast<std::vector<double>>();
    if (v.size() == 3 && std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]))
      return Eigen::Vector3d(v[0], v[1], v[2]);
  } catch (const py::cast_error&) {
  }
  throw InputError(argument, "", "is not three finite numbers",
                   "give (x, y, z), e.g. (0, -9.81, 0)");
}

LayeredBodyOptions LoadOptions(const py::object& gravity, const std::string& lock,
                               const py::object& external_force,
                               const py::object& external_torque) {
  LayeredBodyOptions options;
  options.gravity = Vector3(gravity, "gravity");
  options.external_force = Vector3(external_force, "external_force");
  options.external_torque = Vector3(external_torque, "external_torque");
  options.lock = ParseCoreLock(lock, "lock");
  return options;
}

// A progress argument: None/False = quiet, True = lines on sys.stderr, a callable = called
// with each line (with the GIL held).
std::function<void(const std::string&)> ProgressSink(const py::object& progress) {
  if (progress.is_none() || (py::isinstance<py::bool_>(progress) && !progress.cast<bool>()))
    return {};
  py::object sink = progress;
  if (py::isinstance<py::bool_>(progress)) {
    sink = py::module_::import("sys").attr("stderr").attr("write");
    return [sink](const std::string& line) {
      py::gil_scoped_acquire gil;
      sink(line + "\n");
    };
  }
  return [sink](const std::string& line) {
    py::gil_scoped_acquire gil;
    sink(line);
  };
}

// One option of BodyBuildOptions by its flag name; a value of the wrong type is an InputError.
void SetBuildOption(BodyBuildOptions* options, const std::string& name, const py::handle& value) {
  auto number = [&]() {
    try {
      return value.cast<double>();
    } catch (const py::cast_error&) {
      throw InputError("--" + name, "", "is not a number", "give a number, e.g. " + name + "=0.01");
    }
  };
  auto text = [&]() {
    if (!py::isinstance<py::str>(value))
      throw InputError("--" + name, "", "is not a string",
                       "give a path or a name, e.g. " + name + "=\"...\"");
    return value.cast<std::string>();
  };
  if (name == "surface")
    options->surface = text();
  else if (name == "unit")
    options->unit = UnitArgument(text(), "--unit");
  else if (name == "shape")
    options->shape = text();
  else if (name == "outer_radius")
    options->outer_radius = number();
  else if (name == "core_radius")
    options->core_radius = number();
  else if (name == "semi_axes")
    options->semi_axes = Vector3(value, "--semi_axes");
  else if (name == "depth")
    options->depth = number();
  else if (name == "depth_samples")
    options->depth_samples = text();
  else if (name == "youngs_modulus")
    options->youngs_modulus = number();
  else if (name == "stiffness_samples")
    options->stiffness_samples = text();
  else if (name == "poisson_ratio")
    options->poisson_ratio = number();
  else if (name == "density")
    options->density = number();
  else if (name == "core_mass")
    options->core_mass = number();
  else if (name == "core_density")
    options->core_density = number();
  else if (name == "compression_resistance")
    options->compression_resistance = number();
  else if (name == "inversion_threshold")
    options->inversion_threshold = number();
  else if (name == "edge_length")
    options->edge_length = number();
  else if (name == "facet_distance")
    options->facet_distance = number();
  else if (name == "seed")
    options->seed = static_cast<int>(number());
  else
    throw InputError("keyword argument " + name, "", "is not an option of build_body",
                     "the options are the flags of `ergo_body build --help`");
}

py::dict BodyInfo(const LayeredBody& body) {
  py::dict d;
  d["vertices"] = body.rest().vertices.rows();
  d["tets"] = body.rest().tets.rows();
  d["skin_vertices"] = body.skin().vertices.size();
  d["mass_kg"] = body.total_mass();
  d["core_mass_kg"] = body.core_mass();
  d["lock"] = body.lock().ToString();
  return d;
}

}  // namespace

void BindBody(py::module_& m) {
  py::class_<BodyHandle>(
      m, "Body", py::dynamic_attr(),
      "A body part: a tetrahedral tissue layer around a rigid core (paper §3.1).")
      .def_property_readonly(
          "rest_vertices", [](const BodyHandle& h) { return h.body->rest().vertices; },
          "#V × 3 rest positions, m")
      .def_property_readonly("tets", [](const BodyHandle& h) { return h.body->rest().tets; })
      .def_property_readonly(
          "attached",
          [](const BodyHandle& h) {
            Eigen::Matrix<bool, Eigen::Dynamic, 1> a(h.body->attached().size());
            for (size_t i = 0; i < h.body->attached().size(); ++i)
              a[static_cast<Eigen::Index>(i)] = h.body->attached()[i];
            return a;
          },
          "per vertex: moves with the rigid core")
      .def_property_readonly(
          "skin_vertices", [](const BodyHandle& h) { return h.body->skin().vertices; },
          "tet-mesh ids of the skin vertices (the order of skin pressures)")
      .def_property_readonly(
          "skin_triangles", [](const BodyHandle& h) { return h.body->skin().triangles; },
          "skin triangles as tet-mesh vertex ids, outward")
      .def_property_readonly("skin_areas",
                             [](const BodyHandle& h) { return h.body->skin().rest_areas; })
      .def_property_readonly(
          "mass", [](const BodyHandle& h) { return h.body->total_mass(); }, "kg")
      .def_property_readonly(
          "total_load", [](const BodyHandle& h) { return Eigen::Vector3d(h.body->TotalLoad()); },
          "weight + external force, N")
      .def_property_readonly("info", [](const BodyHandle& h) { return BodyInfo(*h.body); })
      .def("__repr__", [](const BodyHandle& h) {
        return "<ergo.Body " + std::to_string(h.body->rest().vertices.rows()) + " vertices, " +
               std::to_string(h.body->rest().tets.rows()) + " tets, " +
               std::to_string(h.body->total_mass()) + " kg>";
      });

  m.def(
      "load_body",
      [](const std::string& directory, const py::object& gravity, const std::string& lock,
         const py::object& external_force, const py::object& external_torque) {
        const LayeredBodyOptions options =
            LoadOptions(gravity, lock, external_force, external_torque);
        py::gil_scoped_release release;
        return BodyHandle{std::make_shared<const LayeredBody>(LoadLayeredBody(directory, options))};
      },
      py::arg("directory"), py::arg("gravity") = std::vector<double>{0, -9.81, 0},
      py::arg("lock") = "tx,tz", py::arg("external_force") = std::vector<double>{0, 0, 0},
      py::arg("external_torque") = std::vector<double>{0, 0, 0},
      "Loads a body directory written by `ergo_body build` (or build_body(out=...)).");

  m.def(
      "_build_body",
      [](const py::object& out, const py::object& progress, const py::kwargs& keywords) {
        BodyBuildOptions options;
        for (const auto& [key, value] : keywords)
          SetBuildOption(&options, key.cast<std::string>(), value);
        options.progress = ProgressSink(progress);
        const std::string directory = out.is_none() ? "" : out.cast<std::string>();
        ScopedInterrupt interrupt;
        BuiltBody built;
        std::shared_ptr<const LayeredBody> body;
        {
          py::gil_scoped_release release;
          built = BuildBody(options);
          LayeredBodyOptions body_options;
          body_options.tissue_density = built.record.tissue_density;
          body_options.core_mass = built.record.core_mass;
          body_options.core_density = built.record.core_density;
          body = std::make_shared<const LayeredBody>(
              LayeredBody::Create(built.record.rest, built.record.attached, built.record.material,
                                  body_options, directory.empty() ? "body" : directory));
          // As `ergo_body build`: a skin that contact would refuse is refused now, unwritten.
          ValidateSkinForContact(body->skin().RestSurface(body->rest().vertices),
                                 (options.surface.empty() ? options.shape : options.surface) +
                                     " (the built body's skin)");
          if (!directory.empty()) SaveBodyDirectory(directory, built.record);
        }
        interrupt.RaiseIfInterrupted();
        return py::make_tuple(BodyHandle{body}, built.report, JsonToPython(built.record.summary));
      },
      py::arg("out") = py::none(), py::arg("progress") = py::none());

  m.def(
      "_simulate",
      [](const BodyHandle& handle, const Vertices& V, const Triangles& F, const std::string& source,
         const py::object& contact_stiffness, double target_penetration, bool place, double gap,
         double tolerance, int max_iterations, double max_seconds, const Eigen::Vector3d& rotation,
         const py::object& progress) {
        StaticEquilibriumOptions options;
        options.start_rotation = rotation;
        if (!(py::isinstance<py::str>(contact_stiffness) &&
              contact_stiffness.cast<std::string>() == "auto")) {
          try {
            options.contact_stiffness = contact_stiffness.cast<double>();
          } catch (const py::cast_error&) {
            throw InputError("--contact_stiffness", "", "is neither a number nor \"auto\"",
                             "give κ in Pa/m (e.g. 1e8) or \"auto\"");
          }
          if (!(options.contact_stiffness > 0))
            throw InputError("--contact_stiffness", "", "must be positive",
                             "give κ in Pa/m (e.g. 1e8)");
        }
        options.target_penetration = target_penetration;
        options.place = place;
        options.gap = gap;
        options.relative_tolerance = tolerance;
        options.max_iterations = max_iterations;
        options.max_seconds = max_seconds;
        options.progress = ProgressSink(progress);
        RequireMesh(V, F, source);
        ScopedInterrupt interrupt;
        options.stop = interrupt.flag();
        const TriMesh support{V, F};
        StaticEquilibrium solved;
        {
          py::gil_scoped_release release;
          solved = SolveStaticEquilibrium(*handle.body, support, source, options);
        }
        interrupt.RaiseIfInterrupted();
        const LayeredBody& body = *handle.body;
        py::dict d;
        d["ok"] = solved.ok();
        d["message"] = solved.message();
        d["positions"] = DeformedPositions(body, solved.result.state);
        d["skin_vertices"] = body.skin().vertices;
        d["skin_pressure"] = solved.pressures.human.pressure;
        d["skin_smoothed_pressure"] = solved.pressures.human.smoothed;
        d["skin_force"] = solved.pressures.contacts.skin_force;
        d["support_pressure"] = solved.pressures.support.pressure;
        d["support_force"] = solved.pressures.contacts.support_force;
        d["contact_stiffness"] = solved.contact_stiffness;
        d["summary"] = JsonToPython(solved.summary);
        return d;
      },
      py::arg("body"), py::arg("V"), py::arg("F"), py::arg("source"), py::arg("contact_stiffness"),
      py::arg("target_penetration"), py::arg("place"), py::arg("gap"), py::arg("tolerance"),
      py::arg("max_iterations"), py::arg("max_seconds"), py::arg("start_rotation"),
      py::arg("progress"));

  m.def(
      "_stance_roll",
      [](const BodyHandle& handle, double calcaneal_stance_deg, const std::string& heel_end,
         const std::string& foot_side) {
        AnatomyOptions foot;
        foot.heel_end = ParseHeelEnd(heel_end, "heel_end");
        foot.foot_side = ParseFootSide(foot_side, "foot_side");
        const StanceRoll stance =
            FindStanceRoll(*handle.body, foot, calcaneal_stance_deg * StanceRoll::kDegree,
                           30 * StanceRoll::kDegree, "stance_roll");
        py::dict d;
        d["roll"] = stance.roll;
        d["heel_eversion"] = stance.heel_eversion;
        d["calcaneal_stance"] = stance.calcaneal_stance;
        d["medial_sign"] = stance.medial_sign;
        d["report"] = stance.BriefReport();
        return d;
      },
      py::arg("body"), py::arg("calcaneal_stance_deg"), py::arg("heel_end"), py::arg("foot_side"));
}

}  // namespace ergo::python

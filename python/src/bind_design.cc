// Scenarios (by name, preset, flagfile and the tools' flags as keyword arguments), design
// problems whose evaluate(x) gives φ, its parts and ∇φ, and the built-in optimisers.
#include <memory>
#include <mutex>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "ergo/design/lengthwise_shares.h"
#include "ergo/mesh/input_error.h"
#include "python/src/bindings.h"
#include "python/src/body_handle.h"
#include "python/src/flag_options.h"
#include "python/src/interrupt.h"
#include "solvers/design_objective.h"
#include "solvers/optimizer.h"
#include "solvers/robust_design_objective.h"
#include "tools/common/design_flags.h"
#include "tools/common/scenario_flags.h"

namespace py = pybind11;

namespace ergo::python {
namespace {

// gflags are process-wide: one flag-reading call at a time.
std::mutex flag_mutex;

struct ScenarioHandle {
  std::shared_ptr<Scenario> scenario;
  std::shared_ptr<DesignProblem> problem;  // as the flags pose it (γ, placement)
  int robust_placements = 1;
  double robust_shift = 0;  // m
  double robust_tilt = 0;   // rad
};

// A design problem and what it references; evaluations of one problem are serialised
// (each keeps the warm start of the last).
struct ProblemHandle {
  std::shared_ptr<Scenario> scenario;
  std::shared_ptr<DesignProblem> problem;
  std::shared_ptr<std::mutex> mutex = std::make_shared<std::mutex>();
};

DesignPlacement ParsePlacement(const std::string& name) {
  DesignPlacement placement;
  if (ParseDesignPlacement(name, &placement)) return placement;
  throw InputError("placement", "", "\"" + name + "\" is not fresh, followed or anchored",
                   "fresh scores the body placed afresh on the design (the headline score)");
}

void RequireDesign(const DesignProblem& problem, const Eigen::VectorXd& x) {
  if (x.size() != problem.NumParameters())
    throw InputError("x", "",
                     "has " + std::to_string(x.size()) + " entries, the design has " +
                         std::to_string(problem.NumParameters()),
                     "start from problem.initial_design()");
  if (!x.allFinite()) throw InputError("x", "", "has a non-finite entry", "give finite values");
}

// The time split as evaluation_timing.h names it: seconds as floats, counts as ints.
py::dict TimingDict(const EvaluationTiming& timing) {
  py::dict d;
  ForEachTimingEntry(
      timing, [&](const char* name, double seconds) { d[name] = seconds; },
      [&](const char* name, long count) { d[name] = count; });
  return d;
}

py::dict EvaluationDict(const DesignEvaluation& e, bool with_gradient) {
  py::dict d;
  d["ok"] = e.ok;
  d["message"] = e.message;
  d["phi"] = e.phi;
  d["zeta"] = e.zeta;
  d["psi"] = e.psi;
  d["zeta_skin"] = e.zeta_human;
  d["zeta_support"] = e.zeta_support;
  if (with_gradient) {
    d["gradient"] = e.gradient;
    d["zeta_gradient"] = e.zeta_gradient;
    d["psi_gradient"] = e.psi_gradient;
  }
  d["contact_vertices"] = e.equilibrium.contact_vertices;
  d["newton_iterations"] = e.equilibrium.iterations;
  d["max_penetration"] = e.equilibrium.max_penetration;
  d["skin_pressure"] = e.pressures.human.pressure;
  d["support_pressure"] = e.pressures.support.pressure;
  d["peak_pressure"] =
      e.pressures.human.pressure.size() ? e.pressures.human.pressure.maxCoeff() : 0.0;
  d["seconds"] = e.timing.total_seconds;
  d["timing"] = TimingDict(e.timing);
  return d;
}

// φ's named terms: "terms" {name: {"weight", "value"}}, and each term's value under its own
// name (a design problem's "zeta" and "psi").
void AddTerms(const ObjectiveTerms& terms, py::dict* d) {
  py::dict named;
  for (const ObjectiveTerm& term : terms) {
    py::dict entry;
    entry["weight"] = term.weight;
    entry["value"] = term.value;
    named[py::str(term.name)] = entry;
    (*d)[py::str(term.name)] = term.value;
  }
  (*d)["terms"] = named;
}

py::dict RecordDict(const IterationRecord& r) {
  py::dict d;
  d["iteration"] = r.iteration;
  d["evaluations"] = r.evaluations;
  d["newton_iterations"] = r.newton_iterations;
  d["seconds"] = r.seconds;
  d["phi"] = r.phi;
  AddTerms(r.terms, &d);
  d["gradient_norm"] = r.gradient_norm;
  d["step"] = r.step;
  d["kept_fresh_phi"] = r.kept_fresh_phi;  // NaN outside runs in fresh rounds
  d["time_split"] = TimingDict(r.timing);  // cumulative, as history.csv's columns
  return d;
}

py::dict ResultDict(const OptimizerResult& r) {
  py::dict d;
  d["optimizer"] = r.optimizer;
  d["ok"] = r.ok;
  d["x"] = r.best_x;
  d["phi"] = r.best_phi;
  d["initial_phi"] = r.initial_phi;
  d["reduction_percent"] = r.ReductionPercent();
  AddTerms(r.best_terms, &d);
  d["evaluations"] = r.evaluations;
  d["failed_evaluations"] = r.failed_evaluations;
  d["newton_iterations"] = r.newton_iterations;
  d["seconds"] = r.seconds;
  d["time_split"] = TimingDict(r.timing);
  d["stop_reason"] = r.stop_reason;
  py::list history;
  for (const IterationRecord& record : r.history) history.append(RecordDict(record));
  d["history"] = history;
  d["candidates"] = r.candidates;
  d["candidate_phi"] = r.candidate_phi;
  d["report"] = r.FullReport();
  return d;
}

ProblemHandle MakeHandle(const ScenarioHandle& s, const std::string& placement,
                         const py::object& equilibrium_tolerance) {
  ProblemHandle handle;
  handle.scenario = s.scenario;
  if (equilibrium_tolerance.is_none()) {
    handle.problem = std::make_shared<DesignProblem>(*s.problem);
  } else {
    DesignOptions options = s.problem->options();
    options.equilibrium.relative_tolerance = equilibrium_tolerance.cast<double>();
    if (!(options.equilibrium.relative_tolerance >= 1e-14 &&
          options.equilibrium.relative_tolerance <= 1e-2))
      throw InputError("equilibrium_tolerance", "", "must be in [1e-14, 1e-2]", "e.g. 1e-10");
    const Scenario& scenario = *s.scenario;
    handle.problem =
        std::make_shared<DesignProblem>(*scenario.body, scenario.support, scenario.start, options);
  }
  if (!placement.empty()) handle.problem->set_placement(ParsePlacement(placement));
  handle.problem->ClearWarmStarts();
  return handle;
}

}  // namespace

void BindDesign(py::module_& m) {
  py::class_<ScenarioHandle>(m, "Scenario",
                             "A posed design problem: body, support, start pose, designed "
                             "vertices and the cost's options (problems/scenario.h).")
      .def_property_readonly("name", [](const ScenarioHandle& s) { return s.scenario->name; })
      .def_property_readonly("description",
                             [](const ScenarioHandle& s) { return s.scenario->description; })
      .def_property_readonly("body",
                             [](const ScenarioHandle& s) { return BodyHandle{s.scenario->body}; })
      .def_property_readonly(
          "support",
          [](const ScenarioHandle& s) {
            return py::make_tuple(s.scenario->support.vertices, s.scenario->support.triangles);
          },
          "the initial support (V, F), m")
      .def_property_readonly("gamma",
                             [](const ScenarioHandle& s) { return s.problem->options().gamma; })
      .def_property_readonly(
          "contact_stiffness",
          [](const ScenarioHandle& s) {
            return s.problem->options().equilibrium.contact_stiffness;
          },
          "κ, Pa/m")
      .def_property_readonly("robust_placements",
                             [](const ScenarioHandle& s) { return s.robust_placements; })
      .def_property_readonly("robust_shift", [](const ScenarioHandle& s) { return s.robust_shift; })
      .def_property_readonly("robust_tilt", [](const ScenarioHandle& s) { return s.robust_tilt; })
      .def(
          "problem",
          [](const ScenarioHandle& s, const std::string& placement,
             const py::object& equilibrium_tolerance) {
            return MakeHandle(s, placement, equilibrium_tolerance);
          },
          py::arg("placement") = "", py::arg("equilibrium_tolerance") = py::none(),
          "A DesignProblem: placement \"\" as the flags say (--placement, default followed), "
          "\"fresh\" (the body placed afresh on every design: the headline score), "
          "\"followed\" or \"anchored\". equilibrium_tolerance: the force residual relative to "
          "the load at which each equilibrium stops (default the scenario's, 1e-8).")
      .def("__repr__", [](const ScenarioHandle& s) {
        return "<ergo.Scenario " + s.scenario->name + ": " + s.scenario->description + ">";
      });

  m.def(
      "_scenario",
      [](const py::object& flagfile, const py::kwargs& flags) {
        std::lock_guard<std::mutex> lock(flag_mutex);
        gflags::FlagSaver saver;  // every flag back to what it was when this returns
        gflags::SetCommandLineOption("scenario", "shoe");  // ergo_optimize's default
        if (!flagfile.is_none()) SetFlagsFromFile(flagfile.cast<std::string>());
        SetFlagsFromKeywords(flags);
        ScenarioHandle handle;
        {
          py::gil_scoped_release release;
          handle.scenario = std::make_shared<Scenario>(ScenarioFromFlags());
          ApplyDesignFlags(handle.scenario.get());
          handle.problem = std::make_shared<DesignProblem>(handle.scenario->MakeProblem());
          ApplyGammaFlags(handle.problem.get());
          handle.robust_placements = RobustPlacementsFlag();
          handle.robust_shift = RobustShiftFlag();
          handle.robust_tilt = RobustTiltFlag();
        }
        return handle;
      },
      py::arg("flagfile") = py::none());

  py::class_<ProblemHandle>(m, "DesignProblem",
                            "φ(x) = ζ + γψ of a support design x and its gradient by the adjoint "
                            "(paper §4; ergo/design/design_problem.h).")
      .def_property_readonly("num_parameters",
                             [](const ProblemHandle& h) { return h.problem->NumParameters(); })
      .def("initial_design", [](const ProblemHandle& h) { return h.problem->InitialDesign(); })
      .def_property(
          "placement",
          [](const ProblemHandle& h) {
            return DesignPlacementName(h.problem->options().placement);
          },
          [](ProblemHandle& h, const std::string& name) {
            h.problem->set_placement(ParsePlacement(name));
          })
      .def_property(
          "gamma", [](const ProblemHandle& h) { return h.problem->options().gamma; },
          [](ProblemHandle& h, double gamma) {
            if (!(gamma >= 0) || !std::isfinite(gamma))
              throw InputError("gamma", "", "must be a finite number >= 0", "e.g. 0");
            h.problem->set_gamma(gamma);
          })
      .def(
          "evaluate",
          [](ProblemHandle& h, const Eigen::VectorXd& x, bool gradient) {
            RequireDesign(*h.problem, x);
            ScopedInterrupt interrupt;
            DesignEvaluation evaluation;
            {
              py::gil_scoped_release release;
              std::lock_guard<std::mutex> lock(*h.mutex);
              evaluation = h.problem->Evaluate(x, gradient);
            }
            interrupt.RaiseIfInterrupted();
            py::dict d = EvaluationDict(evaluation, gradient);
            // The load's split along the scenario's regions (the shoe: rearfoot, midfoot,
            // forefoot from the heel), as summary.json's region_shares.
            const LengthRegions& regions = h.scenario->regions;
            if (evaluation.ok && !regions.names.empty()) {
              const std::vector<double> shares =
                  ComputeLengthwiseShares(h.problem->body(), evaluation.pressures.contacts,
                                          regions.ends, regions.from_min_z)
                      .shares;
              py::dict named;
              for (size_t k = 0; k < shares.size(); ++k)
                named[py::str(regions.names[k])] = shares[k];
              d["region_shares"] = named;
            }
            return d;
          },
          py::arg("x"), py::arg("gradient") = true,
          "A dict: ok, message, phi, zeta, psi, zeta_skin, zeta_support, gradient (dφ/dx), "
          "zeta_gradient, psi_gradient, contact_vertices, skin_pressure, support_pressure, "
          "peak_pressure, seconds, timing (where the seconds went: support_s, placement_s, "
          "contact_s, assembly_s, factorization_s, solve_s, line_search_s, adjoint_s, ..., "
          "other_s, and the counts factorizations, pcg_iterations, ...); for the shoe "
          "region_shares {rearfoot, midfoot, forefoot}: the load's split below 30 %, 30-60 % "
          "and from 60 % of the foot's length from the heel. An equilibrium that fails is "
          "ok=False (never NaN).")
      .def(
          "support_at",
          [](const ProblemHandle& h, const Eigen::VectorXd& x) {
            RequireDesign(*h.problem, x);
            const TriMesh support = h.problem->SupportAt(x);
            return py::make_tuple(support.vertices, support.triangles);
          },
          py::arg("x"), "The support surface (V, F) of design x, m.")
      .def(
          "copy",
          [](const ProblemHandle& h) {
            ProblemHandle copy;
            copy.scenario = h.scenario;
            copy.problem = std::make_shared<DesignProblem>(*h.problem);
            return copy;
          },
          "An independent copy (same options, its own warm starts).")
      .def("clear_warm_starts", [](ProblemHandle& h) { h.problem->ClearWarmStarts(); });

  m.def("optimizers", &OptimizerNames, "The names minimize() accepts.");
  m.def(
      "_minimize",
      [](const ProblemHandle& h, const py::object& x0_object, const std::string& name,
         int max_evals, double max_seconds, int robust_placements, double robust_shift,
         double robust_tilt, const py::object& progress) {
        std::string error;
        std::unique_ptr<Optimizer> optimizer = MakeOptimizer(name, OptimizerOptions(), &error);
        if (!optimizer) throw InputError("optimizer", "", "\"" + name + "\" is unknown", error);
        if (max_evals < 1) throw InputError("max_evals", "", "must be >= 1", "e.g. 40");
        if (!(max_seconds >= 0))
          throw InputError("max_seconds", "", "must be >= 0", "0 = unlimited");
        if (robust_placements != 1 && robust_placements != 3 && robust_placements != 5)
          throw InputError("robust_placements", "", "must be 1, 3 or 5",
                           "5: centred and ±shift on both axes");
        if (!(robust_tilt >= 0 && robust_tilt <= 0.5))
          throw InputError("robust_tilt", "", "must be between 0 and 0.5 rad",
                           "0.0175 (1 degree); 0 = no tilted placements");
        const Eigen::VectorXd x0 =
            x0_object.is_none() ? h.problem->InitialDesign() : x0_object.cast<Eigen::VectorXd>();
        RequireDesign(*h.problem, x0);
        DesignProblem path(*h.problem);
        path.ClearWarmStarts();
        std::unique_ptr<Objective> objective;
        const std::vector<Placement> placements =
            RobustPlacements(path.body(), robust_placements, robust_shift, robust_tilt);
        if (placements.size() > 1)
          objective = std::make_unique<RobustDesignObjective>(path, placements);
        else
          objective = std::make_unique<DesignObjective>(path);
        Budget budget;
        budget.max_evaluations = max_evals;
        budget.max_seconds = max_seconds;
        ScopedInterrupt interrupt;
        RunControl control;
        control.stop = interrupt.flag();
        std::string callback_error;
        if (!progress.is_none()) {
          control.progress = [&](const IterationRecord& record) {
            py::gil_scoped_acquire gil;
            try {
              const py::object keep_going = progress(RecordDict(record));
              return keep_going.is_none() || keep_going.cast<bool>();
            } catch (py::error_already_set& raised) {
              callback_error = raised.what();
              return false;
            }
          };
        }
        OptimizerResult result;
        {
          py::gil_scoped_release release;
          result = optimizer->Minimize(*objective, x0, budget, control);
        }
        if (!callback_error.empty())
          throw InputError("progress", "", "the callback raised: " + callback_error,
                           "fix the callback (return False to stop the run)");
        return py::make_tuple(ResultDict(result), interrupt.interrupted());
      },
      py::arg("problem"), py::arg("x0"), py::arg("optimizer"), py::arg("max_evals"),
      py::arg("max_seconds"), py::arg("robust_placements"), py::arg("robust_shift"),
      py::arg("robust_tilt"), py::arg("progress"));
}

}  // namespace ergo::python

"""ergo: design body-supporting surfaces (seats, insoles, mice) for even contact pressure.

The C++ toolkit's parts as Python calls, with NumPy arrays (V: #V x 3 float64 metres,
F: #F x 3 int32, T: #T x 4 int32):

    import ergo
    V, F = ergo.read_mesh("seat.stl", unit="mm")
    report = ergo.check_mesh("seat.stl", unit="mm")          # dict with "findings"
    body = ergo.build_body(shape="sphere_shell", outer_radius=0.05, core_radius=0.03,
                           youngs_modulus=1e4, edge_length=0.012)
    result = ergo.simulate(body, (V, F))                      # one static equilibrium
    scene = ergo.scenario("shoe", preset="quick")             # or flagfile="data/shoe.flags"
    problem = scene.problem()
    value = problem.evaluate(problem.initial_design())        # phi, its parts, gradient
    best = ergo.minimize(problem, optimizer="nlopt-lbfgs", max_evals=40)
    fit = ergo.fit_indentation(delta, force, indenter_radius=0.008, fit_depth=True)

Options are named as the command-line tools' flags (ergo_body build, ergo_simulate,
ergo_optimize), with the same checks and messages; bad input raises ergo.InputError (a
ValueError). Long calls release the GIL and stop cleanly on Ctrl-C: KeyboardInterrupt, and
for minimize() ergo.Interrupted (a KeyboardInterrupt) carrying the best design so far.
"""

import sys as _sys

from ._ergo import (Body, DesignProblem, InputError, Scenario, check_mesh, check_surface,
                    fit_indentation, indentation_force, load_body, optimizers, read_mesh,
                    read_tet_mesh, write_mesh, write_tet_mesh)
from . import _ergo

__all__ = ["Body", "DesignProblem", "InputError", "Interrupted", "Scenario", "build_body",
           "check_mesh", "check_surface", "fit_indentation", "indentation_force", "load_body",
           "minimize", "optimizers", "read_mesh", "read_tet_mesh", "scenario", "simulate",
           "stance_roll", "write_mesh", "write_tet_mesh"]


class Interrupted(KeyboardInterrupt):
    """Ctrl-C stopped minimize(); `result` holds the best design found until then."""

    def __init__(self, result):
        super().__init__("interrupted (Ctrl-C): the best design so far is in .result")
        self.result = result


def _progress_sink(progress):
    # True: lines on sys.stderr (looked up at call time, so redirection works).
    if progress is True:
        return lambda line: _sys.stderr.write(line + "\n")
    return progress or None


def build_body(out=None, progress=False, **options):
    """Builds a body part; the options are `ergo_body build`'s flags, e.g.
    surface="leg.stl", unit="mm", depth=0.02 (or depth_samples="d.csv"),
    youngs_modulus=1e4 (or stiffness_samples="E.csv"), edge_length=0.008, or
    shape="sphere_shell", outer_radius=..., core_radius=...; semi_axes=(a, b, c) for
    shape="ellipsoid_shell". Writes a body directory when `out` is given. Returns the Body;
    its build report and summary are in body.build_report and body.build_summary."""
    body, report, summary = _ergo._build_body(out=out, progress=_progress_sink(progress),
                                              **options)
    body.build_report = report
    body.build_summary = summary
    return body


def _support_arrays(support, unit):
    if isinstance(support, str):
        V, F = read_mesh(support, unit=unit)
        return V, F, support
    V, F = support
    return V, F, "support (V, F)"


def simulate(body, support, unit="m", contact_stiffness="auto", target_penetration=3e-4,
             place=True, gap=1e-3, tolerance=1e-8, max_iterations=100, max_seconds=0,
             progress=False, start_rotation=(0.0, 0.0, 0.0)):
    """The static contact equilibrium of `body` on `support` (a mesh file or (V, F)), as
    `ergo_simulate`. contact_stiffness: kappa in Pa/m, or "auto" (calibrated so that the
    largest penetration is target_penetration). start_rotation: a rotation vector (rad) that
    turns the rest body about its core's centre before it is placed (a foot's roll about its
    length: (0, 0, roll), e.g. stance_roll(body)["roll"]; ergo_simulate --roll). Returns a
    dict: ok, message, positions (deformed tet vertices, m), skin_vertices, skin_pressure (Pa,
    per skin vertex), skin_force (N), support_pressure, support_force, contact_stiffness and
    summary (the summary.json of ergo_simulate)."""
    V, F, source = _support_arrays(support, unit)
    return _ergo._simulate(body, V, F, source, contact_stiffness, target_penetration, place, gap,
                           tolerance, max_iterations, max_seconds,
                           [float(v) for v in start_rotation], _progress_sink(progress))


def stance_roll(body, calcaneal_stance_deg=6.07, heel_end="auto", foot_side="auto"):
    """The roll (rad about the length axis z, > 0 turns +x up) that stands a foot's heel at
    the resting calcaneal stance (degrees everted; default the healthy adults' mean, Sobel et
    al. 1999), as ergo_optimize --shoe_roll=stance: the heel's bisector drawn on the body's rest
    skin (the tools take the scan's own, recorded in body.json, which differs by the mesh's
    facets: up to 0.8 degrees), turned with the foot. Returns a dict: roll, heel_eversion (rad, at rest), calcaneal_stance
    (rad), medial_sign (+1: the medial side is +x), report. Raises ergo.InputError when the
    body is not a foot whose heel and medial side can be told."""
    return _ergo._stance_roll(body, calcaneal_stance_deg, heel_end, foot_side)


def scenario(name=None, preset=None, flagfile=None, **flags):
    """A scenario (bump, chair, shoe, mouse, or a user's body/support through the flags
    body_dir=, support_mesh=, ...), posed by the same flags as ergo_optimize:
    scenario("shoe", preset="quick"), scenario(flagfile="data/chair.flags",
    preset="paper", support_edge_length=0.005)."""
    if name is not None:
        flags["scenario"] = name
    if preset is not None:
        flags["preset"] = preset
    return _ergo._scenario(flagfile=flagfile, **flags)


def minimize(problem, x0=None, optimizer="nlopt-lbfgs", max_evals=40, max_seconds=0,
             robust_placements=1, robust_shift=0.003, robust_tilt=0.0, progress=None):
    """Runs a built-in optimiser (ergo.optimizers()) on a DesignProblem from x0 (default
    its initial design) within max_evals evaluations / max_seconds. robust_placements 3
    or 5 averages phi over the body placed at +-robust_shift (m); robust_tilt > 0 (rad)
    adds the body held tilted by +-robust_tilt about each axis across the load whose
    rotation the core lock holds (scenario.robust_tilt: --robust_tilt_deg). progress: a callable
    given each history entry (a dict); returning False stops the run. Returns a dict: x,
    phi, initial_phi, reduction_percent, evaluations, newton_iterations, seconds,
    stop_reason, history, candidates. Ctrl-C raises ergo.Interrupted with that dict."""
    result, interrupted = _ergo._minimize(problem, x0, optimizer, max_evals, max_seconds,
                                          robust_placements, robust_shift, robust_tilt,
                                          progress)
    if interrupted:
        raise Interrupted(result)
    return result

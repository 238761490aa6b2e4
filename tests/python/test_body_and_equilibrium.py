# Bodies and one static equilibrium through the bindings, checked against laws that hold
# without the code: the contact forces carry the body's weight, and a body built and
# saved reads back identical.
import numpy as np
import pytest

import ergo


def box(half_width, y_top, depth):
    """A closed, outward box surface: x, z in [-half_width, half_width], y in
    [y_top - depth, y_top]."""
    V = []
    for y in (y_top - depth, y_top):
        for x, z in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
            V.append([x * half_width, y, z * half_width])
    F = [[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6], [0, 4, 5], [0, 5, 1], [1, 5, 6],
         [1, 6, 2], [2, 6, 7], [2, 7, 3], [3, 7, 4], [3, 4, 0]]
    return np.array(V, dtype=float), np.array(F, dtype=np.int32)


@pytest.fixture(scope="module")
def ball(tmp_path_factory):
    out = tmp_path_factory.mktemp("ball") / "body"
    lines = []
    body = ergo.build_body(out=str(out), progress=lines.append, shape="sphere_shell",
                           outer_radius=0.05, core_radius=0.03, youngs_modulus=1e4,
                           edge_length=0.014, seed=1)
    return body, out, lines


def test_built_body_is_saved_and_loads_back_identical(ball):
    body, out, lines = ball
    assert any("meshing the layer" in line for line in lines), lines
    assert all(line.split()[1] == "s" for line in lines), lines  # "   0.1 s  stage"
    loaded = ergo.load_body(str(out))
    np.testing.assert_array_equal(loaded.rest_vertices, body.rest_vertices)
    np.testing.assert_array_equal(loaded.tets, body.tets)
    # Mass of the ball: ρ · 4/3 π R³ (the core's automatic mass uses the tissue density),
    # within the meshing's volume error (a 14 mm mesh of a 5 cm sphere: a few percent).
    expected = 1050 * 4 / 3 * np.pi * 0.05 ** 3
    assert abs(loaded.mass - expected) < 0.06 * expected, (loaded.mass, expected)
    assert body.build_summary["mass_kg"] == pytest.approx(body.mass)
    assert "mass:" in body.build_report
    assert body.skin_vertices.size > 0 and body.attached.any()


def resting(ball):
    """The ball with its core moving only vertically (a sphere's sliding and rolling meet
    no resistance on a frictionless plane)."""
    return ergo.load_body(str(ball[1]), lock="tx,tz,rx,ry,rz")


def test_equilibrium_carries_the_weight(ball):
    body = resting(ball)
    V, F = box(0.1, 0.0, 0.02)
    result = ergo.simulate(body, (V, F), contact_stiffness=3e7)
    assert result["ok"], result["message"]
    summary = result["summary"]
    assert summary["converged"] and summary["contact_vertices"] > 0
    # Balance: the contact forces on the skin add up to the weight (the solver's tolerance
    # is 1e-8 of the load).
    weight = body.mass * 9.81
    total = result["skin_force"].sum(axis=0)
    np.testing.assert_allclose(total, [0, weight, 0], atol=1e-6 * weight)
    # Pressures: one per skin vertex, non-negative, and zero away from the contact.
    pressure = result["skin_pressure"]
    assert pressure.shape == (body.skin_vertices.size,) and (pressure >= 0).all()
    assert 0 < (pressure > 0).sum() < pressure.size
    # A ball resting under its own weight squeezes its layer mildly: no tet near the material
    # law's inversion threshold, and the summary says so.
    squeeze = summary["tissue_compression"]
    assert squeeze["tets_beyond_inversion_threshold"] == 0 and squeeze["inverted_tets"] == 0
    assert 0.1 < squeeze["min_principal_stretch"] <= 1
    # What a 5 mm plate under the ball would read at its largest cell: one cell cannot carry
    # more than the whole weight, and it lies under the ball's lowest point.
    plate = summary["plate_peak"]
    assert plate["pitch_m"] == 0.005
    assert 0 < plate["pressure_Pa"] * plate["pitch_m"] ** 2 < weight
    lowest = result["positions"][np.argmin(result["positions"][:, 1])]
    assert np.hypot(*(np.array(plate["cell_centre_xz_m"]) - lowest[[0, 2]])) < 0.01
    # The body rests on the box's top (y = 0): nothing is far inside.
    assert result["positions"][:, 1].min() > -1e-3
    assert result["contact_stiffness"] == 3e7


def test_start_rotation_turns_the_rest_body_before_it_is_placed(ball):
    # Known answer: with its rotation locked, the core ends turned by exactly the start
    # rotation, so every pair of core (attached) vertices is the rest pair turned by
    # R = exp([0, 0, 0.3]x), to round-off; the weight is carried as before.
    body = resting(ball)
    V, F = box(0.1, 0.0, 0.02)
    result = ergo.simulate(body, (V, F), contact_stiffness=3e7, start_rotation=(0, 0, 0.3))
    assert result["ok"], result["message"]
    core = np.flatnonzero(body.attached)
    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    rest = body.rest_vertices[core] - body.rest_vertices[core[0]]
    moved = result["positions"][core] - result["positions"][core[0]]
    np.testing.assert_allclose(moved, rest @ R.T, atol=1e-12)
    np.testing.assert_allclose(result["skin_force"].sum(axis=0), [0, body.mass * 9.81, 0],
                               atol=1e-6 * body.mass * 9.81)
    # A ball is no foot: its stance roll is refused with a reason.
    with pytest.raises(ergo.InputError):
        ergo.stance_roll(body)


def test_stance_roll_of_the_generated_foot_stands_its_heel_at_the_stance():
    # The generated foot (medial side +x, heel upright at rest: -0.13 degrees) is turned by
    # medial_sign * (heel eversion - stance): -6.2 degrees for the adults' 6.07 (C++ test
    # StanceRoll.TurnsTheHeelsBisectorToTheStatedCalcanealStance checks the turned line).
    foot = ergo.scenario("shoe", preset="quick").body
    stance = ergo.stance_roll(foot, heel_end="min_z")
    assert stance["medial_sign"] == 1
    assert stance["roll"] == pytest.approx(
        stance["medial_sign"] * (stance["heel_eversion"] - stance["calcaneal_stance"]), abs=1e-15)
    assert stance["calcaneal_stance"] == pytest.approx(np.radians(6.07), abs=1e-15)
    assert np.degrees(stance["roll"]) == pytest.approx(-6.2, abs=0.05)
    assert "stance roll" in stance["report"]


def test_auto_stiffness_reaches_the_target_penetration(ball):
    body = resting(ball)
    V, F = box(0.1, 0.0, 0.02)
    lines = []
    result = ergo.simulate(body, (V, F), target_penetration=3e-4, progress=lines.append)
    assert result["ok"], result["message"]
    calibration = result["summary"]["calibration"]
    assert calibration["converged"]
    assert abs(result["summary"]["max_penetration_m"] - 3e-4) <= 0.05 * 3e-4 + 1e-12
    assert any("calibration" in line for line in lines)
    assert any("Newton" in line for line in lines)


def test_bad_options_raise_with_the_flag_named(ball, tmp_path):
    body, _, _ = ball
    with pytest.raises(ergo.InputError, match="--edge_length"):
        ergo.build_body(shape="sphere_shell", outer_radius=0.05, core_radius=0.03,
                        youngs_modulus=1e4)
    with pytest.raises(ergo.InputError, match="--shape: is not a string"):
        ergo.build_body(shape=3, edge_length=0.01)
    with pytest.raises(ergo.InputError, match="not an option of build_body"):
        ergo.build_body(shape="sphere_shell", edge_lenght=0.01)
    with pytest.raises(ergo.InputError, match="lock"):
        ergo.load_body(str(tmp_path), lock="tq")
    with pytest.raises(ergo.InputError, match="body.json"):
        ergo.load_body(str(tmp_path))
    V, F = box(0.1, 0.0, 0.02)
    with pytest.raises(ergo.InputError, match="contact_stiffness"):
        ergo.simulate(body, (V, F), contact_stiffness=-1)
    with pytest.raises(ergo.InputError):
        ergo.simulate(body, (V, F[:6]))  # an open support: the tools' validation message


def octasphere(radius, levels):
    """A closed, outward sphere surface: an octahedron subdivided `levels` times."""
    V = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    F = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    V = [np.array(v, dtype=float) for v in V]
    for _ in range(levels):
        midpoint = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                V.append((V[a] + V[b]) / 2)
                midpoint[key] = len(V) - 1
            return midpoint[key]

        refined = []
        for a, b, c in F:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            refined += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        F = refined
    V = np.array([radius * v / np.linalg.norm(v) for v in V])
    return V, np.array(F, dtype=np.int32)


def test_body_from_a_surface_in_millimetres(tmp_path):
    V, F = octasphere(100.0, 3)  # a 10 cm ball, in millimetres
    path = str(tmp_path / "ball_mm.ply")
    ergo.write_mesh(path, V, F)
    lines = []
    body = ergo.build_body(surface=path, unit="mm", depth=0.03, youngs_modulus=1e4,
                           edge_length=0.02, progress=lines.append)
    assert any("checking the skin surface" in line for line in lines), lines
    # The skin is the given surface: every skin vertex within the meshing's facet distance
    # (edge/10 = 2 mm) of the 10 cm sphere.
    skin = body.rest_vertices[body.skin_vertices]
    radii = np.linalg.norm(skin, axis=1)
    assert np.all(np.abs(radii - 0.1) < 0.004), (radii.min(), radii.max())
    # Mass of a 10 cm ball of water-like tissue (the core by default has the same density).
    assert abs(body.mass - 1050 * 4 / 3 * np.pi * 0.1 ** 3) < 0.08 * 4.4
    assert body.build_summary["youngs_modulus_min_pa"] == pytest.approx(1e4)

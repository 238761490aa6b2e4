# The measurement scripts of tools/ on inputs whose answers are known without them:
# compare_sole_surfaces.py on two grids sampling known displacement fields, and
# plot_scaling.py on benchmark rows that follow an exact power law.
import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest


def write_grid_run(run, spacing_mm, field):
    """An ergo_optimize-like run: a flat 100 × 100 mm top at y = 0 (grid of `spacing_mm`)
    over a bottom at y = -20, support_initial.ply and support_optimized.ply with the top
    raised by field(x, z) (mm)."""
    n = int(round(100 / spacing_mm)) + 1
    xs = np.linspace(0, 100, n)
    top = [(x, 0.0, z) for z in xs for x in xs]
    bottom = [(x, -20.0, z) for (x, _, z) in top]
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            faces += [(a, b, c), (a, c, d)]
    run.mkdir()
    for name, lift in (("support_initial.ply", lambda x, z: 0.0), ("support_optimized.ply", field)):
        vertices = [(x, y + lift(x, z), z) for (x, y, z) in top] + bottom
        header = ["ply", "format ascii 1.0", "comment ergo triangle mesh, unit mm",
                  f"element vertex {len(vertices)}", "property double x", "property double y",
                  "property double z", f"element face {len(faces)}",
                  "property list uchar int vertex_indices", "end_header"]
        lines = header + [f"{x!r} {y!r} {z!r}" for (x, y, z) in vertices]
        lines += [f"3 {a} {b} {c}" for (a, b, c) in faces]
        (run / name).write_text("\n".join(lines) + "\n")
    return n


def bump(x, z):
    return 2.0 * math.exp(-((x - 50) ** 2 + (z - 50) ** 2) / (2 * 15.0 ** 2))


def run_compare(source_dir, *args):
    completed = subprocess.run(
        [sys.executable, str(source_dir / "tools" / "compare_sole_surfaces.py"), *map(str, args)],
        capture_output=True, text=True, timeout=300)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    return [float(v) for v in re.findall(r"= ([0-9.]+) %", completed.stdout)]


def test_the_same_field_on_two_grids_is_near_zero_and_a_scaled_field_is_its_ratio(
        source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    write_grid_run(tmp_path / "coarse", 10, bump)
    write_grid_run(tmp_path / "fine", 5, bump)
    write_grid_run(tmp_path / "scaled", 5, lambda x, z: 0.8 * bump(x, z))
    # On the coarse vertices the fine field is exact (they are fine vertices too): 0 %. On
    # the fine ones, the coarse grid's linear interpolant of a 15 mm Gaussian: 5.8 % RMS
    # (measured; the pointwise bound is 0.22 mm on a 2 mm bump, next test); a wrong mapping of
    # either axis gives tens of per cent.
    same = run_compare(source_dir, tmp_path / "coarse", tmp_path / "fine")
    assert same[0] == pytest.approx(0, abs=0.05)
    assert 1 < same[1] < 8
    # 0.8 × the field on the same grid: |1 - 0.8| / 1 = 20 % of A's, 0.2 / 0.8 = 25 % of B's.
    scaled = run_compare(source_dir, tmp_path / "fine", tmp_path / "scaled")
    assert scaled == pytest.approx([20.0, 25.0], abs=0.1)


def test_transfer_carries_each_design_onto_the_other_mesh(source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    write_grid_run(tmp_path / "coarse", 10, bump)
    fine_n = write_grid_run(tmp_path / "fine", 5, lambda x, z: 0.0)
    run_compare(source_dir, tmp_path / "coarse", tmp_path / "fine", f"--transfer={tmp_path/'x'}")
    lines = (tmp_path / "x" / "a_on_b.ply").read_text().split("\n")
    end = lines.index("end_header")
    vertices = np.array([[float(v) for v in l.split()] for l in lines[end + 1:end + 1 + 2 * fine_n ** 2]])
    top, bottom = vertices[:fine_n ** 2], vertices[fine_n ** 2:]
    exact = np.array([bump(x, z) for x, _, z in top])
    # The coarse design on the fine grid: its linear interpolant, within the interpolation
    # bound h²/8 · max|f''| along a triangle's longest edge (the diagonal, h = 10√2 mm;
    # max|f''| = 2 mm / (15 mm)²: 0.22 mm); the bottom is untouched, the faces are the fine grid's.
    assert np.abs(top[:, 1] - exact).max() < (10 * math.sqrt(2)) ** 2 / 8 * 2 / 15.0 ** 2
    assert np.abs(top[:, 1] - exact).max() > 0.01  # it is the interpolant, not the field
    assert np.all(bottom[:, 1] == -20.0)
    assert lines[end + 1 + 2 * fine_n ** 2].startswith("3 ")
    assert not list((tmp_path / "x").glob("*.tmp"))


def test_plot_scaling_fits_the_exponent_of_a_power_law(source_dir, tmp_path):
    rows = []
    for body, support, body_vertices, support_vertices in (
            (2, 40, 2e3, 4e4), (10, 40, 1e4, 4e4), (40, 40, 4e4, 4e4), (10, 10, 1e4, 1e4),
            (10, 160, 1e4, 1.6e5)):
        # time = 1e-4 · body^1.2 · (support / 4e4)^0.5; one factorisation = 1e-5 · body^1.5
        seconds = 1e-4 * body_vertices ** 1.2 * (support_vertices / 4e4) ** 0.5
        counters = {"body_vertices": body_vertices, "support_vertices": support_vertices,
                    "newton_iterations": 3, "factorizations": 0, "assembly_s": 0.1,
                    "contact_s": 0.1, "support_s": 0.1, "adjoint_s": 0.1,
                    "one_factorization_s": 1e-5 * body_vertices ** 1.5}
        rows.append({"name": f"BM_WarmEvaluationScaling/body={body}k/support={support}k/"
                             "iterations:1", "real_time": seconds, **counters})
    (tmp_path / "scaling.json").write_text(json.dumps({"benchmarks": rows}))
    completed = subprocess.run(
        [sys.executable, str(source_dir / "tools" / "plot_scaling.py"), str(tmp_path / "scaling.json"),
         str(tmp_path / "scaling.png")], capture_output=True, text=True, timeout=300)
    assert completed.returncode in (0, 3), completed.stderr  # 3: no matplotlib, table only
    exponents = [float(v) for v in re.findall(r"\^(-?[0-9.]+)", completed.stdout)]
    assert exponents == pytest.approx([1.2, 0.5, 1.5], abs=0.005)
    assert sum(line.startswith("|") for line in completed.stdout.splitlines()) == 7  # + header, rule


def test_compare_names_a_directory_that_is_not_a_run(source_dir, tmp_path):
    pytest.importorskip("matplotlib")  # the script imports it first
    write_grid_run(tmp_path / "run", 10, bump)
    (tmp_path / "empty").mkdir()
    completed = subprocess.run(
        [sys.executable, str(source_dir / "tools" / "compare_sole_surfaces.py"),
         str(tmp_path / "run"), str(tmp_path / "empty")], capture_output=True, text=True,
        timeout=300)
    assert completed.returncode == 1
    assert "empty has no support_initial.ply" in completed.stderr
    assert "Traceback" not in completed.stderr


def run_pose(source_dir, *args):
    return subprocess.run(
        [sys.executable, str(source_dir / "tools" / "pose_foot_scan.py"), *map(str, args)],
        capture_output=True, text=True, timeout=60)


def read_obj(path):
    lines = path.read_text().split("\n")
    vertices = np.array([[float(t) for t in l.split()[1:4]] for l in lines if l.startswith("v ")])
    faces = [l for l in lines if l.startswith("f ")]
    return vertices, faces


def test_pose_foot_scan_turns_each_part_by_its_angle_about_its_axis(source_dir, tmp_path):
    # A foot-sized cloud in the scan's axes (z up, length along x, as the FIND foot: --axes=y,z,x)
    # with two faces that must survive. In ergo's frame it spans x 0..0.1, y 0..0.05,
    # z 0..0.25 (the length).
    rng = np.random.default_rng(7)
    ergo = rng.uniform([0, 0, 0], [0.1, 0.05, 0.25], size=(400, 3))
    ergo[0], ergo[1] = [0, 0, 0], [0.1, 0.05, 0.25]  # the extent's corners
    scan = ergo[:, [2, 0, 1]]  # scan x = ergo z, scan y = ergo x, scan z = ergo y
    source = tmp_path / "foot.obj"
    source.write_text("# a cloud\n" + "".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in scan)
                      + "f 1 2 3\nf 2 3 4\n")
    same = run_pose(source_dir, source, tmp_path / "same.obj", "--axes=y,z,x")
    assert same.returncode == 0, same.stderr
    vertices, faces = read_obj(tmp_path / "same.obj")
    assert np.abs(vertices - scan).max() == 0
    assert faces == ["f 1 2 3", "f 2 3 4"]

    done = run_pose(source_dir, source, tmp_path / "posed.obj", "--axes=y,z,x",
                    "--forefoot_eversion=10", "--toe_flexion=20")
    assert done.returncode == 0, done.stderr
    posed = read_obj(tmp_path / "posed.obj")[0][:, [1, 2, 0]]  # back to ergo's frame
    s = ergo[:, 2] / 0.25
    # Behind the forefoot's ramp nothing moves; within it each point keeps its distance to the
    # eversion axis (x 0.05, y 0.025, along z), since only a turn about that axis moves it.
    behind = s <= 0.35
    assert behind.sum() > 50
    assert np.abs(posed[behind] - ergo[behind]).max() == 0
    ramp = (s > 0.35) & (s < 0.65)
    axis = np.array([0.05, 0.025])
    assert np.allclose(np.linalg.norm(posed[ramp, :2] - axis, axis=1),
                       np.linalg.norm(ergo[ramp, :2] - axis, axis=1), atol=1e-15)
    # From 65 % to the toes' root (72 %) the forefoot is turned by the full 10 degrees: a point
    # on the -x side goes down, and the turn is exactly R(10°) about the axis.
    full = (s >= 0.65) & (s <= 0.72)
    c, d = np.cos(np.radians(10)), np.sin(np.radians(10))
    rel = ergo[full, :2] - axis
    expected = np.column_stack([c * rel[:, 0] - d * rel[:, 1], d * rel[:, 0] + c * rel[:, 1]])
    assert np.allclose(posed[full, :2] - axis, expected, atol=1e-15)
    assert np.allclose(posed[full, 2], ergo[full, 2], atol=1e-15)
    # Beyond 80 % the toes are turned down by 20 degrees about x through (y 0.015, z 0.18),
    # after the eversion: the distance to that axis is kept and a tip ahead of it goes down.
    toes = s >= 0.80
    everted = ergo[toes].copy()
    rel = everted[:, :2] - axis
    everted[:, :2] = axis + np.column_stack([c * rel[:, 0] - d * rel[:, 1],
                                             d * rel[:, 0] + c * rel[:, 1]])
    pivot = np.array([0.015, 0.18])  # y, z
    c, d = np.cos(np.radians(20)), np.sin(np.radians(20))
    rel = everted[:, 1:] - pivot
    expected = pivot + np.column_stack([c * rel[:, 0] - d * rel[:, 1], d * rel[:, 0] + c * rel[:, 1]])
    assert np.allclose(posed[toes, 1:], expected, atol=1e-15)
    assert np.allclose(posed[toes, 0], everted[:, 0], atol=1e-15)
    tip = np.argmax(ergo[:, 2])
    assert posed[tip, 1] < ergo[tip, 1] - 0.01

    bad = run_pose(source_dir, source, tmp_path / "bad.obj", "--axes=y,y,x")
    assert bad.returncode != 0 and "--axes=y,y,x" in bad.stderr
    assert not (tmp_path / "bad.obj").exists()


def test_pose_foot_scan_measures_the_forefoots_tilt_across_the_foot(source_dir, tmp_path):
    # Known answer: in ergo's frame a foot-sized cloud whose lowest skin in the band 0.6-0.8 of
    # the length lies on a line rising 5 degrees towards -x (the medial side of a left foot);
    # everything else in the band stands higher. Read with --medial=-x it is 5 degrees medial
    # side up, with +x -5.
    rng = np.random.default_rng(3)
    tilt = np.tan(np.radians(5))
    x = np.linspace(0.0, 0.1, 201)
    z = np.full_like(x, 0.175)  # 0.7 of the 0.25 length
    lowest = np.column_stack([x, 0.01 + tilt * (0.1 - x), z])
    above = rng.uniform([0, 0.03, 0], [0.1, 0.06, 0.25], size=(400, 3))
    ends = np.array([[0.05, 0.02, 0.0], [0.05, 0.02, 0.25]])  # the length's ends
    ergo = np.vstack([lowest, above, ends])
    scan = ergo[:, [2, 0, 1]]
    source = tmp_path / "foot.obj"
    source.write_text("".join(f"v {a!r} {b!r} {c!r}\n" for a, b, c in scan))
    for medial, expected in (("-x", 5.0), ("+x", -5.0)):
        run = run_pose(source_dir, source, "--axes=y,z,x", "--measure_forefoot=0.6,0.8",
                       f"--medial={medial}")
        assert run.returncode == 0, run.stderr
        angle = float(run.stdout.split(":")[1].split("deg")[0])
        assert abs(angle - expected) < 0.01, run.stdout  # printed to 0.01 degrees
    for bad in ("--measure_forefoot=0.8,0.6", "--measure_forefoot=a,b", "--medial=up"):
        refused = run_pose(source_dir, source, "--axes=y,z,x", "--measure_forefoot=0.6,0.8", bad)
        assert refused.returncode != 0 and bad in refused.stderr, refused.stderr


def test_pose_foot_scan_refuses_bad_input_naming_it_and_writes_nothing(source_dir, tmp_path):
    good = tmp_path / "foot.obj"
    good.write_text("v 0 0 0\nv 0.25 0.1 0.05\nv 0.1 0.05 0.02\nf 1 2 3\n")
    broken = tmp_path / "broken.obj"
    broken.write_text("v 0 0 0\nv 0.25 oops 0.05\nf 1 2 2\n")
    cases = [((tmp_path / "missing.obj", "--axes=y,z,x"), "cannot read"),
             ((broken, "--axes=y,z,x"), "broken.obj:2"),
             ((good, "--forefoot_eversion=nan"), "--forefoot_eversion=nan"),
             ((good, "--toe_flexion=ten"), "--toe_flexion=ten"),
             ((good, "--twist=3"), "unknown option --twist=3")]
    for (source, option), message in cases:
        out = tmp_path / "out.obj"
        done = run_pose(source_dir, source, out, option)
        assert done.returncode != 0, message
        assert message in done.stderr, done.stderr
        assert "Traceback" not in done.stderr
        assert not out.exists() and not (tmp_path / "out.obj.partial").exists()


def run_plot_simulation(source_dir, directory):
    return subprocess.run(
        [sys.executable, str(source_dir / "tools" / "plot_simulation.py"), str(directory)],
        capture_output=True, text=True, timeout=300)


def test_plot_simulation_draws_the_map_and_refuses_unusable_data(source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    # A 10 x 10 grid of skin points (x, z in metres) with a pressure bump, two triangles per
    # cell, the foot's three bands and a centre of pressure: what ergo_simulate writes.
    n = 10
    points = [[0.01 * i, 0.02 * j] for j in range(n) for i in range(n)]
    pressure = [1e5 * math.exp(-((x - 0.05) ** 2 + (z - 0.1) ** 2) / 2e-3) for x, z in points]
    triangles = []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j * n + i
            triangles += [[a, a + 1, a + n + 1], [a, a + n + 1, a + n]]
    bands = [{"name": name, "v_from": 0.06 * k, "v_to": 0.06 * (k + 1), "share": share}
             for k, (name, share) in enumerate((("rearfoot", 0.5), ("midfoot", 0.1),
                                               ("forefoot", 0.4)))]
    data = {"tool": "ergo_simulate", "title": "grid on plate", "view": {"axes": ["x", "z"]},
            "skin": {"points2d": points, "triangles": triangles, "pressure": pressure},
            "centre_of_pressure2d": [0.05, 0.1], "regions": bands}
    good = tmp_path / "good"
    good.mkdir()
    (good / "plot_data.json").write_text(json.dumps(data))
    done = run_plot_simulation(source_dir, good)
    assert done.returncode == 0, done.stderr
    for png in ("pressure_map.png", "pressure_histogram.png"):
        assert (good / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", png
        assert (good / png).stat().st_size > 10000, png
    assert not list(good.glob("*.tmp.png"))
    # One pressure short, a missing view, no file, not JSON: exit 2 naming the file, no picture.
    short = dict(data, skin=dict(data["skin"], pressure=pressure[:-1]))
    no_view = {k: v for k, v in data.items() if k != "view"}
    for name, text, message in (("short", json.dumps(short), "100 points but 99 pressures"),
                                ("no_view", json.dumps(no_view), "'view'"),
                                ("missing", None, "No such file"),
                                ("not_json", "{oops", "plot_data.json")):
        bad = tmp_path / name
        bad.mkdir()
        if text is not None:
            (bad / "plot_data.json").write_text(text)
        done = run_plot_simulation(source_dir, bad)
        assert done.returncode == 2, name
        assert "plot_data.json" in done.stderr and message in done.stderr, done.stderr
        assert "Traceback" not in done.stderr
        assert not list(bad.glob("*.png")), name

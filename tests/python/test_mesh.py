# Meshes through the bindings: arrays in and out, the check's findings, errors as
# ergo.InputError with the tools' messages.
import numpy as np
import pytest

import ergo

# A unit-ish tetrahedron surface, outward (volume > 0 by the right-hand rule).
TETRA_V = np.array([[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]], dtype=float)
TETRA_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)


def test_write_read_round_trip_in_every_triangle_format(tmp_path):
    for ext, binary in [(".obj", False), (".off", False), (".ply", True), (".stl", True),
                        (".msh", False)]:
        path = str(tmp_path / ("tetra" + ext))
        ergo.write_mesh(path, TETRA_V, TETRA_F, binary=binary)
        V, F = ergo.read_mesh(path)
        assert V.shape[1] == 3 and F.shape == (4, 3), ext
        # STL stores no shared vertices and single precision; the others are exact.
        tolerance = 1e-7 if ext == ".stl" else 0
        for face, original in zip(F, TETRA_F):
            np.testing.assert_allclose(V[face], TETRA_V[original], atol=tolerance, err_msg=ext)


def test_units_scale_to_metres(tmp_path):
    path = str(tmp_path / "tetra_mm.off")
    ergo.write_mesh(path, TETRA_V, TETRA_F, unit="mm")  # written in millimetres
    V_mm, _ = ergo.read_mesh(path, unit="mm")
    np.testing.assert_allclose(V_mm, TETRA_V, rtol=1e-15)
    V_raw, _ = ergo.read_mesh(path)  # read as metres: a thousand times too large
    np.testing.assert_allclose(V_raw, 1000 * TETRA_V, rtol=1e-15)


def test_tet_mesh_round_trip(tmp_path):
    V = TETRA_V
    T = np.array([[0, 1, 2, 3]], dtype=np.int32)
    path = str(tmp_path / "one.msh")
    ergo.write_tet_mesh(path, V, T)
    V2, T2 = ergo.read_tet_mesh(path)
    np.testing.assert_array_equal(T2, T)
    np.testing.assert_array_equal(V2, V)


def test_check_reports_findings_of_a_broken_surface():
    clean = ergo.check_surface(TETRA_V, TETRA_F, require_closed=True)
    assert clean["exit_code"] == 0, clean["report"]
    assert clean["verdict"] == "note"
    open_surface = ergo.check_surface(TETRA_V, TETRA_F[:3], name="open", require_closed=True)
    assert open_surface["exit_code"] == 1
    codes = [finding["code"] for finding in open_surface["findings"]]
    assert "open-boundary" in codes, codes
    finding = open_surface["findings"][codes.index("open-boundary")]
    assert finding["severity"] == "problem" and finding["fix"] and finding["count"] == 3


def test_check_of_a_real_file_and_of_a_missing_one(source_dir, tmp_path):
    path = str(tmp_path / "tetra.ply")
    ergo.write_mesh(path, TETRA_V, TETRA_F)
    report = ergo.check_mesh(path, require_closed=True)
    assert report["exit_code"] == 0 and report["vertices"] == 4 and report["triangles"] == 4
    missing = ergo.check_mesh(str(tmp_path / "nothing.stl"))
    assert missing["exit_code"] == 2 and missing["verdict"] == "unusable"


def test_bad_input_raises_input_error_with_the_tools_message(tmp_path):
    with pytest.raises(ergo.InputError) as raised:
        ergo.read_mesh(str(tmp_path / "nothing.stl"))
    assert "nothing.stl" in str(raised.value)
    assert isinstance(raised.value, ValueError)
    with pytest.raises(ergo.InputError, match="refers to vertex 9"):
        ergo.write_mesh(str(tmp_path / "bad.obj"), TETRA_V, np.array([[0, 1, 9]]))
    with pytest.raises(ergo.InputError, match="non-finite"):
        ergo.check_surface(np.full((4, 3), np.nan), TETRA_F)
    with pytest.raises(ergo.InputError, match="not m or mm"):
        ergo.read_mesh(str(tmp_path / "x.obj"), unit="inch")

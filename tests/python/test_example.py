# The example script runs end to end on a tiny budget and writes its picture and numbers.
import json
import os
import subprocess
import sys

import pytest


def test_scipy_shoe_example_runs(source_dir, tmp_path):
    pytest.importorskip("scipy")
    pytest.importorskip("matplotlib")
    out = tmp_path / "example"
    completed = subprocess.run(
        [sys.executable, str(source_dir / "examples" / "optimize_shoe_scipy.py"),
         "--max_evals=3", f"--out={out}"],
        capture_output=True, text=True, env=dict(os.environ), timeout=800)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    result = json.loads((out / "result.json").read_text())
    assert result["evaluations"] == 3  # the budget is enforced by the example itself
    assert result["optimized_fresh_phi"] > 0 and result["initial_fresh_phi"] > 0
    assert (out / "pressure_maps.png").stat().st_size > 10000

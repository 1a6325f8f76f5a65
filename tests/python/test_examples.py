"""The examples of examples/python run, check their own claims and write their plots."""

import os
import subprocess
import sys

import pytest


def run_example(source_dir, name, *arguments, cwd):
    # The example runs in a scratch folder: PYTHONPATH's folders made absolute.
    path = os.pathsep.join(os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)
    env = dict(os.environ, MPLCONFIGDIR=str(cwd), PYTHONPATH=path)
    return subprocess.run([sys.executable, str(source_dir / "examples/python" / name), *arguments],
                          cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


@pytest.mark.parametrize("name", ["cor_sweep.py", "integrator_energy.py"])
def test_plotting_examples(name, source_dir, tmp_path):
    plot = tmp_path / "plot.png"
    result = run_example(source_dir, name, str(plot), cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_custom_integrator_example(source_dir, tmp_path):
    result = run_example(source_dir, "custom_integrator.py", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "bit for bit: True" in result.stdout

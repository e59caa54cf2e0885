"""``python -m msmesh`` and msmesh._cli: the msmesh program run from Python (docs/python.md).

In the CMake build tree (PYTHONPATH=<build>/python, as ctest's python_tests runs) the program is
<build>/msmesh; a pip install bundles it as msmesh/_bin/msmesh (tests/install/run_pip_test.sh
checks that one). Skipped when the program is absent.
"""

import os
import subprocess
import sys

import pytest

import msmesh
from msmesh import _cli

pytestmark = pytest.mark.skipif(_cli.program_path() is None, reason="no msmesh program beside the module")


def run_module(*args, cwd=None):
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(msmesh.__file__)))
    return subprocess.run([sys.executable, "-m", "msmesh", *args], capture_output=True, text=True, env=env, cwd=cwd)


def run_program(*args, cwd=None):
    return subprocess.run([_cli.program_path(), *args], capture_output=True, text=True, cwd=cwd)


def test_version_is_the_program_s_and_the_module_s():
    result = run_module("--version")
    assert result.returncode == 0
    assert result.stdout.strip() == run_program("--version").stdout.strip() == f"msmesh {msmesh.__version__}"


def test_help_lists_the_subcommands():
    result = run_module("--help")
    assert result.returncode == 0
    for name in ("denoise", "inpaint", "segment", "repair"):
        assert name in result.stdout


@pytest.mark.parametrize("args, status", [(["nosuchcommand"], 2), (["denoise", "missing.obj", "-o", "out.obj"], 1),
                                          (["denoise", "--alpha", "x", "in.obj", "-o", "out.obj"], 2)])
def test_exit_status_and_error_are_the_program_s(tmp_path, args, status):
    module, program = run_module(*args, cwd=tmp_path), run_program(*args, cwd=tmp_path)
    assert module.returncode == program.returncode == status
    assert module.stderr == program.stderr
    assert module.stderr.startswith("msmesh: error:")


def test_denoise_writes_what_the_program_writes(tmp_path):
    assert run_program("shape", "fandisk", "--resolution", "6", "-o", "clean.obj", "-q", cwd=tmp_path).returncode == 0
    assert run_program("noise", "clean.obj", "-o", "noisy.obj", "--seed", "3", "-q", cwd=tmp_path).returncode == 0
    assert run_module("denoise", "noisy.obj", "-o", "a.obj", "-q", cwd=tmp_path).returncode == 0
    assert run_program("denoise", "noisy.obj", "-o", "b.obj", "-q", cwd=tmp_path).returncode == 0
    assert (tmp_path / "a.obj").read_bytes() == (tmp_path / "b.obj").read_bytes()


def test_run_returns_the_status(tmp_path):
    assert _cli.run(["shape", "cube", "--resolution", "2", "-o", str(tmp_path / "c.obj"), "-q"]) == 0
    assert (tmp_path / "c.obj").stat().st_size > 0
    assert _cli.main(["nosuchcommand"]) == 2

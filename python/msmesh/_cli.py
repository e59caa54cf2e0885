"""The msmesh program from Python: the `msmesh` command a pip install puts on PATH, and
``python -m msmesh``. Both run the C++ program with the same arguments, output and exit status.

A pip install (docs/python.md) puts the program inside the package, ``msmesh/_bin/msmesh``; in
a CMake build tree (``PYTHONPATH=build/python``) it is ``build/msmesh``.
"""

import os
import subprocess
import sys
from pathlib import Path
from typing import List, Optional, Sequence

_HERE = Path(__file__).resolve().parent


def program_path() -> Optional[str]:
    """The msmesh program this module runs, or None when there is none.

    Returns
    -------
    str or None
        ``<package>/_bin/msmesh`` (pip install), else ``<build>/msmesh`` when the package is
        the CMake build tree's ``<build>/python/msmesh``.
    """
    for candidate in (_HERE / "_bin" / "msmesh", _HERE.parent.parent / "msmesh"):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


def run(args: Sequence[str]) -> int:
    """Runs ``msmesh ARGS...`` as a child process and waits for it.

    Parameters
    ----------
    args : sequence of str
        The arguments after ``msmesh``, e.g. ``["denoise", "in.ply", "-o", "out.ply"]``.

    Returns
    -------
    int
        The program's exit status (0 success, 1 the work failed, 2 a usage error; 128 + N
        when signal N ended it).
    """
    program = program_path()
    if program is None:
        return _missing()
    status = subprocess.call([program, *args])
    return 128 - status if status < 0 else status


def main(argv: Optional[List[str]] = None) -> int:
    """Entry point of the `msmesh` command and of ``python -m msmesh``: replaces this process
    with the program (same arguments, streams, signals and exit status). With ``argv`` given, runs
    it as a child process instead and returns its exit status (see run). ``batch ...`` runs
    msmesh.batch.main in this interpreter."""
    args = sys.argv[1:] if argv is None else list(argv)
    if args[:1] == ["batch"]:
        # The batch runner is Python: run it here rather than through the program, which would
        # start this interpreter again (cli/cmd_batch.cpp).
        from . import batch

        return batch.main(args[1:])
    if argv is not None:
        return run(argv)
    program = program_path()
    if program is None:
        return _missing()
    sys.stdout.flush()
    sys.stderr.flush()
    if os.name == "posix":
        os.execv(program, ["msmesh", *sys.argv[1:]])  # does not return
    return run(sys.argv[1:])


def _missing() -> int:
    sys.stderr.write(
        f"msmesh: error: the msmesh program is not installed with this Python module ({_HERE}); "
        "install the package with pip (docs/python.md) or build the program (scripts/build)\n")
    return 1

"""One task of ``msmesh batch``, run on a Dask worker: the msmesh program as a child process on
one mesh, so that the output is the one a single run writes, bit for bit, and a crash of the
program on one mesh cannot take the worker down.

The task is idempotent, so that Dask can run it again on another worker when the one running
it dies: msmesh writes its output atomically (a temporary file renamed into place), the child
gets SIGTERM when the worker dies (its signal handler removes the temporary file), and the
temporary files a SIGKILL left behind are removed before the next attempt.
"""

import ctypes
import glob
import json
import os
import signal
import socket
import subprocess
import tempfile
import time
from typing import Any, Dict, List

_PR_SET_PDEATHSIG = 1


def _die_with_parent():  # runs in the child between fork and exec
    try:
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGTERM)
    except (OSError, AttributeError):
        pass


def _remove_stale_temporaries(path: str) -> None:
    """Temporary files an earlier, killed attempt left next to the output (io/atomic_file.cpp
    names them .NAME.tmp-PID-N-R)."""
    folder, name = os.path.split(path)
    for stale in glob.glob(os.path.join(glob.escape(folder or "."), "." + glob.escape(name) + ".tmp-*")):
        try:
            os.remove(stale)
        except OSError:
            pass


def _run(argv: List[str], env: Dict[str, str]) -> Dict[str, Any]:
    """Runs a program; its exit status, output, error text, seconds and peak memory (bytes)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        t0 = time.monotonic()
        child = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out, stderr=err, env=env,
                                 preexec_fn=_die_with_parent)
        while True:
            try:
                _, status, usage = os.wait4(child.pid, 0)
                break
            except InterruptedError:
                continue
        child.returncode = os.waitstatus_to_exitcode(status) if hasattr(os, "waitstatus_to_exitcode") else (
            -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status))
        seconds = time.monotonic() - t0
        out.seek(0)
        err.seek(0)
        return {"status": child.returncode, "stdout": out.read().decode(errors="replace"),
                "stderr": err.read().decode(errors="replace"), "seconds": seconds,
                "peak_memory": usage.ru_maxrss * 1024}


def _write_atomically(path: str, text: str) -> None:
    folder = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".tmp-")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


def _figures(command: str, report: Dict[str, Any]) -> Dict[str, Any]:
    """The error figures of msmesh's --json output (with a ground truth)."""
    if command == "eval":
        keys = ("msae_e3", "mean_angle_deg", "flipped", "dist_mean_e3", "dist_rms_e3", "dist_max_e3",
                "dist_area_weighted_rms_e3")
        return {k: report[k] for k in keys if k in report}
    found = {}
    for name, prefix in (("result_errors", ""), ("input_errors", "input_"), ("errors", "")):
        for k, v in (report.get(name) or {}).items():
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                found[prefix + k] = v
    return found


def _worker_name() -> str:
    try:
        from distributed import get_worker

        return get_worker().name if isinstance(get_worker().name, str) else str(get_worker().address)
    except (ImportError, ValueError):
        return socket.gethostname()


def _worker_memory_limit() -> int:
    try:
        from distributed import get_worker

        w = get_worker()
        manager = getattr(w, "memory_manager", None)
        return int(getattr(manager, "memory_limit", None) or getattr(w, "memory_limit", 0) or 0)
    except (ImportError, ValueError):
        return 0


def message_of(stderr: str, status: int) -> str:
    """The error msmesh printed (its "msmesh: error: " lines), else the exit status."""
    lines = [ln[len("msmesh: error: "):] if ln.startswith("msmesh: error: ") else ln
             for ln in stderr.strip().splitlines() if ln.strip()]
    if lines:
        return " ".join(lines)[:2000]
    if status < 0:
        return f"msmesh was killed by signal {-status} ({signal.Signals(-status).name})"
    return f"msmesh exited with status {status}"


def run_task(spec: Dict[str, Any]) -> Dict[str, Any]:
    """Runs one task (a dict made by msmesh.batch) and returns its record for the results table.

    Never raises for a failure of msmesh on the mesh: the record says status "failed" and
    holds the error.
    """
    command, output = spec["command"], spec["output"]
    os.makedirs(os.path.dirname(output) or ".", exist_ok=True)
    _remove_stale_temporaries(output)
    argv = [spec["program"], command, spec["input"]]
    if command != "eval":
        argv += ["-o", output]
    if spec.get("truth"):
        argv += ["--truth", spec["truth"]]
    argv += list(spec["options"]) + ["--json", "--threads", str(spec.get("threads", 1))]
    env = dict(os.environ)
    limit = _worker_memory_limit()
    if limit and "MSMESH_MEMORY_LIMIT" not in env:
        env["MSMESH_MEMORY_LIMIT"] = str(limit)  # msmesh refuses a mesh it cannot hold (include/msmesh/memory.h)
    record: Dict[str, Any] = {"worker": _worker_name()}
    result = _run(argv, env)
    record.update(seconds=round(result["seconds"], 4), peak_memory_mb=round(result["peak_memory"] / 2**20, 1),
                  exit_status=result["status"])
    report: Dict[str, Any] = {}
    if result["status"] == 0:
        try:
            report = json.loads(result["stdout"].strip().splitlines()[-1])
        except (ValueError, IndexError):
            report = {}
        if command == "eval":
            _write_atomically(output, result["stdout"])
    if result["status"] != 0 or not os.path.isfile(output):
        record.update(status="failed", error=message_of(result["stderr"], result["status"]))
        return record
    record.update(status="ok", error="")
    for key in ("vertices", "faces", "result_faces"):
        if key in report:
            record["faces" if key != "vertices" else "vertices"] = report[key]
    record["figures"] = _figures(command, report)
    notes = report.get("notes")
    if notes:
        record["notes"] = "; ".join(str(n) for n in notes) if isinstance(notes, list) else str(notes)
    thumbnail = spec.get("thumbnail")
    if thumbnail:
        os.makedirs(os.path.dirname(thumbnail), exist_ok=True)
        _remove_stale_temporaries(thumbnail)
        mesh = spec["input"] if command == "eval" else output
        shot = _run([spec["program"], "render", mesh, "-o", thumbnail, "--size", "200x150", "--threads",
                     str(spec.get("threads", 1))], env)
        if shot["status"] != 0:
            record["notes"] = ((record.get("notes") or "") + " thumbnail: " +
                               message_of(shot["stderr"], shot["status"])).strip()
    return record

"""Batch processing of many meshes on Dask (docs/batch.md): ``msmesh batch COMMAND INPUTS... -o
OUTDIR [OPTIONS]``, ``python -m msmesh batch ...``, ``python -m msmesh.batch ...`` and
``msmesh.batch.run(...)``.

Every task runs the msmesh program on one mesh (msmesh._batch_task), on the workers of a Dask
cluster: by default a local one (one worker process per core, one thread each, a memory limit
per worker), or an existing one (``--scheduler tcp://HOST:PORT``). Tasks are scheduled by the
library's memory estimate (msmesh._batch_memory) as the worker resource MEMORY. Outputs keep
the inputs' folders under OUTDIR; OUTDIR/results.csv, results.jsonl and index.html record every
mesh (msmesh._batch_results). A rerun skips the meshes already done with the same options.
"""

import json
import os
import subprocess
import sys
import threading
import time
from typing import Any, Dict, List, Optional, Sequence

from . import _batch_results as results
from ._batch_inputs import BatchInputError, collect_tasks, output_relative, split_arguments, truth_for
from ._batch_memory import face_count, format_bytes, memory_estimate, parse_bytes
from ._batch_progress import Progress, failure
from ._batch_task import run_task
from ._cli import program_path

COMMANDS = ("denoise", "inpaint", "segment", "repair", "eval")
# Options of the single commands that name one more file per run, or change what a run writes:
# a batch cannot share them among its tasks.
REFUSED = {"--report": "per-mesh HTML reports", "--save-field": "edge field files", "--labels": "label files",
           "--parts": "part folders", "--in-place": "writing over the inputs", "--list": "listing holes",
           "--dry-run": "a dry run", "-o": "", "--output": ""}
DROPPED = ("--json", "-q", "--quiet")  # the batch adds --json itself and prints its own progress
THUMBNAILS = "_thumbnails"

USAGE = """usage: msmesh batch {denoise,inpaint,segment,repair,eval} INPUTS... -o OUTDIR [OPTIONS]

Runs `msmesh COMMAND` on many meshes on a Dask cluster (docs/batch.md).

INPUTS     mesh files, folders (searched recursively for .obj .off .ply .stl .gltf .glb, also .gz),
           globs ('scans/**/*.ply', quoted), or CSV manifests (columns input, truth, options)
OPTIONS    every option of `msmesh COMMAND` (after the inputs) applies to every mesh, and:
  -o, --output-dir DIR    where the outputs go, with the folders of the inputs (required)
  --truth PATH            ground truth: a file for every mesh, or a folder with one at each
                          input's relative path (a manifest's truth column comes first)
  --scheduler ADDRESS     an existing Dask scheduler (tcp://HOST:8786) instead of a local cluster
  --workers N             local cluster: worker processes (default: one per core)
  --memory-limit BYTES    local cluster: memory per worker (e.g. 4G; default: the memory / N)
  --threads-per-task N    msmesh --threads for each task (default: cores / workers)
  --ext EXT               write the outputs in another format (e.g. .ply)
  --force                 redo every mesh (default: skip those done with the same options)
  --no-thumbnails         no thumbnail per mesh in OUTDIR/index.html
  --program PATH          the msmesh program the workers run (default: the one of this package)
  -q, --quiet             no progress and no summary
Writes OUTDIR/results.csv, results.jsonl (status, error, figures, seconds, peak memory of each
mesh) and index.html. Exit status 0 when every mesh succeeded, 1 when one failed, 2 on a usage
error."""


class UsageError(ValueError):
    pass


def _program_version(program: str) -> str:
    try:
        return subprocess.run([program, "--version"], capture_output=True, text=True, timeout=60).stdout.strip()
    except (OSError, subprocess.TimeoutExpired) as e:
        raise UsageError(f"{program}: cannot run the msmesh program: {e}") from e


def _check_options(options: Sequence[str], where: str) -> List[str]:
    kept = []
    for a in options:
        name = a.split("=", 1)[0]
        if name in REFUSED:
            what = REFUSED[name]
            raise UsageError(f"{where}{name} cannot be given to a batch" + (f" ({what})" if what else
                                                                             " (use -o OUTDIR of the batch)"))
        if name in DROPPED:
            continue
        kept.append(a)
    return kept


def _start_cluster(workers: Optional[int], memory_limit: Optional[int]):
    import logging

    from distributed import LocalCluster
    from distributed.system import MEMORY_LIMIT

    n = workers or os.cpu_count() or 1
    limit = memory_limit or int(MEMORY_LIMIT / n)
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, memory_limit=limit,
                           resources={"MEMORY": limit}, dashboard_address=":0", silence_logs=logging.ERROR)
    return cluster


def _capacity(client) -> Dict[str, Any]:
    """What the workers hold: whether they all have the resource MEMORY, the largest amount of it
    (or of their memory limit), and their number of threads."""
    info = client.scheduler_info().get("workers", {})
    memory = [w.get("resources", {}).get("MEMORY") for w in info.values()]
    use_resources = bool(memory) and all(m for m in memory)
    limits = memory if use_resources else [w.get("memory_limit") or 0 for w in info.values()]
    return {"resources": use_resources, "largest": max(limits) if limits and all(limits) else 0,
            "threads": sum(w.get("nthreads", 1) for w in info.values()) or 1}


def _outcome(future):
    """The task's outcome dict, or a failed one naming the error. A future that is done without
    an error nor a result lost its result with its worker (killed after the task finished):
    Dask computes it again for a client that still holds the future, so wait for that."""
    if future.status == "finished":
        return future.result()
    error = future.exception()
    if error is None:
        try:
            return future.result()
        except Exception as e:  # noqa: BLE001 (any error of the task or the cluster is reported)
            error = e
    return {"status": "failed", "error": f"the task failed on the cluster: {type(error).__name__}: {error}"}


def run(command: str, inputs: Sequence[str], output_dir: str, options: Sequence[str] = (), *,
        truth: Optional[str] = None, scheduler: Optional[str] = None, client=None, workers: Optional[int] = None,
        memory_limit: Optional[int] = None, threads_per_task: Optional[int] = None, force: bool = False,
        thumbnails: bool = True, extension: Optional[str] = None, program: Optional[str] = None,
        quiet: bool = True, progress_stream=None) -> List[Dict[str, Any]]:
    """Runs ``msmesh COMMAND`` on every input and returns the records of the results table (one
    dict per input: input, output, status "ok" or "failed", error, figures, seconds,
    peak_memory_mb, reused ...), also written to OUTDIR/results.csv, results.jsonl and index.html.

    Parameters
    ----------
    command : str
        denoise, inpaint, segment, repair or eval.
    inputs : sequence of str
        Files, folders, globs, CSV manifests.
    output_dir : str
        Where the outputs go (created).
    options : sequence of str
        Options of the single command for every mesh, e.g. ``["--preset", "cad"]``.
    scheduler, client
        An existing Dask scheduler's address, or a distributed.Client; else a local cluster of
        ``workers`` processes with ``memory_limit`` bytes each.

    Raises
    ------
    ValueError
        A command, option or input that cannot be run (nothing is done then).
    """
    if command not in COMMANDS:
        raise UsageError(f"unknown batch command '{command}'; valid: {', '.join(COMMANDS)}")
    program = program or os.environ.get("MSMESH_CLI") or program_path()
    if not program:
        raise UsageError("no msmesh program beside this Python module; give --program PATH")
    program = os.path.abspath(program)
    version = _program_version(program)
    options = _check_options(options, "")
    tasks = collect_tasks(inputs, output_dir)
    if not tasks:
        raise BatchInputError("no input given")
    os.makedirs(output_dir, exist_ok=True)
    previous = {} if force else results.load(output_dir)

    specs, records = [], {}
    for i, t in enumerate(tasks):
        task_options = options + _check_options(t.options, f"{t.input}: manifest options: ")
        task_truth = truth_for(t, truth)
        if command == "eval" and not task_truth:
            raise UsageError(f"{t.input}: eval needs a ground truth (--truth or a manifest's truth column)")
        out = os.path.abspath(os.path.join(output_dir, output_relative(t.relative, command, extension)))
        source = os.path.abspath(t.input)
        key = json.dumps([command, task_options, os.path.abspath(task_truth) if task_truth else None, version])
        spec = {"command": command, "input": source, "output": out,
                "truth": os.path.abspath(task_truth) if task_truth else None, "options": task_options,
                "program": program, "options_key": key, "index": i,
                "thumbnail": os.path.abspath(os.path.join(output_dir, THUMBNAILS, t.relative + ".png"))
                if thumbnails else None}
        if not force and results.up_to_date(previous.get(source, {}), key, out, [source, spec["truth"]]):
            records[i] = dict(previous[source], reused=True)
            continue
        specs.append(spec)

    journal = results.Journal(output_dir)
    progress = Progress(len(tasks), progress_stream, quiet)
    progress.done = len(records)
    own_cluster = None
    try:
        if specs:
            from distributed import Client, as_completed

            if client is None:
                if scheduler:
                    client = Client(scheduler)
                else:
                    own_cluster = _start_cluster(workers, memory_limit)
                    client = Client(own_cluster)
            capacity = _capacity(client)
            n_workers = max(1, len(client.scheduler_info().get("workers", {})))
            threads = threads_per_task or (max(1, (os.cpu_count() or 1) // n_workers) if own_cluster else 1)
            futures = {}
            for spec in specs:
                spec["threads"] = threads
                faces = face_count(spec["input"], program)
                estimate = memory_estimate(faces, command, spec["options"])
                spec["faces"], spec["estimate_mb"] = faces, round(estimate / 2**20, 1)
                if capacity["largest"] and estimate > capacity["largest"]:
                    record = _record(spec, {"status": "failed", "error": (
                        f"{spec['input']}: {faces} faces need about {format_bytes(estimate)} of memory, more than "
                        f"any worker holds ({format_bytes(capacity['largest'])}); give the workers more memory "
                        "(--memory-limit, dask-worker --memory-limit and --resources MEMORY=BYTES)")})
                    records[spec["index"]] = record
                    journal.add(record)
                    progress.finished(record)
                    continue
                resources = {"MEMORY": estimate} if capacity["resources"] and estimate > 0 else None
                future = client.submit(run_task, spec, key=f"msmesh-{command}-{spec['index']}-{os.getpid()}-"
                                       f"{time.time_ns()}", pure=False, resources=resources)
                futures[future] = spec
            lock = threading.Lock()
            stop = threading.Event()

            left = [len(futures)]  # tasks not finished yet; at most one per worker thread runs

            def redraw():
                while not stop.wait(0.5):
                    with lock:
                        progress.draw()

            progress.running = min(left[0], capacity["threads"])
            drawer = threading.Thread(target=redraw, daemon=True)
            drawer.start()
            try:
                for future in as_completed(list(futures)):
                    spec = futures[future]
                    outcome = _outcome(future)
                    record = _record(spec, outcome)
                    with lock:
                        records[spec["index"]] = record
                        journal.add(record)
                        left[0] -= 1
                        progress.running = min(left[0], capacity["threads"])
                        progress.finished(record)
            finally:
                stop.set()
                drawer.join()
    finally:
        journal.close()
        progress.close()
        done = [records[i] for i in sorted(records)]
        if done:
            results.write_tables(output_dir, done)
            results.write_html(output_dir, done, f"msmesh batch {command}: {len(done)} meshes")
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    return [records[i] for i in sorted(records)]


def _record(spec: Dict[str, Any], outcome: Dict[str, Any]) -> Dict[str, Any]:
    record = {"input": spec["input"], "output": spec["output"], "truth": spec["truth"], "faces": spec.get("faces"),
              "estimate_mb": spec.get("estimate_mb"), "options": spec["options_key"], "reused": False,
              "finished": time.strftime("%Y-%m-%dT%H:%M:%S%z")}
    record.update(outcome)
    if record.get("status") == "ok" and spec.get("thumbnail") and os.path.isfile(spec["thumbnail"]):
        record["thumbnail"] = spec["thumbnail"]
    return record


def _parse(argv: Sequence[str]) -> Dict[str, Any]:
    argv = list(argv)
    if not argv or argv[0] in ("-h", "--help"):
        raise SystemExit(print(USAGE) or 0)
    command, rest = argv[0], argv[1:]
    if command not in COMMANDS:
        raise UsageError(f"unknown batch command '{command}'; valid: {', '.join(COMMANDS)}")
    values = {"-o": "output_dir", "--output-dir": "output_dir", "--scheduler": "scheduler", "--workers": "workers",
              "--memory-limit": "memory_limit", "--threads-per-task": "threads_per_task", "--ext": "extension",
              "--program": "program", "--truth": "truth"}
    flags = {"--force": "force", "--no-thumbnails": "no_thumbnails", "-q": "quiet", "--quiet": "quiet"}
    found: Dict[str, Any] = {}
    left: List[str] = []
    i = 0
    while i < len(rest):
        a = rest[i]
        name, eq, value = a.partition("=")
        if a in ("-h", "--help"):
            raise SystemExit(print(USAGE) or 0)
        if name in values:
            if not eq:
                if i + 1 >= len(rest):
                    raise UsageError(f"{name} needs a value")
                value = rest[i + 1]
                i += 1
            found[values[name]] = value
        elif a in flags:
            found[flags[a]] = True
        else:
            left.append(a)
        i += 1
    inputs, options = split_arguments(left)
    if not inputs:
        raise UsageError("no input given (files, folders, globs or CSV manifests)")
    if "output_dir" not in found:
        raise UsageError("-o OUTDIR is required")
    try:
        for k in ("workers", "threads_per_task"):
            if k in found:
                found[k] = int(found[k])
                if found[k] < 1:
                    raise ValueError(f"{k.replace('_', '-')} must be at least 1")
        if "memory_limit" in found:
            found["memory_limit"] = parse_bytes(found["memory_limit"])
    except ValueError as e:
        raise UsageError(f"bad value: {e}") from e
    return dict(found, command=command, inputs=inputs, options=options)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """``msmesh batch ...``: the exit status (0 all done, 1 a mesh failed, 2 a usage error)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        a = _parse(argv)
        quiet = a.get("quiet", False)
        t0 = time.monotonic()
        records = run(a["command"], a["inputs"], a["output_dir"], a["options"], truth=a.get("truth"),
                      scheduler=a.get("scheduler"), workers=a.get("workers"), memory_limit=a.get("memory_limit"),
                      threads_per_task=a.get("threads_per_task"), force=a.get("force", False),
                      thumbnails=not a.get("no_thumbnails", False), extension=a.get("extension"),
                      program=a.get("program"), quiet=quiet)
    except (UsageError, BatchInputError) as e:
        sys.stderr.write(f"msmesh: error: {e}\nRun 'msmesh batch --help' for the options.\n")
        return 2
    except KeyboardInterrupt:
        sys.stderr.write("msmesh: error: interrupted; a rerun goes on where this one stopped\n")
        return 130
    failed = [r for r in records if r.get("status") != "ok"]
    if not quiet:
        reused = sum(bool(r.get("reused")) for r in records)
        seconds = time.monotonic() - t0
        print(f"batch {a['command']}: {len(records) - len(failed)} done ({reused} already done before), "
              f"{len(failed)} failed, in {seconds:.1f} s -> {a['output_dir']} "
              f"(results.csv, results.jsonl, index.html)")
        for r in failed:
            print(f"  failed: {failure(r)}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

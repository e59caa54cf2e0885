"""msmesh batch (msmesh.batch, docs/batch.md) on a local Dask cluster of two workers: outputs
identical bit for bit to single `msmesh denoise` runs, a worker killed in the middle of the run,
resuming, bad files among good ones, a crash of msmesh, manifests, the memory limit, the command
line.

Needs the msmesh program (MSMESH_CLI or beside the module) and python3-distributed; skipped
without them. About a minute on two busy cores.
"""

import csv
import json
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

import msmesh
from msmesh import _cli

distributed = pytest.importorskip("distributed", reason="python3-distributed (Debian) is not installed")

from msmesh import batch  # noqa: E402
from msmesh._batch_inputs import BatchInputError, collect_tasks, output_relative  # noqa: E402

PROGRAM = os.environ.get("MSMESH_CLI") or _cli.program_path()
pytestmark = pytest.mark.skipif(PROGRAM is None, reason="no msmesh program (MSMESH_CLI or beside the module)")


def msmesh_run(*args, cwd=None):
    result = subprocess.run([PROGRAM, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture(scope="module")
def meshes(tmp_path_factory):
    """20 small noisy meshes in two folders (in/a, in/b/deep) with their clean truths, and the
    outputs of single `msmesh denoise` runs (expected/, same relative paths)."""
    root = tmp_path_factory.mktemp("batch")
    shapes = ["fandisk", "cube", "cylinder", "pyramid", "torus"]
    relatives = []
    for i in range(20):
        shape = shapes[i % len(shapes)]
        folder = "a" if i < 10 else os.path.join("b", "deep")
        ext = ".ply" if i % 4 == 3 else ".obj"
        rel = os.path.join(folder, f"{shape}{i:02d}{ext}")
        for d in ("in", "truth", "expected"):
            (root / d / folder).mkdir(parents=True, exist_ok=True)
        msmesh_run("shape", shape, "-r", 3 + i % 3, "-o", root / "truth" / rel)
        msmesh_run("noise", root / "truth" / rel, "-o", root / "in" / rel, "--seed", i, "-q")
        msmesh_run("denoise", root / "in" / rel, "-o", root / "expected" / rel, "-q")
        relatives.append(rel)
    return root, relatives


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, memory_limit="1GB",
                                       resources={"MEMORY": 2**30}, dashboard_address=":0", silence_logs=40)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def no_temporaries(folder):
    return [os.path.join(d, f) for d, _, files in os.walk(folder) for f in files if ".tmp-" in f]


def test_outputs_are_those_of_single_runs(meshes, client, tmp_path):
    root, relatives = meshes
    out = tmp_path / "out"
    records = batch.run("denoise", [str(root / "in")], str(out), client=client)
    assert len(records) == 20
    assert all(r["status"] == "ok" for r in records), [r["error"] for r in records]
    for rel in relatives:
        assert (out / rel).read_bytes() == (root / "expected" / rel).read_bytes(), rel
    assert no_temporaries(out) == []
    with open(out / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 20 and {r["status"] for r in rows} == {"ok"}
    assert all(float(r["seconds"]) > 0 and float(r["peak_memory_mb"]) > 0 for r in rows)
    assert {int(r["faces"]) for r in rows} == {r["faces"] for r in records}
    lines = (out / "results.jsonl").read_text().splitlines()
    assert sorted(json.loads(ln)["output"] for ln in lines) == sorted(str(out / rel) for rel in relatives)
    page = (out / "index.html").read_text()
    assert page.count("<img ") == 20
    for rel in relatives:
        assert (out / "_thumbnails" / (rel + ".png")).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert {r["worker"] for r in records} == set(client.scheduler_info()["workers"])  # both workers worked


def test_resume_skips_what_is_done(meshes, client, tmp_path):
    root, relatives = meshes
    inputs = tmp_path / "in"
    subprocess.run(["cp", "-r", str(root / "in"), str(inputs)], check=True)
    out = tmp_path / "out"
    first = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    assert not any(r["reused"] for r in first)
    again = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    assert all(r["reused"] for r in again) and all(r["status"] == "ok" for r in again)

    # An input newer than its output is redone, and only that one.
    changed = inputs / relatives[4]
    earlier = os.stat(changed).st_mtime - 5
    os.utime(out / relatives[4], (earlier, earlier))
    third = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    assert [r["input"] for r in third if not r["reused"]] == [str(changed)]
    # An output that disappeared is redone.
    os.remove(out / relatives[7])
    fourth = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    assert [r["input"] for r in fourth if not r["reused"]] == [str(inputs / relatives[7])]
    assert (out / relatives[7]).read_bytes() == (root / "expected" / relatives[7]).read_bytes()
    # Other options: every mesh again, and what they write is what a single run with them writes.
    fifth = batch.run("denoise", [str(inputs)], str(out), ["--strength", "0.5"], client=client, thumbnails=False)
    assert not any(r["reused"] for r in fifth)
    msmesh_run("denoise", inputs / relatives[0], "-o", tmp_path / "single.obj", "--strength", "0.5", "-q")
    assert (out / relatives[0]).read_bytes() == (tmp_path / "single.obj").read_bytes()
    # Another output format: other outputs, so every mesh again but those that were PLY already.
    as_ply = batch.run("denoise", [str(inputs)], str(out), ["--strength", "0.5"], client=client, thumbnails=False,
                       extension=".ply")
    assert all(r["output"].endswith(".ply") for r in as_ply)
    assert [r["reused"] for r in as_ply] == [r["input"].endswith(".ply") for r in as_ply]
    # --force: everything again.
    sixth = batch.run("denoise", [str(inputs)], str(out), ["--strength", "0.5"], client=client, thumbnails=False,
                      force=True)
    assert not any(r["reused"] for r in sixth)
    assert len((out / "results.jsonl").read_text().splitlines()) == 20  # rewritten: one line per input


def test_bad_files_are_recorded_and_the_rest_go_on(meshes, client, tmp_path):
    root, relatives = meshes
    inputs = tmp_path / "in"
    inputs.mkdir()
    for rel in relatives[:4]:
        (inputs / os.path.basename(rel)).write_bytes((root / "in" / rel).read_bytes())
    (inputs / "garbage.obj").write_text("this is not a mesh\n")
    (inputs / "cut.off").write_text("OFF\n100 200 0\n0 0 0\n1 0 0\n")  # counts promise more than there is
    (inputs / "empty.ply").write_bytes(b"")
    out = tmp_path / "out"
    records = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    by_name = {os.path.basename(r["input"]): r for r in records}
    assert len(records) == 7
    for name in ("garbage.obj", "cut.off", "empty.ply"):
        r = by_name[name]
        assert r["status"] == "failed"
        assert name in r["error"], r["error"]
        assert not (out / name).exists()
    for rel in relatives[:4]:
        name = os.path.basename(rel)
        assert by_name[name]["status"] == "ok"
        assert (out / name).read_bytes() == (root / "expected" / rel).read_bytes()
    assert no_temporaries(out) == []
    # A rerun redoes the failures only (they fail again) and keeps the rest.
    again = batch.run("denoise", [str(inputs)], str(out), client=client, thumbnails=False)
    assert sorted(os.path.basename(r["input"]) for r in again if not r["reused"]) == [
        "cut.off", "empty.ply", "garbage.obj"]


def test_a_killed_worker_s_task_is_done_again(meshes, tmp_path):
    """A worker process killed (SIGKILL) while it runs a task: Dask runs the task again on a
    worker; every output is complete and identical, and no temporary file is left. The tasks
    run msmesh through a wrapper that waits 0.4 s first, so that the kill lands in one."""
    root, relatives = meshes
    wrapper = tmp_path / "slow-msmesh"
    wrapper.write_text(f"#!/bin/sh\nsleep 0.4\nexec {PROGRAM} \"$@\"\n")
    wrapper.chmod(0o755)
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, memory_limit="1GB",
                                       dashboard_address=":0", silence_logs=50)
    c = distributed.Client(cluster)
    try:
        pids = c.run(os.getpid)
        out = tmp_path / "out"
        found = {}

        def kill_one():
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                busy = [w for w, keys in c.processing().items() if keys and w in pids]
                if busy and len(list(out.rglob("*.obj"))) >= 2:
                    found["processing"] = c.processing()[busy[0]]
                    os.kill(pids[busy[0]], signal.SIGKILL)
                    found["killed"] = busy[0]
                    return
                time.sleep(0.02)

        killer = threading.Thread(target=kill_one)
        killer.start()
        records = batch.run("denoise", [str(root / "in")], str(out), client=c, program=str(wrapper),
                            thumbnails=False)
        killer.join()
        assert "killed" in found and found["processing"], "no worker was busy to kill"
        assert found["killed"] not in c.scheduler_info()["workers"]  # the nanny started a new one
        assert len(records) == 20
        assert all(r["status"] == "ok" for r in records), [r["error"] for r in records]
        for rel in relatives:
            assert (out / rel).read_bytes() == (root / "expected" / rel).read_bytes(), rel
        assert no_temporaries(out) == []
    finally:
        c.close()
        cluster.close()


def test_manifest_with_truths_and_options(meshes, client, tmp_path):
    root, relatives = meshes
    manifest = tmp_path / "list.csv"
    with open(manifest, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["input", "truth", "options"])
        w.writerow([root / "in" / relatives[0], root / "truth" / relatives[0], ""])
        w.writerow([root / "in" / relatives[1], root / "truth" / relatives[1], "--preset cad --strength 2"])
    out = tmp_path / "out"
    records = batch.run("denoise", [str(manifest)], str(out), client=client, thumbnails=False)
    assert [r["status"] for r in records] == ["ok", "ok"]
    single = json.loads(msmesh_run("denoise", root / "in" / relatives[1], "-o", tmp_path / "one.obj", "--truth",
                                   root / "truth" / relatives[1], "--preset", "cad", "--strength", "2",
                                   "--json").stdout)
    assert (out / os.path.basename(relatives[1])).read_bytes() == (tmp_path / "one.obj").read_bytes()
    assert records[1]["figures"]["msae_e3"] == pytest.approx(single["result_errors"]["msae_e3"], rel=1e-9)
    assert records[1]["figures"]["input_msae_e3"] > records[1]["figures"]["msae_e3"]
    with open(out / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert float(rows[0]["msae_e3"]) > 0 and "dist_rms_e3" in rows[0]

    # eval of the outputs against the truths folder: the same figures.
    evals = batch.run("eval", [str(root / "expected" / "a")], str(tmp_path / "ev"), truth=str(root / "truth" / "a"),
                      client=client, thumbnails=False)
    assert len(evals) == 10 and all(r["status"] == "ok" for r in evals)
    rel = os.path.basename(relatives[2])
    figures = json.loads((tmp_path / "ev" / (rel + ".json")).read_text())
    direct = json.loads(msmesh_run("eval", root / "expected" / relatives[2], "--truth", root / "truth" /
                                   relatives[2], "--json").stdout)
    assert figures["msae"] == direct["msae"]


def test_a_mesh_larger_than_any_worker_is_refused(meshes, tmp_path):
    root, relatives = meshes
    cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, memory_limit=0,
                                       resources={"MEMORY": 50_000}, dashboard_address=":0", silence_logs=50)
    c = distributed.Client(cluster)
    try:
        big = relatives[0]  # fandisk at -r 3: 106 faces, about 106 KB > 50 KB
        records = batch.run("denoise", [str(root / "in" / big)], str(tmp_path / "out"), client=c, thumbnails=False)
        assert records[0]["status"] == "failed"
        assert "more than any worker holds" in records[0]["error"] and "faces need about" in records[0]["error"]
        assert not (tmp_path / "out" / os.path.basename(big)).exists()
    finally:
        c.close()
        cluster.close()


def test_inputs_folders_globs_and_output_names(meshes, tmp_path):
    root, relatives = meshes
    tasks = collect_tasks([str(root / "in")], str(tmp_path))
    assert sorted(t.relative for t in tasks) == sorted(relatives)
    globbed = collect_tasks([str(root / "in" / "b" / "**" / "*.ply")], str(tmp_path))
    assert sorted(t.relative for t in globbed) == sorted(
        os.path.relpath(r, "b") for r in relatives if r.startswith("b") and r.endswith(".ply"))
    one = collect_tasks([str(root / "in" / relatives[0]), str(root / "in")], str(tmp_path))
    assert len(one) == 20  # each input once
    with pytest.raises(BatchInputError, match="no such file"):
        collect_tasks([str(tmp_path / "missing.obj")], str(tmp_path))
    (tmp_path / "x").mkdir()
    (tmp_path / "y").mkdir()
    for d in ("x", "y"):
        (tmp_path / d / "m.obj").write_text("v 0 0 0\n")
    with pytest.raises(BatchInputError, match="would both be written"):
        collect_tasks([str(tmp_path / "x" / "m.obj"), str(tmp_path / "y" / "m.obj")], str(tmp_path / "o"))
    assert output_relative("a/b.obj.gz", "denoise", ".ply") == "a/b.ply"
    assert output_relative("a/b.obj", "segment", None) == "a/b.ply"
    assert output_relative("a/b.obj", "eval", None) == "a/b.obj.json"
    assert output_relative("a/b.obj", "repair", None) == "a/b.obj"


def test_command_line(meshes, tmp_path):
    """`msmesh batch` (the program forwards to `python -m msmesh.batch`) and `python -m msmesh
    batch`: usage, errors, a run."""
    root, relatives = meshes
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(msmesh.__file__)))
    helped = subprocess.run([PROGRAM, "batch", "--help"], capture_output=True, text=True, env=env)
    assert helped.returncode == 0 and "usage: msmesh batch" in helped.stdout
    refused = subprocess.run([PROGRAM, "batch", "denoise", str(root / "in"), "-o", str(tmp_path / "o"), "--report",
                              "r.html"], capture_output=True, text=True, env=env)
    assert refused.returncode == 2 and "--report cannot be given to a batch" in refused.stderr
    module = subprocess.run([sys.executable, "-m", "msmesh", "batch", "denoise", str(tmp_path / "none"), "-o",
                             str(tmp_path / "o")], capture_output=True, text=True, env=env)
    assert module.returncode == 2 and "no such file or folder" in module.stderr
    inputs = [str(root / "in" / r) for r in relatives[:3]]
    ran = subprocess.run([PROGRAM, "batch", "denoise", *inputs, "-o", str(tmp_path / "o"), "--workers", "2",
                          "--no-thumbnails", "--ascii"], capture_output=True, text=True, env=env)
    assert ran.returncode == 0, ran.stderr
    assert "3 done" in ran.stdout and ran.stderr.count("ok") == 3  # plain progress lines: not a terminal
    msmesh_run("denoise", inputs[0], "-o", tmp_path / "single.obj", "--ascii", "-q")
    assert (tmp_path / "o" / os.path.basename(inputs[0])).read_bytes() == (tmp_path / "single.obj").read_bytes()


def test_a_crash_of_msmesh_fails_its_mesh_only(meshes, client, tmp_path):
    """msmesh killed by a signal on one mesh (here a wrapper sends itself SIGSEGV for it): that
    mesh is recorded with the signal, the others are done and the workers live on."""
    root, relatives = meshes
    wrapper = tmp_path / "crashing-msmesh"
    wrapper.write_text(f"#!/bin/sh\ncase \"$2\" in *{os.path.basename(relatives[1])}) kill -SEGV $$;; esac\n"
                       f"exec {PROGRAM} \"$@\"\n")
    wrapper.chmod(0o755)
    workers = set(client.scheduler_info()["workers"])
    inputs = [str(root / "in" / r) for r in relatives[:4]]
    records = batch.run("denoise", inputs, str(tmp_path / "out"), client=client, program=str(wrapper),
                        thumbnails=False)
    assert [r["status"] for r in records] == ["ok", "failed", "ok", "ok"]
    assert "killed by signal 11 (SIGSEGV)" in records[1]["error"]
    assert not (tmp_path / "out" / os.path.basename(relatives[1])).exists()
    assert set(client.scheduler_info()["workers"]) == workers

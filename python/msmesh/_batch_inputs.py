"""The inputs of ``msmesh batch``: files, folders (searched recursively for mesh files), globs
and CSV manifests, each turned into tasks with the output path that keeps the inputs' folders.

A manifest is a ``.csv`` file with a header row and the columns ``input`` (required), ``truth``
and ``options`` (optional; the options of that row, split like a shell command line, added after
the options given for every task). Relative paths in it are relative to the manifest's folder.
"""

import csv
import dataclasses
import glob
import os
import shlex
from typing import Dict, List, Optional, Sequence, Tuple

# io/include/msmesh/mesh_format.h: the formats msmesh reads, each also gzip-compressed.
MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".gltf", ".glb")


class BatchInputError(ValueError):
    """An input that does not exist, names no mesh, or two inputs that would share an output."""


def is_mesh_path(path: str) -> bool:
    """True when the file name ends in a mesh extension msmesh reads (also with .gz)."""
    name = path.lower()
    if name.endswith(".gz"):
        name = name[:-3]
    return name.endswith(MESH_EXTENSIONS)


@dataclasses.dataclass
class Task:
    """One mesh to process: the input, its path relative to the output folder, its ground truth
    (or None) and the options of its manifest row."""

    input: str
    relative: str
    truth: Optional[str] = None
    options: List[str] = dataclasses.field(default_factory=list)


def _walk(folder: str, exclude: Optional[str]) -> List[str]:
    found = []
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and
                         (exclude is None or os.path.realpath(os.path.join(root, d)) != exclude))
        found.extend(os.path.join(root, f) for f in sorted(files) if is_mesh_path(f) and not f.startswith("."))
    return found


def _glob_root(pattern: str) -> str:
    """The folder part of a glob before its first wildcard: outputs are relative to it."""
    parts = pattern.split(os.sep)
    fixed = []
    for part in parts[:-1]:
        if glob.has_magic(part):
            break
        fixed.append(part)
    return os.sep.join(fixed) or "."


def _manifest(path: str) -> List[Task]:
    base = os.path.dirname(os.path.abspath(path))
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise BatchInputError(f"{path}: cannot read the manifest: {e}") from e
    tasks = []
    for number, row in enumerate(rows, start=2):
        if "input" not in row or not (row["input"] or "").strip():
            raise BatchInputError(f"{path}: line {number}: no 'input' column (the header must name input, and "
                                  "optionally truth and options)")
        source = os.path.join(base, row["input"].strip())
        truth = (row.get("truth") or "").strip()
        try:
            options = shlex.split(row.get("options") or "")
        except ValueError as e:
            raise BatchInputError(f"{path}: line {number}: options: {e}") from e
        inside = os.path.commonpath([base, os.path.abspath(source)]) == base
        relative = os.path.relpath(os.path.abspath(source), base) if inside else os.path.basename(source)
        tasks.append(Task(source, relative, os.path.join(base, truth) if truth else None, options))
    return tasks


def collect_tasks(inputs: Sequence[str], output_dir: str) -> List[Task]:
    """The tasks of the given inputs, in order, each input once.

    Raises
    ------
    BatchInputError
        An input that is missing, a folder or glob with no mesh file, or two inputs that would
        write the same output.
    """
    exclude = os.path.realpath(output_dir)
    tasks: List[Task] = []
    for item in inputs:
        if item.lower().endswith(".csv") and os.path.isfile(item):
            tasks.extend(_manifest(item))
        elif os.path.isdir(item):
            files = _walk(item, exclude)
            if not files:
                raise BatchInputError(f"{item}: no mesh file in this folder ({', '.join(MESH_EXTENSIONS)}, also .gz)")
            tasks.extend(Task(p, os.path.relpath(p, item)) for p in files)
        elif os.path.isfile(item):
            tasks.append(Task(item, os.path.basename(item)))
        elif glob.has_magic(item):
            files = sorted(p for p in glob.glob(item, recursive=True) if os.path.isfile(p) and is_mesh_path(p))
            if not files:
                raise BatchInputError(f"{item}: no mesh file matches this pattern")
            root = _glob_root(item)
            tasks.extend(Task(p, os.path.relpath(p, root)) for p in files)
        else:
            raise BatchInputError(f"{item}: no such file or folder")
    seen: Dict[str, str] = {}
    unique: List[Task] = []
    by_output: Dict[str, str] = {}
    for t in tasks:
        key = os.path.realpath(t.input)
        if key in seen:
            continue
        seen[key] = t.input
        if t.relative in by_output:
            raise BatchInputError(f"{t.input} and {by_output[t.relative]} would both be written to "
                                  f"{os.path.join(output_dir, t.relative)}; give their common folder instead")
        by_output[t.relative] = t.input
        unique.append(t)
    return unique


def truth_for(task: Task, truth: Optional[str]) -> Optional[str]:
    """The ground truth of a task: its manifest's, else ``--truth`` (a file for every input, or a
    folder holding a truth at each input's relative path)."""
    if task.truth or not truth:
        return task.truth
    return os.path.join(truth, task.relative) if os.path.isdir(truth) else truth


def output_relative(relative: str, command: str, extension: Optional[str]) -> str:
    """The output path (relative to the output folder) of an input: the same name, or with the
    extension replaced (``--ext``; segment writes .ply, eval writes the figures as .json)."""
    if command == "eval":
        return relative + ".json"
    if command == "segment":
        extension = ".ply"
    if not extension:
        return relative
    stem = relative[:-3] if relative.lower().endswith(".gz") else relative
    stem = os.path.splitext(stem)[0]
    return stem + (extension if extension.startswith(".") else "." + extension)


def split_arguments(args: Sequence[str]) -> Tuple[List[str], List[str]]:
    """Inputs (the arguments before the first option) and the options after them."""
    args = list(args)
    for i, a in enumerate(args):
        if a.startswith("-") and a != "-":
            return args[:i], args[i:]
    return args, []

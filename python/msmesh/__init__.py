"""msmesh: feature-preserving mesh denoising (NMSTV normal filtering + vertex updating).

Meshes are numpy arrays: V is (#V, 3) float vertex positions, F is (#F, 3) integer vertex
indices of triangles (counter-clockwise seen from outside). Every function checks its
arguments first and raises InvalidInputError (a ValueError) with a message naming the argument,
the row and the value; nothing is modified in place.

Errors: InvalidInputError (ValueError), IoError (OSError), SolverError (RuntimeError),
Cancelled (a progress callback returned False); all derive from msmesh.Error.

Long calls release the GIL, so they can run in a thread while Python goes on. A progress
callback ``progress(event)`` gets a ProgressEvent (stage, iteration, max_iterations, residual)
after every iteration; returning False cancels the call (Cancelled), returning None or True
continues; an exception it raises is re-raised by the call.
"""

import dataclasses
import os
from typing import Dict, List, Optional, Tuple, Union

# OpenMP threads waiting at a barrier spin by default, which makes runs several times slower
# on a busy machine (docs/performance.md); libgomp reads this once, when the extension
# loads it below, so set the passive policy unless the user chose one.
if "OMP_WAIT_POLICY" not in os.environ and "GOMP_SPINCOUNT" not in os.environ:
    os.environ["OMP_WAIT_POLICY"] = "passive"

import numpy as np  # noqa: E402

from . import _checks  # noqa: E402
from ._core import (  # noqa: E402
    BilateralOptions,
    Cancelled,
    DenoiseMethod,
    DenoiseOptions,
    Error,
    InvalidInputError,
    IoError,
    LinearSolver,
    NormalFilterOptions,
    ProgressEvent,
    SolverError,
    VertexUpdateOptions,
)
from . import _core

__version__ = "0.1.0"

__all__ = [
    "denoise", "filter_normals", "update_vertices", "add_noise", "evaluate", "choose_preset",
    "read_mesh", "write_mesh", "Mesh", "repair", "make_shape", "shape_names", "preset_names", "PARAMETERS",
    "set_threads", "threads",
    "Error", "InvalidInputError", "IoError", "SolverError", "Cancelled", "ProgressEvent",
    "DenoiseOptions", "DenoiseMethod", "LinearSolver", "NormalFilterOptions", "VertexUpdateOptions", "BilateralOptions",
]

_METHODS = {"nmstv": DenoiseMethod.NMSTV, "mstv": DenoiseMethod.MSTV, "bilateral": DenoiseMethod.Bilateral}
_PRESETS = ("auto",) + tuple(_core.preset_names())
DEFAULT_PRESET = _core.default_preset()  # "auto", as `msmesh denoise`


def _table(kind):
    """A parameter table of the library (msmesh/parameters.h) as {python name: entry}: each
    entry a dict with option (the CLI spelling), symbol, unit, type, range, help, group and
    defaults (preset or '' -> value)."""
    return {p["name"]: p for p in _core.parameter_table(kind)}


# Keyword parameters: the library's tables, named like the CLI's options with '-' -> '_'
# (`msmesh denoise --help`, `msmesh params`), plus the solver choice. As in the CLI,
# vertex_iterations sets both the NMSTV/MSTV vertex update and the bilateral one, and
# solver_tolerance both solvers.
PARAMETERS = _table("denoise")
_NORMAL_PARAMETERS = _table("normal_filter")
_VERTEX_PARAMETERS = _table("vertex_update")
_SOLVERS = {"auto": LinearSolver.Auto, "cholesky": LinearSolver.Cholesky, "cg": LinearSolver.CG}
_SOLVER_PARAMETER = {"name": "solver", "type": "choice", "range": "auto, cholesky or cg",
                     "help": "linear solver of the fixed systems", "defaults": {"": "auto"}}


def _parameter_doc(table, indent="        "):
    """One line per parameter for a docstring: name (symbol; range; default): help."""
    lines = []
    for name, p in table.items():
        d = p["defaults"]
        values = sorted(set(d.values()), key=str)
        if p["type"] == "bool":
            shown = "/".join(("True" if v else "False") for v in values)
        else:
            shown = ", ".join(f"{k} {v:g}" for k, v in d.items()) if len(values) > 1 else f"{values[0]:g}"
        symbol = p.get("symbol") or ""
        lines.append(f"{indent}{name}{' (' + symbol + ')' if symbol else ''}: {p['help']}; "
                     f"{p['range']}{' ' + p['unit'] if p.get('unit') else ''}; default {shown}")
    return "\n".join(lines)


def preset_names():
    """Preset names accepted by denoise(): auto (the default: chosen from the mesh), cad, smooth."""
    return list(_PRESETS)


def shape_names():
    """Names accepted by make_shape()."""
    return list(_core.shape_names())


def set_threads(n):
    """Threads for the parallel work of every later call, from any Python thread: n >= 1, or 0
    for the default (OMP_NUM_THREADS, else every core). Results are the same for any n.
    Raises InvalidInputError for n < 0 or n > 4096."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise InvalidInputError(f"threads: n must be an integer, got {n!r}")
    if not 0 <= int(n) <= 4096:
        raise InvalidInputError(f"threads: {int(n)} is out of range; valid: 1 to 4096, or 0 for the default")
    _core.set_threads(int(n))


def threads():
    """The number of threads the next call will use."""
    return _core.threads()


def _apply_parameters(options, params, table, function, solvers=()):
    """Sets keyword parameters on an options object through the library's table (`table`, from
    _table()). Unknown names are a TypeError (as for any Python function); a value of the wrong
    type, out of range, not whole (int) or not a bool is an InvalidInputError naming it.
    `solvers`: the option sets ('normals', 'vertices') that 'solver' sets, if accepted."""
    for name, value in params.items():
        if name == "solver" and solvers:
            value = _SOLVERS[_checks.choice(value, name, tuple(_SOLVERS))]
            for attribute in solvers:
                setattr(getattr(options, attribute) if attribute else options, "solver", value)
            continue
        if name not in table:
            valid = list(table) + (["solver"] if solvers else [])
            raise TypeError(f"{function}() got an unexpected keyword argument '{name}'; "
                            f"parameters: {', '.join(valid)}")
        kind = table[name]["type"]
        if kind == "int":
            value = _checks.integer(value, name)
        elif kind == "bool":
            value = _checks.boolean(value, name)
        else:
            value = _checks.real(value, name)
        _core.set_parameter(options, name, float(value))


def _resolve_preset(V, F, preset, report):
    """DenoiseOptions of a preset name; 'auto' is chosen from the mesh by the library (what it
    saw and why recorded in report)."""
    _checks.choice(preset, "preset", _PRESETS)
    r = _core.resolve_preset(preset, V, F)
    report["preset_requested"] = preset
    report["preset"] = r["preset"]
    report["preset_reason"] = r["reason"]
    if r["automatic"]:
        report["auto_sharp_fraction"] = r["sharp_fraction"]
        report["auto_flat_fraction"] = r["flat_fraction"]
        report["auto_noise_level"] = r["noise_level"]
    return r["options"]


def choose_preset(V, F):
    """The preset 'auto' picks for a mesh: dict(preset, sharp_fraction, flat_fraction,
    noise_level, reason)."""
    V, F = _checks.mesh(V, F)
    return _core.choose_preset(V, F)


def denoise(V, F, preset=DEFAULT_PRESET, method="nmstv", progress=None, **params):
    """Denoises a mesh: normal filtering, then vertex updating (F is unchanged).

    V: (#V, 3) positions; F: (#F, 3) triangle indices.
    preset: 'cad' (sharp features), 'smooth' (organic shapes, scans) or 'auto' (chosen from the
        mesh, as `msmesh denoise --preset auto`).
    method: 'nmstv' (the paper), 'mstv' (all IRLA weights 1) or 'bilateral' (Zheng et al. 2011).
    progress: None or a callable(ProgressEvent) -> False to cancel.
    params: overrides of the preset, named like the CLI's options (PARAMETERS; `msmesh params`
        prints the values a preset gives), and solver ('auto', 'cholesky', 'cg'):
{parameters}

    Returns (V_new, report): V_new (#V, 3); report a dict with the filtered 'normals' (#F, 3),
    the edge field 'v' (#E, None for bilateral) on 'edges' (#E, 2), 'preset' (the one used),
    'method', 'parameters', iteration counts, convergence flags, residual and change
    histories, and times in seconds.
    """
    V, F = _checks.mesh(V, F)
    _checks.choice(method, "method", tuple(_METHODS))
    progress = _checks.progress(progress)
    report = {}
    options = _resolve_preset(V, F, preset, report)
    options.method = _METHODS[method]
    _apply_parameters(options, params, PARAMETERS, "denoise", solvers=("normals", "vertices"))
    result = _core.denoise(V, F, options, progress)
    V_new = result.pop("V")
    report["method"] = method
    report["parameters"] = _core.parameters(options)
    report.update(result)
    report["seconds_total"] = report["seconds_normals"] + report["seconds_vertices"]
    return V_new, report


def filter_normals(V, F, preset=None, method="nmstv", normals0=None, progress=None, **params):
    """Algorithm 1 alone: filters the face normals of a mesh.

    preset: None (the library defaults of NormalFilterOptions: preset 'cad'), 'cad', 'smooth'
        or 'auto'.
    method: 'nmstv' (IRLA reweighting) or 'mstv' (all weights 1).
    normals0: (#F, 3) input normals N0; None = the face normals of V.
    params: overrides, and solver ('auto', 'cholesky', 'cg'):
{parameters}

    Returns (N, v, report): N (#F, 3) unit normals, v (#E) the edge field (about 0 on features,
    1 elsewhere) on the edges report['edges'] (#E, 2); report has iterations, convergence,
    residual/change/energy histories and seconds.
    """
    V, F = _checks.mesh(V, F)
    _checks.choice(method, "method", ("nmstv", "mstv"))
    progress = _checks.progress(progress)
    N0 = np.zeros((0, 3)) if normals0 is None else _checks.real_matrix(normals0, "normals0")
    if normals0 is not None and N0.shape[0] != F.shape[0]:
        raise InvalidInputError(f"normals0: must have one row per face ({F.shape[0]}), got {N0.shape[0]}")
    report = {}
    options = DenoiseOptions() if preset is None else _resolve_preset(V, F, preset, report)
    normal_options = options.normals
    _apply_parameters(normal_options, params, _NORMAL_PARAMETERS, "filter_normals", solvers=("",))
    normal_options.reweight = method == "nmstv"
    result = _core.filter_normals(V, F, normal_options, N0, progress)
    N, v = result.pop("normals"), result.pop("v")
    report["method"] = method
    report["parameters"] = _core.parameters(normal_options)
    report.update(result)
    return N, v, report


def update_vertices(V, F, N, v=None, preset=None, progress=None, **params):
    """Algorithm 2 alone: moves the vertices so that the face normals match N.

    N: (#F, 3) target unit normals; v: None (all ones) or the (#E,) edge field of
    filter_normals (values are used as given; denoise() clips them to [0, 1]).
    preset: None (the library defaults of VertexUpdateOptions: preset 'cad'), 'cad', 'smooth'
        or 'auto'.
    params: overrides, and solver ('auto', 'cholesky', 'cg'):
{parameters}

    Returns (V_new, report): report has iterations, convergence, change history and seconds.
    """
    V, F = _checks.mesh(V, F)
    N = _checks.real_matrix(N, "N")
    if N.shape[0] != F.shape[0]:
        raise InvalidInputError(f"N: must have one row per face ({F.shape[0]}), got {N.shape[0]}")
    progress = _checks.progress(progress)
    v = np.zeros(0) if v is None else _checks.real_vector(v, "v")
    report = {}
    options = DenoiseOptions() if preset is None else _resolve_preset(V, F, preset, report)
    vertex_options = options.vertices
    _apply_parameters(vertex_options, params, _VERTEX_PARAMETERS, "update_vertices", solvers=("",))
    result = _core.update_vertices(V, F, N, v, vertex_options, progress)
    V_new = result.pop("V")
    report["parameters"] = _core.parameters(vertex_options)
    report.update(result)
    return V_new, report


for _function, _parameters in ((denoise, PARAMETERS), (filter_normals, _NORMAL_PARAMETERS),
                               (update_vertices, _VERTEX_PARAMETERS)):
    _function.__doc__ = _function.__doc__.replace("{parameters}", _parameter_doc(_parameters))


def add_noise(V, F, sigma=0.2, direction="normal", impulsive=0.0, seed=0):
    """Seeded noise as in the denoising literature; returns noisy V (#V, 3).

    sigma: standard deviation in units of the mean edge length, in [0, 1e6].
    direction: 'normal' (along vertex normals) or 'random' (uniform directions).
    impulsive: 0 for Gaussian noise on every vertex; in (0, 1] the fraction of vertices hit.
    seed: integer in [0, 2**53]; equal seeds give equal noise on any machine (and equal to
        `msmesh noise --seed`).
    """
    V, F = _checks.mesh(V, F)
    sigma = _checks.real(sigma, "sigma", minimum=0.0)
    _checks.choice(direction, "direction", ("normal", "random"))
    impulsive = _checks.real(impulsive, "impulsive", minimum=0.0)
    seed = _checks.integer(seed, "seed", minimum=0, maximum=2**53)
    return _core.add_noise(V, F, sigma, direction, impulsive, seed)


def evaluate(V, F, V_truth, F_truth):
    """Error figures of a result (V, F) against a ground truth (as `msmesh eval`).

    Returns a dict: same_connectivity; msae (radians^2), msae_e3 (= msae x 1e3, as printed in
    the papers), mean_angle_deg, flipped (faces off by > 90 deg), angle_rad (#F) -- these are
    None unless the connectivity is the same; distance_mean, distance_rms, distance_max,
    distance_area_weighted_rms: vertex-to-truth-surface distances relative to the truth's
    bounding-box diagonal.
    """
    V, F = _checks.mesh(V, F)
    V_truth, F_truth = _checks.mesh(V_truth, F_truth, prefix="truth ")
    return _core.evaluate(V, F, V_truth, F_truth)


@dataclasses.dataclass
class Mesh:
    """A mesh and every attribute its file carries, as :func:`read_mesh` returns it with
    ``attributes=True`` and :func:`write_mesh` takes it (the C++ ``msmesh::Mesh``, mesh.h).

    Arrays are numpy arrays; an absent attribute is None (lists and dicts: empty).

    Attributes
    ----------
    V : ndarray, shape (#V, 3), float64
        Vertex positions.
    F : ndarray, shape (#F, 3), int32
        Triangles, counter-clockwise seen from outside.
    vertex_colors : ndarray, shape (#V, 3) or (#V, 4), optional
        RGB or RGBA in [0, 1].
    uv : ndarray, shape (#V, 2), optional
        Per-vertex texture coordinates (origin at the bottom left, as in OBJ and PLY).
    vertex_normals : ndarray, shape (#V, 3), optional
    face_colors : ndarray, shape (#F, 3) or (#F, 4), optional
        RGB or RGBA in [0, 1] per face (PLY).
    texcoords : ndarray, shape (#T, 2), optional
        Table of per-corner texture coordinates (textures with seams) ...
    face_texcoords : ndarray, shape (#F, 3), int32, optional
        ... and, per face corner, its index into `texcoords` (-1: none).
    material_libraries : list of str
        OBJ ``mtllib`` paths, from the current folder (the .mtl file is referenced, not copied).
    material_names : list of str
    face_materials : ndarray, shape (#F,), int32, optional
        Index into `material_names` per face (-1: none); OBJ ``usemtl``, glTF materials.
    group_names, object_names : list of str
    face_groups, face_objects : ndarray, shape (#F,), int32, optional
        OBJ ``g`` groups and ``o`` objects (glTF: one group per primitive), -1: none.
    vertex_properties : dict of str to ndarray, shape (#V,)
        Extra per-vertex scalars (PLY ``quality``, ``intensity``, ...).
    vertex_property_types : dict of str to str
        Their types in the file ("uint8", "float32", ...; default "float64"), kept on writing.
    position_type : str
        "float32" when the file stored float coordinates (written as float again), else "float64".
    gltf_document : bytes, optional
        The source glTF scene (a GLB): writing a .gltf/.glb keeps its materials, textures and nodes.
    notes : list of str
        What reading dropped (never written; informative).
    """

    V: np.ndarray
    F: np.ndarray
    vertex_colors: Optional[np.ndarray] = None
    uv: Optional[np.ndarray] = None
    vertex_normals: Optional[np.ndarray] = None
    face_colors: Optional[np.ndarray] = None
    texcoords: Optional[np.ndarray] = None
    face_texcoords: Optional[np.ndarray] = None
    material_libraries: List[str] = dataclasses.field(default_factory=list)
    material_names: List[str] = dataclasses.field(default_factory=list)
    face_materials: Optional[np.ndarray] = None
    group_names: List[str] = dataclasses.field(default_factory=list)
    face_groups: Optional[np.ndarray] = None
    object_names: List[str] = dataclasses.field(default_factory=list)
    face_objects: Optional[np.ndarray] = None
    vertex_properties: Dict[str, np.ndarray] = dataclasses.field(default_factory=dict)
    vertex_property_types: Dict[str, str] = dataclasses.field(default_factory=dict)
    position_type: str = "float64"
    gltf_document: Optional[bytes] = None
    notes: List[str] = dataclasses.field(default_factory=list)


_MESH_FIELDS = tuple(f.name for f in dataclasses.fields(Mesh))
_ATTRIBUTES = tuple(n for n in _MESH_FIELDS if n not in ("V", "F", "notes"))


def read_mesh(path, attributes: bool = False) -> Union[Tuple[np.ndarray, np.ndarray], Mesh]:
    """Reads a mesh file: OBJ, OFF, PLY, STL, glTF (.gltf, .glb), each optionally gzip-compressed
    (``.obj.gz``, ``.ply.gz``, ...), by extension.

    Parameters
    ----------
    path : str or os.PathLike
    attributes : bool, default False
        False: return ``(V, F)`` only (as before). True: return a :class:`Mesh` with every
        attribute the file carries (colours, alpha, uv, per-corner texture coordinates,
        normals, face colours, materials, groups, extra vertex properties, glTF scene) and
        ``notes`` naming what the file had that is not kept.

    Returns
    -------
    (V, F) : tuple of ndarray, or Mesh

    Raises
    ------
    IoError
        Missing, unreadable, truncated or malformed file (also a corrupt gzip stream).

    Notes
    -----
    Polygons are triangulated; faces repeating a vertex are dropped.
    """
    path = _checks.path(path)
    if not _checks.boolean(attributes, "attributes"):
        V, F, _dropped = _core.read_mesh(path)
        return V, F
    d = _core.read_mesh_attributes(path)
    d.pop("dropped_degenerate", None)
    return Mesh(**d)


def write_mesh(path, V, F=None, binary: bool = True, **attributes) -> List[str]:
    """Writes a mesh file; the format follows the extension (OBJ, OFF, PLY, STL, .gltf, .glb;
    add ``.gz`` to compress). The file appears completely or not at all.

    Parameters
    ----------
    path : str or os.PathLike
    V : ndarray (#V, 3) or Mesh
        Vertex positions, or a :class:`Mesh` (then F and the attributes come from it).
    F : ndarray (#F, 3), optional
        Triangles (required unless V is a Mesh).
    binary : bool, default True
        PLY and STL: binary (True) or ascii.
    **attributes
        Any :class:`Mesh` attribute by name (``vertex_colors=...``, ``uv=...``,
        ``face_colors=...``, ``vertex_normals=...``, ...); with a Mesh, they replace its own.

    Returns
    -------
    list of str
        What the format could not hold and was not written (e.g. "STL cannot hold vertex
        colours: not written"); empty when everything was written.

    Raises
    ------
    InvalidInputError
        Bad shapes, indices or values (nothing written).
    IoError
        Unknown extension or a file-system failure.
    """
    path = _checks.path(path)
    binary = _checks.boolean(binary, "binary")
    unknown = sorted(set(attributes) - set(_ATTRIBUTES))
    if unknown:
        raise InvalidInputError("write_mesh: unknown attribute(s) " + ", ".join(unknown) +
                                "; valid: " + ", ".join(_ATTRIBUTES))
    if isinstance(V, Mesh):
        if F is not None:
            raise InvalidInputError("write_mesh: give F only with a V array, not with a Mesh")
        d = {n: getattr(V, n) for n in _MESH_FIELDS if n != "notes"}
        V, F = d["V"], d["F"]
    else:
        if F is None:
            raise InvalidInputError("write_mesh: F is required (or pass a Mesh as V)")
        d = {}
    d.update(attributes)
    V, F = _checks.mesh(V, F, allow_empty_faces=True)
    def empty(x):
        return x is None or (isinstance(x, (list, dict, tuple, str)) and (len(x) == 0 or x == "float64"))

    if all(empty(d.get(n)) for n in _ATTRIBUTES):
        _core.write_mesh(path, V, F, binary)
        return []
    d["V"], d["F"] = V, F
    for name in ("vertex_colors", "uv", "vertex_normals", "face_colors", "texcoords"):
        if d.get(name) is not None:
            d[name] = np.asarray(d[name], dtype=np.float64)
    for name in ("face_texcoords", "face_materials", "face_groups", "face_objects"):
        if d.get(name) is not None:
            d[name] = np.asarray(d[name], dtype=np.int32)
    if d.get("vertex_properties"):
        d["vertex_properties"] = {str(k): np.asarray(v, dtype=np.float64).reshape(-1)
                                  for k, v in d["vertex_properties"].items()}
    if d.get("gltf_document") is not None:
        d["gltf_document"] = bytes(d["gltf_document"])
    return list(_core.write_mesh_attributes(path, d, binary))


def repair(V, F, weld=0.0, merge_duplicate_vertices=True, remove_degenerate_faces=True,
           remove_duplicate_faces=True, orient=True, split_non_manifold=False, remove_unreferenced=False):
    """Repairs a messy mesh (see docs/robustness.md): merges duplicate vertices (exact, or closer
    than weld x mean edge length; faces are redirected, the copies stay unreferenced), removes
    faces repeating a vertex, zero-area and duplicate faces, orients each component
    consistently (closed ones outwards), optionally splits non-manifold vertices (copies
    appended) and removes unreferenced vertices (the only option that renumbers vertices).

    Returns a dict: V, F, vertex_map (new index of each input vertex, -1 if removed),
    face_origin (input face of each output face) and report (counts of what was done, and
    'actions', one line per action)."""
    V = _checks.real_matrix(V, "V")
    F = _checks.faces(F, V.shape[0], "F", allow_empty=True, allow_repeated=True)
    o = _core.RepairOptions()
    o.weld_tolerance = _checks.real(weld, "weld", minimum=0.0)
    o.merge_duplicate_vertices = _checks.boolean(merge_duplicate_vertices, "merge_duplicate_vertices")
    o.remove_degenerate_faces = _checks.boolean(remove_degenerate_faces, "remove_degenerate_faces")
    o.remove_duplicate_faces = _checks.boolean(remove_duplicate_faces, "remove_duplicate_faces")
    o.orient = _checks.boolean(orient, "orient")
    o.split_non_manifold = _checks.boolean(split_non_manifold, "split_non_manifold")
    o.remove_unreferenced = _checks.boolean(remove_unreferenced, "remove_unreferenced")
    return _core.repair(V, F, o)


def make_shape(name, resolution):
    """A built-in test shape (see shape_names()) at a resolution level >= 1; returns (V, F)."""
    _checks.choice(name, "name", tuple(_core.shape_names()))
    resolution = _checks.integer(resolution, "resolution", minimum=1)
    return _core.make_shape(name, resolution)


# ---- applications (present when the library was built with them) --------------------------------

if hasattr(_core, "segment"):
    from ._core import MulticutOptions, SegmentOptions

    # Keyword parameters of segment(): the library's table (the segmentation's own and the
    # normal filter's, as the options of `msmesh segment`) plus the multicut's local search.
    SEGMENT_PARAMETERS = _table("segment")
    _MULTICUT_PARAMETERS = {"local_search": bool, "max_local_rounds": int}

    def _denoise_first(V, F, preset, progress, report):
        """The positions `--denoise` of `msmesh segment` / `features` segments: denoise() with
        the preset (NMSTV), recorded in report['V_denoised']."""
        options = _core.preset_options(preset)
        V = _core.denoise(V, F, options, progress)["V"]
        report["V_denoised"] = V
        return V

    def segment(V, F, preset="cad", denoise=False, progress=None, local_search=True, max_local_rounds=50,
                **params):
        """Segments a mesh into piecewise-smooth parts (paper 6.3), as `msmesh segment`:
        Algorithm 1 gives the edge field v, a multicut of the face graph gives the segments.

        preset: 'cad' or 'smooth', the normal filtering parameters (as `--preset`).
        denoise: denoise with the preset first and segment the result (`--denoise`).
        local_search, max_local_rounds: the multicut's local search (on, 50 rounds).
        params: named like the options of `msmesh segment` (SEGMENT_PARAMETERS):
{parameters}

        Returns (labels, report): labels (#F,) int32 in [0, count), segment 0 the largest;
        report has count, areas, objective, multicut_count, normals, v, v_normalized,
        split_probability on report['edges'], iteration counts, seconds, and V_denoised when
        denoise=True.
        """
        V, F = _checks.mesh(V, F)
        _checks.choice(preset, "preset", tuple(_core.preset_names()))
        denoise = _checks.boolean(denoise, "denoise")
        progress = _checks.progress(progress)
        options = SegmentOptions()
        options.normals = _core.preset_options(preset).normals
        _apply_parameters(options, params, SEGMENT_PARAMETERS, "segment")
        options.multicut.local_search = _checks.boolean(local_search, "local_search")
        options.multicut.max_local_rounds = _checks.integer(max_local_rounds, "max_local_rounds", minimum=0)
        options.validate()  # before a denoise=True spends time
        report = {}
        if denoise:
            V = _denoise_first(V, F, preset, progress, report)
        report.update(_core.segment(V, F, options, progress))
        labels = report.pop("labels")
        report["preset"] = preset
        report["parameters"] = dict(_core.parameters(options), local_search=options.multicut.local_search,
                                    max_local_rounds=options.multicut.max_local_rounds)
        return labels, report

    segment.__doc__ = segment.__doc__.replace("{parameters}", _parameter_doc(SEGMENT_PARAMETERS, " " * 12))

    def feature_lines(V, F, v=None, threshold=0.5, min_edges=1, preset="cad", denoise=False, progress=None):
        """Feature lines: chains of the edges whose normalised edge field is below `threshold`
        (in (0, 1]), as `msmesh features`.

        v: the (#E,) edge field of filter_normals() / segment() (edges of report['edges']); None
            computes it with filter_normals(preset=preset), after denoise() when denoise=True.
        Returns a list of int32 arrays of vertex indices (a closed loop repeats its first
        vertex); polylines with fewer than `min_edges` edges are dropped.
        """
        V, F = _checks.mesh(V, F)
        threshold = _checks.real(threshold, "threshold")
        min_edges = _checks.integer(min_edges, "min_edges", minimum=0)
        if v is None:
            _checks.choice(preset, "preset", tuple(_core.preset_names()))
            progress = _checks.progress(progress)
            if _checks.boolean(denoise, "denoise"):
                V = _denoise_first(V, F, preset, progress, {})
            v = _core.filter_normals(V, F, _core.preset_options(preset).normals, np.zeros((0, 3)), progress)["v"]
        else:
            v = _checks.real_vector(v, "v")
        return _core.feature_lines(V, F, v, threshold, min_edges)

    def rand_index(labels_a, labels_b):
        """Rand index of two labellings of the same elements (in [0, 1]; 1 = same partition)."""
        a = _checks.labels(labels_a, "labels_a")
        b = _checks.labels(labels_b, "labels_b")
        return _core.rand_index(a, b)

    __all__ += ["segment", "feature_lines", "rand_index", "SegmentOptions", "MulticutOptions", "SEGMENT_PARAMETERS"]


if hasattr(_core, "inpaint"):
    from ._core import InpaintOptions

    # Every number and switch of InpaintOptions, named like the options of `msmesh inpaint`
    # (the library's table); holes= is the list of hole indices.
    INPAINT_PARAMETERS = _table("inpaint")

    def find_holes(V, F):
        """The boundary loops of a mesh: a list of dicts (loop: vertex indices, edges,
        diameter and length in mean edge lengths, component, outer_boundary, simple)."""
        V, F = _checks.mesh(V, F)
        return _core.find_holes(V, F)

    def inpaint(V, F, holes=None, progress=None, **params):
        """Fills the holes of a mesh and recovers their sharp features (paper 6.2), like
        `msmesh inpaint`.

        holes: None (every hole within the limits, outer boundaries excepted) or indices into
            find_holes().
        params: named like the options of `msmesh inpaint` (INPAINT_PARAMETERS):
{parameters}

        Returns (V_new, F_new, report): input vertices and faces first, then the new ones;
        report has new_faces / new_vertices (bool arrays), holes (one dict per hole with its
        action 'filled'/'skipped'/'failed' and reason), filled/skipped/failed counts, the
        parameters, iteration counts and seconds.
        """
        V, F = _checks.mesh(V, F)
        progress = _checks.progress(progress)
        options = InpaintOptions()
        if holes is not None:
            options.holes = [_checks.integer(h, "holes", minimum=0) for h in np.asarray(holes).ravel().tolist()]
        _apply_parameters(options, params, INPAINT_PARAMETERS, "inpaint")
        report = _core.inpaint(V, F, options, progress)
        report["parameters"] = _core.parameters(options)
        return report.pop("V"), report.pop("F"), report

    inpaint.__doc__ = inpaint.__doc__.replace("{parameters}", _parameter_doc(INPAINT_PARAMETERS, " " * 12))

    def inpaint_errors(V_input, F_input, V_result, F_result, V_truth, F_truth, new_faces=None):
        """Error figures of an inpainting result against a ground truth (distances relative
        to the truth's bounding-box diagonal; see metrics.h). new_faces: (#F_result,) bools, or
        None for the faces beyond the input's."""
        V_input, F_input = _checks.mesh(V_input, F_input, prefix="input ")
        V_result, F_result = _checks.mesh(V_result, F_result, prefix="result ")
        V_truth, F_truth = _checks.mesh(V_truth, F_truth, prefix="truth ")
        if new_faces is None:
            flags = []
        else:
            a = np.asarray(new_faces)
            if a.dtype != np.bool_ or a.shape != (F_result.shape[0],):
                raise InvalidInputError(f"new_faces: must be {F_result.shape[0]} bools, got {a.dtype} {a.shape}")
            flags = a.tolist()
        return _core.inpaint_errors(V_input, F_input, V_result, F_result, flags, V_truth, F_truth)

    def punch_holes(V, F, count, radius, seed=0, on_features=False):
        """Punches `count` holes (geodesic disks of `radius` mean edge lengths, seeded) into a
        mesh, for tests and demos. Returns (V_new, F_new, info) with info vertex_map,
        old_to_new, centers and punched (the number of holes made)."""
        V, F = _checks.mesh(V, F)
        count = _checks.integer(count, "count", minimum=0)
        radius = _checks.real(radius, "radius", minimum=0.0)
        seed = _checks.integer(seed, "seed", minimum=0, maximum=2**53)
        return _core.punch_holes(V, F, count, radius, seed, _checks.boolean(on_features, "on_features"))

    __all__ += ["find_holes", "inpaint", "inpaint_errors", "punch_holes", "InpaintOptions", "INPAINT_PARAMETERS"]

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
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

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

# Type hints: a file name, and anything numpy.asarray accepts (arrays, nested lists).
PathLike = Union[str, "os.PathLike[str]"]
ArrayLike = Any
Progress = Optional[Callable[[ProgressEvent], Optional[bool]]]

__all__ = [
    "denoise", "filter_normals", "update_vertices", "add_noise", "evaluate", "choose_preset", "estimate_noise",
    "taubin_smooth",
    "read_mesh", "write_mesh", "Mesh", "repair", "make_shape", "shape_names", "preset_names", "PARAMETERS",
    "render", "compare", "info", "report", "write_png", "view_names", "up_axis_names", "RENDER_PARAMETERS",
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


def preset_names() -> List[str]:
    """Preset names accepted by denoise(): auto (the default: chosen from the mesh), cad, smooth."""
    return list(_PRESETS)


def shape_names() -> List[str]:
    """Names accepted by make_shape()."""
    return list(_core.shape_names())


def set_threads(n: int) -> None:
    """Threads for the parallel work of every later call, from any Python thread: n >= 1, or 0
    for the default (OMP_NUM_THREADS, else every core). Results are the same for any n.
    Raises InvalidInputError for n < 0 or n > 4096."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise InvalidInputError(f"threads: n must be an integer, got {n!r}")
    if not 0 <= int(n) <= 4096:
        raise InvalidInputError(f"threads: {int(n)} is out of range; valid: 1 to 4096, or 0 for the default")
    _core.set_threads(int(n))


def threads() -> int:
    """The number of threads the next call will use."""
    return _core.threads()


def _apply_parameters(options, params, table, function, solvers=()):
    """Sets keyword parameters on an options object through the library's table (`table`, from
    _table()). Unknown names are a TypeError (as for any Python function); a value of the wrong
    type, out of range, not whole (int) or not a bool is an InvalidInputError naming it.
    `solvers`: the option sets ('normals', 'vertices') that 'solver' sets, if accepted.
    Returns the values set, by name ('solver' aside)."""
    values = {}
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
        values[name] = float(value)
    return values


def _resolve_preset(V, F, preset, report, strength=1.0):
    """DenoiseOptions of a preset name; 'auto' is chosen from the mesh by the library (what it
    saw and why recorded in report)."""
    _checks.choice(preset, "preset", _PRESETS)
    strength = _checks.real(strength, "strength", minimum=_core.MIN_STRENGTH)
    if strength > _core.MAX_STRENGTH:
        raise InvalidInputError(f"strength: must be <= {_core.MAX_STRENGTH}, got {strength}")
    r = _core.resolve_preset(preset, V, F, strength)
    report["preset_requested"] = preset
    report["preset"] = r["preset"]
    report["preset_reason"] = r["reason"]
    if r["automatic"]:
        report["auto_sharp_fraction"] = r["sharp_fraction"]
        report["auto_crease_line_fraction"] = r["crease_line_fraction"]
        report["auto_steep_line_fraction"] = r["steep_line_fraction"]
        report["auto_flat_fraction"] = r["flat_fraction"]
        report["auto_noise_level"] = r["noise_level"]
        for key in (
            "noise_sigma",
            "noise_sigma_rms",
            "noise_outlier_fraction",
            "noise_sigma_noise",
            "noise_detail",
            "noise_across_ratio",
            "noise_level_used",
            "noise_detail_as_noise",
            "noise_detail_ease",
            "noise_despiked",
            "noise_sigma_rms_despiked",
        ):
            report[key] = r[key]
        report["auto_quadric_excess"] = r["quadric_excess"]
        report["auto_featureless_limit"] = r["featureless_limit"]
        report["auto_featureless"] = r["featureless"]
        report["auto_second_round"] = r["second_round"]
    report["strength"] = r["strength"]
    return r["options"]


def estimate_noise(V: ArrayLike, F: ArrayLike) -> Dict[str, Any]:
    """The noise of a mesh, from the mesh alone (include/msmesh/noise_estimate.h).

    Returns a dict: sigma (robust standard deviation of the noise along the normals, in mean
    edge lengths), sigma_rms (RMS of the same residuals; well above sigma under impulsive
    noise), outlier_fraction (vertices beyond 4 sigma), sigma_noise and detail (sigma split
    into the noise alone and the shape's own fine detail and creases, which a low pass also
    removes: sigma**2 = sigma_noise**2 + detail**2), across_ratio (RMS of the residuals across
    the normals over along them: 1.3-1.9 for heavy noise in random directions, mostly below 1
    along the normals) and summary (one line). 'auto' sets its
    parameters from sigma_rms, for organic shapes without their detail (docs/presets.md).
    """
    V, F = _checks.mesh(V, F)
    return _core.estimate_noise(V, F)


def taubin_smooth(V: ArrayLike, F: ArrayLike, iterations: int = 10, lambda_: float = 0.5, mu: float = -0.53) -> np.ndarray:
    """Taubin's lambda|mu smoothing with uniform weights (no shrinkage); returns (#V, 3).

    iterations: lambda|mu pairs (>= 0); lambda_ in (0, 1]; mu in [-1, 0) with |mu| > lambda_.
    The pre-filter of 'auto' under heavy noise. Open3D's filter_smooth_taubin takes the same
    pairs with inverse-distance weights instead, so its results differ.
    """
    V, F = _checks.mesh(V, F)
    iterations = _checks.integer(iterations, "iterations", minimum=0)
    lambda_ = _checks.real(lambda_, "lambda_")
    mu = _checks.real(mu, "mu")
    return _core.taubin_smooth(V, F, iterations, lambda_, mu)


def choose_preset(V: ArrayLike, F: ArrayLike) -> Dict[str, Any]:
    """The preset 'auto' picks for a mesh: dict(preset, sharp_fraction, crease_line_fraction,
    steep_line_fraction, flat_fraction, noise_level, reason)."""
    V, F = _checks.mesh(V, F)
    return _core.choose_preset(V, F)


def denoise(V: ArrayLike, F: ArrayLike, preset: str = DEFAULT_PRESET, method: str = "nmstv", progress: Progress = None,
            strength: float = 1.0, **params: Any) -> Tuple[np.ndarray, Dict[str, Any]]:
    """Denoises a mesh: normal filtering, then vertex updating (F is unchanged).

    V: (#V, 3) positions; F: (#F, 3) triangle indices.
    preset: 'auto' (the default: parameters from the mesh's estimated noise and shape, as
        `msmesh denoise`), 'cad' (sharp features), 'smooth' (organic shapes) or 'paper'
        (Algorithms 1 and 2 with the paper's settings).
    strength: how much to remove, in [0.1, 10]: 1 the default, larger smooths more ('auto'
        scales the estimated noise its rules use; a named preset divides alpha by it).
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
    if method == "bilateral" and strength != 1.0:
        raise InvalidInputError("strength: needs method 'nmstv' or 'mstv' (bilateral has its own parameters)")
    options = _resolve_preset(V, F, "cad" if method == "bilateral" and preset == "auto" else preset, report,
                              strength)
    options.method = _METHODS[method]
    overrides = _apply_parameters(options, params, PARAMETERS, "denoise", solvers=("normals", "vertices"))
    # Auto under heavy noise: a second round on the result, blended in (docs/presets.md).
    result = _core.denoise(V, F, options, progress, report.get("auto_second_round", 0.0), report["strength"],
                           overrides)
    V_new = result.pop("V")
    report["method"] = method
    report["parameters"] = _core.parameters(options)
    report.update(result)
    report["seconds_total"] = report["seconds_normals"] + report["seconds_vertices"]
    return V_new, report


def filter_normals(V: ArrayLike, F: ArrayLike, preset: Optional[str] = None, method: str = "nmstv",
                   normals0: Optional[ArrayLike] = None, progress: Progress = None,
                   **params: Any) -> Tuple[np.ndarray, np.ndarray, Dict[str, Any]]:
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


def update_vertices(V: ArrayLike, F: ArrayLike, N: ArrayLike, v: Optional[ArrayLike] = None, preset: Optional[str] = None,
                    progress: Progress = None, **params: Any) -> Tuple[np.ndarray, Dict[str, Any]]:
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


def add_noise(V: ArrayLike, F: ArrayLike, sigma: float = 0.2, direction: str = "normal", impulsive: float = 0.0,
              seed: int = 0, correlation: int = 0) -> np.ndarray:
    """Seeded noise as in the denoising literature; returns noisy V (#V, 3).

    sigma: standard deviation in units of the mean edge length, in [0, 1e6].
    direction: 'normal' (along vertex normals) or 'random' (uniform directions).
    impulsive: 0 for Gaussian noise on every vertex; in (0, 1] the fraction of vertices hit.
    seed: integer in [0, 2**53]; equal seeds give equal noise on any machine (and equal to
        `msmesh noise --seed`).
    correlation: 0 for white noise; k in [1, 1000] for correlated, long-waved noise like a depth
        camera's (the displacements averaged with their neighbours' k times, then scaled back to
        sigma; `msmesh noise --correlation`). Not with impulsive noise.
    """
    V, F = _checks.mesh(V, F)
    sigma = _checks.real(sigma, "sigma", minimum=0.0)
    _checks.choice(direction, "direction", ("normal", "random"))
    impulsive = _checks.real(impulsive, "impulsive", minimum=0.0)
    seed = _checks.integer(seed, "seed", minimum=0, maximum=2**53)
    correlation = _checks.integer(correlation, "correlation", minimum=0, maximum=1000)
    return _core.add_noise(V, F, sigma, direction, impulsive, seed, correlation)


def evaluate(V: ArrayLike, F: ArrayLike, V_truth: ArrayLike, F_truth: ArrayLike) -> Dict[str, Any]:
    """Error figures of a result (V, F) against a ground truth (as `msmesh eval`).

    Returns a dict: same_connectivity; msae (radians^2), msae_e3 (= msae x 1e3, as printed in
    the papers), mean_angle_deg, flipped (faces off by > 90 deg), angle_rad (#F),
    truth_folded (faces the truth folds against their neighbours: a sliver turned over, a
    zig-zag), flipped_outside_folds and msae_outside_folds_e3 (the same without those) -- these
    are None unless the connectivity is the same; distance_mean, distance_rms, distance_max,
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


def repair(V: ArrayLike, F: ArrayLike, weld: float = 0.0, merge_duplicate_vertices: bool = True,
           remove_degenerate_faces: bool = True, remove_duplicate_faces: bool = True, orient: bool = True,
           split_non_manifold: bool = False, remove_unreferenced: bool = False) -> Dict[str, Any]:
    """Repairs a messy mesh, as `msmesh repair` (same defaults; see docs/robustness.md).

    Parameters
    ----------
    V : array_like
        (#V, 3) vertex positions.
    F : array_like
        (#F, 3) triangle indices; faces repeating a vertex are accepted (and removed).
    weld : float
        Merge vertices closer than weld x the mean edge length (0: exact duplicates only); faces
        are redirected to the first copy, the copies stay unreferenced (``--weld``).
    merge_duplicate_vertices, remove_degenerate_faces, remove_duplicate_faces, orient : bool
        The repairs done by default: merge duplicates, remove faces repeating a vertex or of
        zero area, remove duplicate faces, orient each component consistently (closed ones
        outwards).
    split_non_manifold : bool
        Give each fan around a non-manifold vertex its own copy (appended), as
        ``--split-non-manifold``.
    remove_unreferenced : bool
        Remove vertices no face uses (the only option that renumbers vertices).

    Returns
    -------
    dict
        V, F, vertex_map (new index of each input vertex, -1 if removed), face_origin (input
        face of each output face) and report (counts of what was done, and 'actions', one line
        per action).
    """
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


def make_shape(name: str, resolution: int) -> Tuple[np.ndarray, np.ndarray]:
    """A built-in test shape (see shape_names()) at a resolution level >= 1; returns (V, F)."""
    _checks.choice(name, "name", tuple(_core.shape_names()))
    resolution = _checks.integer(resolution, "resolution", minimum=1)
    return _core.make_shape(name, resolution)


# ---- pictures and figures (msmesh_draw, mesh_statistics.h) ---------------------------------------

# Keyword parameters of render() and compare(): the library's render table (render.h), named
# like the options of `msmesh render` ('-' -> '_'): width, height, supersample, fov, margin,
# ambient, diffuse, line_width, azimuth, elevation.
RENDER_PARAMETERS = _table("render")
_RENDER_COLORS = ("auto", "none", "file", "error", "field", "labels")


def view_names() -> List[str]:
    """The named views of render() and compare(): iso, front, back, left, right, top, bottom."""
    return list(_core.view_names())


def up_axis_names() -> List[str]:
    """The up axes of render() and compare(): x, -x, y, -y, z, -z."""
    return list(_core.up_axis_names())


def _render_options(view, up, perspective, params, function, defaults=None):
    """RenderOptions of the keywords, checked as the CLI checks its options."""
    o = _core.RenderOptions()
    _checks.choice(view, "view", tuple(_core.view_names()))
    up = _checks.choice(up, "up", tuple(_core.up_axis_names()) + tuple("+" + a for a in "xyz"))
    o.view = view
    o.up = up
    o.perspective = _checks.boolean(perspective, "perspective")
    _apply_parameters(o, dict(defaults or {}, **params), RENDER_PARAMETERS, function)
    o.validate()
    return o


def _degrees(value, name, maximum, maximum_open=False):
    value = _checks.real(value, name, minimum=0.0)
    if value > maximum or (maximum_open and value == maximum):
        raise InvalidInputError(f"{name}: must be in [0, {maximum:g}{')' if maximum_open else ']'} degrees, "
                                f"got {value:g}")
    return value


def write_png(path: PathLike, image: ArrayLike) -> None:
    """Writes an RGB image as a PNG file, atomically (the file appears completely or not at all).

    Parameters
    ----------
    path : str or os.PathLike
        The .png file to write.
    image : numpy.ndarray
        (height, width, 3) uint8 array, as render() and compare() return.

    Raises
    ------
    IoError
        When the file cannot be written.
    """
    _core.write_png(_checks.path(path), _checks.image(image))


def render(V: ArrayLike, F: ArrayLike, path: Optional[PathLike] = None, *, view: str = "iso", up: str = "y",
           perspective: bool = False, color: str = "auto", vertex_colors: Optional[ArrayLike] = None,
           truth: Optional[Tuple[ArrayLike, ArrayLike]] = None, v: Optional[ArrayLike] = None,
           labels: Optional[ArrayLike] = None, feature_edges: float = 0.0, error_max: float = 0.0,
           **params: float) -> np.ndarray:
    """Renders a mesh to an RGB picture, as `msmesh render` (same options, same defaults).

    Parameters
    ----------
    V : array_like
        (#V, 3) vertex positions.
    F : array_like
        (#F, 3) triangle indices.
    path : str or os.PathLike, optional
        Also write the picture to this .png file (atomically).
    view : str
        One of view_names(): iso (default), front, back, left, right, top, bottom.
    up : str
        The world axis shown upwards: 'y' (default; front looks from +z), 'z' (CAD and STL;
        front looks from -y), 'x', or '-x', '-y', '-z' (upside down). See docs/rendering.md.
    perspective : bool
        Perspective camera instead of orthographic.
    color : str
        'auto' (default: vertex_colors when given, else grey), 'none', 'file' (vertex_colors),
        'error' (angle to ``truth`` per face, with a colour bar), 'field' (edge field ``v`` on
        the edges, with a colour bar), 'labels' (one colour per segment of ``labels``).
    vertex_colors : array_like, optional
        (#V, 3) RGB in [0, 1], e.g. the colours of a scan.
    truth : (V, F) pair, optional
        Ground truth with the same faces, for color='error'.
    v : array_like, optional
        (#E,) edge field (filter_normals, segment) on the edges of build order, for color='field'.
    labels : array_like, optional
        (#F,) segment labels, for color='labels'.
    feature_edges : float
        Draw edges sharper than this dihedral angle (degrees, [0, 180)) as thin dark lines; 0: off.
    error_max : float
        Top of the error colour scale in degrees ([0, 180]); 0: the 98th percentile, rounded up.
    **params
        The render parameters (RENDER_PARAMETERS, as `msmesh render`'s options):
{parameters}
        line_width defaults to 2.5 for color='field' and 'labels', as in the CLI.

    Returns
    -------
    numpy.ndarray
        (height, width, 3) uint8 RGB; a colour bar adds a strip below the picture.

    Raises
    ------
    InvalidInputError
        For a bad argument (named), or colour data missing for the colour mode.
    IoError
        When ``path`` cannot be written.
    """
    V, F = _checks.mesh(V, F)
    color = _checks.choice(color, "color", _RENDER_COLORS)
    colors = _checks.colors(vertex_colors, V.shape[0])
    if color == "file" and colors is None:
        raise InvalidInputError("vertex_colors: color='file' needs vertex_colors")
    Vt, Ft = np.zeros((0, 3)), np.zeros((0, 3), np.int32)
    if truth is not None:
        Vt, Ft = _checks.mesh_pair(truth, "truth")
    elif color == "error":
        raise InvalidInputError("truth: color='error' needs truth=(V, F)")
    field = np.zeros(0)
    if v is not None:
        field = _checks.real_vector(v, "v")
    elif color == "field":
        raise InvalidInputError("v: color='field' needs the edge field v")
    segments = np.zeros(0, np.int32)
    if labels is not None:
        segments = _checks.labels(labels, "labels")
    elif color == "labels":
        raise InvalidInputError("labels: color='labels' needs labels")
    feature_edges = _degrees(feature_edges, "feature_edges", 180.0, maximum_open=True)
    error_max = _degrees(error_max, "error_max", 180.0)
    defaults = {"line_width": 2.5} if color in ("field", "labels") else {}
    options = _render_options(view, up, perspective, params, "render", defaults)
    out_path = None if path is None else _checks.path(path)
    image, _summary = _core.render(V, F, options, color, np.zeros((0, 3)) if colors is None else colors, Vt, Ft,
                                   field, segments, feature_edges, error_max)
    if out_path is not None:
        _core.write_png(out_path, image)
    return image


def compare(meshes: Sequence[Tuple[ArrayLike, ...]], path: Optional[PathLike] = None, *,
            captions: Optional[Sequence[str]] = None, truth: Optional[Tuple[ArrayLike, ArrayLike]] = None,
            color: str = "auto", noisy_panel: Union[str, int, None] = "auto", view: str = "iso", up: str = "y",
            perspective: bool = False, feature_edges: float = 0.0, error_max: float = 0.0, title: str = "",
            **params: float) -> Tuple[np.ndarray, Dict[str, Any]]:
    """Several meshes side by side from the same camera, as `msmesh compare` (same defaults).

    Parameters
    ----------
    meshes : sequence of (V, F) or (V, F, vertex_colors)
        The panels, left to right.
    path : str or os.PathLike, optional
        Also write the sheet to this .png file (atomically).
    captions : sequence of str, optional
        One per mesh; default "mesh 1", "mesh 2", ...
    truth : (V, F) pair, optional
        Ground truth: MSAE (x1e-3) and mean angle under each panel, and color='error'.
    color : str
        'auto' (default: a panel's vertex colours when it has them, else grey), 'none', 'file',
        or 'error' (angle to the truth per face, one scale for all panels).
    noisy_panel : 'auto', int or None
        The panel (0-based) holding the noisy input, which the automatic error scale leaves out
        so that the results are not washed out (its larger errors saturate and the legend says
        so). 'auto' (default): the panel whose mean angle error is at least twice every other
        panel's, if any. None: no panel.
    view, up, perspective
        The camera, as for render().
    feature_edges : float
        Draw edges sharper than this angle (degrees, [0, 180)) dark; 0: off.
    error_max : float
        Top of the error colour scale in degrees; 0 (default): from the results.
    title : str
        A line above the panels.
    **params
        The render parameters of each panel (RENDER_PARAMETERS); width and height default to
        400 (kComparePanelSize of compare_sheet.h), as `msmesh compare --size`.

    Returns
    -------
    image : numpy.ndarray
        (height, width, 3) uint8 RGB sheet.
    report : dict
        'panels' (per panel with a truth: same_connectivity, msae_e3, mean_angle_deg, flipped,
        distance_rms), 'error_top' (top of the error scale, degrees), 'noisy_panel' (index or
        None), 'saturated', 'scale_note'.
    """
    if isinstance(meshes, (str, bytes)) or not hasattr(meshes, "__len__") or len(meshes) == 0:
        raise InvalidInputError("meshes: must be a non-empty sequence of (V, F) or (V, F, vertex_colors)")
    if captions is not None:
        if isinstance(captions, str) or len(captions) != len(meshes):
            raise InvalidInputError(f"captions: must be {len(meshes)} strings, one per mesh")
        if not all(isinstance(c, str) for c in captions):
            raise InvalidInputError("captions: must be strings")
    panels = []
    for i, m in enumerate(meshes):
        if not isinstance(m, (tuple, list)) or len(m) not in (2, 3):
            raise InvalidInputError(f"meshes[{i}]: must be (V, F) or (V, F, vertex_colors)")
        V, F = _checks.mesh(m[0], m[1], prefix=f"meshes[{i}] ")
        colors = _checks.colors(m[2] if len(m) == 3 else None, V.shape[0], f"meshes[{i}] vertex_colors")
        caption = captions[i] if captions is not None else f"mesh {i + 1}"
        panels.append(_core.ComparePanel(V, F, np.zeros((0, 3)) if colors is None else colors, caption))
    Vt, Ft = np.zeros((0, 3)), np.zeros((0, 3), np.int32)
    if truth is not None:
        Vt, Ft = _checks.mesh_pair(truth, "truth")
    o = _core.CompareOptions()
    o.color = _checks.choice(color, "color", tuple(_core.sheet_color_names()))
    if o.color == "error" and truth is None:
        raise InvalidInputError("truth: color='error' needs truth=(V, F)")
    if isinstance(noisy_panel, str) and noisy_panel == "auto":
        o.noisy_panel = _core.NOISY_PANEL_AUTO
    elif noisy_panel is None:
        o.noisy_panel = _core.NO_NOISY_PANEL
    else:
        o.noisy_panel = _checks.integer(noisy_panel, "noisy_panel", minimum=0, maximum=len(meshes) - 1)
    o.feature_angle = _degrees(feature_edges, "feature_edges", 180.0, maximum_open=True)
    o.error_max = _degrees(error_max, "error_max", 180.0)
    if not isinstance(title, str):
        raise InvalidInputError(f"title: must be a str, got {type(title).__name__}")
    o.title = title
    panel = _core.parameters(_core.CompareOptions().render)  # the panel size of `msmesh compare --size`
    o.render = _render_options(view, up, perspective, params, "compare",
                               {"width": panel["width"], "height": panel["height"]})
    out_path = None if path is None else _checks.path(path)
    report = _core.compare(panels, Vt, Ft, o)
    image = report.pop("image")
    if out_path is not None:
        _core.write_png(out_path, image)
    return image, report


def info(V: ArrayLike, F: ArrayLike) -> Dict[str, Any]:
    """Counts, defects, size, area, volume, watertightness and genus of a mesh.

    The same fields, with the same values, as `msmesh info --json` gives for a file holding
    (V, F), less those about the file itself (file, dropped_degenerate_faces, vertex_colors,
    texture_coordinates, texture_coordinates_with_seams, vertex_normals).

    Parameters
    ----------
    V : array_like
        (#V, 3) vertex positions.
    F : array_like
        (#F, 3) triangle indices (may be empty).

    Returns
    -------
    dict
        vertices, faces, edges, boundary_edges, boundary_loops, largest_boundary_loops (up to
        5 sizes), non_manifold_edges, non_manifold_vertices, unreferenced_vertices,
        inconsistently_oriented_edges, components, mean_edge_length, bbox_min, bbox_max,
        bbox_diagonal; area; volume (sum over the closed components, signed: negative when
        the faces point inwards; None when no component is closed); closed_components;
        watertight (every edge has two faces walking it in opposite directions);
        euler_characteristic (V - E + F); genus (sum over the components of
        (2 - chi - boundary loops) / 2; None when a component is non-manifold or
        non-orientable); component_details (up to 20 dicts: faces, vertices, edges, area,
        closed, manifold, orientable, consistently_oriented, volume, euler_characteristic,
        boundary_loops, genus).
    """
    V = _checks.real_matrix(V, "V")
    F = _checks.faces(F, V.shape[0], "F", allow_empty=True)
    return _core.info(V, F)


render.__doc__ = render.__doc__.replace("{parameters}", _parameter_doc(RENDER_PARAMETERS, " " * 12))


def _report_number(x):
    """A figure as the CLI's reports print it (4 significant digits, '-' when missing)."""
    return "-" if x is None or not np.isfinite(x) else f"{x:.4g}"


def _report_parameters(parameters):
    """The report's parameter rows of a run's 'parameters' dict, described from the library's
    tables as the CLI describes them: 'name (symbol): help' -> 'value unit'."""
    tables = [PARAMETERS] + [globals()[t] for t in ("SEGMENT_PARAMETERS", "INPAINT_PARAMETERS") if t in globals()]
    rows = []
    for name, value in parameters.items():
        entry = next((t[name] for t in tables if name in t), None)
        if isinstance(value, (bool, np.bool_)):
            shown = "yes" if value else "no"
        elif isinstance(value, float):
            shown = repr(value) if value != int(value) or abs(value) >= 1e15 else str(int(value))
        else:
            shown = str(value)
        if entry is None:
            rows.append((name, shown))
            continue
        if entry.get("unit"):
            shown += " " + entry["unit"]
        option = entry["option"][2:]
        rows.append((f"{option}{' (' + entry['symbol'] + ')' if entry.get('symbol') else ''}: {entry['help']}", shown))
    return rows


def _report_plots(run):
    """The convergence plots of a run report (denoise, filter_normals, segment, inpaint), as the
    CLI's --report draws them."""
    plots = []
    residual, change = run.get("residual_history"), run.get("normal_change_history")
    if residual or change:
        plots.append(("Normal filtering (Algorithm 1)", "mean-edge units", True,
                      [("residual |p - grad N|_V", list(map(float, residual or []))),
                       ("change |N(k+1) - N(k)|_U", list(map(float, change or [])))]))
    if run.get("energy_history"):
        plots.append(("Energy (15) per iteration", "energy", False,
                      [("energy", list(map(float, run["energy_history"])))]))
    if run.get("vertex_change_history"):
        plots.append(("Vertex update (Algorithm 2)", "RMS vertex move", True,
                      [("RMS vertex move (mean edges)", list(map(float, run["vertex_change_history"])))]))
    return plots


def report(path: Optional[PathLike], meshes: Sequence[Union[Tuple[str, ArrayLike, ArrayLike], Dict[str, Any]]], *,
           truth: Optional[Tuple[ArrayLike, ArrayLike]] = None, run: Optional[Dict[str, Any]] = None,
           title: str = "msmesh report", subtitle: str = "", notes: Sequence[str] = (),
           initial_mesh: Optional[int] = None) -> Optional[str]:
    """Writes the self-contained HTML report of the CLI's ``--report`` for meshes from Python.

    One page, nothing loaded from elsewhere when viewed: an interactive 3D viewer (three.js,
    embedded) of the meshes with the colour modes shaded / angle error / edge field / segments,
    the error figures against a truth, the parameters and the convergence plots of a run.

    Parameters
    ----------
    path : str or os.PathLike or None
        The .html file (written atomically); None returns the page as a string instead.
    meshes : sequence
        The viewer's meshes, each ``(name, V, F)`` or a dict with keys name, V, F and optionally
        v (the (#E,) edge field of denoise/filter_normals/segment), labels ((#F,) segment
        labels) and highlighted ((#F,) bools, drawn tinted, e.g. inpaint's new_faces).
    truth : (V, F) pair, optional
        Ground truth: added to the viewer as 'truth', per-face angle errors for every mesh with
        its faces, and a table of MSAE (x1e-3), mean angle, flipped faces and distances.
    run : dict, optional
        The report of denoise(), filter_normals(), update_vertices(), segment() or inpaint():
        its 'parameters' fill the parameter table and its histories the convergence plots.
    title, subtitle : str
        The page's heading.
    notes : sequence of str
        Paragraphs under the tables.
    initial_mesh : int, optional
        The mesh shown first (index into ``meshes``); default the last one (the result, when
        the meshes are input then result, as in the CLI's denoise report).

    Returns
    -------
    str or None
        The page when ``path`` is None.

    Examples
    --------
    >>> V_new, run = msmesh.denoise(noisy, F)                       # doctest: +SKIP
    >>> msmesh.report("r.html", [("input", noisy, F), dict(name="result", V=V_new, F=F, v=run["v"])],
    ...               truth=(V, F), run=run, title="denoise")      # doctest: +SKIP
    """
    if isinstance(meshes, (str, bytes)) or not hasattr(meshes, "__len__"):
        raise InvalidInputError("meshes: must be a sequence of (name, V, F) or dicts")
    for name, value in (("title", title), ("subtitle", subtitle)):
        if not isinstance(value, str):
            raise InvalidInputError(f"{name}: must be a str, got {type(value).__name__}")
    if isinstance(notes, str) or not all(isinstance(n, str) for n in notes):
        raise InvalidInputError("notes: must be a sequence of str")
    if run is not None and not isinstance(run, dict):
        raise InvalidInputError(f"run: must be the report dict of a msmesh call, got {type(run).__name__}")
    viewer = []
    for i, m in enumerate(meshes):
        if isinstance(m, dict):
            unknown = set(m) - {"name", "V", "F", "v", "labels", "highlighted"}
            if unknown:
                raise InvalidInputError(f"meshes[{i}]: unknown keys {sorted(unknown)}; valid: name, V, F, v, labels, "
                                        "highlighted")
            if "V" not in m or "F" not in m:
                raise InvalidInputError(f"meshes[{i}]: needs V and F")
            item = dict(m)
        elif isinstance(m, (tuple, list)) and len(m) == 3:
            item = {"name": m[0], "V": m[1], "F": m[2]}
        else:
            raise InvalidInputError(f"meshes[{i}]: must be (name, V, F) or a dict")
        name = item.get("name", f"mesh {i + 1}")
        if not isinstance(name, str):
            raise InvalidInputError(f"meshes[{i}] name: must be a str")
        V, F = _checks.mesh(item["V"], item["F"], prefix=f"meshes[{i}] ")
        entry = {"name": name, "V": V, "F": F}
        if item.get("v") is not None:
            entry["edge_field"] = _checks.real_vector(item["v"], f"meshes[{i}] v")
        if item.get("labels") is not None:
            entry["face_labels"] = _checks.labels(item["labels"], f"meshes[{i}] labels")
        if item.get("highlighted") is not None:
            flags = np.asarray(item["highlighted"])
            if flags.dtype != np.bool_ or flags.shape != (F.shape[0],):
                raise InvalidInputError(f"meshes[{i}] highlighted: must be {F.shape[0]} bools, got {flags.dtype} "
                                        f"{flags.shape}")
            entry["highlighted_faces"] = flags.tolist()
        viewer.append(entry)
    if initial_mesh is None:
        initial_mesh = max(0, len(viewer) - 1)
    initial_mesh = _checks.integer(initial_mesh, "initial_mesh", minimum=0, maximum=max(0, len(viewer) - 1))
    tables, page_notes = [], []
    if truth is not None:
        Vt, Ft = _checks.mesh_pair(truth, "truth")
        rows = []
        for entry in viewer:
            e = _core.evaluate(entry["V"], entry["F"], Vt, Ft)
            same = e["same_connectivity"]
            if same:
                entry["face_error_deg"] = np.degrees(e["angle_rad"])
            rows.append([entry["name"], _report_number(e["msae_e3"]) if same else "-",
                         _report_number(e["mean_angle_deg"]) if same else "-", str(e["flipped"]) if same else "-",
                         _report_number(e["distance_mean"] * 1e3), _report_number(e["distance_rms"] * 1e3),
                         _report_number(e["distance_max"] * 1e3)])
        viewer.append({"name": "truth", "V": Vt, "F": Ft})
        tables.append(("Error against the ground truth",
                       ["mesh", "MSAE (x1e-3)", "mean angle (deg)", "flipped faces", "dist. mean (x1e-3)",
                        "dist. RMS (x1e-3)", "dist. max (x1e-3)"], rows))
        page_notes.append("MSAE: mean over faces of the squared angle (radians) between result and truth face "
                          "normals, printed x1e-3 as in the paper; mean angle: the plain mean angle in degrees. "
                          "Distances: vertex to truth surface over the truth's bounding-box diagonal.")
    shown = viewer[initial_mesh] if viewer else {}
    # As the CLI's reports: errors when there are, else segments, else the edge field.
    initial_color = ("error" if "face_error_deg" in shown else "labels" if "face_labels" in shown
                     else "field" if "edge_field" in shown else "shaded")
    parameters = _report_parameters(run.get("parameters", {})) if run else []
    plots = _report_plots(run) if run else []
    args = (viewer, title, subtitle, initial_mesh, initial_color, parameters, tables, plots,
            page_notes + list(notes))
    if path is None:
        return _core.report_html(*args)
    _core.write_report(_checks.path(path), *args)
    return None


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

    def segment(V: ArrayLike, F: ArrayLike, preset: str = "cad", denoise: bool = False, progress: Progress = None,
                local_search: bool = True, max_local_rounds: int = 50, **params: Any) -> Tuple[np.ndarray, Dict[str, Any]]:
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

    def feature_lines(V: ArrayLike, F: ArrayLike, v: Optional[ArrayLike] = None, threshold: float = 0.5,
                      min_edges: int = 1, preset: str = "cad", denoise: bool = False,
                      progress: Progress = None) -> List[np.ndarray]:
        """Feature lines, as `msmesh features` (same defaults): chains of the edges whose
        normalised edge field is below ``threshold``.

        Parameters
        ----------
        V : array_like
            (#V, 3) vertex positions.
        F : array_like
            (#F, 3) triangle indices.
        v : array_like, optional
            The (#E,) edge field of filter_normals() / segment() (on report['edges']); None
            computes it with filter_normals(preset=preset), after denoise() when denoise=True.
        threshold : float
            In (0, 1]: edges whose normalised field is below it are features (``--threshold``).
        min_edges : int
            Polylines with fewer edges are dropped (``--min-edges``).
        preset : str
            'cad' or 'smooth': the normal filtering parameters when v is None.
        denoise : bool
            Denoise first (``--denoise``), when v is None.
        progress : callable, optional
            As for denoise().

        Returns
        -------
        list of numpy.ndarray
            int32 arrays of vertex indices, one per polyline; a closed loop repeats its first
            vertex.
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

    def rand_index(labels_a: ArrayLike, labels_b: ArrayLike) -> float:
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

    def find_holes(V: ArrayLike, F: ArrayLike) -> List[Dict[str, Any]]:
        """The boundary loops of a mesh: a list of dicts (loop: vertex indices, edges,
        diameter and length in mean edge lengths, component, outer_boundary, simple)."""
        V, F = _checks.mesh(V, F)
        return _core.find_holes(V, F)

    def inpaint(V: ArrayLike, F: ArrayLike, holes: Optional[Sequence[int]] = None, progress: Progress = None,
                **params: Any) -> Tuple[np.ndarray, np.ndarray, Dict[str, Any]]:
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

    def inpaint_errors(V_input: ArrayLike, F_input: ArrayLike, V_result: ArrayLike, F_result: ArrayLike,
                       V_truth: ArrayLike, F_truth: ArrayLike, new_faces: Optional[ArrayLike] = None) -> Dict[str, Any]:
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

    def punch_holes(V: ArrayLike, F: ArrayLike, count: int, radius: float, seed: int = 0,
                    on_features: bool = False) -> Tuple[np.ndarray, np.ndarray, Dict[str, Any]]:
        """Punches `count` holes (geodesic disks of `radius` mean edge lengths, seeded) into a
        mesh, for tests and demos. Returns (V_new, F_new, info) with info vertex_map,
        old_to_new, centers and punched (the number of holes made)."""
        V, F = _checks.mesh(V, F)
        count = _checks.integer(count, "count", minimum=0)
        radius = _checks.real(radius, "radius", minimum=0.0)
        seed = _checks.integer(seed, "seed", minimum=0, maximum=2**53)
        return _core.punch_holes(V, F, count, radius, seed, _checks.boolean(on_features, "on_features"))

    __all__ += ["find_holes", "inpaint", "inpaint_errors", "punch_holes", "InpaintOptions", "INPAINT_PARAMETERS"]

"""akvf: flip-free minimization of mesh distortion energies (Claici et al. 2017).

Parameterize a disk-topology triangle mesh or deform a tet mesh with any
energy and preconditioner of the C++ library, from NumPy arrays::

    import akvf
    V, F = akvf.read_mesh("horse.obj")
    result = akvf.parameterize(V, F)          # AKVF, symmetric Dirichlet
    result.uv, result.status, result.trace["energy"]

Every option of ``akvf param`` / ``akvf deform`` is a keyword argument named
by its key in the options schema (``akvf.options("parameterize")`` lists them,
docs/options.md documents them). The GIL is released while optimizing, and
Ctrl-C stops a run within one iteration with KeyboardInterrupt.

The module is built for Debian's interpreter, /usr/bin/python3 (docs/python.md).
"""

import sys as _sys

try:
    import numpy as _np
except ImportError as _error:  # the interpreter on the PATH may not be Debian's
    raise ImportError(
        "akvf needs NumPy, which this interpreter (%s, Python %s) does not have. "
        "akvf is built for Debian's /usr/bin/python3 with python3-numpy (bash scripts/setup.sh "
        "installs it): run /usr/bin/python3 instead." % (_sys.executable, _sys.version.split()[0])
    ) from _error

from . import _akvf
from ._akvf import (  # noqa: F401  (the exceptions are part of the API)
    Error,
    InputError,
    NumericalError,
    OptionsError,
    OutputError,
    ValidationError,
)

__version__ = _akvf.__version__
__all__ = [
    "parameterize", "Parameterizer", "deform", "Deformer", "read_mesh", "write_mesh", "write_obj", "write_view",
    "write_layout", "view_available", "energies", "preconditioners",
    "line_searches", "solvers", "options", "load_extension", "Result", "Error", "InputError", "ValidationError",
    "OptionsError", "NumericalError", "OutputError", "__version__",
]


class Result:
    """What a run did.

    Attributes: ``uv`` (parameterize: (n, 2) float64, at the input's scale) or
    ``x`` (deform: (n, 3)); ``status`` (as the command line prints it:
    "converged", "max-iterations", "time-limit", "user-stopped", ...);
    ``message``; ``iterations``; ``energy`` and ``grad_norm`` at the end;
    ``trace`` (a dict of NumPy arrays with the trace CSV's columns, row 0 =
    the start); ``statistics`` (the preconditioner's work: factorizations,
    reused_solves, cg_solves, cg_iterations, symbolic_analyses,
    multigrid_setups, and seconds per phase); ``preconditioner_report``;
    ``warnings``; parameterize only: ``initial_map`` (the start taken:
    "tutte", "cotan", "conformal", "boundary-first", or "file" for ``uv0``), ``boundary_crossings`` and
    ``overlap_fraction`` (the final map's self-overlap per chart, 0 with
    injectivity="global") and ``distortion_energy`` (the energy of ``uv``:
    ``energy`` less the boundary barrier that holds it off an overlap);
    with a cut ``packing_splits`` (straight cuts that split charts for the
    packing, ``min_coverage``); with cut="seams" also ``seams_added``,
    ``seam_length`` (over the square root of the area), ``chart_distortion``
    (each chart's symmetric Dirichlet energy), ``distortion_bounded``,
    ``seam_stop_reason``, ``overlap_pieces`` and ``parted_charts`` (charts
    added where the flip-free map lay over itself, or parted in two to meet
    the bound).
    """

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __repr__(self):
        return "akvf.Result(status=%r, iterations=%d, energy=%.10g, grad_norm=%.3e)" % (
            self.status, self.iterations, self.energy, self.grad_norm)


def _warn(messages):
    import warnings
    for message in messages:
        warnings.warn(message, stacklevel=3)


def parameterize(V, F, *, uv0=None, callback=None, **options):
    """Parameterize a disk-topology triangle mesh; returns a Result with ``uv``
    and ``uv_faces`` (the row of uv each face corner uses: F itself, unless
    cut="auto" cut a closed, multi-boundary, higher-genus or multi-component
    mesh into charts; then uv has one row per vertex of the cut mesh).

    V: (n, 3) reals; F: (m, 3) integers (any integer dtype), 0-based.
    uv0: an (n, 2) start map instead of the initial map (must not invert a
    triangle). callback(row, uv): called after every iteration (row 0 = the
    start) with the trace row as a dict and the current map (n, 2) at the
    input's scale; returning False stops the run ("user-stopped").
    options: every option of ``akvf param`` by key (see below).
    """
    result = Result(_akvf.parameterize(V, F, uv0, callback, options))
    _warn(result.warnings)
    return result


class Parameterizer:
    """Repeated solves on one mesh: validation, normalization, the initial map
    and the symbolic analysis are done once.

        solver = akvf.Parameterizer(V, F, precond="newton")
        a = solver.solve()
        solver.set_options(energy="arap")     # changes these keys, keeps the others
        b = solver.solve(uv0=a.uv)

    Each solve gives the bits akvf.parameterize gives for the same options
    and start. Keyword options as for parameterize.
    """

    def __init__(self, V, F, **options):
        self._options = dict(options)
        self._solver = _akvf.Parameterizer(V, F, self._options)

    def solve(self, *, uv0=None, callback=None):
        """A Result from the initial map, or from uv0 ((n, 2), any scale and placement)."""
        result = Result(self._solver.solve(uv0, callback))
        _warn(result.warnings)
        return result

    def set_options(self, **options):
        """Change the given options for the next solves; the initial map is
        recomputed only when one of the options whose ``recomputes_start`` is
        True in ``akvf.options()`` changes (marked (*) in docs/options.md)."""
        merged = dict(self._options, **options)
        self._solver.set_options(merged)
        self._options = merged

    @property
    def options(self):
        """The options set so far (keys not set have their defaults)."""
        return dict(self._options)

    @property
    def initial_uv(self):
        """The initial map, (n, 2) at the input's scale."""
        return self._solver.initial_uv()


def deform(V, T, constraints, *, callback=None, **options):
    """Deform a tet mesh with positional constraints; returns a Result with ``x``.

    V: (n, 3) reals; T: (m, 4) integers, 0-based. constraints: (indices,
    targets), indices a 1-D integer array into V, targets (len(indices), 3).
    callback(row, x) as for parameterize, x (n, 3).
    options: every option of ``akvf deform`` by key (see below).
    """
    indices, targets = constraints
    result = Result(_akvf.deform(V, T, indices, targets, callback, options))
    _warn(result.warnings)
    return result


class Deformer:
    """Repeated deformations of one tet mesh: the mesh is checked and its
    rest shape computed once, and every solve after the first reuses the
    symbolic analyses of the factored preconditioners (result.statistics
    ["symbolic_analyses"] is 0 from the second solve on with the same options).

        d = akvf.Deformer(V, T)
        r1 = d.solve((indices, targets1))
        r2 = d.solve((indices, targets2), max_iters=50)
    """

    def __init__(self, V, T):
        self._solver = _akvf.Deformer(V, T)

    def solve(self, constraints, *, callback=None, **options):
        """deform() on this mesh: constraints, callback and options as there."""
        indices, targets = constraints
        result = Result(self._solver.solve(indices, targets, callback, options))
        _warn(result.warnings)
        return result


def read_mesh(path, kind=None):
    """(V, F) of a triangle mesh (.obj, .off, .ply, .stl) or (V, T) of a tet mesh (.mesh, .msh, .tet).

    kind: "triangles" or "tets"; by default from the extension (.obj is read
    as triangles: pass kind="tets" for a tet OBJ). Errors name the file and line.
    """
    import os
    path = os.fspath(path)
    if kind is None:
        kind = "tets" if path.lower().endswith((".mesh", ".msh", ".tet")) else "triangles"
    V, elements, warnings = _akvf.read_mesh(path, kind)
    _warn(warnings)
    return V, elements


def write_mesh(path, V, F, uv, uv_faces=None, *, texture="checker"):
    """Write the mesh with its map; the format from the extension: .obj, .ply or .glb.

    uv: (n, 2) per vertex, or per corner with uv_faces (a Result's uv and
    uv_faces). An OBJ with texture="checker" gets PATH.mtl and the
    checkerboard PATH_checker.png beside it and vt scaled into the unit
    square; texture="none" writes vt as given. A GLB embeds the checkerboard;
    a PLY has s, t as given. Written atomically, as the command line does.
    Returns the factor of the unit-square coordinates written, or 0.
    """
    import os
    return _akvf.write_mesh(os.fspath(path), V, F, uv, uv_faces, texture)


def write_obj(path, V, F, uv, uv_faces=None):
    """write_mesh(path, V, F, uv, uv_faces, texture="none") for an .obj path."""
    import os
    path = os.fspath(path)
    if not path.lower().endswith(".obj"):
        raise OptionsError("write_obj writes .obj files, found " + path + " (write_mesh chooses by extension)")
    write_mesh(path, V, F, uv, uv_faces, texture="none")


def write_view(path, V, F, uv, uv_faces=None, summary=None, *, title=""):
    """Write the self-contained HTML view of the map: the checkerboard on the
    surface, the layout, colouring by distortion, and the summary (a dict or
    JSON text, as a Result's or ``akvf param --summary``'s). Returns the
    number of faces shown (meshes beyond 500 000 faces are decimated)."""
    import json
    import os
    if summary is None:
        text = ""
    elif isinstance(summary, str):
        text = summary
    else:
        text = json.dumps(summary, default=_json_default)
    return _akvf.write_view(os.fspath(path), V, F, uv, uv_faces, title, text)


def write_layout(path, V, F, uv, uv_faces=None, *, size=1024, title=""):
    """Write the UV layout shaded by distortion: a PNG (longer side ``size``
    pixels) or an SVG (with ``title``), by the extension."""
    import os
    _akvf.write_layout(os.fspath(path), V, F, uv, uv_faces, size, title)


def view_available():
    """True when this build embeds three.js, which write_view needs."""
    return _akvf.view_available()


def _json_default(value):
    if hasattr(value, "tolist"):  # NumPy arrays and scalars
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not JSON serializable")


def energies(dimension=2):
    """[(name, description)] of the energies (dimension 2: parameterize, 3: deform)."""
    return _akvf.energies(dimension)


def preconditioners(dimension=2):
    """[(name, description)] of the preconditioners (dimension 2 or 3)."""
    return _akvf.preconditioners(dimension)


def line_searches():
    """[(name, description)] of the line searches."""
    return _akvf.line_searches()


def solvers():
    """[(name, description)] of the solvers of parameterize (descent, lbfgs)."""
    return _akvf.solvers()


def load_extension(path):
    """Load a C++ extension that registers energies, preconditioners or line searches.

    The extension is a shared library built against akvf's headers alone
    (CMake: akvf::headers) defining ``extern "C" void akvf_register_extension()``,
    which registers its parts (akvf/extend.h); they are then usable by name
    everywhere and appear in energies(), preconditioners(), line_searches().
    Loading the same file again does nothing. See docs/python.md.
    """
    import os
    _akvf.load_extension(os.fspath(path))


def options(problem="parameterize"):
    """The keyword options of parameterize or deform: dicts of key, kind, default, flag, help,
    values (the accepted words of a fixed choice, "a|b|c"), scope ("param", "deform" or "both") and
    recomputes_start (changing it in Parameterizer.set_options recomputes the initial map)."""
    return _akvf.options(problem)


def _options_doc(problem):
    lines = ["", "Options (keyword = default: help):"]
    for o in _akvf.options(problem):
        lines.append("    %s = %s: %s" % (o["key"], o["default"], o["help"]))
    return "\n".join(lines)


parameterize.__doc__ += _options_doc("parameterize")
deform.__doc__ += _options_doc("deform")

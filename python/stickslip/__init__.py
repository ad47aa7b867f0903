"""stickslip: frictional contact mechanics from Python.

The same Rust crates as the ``stickslip`` program, through PyO3:

- ``run(scene)``: plan, execute and audit a scene; a :class:`Result` mirroring result.json,
  with NumPy arrays for every grid and field;
- ``explain(scene)``: the plan, without computing anything;
- ``sweep(scene, vary, client=None)``: a parameter sweep, the table of ``stickslip sweep``
  as a pandas DataFrame, run point by point here or on a Dask cluster;
- ``SceneError`` (``.key``, ``.line``, ``.column``, ``.hint``) and its subclass
  ``AuditError`` (``.checks``) for scenes that are refused or results that fail their audit.

A scene is a path to a TOML file, TOML text, or a dict with the keys of the TOML format
(docs/SCENES.md).
"""

import json as _json
import os as _os

import numpy as _np

from . import _stickslip

__all__ = ["run", "explain", "sweep", "Result", "SceneError", "AuditError"]
__version__ = "0.1.0"


class SceneError(Exception):
    """A scene that cannot be run as given, or a run that failed.

    Attributes: ``kind`` ("syntax", "schema", "unit", "out of range", "impossible",
    "unsupported", "solver", "audit", "io"), ``exit_code`` (that of the ``stickslip``
    program: 1, 2 or 3), ``message``, ``key`` (dotted, e.g. ``"substrate.nu"``, or None),
    ``line`` and ``column`` (1-based, in the scene text, or None), ``hint``, ``file``.
    ``str(e)`` is the program's message: ``file:line:column: `key`: message`` and the hint.
    """

    def __init__(self, text, kind, exit_code, message, key=None, line=None, column=None,
                 hint=None, file=None):
        super().__init__(text)
        self.kind = kind
        self.exit_code = exit_code
        self.message = message
        self.key = key
        self.line = line
        self.column = column
        self.hint = hint
        self.file = file


class AuditError(SceneError):
    """A result computed but not trustworthy: it failed its audit and was not returned.

    ``checks`` lists the failed checks as dicts with ``name``, ``value``, ``limit``,
    ``pass`` and ``what`` (the same fields as ``audit.checks`` in result.json).
    """

    def __init__(self, text, checks, **kw):
        super().__init__(text, **kw)
        self.checks = checks


def _error(raw):
    kind, code, message, key, line, column, hint, file, checks, text = raw.args
    kw = dict(kind=kind, exit_code=code, message=message, key=key, line=line, column=column,
              hint=hint, file=file)
    if kind == "audit":
        cs = [dict(name=n, value=v, limit=lim, **{"pass": p}, what=w)
              for (n, v, lim, p, w) in checks]
        return AuditError(text, cs, **kw)
    return SceneError(text, **kw)


def _call(f, *args, **kw):
    try:
        return f(*args, **kw)
    except _stickslip.RawSceneError as raw:
        err = _error(raw)
    raise err


def _scene(scene):
    """(TOML text, file name or None) of a scene given as a path, TOML text or dict."""
    if isinstance(scene, dict):
        return _stickslip.json_to_toml(_json.dumps(scene)), None
    if isinstance(scene, _os.PathLike):
        path = _os.fspath(scene)
    elif isinstance(scene, str):
        # One line ending in .toml, or a file that exists: a path; otherwise TOML text.
        one_line = "\n" not in scene and "=" not in scene
        if one_line and (scene.endswith(".toml") or _os.path.isfile(scene)):
            path = scene
        else:
            return scene, None
    else:
        raise TypeError(
            "a scene is a path, TOML text or a dict, not %s" % type(scene).__name__)
    try:
        with open(path, encoding="utf-8") as f:
            return f.read(), path
    except OSError as e:
        raise SceneError("%s: cannot read the scene file: %s" % (path, e), kind="io",
                         exit_code=1, message="cannot read the scene file: %s" % e,
                         file=path) from None


def _numeric(x):
    """True for a non-empty list of numbers, or of such lists (nested)."""
    if not isinstance(x, list) or not x:
        return False
    first = x[0]
    if isinstance(first, list):
        return all(_numeric(y) for y in x)
    return all(isinstance(y, (int, float)) and not isinstance(y, bool) for y in x)


def _flags(x):
    """True for a non-empty list of booleans."""
    return isinstance(x, list) and bool(x) and all(isinstance(y, bool) for y in x)


def _arrays(v, path=()):
    if isinstance(v, dict):
        return {k: _arrays(x, path + (k,)) for k, x in v.items()}
    if _flags(v):
        # Per-step flags (history.gross_slip): a bool array.
        return _np.asarray(v, dtype=bool)
    if _numeric(v):
        # The surface stick map is 1 / 0 / -1 (int8 in result.json too).
        dtype = _np.int8 if path == ("surface", "stick") else _np.float64
        return _np.asarray(v, dtype=dtype)
    if v == [] and path[:1] == ("zones",):  # no intervals: an empty (0, 2) array
        return _np.empty((0, 2))
    return v


class Result:
    """A run's result: the keys of result.json as attributes (and items), with every list
    of numbers a NumPy array (float64; the stick map int8) and every list of flags a bool
    array (a load history's ``gross_slip``). ``json`` is result.json as
    parsed, lists unchanged. ``field.values`` holds a 3D field's arrays, flat (reshape with
    ``field.shape``), also when result.json leaves them out because the box is large."""

    def __init__(self, data, raw=None):
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "json", raw)

    def __getattr__(self, name):
        try:
            v = self._data[name]
        except KeyError:
            raise AttributeError(name) from None
        return Result(v) if isinstance(v, dict) else v

    def __getitem__(self, name):
        return self.__getattr__(name)

    def __contains__(self, name):
        return name in self._data

    def __dir__(self):
        return list(self._data)

    def keys(self):
        """The keys at this level."""
        return self._data.keys()

    def to_dict(self):
        """The result as nested dicts (arrays as NumPy arrays)."""
        return self._data

    def __setattr__(self, name, value):
        raise AttributeError("a Result is read-only")

    def __repr__(self):
        return "Result(%s)" % ", ".join(self._data)


def run(scene, out=None, plots=None, force=False, time_limit=600.0):
    """Plan, execute and audit ``scene``; a :class:`Result`.

    ``out``: also write result.json, CSV and .npy files, the SVG plots and report.html into
    this directory, replaced whole, exactly as ``stickslip run --out`` does (an existing
    directory that is not an earlier result is refused unless ``force=True``).
    ``plots``: ``None`` (the default) follows the scene's ``outputs.plots`` (on unless the
    scene turns it off), ``True`` or ``False`` overrides it.
    ``time_limit``: refuse a run estimated to take longer (seconds).

    Raises :class:`SceneError` (refused, or a solver failed) or :class:`AuditError`.
    """
    text, file = _scene(scene)
    out = None if out is None else _os.fspath(out)
    js, arrays = _call(_stickslip.run, text, file, out, plots, force, time_limit)
    raw = _json.loads(js)
    data = _arrays(raw)
    field = data.get("field")
    if arrays is not None and isinstance(field, dict) and "values" not in field:
        field["values"] = {k: _np.asarray(v, dtype=_np.float64) for k, v in arrays.items()}
    return Result(data, raw)


def explain(scene):
    """The plan of ``scene`` (effects on and off with reasons, techniques, estimated cost),
    as ``stickslip explain`` prints it; nothing is computed."""
    text, file = _scene(scene)
    return _call(_stickslip.explain, text, file)


def _specs(vary):
    """``--vary`` specifications from a dict {key: "start:end:count" | [values]} or a list
    of "key=values" strings."""
    if isinstance(vary, dict):
        out = []
        for k, v in vary.items():
            if isinstance(v, str):
                out.append("%s=%s" % (k, v))
            else:
                vals = list(v)
                if not vals:
                    raise ValueError("vary: no values for %r" % k)
                out.append("%s=%s" % (k, ",".join(_value(x) for x in vals)))
        return out
    if isinstance(vary, str):
        return [vary]
    return list(vary)


def _value(x):
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, (int, float)):
        return repr(x)
    s = str(x)
    if "," in s:
        raise ValueError("vary: a value may not contain a comma: %r" % s)
    return s


def _point(text, file, specs, i, time_limit, zip=False):
    """One point's row (run on a Dask worker): the sweep is rebuilt from its text there."""
    return _call(_stickslip.Sweep, text, specs, file, zip).run_point(i, time_limit)


def _frame(columns, rows):
    import pandas as pd

    # Text columns take the dtype pandas gives text read from Parquet (object, or "str"
    # where strings are inferred), so that the frame equals pd.read_parquet of the CLI's
    # table.
    text = pd.Series(["x"]).dtype
    data = {}
    for j, (name, kind) in enumerate(columns):
        vals = [r[j] for r in rows]
        if kind == "int":
            data[name] = pd.Series(vals, dtype="int64")
        elif kind == "float":
            data[name] = pd.Series([_np.nan if v is None else v for v in vals],
                                   dtype="float64")
        else:
            data[name] = pd.Series(vals, dtype=text)
    return pd.DataFrame(data, columns=[c for c, _ in columns])


def sweep(scene, vary, client=None, shard=None, time_limit=600.0, zip=False):
    """A parameter sweep: the table of ``stickslip sweep`` as a pandas DataFrame.

    ``vary``: {key: "start:end:count"} or {key: [values]} or a list of "key=values"
    strings, as ``--vary`` takes them; the points are the cartesian product in the same
    order (the last key fastest), or with ``zip=True`` (``--zip``) the lists taken in step,
    point ``i`` setting every key to its ``i``-th value (lists of equal length; a pandas
    DataFrame of points gives them as ``{k: list(df[k]) for k in df}``). ``client``: a ``dask.distributed.Client``; the points
    run on its workers (``client.map``), else here one after the other. ``shard``: (i, n)
    for the points of shard i of n only. Each point is an independent, audited run; a point
    that fails is a row with ``status`` "failed" and its ``reason``.
    """
    text, file = _scene(scene)
    specs = _specs(vary)
    s = _call(_stickslip.Sweep, text, specs, file, zip)  # ValueError for a bad specification
    i, n = shard if shard is not None else (1, 1)
    points = s.points(i, n)
    if client is None:
        rows = [s.run_point(p, time_limit) for p in points]
    else:
        rows = _on_cluster(client, text, file, specs, points, time_limit, zip)
    return _frame(s.columns(), rows)


#: How many times a point whose worker died is submitted again before the sweep fails.
WORKER_RETRIES = 3


def _on_cluster(client, text, file, specs, points, time_limit, zip=False):
    """The rows of ``points`` run on the cluster of ``client``, in the order of ``points``.

    Each point is one task; its row is kept in the slot of its point as it arrives, so a
    point appears once whatever happens to the workers. A worker that dies takes its running
    tasks with it: the scheduler runs them again on the others, and a task it gives up on
    (``KilledWorker``, after the scheduler's own ``allowed-failures``) is submitted again
    here, up to ``WORKER_RETRIES`` times. A point is a pure function of the scene text and
    its index (every solver gives the same bits on every run), so a point run twice gives
    the same row.
    """
    from distributed import as_completed
    from distributed.scheduler import KilledWorker

    rows = [None] * len(points)
    owner = {}

    def submit(j, attempt):
        f = client.submit(_point, text, file, specs, points[j], time_limit, zip, pure=False,
                          retries=0)
        owner[f.key] = (j, attempt)
        return f

    pending = as_completed([submit(j, 0) for j in range(len(points))])
    for f in pending:
        j, attempt = owner.pop(f.key)
        try:
            rows[j] = f.result()
        except KilledWorker:
            if attempt + 1 > WORKER_RETRIES:
                raise
            pending.add(submit(j, attempt + 1))
        finally:
            f.release()
    return rows

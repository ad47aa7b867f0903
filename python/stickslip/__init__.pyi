"""Type stubs of the stickslip package (the runtime is ``__init__.py`` and the compiled
``_stickslip`` module); editors and type checkers read these."""

from os import PathLike
from typing import Any, Dict, KeysView, List, Mapping, Optional, Sequence, Tuple, Union

import pandas

__all__ = ["run", "explain", "sweep", "Result", "SceneError", "AuditError"]
__version__: str

#: A scene: a path to a TOML file, TOML text, or a dict with the keys of the TOML format.
Scene = Union[str, "PathLike[str]", Mapping[str, Any]]
#: A value of a varied key: a number, a boolean, or text such as "10 N".
VaryValue = Union[str, float, int, bool]
#: ``--vary`` specifications: {key: "start:end:count"} or {key: [values]}, or
#: "key=values" strings.
Vary = Union[Mapping[str, Union[str, Sequence[VaryValue]]], str, Sequence[str]]

#: How many times a point whose Dask worker died is submitted again.
WORKER_RETRIES: int

class SceneError(Exception):
    """A scene that cannot be run as given, or a run that failed.

    ``kind`` is one of "syntax", "schema", "unit", "out of range", "impossible",
    "unsupported", "solver", "audit", "io"; ``exit_code`` is that of the ``stickslip``
    program (1, 2 or 3); ``key`` the dotted key to change; ``line`` and ``column`` its
    1-based position in the scene text; ``hint`` what is allowed.
    """

    kind: str
    exit_code: int
    message: str
    key: Optional[str]
    line: Optional[int]
    column: Optional[int]
    hint: Optional[str]
    file: Optional[str]
    def __init__(
        self,
        text: str,
        kind: str,
        exit_code: int,
        message: str,
        key: Optional[str] = ...,
        line: Optional[int] = ...,
        column: Optional[int] = ...,
        hint: Optional[str] = ...,
        file: Optional[str] = ...,
    ) -> None: ...

class AuditError(SceneError):
    """A result computed but not trustworthy: it failed its audit and was not returned.
    ``checks``: the failed checks, dicts with ``name``, ``value``, ``limit``, ``pass``,
    ``what``."""

    checks: List[Dict[str, Any]]
    def __init__(self, text: str, checks: List[Dict[str, Any]], **kw: Any) -> None: ...

class Result:
    """A run's result: the keys of result.json as attributes and items (``r.contact.a``,
    ``r["contact"]["a"]``), every list of numbers a NumPy array (lists of flags bool
    arrays); nested tables are
    ``Result`` too. ``json`` is result.json as parsed."""

    json: Optional[Dict[str, Any]]
    def __init__(self, data: Dict[str, Any], raw: Optional[Dict[str, Any]] = ...) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, name: str) -> Any: ...
    def __contains__(self, name: object) -> bool: ...
    def keys(self) -> KeysView[str]:
        """The keys at this level."""
    def to_dict(self) -> Dict[str, Any]:
        """The result as nested dicts (arrays as NumPy arrays)."""

def run(
    scene: Scene,
    out: Union[str, "PathLike[str]", None] = ...,
    plots: Optional[bool] = ...,
    force: bool = ...,
    time_limit: float = ...,
) -> Result:
    """Plan, execute and audit ``scene``; a :class:`Result`. ``out``: also write the result
    files, plots and report.html there as ``stickslip run --out`` does; ``plots=None``
    follows the scene's ``outputs.plots``. Raises :class:`SceneError` or
    :class:`AuditError`."""

def explain(scene: Scene) -> str:
    """The plan of ``scene`` as ``stickslip explain`` prints it; nothing is computed."""

def sweep(
    scene: Scene,
    vary: Vary,
    client: Optional[Any] = ...,
    shard: Optional[Tuple[int, int]] = ...,
    time_limit: float = ...,
    zip: bool = ...,
) -> pandas.DataFrame:
    """A parameter sweep: the table of ``stickslip sweep`` as a pandas DataFrame, run here
    or on the Dask cluster of ``client`` (a ``dask.distributed.Client``); ``zip=True`` takes
    the lists in step (``stickslip sweep --zip``)."""

"""Typed use of the package, checked by mypy --strict against its stubs
(test_types.py); it is not run."""

from pathlib import Path

import pandas

import stickslip


def contact_radius(scene: Path) -> float:
    r: stickslip.Result = stickslip.run(scene, plots=False, time_limit=60.0)
    a: float = r.contact.a
    return a


def plan(text: str) -> str:
    return stickslip.explain(text)


def table() -> pandas.DataFrame:
    return stickslip.sweep({"geometry": {"kind": "sphere"}}, {"load.friction": [0.1, 0.2]},
                           shard=(1, 2))


def refused(text: str) -> str:
    try:
        stickslip.run(text)
    except stickslip.AuditError as e:
        return str(e.checks[0]["name"])
    except stickslip.SceneError as e:
        return "%s:%s %s (%d)" % (e.line, e.column, e.key, e.exit_code)
    return ""

"""The package explains itself: its stubs (``__init__.pyi``, ``py.typed``) type-check with
mypy against a typed usage file, they list the same functions and parameters as the
runtime, and ``help`` answers for what users call."""

import ast
import inspect
import pathlib
import pydoc
import subprocess
import sys

import pytest

import stickslip

HERE = pathlib.Path(__file__).resolve().parent
PUBLIC = ["run", "explain", "sweep"]


def stubs():
    path = pathlib.Path(stickslip.__file__).with_name("__init__.pyi")
    assert path.is_file(), "the installed package has no __init__.pyi"
    assert path.with_name("py.typed").is_file(), "the installed package has no py.typed"
    return ast.parse(path.read_text())


def test_the_stubs_name_the_runtimes_parameters():
    tree = stubs()
    funcs = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {n.name for n in tree.body if isinstance(n, ast.ClassDef)}
    for name in PUBLIC:
        stub = [a.arg for a in funcs[name].args.args]
        runtime = list(inspect.signature(getattr(stickslip, name)).parameters)
        assert stub == runtime, name
    assert {"Result", "SceneError", "AuditError"} <= classes
    assert set(stickslip.__all__) <= set(funcs) | classes


def test_help_answers():
    for obj in [stickslip.run, stickslip.explain, stickslip.sweep, stickslip.Result,
                stickslip.SceneError, stickslip.AuditError]:
        text = pydoc.render_doc(obj)
        assert obj.__doc__ and len(obj.__doc__) > 60, obj
        assert obj.__doc__.split("\n")[0].strip() in text


def test_mypy_accepts_the_stubs_and_a_typed_use():
    pytest.importorskip("mypy")
    o = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                        str(HERE / "typed_usage.py")], capture_output=True, text=True)
    assert o.returncode == 0, o.stdout + o.stderr
    # And it refuses a wrong use (so the stubs are really read).
    bad = HERE / "typed_usage.py"
    wrong = bad.read_text() + "\n\nx: int = stickslip.explain(3)\n"
    o = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                        "-c", wrong], capture_output=True, text=True)
    assert o.returncode == 1 and "explain" in o.stdout, o.stdout + o.stderr

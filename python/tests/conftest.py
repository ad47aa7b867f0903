"""Shared paths for the tests: the repository's scenes and the `stickslip` program."""

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


@pytest.fixture
def cli():
    """The `stickslip` program: $STICKSLIP_BIN, or target/release/stickslip of the
    repository (built by `cargo test --release`). Missing: a failure under CI=true, a skip
    otherwise."""
    path = os.environ.get("STICKSLIP_BIN") or str(ROOT / "target" / "release" / "stickslip")
    if not os.path.isfile(path):
        msg = "no stickslip program at %s (build it with cargo build --release)" % path
        if os.environ.get("CI") == "true":
            pytest.fail(msg)
        pytest.skip(msg)
    return path

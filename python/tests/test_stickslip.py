"""The Python package against the program and result.json: arrays, errors, sweeps (serial,
sharded, on a 2-worker Dask LocalCluster) and the CLI's table."""

import json
import subprocess

import numpy as np
import pandas as pd
import pytest

import stickslip
from conftest import SCENES

HERTZ = SCENES / "hertz_cylinder_cattaneo.toml"
VARY = {"load.tangential": "0 kN/m:40 kN/m:5", "load.friction": [0.2, 0.3]}
CLI_VARY = ["--vary", "load.tangential=0 kN/m:40 kN/m:5", "--vary", "load.friction=0.2,0.3"]


def walk(js, res, path=""):
    """Every list of numbers in result.json equals the result's NumPy array, exactly;
    returns how many arrays were compared."""
    if isinstance(js, dict):
        return sum(walk(v, res[k], path + "." + k) for k, v in js.items())
    if isinstance(js, list) and js and isinstance(js[0], dict):
        return sum(walk(a, b, "%s[%d]" % (path, i)) for i, (a, b) in enumerate(zip(js, res)))
    if isinstance(js, list) and js and not isinstance(js[0], str):
        assert isinstance(res, np.ndarray), path
        np.testing.assert_array_equal(res, np.asarray(js, dtype=float), err_msg=path)
        return 1
    if isinstance(js, (int, float)) and not isinstance(js, bool):
        assert res == js, path
    return 0


@pytest.mark.parametrize("name,grids", [
    ("hertz_cylinder_cattaneo", ["surface.x", "surface.p", "field.sxx"]),
    ("sphere_as_surface", ["surface.p", "surface.gap", "surface.stick"]),
    ("sphere_subsurface_field", ["surface.qx", "field.values.von_mises"]),
    ("seed002_ex1_lp", ["surface.p", "surface.qx", "surface.stick"]),
    ("sphere_fretting_history", ["history.tangential", "history.shift", "history.dissipated",
                                 "surface.dissipation", "surface.slip_amplitude",
                                 "surface.ruiz"]),
])
def test_arrays_equal_result_json(tmp_path, name, grids):
    out = tmp_path / "out"
    r = stickslip.run(SCENES / (name + ".toml"), out=out)
    with open(out / "result.json") as f:
        js = json.load(f)
    assert r.json == js
    assert walk(js, r.to_dict()) >= len(grids)
    for g in grids:
        a = r
        for k in g.split("."):
            a = a[k]
        assert isinstance(a, np.ndarray) and a.size > 1, g
    if "stick" in r.surface:
        assert r.surface.stick.dtype == np.int8
    if "history" in r:
        # Per-step flags are bool arrays; the path's surface maps are the .npy files written
        # (result.json's maps are [i][j] at (x[i], y[j]), the .npy arrays (ny, nx)).
        assert r.history.gross_slip.dtype == bool
        assert r.history.gross_slip.shape == r.history.tangential.shape
        for k in ("dissipation", "slip_amplitude", "ruiz"):
            np.testing.assert_array_equal(r.surface[k], np.load(out / ("surface_%s.npy" % k)).T)


def test_toml_text_and_path_give_the_same_result():
    # A closed-form scene: bitwise repeatable. (The lattice solvers' parallel sums can
    # differ at round-off from run to run, so their scenes are not compared bit for bit.)
    r = stickslip.run(HERTZ)
    r2 = stickslip.run(HERTZ.read_text())
    for k in ("x", "p", "q", "ux", "uy"):
        np.testing.assert_array_equal(r2.surface[k], r.surface[k])
    np.testing.assert_array_equal(r2.field.sxy, r.field.sxy)
    assert r.title == r2.title


def test_a_large_3d_field_has_its_arrays_though_result_json_leaves_them_out():
    r = stickslip.run(SCENES / "sphere_subsurface_field.toml")
    f = r.field
    n = int(np.prod(f.shape))
    assert f.values.von_mises.shape == (n,)
    peak = f.values.von_mises.max()
    assert peak == f.max.von_mises.value


def test_dict_scene_equals_the_file():
    scene = {
        "title": "dict",
        "geometry": {"kind": "cylinder", "radius": "20 mm"},
        "substrate": {"model": "homogeneous", "e": "210 GPa", "nu": 0.3},
        "indenter": {"model": "same"},
        "load": {"normal": "100 kN/m", "tangential": "15 kN/m", "friction": 0.3},
    }
    r = stickslip.run(scene)
    f = stickslip.run(HERTZ)
    assert r.contact.a == f.contact.a
    assert r.forces.tangential == 15e3
    np.testing.assert_array_equal(r.surface.q, f.surface.q)
    assert "effects on" in stickslip.explain(scene)


def test_scene_errors_carry_key_and_position():
    text = HERTZ.read_text().replace("nu = 0.3", "nu = 0.7")
    line = next(i + 1 for i, l in enumerate(text.splitlines()) if l.startswith("nu = 0.7"))
    with pytest.raises(stickslip.SceneError) as e:
        stickslip.run(text)
    err = e.value
    assert not isinstance(err, stickslip.AuditError)
    assert (err.key, err.line, err.column) == ("substrate.nu", line, 6)
    assert err.kind == "out of range" and err.exit_code == 2
    assert "0.5" in err.hint
    assert str(err).startswith("<scene>:%d:6: `substrate.nu`:" % line)
    text = HERTZ.read_text().replace("[load]", "[load]\nfrction = 0.1")
    line = next(i + 1 for i, l in enumerate(text.splitlines()) if l.startswith("frction"))
    with pytest.raises(stickslip.SceneError) as e:
        stickslip.explain(text)
    assert e.value.kind == "schema" and e.value.key == "load.frction"
    assert (e.value.line, e.value.column) == (line, 1)
    with pytest.raises(stickslip.SceneError) as e:
        stickslip.run(str(SCENES / "no_such_scene.toml"))
    assert e.value.kind == "io" and e.value.exit_code == 1


def test_an_audit_failure_is_an_audit_error_with_the_failed_checks():
    src = ("[geometry]\nkind = \"sphere\"\nradius = 0.01\n[substrate]\nmodel = \"homogeneous\"\n"
           "e = 2e11\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = 100.0\n"
           "moment = 0.002\nfriction = 0.3\n[solver]\ngrid = 4\n")
    with pytest.raises(stickslip.AuditError) as e:
        stickslip.run(src)
    err = e.value
    assert isinstance(err, stickslip.SceneError)
    assert (err.key, err.line, err.exit_code) == ("solver.grid", 15, 3)
    assert err.checks and all(not c["pass"] for c in err.checks)
    assert err.checks[0]["name"] == "lattice sampling"
    assert err.checks[0]["value"] > err.checks[0]["limit"]


def test_serial_sweep_rows_and_failures():
    df = stickslip.sweep(HERTZ, VARY)
    assert len(df) == 10 and list(df["point"]) == list(range(10))
    assert list(df.columns[3:5]) == ["load.tangential", "load.friction"]
    ok = df[df.status == "ok"]
    failed = df[df.status == "failed"]
    # T > f P = 0.2 * 100 kN/m or 0.3 * 100 kN/m: refused with the key, exit status 2.
    assert sorted(failed.point) == [6, 8, 9]
    assert (failed.exit_code == 2).all() and (failed.error_kind == "impossible").all()
    assert failed.reason.str.contains("load.tangential").all()
    assert failed.tangential.isna().all()
    # Cattaneo: stick half-width c = a sqrt(1 - Q/(f P)).
    row = ok[ok.point == 5].iloc[0]
    assert row.tangential == 20e3
    assert abs(row.stick_fraction - np.sqrt(1 - 20e3 / (0.3 * 100e3))) < 1e-12


def test_shards_merge_to_the_full_sweep_exactly():
    full = stickslip.sweep(HERTZ, VARY)
    parts = [stickslip.sweep(HERTZ, VARY, shard=(i, 3)) for i in (1, 2, 3)]
    assert [len(p) for p in parts] == [4, 3, 3]
    merged = pd.concat(parts).sort_values("point").reset_index(drop=True)
    pd.testing.assert_frame_equal(merged, full, check_exact=True)


def test_a_two_worker_local_cluster_sweep_equals_the_serial_sweep():
    distributed = pytest.importorskip("distributed")
    serial = stickslip.sweep(HERTZ, VARY)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            df = stickslip.sweep(HERTZ, VARY, client=client)
    pd.testing.assert_frame_equal(df, serial, check_exact=True)


def test_the_frame_equals_the_cli_table(cli, tmp_path):
    subprocess.run([cli, "sweep", str(HERTZ), *CLI_VARY, "--out", str(tmp_path)], check=True,
                   capture_output=True)
    table = pd.read_parquet(tmp_path / "sweep.parquet")
    pd.testing.assert_frame_equal(stickslip.sweep(HERTZ, VARY), table, check_exact=True)
    # All three kinds of varied column (integers, numbers, text).
    out = tmp_path / "kinds"
    subprocess.run([cli, "sweep", str(HERTZ), "--vary", "solver.grid=16,32", *CLI_VARY,
                    "--out", str(out)], check=True, capture_output=True)
    kinds = pd.read_parquet(out / "sweep.parquet")
    assert kinds["solver.grid"].dtype == np.int64
    df = stickslip.sweep(HERTZ, {"solver.grid": [16, 32], **VARY})
    pd.testing.assert_frame_equal(df, kinds, check_exact=True)
    # The CSV reads back to the same numbers.
    csv = pd.read_csv(tmp_path / "sweep.csv")
    np.testing.assert_array_equal(csv.tangential.to_numpy(), table.tangential.to_numpy())


def test_a_zipped_sweep_equals_the_cli_zip_table(cli, tmp_path):
    zipped = {"load.tangential": ["0 kN/m", "10 kN/m", "20 kN/m"], "load.friction": [0.2, 0.3, 0.4]}
    subprocess.run([cli, "sweep", str(HERTZ), "--zip", "--vary",
                    "load.tangential=0 kN/m,10 kN/m,20 kN/m", "--vary", "load.friction=0.2,0.3,0.4",
                    "--out", str(tmp_path)], check=True, capture_output=True)
    table = pd.read_parquet(tmp_path / "sweep.parquet")
    df = stickslip.sweep(HERTZ, zipped, zip=True)
    assert len(df) == 3
    assert list(df["load.friction"]) == [0.2, 0.3, 0.4]
    pd.testing.assert_frame_equal(df, table, check_exact=True)
    with pytest.raises(stickslip.SceneError) as e:
        stickslip.sweep(HERTZ, {"load.tangential": ["0 kN/m"], "load.friction": [0.2, 0.3]},
                        zip=True)
    assert e.value.key == "load.friction"


def test_bad_vary_specs_are_value_errors():
    with pytest.raises(ValueError, match="three parts"):
        stickslip.sweep(HERTZ, {"load.friction": "0:1"})
    with pytest.raises(stickslip.SceneError) as e:
        stickslip.sweep(HERTZ, {"load.frction": [0.1]})
    assert e.value.key == "load.frction"


SLOW = """[geometry]
kind = "surface"
size = ["0.6 mm", "0.6 mm"]
cells = [256, 256]
[geometry.profile]
shape = "sphere"
radius = "10 mm"
[substrate]
material = "steel"
[indenter]
model = "same"
[load]
normal = "5 N"
[solver]
tolerance = 1e-10
"""


def test_a_worker_killed_mid_sweep_costs_no_point_and_repeats_none():
    """A Dask worker killed (SIGKILL) while the sweep runs: its points run again on the
    others, and the table is the serial one, each point once."""
    import os
    import signal
    import threading
    import time

    distributed = pytest.importorskip("distributed")
    vary = {"load.normal": "1:10:16"}
    serial = stickslip.sweep(SLOW, vary)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            client.wait_for_workers(2)
            pids = client.run(os.getpid)
            victim = sorted(pids.values())[0]
            killed = {}

            def kill():
                # Once the sweep is under way (a point takes ~0.1 s or more).
                time.sleep(0.6)
                os.kill(victim, signal.SIGKILL)
                killed["at"] = time.monotonic()

            t0 = time.monotonic()
            th = threading.Thread(target=kill)
            th.start()
            df = stickslip.sweep(SLOW, vary, client=client)
            end = time.monotonic()
            th.join()
    assert "at" in killed and killed["at"] < end, "the worker was not killed mid-sweep"
    print("sweep %.2f s, worker killed at %.2f s" % (end - t0, killed["at"] - t0))
    assert list(df["point"]) == list(range(16))
    pd.testing.assert_frame_equal(df, serial, check_exact=True)


def test_out_writes_what_the_cli_writes_plots_by_default(tmp_path):
    # Issue 33 item 1: the plots are on unless the scene or the caller turns them off, and
    # report.html is written beside result.json, as `stickslip run --out` does.
    out = tmp_path / "on"
    stickslip.run(SCENES / "hertz_cylinder_cattaneo.toml", out=out)
    names = {p.name for p in out.iterdir()}
    assert "report.html" in names and "result.json" in names
    assert any(n.endswith(".svg") for n in names), names
    off = tmp_path / "off"
    stickslip.run(SCENES / "hertz_cylinder_cattaneo.toml", out=off, plots=False)
    names = {p.name for p in off.iterdir()}
    assert "report.html" in names and not any(n.endswith(".svg") for n in names), names

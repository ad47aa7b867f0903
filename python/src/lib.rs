//! The native part of the `stickslip` Python package (`stickslip._stickslip`): thin
//! bindings to the scene, run, report and sweep crates. The Python layer (`stickslip/__init__.py`) turns scenes
//! given as paths, TOML text or dicts into TOML text, results into NumPy arrays, and the
//! raw error into `SceneError` / `AuditError`.

// SceneError carries file, position, key and hint for the user; one per call.
#![allow(clippy::result_large_err)]

use std::collections::BTreeMap;
use std::path::PathBuf;

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use stickslip_report::{write_outputs_report, ReportContext, WriteOptions};
use stickslip_run::{Execute, MachineLimits, Plan, RunOptions};
use stickslip_scene::{Scene, SceneError};
use stickslip_sweep::{Cell, Kind, Mode, Shard, Sweep, Vary};

create_exception!(
    _stickslip,
    RawSceneError,
    PyException,
    "A scene error with its parts as args: (kind, exit_code, message, key, line, column, hint, file, checks, text)."
);

/// A scene error as a Python exception; the Python layer raises `SceneError` or
/// `AuditError` from it.
fn raise(e: SceneError) -> PyErr {
    let checks: Vec<(String, f64, f64, bool, String)> = e
        .checks
        .iter()
        .map(|c| (c.name.to_string(), c.value, c.limit, c.pass, c.what.clone()))
        .collect();
    let (line, column) = match e.position {
        Some((l, c)) => (Some(l), Some(c)),
        None => (None, None),
    };
    let text = e.to_string();
    PyErr::new::<RawSceneError, _>((
        e.kind.name().to_string(),
        e.exit_code(),
        e.message,
        e.key,
        line,
        column,
        e.hint,
        e.file.map(|f| f.display().to_string()),
        checks,
        text,
    ))
}

fn read(text: &str, file: Option<PathBuf>) -> PyResult<Scene> {
    stickslip_run::read_scene(text, file).map_err(raise)
}

/// TOML text from a JSON object (a scene given as a dict).
#[pyfunction]
fn json_to_toml(json: &str) -> PyResult<String> {
    let v: toml::Table = serde_json::from_str(json).map_err(|e| {
        pyo3::exceptions::PyValueError::new_err(format!(
            "the scene dict cannot be written as TOML: {e} (values must be tables, strings, \
             numbers, booleans or lists; None has no TOML form)"
        ))
    })?;
    toml::to_string(&v).map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))
}

/// Plan and execute the scene `text` (read from `file`, for messages); write the outputs
/// into `out` when given, as `stickslip run --out` does (result.json, CSV, NPY, the plots
/// unless `plots` or the scene's `outputs.plots` turns them off, and report.html). Returns result.json's text and the arrays of a 3D field (always,
/// also when result.json leaves them out because the box is large), flat.
#[pyfunction]
#[pyo3(signature = (text, file=None, out=None, plots=None, force=false, time_limit=600.0))]
#[allow(clippy::type_complexity)]
fn run(
    py: Python<'_>,
    text: &str,
    file: Option<PathBuf>,
    out: Option<PathBuf>,
    plots: Option<bool>,
    force: bool,
    time_limit: f64,
) -> PyResult<(String, Option<BTreeMap<String, Vec<f64>>>)> {
    let scene = read(text, file)?;
    py.detach(|| {
        let plan = Plan::new(&scene)?;
        plan.check_machine(&MachineLimits::detect(time_limit))?;
        let outcome = plan.execute(&RunOptions::default())?;
        if let Some(dir) = &out {
            let plots = plots.unwrap_or(scene.outputs.plots);
            write_outputs_report(
                &outcome,
                dir,
                WriteOptions { plots, force },
                ReportContext { scene: &scene, plan: &plan },
            )?;
        }
        let arrays = outcome.field.volume().map(|v| {
            let a = &v.arrays;
            BTreeMap::from([
                ("sxx".to_string(), a.sxx.clone()),
                ("syy".to_string(), a.syy.clone()),
                ("szz".to_string(), a.szz.clone()),
                ("sxy".to_string(), a.sxy.clone()),
                ("syz".to_string(), a.syz.clone()),
                ("sxz".to_string(), a.sxz.clone()),
                ("von_mises".to_string(), a.von_mises.clone()),
                ("tresca".to_string(), a.tresca.clone()),
                ("max_principal".to_string(), a.max_principal.clone()),
            ])
        });
        Ok((outcome.to_json(), arrays))
    })
    .map_err(raise)
}

/// The plan of the scene `text`, as `stickslip explain` prints it.
#[pyfunction]
#[pyo3(signature = (text, file=None))]
fn explain(text: &str, file: Option<PathBuf>) -> PyResult<String> {
    let scene = read(text, file)?;
    Ok(Plan::new(&scene).map_err(raise)?.explain())
}

/// A sweep (`stickslip_sweep::Sweep`): point enumeration, shards, columns and one row per
/// point, the same code as `stickslip sweep`.
#[pyclass(name = "Sweep", module = "stickslip._stickslip", frozen)]
struct PySweep(Sweep);

/// A cell as a Python value: int, float, str or None.
fn cell(py: Python<'_>, c: &Cell) -> PyResult<Py<PyAny>> {
    Ok(match c {
        Cell::Int(i) => i.into_pyobject(py)?.into_any().unbind(),
        Cell::Float(Some(x)) => x.into_pyobject(py)?.into_any().unbind(),
        Cell::Text(Some(t)) => t.into_pyobject(py)?.into_any().unbind(),
        Cell::Float(None) | Cell::Text(None) => py.None(),
    })
}

#[pymethods]
impl PySweep {
    /// A sweep of the scene `text` over `specs` (`key=start:end:count` or `key=v1,v2,...`):
    /// their cartesian product, or with `zip` the lists taken in step (`stickslip sweep
    /// --zip`).
    #[new]
    #[pyo3(signature = (text, specs, file=None, zip=false))]
    fn new(text: &str, specs: Vec<String>, file: Option<PathBuf>, zip: bool) -> PyResult<Self> {
        let vary = specs
            .iter()
            .map(|s| Vary::parse(s))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
        let mode = if zip { Mode::Zip } else { Mode::Cartesian };
        Ok(PySweep(Sweep::with_mode(text, file, &vary, mode).map_err(raise)?))
    }

    /// The number of points.
    fn __len__(&self) -> usize {
        self.0.len()
    }

    /// The sweep's identity (stored in every row).
    #[getter]
    fn id(&self) -> String {
        self.0.id().to_string()
    }

    /// The point indices of shard `index` of `count` (1-based), all points by default.
    #[pyo3(signature = (index=1, count=1))]
    fn points(&self, index: usize, count: usize) -> PyResult<Vec<usize>> {
        let s = Shard::parse(&format!("{index}/{count}"))
            .map_err(pyo3::exceptions::PyValueError::new_err)?;
        Ok(s.points(self.0.len()).collect())
    }

    /// The columns: (name, kind) with kind "int", "float" or "text".
    fn columns(&self) -> Vec<(String, &'static str)> {
        self.0
            .columns()
            .into_iter()
            .map(|(n, k)| {
                let k = match k {
                    Kind::Int => "int",
                    Kind::Float => "float",
                    Kind::Text => "text",
                };
                (n, k)
            })
            .collect()
    }

    /// Run point `i` (read, plan, check, execute, audit); its row of the table.
    #[pyo3(signature = (i, time_limit=600.0))]
    fn run_point(&self, py: Python<'_>, i: usize, time_limit: f64) -> PyResult<Vec<Py<PyAny>>> {
        if i >= self.0.len() {
            return Err(pyo3::exceptions::PyIndexError::new_err(format!(
                "point {i} of a sweep of {} points",
                self.0.len()
            )));
        }
        let row = py.detach(|| self.0.run_point(i, time_limit));
        row.iter().map(|c| cell(py, c)).collect()
    }
}

/// The native module.
#[pymodule]
fn _stickslip(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(explain, m)?)?;
    m.add_function(wrap_pyfunction!(json_to_toml, m)?)?;
    m.add_class::<PySweep>()?;
    m.add("RawSceneError", m.py().get_type::<RawSceneError>())?;
    Ok(())
}

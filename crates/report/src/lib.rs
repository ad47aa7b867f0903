//! The files of a stickslip result: result.json, CSV and `.npy` arrays, SVG plots and
//! report.html, written into one directory all or nothing.
//!
//! This crate computes nothing: it reads an [`Outcome`](stickslip_run::Outcome) of
//! `stickslip-run` (and, for the report, the scene and its plan) and writes it out.
//!
//! - [`write_outputs`], [`write_outputs_with`] ([`WriteOptions`]: plots, force) and
//!   [`write_outputs_report`] (with a [`ReportContext`]: the scene and its plan in the
//!   report): the files, written into a fresh sibling directory and swapped in whole
//!   (`output.rs`);
//! - the SVG plots (`plots/`: line charts with the closed-form references, heat maps with
//!   contour lines, stick/slip maps) and report.html (`report.rs`: one self-contained page).
//!
//! ```
//! use stickslip_report::write_outputs;
//! use stickslip_run::{run, RunOptions};
//! use stickslip_scene::Scene;
//! let text = "[geometry]\nkind = \"sphere\"\nradius = \"10 mm\"\n[substrate]\nmodel = \"homogeneous\"\ne = \"210 GPa\"\nnu = 0.3\n[indenter]\nmodel = \"same\"\n[load]\nnormal = \"100 N\"\n";
//! let out = run(&Scene::from_toml_str(text, None).unwrap(), &RunOptions::default()).unwrap();
//! let dir = std::env::temp_dir().join(format!("stickslip-report-doc-{}", std::process::id()));
//! let written = write_outputs(&out, &dir, false).unwrap();
//! assert!(written.files.iter().any(|f| f.ends_with("result.json")));
//! std::fs::remove_dir_all(&dir).unwrap();
//! ```

// SceneError carries file, position, key and hint for the user; one per call.
#![allow(clippy::result_large_err)]

mod files;
mod output;
mod plots;
mod report;

pub use output::{write_outputs, write_outputs_report, write_outputs_with, WriteOptions, Written};
pub use report::ReportContext;

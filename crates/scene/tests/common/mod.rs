//! Shared helpers of the scene tests.
#![allow(dead_code)]

use std::path::PathBuf;

pub fn scenes_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenes")
}

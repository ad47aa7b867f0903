//! The machine a plan must fit: the memory available now and the time the user allows.
//! The planner's estimate ([`super::Cost`]) is compared with both before anything runs;
//! a plan that does not fit is refused with the estimate and how to proceed.

use super::cost::{human_bytes, human_seconds};
use super::Plan;
use stickslip_scene::{ErrorKind, SceneError};

/// The default time a run may take before it is refused (raise it with `--time-limit`).
pub const DEFAULT_TIME_LIMIT_SECONDS: f64 = 600.0;

/// What the machine offers a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MachineLimits {
    /// Memory available to the run (bytes), or None when it cannot be read.
    pub memory_bytes: Option<u64>,
    /// The longest run allowed (s).
    pub seconds: f64,
}

impl MachineLimits {
    /// The memory available now (Linux: `MemAvailable` of `/proc/meminfo`; elsewhere
    /// unknown) and `seconds` of run time.
    pub fn detect(seconds: f64) -> Self {
        MachineLimits { memory_bytes: available_memory(), seconds }
    }
}

fn available_memory() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

impl Plan {
    /// Refuse a plan whose estimated memory exceeds what the machine has available or whose
    /// estimated time exceeds the limit.
    ///
    /// # Errors
    /// A [`SceneError`] of kind [`ErrorKind::OutOfRange`] at `solver.grid` with the estimate
    /// and how to proceed.
    #[allow(clippy::result_large_err)]
    pub fn check_machine(&self, limits: &MachineLimits) -> Result<(), SceneError> {
        let c = self.cost;
        let refuse = |message: String, hint: String| {
            let e = SceneError::new(ErrorKind::OutOfRange, message).key("solver.grid").hint(hint);
            let e = match &self.source {
                Some(src) => e.at(src.text(), src.span("solver.grid")),
                None => e,
            };
            Err(e.in_file(self.file.clone()))
        };
        if let Some(avail) = limits.memory_bytes {
            if c.memory_bytes > avail {
                return refuse(
                    format!(
                        "the run needs about {} of memory; this machine has {} available",
                        human_bytes(c.memory_bytes),
                        human_bytes(avail)
                    ),
                    "reduce solver.grid (memory grows with its square), or free memory".to_string(),
                );
            }
        }
        if c.seconds > limits.seconds {
            return refuse(
                format!(
                    "the run is estimated at {}, more than the limit of {}",
                    human_seconds(c.seconds),
                    human_seconds(limits.seconds)
                ),
                format!(
                    "reduce solver.grid, or allow it with --time-limit {:.0} (seconds)",
                    (c.seconds * 1.5).ceil()
                ),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stickslip_scene::Scene;

    #[test]
    fn a_plan_over_the_limits_is_refused_with_the_estimate() {
        let scene = Scene::default_scene();
        let plan = Plan::new(&scene).unwrap();
        let roomy = MachineLimits { memory_bytes: Some(u64::MAX), seconds: 1e9 };
        plan.check_machine(&roomy).unwrap();
        let small = MachineLimits { memory_bytes: Some(1), seconds: 1e9 };
        let e = plan.check_machine(&small).unwrap_err();
        assert!(e.message.contains("memory") && e.hint.is_some(), "{e}");
        let quick = MachineLimits { memory_bytes: None, seconds: 0.0 };
        let e = plan.check_machine(&quick).unwrap_err();
        assert!(e.hint.as_deref().unwrap_or("").contains("--time-limit"), "{e}");
        assert!(MachineLimits::detect(600.0).memory_bytes.is_some_and(|m| m > 0));
    }
}

//! Closed-form partial-slip solutions for Hertz contacts (FORMULAS.md sections E and G).
//!
//! * [`Mindlin`]: circle under a tangential force (Mindlin 1949; seed 002 eqs 3.1–3.4);
//! * [`Cattaneo`]: ellipse under a tangential force along an axis (Cattaneo 1938; seed 002
//!   §3.2.2);
//! * [`Deresiewicz`]: unloading, reloading, hysteresis loop and energy per cycle
//!   (Mindlin & Deresiewicz 1953; seed 002 eq. 3.5, corrected sign);
//! * [`Lubkin`]: torsion with a slip annulus (Lubkin 1951; FORMULAS.md G).
//!
//! Each type is a validated parameter set (`new(..) -> Result`). The tangential load ratio
//! $t = T/(fP)$ must lie in $[0, 1]$: $t = 1$ is impending gross slip (stick zone of radius
//! zero, finite compliance); $t > 1$ has no partial-slip solution and is an
//! [`Error::OutOfDomain`]. The grid solver in
//! [`crate::solve`] reports loads beyond gross slip as a result instead.

mod cattaneo;
mod deresiewicz;
mod lubkin;
mod mindlin;

pub use cattaneo::{cattaneo_lambda, Cattaneo, LoadAxis};
pub use deresiewicz::Deresiewicz;
pub use lubkin::{k_minus_e, Lubkin};
pub use mindlin::Mindlin;

use crate::error::{positive, Error, Result};

/// $1 - (1 - t)^{p}$ without cancellation for small $t$: $-\mathrm{expm1}(p\,\mathrm{ln1p}(-t))$.
pub(crate) fn one_minus_pow(t: f64, p: f64) -> f64 {
    if t >= 1.0 {
        1.0
    } else {
        -(p * (-t).ln_1p()).exp_m1()
    }
}

/// Validate $P > 0$, $f > 0$, $0 \le T \le fP$ and return $t = T/(fP)$.
pub(crate) fn load_ratio(normal: f64, friction: f64, tangential: f64) -> Result<f64> {
    positive("normal load P", normal)?;
    positive("friction coefficient f", friction)?;
    if !(tangential.is_finite() && tangential >= 0.0) {
        return Err(Error::OutOfDomain {
            name: "tangential load T",
            value: tangential,
            allowed: "finite and >= 0 (use a negative direction instead of a negative load)",
        });
    }
    let t = tangential / (friction * normal);
    if t > 1.0 {
        return Err(Error::OutOfDomain {
            name: "T/(fP)",
            value: t,
            allowed:
                "[0, 1]; beyond 1 the contact slides (gross slip) and has no partial-slip solution",
        });
    }
    Ok(t)
}

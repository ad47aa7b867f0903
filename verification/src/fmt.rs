//! Our own number formatting, so that snapshots and generated pages are identical on every
//! machine: ten significant digits, `-0` shown as `0`, and quantities that are zero up to
//! rounding shown as `0`.

/// Significant digits of every value in snapshots and pages.
pub const DIGITS: usize = 10;

/// `x` with [`DIGITS`] significant digits: fixed notation for $10^{-4} \le |x| < 10^{7}$,
/// scientific (`1.234e-5`) otherwise; trailing zeros of the fraction trimmed; `-0` as `0`;
/// non-finite values as `inf`, `-inf`, `NaN`.
#[must_use]
pub fn num(x: f64) -> String {
    sig(x, DIGITS)
}

/// `x` with `digits` significant digits (see [`num`]).
#[must_use]
pub fn sig(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf".into() } else { "-inf".into() };
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = digits.max(1);
    let e = format!("{:.*e}", digits - 1, x);
    let (mant, exp) = e.split_once('e').unwrap_or((&e, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let s = if (-4..7).contains(&exp) {
        let decimals = (digits as i32 - 1 - exp).max(0) as usize;
        trim(&format!("{:.*}", decimals, x))
    } else {
        format!("{}e{}", trim(mant), exp)
    };
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        "0".into()
    } else {
        s
    }
}

/// `x` as [`num`], but shown as `0` when $|x| \le 10^{-12}\,$`scale`: for quantities that
/// vanish in exact arithmetic (antisymmetric stresses on the axis, say), whose rounding
/// residue would otherwise differ between machines.
#[must_use]
pub fn num_scaled(x: f64, scale: f64) -> String {
    if x.abs() <= 1e-12 * scale.abs() {
        "0".into()
    } else {
        num(x)
    }
}

/// Relative differences below this are shown as `< 1e-10`: at that level they are rounding
/// and quadrature residue whose digits differ between machines.
pub const REL_FLOOR: f64 = 1e-10;

/// A relative difference with four significant digits and an explicit sign (`+1.234e-2`),
/// `0` for an exact match, `< 1e-10` below [`REL_FLOOR`].
#[must_use]
pub fn rel(x: f64) -> String {
    if x.is_nan() {
        return "n/a".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    if x.abs() < REL_FLOOR {
        return "< 1e-10".into();
    }
    let s = sig(x, 4);
    if s.starts_with('-') || s == "0" || s == "inf" {
        if s == "inf" {
            "+inf".into()
        } else {
            s
        }
    } else {
        format!("+{s}")
    }
}

/// A small error bound shown as the power of ten above it (`< 1e-14`), because its exact
/// value depends on the last bits of the platform's `libm`.
#[must_use]
pub fn bound(x: f64) -> String {
    if !x.is_finite() {
        return num(x);
    }
    if x == 0.0 {
        return "0".into();
    }
    let p = x.abs().log10().floor() as i32 + 1;
    format!("< 1e{p}")
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats() {
        assert_eq!(num(1.026088272145), "1.026088272");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(0.0053), "0.0053");
        assert_eq!(num(6.6196e-5), "6.6196e-5");
        assert_eq!(num(986.389961234567), "986.3899612");
        assert_eq!(num(-1.0e-20), "-1e-20");
        assert_eq!(num(12345678.9), "1.23456789e7");
        assert_eq!(rel(0.0141), "+0.0141");
        assert_eq!(rel(-2.29e-5), "-2.29e-5");
        assert_eq!(rel(2.2e-16), "< 1e-10");
        assert_eq!(num_scaled(1e-18, 1.0), "0");
        assert_eq!(bound(3e-16), "< 1e-15");
        assert_eq!(num(f64::INFINITY), "inf");
    }
}

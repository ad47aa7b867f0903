//! Fixed number formatting and Markdown tables, so that the generated pages are
//! byte-for-byte reproducible (the `current` test compares them with the committed files).

/// `x` to `digits` significant digits, `%g`-style: fixed notation for exponents in
/// $[-4, \text{digits})$, scientific otherwise; trailing zeros trimmed; $-0$ printed as `0`.
#[must_use]
pub fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".to_owned();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = digits.max(1);
    let s = format!("{:.*e}", digits - 1, x);
    let (mant, exp) = s.split_once('e').unwrap_or((s.as_str(), "0"));
    let e: i32 = exp.parse().unwrap_or(0);
    if (-4..digits as i32).contains(&e) {
        let decimals = (digits as i32 - 1 - e).max(0) as usize;
        trim_zeros(format!("{x:.decimals$}"))
    } else {
        format!("{}e{e}", trim_zeros(mant.to_owned()))
    }
}

fn trim_zeros(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

/// A value: 10 significant digits.
#[must_use]
pub fn num(x: f64) -> String {
    sig(x, 10)
}

/// An error or a small difference: 2 significant digits.
#[must_use]
pub fn err(x: f64) -> String {
    sig(x, 2)
}

/// Relative level below which a residual is rounding noise: $10^{-13} \approx 450\,\epsilon$.
///
/// A residual computed in `f64` by a closed form (a few ulp), by adaptive quadrature (the
/// rounding of a few hundred weighted terms) or by a solver's long sums carries noise of a
/// few to a few hundred ulp, and that noise changes with any reordering of the arithmetic in
/// a physics crate. The measured residuals of the checks in this book are below $10^{-13}$
/// except where they are cancellation-limited, and those call [`resid`] with a scale.
pub const ROUNDING: f64 = 1e-13;

/// A residual: a quantity that vanishes in exact arithmetic (a closed form minus an
/// independent evaluation, an identity, an equilibrium or complementarity defect),
/// measured against `scale` (1 for a relative difference; the size of the quantity for an
/// absolute one; the condition number $\kappa$ where cancellation amplifies the rounding).
///
/// At rounding level, $|x| <$ [`ROUNDING`] $\times|\text{scale}|$, the page shows the bound
/// `< 1e-13` (for a scale other than 1: the smallest power of ten above
/// $10^{-13}|\text{scale}|$), so that a harmless change of the last bits does not change the
/// page; above it, two significant digits as [`err`]. The sign is dropped for the bound.
#[must_use]
pub fn resid(x: f64, scale: f64) -> String {
    if x.is_nan() {
        return "NaN".to_owned();
    }
    let level = ROUNDING * scale.abs();
    if x.abs() < level {
        format!("< {}", sig(pow10_at_least(level), 1))
    } else {
        err(x)
    }
}

/// The smallest power of ten $\ge v$ ($v > 0$ finite), exact in its decimal form. A `v` within
/// a few ulp above a power of ten (e.g. `1e-13 * 100.0` = 1.0000000000000002e-11) counts as
/// that power, so the bound does not jump a decade on rounding.
fn pow10_at_least(v: f64) -> f64 {
    let p = |e: i32| format!("1e{e}").parse::<f64>().unwrap_or(f64::INFINITY);
    let v = v * (1.0 - 8.0 * f64::EPSILON);
    let mut e = v.log10().ceil() as i32;
    while p(e) < v {
        e += 1;
    }
    while p(e - 1) >= v {
        e -= 1;
    }
    p(e)
}

/// A value that is zero in exact arithmetic may come out as rounding noise: print `≈ 0`
/// when $|x| \le 10^{-12}\,$`scale`, so that the page does not depend on the last bits.
#[must_use]
pub fn num_or_zero(x: f64, scale: f64) -> String {
    if x.abs() <= 1e-12 * scale.abs() {
        "≈ 0".to_owned()
    } else {
        num(x)
    }
}

/// A relative difference in per cent, 4 significant digits, with an explicit sign.
#[must_use]
pub fn pct(x: f64) -> String {
    let s = sig(100.0 * x, 4);
    if s.starts_with('-') || s == "0" {
        format!("{s} %")
    } else {
        format!("+{s} %")
    }
}

/// A Markdown table.
#[derive(Debug, Clone, Default)]
pub struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with these column titles.
    #[must_use]
    pub fn new(header: &[&str]) -> Self {
        Self { header: header.iter().map(|s| (*s).to_owned()).collect(), rows: Vec::new() }
    }

    /// Append a row (missing cells are left empty).
    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }

    /// The table as GitHub-flavoured Markdown, ending with a blank line.
    #[must_use]
    pub fn render(&self) -> String {
        let n = self.header.len();
        let line = |cells: &[String]| {
            let mut s = String::from("|");
            for i in 0..n {
                s.push(' ');
                s.push_str(cells.get(i).map_or("", String::as_str));
                s.push_str(" |");
            }
            s.push('\n');
            s
        };
        let mut out = line(&self.header);
        out.push('|');
        for _ in 0..n {
            out.push_str("---|");
        }
        out.push('\n');
        for r in &self.rows {
            out.push_str(&line(r));
        }
        out.push('\n');
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats() {
        assert_eq!(sig(1.0260883, 4), "1.026");
        assert_eq!(sig(-0.0, 10), "0");
        assert_eq!(sig(9.99999999999, 10), "10");
        assert_eq!(sig(0.00052807, 5), "0.00052807");
        assert_eq!(sig(3.2e-16, 2), "3.2e-16");
        assert_eq!(sig(986.39e6, 5), "9.8639e8");
        assert_eq!(pct(-0.014), "-1.4 %");
        assert_eq!(pct(0.0055), "+0.55 %");
    }

    #[test]
    fn residuals() {
        assert_eq!(resid(2.2e-16, 1.0), "< 1e-13");
        assert_eq!(resid(-9.9e-14, 1.0), "< 1e-13");
        assert_eq!(resid(0.0, 1.0), "< 1e-13");
        assert_eq!(resid(1.0e-13, 1.0), "1e-13");
        assert_eq!(resid(-2.4e-12, 1.0), "-2.4e-12");
        // Scaled: bound is the power of ten above 1e-13 * scale.
        assert_eq!(resid(3.4e-10, 144721.0), "< 1e-7");
        assert_eq!(resid(3.4e-10, 10000.0), "< 1e-9");
        assert_eq!(resid(2.0e-19, 0.0045), "< 1e-15");
        assert_eq!(resid(f64::NAN, 1.0), "NaN");
        assert_eq!(pow10_at_least(1e-13), 1e-13);
        // One ulp above a power of ten is that power (rounding of 1e-13 * scale), while a
        // value clearly above it moves up a decade.
        assert_eq!(pow10_at_least(1.0000000000000002e-13), 1e-13);
        assert_eq!(pow10_at_least(1e-13 * 100.0), 1e-11);
        assert_eq!(pow10_at_least(1.001e-13), 1e-12);
        assert_eq!(pow10_at_least(0.999e-3), 1e-3);
    }
}

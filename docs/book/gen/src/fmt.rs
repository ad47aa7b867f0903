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
}

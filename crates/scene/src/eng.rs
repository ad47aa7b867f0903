//! Quantities written for people to read: an SI prefix chosen per value and four significant
//! digits (`75.00 µm`, `863.4 MPa`, `0.01459 mm²`). This is the one formatter of the terminal
//! summary, `stickslip explain`, report.html and error messages; files meant for programs
//! (result.json, CSV, NPY) keep SI values at full precision and never go through it.
//!
//! Rules:
//! - The value is first rounded to four significant digits, then the prefix is chosen for the
//!   rounded value, so 999.96 µm is written 1.000 mm, not 1000 µm.
//! - The prefix attaches to the first atom of the unit and is raised to that atom's power: a
//!   plain unit (`m`, `Pa`, `N/m`, `J/m^2`) gets the prefix that puts the number in
//!   [1, 1000); a unit whose first atom is squared (`m^2`, `m²`) gets the prefix that puts the
//!   number in [0.001, 1000), i.e. one step of a squared prefix (`0.01459 mm²`,
//!   `250.0 µm²`), and a cubed one [1e-6, 1000).
//! - Prefixes run from femto (1e-15) to tera (1e12) of the base atom; beyond them the number
//!   is written in scientific notation with four significant digits (`1.000e-21 m`).
//! - Zero (either sign) is `0 unit`; NaN and infinities are written as such (`NaN Pa`,
//!   `-inf N`).
//! - [`eng_scaled`] writes a value whose magnitude is below [`ZERO_RELATIVE`] times the
//!   quantity's characteristic scale as `0 unit`: a tangential force of 3.8e-14 N in a run
//!   whose normal load is 100 N is rounding, not a force.

/// Magnitudes below this fraction of a quantity's scale are written as zero by [`eng_scaled`].
pub const ZERO_RELATIVE: f64 = 1e-12;

const PREFIXES: [&str; 10] = ["f", "p", "n", "µ", "m", "", "k", "M", "G", "T"];
/// Power of 1000 of the first entry of [`PREFIXES`].
const FIRST: i32 = -5;

/// Splits `unit` into its first atom's power and writes the unit with `prefix` on that atom.
fn power_of_first_atom(unit: &str) -> i32 {
    let first = unit.split(['/', ' ', '*', '·']).next().unwrap_or("");
    if first.ends_with('²') {
        2
    } else if first.ends_with('³') {
        3
    } else if let Some((_, p)) = first.split_once('^') {
        p.parse::<i32>().ok().filter(|p| (1..=3).contains(p)).unwrap_or(1)
    } else {
        1
    }
}

/// `v` rounded to four significant digits.
fn round4(v: f64) -> f64 {
    // f64::MAX rounds up to 1.798e308, past the largest double: keep the value then
    format!("{v:.3e}").parse::<f64>().ok().filter(|r| r.is_finite()).unwrap_or(v)
}

/// Decimals that give `m` (a rounded mantissa) four significant digits.
fn decimals(m: f64) -> usize {
    (3 - (m.abs().log10() + 1e-9).floor() as i32).max(0) as usize
}

/// `v` in `unit` with an SI prefix chosen per value and four significant digits (see the
/// module's rules): `eng(7.5e-5, "m")` is "75.00 µm", `eng(1.459e-8, "m^2")` is
/// "0.01459 mm^2".
pub fn eng(v: f64, unit: &str) -> String {
    let sep = if unit.is_empty() { "" } else { " " };
    if v.is_nan() {
        return format!("NaN{sep}{unit}");
    }
    if v.is_infinite() {
        return format!("{}inf{sep}{unit}", if v < 0.0 { "-" } else { "" });
    }
    if v == 0.0 {
        return format!("0{sep}{unit}");
    }
    let r = round4(v);
    if unit.is_empty() {
        // a pure number: no prefix; plain digits where they read well
        let a = r.abs();
        if (1e-4..1e6).contains(&a) {
            return format!("{r:.*}", decimals(r));
        }
        return format!("{r:.3e}");
    }
    let n = power_of_first_atom(unit);
    let e = (((r.abs().log10() - 3.0) / (3 * n) as f64).floor() as i32 + 1).max(i32::MIN / 8);
    if !(FIRST..FIRST + PREFIXES.len() as i32).contains(&e) {
        return format!("{r:.3e} {unit}");
    }
    let mut m = r / 10f64.powi(3 * n * e);
    // the division may leave the last bit off a round value: 99.99999999999999 is 100
    m = round4(m);
    format!("{m:.*} {}{unit}", decimals(m), PREFIXES[(e - FIRST) as usize])
}

/// The one SI prefix for a set of values whose largest magnitude is `maxabs` (a plot axis or
/// a colour scale, where every tick shares the unit): the divisor and the prefixed unit,
/// with the prefix rules of [`eng`] (femto to tera, squared and cubed first atoms). An empty
/// unit (a ratio), a zero or a non-finite `maxabs` gets no prefix.
pub fn common_prefix(maxabs: f64, unit: &str) -> (f64, String) {
    if unit.is_empty() || !(maxabs.is_finite() && maxabs > 0.0) {
        return (1.0, unit.to_string());
    }
    let n = power_of_first_atom(unit);
    let e = (((maxabs.log10() - 3.0) / (3 * n) as f64).floor() as i32 + 1)
        .clamp(FIRST, FIRST + PREFIXES.len() as i32 - 1);
    (10f64.powi(3 * n * e), format!("{}{unit}", PREFIXES[(e - FIRST) as usize]))
}

/// As [`eng`], but a value within [`ZERO_RELATIVE`] times `scale` of zero is written `0 unit`.
/// `scale` is the characteristic magnitude of the quantity in the run (the normal load for
/// forces, the peak pressure for stresses, the contact size for lengths, ...).
pub fn eng_scaled(v: f64, scale: f64, unit: &str) -> String {
    if v.is_finite() && scale.is_finite() && v.abs() <= ZERO_RELATIVE * scale.abs() {
        return eng(0.0, unit);
    }
    eng(v, unit)
}

/// `v` as [`eng`] writes it, or in full (`1.0000001e3 N`) when that would read the same as
/// one of `bounds`: a value refused against a bound must not print as the bound itself.
pub fn eng_beside(v: f64, bounds: &[f64], unit: &str) -> String {
    let found = eng(v, unit);
    if bounds.iter().any(|&b| eng(b, unit) == found) {
        let sep = if unit.is_empty() { "" } else { " " };
        return format!("{v:e}{sep}{unit}");
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_beside_its_bound_is_written_in_full() {
        assert_eq!(eng_beside(2.2e-6, &[1.986e-6], "N"), "2.200 µN");
        assert_eq!(eng_beside(1.00001e3, &[1e3], "N"), "1.00001e3 N");
        assert_eq!(eng_beside(0.50001, &[0.1, 0.5], ""), "5.0001e-1");
    }

    #[test]
    fn common_prefixes() {
        assert_eq!(common_prefix(7.5e-5, "m"), (1e-6, "µm".to_string()));
        assert_eq!(common_prefix(8.6e8, "Pa"), (1e6, "MPa".to_string()));
        assert_eq!(common_prefix(999.0, "N"), (1.0, "N".to_string()));
        assert_eq!(common_prefix(1000.0, "N"), (1e3, "kN".to_string()));
        // a squared first atom takes one step of a squared prefix: 0.01459 mm^2
        assert_eq!(common_prefix(1.459e-8, "m^2"), (1e-6, "mm^2".to_string()));
        assert_eq!(common_prefix(0.5, "").1, "");
        assert_eq!(common_prefix(0.0, "m"), (1.0, "m".to_string()));
        // beyond tera the largest prefix is kept (the ticks carry the rest)
        assert_eq!(common_prefix(1e20, "Pa").1, "TPa");
    }

    #[test]
    fn plain_units() {
        assert_eq!(eng(7.5e-5, "m"), "75.00 µm");
        assert_eq!(eng(8.633969e8, "Pa"), "863.4 MPa");
        assert_eq!(eng(1.0, "N"), "1.000 N");
        assert_eq!(eng(2.5e-4, "m"), "250.0 µm");
        assert_eq!(eng(1.2e9, "Pa"), "1.200 GPa");
        assert_eq!(eng(12.345, "N/m"), "12.35 N/m");
        assert_eq!(eng(0.5, "J/m^2"), "500.0 mJ/m^2");
        assert_eq!(eng(3.0e3, "N m"), "3.000 kN m");
    }

    #[test]
    fn rounding_up_to_the_next_prefix() {
        assert_eq!(eng(999.96e-6, "m"), "1.000 mm");
        assert_eq!(eng(999.94e-6, "m"), "999.9 µm");
        assert_eq!(eng(9.9996, "N"), "10.00 N");
        assert_eq!(eng(99.996, "N"), "100.0 N");
        assert_eq!(eng(999_960.0, "Pa"), "1.000 MPa");
        assert_eq!(eng(-999.96e-6, "m"), "-1.000 mm");
    }

    #[test]
    fn negatives_and_zero() {
        assert_eq!(eng(-3.833e-14, "N"), "-38.33 fN");
        assert_eq!(eng(-0.0, "N"), "0 N");
        assert_eq!(eng(0.0, "m^2"), "0 m^2");
        assert_eq!(eng_scaled(-3.833e-14, 100.0, "N"), "0 N");
        assert_eq!(eng_scaled(-1.01e-10, 100.0, "N"), "-101.0 pN");
        assert_eq!(eng_scaled(1e-10, 100.0, "N"), "0 N");
        assert_eq!(eng_scaled(f64::NAN, 100.0, "N"), "NaN N");
    }

    #[test]
    fn not_finite() {
        assert_eq!(eng(f64::NAN, "Pa"), "NaN Pa");
        assert_eq!(eng(f64::INFINITY, "Pa"), "inf Pa");
        assert_eq!(eng(f64::NEG_INFINITY, "N"), "-inf N");
    }

    #[test]
    fn beyond_the_prefix_table() {
        assert_eq!(eng(1e-21, "m"), "1.000e-21 m");
        assert_eq!(eng(1e-15, "m"), "1.000 fm");
        assert_eq!(eng(9.9996e-16, "m"), "1.000 fm");
        assert_eq!(eng(9.9994e-16, "m"), "9.999e-16 m");
        assert_eq!(eng(999.9e12, "Pa"), "999.9 TPa");
        assert_eq!(eng(1e15, "Pa"), "1.000e15 Pa");
        assert_eq!(eng(f64::MAX, "N"), "1.798e308 N");
        assert_eq!(eng(5e-324, "N"), "4.941e-324 N");
    }

    #[test]
    fn squared_and_cubed_units() {
        assert_eq!(eng(1.459e-8, "m²"), "0.01459 mm²");
        assert_eq!(eng(1.459e-8, "m^2"), "0.01459 mm^2");
        assert_eq!(eng(2.5e-10, "m²"), "250.0 µm²");
        assert_eq!(eng(1e-9, "m²"), "0.001000 mm²");
        assert_eq!(eng(3.0, "m²"), "3.000 m²");
        assert_eq!(eng(1.0e-3, "m²"), "0.001000 m²");
        assert_eq!(eng(9.9996e-4, "m²"), "0.001000 m²");
        assert_eq!(eng(9.9994e-4, "m²"), "999.9 mm²");
        assert_eq!(eng(2.0e-9, "m^3"), "2.000 mm^3");
        assert_eq!(eng(2.0e-12, "m^3"), "0.002000 mm^3");
        assert_eq!(eng(5.0e-40, "m^2"), "5.000e-40 m^2");
    }

    #[test]
    fn pure_numbers() {
        assert_eq!(eng(0.3, ""), "0.3000");
        assert_eq!(eng(1234.6, ""), "1235");
        assert_eq!(eng(1e-7, ""), "1.000e-7");
    }
}

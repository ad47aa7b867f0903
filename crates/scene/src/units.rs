//! Quantities with units, as scenes write them (`"2160 lbf"`, `"30e6 psi"`,
//! `"1767600 kgf/m^2.1"`), converted to SI.
//!
//! A unit expression is a product of atoms separated by `/` (everything after the first `/`
//! is in the denominator, as engineers write `N/m`, `kgf/m^2.1`), each atom optionally raised
//! to a real power with `^`. Each atom has an SI factor and a dimension over the base
//! (force, length, time); the expression's dimension must equal the dimension the key
//! expects, so `"10 psi"` is refused where a length is expected.

use std::fmt;

/// Dimension as exponents of force, length and time. Real exponents are needed for the
/// graded modulus, whose unit is force / length^(2+k).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dim {
    /// Exponent of force.
    pub force: f64,
    /// Exponent of length.
    pub length: f64,
    /// Exponent of time.
    pub time: f64,
}

impl Dim {
    const fn new(force: f64, length: f64, time: f64) -> Self {
        Self { force, length, time }
    }
    /// No dimension (a pure number).
    pub const NONE: Dim = Dim::new(0.0, 0.0, 0.0);
    /// Reciprocal time (an angular velocity in rad/s).
    pub const PER_TIME: Dim = Dim::new(0.0, 0.0, -1.0);
    /// Length (m).
    pub const LENGTH: Dim = Dim::new(0.0, 1.0, 0.0);
    /// Force (N).
    pub const FORCE: Dim = Dim::new(1.0, 0.0, 0.0);
    /// Force per unit length (N/m), the load of a 2D contact.
    pub const FORCE_PER_LENGTH: Dim = Dim::new(1.0, -1.0, 0.0);
    /// Stress or modulus (Pa).
    pub const STRESS: Dim = Dim::new(1.0, -2.0, 0.0);
    /// Moment (N m).
    pub const MOMENT: Dim = Dim::new(1.0, 1.0, 0.0);
    /// Time (s).
    pub const TIME: Dim = Dim::new(0.0, 0.0, 1.0);
    /// Speed (m/s).
    pub const SPEED: Dim = Dim::new(0.0, 1.0, -1.0);
    /// Reciprocal length (1/m), e.g. the spin creepage of rolling.
    pub const PER_LENGTH: Dim = Dim::new(0.0, -1.0, 0.0);

    /// The graded modulus E0 of E = E0 y^k: force / length^(2+k).
    pub fn graded_modulus(k: f64) -> Dim {
        Dim::new(1.0, -(2.0 + k), 0.0)
    }

    fn scaled(self, p: f64) -> Dim {
        Dim::new(self.force * p, self.length * p, self.time * p)
    }

    fn plus(self, o: Dim) -> Dim {
        Dim::new(self.force + o.force, self.length + o.length, self.time + o.time)
    }

    fn close_to(self, o: Dim) -> bool {
        const EPS: f64 = 1e-12;
        (self.force - o.force).abs() < EPS
            && (self.length - o.length).abs() < EPS
            && (self.time - o.time).abs() < EPS
    }
}

impl fmt::Display for Dim {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut num = Vec::new();
        let mut den = Vec::new();
        for (e, s) in [(self.force, "N"), (self.length, "m"), (self.time, "s")] {
            let target = if e > 0.0 { &mut num } else { &mut den };
            let a = e.abs();
            if a == 0.0 {
                continue;
            }
            if a == 1.0 {
                target.push(s.to_string());
            } else {
                target.push(format!("{s}^{a}"));
            }
        }
        match (num.is_empty(), den.is_empty()) {
            (true, true) => write!(f, "1 (dimensionless)"),
            (false, true) => write!(f, "{}", num.join(" ")),
            (true, false) => write!(f, "1/{}", den.join(" ")),
            (false, false) => write!(f, "{}/{}", num.join(" "), den.join(" ")),
        }
    }
}

/// Why a quantity string was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum UnitError {
    /// The number part did not parse.
    #[error("'{text}' does not start with a number (write e.g. \"2160 lbf\" or \"30e6 psi\")")]
    BadNumber {
        /// The whole quantity as written.
        text: String,
    },
    /// An atom is not a known unit.
    #[error("unknown unit '{unit}' in '{text}'{}", unknown_tail(.suggestions, .known))]
    UnknownUnit {
        /// The unrecognised atom.
        unit: String,
        /// The whole quantity as written.
        text: String,
        /// The list of accepted atoms.
        known: &'static str,
        /// Units that differ from `unit` only in letter case ("Mn": "mN", "MN").
        suggestions: Vec<String>,
    },
    /// The unit expression is malformed (e.g. `N//m`, `m^`).
    #[error("malformed unit expression '{unit}' in '{text}': {why}")]
    Malformed {
        /// The unit part.
        unit: String,
        /// The whole quantity as written.
        text: String,
        /// What is wrong.
        why: &'static str,
    },
    /// The unit has the wrong dimension for the key.
    #[error("'{text}' has dimension {found}, but a {expected_name} ({expected}) is expected here")]
    WrongDimension {
        /// The whole quantity as written.
        text: String,
        /// Its dimension.
        found: Dim,
        /// The expected dimension.
        expected: Dim,
        /// A word for what was expected ("length", "stress" ...).
        expected_name: &'static str,
    },
    /// The value is not finite.
    #[error("'{text}' is not a finite number")]
    NotFinite {
        /// The whole quantity as written.
        text: String,
    },
}

/// "'mN' or 'MN'" / "'kN'" for a list of suggestions.
fn or_list(s: &[String]) -> String {
    let q: Vec<String> = s.iter().map(|u| format!("'{u}'")).collect();
    match q.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
    }
}

fn unknown_tail(suggestions: &[String], known: &str) -> String {
    if suggestions.is_empty() {
        format!("; known units: {known}")
    } else {
        format!(
            ": did you mean {}? (units are case-sensitive: m is milli, M is mega)",
            or_list(suggestions)
        )
    }
}

impl UnitError {
    /// A hint naming the intended unit, when the unit was a near miss (a wrong letter case).
    pub fn suggestion(&self) -> Option<String> {
        match self {
            UnitError::UnknownUnit { suggestions, .. } if !suggestions.is_empty() => {
                Some(format!("did you mean {}?", or_list(suggestions)))
            }
            _ => None,
        }
    }
}

/// The atoms a unit expression may use, for error messages.
pub const KNOWN_UNITS: &str = "m N Pa s, each with an SI prefix p n u (or µ) m c k M G \
     (mm, um, nm, mN, kN, MPa, GPa, ms ...); in ft lbf kgf psi ksi min h; rad and a bare 1 \
     (1/m)";

/// Newtons in one pound-force (exact by definition: 0.45359237 kg x 9.80665 m/s^2).
pub const LBF: f64 = 0.45359237 * 9.80665;
/// Newtons in one kilogram-force (exact by definition).
pub const KGF: f64 = 9.80665;
/// Metres in one inch (exact by definition).
pub const INCH: f64 = 0.0254;

/// The SI prefixes a base unit may carry: symbol, power of ten, factor. Micro is written
/// `u`, `µ` (the micro sign) or `μ` (the Greek letter mu).
pub const PREFIXES: [(&str, i32, f64); 10] = [
    ("p", -12, 1e-12),
    ("n", -9, 1e-9),
    ("u", -6, 1e-6),
    ("µ", -6, 1e-6),
    ("μ", -6, 1e-6),
    ("m", -3, 1e-3),
    ("c", -2, 1e-2),
    ("k", 3, 1e3),
    ("M", 6, 1e6),
    ("G", 9, 1e9),
];

/// The units that take an SI prefix: metre, newton, pascal, second, joule.
pub const PREFIXABLE: [(&str, Dim); 5] = [
    ("m", Dim::LENGTH),
    ("N", Dim::FORCE),
    ("Pa", Dim::STRESS),
    ("s", Dim::TIME),
    ("J", Dim::MOMENT),
];

/// The units that take no prefix, with their SI factor and dimension.
pub const PLAIN: [(&str, f64, Dim); 10] = [
    // A bare `1` (as in `1/m`) and the radian are pure numbers.
    ("1", 1.0, Dim::NONE),
    ("rad", 1.0, Dim::NONE),
    ("in", INCH, Dim::LENGTH),
    ("ft", 12.0 * INCH, Dim::LENGTH),
    ("lbf", LBF, Dim::FORCE),
    ("kgf", KGF, Dim::FORCE),
    ("psi", LBF / (INCH * INCH), Dim::STRESS),
    ("ksi", 1e3 * LBF / (INCH * INCH), Dim::STRESS),
    ("min", 60.0, Dim::TIME),
    ("h", 3600.0, Dim::TIME),
];

/// Every atom name: the plain units, and each prefixable unit with and without each prefix.
pub fn all_atoms() -> Vec<String> {
    let mut v: Vec<String> = PLAIN.iter().map(|(n, _, _)| (*n).to_string()).collect();
    for (b, _) in PREFIXABLE {
        v.push(b.to_string());
        for (p, _, _) in PREFIXES {
            v.push(format!("{p}{b}"));
        }
    }
    v
}

fn atom(name: &str) -> Option<(f64, Dim)> {
    if let Some((_, f, d)) = PLAIN.iter().find(|(n, _, _)| *n == name) {
        return Some((*f, *d));
    }
    let base = |b: &str| PREFIXABLE.iter().find(|(n, _)| *n == b).map(|(_, d)| *d);
    if let Some(d) = base(name) {
        return Some((1.0, d));
    }
    // No name is both a base unit and a prefixed one, so the first prefix that fits is the one.
    PREFIXES.iter().find_map(|(p, _, f)| Some((*f, base(name.strip_prefix(p)?)?)))
}

/// What an unknown atom was probably meant to be: the units that equal it but for letter
/// case ("Mn": "mN" and "MN"; micro written `u`), and a product of two units written without
/// the space between them ("Nm": "N m").
fn near_misses(name: &str) -> Vec<String> {
    let lower = name.to_lowercase();
    let mut v: Vec<String> = all_atoms()
        .into_iter()
        .filter(|a| !a.starts_with(['µ', 'μ']) && a.to_lowercase() == lower)
        .collect();
    for (i, _) in name.char_indices().skip(1) {
        let (a, b) = name.split_at(i);
        if atom(a).is_some() && atom(b).is_some() && a != "1" && b != "1" {
            v.push(format!("{a} {b}"));
        }
    }
    v
}

/// Parse a unit expression such as `kgf/m^2.1` or `cm/s` into (SI factor, dimension).
pub fn parse_unit(unit: &str, text: &str) -> Result<(f64, Dim), UnitError> {
    let malformed =
        |why| UnitError::Malformed { unit: unit.to_string(), text: text.to_string(), why };
    let mut factor = 1.0;
    let mut dim = Dim::NONE;
    for (i, part) in unit.split('/').enumerate() {
        let part = part.trim();
        if part.is_empty() {
            return Err(malformed("empty factor around '/'"));
        }
        let sign = if i == 0 { 1.0 } else { -1.0 };
        for word in part.split(['*', ' ', '·']).filter(|w| !w.is_empty()) {
            let (name, power) = match word.split_once('^') {
                None => (word, 1.0),
                Some((n, p)) => {
                    let p: f64 =
                        p.parse().map_err(|_| malformed("'^' must be followed by a number"))?;
                    if !p.is_finite() {
                        return Err(malformed("the power must be finite"));
                    }
                    (n, p)
                }
            };
            let (f, d) = atom(name).ok_or_else(|| UnitError::UnknownUnit {
                unit: name.to_string(),
                text: text.to_string(),
                known: KNOWN_UNITS,
                suggestions: near_misses(name),
            })?;
            factor *= f.powf(sign * power);
            dim = dim.plus(d.scaled(sign * power));
        }
    }
    Ok((factor, dim))
}

/// Parse `"<number> <unit>"` and convert to SI, checking the dimension.
///
/// A bare number string (`"0.3"`) is taken as SI. `expected_name` is the word used in the
/// error message ("length", "stress", ...).
pub fn parse_quantity(
    text: &str,
    expected: Dim,
    expected_name: &'static str,
) -> Result<f64, UnitError> {
    let t = text.trim();
    // The number is the longest prefix that parses as f64.
    let split = t.find(|c: char| c.is_whitespace()).unwrap_or_else(|| {
        // no space: "10psi" — split at the first alphabetic character that cannot be part of a number
        t.char_indices()
            .find(|&(i, c)| {
                c.is_alphabetic()
                    && !(matches!(c, 'e' | 'E')
                        && t[..i].chars().any(|d| d.is_ascii_digit())
                        && t[i + 1..]
                            .starts_with(|n: char| n.is_ascii_digit() || n == '-' || n == '+'))
            })
            .map_or(t.len(), |(i, _)| i)
    });
    let (num, unit) = t.split_at(split);
    let value: f64 =
        num.trim().parse().map_err(|_| UnitError::BadNumber { text: text.to_string() })?;
    if !value.is_finite() {
        return Err(UnitError::NotFinite { text: text.to_string() });
    }
    let unit = unit.trim();
    let (factor, dim) = if unit.is_empty() { (1.0, expected) } else { parse_unit(unit, text)? };
    if !dim.close_to(expected) {
        return Err(UnitError::WrongDimension {
            text: text.to_string(),
            found: dim,
            expected,
            expected_name,
        });
    }
    Ok(value * factor)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn conversions_match_definitions() {
        // NIST SP 811: 1 lbf = 4.448 221 615 260 5 N; 1 psi = 6 894.757 293 168 Pa.
        assert!(
            rel(parse_quantity("1 lbf", Dim::FORCE, "force").unwrap(), 4.4482216152605) < 1e-15
        );
        assert!(
            rel(parse_quantity("1 psi", Dim::STRESS, "stress").unwrap(), 6894.757293168361) < 1e-14
        );
        assert!(
            rel(parse_quantity("30e6 psi", Dim::STRESS, "stress").unwrap(), 2.0684271879505e11)
                < 1e-13
        );
        assert_eq!(parse_quantity("1 in", Dim::LENGTH, "length").unwrap(), 0.0254);
        assert!(rel(parse_quantity("10 cm/s", Dim::SPEED, "speed").unwrap(), 0.1) < 1e-15);
        assert!(
            rel(parse_quantity("2 ksi", Dim::STRESS, "stress").unwrap(), 2e3 * 6894.757293168361)
                < 1e-14
        );
        assert!(
            rel(parse_quantity("5 kN/m", Dim::FORCE_PER_LENGTH, "load per length").unwrap(), 5e3)
                < 1e-15
        );
        assert!(rel(parse_quantity("3 ms", Dim::TIME, "time").unwrap(), 3e-3) < 1e-15);
        assert!(rel(parse_quantity("250um", Dim::LENGTH, "length").unwrap(), 250e-6) < 1e-15);
        assert!(rel(parse_quantity("1.5e-3m", Dim::LENGTH, "length").unwrap(), 1.5e-3) < 1e-15);
    }

    #[test]
    fn reciprocal_lengths() {
        let per_m = |t| parse_quantity(t, Dim::PER_LENGTH, "reciprocal length");
        assert_eq!(per_m("0.1 1/m").unwrap(), 0.1);
        assert!(rel(per_m("0.1 1/mm").unwrap(), 100.0) < 1e-15);
        assert!(rel(per_m("2 rad/m").unwrap(), 2.0) < 1e-15);
        assert!(matches!(per_m("0.1 m"), Err(UnitError::WrongDimension { .. })));
        assert!(matches!(per_m("0.1 2/m"), Err(UnitError::UnknownUnit { .. })));
    }

    #[test]
    fn graded_modulus_unit() {
        // 1767600 kgf/m^2.1 is E0 of seed 000's Table 1 (FORMULAS.md A4: kgf/m^(2+k)).
        let v = parse_quantity("1767600 kgf/m^2.1", Dim::graded_modulus(0.1), "graded modulus")
            .unwrap();
        assert!(rel(v, 1767600.0 * KGF) < 1e-15);
        // The same number with the wrong exponent for k = 0.1 is refused.
        let e = parse_quantity("1767600 kgf/m^2", Dim::graded_modulus(0.1), "graded modulus")
            .unwrap_err();
        assert!(matches!(e, UnitError::WrongDimension { .. }), "{e}");
        // psi per inch^0.5 for k = 0.5: lbf/in^2.5
        let v = parse_quantity("1 lbf/in^2.5", Dim::graded_modulus(0.5), "graded modulus").unwrap();
        assert!(rel(v, LBF / INCH.powf(2.5)) < 1e-14);
    }

    #[test]
    fn bad_quantities_say_what_is_wrong() {
        let cases: [(&str, Dim); 7] = [
            ("abc", Dim::LENGTH),
            ("10 furlong", Dim::LENGTH),
            ("10 psi", Dim::LENGTH),
            ("10 N//m", Dim::FORCE_PER_LENGTH),
            ("10 m^", Dim::LENGTH),
            ("inf m", Dim::LENGTH),
            ("1e999 m", Dim::LENGTH),
        ];
        for (text, dim) in cases {
            let e = parse_quantity(text, dim, "length").unwrap_err();
            let msg = e.to_string();
            assert!(
                msg.contains(text.split_whitespace().next().unwrap_or(text)) || msg.contains(text),
                "{msg}"
            );
        }
        let msg = parse_quantity("10 furlong", Dim::LENGTH, "length").unwrap_err().to_string();
        assert!(msg.contains("furlong") && msg.contains("lbf"), "{msg}");
        let msg = parse_quantity("10 psi", Dim::LENGTH, "length").unwrap_err().to_string();
        assert!(msg.contains("length") && msg.contains("N/m^2"), "{msg}");
    }

    /// Every prefix on every prefixable unit, alone and in compound units, against the factor
    /// 10^exponent computed here from the exponent (not read from the table).
    #[test]
    fn every_prefix_on_every_unit_round_trips() {
        let mut count = 0;
        for (p, exp, _) in PREFIXES {
            let ten = 10f64.powi(exp);
            for (b, dim) in PREFIXABLE {
                let v = parse_quantity(&format!("2.5 {p}{b}"), dim, "q").unwrap();
                assert!(rel(v, 2.5 * ten) < 2e-16, "{p}{b}: {v}");
                // Without the space, as "250um" is written.
                let v = parse_quantity(&format!("2.5{p}{b}"), dim, "q").unwrap();
                assert!(rel(v, 2.5 * ten) < 2e-16, "2.5{p}{b}: {v}");
                count += 1;
            }
            let cases: [(String, Dim, f64); 6] = [
                (format!("3 {p}N/m"), Dim::FORCE_PER_LENGTH, 3.0 * ten),
                (format!("3 N/{p}m"), Dim::FORCE_PER_LENGTH, 3.0 / ten),
                (format!("3 {p}m/s"), Dim::SPEED, 3.0 * ten),
                (format!("3 1/{p}m"), Dim::PER_LENGTH, 3.0 / ten),
                (format!("3 N {p}m"), Dim::MOMENT, 3.0 * ten),
                (format!("3 kgf/{p}m^2.1"), Dim::graded_modulus(0.1), 3.0 * KGF / ten.powf(2.1)),
            ];
            for (text, dim, want) in cases {
                let v = parse_quantity(&text, dim, "q").unwrap();
                assert!(rel(v, want) < 1e-14, "{text}: {v} against {want}");
            }
        }
        assert_eq!(count, 50);
        // Work of adhesion (issue 32): energy per area.
        let w = parse_quantity("50 mJ/m^2", Dim::FORCE_PER_LENGTH, "q").unwrap();
        assert!(rel(w, 0.05) < 1e-15, "{w}");
        assert_eq!(parse_quantity("0.05 J/m^2", Dim::FORCE_PER_LENGTH, "q").unwrap(), 0.05);
        // The three spellings of micro are one prefix.
        for b in ["m", "N", "Pa", "s", "J"] {
            let d = atom(b).unwrap().1;
            let u = parse_quantity(&format!("7 u{b}"), d, "q").unwrap();
            assert_eq!(parse_quantity(&format!("7 \u{b5}{b}"), d, "q").unwrap(), u);
            assert_eq!(parse_quantity(&format!("7 \u{3bc}{b}"), d, "q").unwrap(), u);
        }
        // milli and mega stay apart.
        assert!(rel(parse_quantity("1 mN", Dim::FORCE, "q").unwrap(), 1e-3) < 1e-16);
        assert!(rel(parse_quantity("1 MN", Dim::FORCE, "q").unwrap(), 1e6) < 1e-16);
        assert!(rel(parse_quantity("1 mPa", Dim::STRESS, "q").unwrap(), 1e-3) < 1e-16);
        assert!(rel(parse_quantity("1 MPa", Dim::STRESS, "q").unwrap(), 1e6) < 1e-16);
    }

    /// The units without a prefix, against their definitions (NIST SP 811).
    #[test]
    fn plain_units_round_trip() {
        let want: [(&str, f64, Dim); 10] = [
            ("1", 1.0, Dim::NONE),
            ("rad", 1.0, Dim::NONE),
            ("in", 0.0254, Dim::LENGTH),
            ("ft", 0.3048, Dim::LENGTH),
            ("lbf", 4.4482216152605, Dim::FORCE),
            ("kgf", 9.80665, Dim::FORCE),
            ("psi", 6894.757293168361, Dim::STRESS),
            ("ksi", 6894757.293168361, Dim::STRESS),
            ("min", 60.0, Dim::TIME),
            ("h", 3600.0, Dim::TIME),
        ];
        assert_eq!(want.len(), PLAIN.len());
        for (name, si, dim) in want {
            let (f, d) = atom(name).unwrap();
            assert!(rel(f, si) < 1e-14 && d == dim, "{name}: {f} {d}");
        }
    }

    #[test]
    fn every_atom_has_one_meaning() {
        let all = all_atoms();
        assert_eq!(all.len(), PLAIN.len() + PREFIXABLE.len() * (PREFIXES.len() + 1));
        let mut seen = std::collections::BTreeSet::new();
        for a in &all {
            assert!(seen.insert(a.clone()), "{a} is listed twice");
            assert!(atom(a).is_some(), "{a}");
        }
    }

    #[test]
    fn near_misses_name_the_intended_unit() {
        let hint = |text: &str, dim: Dim| parse_quantity(text, dim, "q").unwrap_err();
        let cases: [(&str, Dim, &str); 8] = [
            ("1 Mn", Dim::FORCE, "did you mean 'mN' or 'MN'?"),
            ("1 KN", Dim::FORCE, "did you mean 'kN'?"),
            ("1 gpa", Dim::STRESS, "did you mean 'GPa'?"),
            ("1 mpa", Dim::STRESS, "did you mean 'mPa' or 'MPa'?"),
            ("1 UM", Dim::LENGTH, "did you mean 'um'?"),
            ("1 NM", Dim::LENGTH, "did you mean 'nm'?"),
            ("1 Nm", Dim::MOMENT, "did you mean 'nm' or 'N m'?"),
            ("1 PA", Dim::STRESS, "did you mean 'Pa'?"),
        ];
        for (text, dim, want) in cases {
            let e = hint(text, dim);
            assert_eq!(e.suggestion().as_deref(), Some(want), "{text}: {e}");
            assert!(e.to_string().contains(want), "{e}");
        }
        // Far misses and prefixes that are not supported: no guess, the list of units.
        for text in ["1 fm", "1 dm", "1 kkm", "1 Kpsi", "1 furlong", "1 parsec"] {
            let e = hint(text, Dim::LENGTH);
            assert!(matches!(e, UnitError::UnknownUnit { .. }), "{text}: {e}");
            assert_eq!(e.suggestion(), None, "{text}: {e}");
            assert!(e.to_string().contains("known units"), "{e}");
        }
    }

    #[test]
    fn bare_numbers_are_si() {
        assert_eq!(parse_quantity("0.3", Dim::LENGTH, "length").unwrap(), 0.3);
        assert_eq!(parse_quantity(" -2.5e3 ", Dim::FORCE, "force").unwrap(), -2500.0);
    }
}

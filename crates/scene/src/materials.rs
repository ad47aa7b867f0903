//! Named materials: `material = "steel"` in `[substrate]` or `[indenter]` instead of `e` and
//! `nu`.
//!
//! Each name stands for one grade (a material family spans a range: grey cast irons run from
//! about 65 to 160 GPa), and the values are the typical room-temperature, small-strain
//! values of that grade as materials handbooks and producers' data sheets give them. The
//! table here is the only copy in code; `docs/materials.md` prints it (a test keeps the two
//! the same), and `stickslip explain` prints the values a scene used.

/// One named material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// The name a scene writes (matched ignoring case, with `-` and `_` read as spaces).
    pub name: &'static str,
    /// Other names accepted for it (`"aluminum"`, `"WC"` ...).
    pub aliases: &'static [&'static str],
    /// Young's modulus (Pa).
    pub e: f64,
    /// Poisson's ratio.
    pub nu: f64,
    /// The grade the values are typical of, and how far other grades stray.
    pub grade: &'static str,
}

impl Material {
    /// Its elastic constants.
    pub fn elastic(&self) -> crate::Elastic {
        crate::Elastic { e: self.e, nu: self.nu }
    }
}

const GPA: f64 = 1e9;
const MPA: f64 = 1e6;

/// Every named material, metals first, then ceramics and glasses, polymers, elastomers.
pub const MATERIALS: &[Material] = &[
    Material {
        name: "steel",
        aliases: &["carbon steel", "bearing steel"],
        e: 210.0 * GPA,
        nu: 0.30,
        grade: "carbon and low-alloy steel (AISI 1045, 4140, bearing steel 52100); \
                steels of all grades lie within about 5%",
    },
    Material {
        name: "stainless steel",
        aliases: &["stainless"],
        e: 193.0 * GPA,
        nu: 0.29,
        grade: "austenitic stainless steel AISI 304 (1.4301)",
    },
    Material {
        name: "cast iron",
        aliases: &["grey cast iron", "gray cast iron"],
        e: 110.0 * GPA,
        nu: 0.26,
        grade: "grey cast iron, ASTM A48 class 30; grey irons range from about 65 to 160 GPa \
                by grade",
    },
    Material {
        name: "aluminium",
        aliases: &["aluminum", "aluminium alloy"],
        e: 69.0 * GPA,
        nu: 0.33,
        grade: "wrought aluminium alloy 6061-T6; other wrought alloys 68 to 73 GPa",
    },
    Material {
        name: "titanium",
        aliases: &["Ti-6Al-4V", "titanium alloy"],
        e: 114.0 * GPA,
        nu: 0.34,
        grade: "Ti-6Al-4V (grade 5), annealed; commercially pure titanium is about 105 GPa",
    },
    Material {
        name: "copper",
        aliases: &[],
        e: 117.0 * GPA,
        nu: 0.34,
        grade: "copper C11000 (electrolytic tough pitch), annealed",
    },
    Material {
        name: "brass",
        aliases: &[],
        e: 110.0 * GPA,
        nu: 0.35,
        grade: "cartridge brass C26000 (70/30); free-cutting brass is nearer 97 GPa",
    },
    Material {
        name: "bronze",
        aliases: &["phosphor bronze"],
        e: 110.0 * GPA,
        nu: 0.34,
        grade: "phosphor bronze C51000",
    },
    Material {
        name: "nickel",
        aliases: &[],
        e: 200.0 * GPA,
        nu: 0.31,
        grade: "commercially pure nickel (Nickel 200)",
    },
    Material {
        name: "gold",
        aliases: &[],
        e: 79.0 * GPA,
        nu: 0.42,
        grade: "pure gold, polycrystalline (contact pads, coatings)",
    },
    Material {
        name: "tungsten",
        aliases: &[],
        e: 411.0 * GPA,
        nu: 0.28,
        grade: "pure tungsten, polycrystalline",
    },
    Material {
        name: "tungsten carbide",
        aliases: &["WC", "carbide", "cemented carbide"],
        e: 620.0 * GPA,
        nu: 0.22,
        grade: "cemented carbide WC-6Co (6% cobalt binder); more cobalt lowers the modulus, \
                pure WC is about 700 GPa",
    },
    Material {
        name: "silicon nitride",
        aliases: &["Si3N4"],
        e: 310.0 * GPA,
        nu: 0.27,
        grade: "hot isostatically pressed Si3N4 of bearing-ball grade",
    },
    Material {
        name: "alumina",
        aliases: &["Al2O3", "aluminium oxide", "aluminum oxide"],
        e: 370.0 * GPA,
        nu: 0.22,
        grade: "99.5% alumina ceramic (sintered Al2O3)",
    },
    Material {
        name: "silicon carbide",
        aliases: &["SiC"],
        e: 410.0 * GPA,
        nu: 0.14,
        grade: "sintered alpha silicon carbide",
    },
    Material {
        name: "zirconia",
        aliases: &["ZrO2", "Y-TZP"],
        e: 205.0 * GPA,
        nu: 0.31,
        grade: "yttria-stabilised tetragonal zirconia (3Y-TZP)",
    },
    Material {
        name: "diamond",
        aliases: &[],
        e: 1141.0 * GPA,
        nu: 0.07,
        grade: "the isotropic values used for diamond tips in instrumented indentation",
    },
    Material {
        name: "silicon",
        aliases: &["polysilicon"],
        e: 160.0 * GPA,
        nu: 0.22,
        grade: "polycrystalline silicon (MEMS polysilicon); a single crystal is anisotropic, \
                130 to 188 GPa by direction",
    },
    Material {
        name: "fused silica",
        aliases: &["silica", "quartz glass"],
        e: 72.0 * GPA,
        nu: 0.17,
        grade: "fused silica, the usual reference of indentation calibration",
    },
    Material {
        name: "glass",
        aliases: &["soda-lime glass"],
        e: 70.0 * GPA,
        nu: 0.22,
        grade: "soda-lime float glass; borosilicate glass is about 63 GPa",
    },
    Material {
        name: "PMMA",
        aliases: &["acrylic"],
        e: 3.0 * GPA,
        nu: 0.35,
        grade: "cast PMMA (acrylic sheet) at room temperature, short-time loading",
    },
    Material {
        name: "polycarbonate",
        aliases: &["PC"],
        e: 2.3 * GPA,
        nu: 0.37,
        grade: "unfilled polycarbonate",
    },
    Material {
        name: "nylon",
        aliases: &["PA66", "polyamide"],
        e: 2.8 * GPA,
        nu: 0.39,
        grade: "nylon 6,6 (PA66), dry as moulded; water lowers the modulus by up to half",
    },
    Material { name: "PEEK", aliases: &[], e: 3.6 * GPA, nu: 0.40, grade: "unfilled PEEK" },
    Material {
        name: "polyethylene",
        aliases: &["HDPE"],
        e: 1.0 * GPA,
        nu: 0.42,
        grade: "high-density polyethylene (HDPE)",
    },
    Material { name: "PTFE", aliases: &["teflon"], e: 0.5 * GPA, nu: 0.46, grade: "unfilled PTFE" },
    Material {
        name: "rubber",
        aliases: &["natural rubber"],
        e: 3.6 * MPA,
        nu: 0.5,
        grade: "vulcanised natural rubber of hardness 60 Shore A, small-strain modulus \
                (about 1 MPa at 30 Shore A, 10 MPa at 80 Shore A); incompressible",
    },
    Material {
        name: "PDMS",
        aliases: &["silicone rubber"],
        e: 1.8 * MPA,
        nu: 0.5,
        grade: "PDMS (Sylgard 184, 10:1 base to curing agent); 1 to 3 MPa by curing; \
                incompressible",
    },
];

/// `name` as matched: lower case, `-` and `_` read as spaces, runs of spaces as one.
fn normal(name: &str) -> String {
    name.to_lowercase().replace(['-', '_'], " ").split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The material a scene's name stands for, ignoring case (`"PMMA"`, `"pmma"`) and reading
/// `-` and `_` as spaces (`"tungsten-carbide"`); aliases the same way (`"Ti-6Al-4V"`).
pub fn lookup(name: &str) -> Option<&'static Material> {
    let n = normal(name);
    MATERIALS.iter().find(|m| normal(m.name) == n || m.aliases.iter().any(|a| normal(a) == n))
}

/// The names, for hints.
pub fn names() -> String {
    MATERIALS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
}

/// A modulus in words: "210 GPa", "3.6 MPa".
pub fn modulus(e: f64) -> String {
    let (v, u) = if e >= 1e9 { (e / 1e9, "GPa") } else { (e / 1e6, "MPa") };
    let v = format!("{v:.3}");
    let v = v.trim_end_matches('0').trim_end_matches('.');
    format!("{v} {u}")
}

/// The table of docs/materials.md.
pub fn table_markdown() -> String {
    let mut s = String::from(
        "| name | also | E | nu | grade (the values are typical of it) |\n|---|---|---|---|---|\n",
    );
    for m in MATERIALS {
        let also = m.aliases.iter().map(|a| format!("`{a}`")).collect::<Vec<_>>().join(", ");
        s.push_str(&format!(
            "| `{}` | {also} | {} | {} | {} |\n",
            m.name,
            modulus(m.e),
            m.nu,
            m.grade.split_whitespace().collect::<Vec<_>>().join(" ")
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_found() {
        let mut seen = std::collections::BTreeSet::new();
        for m in MATERIALS {
            for n in std::iter::once(&m.name).chain(m.aliases) {
                assert!(seen.insert(normal(n)), "{n} names two materials");
                assert_eq!(lookup(n).map(|x| x.name), Some(m.name), "{n}");
            }
            assert!(m.e > 0.0 && m.nu > -1.0 && m.nu <= 0.5, "{}", m.name);
        }
        assert_eq!(lookup("Tungsten-Carbide").map(|m| m.name), Some("tungsten carbide"));
        assert_eq!(lookup("pmma").map(|m| m.name), Some("PMMA"));
        assert_eq!(lookup("Ti-6Al-4V").map(|m| m.name), Some("titanium"));
        assert_eq!(lookup("unobtainium"), None);
    }

    /// The list of names a contact engineer reaches for is in the table.
    #[test]
    fn the_usual_names_are_there() {
        for n in [
            "steel",
            "aluminium",
            "titanium",
            "copper",
            "tungsten carbide",
            "silicon nitride",
            "glass",
            "PMMA",
            "rubber",
        ] {
            assert!(lookup(n).is_some(), "{n}");
        }
    }

    /// E and nu against an independent figure: the shear modulus G = E / (2 (1 + nu)) of
    /// the isotropic solid against the shear modulus handbooks list for the same grade
    /// (measured separately, in torsion or by ultrasound), within 5%.
    #[test]
    fn shear_moduli_agree_with_listed_ones() {
        let listed: [(&str, f64); 8] = [
            ("steel", 80.0e9),
            ("stainless steel", 77.0e9),
            ("aluminium", 26.0e9),
            ("titanium", 44.0e9),
            ("copper", 44.0e9),
            ("nickel", 76.0e9),
            ("tungsten", 161.0e9),
            ("gold", 27.0e9),
        ];
        for (n, g) in listed {
            let m = lookup(n).unwrap();
            let ours = m.e / (2.0 * (1.0 + m.nu));
            assert!((ours / g - 1.0).abs() < 0.05, "{n}: G = {ours:.3e} against {g:.3e}");
        }
    }

    /// The rubber modulus against Gent's relation between Shore A hardness S and Young's
    /// modulus, E = 0.0981 (56 + 7.62336 S) / (0.137505 (254 - 2.54 S)) MPa, at S = 60.
    #[test]
    fn rubber_modulus_follows_its_hardness() {
        let s = 60.0;
        let gent = 0.0981 * (56.0 + 7.62336 * s) / (0.137505 * (254.0 - 2.54 * s)) * 1e6;
        let m = lookup("rubber").unwrap();
        assert!((m.e / gent - 1.0).abs() < 0.02, "{} against {gent}", m.e);
    }

    #[test]
    fn moduli_print_plainly() {
        assert_eq!(modulus(210e9), "210 GPa");
        assert_eq!(modulus(3.6e6), "3.6 MPa");
        assert_eq!(modulus(0.5e9), "500 MPa");
    }
}

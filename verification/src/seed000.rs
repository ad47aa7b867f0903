//! Seed 000 (rigid roller on a power-law graded substrate): Table 1, Figs 4–11, Tables 2
//! and 3, and the two-term comparison, at Table 1's parameters ($\nu = 0.3$, $k = 0.1$,
//! $R = 0.3$ m, $a = 0.0178$ m, $E_0 = 1\,767\,600$ kgf/m$^{2.1}$). Lengths in m, forces in
//! kgf (per metre of roller), stresses in kgf/m².

use crate::as_published::{self, Faults, TwoTermInputs};
use crate::fmt::{num, num_scaled, sig};
use crate::published::seed000 as pubv;
use crate::record::{Cause, Check, Claim, Figure, Row, Series, Source, Style, Table};
use crate::Error;
use std::sync::OnceLock;
use stickslip_graded::{
    beta, i_k, j_k, Accuracy, GradedMaterial, RigidCylinder, Stress2, StressField,
    SurfaceDisplacement,
};
use stickslip_halfspace::cattaneo2d::Cattaneo2d;
use stickslip_halfspace::mcewen::HertzTraction;

const SEED: &str = "000";
/// The friction coefficients of Figs 4–9.
pub const MUS: [f64; 5] = [0.0, 0.25, 0.5, 0.75, 1.0];
/// Depths $y/a$ of Figs 4–6: $a/4$, $a/2$, and $10^{-3}a$ standing in for the surface limit
/// (the paper does not state the depth of its "inside the contact region" curves).
pub const DEPTHS: [f64; 3] = [0.25, 0.5, 1e-3];

fn src(place: &'static str, words: &'static str) -> Source {
    Source { seed: SEED, place, words }
}

/// Table 1's material and the cylinder of half-width $a$ (corrected eq 15 gives $P$).
///
/// # Errors
/// From `stickslip-graded` (cannot happen for Table 1's values).
pub fn table1_cylinder() -> Result<RigidCylinder, Error> {
    let m = GradedMaterial::new(pubv::E0.value, pubv::K.value, pubv::NU.value)?;
    Ok(RigidCylinder::from_half_width(&m, pubv::R.value, pubv::A.value)?)
}

/// $x/a$ from $-1$ to $1$ in steps of 0.05.
fn x_grid() -> Vec<f64> {
    (0..=40).map(|i| (i as f64 - 20.0) / 20.0).collect()
}

/// T1: Table 1 recomputed.
///
/// # Errors
/// From the physics crates.
pub fn t1() -> Result<Check, Error> {
    let cyl = table1_cylinder()?;
    let m = cyl.material();
    let (nu, k) = (m.poisson_ratio(), m.k());
    let b = beta(nu, k);
    let (e0, r, a) = (m.e0(), cyl.radius(), cyl.half_width());
    let rows = vec![
        Row::published("beta (eq 13)", pubv::BETA, b),
        Row::published("I_k (eq 12)", pubv::I_K, i_k(nu, k)).because(Cause::GammaSetToOne),
        Row::published("J_k (eq 14)", pubv::J_K, j_k(nu, k)).because(Cause::GammaSetToOne),
        Row::published(
            "I_k, eq 12 with every Gamma = 1 (as published)",
            pubv::I_K,
            as_published::i_k_gamma_one(k),
        )
        .because(Cause::Misprint("truncated, not rounded: 0.348954 printed as 0.3489")),
        Row::published(
            "J_k, eq 14 on the Gamma = 1 I_k (as published)",
            pubv::J_K,
            as_published::j_k_gamma_one(k, b),
        ),
        Row::published("h = a^2/(2Rk) (eq 16)", pubv::H, cyl.indentation()?),
        Row::value("P implied by a: corrected eq 15 (kgf/m)", cyl.load()),
        Row::closed(
            "P implied by a: eq 15 as printed (kgf/m)",
            "corrected eq 15",
            cyl.load(),
            as_published::load_eq15_printed(nu, k, b, e0, r, a, false),
            1e-9,
        )
        .because(Cause::Misprint("eq 15 lacks the factor Gamma((3+k-beta)/2)")),
        Row::closed(
            "P implied by a: eq 15 with every Gamma = 1 (kgf/m)",
            "corrected eq 15",
            cyl.load(),
            as_published::load_eq15_printed(nu, k, b, e0, r, a, true),
            1e-9,
        )
        .because(Cause::GammaSetToOne),
        Row::value("p0 = P/(a B(1/2,(3+k)/2)) (kgf/m^2)", cyl.p0()),
        Row::closed(
            "I_k / I_k(Gamma = 1)",
            "FORMULAS.md A1: 2.181",
            2.181,
            i_k(nu, k) / as_published::i_k_gamma_one(k),
            5e-4,
        ),
    ];
    Ok(Check {
        id: "T1",
        seed: SEED,
        title: "Table 1: beta, I_k, J_k, h and the load implied by a".into(),
        how: vec![
            "beta, I_k, J_k from stickslip-graded (FORMULAS.md A1); h and P from the corrected eq 15 (A4) with a = 0.0178 m".into(),
            "the as-published columns use eq 12 and eq 15 with every Gamma set to 1, and eq 15 as printed".into(),
        ],
        rows,
        ..Check::default()
    })
}

/// The stresses of Figs 4–6: for each $\mu$ in [`MUS`] and each depth in [`DEPTHS`], the
/// stress at the $x/a$ of `x_grid`.
struct StressTable {
    xs: Vec<f64>,
    /// `[mu][depth][x]`.
    s: Vec<Vec<Vec<Stress2>>>,
    p0: f64,
}

fn stress_table() -> Result<&'static StressTable, Error> {
    static T: OnceLock<Result<StressTable, Error>> = OnceLock::new();
    T.get_or_init(|| {
        let cyl = table1_cylinder()?;
        let a = cyl.half_width();
        let xs = x_grid();
        let mut s = Vec::new();
        for &mu in &MUS {
            let field =
                StressField::new(cyl.material(), cyl.surface_load(mu)?, Accuracy::default())?;
            let mut per_depth = Vec::new();
            for &yd in &DEPTHS {
                let pts: Vec<(f64, f64)> = xs.iter().map(|&x| (x * a, yd * a)).collect();
                per_depth.push(field.stress_at(&pts)?);
            }
            s.push(per_depth);
        }
        Ok(StressTable { xs, s, p0: cyl.p0() })
    })
    .as_ref()
    .map_err(Clone::clone)
}

type Component = fn(&Stress2) -> f64;

fn peak(v: impl Iterator<Item = f64>) -> f64 {
    v.fold(0.0, |m, x| m.max(x.abs()))
}

/// A stress figure check (F4, F5, F6).
fn stress_check(
    id: &'static str,
    name: &str,
    comp: Component,
    fig: &'static str,
    grows: Option<&'static str>,
    constant: Option<&'static str>,
    asym: Option<&'static str>,
) -> Result<Check, Error> {
    let t = stress_table()?;
    let p0 = t.p0;
    let mut claims = Vec::new();
    let mut figures = Vec::new();
    let mut tab = Table {
        caption: format!("{name}/p0 at x/a = -1, -0.5, 0, 0.5, 1 (p0 = {} kgf/m^2)", num(p0)),
        header: vec![
            "y/a".into(),
            "mu".into(),
            "-1".into(),
            "-0.5".into(),
            "0".into(),
            "0.5".into(),
            "1".into(),
        ],
        rows: Vec::new(),
    };
    let idx = |x: f64| t.xs.iter().position(|&v| v == x).unwrap_or(0);
    for (di, &yd) in DEPTHS.iter().enumerate() {
        let mut series = Vec::new();
        for (mi, &mu) in MUS.iter().enumerate() {
            let vals: Vec<f64> = t.s[mi][di].iter().map(comp).collect();
            let mut row = vec![sig(yd, 3), sig(mu, 3)];
            for x in [-1.0, -0.5, 0.0, 0.5, 1.0] {
                row.push(num_scaled(vals[idx(x)] / p0, 1.0));
            }
            tab.rows.push(row);
            series.push(Series {
                label: format!("mu = {mu}"),
                style: Style::Line,
                points: t.xs.iter().zip(&vals).map(|(&x, &v)| (x, v / p0)).collect(),
            });
        }
        figures.push(Figure {
            name: format!("seed000_{}_y{}a", id, sig(yd, 3)),
            caption: format!(
                "{fig}: {name}/p0 vs x/a at y = {}a, mu = 0 ... 1 (full integration)",
                sig(yd, 3)
            ),
            x_label: "x/a".into(),
            y_label: format!("{name}/p0"),
            series,
        });
    }
    let peaks: Vec<Vec<f64>> = (0..DEPTHS.len())
        .map(|di| {
            MUS.iter().enumerate().map(|(mi, _)| peak(t.s[mi][di].iter().map(comp))).collect()
        })
        .collect();
    if let Some(words) = grows {
        let holds = peaks.iter().all(|p| p.windows(2).all(|w| w[1] > w[0]));
        let deciding = DEPTHS
            .iter()
            .zip(&peaks)
            .map(|(yd, p)| {
                format!(
                    "y={}a: max|{name}|/p0 {} (mu=0) -> {} (mu=1)",
                    sig(*yd, 3),
                    num(p[0] / p0),
                    num(p[4] / p0)
                )
            })
            .collect::<Vec<_>>()
            .join("; ");
        claims.push(Claim {
            claim: format!("max over x of |{name}| grows with mu at every depth"),
            source: src("Conclusions", words),
            holds,
            deciding,
            expected: None,
        });
    }
    if let Some(words) = constant {
        let mut worst: f64 = 0.0;
        let mut parts = Vec::new();
        for (di, yd) in DEPTHS.iter().enumerate() {
            let d = peak(t.s[4][di].iter().zip(&t.s[0][di]).map(|(s1, s0)| comp(s1) - comp(s0)));
            let r = d / peaks[di][0];
            worst = worst.max(r);
            parts.push(format!(
                "y={}a: max|{name}(mu=1)-{name}(mu=0)|/max|{name}(mu=0)| = {}",
                sig(*yd, 3),
                sig(r, 4)
            ));
        }
        claims.push(Claim {
            claim: format!("{name} almost constant in mu (change from mu=0 to 1 below 10 % of its peak at every depth)"),
            source: src("Conclusions", words),
            holds: worst < 0.1,
            deciding: parts.join("; "),
            expected: None,
        });
    }
    if let Some(words) = asym {
        let mut holds = true;
        let mut parts = Vec::new();
        for (di, yd) in DEPTHS.iter().enumerate() {
            let v = &t.s[4][di];
            let post = peak(t.xs.iter().zip(v).filter(|(x, _)| **x < 0.0).map(|(_, s)| comp(s)));
            let ante = peak(t.xs.iter().zip(v).filter(|(x, _)| **x > 0.0).map(|(_, s)| comp(s)));
            holds &= post > ante;
            parts.push(format!(
                "y={}a, mu=1: max|{name}|/p0 posterior {} vs anterior {}",
                sig(*yd, 3),
                num(post / p0),
                num(ante / p0)
            ));
        }
        claims.push(Claim {
            claim: format!("{name} asymmetric, larger in the posterior (x < 0, trailing) half"),
            source: src("Conclusions", words),
            holds,
            deciding: parts.join("; "),
            expected: None,
        });
    }
    Ok(Check {
        id,
        seed: SEED,
        title: format!("{fig}: {name} inside the contact region for mu = 0, 0.25, 0.5, 0.75, 1"),
        how: vec![
            "full integration of the line-load field with p(s) inside the integral (stickslip-graded StressField, FORMULAS.md A2), q = mu p acting on the substrate in +x".into(),
            "depths chosen here (the figure's depth is not stated): y = a/4, a/2, and 1e-3 a for the surface limit; the image of the figure was lost, so no published points".into(),
        ],
        claims,
        tables: vec![tab],
        figures,
        ..Check::default()
    })
}

/// F4: $\sigma_{xx}$ vs $x$.
///
/// # Errors
/// From the physics crates.
pub fn f4() -> Result<Check, Error> {
    stress_check("F4", "sigma_xx", |s| s.xx, "Fig. 4", Some("with increasing friction coefficient, tangential stress and shear stress are increased"), None, None)
}

/// F5: $\sigma_{yy}$ vs $x$.
///
/// # Errors
/// From the physics crates.
pub fn f5() -> Result<Check, Error> {
    stress_check(
        "F5",
        "sigma_yy",
        |s| s.yy,
        "Fig. 5",
        None,
        Some("normal stress in almost all of contact zone is constant"),
        Some("the normal stress (Figure 5) are asymmetrical because in posterior half ... values are greater"),
    )
}

/// F6: $\sigma_{xy}$ vs $x$.
///
/// # Errors
/// From the physics crates.
pub fn f6() -> Result<Check, Error> {
    stress_check(
        "F6",
        "sigma_xy",
        |s| s.xy,
        "Fig. 6",
        Some("with increasing friction coefficient, tangential stress and shear stress are increased"),
        None,
        Some("the figure of shear stress (Figure 6) ... asymmetrical ... posterior half ... greater"),
    )
}

/// F7/T2: Table 2's points against the 2D Cattaneo–Mindlin shear traction and the surface
/// $\sigma_{xx}$ (FORMULAS.md C).
///
/// # Errors
/// From the physics crates.
pub fn f7_t2() -> Result<Check, Error> {
    // Normalised homogeneous Hertz line contact: a = 1, p0 = 1, f = 1.
    let shape = |x: f64| (1.0 - x * x).max(0.0).sqrt();
    let slide = HertzTraction::sliding(1.0, 1.0, 1.0)?;
    let sxx = |x: f64| slide.stress(x, 0.0).map(|s| s.xx);
    let mut rows = Vec::new();
    let mut tab = Table {
        caption: "Table 2 points: published y, shear-traction shape sqrt(1-x^2), surface sigma_xx/p0 (f = 1, homogeneous)".into(),
        header: vec!["row".into(), "point".into(), "x".into(), "y published".into(), "sqrt(1-x^2)".into(), "sigma_xx(x,0)/p0".into()],
        rows: Vec::new(),
    };
    let mut d_shape: f64 = 0.0;
    let mut d_sxx: f64 = 0.0;
    let mut pub_points = [Vec::new(), Vec::new()];
    for (ri, (label, pts)) in
        [("Muskhelishvili", &pubv::T2_MUSKHELISHVILI), ("Figure 7", &pubv::T2_FIGURE7)]
            .iter()
            .enumerate()
    {
        for (i, (px, py)) in pts.iter().enumerate() {
            let x = px.value;
            let s = sxx(x)?;
            pub_points[ri].push((x, py.value));
            tab.rows.push(vec![
                label.to_string(),
                (i + 1).to_string(),
                num(x),
                num(py.value),
                num(shape(x)),
                num(s),
            ]);
            if i < 9 {
                let row = Row::published(
                    format!("{label} point {}: q/(f p0) at x/a = {}", i + 1, num(x)),
                    *py,
                    shape(x),
                );
                let row = if ri == 1 {
                    row.because(Cause::Truncation)
                } else {
                    row.because(Cause::Digitisation)
                };
                rows.push(row);
                if ri == 0 {
                    d_shape = d_shape.max((py.value - shape(x)).abs());
                    d_sxx = d_sxx.max((py.value - s).abs().min((py.value + s).abs()));
                }
            } else {
                // Points 10-12 sit at x = 0: read as centre values 1 - c/a of partial-slip
                // curves, whose Q is not stated.
                let c = 1.0 - py.value;
                rows.push(Row::value(
                    format!("{label} point {}: Q/(fP) implied if y = 1 - c/a (Cattaneo-Mindlin centre value)", i + 1),
                    1.0 - c * c,
                ));
            }
        }
    }
    let claim = Claim {
        claim: "Table 2's Muskhelishvili points 1-9 lie on the shear-traction shape sqrt(1-x^2/a^2), not on the surface sigma_xx".into(),
        source: src("Table 2 / Results", "the tangential stress in unit of length in partial slip contact region"),
        holds: d_shape <= pubv::T2_READ + 0.02 && d_sxx > 2.0 * d_shape,
        deciding: format!(
            "max distance to sqrt(1-x^2): {}; to +-sigma_xx(x,0)/p0 (f = 1): {}",
            num(d_shape),
            num(d_sxx)
        ),
        expected: Some(true),
    };
    let mut series = vec![Series {
        label: "shear traction q/(f p0), full slip".into(),
        style: Style::Line,
        points: (0..=80).map(|i| (i as f64 / 40.0 - 1.0, shape(i as f64 / 40.0 - 1.0))).collect(),
    }];
    for qr in [0.25, 0.5, 0.75] {
        let cm = Cattaneo2d::new(1.0, 1.0, 1.0, qr * std::f64::consts::PI / 2.0)?;
        series.push(Series {
            label: format!("Cattaneo-Mindlin q/(f p0), Q/fP = {qr}"),
            style: Style::Line,
            points: (0..=80)
                .map(|i| (i as f64 / 40.0 - 1.0, cm.traction(i as f64 / 40.0 - 1.0)))
                .collect(),
        });
    }
    let mut sx = Vec::new();
    for i in 0..=80 {
        let x = i as f64 / 40.0 - 1.0;
        sx.push((x, sxx(x)?));
    }
    series.push(Series {
        label: "surface sigma_xx/p0 (f = 1)".into(),
        style: Style::Line,
        points: sx,
    });
    series.push(Series {
        label: "Table 2, Muskhelishvili (published)".into(),
        style: Style::Published,
        points: pub_points[0].clone(),
    });
    series.push(Series {
        label: "Table 2, Figure 7 (published)".into(),
        style: Style::Published,
        points: pub_points[1].clone(),
    });
    Ok(Check {
        id: "F7/T2",
        seed: SEED,
        title: "Fig. 7 and Table 2: 'tangential stress inside the partial slip contact region'".into(),
        how: vec![
            "homogeneous Hertz line contact normalised to a = 1, p0 = 1, f = 1 (stickslip-halfspace): shear traction shape and surface sigma_xx = -p - 2 q0 x/a (FORMULAS.md C)".into(),
            "the paper conflates the shear traction with sigma_xx; points 10-12 (x = 0) are read as centre values of partial-slip curves whose Q is not given".into(),
        ],
        rows,
        claims: vec![claim],
        tables: vec![tab],
        figures: vec![Figure {
            name: "seed000_F7".into(),
            caption: "Fig. 7 / Table 2: shear traction and surface sigma_xx with Table 2's points".into(),
            x_label: "x/a".into(),
            y_label: "q/(f p0), sigma_xx/p0".into(),
            series,
        }],
    })
}

/// Surface displacements of Figs 8, 9: `[mu][x]` parts.
struct DispTable {
    xs: Vec<f64>,
    d: Vec<Vec<stickslip_graded::DisplacementParts>>,
}

fn disp_table() -> Result<&'static DispTable, Error> {
    static T: OnceLock<Result<DispTable, Error>> = OnceLock::new();
    T.get_or_init(|| {
        let cyl = table1_cylinder()?;
        let a = cyl.half_width();
        let xs = x_grid();
        let mut d = Vec::new();
        for &mu in &MUS {
            let sd = SurfaceDisplacement::new(
                cyl.material(),
                cyl.surface_load(mu)?,
                Accuracy::default(),
            )?;
            d.push(xs.iter().map(|&x| sd.parts(x * a)).collect::<Result<Vec<_>, _>>()?);
        }
        Ok(DispTable { xs, d })
    })
    .as_ref()
    .map_err(Clone::clone)
}

fn disp_check(id: &'static str, fig: &'static str, along_x: bool) -> Result<Check, Error> {
    let t = disp_table()?;
    let name = if along_x { "u_x" } else { "u_y" };
    let u = |p: &stickslip_graded::DisplacementParts| {
        if along_x {
            p.ux_from_p + p.ux_from_q
        } else {
            p.uy_from_p + p.uy_from_q
        }
    };
    let series = MUS
        .iter()
        .enumerate()
        .map(|(mi, mu)| Series {
            label: format!("mu = {mu}"),
            style: Style::Line,
            points: t.xs.iter().zip(&t.d[mi]).map(|(&x, p)| (x, u(p))).collect(),
        })
        .collect();
    let n = t.xs.len();
    let mut tab = Table {
        caption: format!("{name} (m) at x/a = -1, -0.5, 0, 0.5, 1"),
        header: vec!["mu".into(), "-1".into(), "-0.5".into(), "0".into(), "0.5".into(), "1".into()],
        rows: Vec::new(),
    };
    for (mi, mu) in MUS.iter().enumerate() {
        let mut r = vec![sig(*mu, 3)];
        for i in [0, 10, 20, 30, 40] {
            r.push(num_scaled(u(&t.d[mi][i]), 1e-3));
        }
        tab.rows.push(r);
    }
    let m1 = &t.d[4];
    // Asymmetry at mu = 1: compare u(-x) and u(x) over 0 < x <= a.
    let mut post_gt = true;
    let mut worst_asym: f64 = 0.0;
    let scale = peak(m1.iter().map(u));
    for i in 0..n / 2 {
        let (ul, ur) = (u(&m1[i]), u(&m1[n - 1 - i]));
        post_gt &= ul > ur;
        worst_asym = worst_asym.max((ul - ur).abs() / scale);
    }
    let grows_everywhere =
        (0..n).all(|i| (1..MUS.len()).all(|mi| u(&t.d[mi][i]) > u(&t.d[mi - 1][i])));
    let grows_peak =
        (1..MUS.len()).all(|mi| peak(t.d[mi].iter().map(u)) > peak(t.d[mi - 1].iter().map(u)));
    let mut claims = Vec::new();
    let mut rows = Vec::new();
    if along_x {
        claims.push(Claim {
            claim: "u_x asymmetric, larger in the posterior (x < 0) half".into(),
            source: src("Conclusions", "tangential displacement (Figure 8) ... asymmetrical ... posterior half ... greater"),
            holds: post_gt,
            deciding: format!(
                "mu=1: u_x(-a/2) = {}, u_x(a/2) = {}; max |u_x(-x)-u_x(x)|/max|u_x| = {}",
                num(u(&m1[10])),
                num(u(&m1[30])),
                sig(worst_asym, 4)
            ),
            expected: Some(true),
        });
        // FORMULAS.md A5's numbers for the pressure-induced part.
        let cyl = table1_cylinder()?;
        let sd =
            SurfaceDisplacement::new(cyl.material(), cyl.surface_load(0.0)?, Accuracy::default())?;
        for (x, want) in
            [(-0.01, 1.448e-4), (0.01, -1.448e-4), (-0.0178, 2.089e-4), (0.0178, -2.089e-4)]
        {
            rows.push(Row::closed(
                format!("u_x from p alone at x = {x} m (omitted by eq 32)"),
                "FORMULAS.md A5 (4 digits)",
                want,
                sd.parts(x)?.ux_from_p,
                5e-4,
            ));
        }
    } else {
        claims.push(Claim {
            claim: "u_y symmetric".into(),
            source: src("Conclusions", "normal displacement (Figure 9) ... symmetrical"),
            holds: worst_asym < 1e-3,
            deciding: format!(
                "mu=1: u_y(-a/2) = {}, u_y(a/2) = {}; max |u_y(-x)-u_y(x)|/max|u_y| = {} (the shear q = mu p adds an odd part, FORMULAS.md A3)",
                num(u(&m1[10])),
                num(u(&m1[30])),
                sig(worst_asym, 4)
            ),
            expected: None,
        });
    }
    claims.push(Claim {
        claim: format!("{name} grows with mu"),
        source: src("Conclusions", "by increasing the friction coefficient, the tangential and normal displacements are increased"),
        holds: grows_everywhere,
        deciding: format!(
            "at every x of the grid: {}; peak |{name}| grows: {}; peak {} (mu=0) -> {} (mu=1)",
            if grows_everywhere { "yes" } else { "no" },
            if grows_peak { "yes" } else { "no" },
            num(peak(t.d[0].iter().map(u))),
            num(peak(t.d[4].iter().map(u)))
        ),
        expected: if along_x { Some(true) } else { None },
    });
    Ok(Check {
        id,
        seed: SEED,
        title: format!("{fig}: {name} at the surface vs x for mu = 0 ... 1"),
        how: vec![
            "surface displacement kernels of FORMULAS.md A3 by full integration (stickslip-graded SurfaceDisplacement), absolute (relative to the surface at infinity, k > 0), u_y positive into the substrate".into(),
        ],
        rows,
        claims,
        tables: vec![tab],
        figures: vec![Figure {
            name: format!("seed000_{id}"),
            caption: format!("{fig}: {name} vs x/a, mu = 0 ... 1"),
            x_label: "x/a".into(),
            y_label: format!("{name} (m)"),
            series,
        }],
    })
}

/// F8: tangential surface displacement.
///
/// # Errors
/// From the physics crates.
pub fn f8() -> Result<Check, Error> {
    disp_check("F8", "Fig. 8", true)
}

/// F9: normal surface displacement.
///
/// # Errors
/// From the physics crates.
pub fn f9() -> Result<Check, Error> {
    disp_check("F9", "Fig. 9", false)
}

/// F10/F11/T3: eq 32 and Table 3.
///
/// # Errors
/// From the physics crates.
pub fn f10_f11_t3() -> Result<Check, Error> {
    let cyl = table1_cylinder()?;
    let mu = pubv::F.value;
    let h = cyl.indentation()?;
    let scale_h = pubv::H.value / h;
    let sd = SurfaceDisplacement::new(cyl.material(), cyl.surface_load(mu)?, Accuracy::default())?;
    let m = cyl.material();
    let inp = two_term_inputs(&cyl, mu);
    let mut rows = Vec::new();
    for i in 0..5 {
        let x = pubv::T3_X[i].value;
        let eq32 = cyl.slip_displacement_eq32(x, mu)?;
        let parts = sd.parts(x)?;
        let xs = num(x);
        rows.push(Row::published(
            format!("x = {xs}: eq 32 with h = 0.0053"),
            pubv::T3_GP[i],
            eq32 * scale_h,
        ));
        rows.push(Row::published(format!("x = {xs}: eq 32 with exact h"), pubv::T3_GP[i], eq32));
        rows.push(Row::closed(
            format!("x = {xs}: u_x from q = mu p, full integration"),
            "eq 32, exact h",
            eq32,
            parts.ux_from_q,
            1e-9,
        ));
        rows.push(
            Row::value(format!("x = {xs}: u_x from p (omitted by eq 32)"), parts.ux_from_p)
                .zero_below(1e-3),
        );
        rows.push(
            Row::published(
                format!("x = {xs}: total u_x, full integration"),
                pubv::T3_STUDY[i],
                parts.ux_from_p + parts.ux_from_q,
            )
            .because(Cause::NotReproducible(
                "the paper's column comes from eqs 28-31, which need p'(+-a) = infinity",
            )),
        );
        rows.push(
            Row::published(format!("x = {xs}: eq 29 as printed"), pubv::T3_STUDY[i], as_published::ux_eq29(&inp, m.poisson_ratio(), m.e0(), x))
                .because(Cause::NotReproducible("eq 29's boundary terms contain p'(+-a) and p''(+-a), infinite for p ~ (1-s^2/a^2)^((1+k)/2)")),
        );
    }
    let a = cyl.half_width();
    let xs: Vec<f64> = x_grid().iter().map(|t| t * a).collect();
    let mut eq32_pub = Vec::new();
    let mut eq32_exact = Vec::new();
    let mut full = Vec::new();
    for &x in &xs {
        let e = cyl.slip_displacement_eq32(x.clamp(-a, a), mu)?;
        eq32_pub.push((x, e * scale_h));
        eq32_exact.push((x, e));
        let p = sd.parts(x)?;
        full.push((x, p.ux_from_p + p.ux_from_q));
    }
    let gp: Vec<(f64, f64)> = (0..5).map(|i| (pubv::T3_X[i].value, pubv::T3_GP[i].value)).collect();
    let study: Vec<(f64, f64)> =
        (0..5).map(|i| (pubv::T3_X[i].value, pubv::T3_STUDY[i].value)).collect();
    Ok(Check {
        id: "F10/F11/T3",
        seed: SEED,
        title: "Figs 10, 11 and Table 3: slip-zone tangential displacement at mu = 1".into(),
        how: vec![
            "eq 32 (stickslip-graded, FORMULAS.md A5) with the table's h = 0.0053 and with the exact h; full-integration u_x split into the q = mu p part (which eq 32 is) and the p part it omits".into(),
            "eq 29 (boundary-term form) evaluated as printed: it needs p'(+-a), infinite, so it returns a non-finite value".into(),
        ],
        rows,
        figures: vec![
            Figure {
                name: "seed000_F10".into(),
                caption: "Fig. 10: eq 32 (G&P) with Table 3's G&P column".into(),
                x_label: "x (m)".into(),
                y_label: "u_x (m)".into(),
                series: vec![
                    Series { label: "eq 32, h = 0.0053".into(), style: Style::Line, points: eq32_pub },
                    Series { label: "eq 32, exact h".into(), style: Style::Line, points: eq32_exact.clone() },
                    Series { label: "Table 3, G&P (published)".into(), style: Style::Published, points: gp },
                ],
            },
            Figure {
                name: "seed000_F11".into(),
                caption: "Fig. 11: eq 32 vs full integration, with Table 3's 'this study' column".into(),
                x_label: "x (m)".into(),
                y_label: "u_x (m)".into(),
                series: vec![
                    Series { label: "eq 32, exact h (q part)".into(), style: Style::Line, points: eq32_exact },
                    Series { label: "full integration, q and p parts".into(), style: Style::Line, points: full },
                    Series { label: "Table 3, 'this study' (published)".into(), style: Style::Published, points: study },
                ],
            },
        ],
        ..Check::default()
    })
}

fn two_term_inputs(cyl: &RigidCylinder, mu: f64) -> TwoTermInputs {
    let m = cyl.material();
    TwoTermInputs {
        k: m.k(),
        beta: m.beta(),
        i_k: m.i_k(),
        j_k: m.j_k(),
        a: cyl.half_width(),
        load: cyl.load(),
        p0: cyl.p0(),
        mu,
    }
}

/// Depths $y/a$ of the two-term comparison.
pub const TT_DEPTHS: [f64; 6] = [0.02, 0.1, 0.25, 0.5, 1.0, 2.0];

/// TT: the two-term partial integration (eqs 21, 23, 25 as published) against full
/// integration over $x/a \in [-1.5, 1.5]$ (step 0.1), $y/a$ in [`TT_DEPTHS`], $\mu = 1$.
///
/// # Errors
/// From the physics crates or the quadrature.
pub fn two_term() -> Result<Check, Error> {
    let cyl = table1_cylinder()?;
    let mu = 1.0;
    let a = cyl.half_width();
    let inp = two_term_inputs(&cyl, mu);
    let field = StressField::new(cyl.material(), cyl.surface_load(mu)?, Accuracy::default())?;
    let ts: Vec<f64> = (0..=30).map(|i| (i as f64 - 15.0) / 10.0).collect();
    let variants: [(&str, Faults); 5] = [
        ("as published", Faults::AS_PUBLISHED),
        ("(1) Gamma off", Faults { gamma_one: false, ..Faults::AS_PUBLISHED }),
        ("(2) p(s) inside", Faults { load_outside: false, ..Faults::AS_PUBLISHED }),
        ("(3) y^2+(x-s)^2", Faults { minus_denominator: false, ..Faults::AS_PUBLISHED }),
        ("(4) no truncation", Faults { two_terms: false, ..Faults::AS_PUBLISHED }),
    ];
    let comps: [(&str, Component); 3] =
        [("sigma_xx", |s| s.xx), ("sigma_yy", |s| s.yy), ("sigma_xy", |s| s.xy)];
    let mut tab = Table {
        caption: "per component and depth, three numbers: median over x of |V - F| / max_x |F|; median V/F (where |F| >= 0.1 max|F|), the scale error; RMS of (c V - F)/max|F| with the least-squares scale c, the shape error. V: variant, F: full integration; n_sing: grid points on a singular line (excluded), non-finite V also excluded".into(),
        header: vec!["component".into(), "y/a".into(), "n_sing".into()]
            .into_iter()
            .chain(variants.iter().map(|(n, _)| (*n).to_string()))
            .collect(),
        rows: Vec::new(),
    };
    let mut sing = Table {
        caption: "singular lines of eqs 21, 23, 25 inside the grid: x - s = 0 and y^2 - (x-s)^2 = 0 for s = +-a".into(),
        header: vec!["y/a".into(), "x/a where a denominator vanishes".into()],
        rows: Vec::new(),
    };
    let mut figures = Vec::new();
    let mut medians_as_pub = Vec::new();
    for &yd in &TT_DEPTHS {
        let y = yd * a;
        let mut lines: Vec<f64> = vec![-1.0, 1.0];
        for s in [-1.0, 1.0] {
            for sg in [-1.0, 1.0] {
                let x = s + sg * yd;
                if (-1.5..=1.5).contains(&x) {
                    lines.push(x);
                }
            }
        }
        lines.sort_by(f64::total_cmp);
        lines.dedup();
        sing.rows.push(vec![
            sig(yd, 3),
            lines.iter().map(|v| sig(*v, 4)).collect::<Vec<_>>().join(", "),
        ]);
        let on_line = |t: f64| {
            [-1.0f64, 1.0].iter().any(|s| (t - s).abs() < 1e-9 || ((t - s).abs() - yd).abs() < 1e-9)
        };
        let pts: Vec<(f64, f64)> = ts.iter().map(|&t| (t * a, y)).collect();
        let full = field.stress_at(&pts)?;
        let mut vals = Vec::new();
        for (_, faults) in &variants {
            let v = ts
                .iter()
                .map(|&t| as_published::two_term_stress(&inp, *faults, t * a, y))
                .collect::<Result<Vec<_>, _>>()?;
            vals.push(v);
        }
        for (ci, (cname, comp)) in comps.iter().enumerate() {
            let fmax = peak(full.iter().map(comp));
            let keep: Vec<usize> = (0..ts.len()).filter(|&i| !on_line(ts[i])).collect();
            let mut row = vec![cname.to_string(), sig(yd, 3), (ts.len() - keep.len()).to_string()];
            for (vi, v) in vals.iter().enumerate() {
                let fin: Vec<usize> =
                    keep.iter().copied().filter(|&i| comp(&v[i]).is_finite()).collect();
                let mut e: Vec<f64> =
                    fin.iter().map(|&i| (comp(&v[i]) - comp(&full[i])).abs() / fmax).collect();
                e.sort_by(f64::total_cmp);
                let med = e.get(e.len() / 2).copied().unwrap_or(f64::NAN);
                // Scale: median of V/F where |F| is at least 10 % of its peak; shape: RMS of
                // c V - F (c the least-squares scale) relative to max |F|.
                let mut ratio: Vec<f64> = fin
                    .iter()
                    .filter(|&&i| comp(&full[i]).abs() >= 0.1 * fmax)
                    .map(|&i| comp(&v[i]) / comp(&full[i]))
                    .collect();
                ratio.sort_by(f64::total_cmp);
                let med_ratio = ratio.get(ratio.len() / 2).copied().unwrap_or(f64::NAN);
                let (svf, svv) = fin.iter().fold((0.0, 0.0), |(a, b), &i| {
                    (a + comp(&v[i]) * comp(&full[i]), b + comp(&v[i]) * comp(&v[i]))
                });
                let c = if svv > 0.0 { svf / svv } else { 0.0 };
                let shape =
                    (fin.iter().map(|&i| (c * comp(&v[i]) - comp(&full[i])).powi(2)).sum::<f64>()
                        / fin.len().max(1) as f64)
                        .sqrt()
                        / fmax;
                if vi == 0 {
                    medians_as_pub.push(med);
                }
                row.push(format!("{} / {} / {}", sig(med, 3), sig(med_ratio, 3), sig(shape, 3)));
            }
            tab.rows.push(row);
            if yd == 0.25 || yd == 1.0 {
                let _ = ci;
                figures.push(Figure {
                    name: format!("seed000_TT_{}_y{}a", cname, sig(yd, 3)),
                    caption: format!("Two-term (as published, and with fault (1) off) vs full integration: {cname} at y = {}a, mu = 1 (kgf/m^2; the as-published value is in kgf/m)", sig(yd, 3)),
                    x_label: "x/a".into(),
                    y_label: cname.to_string(),
                    series: vec![
                        Series { label: "full integration".into(), style: Style::Line, points: ts.iter().zip(&full).map(|(&t, s)| (t, comp(s))).collect() },
                        Series {
                            label: "eqs 21/23/25 as published".into(),
                            style: Style::Points,
                            points: keep.iter().map(|&i| (ts[i], comp(&vals[0][i]))).filter(|p| p.1.is_finite()).collect(),
                        },
                        Series {
                            label: "(4) untruncated, P outside".into(),
                            style: Style::Points,
                            points: keep.iter().map(|&i| (ts[i], comp(&vals[4][i]))).filter(|p| p.1.is_finite()).collect(),
                        },
                    ],
                });
            }
        }
    }
    let worst_median = medians_as_pub.iter().fold(f64::INFINITY, |m, v| m.min(*v));
    Ok(Check {
        id: "TT",
        seed: SEED,
        title: "Two-term partial integration (eqs 21, 23, 25 as published) vs full integration".into(),
        how: vec![
            "Table 1's contact (P = 986.39 kgf/m from the corrected eq 15, used by both sides), mu = 1; grid x/a = -1.5 ... 1.5 step 0.1, y/a in {0.02, 0.1, 0.25, 0.5, 1, 2}".into(),
            "each fault switched off alone: (1) correct I_k, J_k; (2) p(s) inside (the boundary terms then vanish, p(+-a) = 0); (3) derivative denominator y^2+(x-s)^2; (4) the integral with P outside by adaptive quadrature".into(),
            "with P outside (fault 2) the expressions have units of force per length, not stress: their divergence in this table depends on the length unit (m, as in Table 1)".into(),
        ],
        rows: vec![Row::value("smallest median divergence of the as-published forms over components and depths", worst_median)],
        tables: vec![tab, sing],
        figures,
        ..Check::default()
    })
}

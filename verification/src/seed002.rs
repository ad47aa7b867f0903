//! Seed 002 (traction and microslip): Mindlin, Mindlin–Deresiewicz, Examples 1–5 and the
//! twist check, solved by the modified LP of `stickslip-traction` and compared with the
//! closed forms (FORMULAS.md E, F, G). Units: in, lbf, psi.
//!
//! Inputs lost in the OCR follow FORMULAS.md E: steel $E = 30\times10^6$ psi, $\nu = 0.3$;
//! the Example 2 "rubber" $E = 1.0\times10^6$ psi, $\nu = 0.3$. Example 3's loads and
//! materials are not stated: Example 1's (steel on steel, $P$ = 2160 lbf, $T$ = 144 lbf,
//! $f$ = 0.1) are used, with the semi-axes $a = a_1\sqrt{r}$, $b = a_1/\sqrt{r}$ for ratio
//! $r = a/b$ and $a_1$ Example 1's radius.

use crate::as_published;
use crate::fmt::{num, sig};
use crate::published::seed002 as pubv;
use crate::record::{Cause, Check, Claim, Figure, Row, Series, Source, Style, Table};
use crate::Error;
use std::f64::consts::PI;
use stickslip_halfspace::hertz::HertzSphere;
use stickslip_halfspace::material::composite_modulus;
use stickslip_halfspace::Material;
use stickslip_lattice::{ContactGrid, GridPatch, InfluenceModel, PatchPressure, Shape};
use stickslip_quad::{gauss_kronrod, AdaptiveConfig, Tolerance};
use stickslip_traction::{closed::Cattaneo, closed::Deresiewicz, closed::Lubkin, closed::Mindlin};
use stickslip_traction::{ElementState, Load, Regime, TractionProblem, TractionSolution};

const SEED: &str = "002";

fn src(place: &'static str, words: &'static str) -> Source {
    Source { seed: SEED, place, words }
}

/// Steel of the examples (FORMULAS.md E).
///
/// # Errors
/// Never for these constants.
pub fn steel() -> Result<Material, Error> {
    Ok(Material::new(30e6, 0.3)?)
}

/// The Example 2 "rubber" (FORMULAS.md E).
///
/// # Errors
/// Never for these constants.
pub fn rubber() -> Result<Material, Error> {
    Ok(Material::new(1.0e6, 0.3)?)
}

fn hertz_radius(p: f64, r: f64, m1: &Material, m2: &Material) -> Result<f64, Error> {
    Ok(HertzSphere::new(p, r, composite_modulus(m1, m2))?.contact_radius())
}

fn lp(
    grid: &ContactGrid,
    bodies: [Material; 2],
    f: f64,
    load: Load,
    model: InfluenceModel,
) -> Result<TractionSolution, Error> {
    Ok(TractionProblem::new(grid, bodies, f, load)?.with_model(model).solve()?)
}

fn force(t: f64) -> Load {
    Load::Force { magnitude: t, angle: 0.0 }
}

/// Largest centre radius of a stick element (the discrete stick radius).
fn stick_radius(grid: &ContactGrid, sol: &TractionSolution, centre: (f64, f64)) -> f64 {
    (0..grid.len())
        .filter(|&k| sol.state[k] == ElementState::Stick)
        .map(|k| (grid.x[k] - centre.0).hypot(grid.y[k] - centre.1))
        .fold(0.0, f64::max)
}

/// F3.2: Mindlin traction on a circle, closed form and LP (Example 1's contact,
/// $T = fP/2$, 80 elements, exact-rectangle influence).
///
/// # Errors
/// From the physics crates.
pub fn f3_2() -> Result<Check, Error> {
    let s = steel()?;
    let (p, f) = (pubv::EX1_P.value, pubv::EX1_F.value);
    let a = hertz_radius(p, pubv::EX1_R.value, &s, &s)?;
    let t = 0.5 * f * p;
    let grid = ContactGrid::hertz_circle(a, p, 10)?;
    let sol = lp(&grid, [s, s], f, force(t), InfluenceModel::ExactRectangle)?;
    let m = Mindlin::new(a, p, f, t)?;
    let fq0 = f * 3.0 * p / (2.0 * PI * a * a);
    let mut worst: f64 = 0.0;
    let mut sq = 0.0;
    for k in 0..grid.len() {
        let d = (sol.traction[k] - m.traction(grid.x[k].hypot(grid.y[k]))) / fq0;
        worst = worst.max(d.abs());
        sq += d * d;
    }
    let rms = (sq / grid.len() as f64).sqrt();
    let h = grid.hx;
    let m0 = Mindlin::new(a, p, f, 0.0)?;
    let m1 = Mindlin::new(a, p, f, f * p)?;
    let mut series = Vec::new();
    for ratio in [0.25, 0.5, 0.75, 1.0] {
        let mm = Mindlin::new(a, p, f, ratio * f * p)?;
        series.push(Series {
            label: format!("Mindlin, T/fP = {ratio}"),
            style: Style::Line,
            points: (0..=100)
                .map(|i| (i as f64 / 100.0, mm.traction(a * i as f64 / 100.0) / fq0))
                .collect(),
        });
    }
    series.push(Series {
        label: "LP, 80 elements, T/fP = 0.5".into(),
        style: Style::Points,
        points: (0..grid.len())
            .map(|k| (grid.x[k].hypot(grid.y[k]) / a, sol.traction[k] / fq0))
            .collect(),
    });
    Ok(Check {
        id: "F3.2",
        seed: SEED,
        title: "Fig. 3.2: Mindlin traction for a circular contact, closed form and LP".into(),
        how: vec!["Example 1's contact (steel on steel, R = 1 in, P = 2160 lbf, f = 0.1), T = fP/2; LP on 80 elements with exact rectangle influence coefficients".into()],
        rows: vec![
            Row::closed("LP stick radius / a (largest stick element centre)", "Mindlin a*/a = (1 - T/fP)^(1/3)", m.stick_radius() / a, stick_radius(&grid, &sol, (0.0, 0.0)) / a, h / m.stick_radius())
                .because(Cause::Discretisation("element centres resolve the stick radius to one element")),
            Row::value("max |q_LP - q_Mindlin| / (f q0) over the elements", worst),
            Row::value("RMS (q_LP - q_Mindlin) / (f q0)", rms),
        ],
        claims: vec![
            Claim {
                claim: "a* = a for T = 0: no microslip".into(),
                source: src("Section 3.2.1", "a* = a for T = 0 and no microslip occurs"),
                holds: m0.stick_radius() == a,
                deciding: format!("a*(T=0)/a = {}", num(m0.stick_radius() / a)),
                expected: Some(true),
            },
            Claim {
                claim: "a* = 0 for T = fP: impending gross slip".into(),
                source: src("Section 3.2.1", "a* = 0 for T = fP and the entire contact area is in a state of microslip"),
                holds: m1.stick_radius() == 0.0,
                deciding: format!("a*(T=fP)/a = {}", num(m1.stick_radius() / a)),
                expected: Some(true),
            },
        ],
        figures: vec![Figure {
            name: "seed002_F3.2".into(),
            caption: "Fig. 3.2: Mindlin traction q/(f q0) vs r/a, q0 = 3P/(2 pi a^2)".into(),
            x_label: "r/a".into(),
            y_label: "q/(f q0)".into(),
            series,
        }],
        ..Check::default()
    })
}

/// F3.3/F3.4/Eq3.5: Mindlin–Deresiewicz unloading, hysteresis and energy per cycle.
///
/// # Errors
/// From the physics crates or the quadrature.
pub fn f3_3_f3_4_eq3_5() -> Result<Check, Error> {
    let s = steel()?;
    let (p, f) = (pubv::EX1_P.value, pubv::EX1_F.value);
    let a = hertz_radius(p, pubv::EX1_R.value, &s, &s)?;
    let fp = f * p;
    let qerr = |e: stickslip_quad::Error| Error::Quadrature(e.to_string());
    let cfg = AdaptiveConfig::new(Tolerance::relative(1e-12).map_err(qerr)?);
    let mut rows = Vec::new();
    let d = Deresiewicz::new(a, p, f, 0.5 * fp)?;
    // Resultant of the unloading traction equals T (breakpoints at the radii where the
    // profile has kinks).
    for t in [0.25 * fp, 0.0, -0.25 * fp] {
        let b = d.reversal_radius(t)?;
        let astar = a * 0.5f64.cbrt();
        let mut bps = vec![astar.min(b), astar.max(b)];
        bps.dedup();
        let cfgb = AdaptiveConfig::new(Tolerance::new(1e-12 * fp, 1e-12).map_err(qerr)?)
            .with_breakpoints(bps)
            .map_err(qerr)?;
        let r = gauss_kronrod(
            |rho| 2.0 * PI * rho * d.unloading_traction(rho, t).unwrap_or(f64::NAN),
            0.0,
            a,
            &cfgb,
        )
        .map_err(qerr)?;
        rows.push(
            Row::closed(
                format!("resultant of the unloading traction at T = {} lbf, T* = fP/2", num(t)),
                "T",
                t,
                r.value,
                1e-9,
            )
            .zero_below(fp),
        );
    }
    let g = s.shear_modulus();
    let mut loops = Vec::new();
    for ratio in [0.1, 0.5, 0.9, 1.0] {
        let d = Deresiewicz::new(a, p, f, ratio * fp)?;
        let ts = ratio * fp;
        let area = gauss_kronrod(
            |t| {
                d.delta_unloading(t, &s).unwrap_or(f64::NAN)
                    - d.delta_reloading(t, &s).unwrap_or(f64::NAN)
            },
            -ts,
            ts,
            &cfg,
        )
        .map_err(qerr)?;
        let w = d.energy_per_cycle(&s);
        rows.push(Row::closed(
            format!("loop area, T*/fP = {ratio} (lbf in)"),
            "eq 3.5 with '+' (FORMULAS.md E)",
            w,
            area.value,
            1e-9,
        ));
        rows.push(
            Row::closed(
                format!("eq 3.5 as printed ('-'), T*/fP = {ratio}"),
                "loop area",
                area.value,
                as_published::energy_eq35_printed(s.poisson_ratio(), g, a, f, p, ts),
                1e-9,
            )
            .because(Cause::Misprint("eq 3.5's last bracket needs (1 + (1 - T*/fP)^(2/3))")),
        );
        loops.push(Series {
            label: format!("T*/fP = {ratio}"),
            style: Style::Line,
            points: d.hysteresis_loop(&s, 100)?.into_iter().map(|(t, dl)| (t / fp, dl)).collect(),
        });
    }
    let tiny = Deresiewicz::new(a, p, f, 1e-3 * fp)?;
    let ts = 1e-3 * fp;
    rows.push(Row::closed(
        "W at T*/fP = 1e-3",
        "small amplitude (2-nu) T*^3/(36 G a fP)",
        (2.0 - s.poisson_ratio()) * ts.powi(3) / (36.0 * g * a * fp),
        tiny.energy_per_cycle(&s),
        2e-3,
    ));
    let qh = 3.0 * fp / (2.0 * PI * a.powi(3));
    let mut prof = Vec::new();
    for t in [0.5 * fp, 0.25 * fp, 0.0, -0.25 * fp, -0.5 * fp] {
        let mut pts = Vec::new();
        for i in 0..=100 {
            let rho = a * i as f64 / 100.0;
            pts.push((rho / a, d.unloading_traction(rho, t)? / (qh * a)));
        }
        prof.push(Series {
            label: format!("T/fP = {}", sig(t / fp, 3)),
            style: Style::Line,
            points: pts,
        });
    }
    Ok(Check {
        id: "F3.3/F3.4/Eq3.5",
        seed: SEED,
        title: "Figs 3.3, 3.4 and eq 3.5: unloading traction, hysteresis loop, energy per cycle".into(),
        how: vec!["Mindlin-Deresiewicz closed forms (stickslip-traction, FORMULAS.md E), Example 1's contact, per body; loop area by adaptive Gauss-Kronrod of delta_d - delta_i".into()],
        rows,
        figures: vec![
            Figure { name: "seed002_F3.3".into(), caption: "Fig. 3.3: traction while unloading from T* = fP/2".into(), x_label: "r/a".into(), y_label: "q/(f q0)".into(), series: prof },
            Figure { name: "seed002_F3.4".into(), caption: "Fig. 3.4: hysteresis loops, per-body displacement (in) vs T/fP".into(), x_label: "T/fP".into(), y_label: "delta (in)".into(), series: loops },
        ],
        ..Check::default()
    })
}

/// Example 1 / Fig 3.6 (and the shared part of Example 2).
///
/// # Errors
/// From the physics crates.
pub fn ex1() -> Result<Check, Error> {
    let s = steel()?;
    let (p, t, f) = (pubv::EX1_P.value, pubv::EX1_T.value, pubv::EX1_F.value);
    let a = hertz_radius(p, pubv::EX1_R.value, &s, &s)?;
    let grid = ContactGrid::hertz_circle(a, p, 10)?;
    let exact = lp(&grid, [s, s], f, force(t), InfluenceModel::ExactRectangle)?;
    let point = lp(&grid, [s, s], f, force(t), InfluenceModel::PointLoad)?;
    let m = Mindlin::new(a, p, f, t)?;
    let want = m.compliance_per_body(&s);
    let dev = |v: f64| -100.0 * (v / want - 1.0);
    let fq0 = f * 3.0 * p / (2.0 * PI * a * a);
    let peak = (0..=1000).map(|i| m.traction(a * i as f64 / 1000.0)).fold(0.0, f64::max);
    let rows = vec![
        Row::published("elements", pubv::EX1_N, grid.len() as f64),
        Row::published("Mindlin per-body delta (in)", pubv::EX1_DELTA_MINDLIN, want),
        Row::published("Mindlin relative (two-body) delta (in)", pubv::EX1_DELTA_MINDLIN, m.compliance_relative(&s, &s)).because(Cause::PerBodyVsRelative),
        Row::published("LP per-body delta, exact rectangle influence (in)", pubv::EX1_DELTA_LP, exact.rigid_per_body[0])
            .because(Cause::Discretisation("exact rectangle influence coefficients vs the seed's point-load approximation")),
        Row::published("LP per-body delta, point-load influence (in)", pubv::EX1_DELTA_LP, point.rigid_per_body[0])
            .because(Cause::Discretisation("the seed's k = j coefficient is missing from the OCR; ours is the exact square self-term (FORMULAS.md F)")),
        Row::published("deviation below Mindlin, exact rectangle (%)", pubv::EX1_DEVIATION, dev(exact.rigid_per_body[0]))
            .because(Cause::Discretisation("influence model and element placement")),
        Row::published("deviation below Mindlin, point load (%)", pubv::EX1_DEVIATION, dev(point.rigid_per_body[0]))
            .because(Cause::Discretisation("influence model and element placement")),
        Row::published("deviation of the seed's own numbers, 100 (1 - 0.66196/0.67139) (%)", pubv::EX1_DEVIATION, -100.0 * (pubv::EX1_DELTA_LP.value / pubv::EX1_DELTA_MINDLIN.value - 1.0))
            .because(Cause::Misprint("0.66196/0.67139 is 1.40 % below, not 1.41 %")),
        Row::published("Mindlin peak traction (psi) vs Fig. 3.6 axis top", pubv::F36_AXIS_TOP, peak),
        Row::value("LP pivots (exact)", exact.info.iterations as f64),
    ];
    let mut series = vec![Series {
        label: "Mindlin".into(),
        style: Style::Line,
        points: (0..=100).map(|i| (i as f64 / 100.0, m.traction(a * i as f64 / 100.0))).collect(),
    }];
    for (label, sol) in [("LP, exact rectangle", &exact), ("LP, point load", &point)] {
        series.push(Series {
            label: label.into(),
            style: Style::Points,
            points: (0..grid.len())
                .map(|k| (grid.x[k].hypot(grid.y[k]) / a, sol.traction[k]))
                .collect(),
        });
    }
    Ok(Check {
        id: "Ex1/F3.6",
        seed: SEED,
        title: "Example 1 and Fig. 3.6: steel sphere on steel, 80 elements".into(),
        how: vec![format!(
            "Hertz a = {} in, f q0 = {} psi; LP (stickslip-traction) with both influence models, per-body movement = rigid_per_body[0]",
            num(a),
            num(fq0)
        )],
        rows,
        figures: vec![Figure {
            name: "seed002_F3.6".into(),
            caption: "Fig. 3.6: traction (psi) vs r/a, Mindlin and LP (80 elements)".into(),
            x_label: "r/a".into(),
            y_label: "traction (psi)".into(),
            series,
        }],
        ..Check::default()
    })
}

/// Example 2 / Fig 3.7: steel sphere on "rubber".
///
/// # Errors
/// From the physics crates.
pub fn ex2() -> Result<Check, Error> {
    let (s, r) = (steel()?, rubber()?);
    let (p, t, f) = (pubv::EX2_P.value, pubv::EX2_T.value, pubv::EX2_F.value);
    let a = hertz_radius(p, pubv::EX1_R.value, &s, &r)?;
    let grid = ContactGrid::hertz_circle(a, p, 10)?;
    let sol = lp(&grid, [s, r], f, force(t), InfluenceModel::ExactRectangle)?;
    let point = lp(&grid, [s, r], f, force(t), InfluenceModel::PointLoad)?;
    let m = Mindlin::new(a, p, f, t)?;
    let (ws, wr) = (m.compliance_per_body(&s), m.compliance_per_body(&r));
    let lp_s = sol.rigid_per_body[0];
    let lp_r = sol.rigid_per_body[1];
    let disc =
        Cause::Discretisation("exact rectangle influence coefficients and our grid vs the seed's");
    let rows = vec![
        Row::published("LP per-body delta, rubber (in)", pubv::EX2_DELTA_RUBBER, lp_r)
            .because(disc.clone()),
        Row::published("LP per-body delta, steel (in)", pubv::EX2_DELTA_STEEL, lp_s)
            .because(disc.clone()),
        Row::published(
            "LP per-body delta, rubber, point-load influence (in)",
            pubv::EX2_DELTA_RUBBER,
            point.rigid_per_body[1],
        )
        .because(disc.clone()),
        Row::published("ratio rubber/steel (LP)", pubv::EX2_RATIO, lp_r / lp_s),
        Row::published(
            "deviation below Mindlin, rubber (%)",
            pubv::EX2_DEVIATION,
            -100.0 * (lp_r / wr - 1.0),
        )
        .because(disc.clone()),
        Row::published(
            "deviation below Mindlin, steel (%)",
            pubv::EX2_DEVIATION,
            -100.0 * (lp_s / ws - 1.0),
        )
        .because(disc.clone()),
        Row::published(
            "deviation below Mindlin, rubber, point load (%)",
            pubv::EX2_DEVIATION,
            -100.0 * (point.rigid_per_body[1] / wr - 1.0),
        )
        .because(disc),
        Row::closed(
            "Mindlin per body, rubber (in)",
            "FORMULAS.md E: 0.403917e-3",
            0.403917e-3,
            wr,
            5e-6,
        ),
        Row::closed(
            "Mindlin per body, steel (in)",
            "FORMULAS.md E: 0.134639e-4",
            0.134639e-4,
            ws,
            5e-6,
        ),
        Row::closed(
            "seed's rubber value vs Mindlin (%)",
            "FORMULAS.md E: -2.284 (listed there as the steel value)",
            -2.284,
            100.0 * (pubv::EX2_DELTA_RUBBER.value / wr - 1.0),
            5e-4,
        ),
        Row::closed(
            "seed's steel value vs Mindlin (%)",
            "FORMULAS.md E: -2.287 (listed there as the rubber value)",
            -2.287,
            100.0 * (pubv::EX2_DELTA_STEEL.value / ws - 1.0),
            5e-4,
        ),
        Row::value(
            "Dundurs beta of the pair (coupling neglected by Mindlin and the seed)",
            stickslip_halfspace::material::dundurs_beta(&s, &r),
        ),
    ];
    let fq0 = f * 3.0 * p / (2.0 * PI * a * a);
    Ok(Check {
        id: "Ex2/F3.7",
        seed: SEED,
        title: "Example 2 and Fig. 3.7: steel sphere on 'rubber' (E = 1.0e6 psi), 80 elements".into(),
        how: vec![format!("Hertz a = {} in, f q0 = {} psi; bodies [steel sphere, rubber]; LP exact rectangle unless stated", num(a), num(fq0))],
        rows,
        figures: vec![Figure {
            name: "seed002_F3.7".into(),
            caption: "Fig. 3.7: traction (psi) vs r/a, Mindlin and LP".into(),
            x_label: "r/a".into(),
            y_label: "traction (psi)".into(),
            series: vec![
                Series { label: "Mindlin".into(), style: Style::Line, points: (0..=100).map(|i| (i as f64 / 100.0, m.traction(a * i as f64 / 100.0))).collect() },
                Series { label: "LP, exact rectangle".into(), style: Style::Points, points: (0..grid.len()).map(|k| (grid.x[k].hypot(grid.y[k]) / a, sol.traction[k])).collect() },
            ],
        }],
        ..Check::default()
    })
}

/// A lattice $n_x \times n_y$ over the ellipse's bounding box whose element count is
/// `target`: square lattices ($n_x = n_y$) first, then the most nearly square exact match,
/// else the closest count.
fn ellipse_grid(
    a: f64,
    b: f64,
    p: f64,
    target: usize,
) -> Result<(ContactGrid, usize, usize), Error> {
    let mut best: Option<(usize, usize, ContactGrid, usize, usize)> = None;
    for nx in 4..=30usize {
        for ny in 4..=30usize {
            let g = ContactGrid::hertz_ellipse(a, b, p, nx, ny)?;
            let key = (g.len().abs_diff(target), nx.abs_diff(ny));
            if best.as_ref().is_none_or(|(d, u, ..)| key < (*d, *u)) {
                best = Some((key.0, key.1, g, nx, ny));
            }
        }
    }
    let (_, _, g, nx, ny) = best.expect("the loops run at least once");
    Ok((g, nx, ny))
}

/// Example 3 / Table 3.1 / Figs 3.8–3.11: elliptical contacts.
///
/// # Errors
/// From the physics crates.
pub fn ex3() -> Result<Check, Error> {
    let s = steel()?;
    let (p, t, f) = (pubv::EX1_P.value, pubv::EX1_T.value, pubv::EX1_F.value);
    let a1 = hertz_radius(p, pubv::EX1_R.value, &s, &s)?;
    let mut rows = Vec::new();
    let mut figures = Vec::new();
    for (ratio, count) in pubv::T31 {
        let r = ratio.value;
        let (a, b) = (a1 * r.sqrt(), a1 / r.sqrt());
        let (grid, nx, ny) = ellipse_grid(a, b, p, count.value as usize)?;
        let sol = lp(&grid, [s, s], f, force(t), InfluenceModel::ExactRectangle)?;
        let c = Cattaneo::new(a, b, p, f, t)?;
        let rs = ratio.text;
        rows.push(Row::published(
            format!("a/b = {rs}: elements ({nx} x {ny} lattice over the bounding box)"),
            count,
            grid.len() as f64,
        ));
        rows.push(
            Row::closed(format!("a/b = {rs}: LP per-body delta / Cattaneo"), "Cattaneo Lambda formula", 1.0, sol.rigid_per_body[0] / c.compliance_per_body(&s), 0.03)
                .because(Cause::Discretisation("rectangular elements; the seed: 'If a square grid element had been used, better correlation would have been obtained'")),
        );
        // Traction along the loaded axis: the element row nearest y = 0.
        let ymin = grid.y.iter().fold(f64::INFINITY, |m, y| m.min(y.abs()));
        let axis: Vec<usize> =
            (0..grid.len()).filter(|&k| (grid.y[k].abs() - ymin).abs() < 1e-12 * b).collect();
        let fp0 = f * c.peak_pressure();
        let worst = axis
            .iter()
            .map(|&k| (sol.traction[k] - c.traction(grid.x[k], grid.y[k])).abs() / fp0)
            .fold(0.0, f64::max);
        rows.push(Row::value(format!("a/b = {rs}: max |q_LP - q_Cattaneo|/(f p0) on the element row nearest the loaded axis"), worst));
        figures.push(Figure {
            name: format!("seed002_Ex3_ab{rs}"),
            caption: format!(
                "Fig. {}: traction along the loaded axis, a/b = {rs}",
                count
                    .source
                    .words
                    .trim_start_matches(|ch: char| ch.is_ascii_digit() || ch == ' ')
                    .trim_start_matches("Fig. ")
            ),
            x_label: "x/a".into(),
            y_label: "q/(f p0)".into(),
            series: vec![
                Series {
                    label: format!("Cattaneo at y = {}", sig(ymin, 4)),
                    style: Style::Line,
                    points: (0..=100)
                        .map(|i| {
                            let x = a * (i as f64 / 50.0 - 1.0);
                            (x / a, c.traction(x, ymin) / fp0)
                        })
                        .collect(),
                },
                Series {
                    label: "LP, exact rectangle".into(),
                    style: Style::Points,
                    points: axis.iter().map(|&k| (grid.x[k] / a, sol.traction[k] / fp0)).collect(),
                },
            ],
        });
    }
    Ok(Check {
        id: "Ex3/T3.1/F3.8-F3.11",
        seed: SEED,
        title: "Example 3, Table 3.1, Figs 3.8-3.11: elliptical contacts a/b = 2, 0.5, 8, 0.125".into(),
        how: vec!["loads and materials not stated: Example 1's (steel, P = 2160 lbf, T = 144 lbf along x = the a-axis, f = 0.1), a b = a1^2; grids nx x ny over the bounding box, the most nearly square lattice that matches Table 3.1's count".into()],
        rows,
        figures,
        ..Check::default()
    })
}

/// Example 4 / Figs 3.12–3.15: uniformly pressed 1 in square.
///
/// # Errors
/// From the physics crates.
pub fn ex4() -> Result<Check, Error> {
    let s = steel()?;
    let (pr, f) = (pubv::EX4_PRESSURE.value, pubv::EX4_F.value);
    let grid = ContactGrid::uniform_square(1.0, pr, 10)?;
    let capacity: f64 = grid.normal_force().iter().map(|v| f * v).sum();
    let solve = |t: f64| lp(&grid, [s, s], f, force(t), InfluenceModel::ExactRectangle);
    let s800 = solve(800.0)?;
    let s1000 = solve(1000.0)?;
    let min = |v: &[f64]| v.iter().fold(f64::INFINITY, |m, x| m.min(*x));
    let max = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(*x));
    let mut tab = Table {
        caption: "slip development and rigid-body movement vs T (Figs 3.14, 3.15)".into(),
        header: [
            "T (lbf)",
            "regime",
            "slipping elements",
            "relative movement (in)",
            "per-body movement (in)",
        ]
        .map(String::from)
        .to_vec(),
        rows: Vec::new(),
    };
    let mut curve = Vec::new();
    let mut gross_per_body = f64::NAN;
    for i in 1..=12 {
        let t = 100.0 * i as f64;
        let sol = solve(t)?;
        let ns = sol.state.iter().filter(|st| **st == ElementState::Slip).count();
        tab.rows.push(vec![
            num(t),
            format!("{:?}", sol.regime),
            ns.to_string(),
            num(sol.rigid),
            num(sol.rigid_per_body[0]),
        ]);
        curve.push((sol.rigid_per_body[0], t));
        if sol.regime == Regime::GrossSlip {
            gross_per_body = sol.rigid_per_body[0];
        }
    }
    let rows = vec![
        Row::published("elements", pubv::EX4_N, grid.len() as f64),
        Row::published("gross slip load f p A (lbf)", pubv::F315_GROSS, capacity),
        Row::published("lowest traction at T = 800 lbf (psi)", pubv::F312_LOWEST, min(&s800.traction)).because(Cause::Digitisation),
        Row::published("highest traction at T = 800 lbf (psi)", pubv::F312_HIGHEST, max(&s800.traction)),
        Row::published("lowest traction at T = 1000 lbf (psi)", pubv::F313_LOWEST, min(&s1000.traction)).because(Cause::Digitisation),
        Row::published("per-body movement at gross slip (in) vs Fig. 3.15 axis end", pubv::F315_MOVEMENT_AXIS, gross_per_body)
            .because(Cause::NotReproducible("the axis end bounds the curve; whether Fig. 3.15 plots per-body or relative movement is not stated")),
    ];
    let grid_pts = |sol: &TractionSolution| {
        (0..grid.len()).map(|k| (grid.x[k], sol.traction[k])).collect::<Vec<_>>()
    };
    Ok(Check {
        id: "Ex4/F3.12-F3.15",
        seed: SEED,
        title: "Example 4, Figs 3.12-3.15: 1 in square, 10,000 psi, f = 0.12, 100 elements".into(),
        how: vec!["steel on steel, 10 x 10 elements, LP exact rectangle; the contour labels of Figs 3.12-3.13 are compared with the extreme element tractions".into()],
        rows,
        tables: vec![tab],
        figures: vec![
            Figure { name: "seed002_F3.12_F3.13".into(), caption: "Figs 3.12-3.13: element traction (psi) vs x (in), all rows, T = 800 and 1000 lbf".into(), x_label: "x (in)".into(), y_label: "traction (psi)".into(), series: vec![
                Series { label: "T = 800 lbf".into(), style: Style::Points, points: grid_pts(&s800) },
                Series { label: "T = 1000 lbf".into(), style: Style::Points, points: grid_pts(&s1000) },
            ] },
            Figure { name: "seed002_F3.15".into(), caption: "Fig. 3.15: T vs per-body rigid-body movement".into(), x_label: "movement (in)".into(), y_label: "T (lbf)".into(), series: vec![Series { label: "LP".into(), style: Style::Line, points: curve }] },
        ],
        ..Check::default()
    })
}

fn two_squares(p1: f64, p2: f64) -> Result<ContactGrid, Error> {
    let side = pubv::EX5_SIDE.value;
    let half = 0.5 * pubv::EX5_DISTANCE.value;
    let h = side / 6.0;
    let sq = |cx: f64, p: f64| GridPatch {
        shape: Shape::Rectangle { cx, cy: 0.0, wx: side, wy: side },
        pressure: PatchPressure::Uniform(p),
    };
    Ok(ContactGrid::from_patches(
        h,
        h,
        (-half - 0.5 * side, -0.5 * side),
        &[sq(-half, p1), sq(half, p2)],
    )?)
}

/// Example 5 / Figs 3.16–3.21: two 0.6 in squares.
///
/// # Errors
/// From the physics crates.
pub fn ex5() -> Result<Check, Error> {
    let s = steel()?;
    let f = 0.12;
    let angle = PI / 4.0;
    let g1 = two_squares(10_000.0, 10_000.0)?;
    let g2 = two_squares(20_000.0, 10_000.0)?;
    let solve = |g: &ContactGrid, t: f64| {
        lp(g, [s, s], f, Load::Force { magnitude: t, angle }, InfluenceModel::ExactRectangle)
    };
    let mut rows = Vec::new();
    let mut tab = Table {
        caption:
            "cases: per-region force (lbf), slipping elements / elements, centre of traction (in)"
                .into(),
        header: [
            "case",
            "regime",
            "region 1 force",
            "region 2 force",
            "region 1 slip",
            "region 2 slip",
            "centre x",
            "centre y",
        ]
        .map(String::from)
        .to_vec(),
        rows: Vec::new(),
    };
    for (name, g, t) in [
        ("1: 10,000/10,000 psi, 800 lbf", &g1, 800.0),
        ("2: 20,000/10,000 psi, 800 lbf", &g2, 800.0),
        ("3: 20,000/10,000 psi, 1200 lbf", &g2, 1200.0),
    ] {
        let sol = solve(g, t)?;
        let (r1, r2) = (&sol.patches[0], &sol.patches[1]);
        tab.rows.push(vec![
            name.into(),
            format!("{:?}", sol.regime),
            num(r1.force),
            num(r2.force),
            format!("{}/{}", r1.slipping, r1.elements),
            format!("{}/{}", r2.slipping, r2.elements),
            crate::fmt::num_scaled(sol.centre_of_traction.0, 1.0),
            crate::fmt::num_scaled(sol.centre_of_traction.1, 1.0),
        ]);
        if name.starts_with('1') {
            let c = sol.centre_of_traction;
            rows.push(
                Row::closed(
                    "case 1: distance of the centre of traction from the centroid (in)",
                    "resultant through the centroid",
                    0.0,
                    c.0.hypot(c.1),
                    1e-9,
                )
                .zero_below(1.0),
            );
        }
    }
    let capacity: f64 = g2.normal_force().iter().map(|v| f * v).sum();
    rows.push(Row::published(
        "gross slip of the whole contact, cases 2/3 (lbf)",
        pubv::EX5_GROSS_SLIP,
        capacity,
    ));
    // Region 2 full slip: bisection on T.
    let full2 = |t: f64| -> Result<bool, Error> {
        let sol = solve(&g2, t)?;
        Ok(sol.regime == Regime::GrossSlip || sol.patches[1].slipping == sol.patches[1].elements)
    };
    let (mut lo, mut hi) = (0.0, capacity);
    for _ in 0..14 {
        let mid = 0.5 * (lo + hi);
        if full2(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let t_full2 = 0.5 * (lo + hi);
    rows.push(
        Row::published(
            "region 2 reaches full slip, cases 2/3 pressures (lbf, bisection to 0.1 lbf)",
            pubv::EX5_REGION2_FULL_SLIP,
            t_full2,
        )
        .because(Cause::Discretisation(
            "6 x 6 elements per square here; the seed's grid is not stated",
        )),
    );
    let mut share = [Vec::new(), Vec::new()];
    let mut offset = [Vec::new(), Vec::new(), Vec::new()];
    let mut movement = [Vec::new(), Vec::new()];
    let mut seq = Table {
        caption:
            "slip sequence, cases 2/3 pressures (Fig. 3.20): slipping elements per region vs T"
                .into(),
        header: ["T (lbf)", "region 1", "region 2", "regime"].map(String::from).to_vec(),
        rows: Vec::new(),
    };
    let mut slip1_below = 0;
    for i in 1..=13 {
        let t = (100.0 * i as f64).min(capacity);
        let sol = solve(&g2, t)?;
        let (r1, r2) = (&sol.patches[0], &sol.patches[1]);
        seq.rows.push(vec![
            num(t),
            r1.slipping.to_string(),
            r2.slipping.to_string(),
            format!("{:?}", sol.regime),
        ]);
        if t < 1000.0 {
            slip1_below = slip1_below.max(r1.slipping);
        }
        share[0].push((t, r1.force / t));
        share[1].push((t, r2.force / t));
        let proj = |c: (f64, f64)| c.1 * angle.cos() - c.0 * angle.sin();
        offset[0].push((t, proj(r1.centre) - proj((-0.5, 0.0))));
        offset[1].push((t, proj(r2.centre) - proj((0.5, 0.0))));
        offset[2].push((t, proj(sol.centre_of_traction)));
        movement[1].push((sol.rigid_per_body[0], t));
        let s1 = solve(&g1, t)?;
        movement[0].push((s1.rigid_per_body[0], t));
    }
    let claims = vec![Claim {
        claim: "some slip occurs in region 1 below 1000 lbf (cases 2/3 pressures)".into(),
        source: src("Example 5", "Some slip is also shown to occur in region 1 below 1000 lbf"),
        holds: slip1_below > 0,
        deciding: format!(
            "largest number of slipping region-1 elements for T < 1000 lbf: {slip1_below} of 36"
        ),
        expected: None,
    }];
    let lines = |v: &[Vec<(f64, f64)>], labels: &[&str]| -> Vec<Series> {
        v.iter()
            .zip(labels)
            .map(|(p, l)| Series { label: (*l).into(), style: Style::Line, points: p.clone() })
            .collect()
    };
    Ok(Check {
        id: "Ex5/F3.16-F3.21",
        seed: SEED,
        title: "Example 5, Figs 3.16-3.21: two 0.6 in squares 1.0 in apart, f = 0.12, load at 45 degrees".into(),
        how: vec!["steel on steel, squares centred at x = -0.5 (region 1) and +0.5 in (region 2), 6 x 6 elements each, LP exact rectangle with traction parallel to the load".into()],
        rows,
        claims,
        tables: vec![tab, seq],
        figures: vec![
            Figure { name: "seed002_F3.19a".into(), caption: "Fig. 3.19a: share of the load carried by each region vs T (cases 2/3 pressures)".into(), x_label: "T (lbf)".into(), y_label: "region force / T".into(), series: lines(&share, &["region 1 (20,000 psi)", "region 2 (10,000 psi)"]) },
            Figure { name: "seed002_F3.19b".into(), caption: "Fig. 3.19b: offset of the resultant's line of action from each centroid, perpendicular to the load (in)".into(), x_label: "T (lbf)".into(), y_label: "offset (in)".into(), series: lines(&offset, &["region 1", "region 2", "whole contact"]) },
            Figure { name: "seed002_F3.21".into(), caption: "Fig. 3.21: T vs per-body rigid-body movement".into(), x_label: "movement (in)".into(), y_label: "T (lbf)".into(), series: lines(&movement, &["case 1 pressures", "cases 2/3 pressures"]) },
        ],
    })
}

/// Tw: twisting moment on Example 1's Hertz circle vs Lubkin.
///
/// # Errors
/// From the physics crates.
pub fn twist() -> Result<Check, Error> {
    let s = steel()?;
    let (p, f) = (pubv::EX1_P.value, pubv::EX1_F.value);
    let a = hertz_radius(p, pubv::EX1_R.value, &s, &s)?;
    let grid = ContactGrid::hertz_circle(a, p, 24)?;
    let mut rows = Vec::new();
    let mut series = Vec::new();
    let h = grid.hx;
    for frac in [0.5, 0.8] {
        let mmax = 3.0 * PI * f * p * a / 16.0;
        let lub = Lubkin::from_moment(a, p, f, frac * mmax)?;
        let sol = lp(
            &grid,
            [s, s],
            f,
            Load::Moment { moment: frac * mmax, centre: None },
            InfluenceModel::ExactRectangle,
        )?;
        let disc = Cause::Discretisation(
            "448 elements and traction directions fixed from the full-stick solution",
        );
        rows.push(
            Row::closed(
                format!("M = {frac} M_max: rotation, relative (rad)"),
                "Lubkin omega, two bodies",
                lub.rotation_relative(&s, &s),
                sol.rigid,
                0.02,
            )
            .because(disc.clone()),
        );
        rows.push(
            Row::closed(
                format!("M = {frac} M_max: rotation per body (rad)"),
                "Lubkin omega, per body",
                lub.rotation_per_body(&s),
                sol.rigid_per_body[0],
                0.02,
            )
            .because(disc.clone()),
        );
        rows.push(
            Row::closed(
                format!("M = {frac} M_max: stick radius (largest stick element centre, in)"),
                "Lubkin c(M)",
                lub.stick_radius(),
                stick_radius(&grid, &sol, (0.0, 0.0)),
                h / lub.stick_radius(),
            )
            .because(disc),
        );
        let mut curve = Vec::new();
        for i in 1..100 {
            let r = a * i as f64 / 100.0;
            curve.push((r / a, lub.traction(r)?));
        }
        series.push(Series {
            label: format!("Lubkin, M = {frac} M_max"),
            style: Style::Line,
            points: curve,
        });
        series.push(Series {
            label: format!("LP, M = {frac} M_max"),
            style: Style::Points,
            points: (0..grid.len())
                .map(|k| (grid.x[k].hypot(grid.y[k]) / a, sol.traction[k]))
                .collect(),
        });
    }
    rows.push(Row::value("elements", grid.len() as f64));
    Ok(Check {
        id: "Tw",
        seed: SEED,
        title: "Twisting moment (section 3.4): LP with the circumferential preprocessor vs Lubkin".into(),
        how: vec!["Example 1's Hertz circle, 24 elements across (448 elements) (exact rectangle influence), M = 0.5 and 0.8 of 3 pi f P a/16; Lubkin M(c), rotation and traction from stickslip-traction (FORMULAS.md G)".into()],
        rows,
        figures: vec![Figure { name: "seed002_Tw".into(), caption: "Twist: circumferential traction (psi) vs r/a, Lubkin and LP".into(), x_label: "r/a".into(), y_label: "traction (psi)".into(), series }],
        ..Check::default()
    })
}

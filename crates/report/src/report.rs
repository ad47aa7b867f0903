//! `report.html`: one self-contained page per run (inline CSS and SVG, no script, nothing
//! fetched), written beside result.json: the scene as given and as resolved, the plan, the
//! key results, the audit, the plots and the solver's figures.

use std::fmt::Write as _;

use stickslip_run::{Outcome, Plan, SurfaceOut};
use stickslip_scene::Scene;

/// What the report shows beyond the outcome: the scene and its plan, when the caller has them
/// (a library caller that only holds an [`Outcome`] gets a report without these sections).
#[derive(Debug, Clone, Copy)]
pub struct ReportContext<'a> {
    /// The scene as read.
    pub scene: &'a Scene,
    /// Its plan.
    pub plan: &'a Plan,
}

/// Text made safe inside HTML elements and attribute values.
fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            _ => o.push(c),
        }
    }
    o
}

pub(crate) use stickslip_scene::eng::eng;

/// `v` as [`eng`] writes it, except that a value within `tol` times `scale` of zero (the
/// result's own tolerance relative to the quantity's scale: rounding, or what the solver did
/// not resolve) is written as 0: `eng_near(3e-17, 1e3, 1e-10, "N")` is "0 N", not
/// "30.00 aN" or "3.000e-17 N". With `tol` = [`stickslip_scene::eng::ZERO_RELATIVE`] this is
/// [`stickslip_scene::eng::eng_scaled`].
pub(crate) fn eng_near(v: f64, scale: f64, tol: f64, unit: &str) -> String {
    if v.is_finite() && v.abs() <= tol * scale.abs() {
        return eng(0.0, unit);
    }
    eng(v, unit)
}

/// The relative tolerance below which a result's value is zero: the grid solver's tolerance
/// when one ran, else 1e-10 (closed forms and quadratures: well below their accuracy and far
/// above rounding of quantities near 1).
fn zero_tolerance(ctx: Option<ReportContext<'_>>) -> f64 {
    use stickslip_run::plan::recipe::{ContactNormal, Recipe, Tangential};
    let fallback = 1e-10;
    let Some(Recipe::Contact(r)) = ctx.map(|c| &c.plan.recipe) else { return fallback };
    let grid = match r.tangential {
        Some(Tangential::Grid(g)) => g.tolerance,
        Some(Tangential::Rolling(g)) => g.tolerance,
        _ => 0.0,
    };
    let normal = match &r.normal {
        ContactNormal::Surface { tolerance, .. } => *tolerance,
        _ => 0.0,
    };
    grid.max(normal).max(fallback)
}

const STYLE: &str = "body{font-family:sans-serif;max-width:1100px;margin:1.5em auto;padding:0 1em;color:#222;line-height:1.4}\
h1{font-size:1.6em;margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}\
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em .6em;text-align:left;vertical-align:top}\
th{background:#f2f2f2}td.num{text-align:right;font-variant-numeric:tabular-nums}\
pre{background:#f7f7f7;border:1px solid #ddd;padding:.6em;overflow-x:auto;font-size:.9em}\
.pass{color:#1a7f37;font-weight:bold}.fail{color:#b42318;font-weight:bold}\
figure.plot{margin:1em 0;padding:0}figure.plot svg{display:block;max-width:100%;height:auto}\
figcaption{font-size:.9em;color:#555}nav a{margin-right:1em}";

fn row(s: &mut String, name: &str, value: &str) {
    let _ = writeln!(s, "<tr><th>{}</th><td class=\"num\">{}</td></tr>", esc(name), esc(value));
}

/// The report page. `plots` are the SVG plots (file name, SVG text) in the order written.
pub(crate) fn render(
    out: &Outcome,
    ctx: Option<ReportContext<'_>>,
    plots: &[(String, String)],
    plots_on: bool,
) -> String {
    let mut s = String::new();
    let title = esc(&out.title);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <link rel=\"icon\" href=\"data:,\">\n<title>{title}: stickslip report</title>\n\
         <style>{STYLE}</style>\n</head>\n<body>\n<h1>{title}</h1>\n"
    );
    let verdict = if out.audit.passed {
        "<span class=\"pass\">audit passed</span>"
    } else {
        "<span class=\"fail\">audit failed</span>"
    };
    let _ = writeln!(
        s,
        "<p>stickslip {} · {verdict} · solved in {} · effects on: {}</p>",
        env!("CARGO_PKG_VERSION"),
        esc(&stickslip_run::plan::human_seconds(out.solver.seconds)),
        esc(&out.effects.on.join(", "))
    );
    s.push_str(
        "<nav><a href=\"#results\">Key results</a><a href=\"#plan\">Plan</a>\
         <a href=\"#scene\">Scene</a><a href=\"#audit\">Audit</a><a href=\"#plots\">Plots</a>\
         <a href=\"#solver\">Solver</a></nav>\n",
    );
    results(&mut s, out, ctx);
    plan(&mut s, out, ctx);
    scene(&mut s, ctx);
    audit(&mut s, out);
    figures(&mut s, plots, plots_on);
    solver(&mut s, out);
    s.push_str("</body>\n</html>\n");
    s
}

fn results(s: &mut String, out: &Outcome, ctx: Option<ReportContext<'_>>) {
    // 2D (plane strain) loads are per unit length.
    let two_d = ctx.map(|c| c.scene.geometry.is_2d());
    let (f, m) = match two_d {
        Some(true) => ("N/m", "N m/m"),
        Some(false) => ("N", "N m"),
        None => ("N (N/m in 2D)", "N m (N m/m in 2D)"),
    };
    s.push_str("<h2 id=\"results\">Key results</h2>\n<table>\n");
    let c = &out.contact;
    let tol = zero_tolerance(ctx);
    // The scales of forces, moments and lengths: the normal load, its moment arm a, and a.
    let (fs, ls) = (c.normal_load, c.a.max(c.b));
    let near = |v: f64, scale: f64, unit: &str| eng_near(v, scale, tol, unit);
    row(s, "contact half-width a", &eng(c.a, "m"));
    row(s, "contact half-width b", &eng(c.b, "m"));
    row(s, "peak pressure p0", &eng(c.p0, "Pa"));
    if let Some(h) = c.indentation {
        row(s, "indentation", &eng(h, "m"));
    }
    row(s, "normal load", &eng(c.normal_load, f));
    if let Some(a) = c.area {
        row(s, "contact area", &eng(a, "m²"));
    }
    if let Some(fr) = c.fraction {
        row(s, "contact fraction", &format!("{fr:.4}"));
    }
    if let Some(fr) = c.plastic_fraction {
        row(s, "plastic fraction of the contact", &format!("{fr:.4}"));
    }
    if let (Some(p), Some(reached)) = (c.pull_off, c.pull_off_reached) {
        if reached {
            row(s, "pull-off", &eng(p, f));
        } else {
            row(s, "pull-off", &format!("not reached (most tensile force {})", eng(p, f)));
        }
    }
    let fo = &out.forces;
    row(s, "normal force", &eng(fo.normal, f));
    row(s, "tangential force", &near(fo.tangential, fs, f));
    row(s, "moment", &near(fo.moment, fs * ls, m));
    row(s, "rolling moment", &near(fo.rolling_moment, fs * ls, m));
    for (name, v, u) in [("creep force Fx", fo.fx, "N"), ("creep force Fy", fo.fy, "N")] {
        if let Some(v) = v {
            row(s, name, &near(v, fs, u));
        }
    }
    if let Some(mz) = fo.mz {
        row(s, "spin moment Mz", &near(mz, fs * ls, "N m"));
    }
    let r = &out.rigid_displacement;
    if let Some(t) = r.tangential {
        row(s, "rigid tangential displacement", &near(t, ls, "m"));
    }
    if let Some(t) = r.rotation {
        row(s, "rigid rotation", &eng(t, "rad"));
    }
    let z = &out.zones;
    let spans = |v: &[[f64; 2]]| -> String {
        if v.is_empty() {
            "none".to_string()
        } else {
            v.iter()
                .map(|p| format!("[{}, {}]", near(p[0], ls, "m"), near(p[1], ls, "m")))
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    if z.grid.is_none() {
        row(s, &format!("stick zones (along {})", z.coordinate), &spans(&z.stick));
        row(s, &format!("slip zones (along {})", z.coordinate), &spans(&z.slip));
    }
    if let Some(g) = &z.grid {
        row(s, "stick / slip elements", &format!("{} / {}", g.stick, g.slip));
        row(s, "stick area fraction", &format!("{:.4}", g.stick_area_fraction));
    }
    if let Some(rl) = &out.rolling {
        row(s, "rolling regime", rl.regime);
        row(s, "rolling response", rl.response);
    }
    if let Some(cy) = &out.cycle {
        row(s, "cycle amplitude T*/(fP)", &format!("{:.4}", cy.amplitude));
        row(
            s,
            "energy per cycle (computed, closed form)",
            &format!("{}, {}", eng(cy.energy_per_cycle[0], "J"), eng(cy.energy_per_cycle[1], "J")),
        );
    }
    if let Some(h) = out.history.as_ref().filter(|h| !h.distance.is_empty()) {
        let n = h.distance.len() - 1;
        row(
            s,
            "transient rolling",
            &format!(
                "{} steps, {} rolled; final creepages xi = {}, eta = {} under Fx = {}, Fy = {}",
                n + 1,
                eng(h.distance[n], "m"),
                eng(h.creepage_longitudinal[n], ""),
                eng(h.creepage_lateral[n], ""),
                eng(h.fx[n], "N"),
                eng(h.fy[n], "N")
            ),
        );
        row(s, "energy dissipated while rolling", &eng(h.dissipated[n], "J"));
    } else if let Some(h) = &out.history {
        row(
            s,
            "load path",
            &format!(
                "{} control along {:.1} degrees, {} steps, {} corners",
                h.control,
                h.direction_deg,
                h.tangential.len(),
                h.corners.len()
            ),
        );
        if let Some(d) = h.dissipated.last() {
            row(s, "energy dissipated over the path", &eng(*d, "J"));
        }
        for (i, l) in h.loops.iter().enumerate() {
            row(
                s,
                &format!("loop {} (steps {} to {})", i + 1, l.first_step, l.last_step),
                &format!(
                    "energy {}; force range {}, shift range {}, shift drift {}",
                    eng(l.energy, "J"),
                    eng(l.force_range, "N"),
                    eng(l.shift_range, "m"),
                    stickslip_scene::eng::eng_scaled(l.shift_drift, l.shift_range, "m")
                ),
            );
        }
        let slides = h.gross_slip.iter().filter(|g| **g).count();
        if slides > 0 {
            row(s, "steps in gross slip", &slides.to_string());
        }
    }
    if let Some(v) = out.field.volume() {
        for (name, p) in [
            ("peak von Mises", &v.max.von_mises),
            ("peak Tresca", &v.max.tresca),
            ("peak max principal", &v.max.max_principal),
        ] {
            row(
                s,
                name,
                &format!(
                    "{} at ({}, {}, {})",
                    eng(p.value, "Pa"),
                    near(p.x, ls, "m"),
                    near(p.y, ls, "m"),
                    near(p.z, ls, "m")
                ),
            );
        }
    }
    s.push_str("</table>\n");
    if !out.notes.is_empty() {
        s.push_str("<p>Notes:</p>\n<ul>\n");
        for n in &out.notes {
            let _ = writeln!(s, "<li>{}</li>", esc(n));
        }
        s.push_str("</ul>\n");
    }
}

fn plan(s: &mut String, out: &Outcome, ctx: Option<ReportContext<'_>>) {
    s.push_str("<h2 id=\"plan\">Plan</h2>\n");
    let Some(ctx) = ctx else {
        // Only the outcome is at hand: its effects and methods.
        s.push_str("<table>\n<tr><th>effect</th><th>on</th><th>method or reason</th></tr>\n");
        for e in &out.effects.on {
            let m = out.effects.methods.get(e).map_or("", String::as_str);
            let _ = writeln!(s, "<tr><td>{}</td><td>on</td><td>{}</td></tr>", esc(e), esc(m));
        }
        for (e, why) in &out.effects.off {
            let _ = writeln!(s, "<tr><td>{}</td><td>off</td><td>{}</td></tr>", esc(e), esc(why));
        }
        s.push_str("</table>\n");
        return;
    };
    let p = ctx.plan;
    s.push_str("<table>\n<tr><th>effect</th><th>on</th><th>why</th><th>method</th></tr>\n");
    for e in &p.effects {
        let method = e.technique.map_or("", stickslip_run::Technique::describe);
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(e.effect.name()),
            if e.on { "on" } else { "off" },
            esc(&e.reason),
            esc(method)
        );
    }
    s.push_str("</table>\n");
    if let Some(g) = &p.grid_solver {
        let _ = writeln!(s, "<p>Grid solver: {}</p>", esc(g));
    }
    if !p.notes.is_empty() {
        s.push_str("<ul>\n");
        for n in &p.notes {
            let _ = writeln!(s, "<li>{}</li>", esc(n));
        }
        s.push_str("</ul>\n");
    }
    let c = p.cost;
    let _ = writeln!(
        s,
        "<p>Estimate: {} evaluations, about {} on one core, {} of working memory \
         (measured: {}).</p>",
        c.evaluations,
        esc(&stickslip_run::plan::human_seconds(c.seconds)),
        esc(&stickslip_run::plan::human_bytes(c.memory_bytes)),
        esc(&stickslip_run::plan::human_seconds(out.solver.seconds))
    );
}

fn scene(s: &mut String, ctx: Option<ReportContext<'_>>) {
    s.push_str("<h2 id=\"scene\">Scene</h2>\n");
    let Some(ctx) = ctx else {
        s.push_str("<p>The result was written without its scene (a library call that passed only the outcome).</p>\n");
        return;
    };
    let sc = ctx.scene;
    if let Some(f) = &sc.file {
        let _ = writeln!(s, "<p>File: <code>{}</code></p>", esc(&f.display().to_string()));
    }
    match &sc.source {
        Some(src) => {
            let _ = writeln!(s, "<h3>As given</h3>\n<pre>{}</pre>", esc(src.text()));
        }
        None => s.push_str("<p>The scene was built in code; there is no file text.</p>\n"),
    }
    let named = sc.source.as_ref().map_or(&[][..], |src| src.materials());
    if !named.is_empty() {
        s.push_str(
            "<p>Named materials (typical values of one grade; docs/materials.md):</p>\n<ul>\n",
        );
        for (table, m) in named {
            let _ = writeln!(
                s,
                "<li>{}: {}, E = {}, ν = {} ({})</li>",
                esc(table),
                esc(m.name),
                esc(&stickslip_scene::materials::modulus(m.e)),
                m.nu,
                esc(&m.grade.split_whitespace().collect::<Vec<_>>().join(" "))
            );
        }
        s.push_str("</ul>\n");
    }
    // The keys of the file as a table: as given, in SI, and where the value came from.
    if let Some(table) = sc.source.as_ref().and_then(|src| src.text().parse::<toml::Table>().ok()) {
        let mut rows = Vec::new();
        given_rows("", &toml::Value::Table(table), &mut rows);
        s.push_str(
            "<h3>As resolved</h3>\n<table>\n<tr><th>key</th><th>as given</th>\
             <th>value (SI)</th><th>from</th></tr>\n",
        );
        for (key, given, si) in &rows {
            let _ = writeln!(
                s,
                "<tr><td><code>{}</code></td><td>{}</td><td class=\"num\">{}</td><td>given</td></tr>",
                esc(key),
                esc(given),
                esc(si)
            );
        }
        s.push_str(
            "</table>\n<p>Every key the file leaves out takes its default (docs/SCENES.md); \
             the validated scene below shows them all.</p>\n",
        );
    }
    // The validated scene, every quantity converted to SI, defaults included.
    let mut resolved = Scene { source: None, ..sc.clone() };
    // A measured or generated roughness has a height per lattice cell (a million at 1024^2):
    // the page states its size and range; the heights themselves are in the scene's file or
    // its generator, and the gap they give in surface_gap.npy.
    let mut roughness = String::new();
    if let stickslip_scene::Geometry::Surface(surf) = &mut resolved.geometry {
        if let Some(h) = surf.roughness.take() {
            let n = h.len() as f64;
            let rms = (h.iter().map(|v| v * v).sum::<f64>() / n.max(1.0)).sqrt();
            let (lo, hi) = h
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
            roughness = format!(
                "\nroughness (shown as None above): {} heights, rms {rms:e} m, from {lo:e} to {hi:e} m; \
                 the initial gap they give is in surface_gap.npy",
                h.len()
            );
        }
    }
    let _ = writeln!(
        s,
        "<details><summary>The validated scene with its defaults</summary>\n<p>Every quantity in SI units: lengths in m, moduli and stresses \
         in Pa, forces in N (N/m in 2D), speeds in m/s, times in s, angles in rad (in degrees \
         where the name ends in <code>_deg</code>); a field grid with <code>scale: HalfWidth</code> \
         is in units of the contact half-width a. Printed as Rust values.</p>\n<pre>{}</pre>\n</details>",
        esc(&tidy_floats(&format!(
            "geometry: {:#?}{roughness}\nsubstrate: {:#?}\nindenter: {:#?}\nload: {:#?}\nmotion: {:#?}\noutputs: {:#?}\nsolver: {:#?}",
            resolved.geometry,
            resolved.substrate,
            resolved.indenter,
            resolved.load,
            resolved.motion,
            resolved.outputs,
            resolved.solver
        )))
    );
}

/// A quantity string ("20 mm", "210 GPa") in SI: the value and the SI unit (Pa for a
/// stress); None when `text` is not a number with a known unit.
fn si_quantity(text: &str) -> Option<(f64, String)> {
    let t = text.trim();
    // the number is the longest prefix that parses, as the scene reader takes it
    let (num, unit) = (1..=t.len())
        .rev()
        .filter(|&k| t.is_char_boundary(k))
        .find_map(|k| t[..k].trim().parse::<f64>().ok().map(|v| (v, t[k..].trim())))?;
    if unit.is_empty() {
        return Some((num, String::new()));
    }
    let (factor, dim) = stickslip_scene::units::parse_unit(unit, t).ok()?;
    let u = match dim.to_string().as_str() {
        "N/m^2" => "Pa".to_string(),
        "1 (dimensionless)" => String::new(),
        d => d.to_string(),
    };
    Some((num * factor, u))
}

/// `text` (a Rust value printed with `{:#?}`) with each floating-point number rounded to 12
/// significant digits, so that conversion noise such as `5.0000000000000004e-8` reads `5e-8`.
fn tidy_floats(text: &str) -> String {
    let b = text.as_bytes();
    let mut o = String::with_capacity(text.len());
    let mut k = 0;
    while k < b.len() {
        let starts = b[k].is_ascii_digit()
            && (k == 0 || !(b[k - 1].is_ascii_alphanumeric() || b[k - 1] == b'_'));
        if starts {
            let mut e = k;
            while e < b.len()
                && (b[e].is_ascii_digit()
                    || b[e] == b'.'
                    || b[e] == b'e'
                    || (matches!(b[e], b'-' | b'+') && e > k && b[e - 1] == b'e'))
            {
                e += 1;
            }
            let tok = &text[k..e];
            if tok.contains(['.', 'e']) {
                if let Ok(v) = tok.parse::<f64>() {
                    let r: f64 = format!("{v:.11e}").parse().unwrap_or(v);
                    o.push_str(&format!("{r:?}"));
                    k = e;
                    continue;
                }
            }
            o.push_str(tok);
            k = e;
            continue;
        }
        let ch = text[k..].chars().next().unwrap_or(' ');
        o.push(ch);
        k += ch.len_utf8();
    }
    o
}

/// Every leaf of the scene file `v` under the dotted key `key`: (key, as given, in SI).
fn given_rows(key: &str, v: &toml::Value, rows: &mut Vec<(String, String, String)>) {
    let join = |k: &str| if key.is_empty() { k.to_string() } else { format!("{key}.{k}") };
    let scalar = |v: &toml::Value| -> Option<(String, String)> {
        match v {
            toml::Value::String(t) => {
                Some((t.clone(), si_quantity(t).map_or_else(|| t.clone(), |(x, u)| eng(x, &u))))
            }
            toml::Value::Float(x) => Some((v.to_string(), eng(*x, ""))),
            toml::Value::Integer(_) | toml::Value::Boolean(_) | toml::Value::Datetime(_) => {
                Some((v.to_string(), v.to_string()))
            }
            _ => None,
        }
    };
    match v {
        toml::Value::Table(t) => {
            for (k, x) in t {
                given_rows(&join(k), x, rows);
            }
        }
        toml::Value::Array(a) => {
            let parts: Option<Vec<(String, String)>> = a.iter().map(scalar).collect();
            match parts {
                Some(p) => rows.push((
                    key.to_string(),
                    format!("[{}]", p.iter().map(|x| x.0.as_str()).collect::<Vec<_>>().join(", ")),
                    format!("[{}]", p.iter().map(|x| x.1.as_str()).collect::<Vec<_>>().join(", ")),
                )),
                None => {
                    for (i, x) in a.iter().enumerate() {
                        given_rows(&format!("{key}[{i}]"), x, rows);
                    }
                }
            }
        }
        _ => {
            if let Some((g, si)) = scalar(v) {
                rows.push((key.to_string(), g, si));
            }
        }
    }
}

fn audit(s: &mut String, out: &Outcome) {
    s.push_str("<h2 id=\"audit\">Audit</h2>\n<table>\n<tr><th>check</th><th>value</th><th>limit</th><th>result</th><th>what</th></tr>\n");
    for c in &out.audit.checks {
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td class=\"num\">{:.3e}</td><td class=\"num\">{:.3e}</td><td class=\"{}\">{}</td><td>{}</td></tr>",
            esc(c.name),
            c.value,
            c.limit,
            if c.pass { "pass" } else { "fail" },
            if c.pass { "pass" } else { "fail" },
            esc(&c.what)
        );
    }
    s.push_str("</table>\n");
}

fn figures(s: &mut String, plots: &[(String, String)], plots_on: bool) {
    s.push_str("<h2 id=\"plots\">Plots</h2>\n");
    if !plots_on {
        s.push_str("<p>Plots are off for this scene (<code>outputs.plots = false</code>).</p>\n");
        return;
    }
    if plots.is_empty() {
        s.push_str("<p>This result has no arrays to plot (turn on <code>outputs.surface</code>, <code>outputs.field</code> or <code>outputs.cycle</code>).</p>\n");
        return;
    }
    s.push_str(
        "<p>The plots are for reading: a map of a lattice more than 160 cells across shows the \
         means of square blocks of cells (its title gives the block size), drawn as an image. \
         The full-resolution arrays lie beside this report, whole: the <code>.npy</code> files \
         (<code>surface_p.npy</code>, <code>surface_qx.npy</code>, … and <code>field_*.npy</code>), \
         the CSV files and <code>result.json</code>.</p>\n",
    );
    for (i, (name, svg)) in plots.iter().enumerate() {
        // The SVG follows its XML prologue, if any.
        let body = svg.find("<svg").map_or(svg.as_str(), |k| &svg[k..]);
        let _ = writeln!(
            s,
            "<figure class=\"plot\" id=\"plot-{i}\">\n{body}\n<figcaption>{} (also {})</figcaption>\n</figure>",
            esc(name.trim_end_matches(".svg")),
            esc(name)
        );
    }
}

fn solver(s: &mut String, out: &Outcome) {
    let v = &out.solver;
    s.push_str("<h2 id=\"solver\">Solver</h2>\n<table>\n");
    row(s, "method", &v.method);
    row(s, "iterations", &v.iterations.to_string());
    row(s, "inner iterations", &v.inner_iterations.to_string());
    row(s, "residual", &format!("{:.3e}", v.residual));
    row(s, "elements", &v.elements.to_string());
    row(s, "solve time", &stickslip_run::plan::human_seconds(v.solve_seconds));
    row(s, "total time", &stickslip_run::plan::human_seconds(v.seconds));
    if let SurfaceOut::Grid { x, y, .. } = &out.surface {
        row(s, "grid", &format!("{} x {}", x.len(), y.len()));
    }
    if let Some(n) = &v.normal {
        row(
            s,
            "normal solver",
            &format!(
                "{} iterations ({} FFT products, {} preconditioner products), {} coarser \
                 lattices first ({} iterations); residual {:.3e}; {} (set-up {})",
                n.iterations,
                n.products,
                n.preconditioner_products,
                n.levels,
                n.coarse_iterations,
                n.residual,
                stickslip_run::plan::human_seconds(n.solve_seconds),
                stickslip_run::plan::human_seconds(n.setup_seconds),
            ),
        );
    }
    s.push_str("</table>\n");
}

#[cfg(test)]
mod tests {
    use super::{eng, eng_near, esc, si_quantity, tidy_floats};

    #[test]
    fn quantities_in_si() {
        assert_eq!(si_quantity("20 mm"), Some((0.02, "m".to_string())));
        assert_eq!(si_quantity("210 GPa"), Some((210e9, "Pa".to_string())));
        assert_eq!(si_quantity("0.3"), Some((0.3, String::new())));
        assert_eq!(si_quantity("cylinder"), None);
    }

    #[test]
    fn near_zero_prints_zero_in_the_scale_unit() {
        assert_eq!(eng_near(3e-17, 1e3, 1e-10, "N"), "0 N");
        assert_eq!(eng_near(-1e-30, 2.5e-4, 1e-10, "m"), "0 m");
        assert_eq!(eng_near(0.0, 0.0, 1e-10, "N"), "0 N");
        // above the tolerance: the value itself
        assert_eq!(eng_near(2e-6, 1e3, 1e-10, "N"), "2.000 µN");
        // never a femto-prefixed zero: tiny values without a scale keep their exponent
        assert_eq!(eng(1e-30, "N"), "1.000e-30 N");
    }

    #[test]
    fn engineering_prefixes() {
        assert_eq!(eng(2.5e-4, "m"), "250.0 µm");
        assert_eq!(eng(1.2e9, "Pa"), "1.200 GPa");
        assert_eq!(eng(-15e3, "N/m"), "-15.00 kN/m");
        assert_eq!(eng(0.0, "N"), "0 N");
        assert_eq!(eng(1.0, "N"), "1.000 N");
    }

    #[test]
    fn tidy_floats_rounds_conversion_noise_only() {
        assert_eq!(tidy_floats("a: 5.0000000000000004e-8,"), "a: 5e-8,");
        assert_eq!(tidy_floats("x: 0.30000000000000004 y: 7 z2: 1.5"), "x: 0.3 y: 7 z2: 1.5");
        assert_eq!(tidy_floats("e: -2.1e11, µ: 0.1"), "e: -210000000000.0, µ: 0.1");
    }

    #[test]
    fn escaping() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}

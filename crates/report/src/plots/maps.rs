//! Maps on the lattice: colour scales, colour bars and contour levels, the stick zone's
//! outline, block means of big lattices and their raster image, and the heat and stick
//! maps themselves.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::prelude::*;

use super::raster as png;
use super::{contour, err, tick, titled, PlotResult, Units};

/// Blue (negative) - white - red (positive) colour scale, symmetric about zero.
pub(super) fn diverging(v: f64, vmax: f64) -> RGBColor {
    let t = if vmax > 0.0 { (v / vmax).clamp(-1.0, 1.0) } else { 0.0 };
    let w = |a: f64| (255.0 * (1.0 - a.abs())) as u8;
    if t >= 0.0 {
        RGBColor(255, w(t), w(t))
    } else {
        RGBColor(w(t), w(t), 255)
    }
}

/// The colour scale of a map: viridis from 0 to the largest value for a quantity that is
/// never negative, or the diverging scale centred on zero for a signed one.
#[derive(Debug, Clone, Copy)]
pub(super) enum Scale {
    Viridis { max: f64 },
    Diverging { max: f64 },
}

impl Scale {
    fn of(v: &[Vec<f64>]) -> Scale {
        let vals = v.iter().flatten().copied().filter(|x| x.is_finite());
        let (lo, hi) = vals.fold((0.0f64, 0.0f64), |(lo, hi), x| (lo.min(x), hi.max(x)));
        // A negative value below 1e-9 of the largest is rounding, not a sign.
        if lo >= -1e-9 * hi.abs() {
            Scale::Viridis { max: hi }
        } else {
            Scale::Diverging { max: hi.max(-lo) }
        }
    }

    fn bounds(self) -> (f64, f64) {
        match self {
            Scale::Viridis { max } => (0.0, max),
            Scale::Diverging { max } => (-max, max),
        }
    }

    fn colour(self, v: f64) -> RGBColor {
        use plotters::style::colors::colormaps::{ColorMap, ViridisRGB};
        match self {
            Scale::Viridis { max } => {
                let t = if max > 0.0 { (v / max).clamp(0.0, 1.0) } else { 0.0 };
                ViridisRGB.get_color_normalized(t, 0.0, 1.0)
            }
            Scale::Diverging { max } => diverging(v, max),
        }
    }
}

/// A label of a contour level on a grid of round levels `step` apart: the decimals the step
/// needs, no exponent, no "-0".
pub(super) fn level_label(v: f64, step: f64) -> String {
    let decimals = (-step.abs().max(1e-300).log10().floor()).clamp(0.0, 9.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// A linear axis from `lo` to `hi` whose ticks are exactly `ticks` (the contour levels), for
/// the colour bar. (plotters' own `with_key_points` does not take a label formatter.)
pub(super) struct LevelAxis {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
}

impl Ranged for LevelAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let t = (v - self.lo) / (self.hi - self.lo);
        limit.0 + (t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, _hint: Hint) -> Vec<f64> {
        self.ticks.clone()
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// Contour lines: thin, dark and half transparent so that the colours stay readable.
pub(super) fn contour_style() -> ShapeStyle {
    RGBColor(20, 20, 20).mix(0.7).stroke_width(1)
}

/// The colour bar of `scale` in `area`, labelled with the value's name and unit. Its ticks
/// are the contour levels `levels` (in the units of `units`, `step` apart), each marked
/// with a contour-styled line across the bar, and the bar's ends where they are round.
pub(super) fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    scale: Scale,
    units: &Units,
    name: &str,
    (step, levels): (f64, &[f64]),
) -> Result<(), String> {
    let (lo, hi) = scale.bounds();
    let (a, b) = (lo / units.div, hi / units.div);
    let (a, b) = if b > a { (a, b) } else { (a - 1.0, a + 1.0) };
    let mut ticks = levels.to_vec();
    let round = |v: f64| step > 0.0 && (v / step - (v / step).round()).abs() < 1e-9;
    for end in [a, b] {
        if round(end) {
            ticks.push(end);
        }
    }
    ticks.sort_by(f64::total_cmp);
    let mut bar = ChartBuilder::on(area)
        .margin_top(12)
        .margin_bottom(45)
        .margin_right(8)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, LevelAxis { lo: a, hi: b, ticks })
        .map_err(|e| e.to_string())?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_label_style(("sans-serif", 12))
        .axis_desc_style(("sans-serif", 13))
        .y_desc(units.desc(name))
        .y_label_formatter(&|v| if step > 0.0 { level_label(*v, step) } else { tick(*v, b - a) })
        .draw()
        .map_err(|e| e.to_string())?;
    let n = 64;
    bar.draw_series((0..n).map(|k| {
        let (v0, v1) = (a + (b - a) * k as f64 / n as f64, a + (b - a) * (k + 1) as f64 / n as f64);
        let c = scale.colour(0.5 * (v0 + v1) * units.div);
        Rectangle::new([(0.0, v0), (1.0, v1)], c.filled())
    }))
    .map_err(|e| e.to_string())?;
    bar.draw_series(
        levels.iter().map(|&l| PathElement::new(vec![(0.0, l), (1.0, l)], contour_style())),
    )
    .map_err(|e| e.to_string())?;
    Ok(())
}

/// Plot area (pixels) with equal scales on both axes for spans `w` x `h`, at most 500 x 420.
pub(super) fn equal_axes(w: f64, h: f64) -> (u32, u32) {
    let (mw, mh) = (500.0, 420.0);
    let k = (mw / w).min(mh / h);
    ((w * k).round().max(60.0) as u32, (h * k).round().max(60.0) as u32)
}

/// The outline of the stick zone (`stick[i][j] == 1`), as segments in metres. On a lattice
/// drawn in blocks, the outline of the blocks' stick map (as the stick map
/// shows it); collinear edges that meet are joined into one segment.
pub(super) fn stick_outline(x: &[f64], y: &[f64], stick: &[Vec<i8>]) -> Vec<[(f64, f64); 2]> {
    let (bx, by) = (block(x.len()), block(y.len()));
    let segs = if bx > 1 || by > 1 {
        let merged = merge_stick(stick, y.len(), bx, by);
        cell_edges(&coarse_axis(x, bx), &coarse_axis(y, by), &merged)
    } else {
        cell_edges(x, y, stick)
    };
    join_collinear(segs)
}

/// Segments along x (then along y) that continue one another, joined.
pub(super) fn join_collinear(segs: Vec<[(f64, f64); 2]>) -> Vec<[(f64, f64); 2]> {
    // Cell sides computed from neighbouring centres differ by rounding only.
    let near = |u: f64, v: f64, s: &[(f64, f64); 2]| {
        (u - v).abs() <= 1e-6 * (s[1].0 - s[0].0).abs().max((s[1].1 - s[0].1).abs())
    };
    let (mut along_x, mut along_y): (Vec<_>, Vec<_>) =
        segs.into_iter().partition(|[a, b]| (a.1 - b.1).abs() <= (a.0 - b.0).abs());
    let mut out: Vec<[(f64, f64); 2]> = Vec::new();
    along_x.sort_by(|p, q| p[0].1.total_cmp(&q[0].1).then(p[0].0.total_cmp(&q[0].0)));
    for s in along_x {
        match out.last_mut() {
            Some([a, b]) if near(a.1, s[0].1, &s) && near(b.0, s[0].0, &s) => *b = s[1],
            _ => out.push(s),
        }
    }
    let n = out.len();
    along_y.sort_by(|p, q| p[0].0.total_cmp(&q[0].0).then(p[0].1.total_cmp(&q[0].1)));
    for s in along_y {
        match out[n..].last_mut() {
            Some([a, b]) if near(a.0, s[0].0, &s) && near(b.1, s[0].1, &s) => *b = s[1],
            _ => out.push(s),
        }
    }
    out
}

/// Blocks of `bx` x `by` cells of `stick[i][j]` (`ny` cells along y): a block sticks if most
/// of its contact elements stick; outside if it has none.
pub(super) fn merge_stick(stick: &[Vec<i8>], ny: usize, bx: usize, by: usize) -> Vec<Vec<i8>> {
    stick
        .chunks(bx)
        .map(|cols| {
            (0..ny.div_ceil(by))
                .map(|jb| {
                    let rows = jb * by..((jb + 1) * by).min(ny);
                    let (mut st, mut sl) = (0usize, 0usize);
                    for c in cols {
                        for v in &c[rows.clone()] {
                            match v {
                                1 => st += 1,
                                0 => sl += 1,
                                _ => {}
                            }
                        }
                    }
                    if st + sl == 0 {
                        -1
                    } else {
                        i8::from(st >= sl)
                    }
                })
                .collect()
        })
        .collect()
}

/// Edges between a stick cell and any other cell or the grid's edge, one per cell side.
pub(super) fn cell_edges(x: &[f64], y: &[f64], stick: &[Vec<i8>]) -> Vec<[(f64, f64); 2]> {
    let hx = if x.len() > 1 { x[1] - x[0] } else { 1.0 };
    let hy = if y.len() > 1 { y[1] - y[0] } else { 1.0 };
    let is = |i: isize, j: isize| -> bool {
        i >= 0
            && j >= 0
            && (i as usize) < x.len()
            && (j as usize) < y.len()
            && stick[i as usize][j as usize] == 1
    };
    let mut segs = Vec::new();
    for i in 0..x.len() {
        for j in 0..y.len() {
            if stick[i][j] != 1 {
                continue;
            }
            let (ii, jj) = (i as isize, j as isize);
            let (xl, xr) = (x[i] - 0.5 * hx, x[i] + 0.5 * hx);
            let (yl, yr) = (y[j] - 0.5 * hy, y[j] + 0.5 * hy);
            if !is(ii - 1, jj) {
                segs.push([(xl, yl), (xl, yr)]);
            }
            if !is(ii + 1, jj) {
                segs.push([(xr, yl), (xr, yr)]);
            }
            if !is(ii, jj - 1) {
                segs.push([(xl, yl), (xr, yl)]);
            }
            if !is(ii, jj + 1) {
                segs.push([(xl, yr), (xr, yr)]);
            }
        }
    }
    segs
}

/// Most cells drawn along a side of a map: beyond it, square blocks of cells are merged so
/// that an SVG of a fine grid stays a few MB (one rectangle per drawn cell).
pub(super) const MAX_CELLS_PER_SIDE: usize = 160;

/// Cells merged per block along an axis of `n` cells.
pub(super) fn block(n: usize) -> usize {
    n.div_ceil(MAX_CELLS_PER_SIDE).max(1)
}

/// Block centres of an axis: the mean of each run of `b` coordinates.
pub(super) fn coarse_axis(x: &[f64], b: usize) -> Vec<f64> {
    x.chunks(b).map(|c| c.iter().sum::<f64>() / c.len() as f64).collect()
}

/// Block means of `v[j][i]` (rows along y, columns along x).
pub(super) fn coarse_rows(v: &[Vec<f64>], by: usize, bx: usize) -> Vec<Vec<f64>> {
    v.chunks(by)
        .map(|rows| {
            let nx = rows[0].len();
            (0..nx.div_ceil(bx))
                .map(|ib| {
                    let cols = ib * bx..((ib + 1) * bx).min(nx);
                    let cnt = (rows.len() * cols.len()) as f64;
                    rows.iter().map(|r| r[cols.clone()].iter().sum::<f64>()).sum::<f64>() / cnt
                })
                .collect()
        })
        .collect()
}

/// Maps of more cells than this are drawn as one embedded image rather than a rectangle
/// per cell (which costs about 100 bytes each in the SVG).
pub(super) const MAX_RECT_CELLS: usize = 2500;

/// The image of a map: pixel (column, row from the top) of cell (`i`, `j`), with `x` and
/// `y` the cell centres; `top_is_max_y` when larger y is drawn higher (not for depth).
pub(super) fn raster(
    x: &[f64],
    y: &[f64],
    top_is_max_y: bool,
    colour: impl Fn(usize, usize) -> Option<RGBColor>,
) -> Vec<u8> {
    let (nx, ny) = (x.len(), y.len());
    let x_up = x[nx - 1] >= x[0];
    let y_up = y[ny - 1] >= y[0];
    let mut px = Vec::with_capacity(nx * ny);
    for r in 0..ny {
        let j = if y_up == top_is_max_y { ny - 1 - r } else { r };
        for c in 0..nx {
            let i = if x_up { c } else { nx - 1 - c };
            px.push(colour(i, j).map_or([0, 0, 0, 0], |RGBColor(r, g, b)| [r, g, b, 255]));
        }
    }
    png::png_rgba(nx, ny, &px)
}

/// The marker rectangle over the whole plot area, which [`png::embed`] replaces.
pub(super) fn marker(a: (f64, f64), b: (f64, f64)) -> Rectangle<(f64, f64)> {
    let (r, g, bl) = png::MARKER;
    Rectangle::new([a, b], RGBColor(r, g, bl).filled())
}

/// A map of `v[j][i]` (rows along y, columns along x) of the quantity `name` in `base` units.
pub(super) struct Map<'a> {
    pub(super) title: String,
    /// Key parameters, a second title line.
    pub(super) sub: &'a str,
    pub(super) name: &'a str,
    pub(super) base: &'a str,
    pub(super) x: &'a [f64],
    pub(super) y: &'a [f64],
    pub(super) v: &'a [Vec<f64>],
    /// Depth downwards (the y axis reversed).
    pub(super) yflip: bool,
    pub(super) yname: &'a str,
    /// Segments (m) drawn over the map: the stick zone's outline.
    pub(super) outline: &'a [[(f64, f64); 2]],
}

pub(super) fn heat_map(m: &Map<'_>) -> PlotResult {
    let (bx, by) = (block(m.x.len()), block(m.y.len()));
    if bx > 1 || by > 1 {
        let (x, y, v) = (coarse_axis(m.x, bx), coarse_axis(m.y, by), coarse_rows(m.v, by, bx));
        let title = format!("{}, {bx} x {by} cell blocks", m.title);
        return heat_map(&Map { title, x: &x, y: &y, v: &v, ..*m });
    }
    let (x, y, v) = (m.x, m.y, m.v);
    let as_image = x.len() * y.len() > MAX_RECT_CELLS;
    let hx = if x.len() > 1 { x[1] - x[0] } else { 1.0 };
    let hy = if y.len() > 1 { y[1] - y[0] } else { 1.0 };
    let (xa, xb) = (x[0] - 0.5 * hx, x[x.len() - 1] + 0.5 * hx);
    let (ya, yb) = (y[0] - 0.5 * hy, y[y.len() - 1] + 0.5 * hy);
    let lu = Units::for_max(xa.abs().max(xb.abs()).max(ya.abs()).max(yb.abs()), "m");
    let scale = Scale::of(v);
    let vu = Units::for_max(scale.bounds().1, m.base);
    let (pw, ph) = equal_axes(xb - xa, yb - ya);
    // plot area + y labels (75) + margins; the colour bar takes 110 on the right.
    // At least 720 wide so that the title fits; the map keeps its equal scales on the left.
    let (w, h) = ((pw + 75 + 24 + 110).max(720), ph + 60 + 45 + 24);
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = titled(&root, &m.title, m.sub)?;
        let (left, rest) = root.split_horizontally(pw + 75 + 24);
        let (right, _) = rest.split_horizontally(110);
        let (sxa, sxb, sya, syb) = (xa / lu.div, xb / lu.div, ya / lu.div, yb / lu.div);
        let mut chart = ChartBuilder::on(&left)
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(75)
            .build_cartesian_2d(sxa..sxb, if m.yflip { syb..sya } else { sya..syb })
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(lu.desc("x"))
            .y_desc(lu.desc(m.yname))
            .x_label_formatter(&|v| tick(*v, sxb - sxa))
            .y_label_formatter(&|v| tick(*v, syb - sya))
            .draw()
            .map_err(err)?;
        let d = lu.div;
        let cells = y
            .iter()
            .enumerate()
            .flat_map(|(j, &yy)| x.iter().enumerate().map(move |(i, &xx)| (i, j, xx, yy)))
            .filter(|_| !as_image);
        if as_image {
            chart.draw_series(std::iter::once(marker((sxa, sya), (sxb, syb)))).map_err(err)?;
        }
        chart
            .draw_series(cells.map(|(i, j, xx, yy)| {
                Rectangle::new(
                    [
                        ((xx - 0.5 * hx) / d, (yy - 0.5 * hy) / d),
                        ((xx + 0.5 * hx) / d, (yy + 0.5 * hy) / d),
                    ],
                    scale.colour(v[j][i]).filled(),
                )
            }))
            .map_err(err)?;
        // Contours at the colour bar's round levels.
        let (step, levels) =
            contour::round_levels(scale.bounds().0 / vu.div, scale.bounds().1 / vu.div);
        for &l in &levels {
            for line in contour::iso_lines(x, y, v, l * vu.div) {
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        line.points.iter().map(|&(px, py)| (px / d, py / d)).collect::<Vec<_>>(),
                        contour_style(),
                    )))
                    .map_err(err)?;
            }
        }
        chart
            .draw_series(m.outline.iter().map(|&[(x0, y0), (x1, y1)]| {
                PathElement::new(vec![(x0 / d, y0 / d), (x1 / d, y1 / d)], WHITE.stroke_width(2))
            }))
            .map_err(err)?;
        colour_bar(&right, scale, &vu, m.name, (step, &levels))?;
        root.present().map_err(err)?;
    }
    if as_image {
        let png = raster(x, y, !m.yflip, |i, j| Some(scale.colour(v[j][i])));
        png::embed(&mut s, &png)?;
    }
    Ok(s)
}

/// Colours of the stick map.
pub(super) const STICK: RGBColor = RGBColor(70, 110, 220);
pub(super) const SLIP: RGBColor = RGBColor(220, 80, 60);

pub(super) fn stick_map(
    (title, sub): (&str, &str),
    x: &[f64],
    y: &[f64],
    stick: &[Vec<i8>],
) -> PlotResult {
    let (bx, by) = (block(x.len()), block(y.len()));
    if bx > 1 || by > 1 {
        let merged = merge_stick(stick, y.len(), bx, by);
        return stick_map((title, sub), &coarse_axis(x, bx), &coarse_axis(y, by), &merged);
    }
    let as_image = x.len() * y.len() > MAX_RECT_CELLS;
    let hx = if x.len() > 1 { x[1] - x[0] } else { 1.0 };
    let hy = if y.len() > 1 { y[1] - y[0] } else { 1.0 };
    let (xa, xb) = (x[0] - 0.5 * hx, x[x.len() - 1] + 0.5 * hx);
    let (ya, yb) = (y[0] - 0.5 * hy, y[y.len() - 1] + 0.5 * hy);
    let lu = Units::for_max(xa.abs().max(xb.abs()).max(ya.abs()).max(yb.abs()), "m");
    let d = lu.div;
    let (pw, ph) = equal_axes(xb - xa, yb - ya);
    let mut s = String::new();
    {
        // At least 720 wide so that the title fits; the map keeps its equal scales on the left.
        let root = SVGBackend::with_string(&mut s, ((pw + 75 + 24).max(720), ph + 60 + 45 + 24))
            .into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = titled(&root, &format!("{title}: stick (blue), slip (red)"), sub)?;
        let (root, _) = root.split_horizontally(pw + 75 + 24);
        let (sxa, sxb, sya, syb) = (xa / d, xb / d, ya / d, yb / d);
        let mut chart = ChartBuilder::on(&root)
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(75)
            .build_cartesian_2d(sxa..sxb, sya..syb)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(lu.desc("x"))
            .y_desc(lu.desc("y"))
            .x_label_formatter(&|v| tick(*v, sxb - sxa))
            .y_label_formatter(&|v| tick(*v, syb - sya))
            .draw()
            .map_err(err)?;
        let cells = x.iter().enumerate().flat_map(|(i, &xx)| {
            y.iter().enumerate().filter_map(move |(j, &yy)| {
                let st = stick[i][j];
                (st >= 0 && !as_image).then_some((xx, yy, st))
            })
        });
        if as_image {
            chart.draw_series(std::iter::once(marker((sxa, sya), (sxb, syb)))).map_err(err)?;
        }
        // Coarse grids show each element with a thin gap; fine ones edge to edge.
        let half = if x.len().max(y.len()) > 40 { 0.5 } else { 0.45 };
        chart
            .draw_series(cells.map(|(xx, yy, st)| {
                let c = if st == 1 { STICK } else { SLIP };
                Rectangle::new(
                    [
                        ((xx - half * hx) / d, (yy - half * hy) / d),
                        ((xx + half * hx) / d, (yy + half * hy) / d),
                    ],
                    c.filled(),
                )
            }))
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    if as_image {
        let png = raster(x, y, true, |i, j| match stick[i][j] {
            1 => Some(STICK),
            0 => Some(SLIP),
            _ => None,
        });
        png::embed(&mut s, &png)?;
    }
    Ok(s)
}

//! Iso-lines of a field sampled at the nodes of a rectilinear grid, by marching squares:
//! each square of four neighbouring samples is classified by which corners lie above the
//! level, the line crosses an edge where its two ends differ, at the linearly interpolated
//! point, and a saddle square (two opposite corners above) is resolved by the mean of its
//! corners. Segments are then joined into polylines through the edges they share, so a line
//! is closed exactly when it returns to the edge where it started.

use std::collections::HashMap;

/// An edge of the sample grid: between nodes (i, j) and (i + 1, j) when horizontal,
/// (i, j) and (i, j + 1) when vertical.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct Edge {
    horizontal: bool,
    i: usize,
    j: usize,
}

/// One iso-line: a polyline in the grid's coordinates, closed when it ends where it started
/// (its last point is then a copy of the first).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct IsoLine {
    pub points: Vec<(f64, f64)>,
    pub closed: bool,
}

/// The iso-lines at `level` of the samples `v[j][i]` at (x[i], y[j]). Squares with a
/// non-finite corner are left out; a sample equal to the level counts as below it.
pub(crate) fn iso_lines(x: &[f64], y: &[f64], v: &[Vec<f64>], level: f64) -> Vec<IsoLine> {
    let (nx, ny) = (x.len(), y.len());
    if nx < 2 || ny < 2 || v.len() < ny || v.iter().any(|r| r.len() < nx) {
        return Vec::new();
    }
    let above = |i: usize, j: usize| v[j][i] > level;
    // The crossing point of an edge, a function of the edge alone so that the two squares
    // sharing an edge produce the same floating-point point.
    let point = |e: Edge| -> (f64, f64) {
        let (i1, j1) = if e.horizontal { (e.i + 1, e.j) } else { (e.i, e.j + 1) };
        let (v0, v1) = (v[e.j][e.i], v[j1][i1]);
        let t = ((level - v0) / (v1 - v0)).clamp(0.0, 1.0);
        (x[e.i] + t * (x[i1] - x[e.i]), y[e.j] + t * (y[j1] - y[e.j]))
    };
    let mut segments: Vec<[Edge; 2]> = Vec::new();
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let c = [v[j][i], v[j][i + 1], v[j + 1][i + 1], v[j + 1][i]];
            if c.iter().any(|z| !z.is_finite()) {
                continue;
            }
            // corners c0 (i, j), c1 (i+1, j), c2 (i+1, j+1), c3 (i, j+1)
            let up = [above(i, j), above(i + 1, j), above(i + 1, j + 1), above(i, j + 1)];
            let bottom = Edge { horizontal: true, i, j };
            let right = Edge { horizontal: false, i: i + 1, j };
            let top = Edge { horizontal: true, i, j: j + 1 };
            let left = Edge { horizontal: false, i, j };
            // the edge between corners k and k+1 (mod 4)
            let sides = [bottom, right, top, left];
            let cut: Vec<Edge> =
                (0..4).filter(|&k| up[k] != up[(k + 1) % 4]).map(|k| sides[k]).collect();
            match cut.len() {
                2 => segments.push([cut[0], cut[1]]),
                4 => {
                    let centre_up = c.iter().sum::<f64>() / 4.0 > level;
                    // Cut off the two corners that the centre does not join: the corners
                    // whose state differs from the centre's.
                    if up[0] == centre_up {
                        // c1 and c3 are cut off
                        segments.push([bottom, right]);
                        segments.push([top, left]);
                    } else {
                        // c0 and c2 are cut off
                        segments.push([left, bottom]);
                        segments.push([right, top]);
                    }
                }
                _ => {}
            }
        }
    }
    join(&segments)
        .into_iter()
        .map(|(edges, closed)| IsoLine { points: edges.into_iter().map(point).collect(), closed })
        .collect()
}

/// Segments joined into chains of edges through the edges they share: open chains first
/// (from an edge used once, on the grid's border or beside a left-out square), then loops.
fn join(segments: &[[Edge; 2]]) -> Vec<(Vec<Edge>, bool)> {
    let mut at: HashMap<Edge, Vec<usize>> = HashMap::new();
    for (k, s) in segments.iter().enumerate() {
        for e in s {
            at.entry(*e).or_default().push(k);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut chains = Vec::new();
    let walk = |start: Edge, first: usize, used: &mut Vec<bool>| -> (Vec<Edge>, bool) {
        let mut chain = vec![start];
        let (mut edge, mut seg) = (start, first);
        loop {
            used[seg] = true;
            let s = segments[seg];
            edge = if s[0] == edge { s[1] } else { s[0] };
            chain.push(edge);
            match at[&edge].iter().find(|&&k| !used[k]) {
                Some(&k) => seg = k,
                None => break,
            }
        }
        let closed = chain.len() > 2 && chain[0] == chain[chain.len() - 1];
        (chain, closed)
    };
    let mut ends: Vec<Edge> = at.iter().filter(|(_, s)| s.len() == 1).map(|(e, _)| *e).collect();
    // A fixed order, so that the drawing does not depend on the hash.
    ends.sort_by_key(|e| (e.j, e.i, e.horizontal));
    for e in ends {
        let k = at[&e][0];
        if !used[k] {
            chains.push(walk(e, k, &mut used));
        }
    }
    for k in 0..segments.len() {
        if !used[k] {
            chains.push(walk(segments[k][0], k, &mut used));
        }
    }
    chains
}

/// Round contour levels strictly inside (lo, hi): the multiples of a step of 1, 2 or 5 times
/// a power of ten that gives between about 4 and 10 levels. Returns the step with them.
pub(crate) fn round_levels(lo: f64, hi: f64) -> (f64, Vec<f64>) {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return (0.0, Vec::new());
    }
    let raw = span / 8.0;
    let p = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * p).find(|s| *s >= raw).unwrap_or(10.0 * p);
    let first = (lo / step).floor() as i64 + 1;
    let levels = (first..)
        .map(|k| k as f64 * step)
        .take_while(|l| *l < hi - 1e-9 * step)
        .filter(|l| *l > lo + 1e-9 * step)
        .collect();
    (step, levels)
}

#[cfg(test)]
mod tests {
    use super::{iso_lines, round_levels};

    fn axis(n: usize, a: f64, b: f64) -> Vec<f64> {
        (0..n).map(|k| a + (b - a) * k as f64 / (n - 1) as f64).collect()
    }

    /// f = x² + y² on [-1.3, 1.3]²: the level-c line is the circle of radius r = sqrt(c).
    /// Along an edge of length h, f differs from its linear interpolant by t (1 - t) h² ≤ h²/4
    /// (f'' = 2), so a point of the line has f = c - e with 0 ≤ e ≤ h²/4 and lies off the
    /// circle by e / (r + r_p) ≤ (h²/4) / (r + sqrt(r² - h²/4)). Every line is one closed
    /// loop.
    #[test]
    fn circles_of_a_paraboloid() {
        for n in [11, 41, 161] {
            let x = axis(n, -1.3, 1.3);
            let h = x[1] - x[0];
            let v: Vec<Vec<f64>> =
                x.iter().map(|yy| x.iter().map(|xx| xx * xx + yy * yy).collect()).collect();
            for c in [0.09, 0.25, 0.5, 1.0, 1.44] {
                let r = f64::sqrt(c);
                let lines = iso_lines(&x, &x, &v, c);
                assert_eq!(lines.len(), 1, "n = {n}, c = {c}: {} lines", lines.len());
                let l = &lines[0];
                assert!(l.closed, "n = {n}, c = {c}: the circle is not closed");
                assert_eq!(l.points.first(), l.points.last());
                let bound = 0.25 * h * h / (r + (r * r - 0.25 * h * h).sqrt());
                let worst = l.points.iter().map(|p| (p.0.hypot(p.1) - r).abs()).fold(0.0, f64::max);
                assert!(
                    worst <= bound * (1.0 + 1e-9),
                    "n = {n}, c = {c}: {worst:.3e} > {bound:.3e}"
                );
                // it goes all the way round: the points span every quadrant
                for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
                    assert!(l.points.iter().any(|p| p.0 * sx > 0.0 && p.1 * sy > 0.0));
                }
            }
        }
    }

    /// A level cut by the grid's border gives an open line with both ends on the border.
    #[test]
    fn open_lines_end_on_the_border() {
        let x = axis(31, 0.0, 1.0);
        let v: Vec<Vec<f64>> =
            x.iter().map(|yy| x.iter().map(|xx| xx * xx + yy * yy).collect()).collect();
        let lines = iso_lines(&x, &x, &v, 0.5);
        assert_eq!(lines.len(), 1);
        let l = &lines[0];
        assert!(!l.closed);
        let on_border =
            |p: &(f64, f64)| [p.0, p.1].iter().any(|c| c.abs() < 1e-15 || (c - 1.0).abs() < 1e-15);
        assert!(on_border(&l.points[0]) && on_border(l.points.last().unwrap()));
        for p in &l.points {
            assert!((p.0.hypot(p.1) - 0.5f64.sqrt()).abs() < 1e-3);
        }
    }

    /// Two separate bumps give two loops; the saddle between them is split by its centre.
    #[test]
    fn two_bumps_two_loops() {
        let x = axis(81, -2.0, 2.0);
        let y = axis(41, -1.0, 1.0);
        let bump = |xx: f64, yy: f64, cx: f64| (-((xx - cx).powi(2) + yy * yy) * 8.0).exp();
        let v: Vec<Vec<f64>> = y
            .iter()
            .map(|yy| x.iter().map(|xx| bump(*xx, *yy, -1.0) + bump(*xx, *yy, 1.0)).collect())
            .collect();
        let lines = iso_lines(&x, &y, &v, 0.5);
        assert_eq!(lines.len(), 2);
        assert!(lines.iter().all(|l| l.closed));
    }

    #[test]
    fn round_levels_are_round() {
        let (step, l) = round_levels(0.0, 3.7);
        assert_eq!(step, 0.5);
        assert_eq!(l, vec![0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5]);
        let (step, l) = round_levels(-120.0, 120.0);
        assert_eq!(step, 50.0);
        assert_eq!(l, vec![-100.0, -50.0, 0.0, 50.0, 100.0]);
        assert!(round_levels(1.0, 1.0).1.is_empty());
    }
}

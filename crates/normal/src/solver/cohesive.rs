//! The share of each cell under the cohesive traction (module docs of [`crate::solver`],
//! "Adhesion: the zone inside a cell").

use super::passes::{in_order, BLOCK};
use rayon::prelude::*;
use stickslip_lattice::Boundary;

/// The share of the quarter cell at the centre value `gc` where the gap is below `h0`, the
/// gap over the quarter being the plane through `gc` at the cell centre and the averages
/// with the neighbours, `(gc + gx) / 2` and `(gc + gy) / 2`, at the middles of its two
/// outer sides.
///
/// With $\xi, \eta$ uniform on $[0, \tfrac12]$ (cell units from the centre), the gap is
/// $g_c + (g_x - g_c)\xi + (g_y - g_c)\eta$, the share the probability that it is below
/// $h_0$: the distribution function of a sum of two uniform variables, piecewise quadratic,
/// continuous in every argument, and non-increasing in each gap (the gap is a combination of
/// the three with non-negative weights $1 - \xi - \eta$, $\xi$, $\eta$).
#[must_use]
pub(super) fn quarter_share(gc: f64, gx: f64, gy: f64, h0: f64) -> f64 {
    let (a, b) = (0.5 * (gx - gc), 0.5 * (gy - gc));
    // S = a u + b v with u, v uniform on [0, 1]; P(S < h0 - gc) = P(A u' + B v' < s).
    let s = h0 - gc - a.min(0.0) - b.min(0.0);
    let (big, small) = if a.abs() >= b.abs() { (a.abs(), b.abs()) } else { (b.abs(), a.abs()) };
    if s <= 0.0 {
        0.0
    } else if s >= big + small {
        1.0
    } else if small == 0.0 {
        s / big
    } else if s <= small {
        s * s / (2.0 * big * small)
    } else if s <= big {
        (s - 0.5 * small) / big
    } else {
        let r = big + small - s;
        1.0 - r * r / (2.0 * big * small)
    }
}

/// The share of every cell of the `nx` × (`gap.len() / nx`) lattice where the gap `gap` is
/// below `h0`: the mean of the four [`quarter_share`]s, each from the cell's gap and its
/// neighbours' across the quarter's two outer sides (wrapped round on a periodic lattice;
/// the cell's own gap across the edge of a free one, a gap constant beyond it). Written
/// into `share`; returns the largest difference from `current`.
pub(super) fn shares(
    gap: &[f64],
    nx: usize,
    boundary: Boundary,
    h0: f64,
    current: &[f64],
    share: &mut [f64],
) -> f64 {
    let ny = gap.len() / nx;
    let periodic = boundary == Boundary::Periodic;
    let at = |i: isize, j: isize, own: f64| -> f64 {
        let (w, h) = (nx as isize, ny as isize);
        if periodic {
            gap[(j.rem_euclid(h) as usize) * nx + i.rem_euclid(w) as usize]
        } else if i < 0 || j < 0 || i >= w || j >= h {
            own
        } else {
            gap[j as usize * nx + i as usize]
        }
    };
    in_order(share.par_chunks_mut(BLOCK).zip(current.par_chunks(BLOCK)).enumerate().map(
        |(b, (out, cur))| {
            let mut change = 0.0f64;
            for (o, (f, c)) in out.iter_mut().zip(cur).enumerate() {
                let k = b * BLOCK + o;
                let (i, j) = ((k % nx) as isize, (k / nx) as isize);
                let g = gap[k];
                let (w, e, s, n) =
                    (at(i - 1, j, g), at(i + 1, j, g), at(i, j - 1, g), at(i, j + 1, g));
                let v = if g >= h0 && w >= h0 && e >= h0 && s >= h0 && n >= h0 {
                    // Nowhere below the range (the quick exit for the cells far from contact).
                    0.0
                } else {
                    0.25 * (quarter_share(g, e, n, h0)
                        + quarter_share(g, w, n, h0)
                        + quarter_share(g, e, s, h0)
                        + quarter_share(g, w, s, h0))
                };
                change = change.max((v - c).abs());
                *f = v;
            }
            change
        },
    ))
    .into_iter()
    .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::quarter_share;

    /// The share against a midpoint count on a fine grid of the quarter.
    #[test]
    fn quarter_share_against_a_count() {
        let cases = [
            (0.0, 0.0, 0.0),
            (0.5, 2.0, 0.7),
            (1.2, 0.1, 0.9),
            (0.9, 1.1, 1.05),
            (0.3, 3.0, 0.3),
            (2.0, -1.0, 0.5),
            (1.0, 1.0, 1.0),
            (0.0, 4.0, 4.0),
        ];
        let m = 2000;
        for (gc, gx, gy) in cases {
            let mut below = 0usize;
            for a in 0..m {
                for b in 0..m {
                    let (xi, eta) =
                        ((a as f64 + 0.5) / m as f64 * 0.5, (b as f64 + 0.5) / m as f64 * 0.5);
                    if gc + (gx - gc) * xi + (gy - gc) * eta < 1.0 {
                        below += 1;
                    }
                }
            }
            let count = below as f64 / (m * m) as f64;
            let share = quarter_share(gc, gx, gy, 1.0);
            assert!((share - count).abs() < 2e-3, "{gc} {gx} {gy}: {share} against {count}");
        }
    }
}

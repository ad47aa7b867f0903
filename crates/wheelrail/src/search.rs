//! The contact search: where the undeformed wheel and rail interpenetrate, across the
//! profiles.
//!
//! On vertical lines $y = y_k$ (spacing [`SEARCH_STEP`]) over the lateral range both
//! profiles cover, the rail's top is the smallest $z$ of the placed rail curve at $y_k$ and
//! the wheel's bottom the largest $z$ of the wheel surface on the line. The rail is straight
//! along $x$, so the smallest gap on a line lies where the wheel surface is level along $x$:
//! on the wheel's *contact locus*, the points where its normal is perpendicular to $x$,
//! $(\mathbf w_t\times\mathbf w_\theta)\cdot\mathbf e_x = 0$ ([`crate::placement`] for
//! $\mathbf w(t, \theta)$), solved for $\theta$ at every profile sample $t$ (secant method,
//! from the circle's lowest point $\theta^* = \operatorname{atan2}(R_{zx}, R_{zz})$). For a
//! yawed wheelset the locus leaves $x = 0$, far ahead of the axle on a steep flange (the
//! flange contact's lead), so the search follows the contact along $x$. The vertical gap is
//! $g_k = z_{rail}(y_k) - z_{wheel}(y_k)$ (negative: interpenetration); its smallest value is
//! refined on the exact surfaces (golden section along the locus). Each run of
//! consecutive lines with $g_k < 0$ is one interpenetration region; runs separated by at most
//! [`MERGE_LINES`] lines are one region (a sliver of positive gap inside a contact is not a
//! second patch).
//!
//! Each region becomes a patch with its own tangent plane (CONTACT's planar contact
//! approach): its reference point is the penetration-weighted centre
//! $\bar y = \sum_k (-g_k)\,y_k / \sum_k (-g_k)$ on the rail surface, at the $x$ of the
//! wheel's lowest point there, and its contact angle $\delta$ the mean of the rail's and the
//! wheel's surface angles at $\bar y$, $\tan\delta_r = dz_{rail}/dy$ (rotation from the track
//! $z$ axis to the patch normal about $x$; negative on the gauge side of a right rail,
//! CONTACT's `DELTCP`).

use crate::error::{Error, Result};
use crate::placement::{PlacedRail, PlacedWheel};

/// Spacing of the search lines (m).
pub const SEARCH_STEP: f64 = 2e-5;
/// Interpenetration runs separated by at most this many search lines are one region.
pub const MERGE_LINES: usize = 5;

/// The vertical gap on the search lines.
#[derive(Debug, Clone)]
pub(crate) struct Search {
    pub y: Vec<f64>,
    pub gap: Vec<f64>,
    /// Rail parameter of the rail's top at each line.
    pub rail_t: Vec<f64>,
    /// Wheel parameter and $x$ of the wheel's lowest point at each line.
    pub wheel_t: Vec<f64>,
    pub wheel_x: Vec<f64>,
    /// Smallest gap and its line.
    pub min_gap: f64,
    pub k_min: usize,
}

/// One interpenetration region: lines `k0..=k1`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Region {
    pub k0: usize,
    pub k1: usize,
}

/// Search lines, vertical gap and the profiles' parameters there.
pub(crate) fn search(rail: &PlacedRail<'_>, wheel: &PlacedWheel<'_>) -> Result<Search> {
    let rs = rail.samples();
    let (r_lo, r_hi) =
        rs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, s| (a.0.min(s[1]), a.1.max(s[1])));
    // The wheel's contact locus: (t, x, y, z), over the samples whose circles pass above the
    // rail's lateral range (with 5 mm to spare for the yaw and roll).
    let (theta0, _) = wheel.lowest(0.0);
    let (mut prev, mut theta) = (theta0, theta0);
    let ws: Vec<[f64; 4]> = wheel
        .profile
        .samples()
        .iter()
        .filter(|s| {
            let y = wheel.point(s[0], theta0).w.y;
            y > r_lo - 5e-3 && y < r_hi + 5e-3
        })
        .map(|s| {
            // Start from the straight continuation of the last two.
            let start = 2.0 * theta - prev;
            let th = locus_theta(wheel, s[0], start).unwrap_or(theta0);
            (prev, theta) = (theta, th);
            let w = wheel.point(s[0], th).w;
            [s[0], w.x, w.y, w.z]
        })
        .collect();
    if ws.len() < 2 {
        return Err(Error::NoContact {
            min_gap: f64::INFINITY,
            y: 0.5 * (r_lo + r_hi),
            overlap: false,
        });
    }
    let range = |ys: &mut dyn Iterator<Item = f64>| {
        ys.fold((f64::INFINITY, f64::NEG_INFINITY), |a, y| (a.0.min(y), a.1.max(y)))
    };
    let (r0, r1) = range(&mut rs.iter().map(|s| s[1]));
    let (w0, w1) = range(&mut ws.iter().map(|s| s[2]));
    let (lo, hi) = (r0.max(w0), r1.min(w1));
    if hi <= lo {
        return Err(Error::NoContact {
            min_gap: f64::INFINITY,
            y: 0.5 * (r0 + r1),
            overlap: false,
        });
    }
    let n = ((hi - lo) / SEARCH_STEP).floor() as usize + 1;
    let y: Vec<f64> = (0..n).map(|k| lo + k as f64 * SEARCH_STEP).collect();
    let mut zr = vec![f64::INFINITY; n];
    let mut rail_t = vec![f64::NAN; n];
    let mut zw = vec![f64::NEG_INFINITY; n];
    let mut wheel_t = vec![f64::NAN; n];
    let mut wheel_x = vec![f64::NAN; n];
    // The search lines a segment from y = a to y = b spans.
    let bins = |a: f64, b: f64| {
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        let k0 = ((a - lo) / SEARCH_STEP).ceil().max(0.0);
        let k1 = ((b - lo) / SEARCH_STEP).floor().min((n - 1) as f64);
        (k0 as usize)..(if k1 >= k0 { k1 as usize + 1 } else { k0 as usize })
    };
    for s in rs.windows(2) {
        let (a, b) = (s[0], s[1]);
        for k in bins(a[1], b[1]) {
            let f = if b[1] != a[1] { (y[k] - a[1]) / (b[1] - a[1]) } else { 0.0 };
            let z = a[2] + f * (b[2] - a[2]);
            if z < zr[k] {
                zr[k] = z;
                rail_t[k] = a[0] + f * (b[0] - a[0]);
            }
        }
    }
    for s in ws.windows(2) {
        let (a, b) = (s[0], s[1]);
        for k in bins(a[2], b[2]) {
            let f = if b[2] != a[2] { (y[k] - a[2]) / (b[2] - a[2]) } else { 0.0 };
            let z = a[3] + f * (b[3] - a[3]);
            if z > zw[k] {
                zw[k] = z;
                wheel_t[k] = a[0] + f * (b[0] - a[0]);
                wheel_x[k] = a[1] + f * (b[1] - a[1]);
            }
        }
    }
    let gap: Vec<f64> = zr.iter().zip(&zw).map(|(r, w)| r - w).collect();
    let (k_min, coarse) = gap
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, g)| g.is_finite())
        .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    let min_gap = if coarse.is_finite() {
        refine_min(rail, wheel, wheel_t[k_min], rail_t[k_min]).min(coarse)
    } else {
        coarse
    };
    Ok(Search { y, gap, rail_t, wheel_t, wheel_x, min_gap, k_min })
}

/// $\theta$ on the contact locus at profile parameter $t$ (module docs), from `start`.
pub(crate) fn locus_theta(wheel: &PlacedWheel<'_>, t: f64, start: f64) -> Option<f64> {
    let g = |th: f64| {
        let p = wheel.point(t, th);
        p.dt.y * p.dtheta.z - p.dt.z * p.dtheta.y
    };
    let (mut a, mut b) = (start, start + 1e-4);
    let (mut ga, mut gb) = (g(a), g(b));
    for _ in 0..30 {
        if gb == ga {
            break;
        }
        let c = b - gb * (b - a) / (gb - ga);
        if !c.is_finite() {
            return None;
        }
        (a, ga) = (b, gb);
        b = c;
        gb = g(b);
        if (b - a).abs() < 1e-13 {
            return Some(b);
        }
    }
    (gb.abs() < 1e-9).then_some(b)
}

/// The smallest vertical gap near the locus parameter `tw` (rail parameter `tr` nearby), on
/// the exact surfaces: golden section on $t$ along the locus, the rail's $z$ at the locus
/// point's $y$ by Newton on its parameter.
fn refine_min(rail: &PlacedRail<'_>, wheel: &PlacedWheel<'_>, tw: f64, tr: f64) -> f64 {
    let (theta0, _) = wheel.lowest(0.0);
    let gap = |t: f64| -> f64 {
        let Some(th) = locus_theta(wheel, t, theta0) else { return f64::INFINITY };
        let w = wheel.point(t, th).w;
        let mut u = tr;
        for _ in 0..30 {
            let (p, d1, _) = rail.at(u);
            let step = (p[0] - w.y) / d1[0];
            u -= step;
            if step.abs() < 1e-15 {
                break;
            }
        }
        rail.at(u).0[1] - w.z
    };
    let h = 4.0 * crate::profile::SAMPLE_STEP;
    let (mut a, mut b) = (tw - h, tw + h);
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut c, mut d) = (b - r * (b - a), a + r * (b - a));
    let (mut gc, mut gd) = (gap(c), gap(d));
    for _ in 0..60 {
        if gc < gd {
            b = d;
            (d, gd) = (c, gc);
            c = b - r * (b - a);
            gc = gap(c);
        } else {
            a = c;
            (c, gc) = (d, gd);
            d = a + r * (b - a);
            gd = gap(d);
        }
        if b - a < 1e-12 {
            break;
        }
    }
    gc.min(gd)
}

impl Search {
    /// The interpenetration regions (module docs).
    pub fn regions(&self) -> Vec<Region> {
        let mut out: Vec<Region> = Vec::new();
        let mut k = 0;
        let n = self.gap.len();
        while k < n {
            if self.gap[k] < 0.0 {
                let k0 = k;
                while k + 1 < n && self.gap[k + 1] < 0.0 {
                    k += 1;
                }
                match out.last_mut() {
                    Some(r) if k0 - r.k1 <= MERGE_LINES + 1 => r.k1 = k,
                    _ => out.push(Region { k0, k1: k }),
                }
            }
            k += 1;
        }
        out
    }

    /// The penetration-weighted centre of a region (track $y$) and the interpolated rail
    /// and wheel parameters and wheel $x$ there.
    pub fn centre(&self, r: Region) -> (f64, f64, f64, f64) {
        let (mut sw, mut sy) = (0.0, 0.0);
        for k in r.k0..=r.k1 {
            let w = (-self.gap[k]).max(0.0);
            sw += w;
            sy += w * self.y[k];
        }
        let yc = if sw > 0.0 { sy / sw } else { self.y[(r.k0 + r.k1) / 2] };
        let f = (yc - self.y[0]) / SEARCH_STEP;
        let k = (f.floor() as usize).min(self.y.len() - 2);
        let a = f - k as f64;
        let lerp = |v: &[f64]| v[k] + a * (v[k + 1] - v[k]);
        (yc, lerp(&self.rail_t), lerp(&self.wheel_t), lerp(&self.wheel_x))
    }
}

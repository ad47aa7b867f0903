//! Brent's bracketing root finder (Brent 1973, ch. 4, `zero`), used for eqs 19 and 24.
//!
//! This is the small, problem-specific piece of root finding the solvers need: the brackets
//! are derived analytically (see [`crate::goryacheva`]), so only a safeguarded
//! secant/inverse-quadratic/bisection iteration is required.

/// A converged root.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Root {
    /// The abscissa.
    pub x: f64,
    /// The function value there.
    pub fx: f64,
    /// Number of function evaluations after the two bracket ends.
    pub iterations: usize,
}

/// Find a zero of `f` in `[a, b]` given `fa = f(a)` and `fb = f(b)` of opposite signs (or one
/// of them zero). Stops when the bracket is narrower than $4\varepsilon|x| + $ `xtol_abs`, or
/// after `max_iter` evaluations (the best point is returned either way).
pub(crate) fn brent<F: FnMut(f64) -> f64>(
    mut f: F,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    xtol_abs: f64,
    max_iter: usize,
) -> Root {
    if fa == 0.0 {
        return Root { x: a, fx: fa, iterations: 0 };
    }
    if fb == 0.0 {
        return Root { x: b, fx: fb, iterations: 0 };
    }
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for iter in 0..max_iter {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol_abs;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return Root { x: b, fx: fb, iterations: iter };
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * xm * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b);
    }
    Root { x: b, fx: fb, iterations: max_iter }
}

#[cfg(test)]
mod tests {
    use super::brent;

    #[test]
    fn cubic_root_to_rounding() {
        // x^3 - 2 = 0 on [1, 2]: root 2^(1/3).
        let f = |x: f64| x * x * x - 2.0;
        let r = brent(f, 1.0, 2.0, f(1.0), f(2.0), 0.0, 100);
        let exact = 2f64.cbrt();
        println!("brent cbrt(2): err = {:e}, iterations = {}", r.x - exact, r.iterations);
        assert!((r.x - exact).abs() <= 4.0 * f64::EPSILON * exact);
        assert!(r.iterations < 20);
    }
}

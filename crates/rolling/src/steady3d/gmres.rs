//! Restarted GMRES with right preconditioning, for the non-symmetric steady-rolling system.
//!
//! Solves $A x = b$ through $A M^{-1} y = b$, $x = M^{-1} y$ (Saad & Schultz 1986; Saad,
//! *Iterative Methods for Sparse Linear Systems*, 2nd ed., Alg. 9.5), with modified
//! Gram–Schmidt and Givens rotations. The residual it reports is the true relative residual
//! $\lVert b - Ax\rVert/\lVert b\rVert$, recomputed at each restart and at the end.

/// What one GMRES solve reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct GmresInfo {
    /// Matrix–vector products used.
    pub products: usize,
    /// Final true relative residual.
    pub residual: f64,
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// GMRES(`restart`) from the initial guess in `x`, until the relative residual is below
/// `tol` or `max_products` products are used.
pub(crate) fn gmres(
    mut apply: impl FnMut(&[f64], &mut [f64]),
    precondition: impl Fn(&[f64], &mut [f64]),
    b: &[f64],
    x: &mut [f64],
    tol: f64,
    restart: usize,
    max_products: usize,
) -> GmresInfo {
    let n = b.len();
    let bnorm = norm(b);
    if bnorm == 0.0 {
        x.fill(0.0);
        return GmresInfo { products: 0, residual: 0.0 };
    }
    let m = restart.max(1);
    let mut products = 0;
    let mut r = vec![0.0; n];
    let mut w = vec![0.0; n];
    let mut z = vec![0.0; n];
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(m + 1);
    let mut h = vec![0.0; (m + 1) * m];
    let (mut cs, mut sn, mut g) = (vec![0.0; m], vec![0.0; m], vec![0.0; m + 1]);
    loop {
        apply(x, &mut w);
        products += 1;
        for i in 0..n {
            r[i] = b[i] - w[i];
        }
        let beta = norm(&r);
        let residual = beta / bnorm;
        if residual <= tol || products >= max_products {
            return GmresInfo { products, residual };
        }
        basis.clear();
        basis.push(r.iter().map(|v| v / beta).collect());
        g.fill(0.0);
        g[0] = beta;
        h.fill(0.0);
        let mut k = 0;
        while k < m && products < max_products {
            precondition(&basis[k], &mut z);
            apply(&z, &mut w);
            products += 1;
            for (i, v) in basis.iter().enumerate() {
                let hik = dot(&w, v);
                h[i * m + k] = hik;
                for (wj, vj) in w.iter_mut().zip(v) {
                    *wj -= hik * vj;
                }
            }
            let hnext = norm(&w);
            h[(k + 1) * m + k] = hnext;
            for i in 0..k {
                let (a, c) = (h[i * m + k], h[(i + 1) * m + k]);
                h[i * m + k] = cs[i] * a + sn[i] * c;
                h[(i + 1) * m + k] = -sn[i] * a + cs[i] * c;
            }
            let (a, c) = (h[k * m + k], h[(k + 1) * m + k]);
            let d = a.hypot(c);
            (cs[k], sn[k]) = if d == 0.0 { (1.0, 0.0) } else { (a / d, c / d) };
            h[k * m + k] = d;
            h[(k + 1) * m + k] = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] *= cs[k];
            k += 1;
            if g[k].abs() / bnorm <= tol || hnext == 0.0 {
                break;
            }
            basis.push(w.iter().map(|v| v / hnext).collect());
        }
        // Back substitution for the k coefficients, then x += M^{-1} V y.
        let mut yv = vec![0.0; k];
        for i in (0..k).rev() {
            let mut s = g[i];
            for j in i + 1..k {
                s -= h[i * m + j] * yv[j];
            }
            yv[i] = if h[i * m + i] == 0.0 { 0.0 } else { s / h[i * m + i] };
        }
        w.fill(0.0);
        for (v, c) in basis.iter().zip(&yv) {
            for (wi, vi) in w.iter_mut().zip(v) {
                *wi += c * vi;
            }
        }
        precondition(&w, &mut z);
        for (xi, zi) in x.iter_mut().zip(&z) {
            *xi += zi;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-symmetric, diagonally dominant tridiagonal system with a known solution.
    #[test]
    fn solves_a_nonsymmetric_system_to_its_tolerance() {
        let n = 200;
        let exact: Vec<f64> = (0..n).map(|i| ((i as f64) * 0.37).sin() + 0.1).collect();
        let apply = |v: &[f64], out: &mut [f64]| {
            for i in 0..n {
                let left = if i > 0 { v[i - 1] } else { 0.0 };
                let right = if i + 1 < n { v[i + 1] } else { 0.0 };
                out[i] = 3.0 * v[i] - 1.5 * left + 0.4 * right;
            }
        };
        let mut b = vec![0.0; n];
        apply(&exact, &mut b);
        let mut x = vec![0.0; n];
        let info = gmres(apply, |r, z| z.copy_from_slice(r), &b, &mut x, 1e-12, 20, 2000);
        assert!(info.residual <= 1e-12, "{info:?}");
        let err = x.iter().zip(&exact).map(|(a, e)| (a - e).abs()).fold(0.0, f64::max);
        assert!(err < 1e-10, "max error {err:e}");
    }
}

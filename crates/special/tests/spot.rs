//! First layer: published spot values and exact special cases.
//!
//! - $\Gamma(1/2)=\sqrt\pi$, $\Gamma(-1/2)=-2\sqrt\pi$, $\Gamma(3/2)=\sqrt\pi/2$ (DLMF 5.4.6
//!   with the recurrence), $\Gamma(n)=(n-1)!$ exactly, $170!$ as an integer; $\Gamma(1/3)$ is
//!   the classical constant (A&S Table 6.1 region; the 17 digits used were confirmed with mpmath).
//! - $I_0, I_1, K_0, K_1$ at 1 and 5: A&S Table 9.8 prints them to 10 digits; the 17-digit
//!   literals agree with the table and were confirmed with mpmath.
//! - $K(1/2)=\Gamma(1/4)^2/(4\sqrt\pi)$ (the lemniscatic case), and $E(1/2)$ from Legendre's
//!   relation (DLMF 19.7.1) at $m=1/2$: $2EK-K^2=\pi/2$, i.e. $E = K/2+\pi/(4K)$.

mod common;
use common::{rel_err, tol};
use std::f64::consts::{FRAC_PI_2, PI};
use stickslip_special as sp;

fn check(label: &str, got: f64, want: f64) {
    let e = rel_err(got, want);
    println!("{label:>14}: got {got:e}, want {want:e}, rel err {e:.2e}");
    assert!(e <= tol::REL, "{label}: rel err {e:e}");
}

#[test]
fn gamma_spot_values() {
    let sqrt_pi = PI.sqrt();
    check("G(1/2)", sp::gamma(0.5), sqrt_pi);
    check("G(-1/2)", sp::gamma(-0.5), -2.0 * sqrt_pi);
    check("G(3/2)", sp::gamma(1.5), 0.5 * sqrt_pi);
    check("G(1/3)", sp::gamma(1.0 / 3.0), 2.678_938_534_707_747_6);
    check("G(171)=170!", sp::gamma(171.0), 7.257_415_615_307_999e306);
    // Integers are exact: Gamma(n) = (n-1)!
    let mut fact = 1.0_f64;
    for n in 1..=23 {
        // (n-1)! is exactly representable for n <= 23
        let e = rel_err(sp::gamma(f64::from(n)), fact);
        assert!(e <= tol::FACTORIAL, "Gamma({n}): rel err {e:e}");
        fact *= f64::from(n);
    }
    assert_eq!(sp::gamma(1.0), 1.0);
    assert_eq!(sp::gamma(2.0), 1.0);
    assert_eq!(sp::ln_gamma(1.0), 0.0);
    assert_eq!(sp::ln_gamma(2.0), 0.0);
    check("lnG(1/2)", sp::ln_gamma(0.5), 0.5 * PI.ln());
}

#[test]
fn bessel_spot_values() {
    check("I0(1)", sp::bessel_i0(1.0), 1.266_065_877_752_008_3);
    check("I1(1)", sp::bessel_i1(1.0), 0.565_159_103_992_485_03);
    check("K0(1)", sp::bessel_k0(1.0), 0.421_024_438_240_708_33);
    check("K1(1)", sp::bessel_k1(1.0), 0.601_907_230_197_234_57);
    check("I0(5)", sp::bessel_i0(5.0), 27.239_871_823_604_447);
    check("I1(5)", sp::bessel_i1(5.0), 24.335_642_142_450_527);
    check("K0(5)", sp::bessel_k0(5.0), 0.003_691_098_334_042_594_3);
    check("K1(5)", sp::bessel_k1(5.0), 0.004_044_613_445_452_164_2);
    assert_eq!(sp::bessel_i0(0.0), 1.0);
    assert_eq!(sp::bessel_i1(0.0), 0.0);
    assert_eq!(sp::bessel_i0e(0.0), 1.0);
    assert_eq!(sp::bessel_i1_over_i0(0.0), 0.0);
}

#[test]
fn elliptic_spot_values() {
    assert_eq!(sp::ellipk(0.0), FRAC_PI_2);
    assert_eq!(sp::ellipe(0.0), FRAC_PI_2);
    assert_eq!(sp::ellipe(1.0), 1.0);
    let k_half = 1.854_074_677_301_371_9; // Gamma(1/4)^2 / (4 sqrt(pi))
    check("K(1/2)", sp::ellipk(0.5), k_half);
    check("E(1/2)", sp::ellipe(0.5), 1.350_643_881_047_675_5);
    check("E(1/2) Leg.", sp::ellipe(0.5), 0.5 * k_half + PI / (4.0 * k_half));
    check("K(-1)", sp::ellipk(-1.0), 1.311_028_777_146_059_9);
    check("E(-1)", sp::ellipe(-1.0), 1.910_098_894_513_856);
}

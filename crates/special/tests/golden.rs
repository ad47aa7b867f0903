//! Third layer: the big mpmath tables (scripts/special_golden.py, mp.dps = 60), one per
//! function, covering each documented domain. Run with `--nocapture` to see max/RMS errors.

mod common;
use common::check_table;
use stickslip_special as sp;

#[test]
fn gamma_table() {
    check_table("gamma", sp::gamma);
}
#[test]
fn ln_gamma_table() {
    check_table("ln_gamma", sp::ln_gamma);
}
#[test]
fn bessel_i0_table() {
    check_table("bessel_i0", sp::bessel_i0);
}
#[test]
fn bessel_i1_table() {
    check_table("bessel_i1", sp::bessel_i1);
}
#[test]
fn bessel_k0_table() {
    check_table("bessel_k0", sp::bessel_k0);
}
#[test]
fn bessel_k1_table() {
    check_table("bessel_k1", sp::bessel_k1);
}
#[test]
fn bessel_i0e_table() {
    check_table("bessel_i0e", sp::bessel_i0e);
}
#[test]
fn bessel_i1e_table() {
    check_table("bessel_i1e", sp::bessel_i1e);
}
#[test]
fn bessel_k0e_table() {
    check_table("bessel_k0e", sp::bessel_k0e);
}
#[test]
fn bessel_k1e_table() {
    check_table("bessel_k1e", sp::bessel_k1e);
}
#[test]
fn bessel_i1_over_i0_table() {
    check_table("bessel_i1_over_i0", sp::bessel_i1_over_i0);
}
#[test]
fn bessel_k0_over_k1_table() {
    check_table("bessel_k0_over_k1", sp::bessel_k0_over_k1);
}
#[test]
fn ellipk_table() {
    check_table("ellipk", sp::ellipk);
}
#[test]
fn ellipe_table() {
    check_table("ellipe", sp::ellipe);
}
#[test]
fn ellipd_table() {
    check_table("ellipd", sp::ellipd);
}

//! Limits of the checks printed in the book, each with its reason. A page whose check
//! exceeds its limit is not generated (see [`crate::Error::CheckFailed`]).

/// Closed form against adaptive quadrature requested at $10^{-13}$ relative: the quadrature
/// error bound plus a few ulps of the closed form.
pub const CLOSED_VS_QUAD: f64 = 1e-12;

/// Identities evaluated in `f64` with the crate's special functions (4 ulp each): a few
/// tens of ulps.
pub const IDENTITY: f64 = 1e-14;

/// Full integration of the graded kernels (default accuracy, about $10^{-13}$ relative)
/// against a closed form, and the equilibrium integrals at $10^{-10}$: loose enough for the
/// infinite-range quadrature of a quadrature.
pub const FULL_INTEGRATION: f64 = 1e-9;

/// $k \to 0$ limits: the graded results at $k = 10^{-6}$ differ from the homogeneous ones by
/// $O(k)$.
pub const SMALL_K: f64 = 1e-5;

/// Two-dimensional Cerruti quadrature of a traction against a compliance formula (nested
/// adaptive quadrature at $10^{-11}$).
pub const CERRUTI_2D: f64 = 1e-9;

/// Goryacheva with $\alpha = \beta(1+\varepsilon)$ against Carter: the viscoelastic
/// corrections are $O(\varepsilon)$; the check uses $\varepsilon = 10^{-6}$.
pub const ELASTIC_LIMIT: f64 = 1e-5;

/// Integrals of the viscoelastic stresses (quadrature of quadratures at $10^{-10}$) against
/// the resultants $P$, $Q$, $M_1$ of eqs 27–28.
pub const ROLLING_RESULTANTS: f64 = 1e-7;

/// The modified LP on seed 002's 80-element Example 1 against Mindlin: issue 5's target
/// for the exact influence coefficients is 1.5 %.
pub const LP_EXAMPLE1: f64 = 0.015;

/// Equilibrium and complementarity of an LP solution, relative to the load: the LP's
/// feasibility tolerance is $10^{-11}$ on the scaled tableau.
pub const LP_OPTIMALITY: f64 = 1e-9;

/// Loop area of Mindlin–Deresiewicz against eq 3.5: the direct form of $W$ sums $O(1)$ terms
/// to a bracket of size $5t^3/162$ and so loses about $\epsilon/(5t^3/162)$ relative (measured
/// 2.4e-12 at $t = 0.1$; the crate switches to its series only below $t = 0.05$).
pub const DERESIEWICZ_W: f64 = 1e-10;

/// FFT convolution against the dense influence matrix (same kernel entries): the FFT adds
/// about $\epsilon\log_2 M$ times $\sum|K|$ relative to the largest displacement, a few
/// $10^{-15}$ on these grids; the limit leaves room for larger lattices.
pub const FFT_VS_DENSE: f64 = 1e-12;

/// The fast solver's relative complementarity residual: it stops at its default tolerance
/// $10^{-10}$ (`FastConfig::default`), so a converged solve cannot exceed it.
pub const FAST_RESIDUAL: f64 = 1e-10;

/// Optimality conditions recomputed from a fast solution converged to $10^{-10}$ in the
/// 2-norm over $N$ elements: each element's violation relative to its scale, with room for
/// the $\sqrt N$ between the 2-norm and the worst element (as in the traction crate's tests).
pub const FAST_OPTIMALITY: f64 = 1e-7;

/// Area-equivalent stick radius of a lattice solution against Mindlin's $a^*$: one cell,
/// the resolution of the stick/slip boundary on the lattice (issue 6).
pub const STICK_CELLS: f64 = 1.0;

/// Rigid shift against Mindlin on the $64^2$ (25 cells per radius) and $128^2$ (50 cells)
/// lattices: the discretisation error of uniform-traction cells, $O(h/a)$ at the contact
/// edge; issue 6's 0.5 % is for $256^2$ (100 cells), so twice that here.
pub const FAST_SHIFT_MINDLIN: f64 = 0.01;

/// The fast solver with the LP's one-direction assumption against the LP on the same grid,
/// relative to the largest element force (issue 6): both solve the same discrete equations,
/// the LP to about $10^{-11}$ of its scaled tableau and the fast solver to its residual.
pub const FAST_VS_LP: f64 = 1e-6;

/// Complementary energy of the free-direction solution over that of the parallel one,
/// minus 1: must be $\le 0$ (a less constrained minimum of the same energy), up to the
/// solver residual $10^{-10}$ acting on an energy that is quadratic in the traction.
pub const ENERGY_ORDER: f64 = 1e-9;

//! A fast partial-slip solver for large grids: both traction components free on the Coulomb
//! disc $|\mathbf q_k| \le f p_k$, a tangential force in any direction and optionally a
//! twisting moment, the influence operator applied by zero-padded FFT convolution
//! ([`stickslip_lattice::TensorConvolution`]).
//!
//! # The discrete problem
//!
//! Unknowns: the traction $\mathbf q_k$ of every element (uniform over the element), the rigid
//! shift $\boldsymbol\delta$ of the two bodies and, when a moment is prescribed, their rigid
//! rotation $\omega$ about a centre $\mathbf c$. With $\mathbf u = K * \mathbf q$ the relative
//! elastic displacement (FORMULAS.md F) and
//! $\mathbf w_k = \boldsymbol\delta + \omega\,\hat z\times(\mathbf x_k - \mathbf c)$ the rigid
//! motion, the slip is $\mathbf s_k = \mathbf w_k - \mathbf u_k$ (the sign convention of the
//! LP, seed 002 eq. 3.13: $Y_1 = \beta g - AF$) and
//! $$|\mathbf q_k| \le c_k = f p_k,\quad \mathbf s_k = \lambda_k\mathbf q_k,\ \lambda_k\ge 0,
//!   \quad \lambda_k\,(c_k - |\mathbf q_k|) = 0,$$
//! $$h_xh_y\sum_k \mathbf q_k = \mathbf T,\qquad
//!   h_xh_y\sum_k (\mathbf x_k - \mathbf c)\times\mathbf q_k = M .$$
//! These are the optimality conditions of the convex program
//! $\min \tfrac12\mathbf q^{\mathsf T}K\mathbf q$ over the product of discs with the load
//! constraints, whose multipliers are $\boldsymbol\delta$ and $\omega$ (the discrete form of
//! Kalker's complementary-energy principle). Without a prescribed moment the rotation is held
//! at zero (pure translation, as in Mindlin and in the LP).
//!
//! # The method
//!
//! A semismooth Newton (primal–dual active set) iteration on the natural residual
//! $$\mathbf r_k = \mathbf q_k - \Pi_{D_k}\!\big(\mathbf q_k + \rho\,\mathbf s_k\big),\qquad
//!   \rho = \frac{2}{K_{xx}(0) + K_{yy}(0)},$$
//! the inverse of the mean self-influence (equal to $1/K_{xx}(0)$ on square cells),
//! (Hüeber, Stadler & Wohlmuth 2008, *SIAM J. Sci. Comput.* 30, for 3D Coulomb contact;
//! Vollebregt's TangCG in CONTACT uses the same stick/slip split with conjugate gradients):
//! elements with $|\mathbf q_k + \rho\mathbf s_k| \le c_k$ stick (two free components, slip
//! zero), the others slip with $|\mathbf q_k| = c_k$ and a free direction. Linearising
//! $\mathbf t_k\cdot\mathbf s_k = 0$ (slip parallel to traction) with respect to the direction
//! gives the symmetric positive definite system
//! $$\big(P^{\mathsf T}KP + D\big)\,x - B^{\mathsf T}\Delta m = P^{\mathsf T}\mathbf s,\qquad
//!   Bx = b,\qquad D_k = \frac{\mathbf n_k\cdot\mathbf s_k}{c_k}\ \text{(slip elements)},$$
//! with $P$ the stick components and slip tangents, $B$ the load constraints, solved by
//! projected conjugate gradients (Gould, Hribar & Nocedal 2001, *SIAM J. Sci. Comput.* 23)
//! in which every product with $K$ is one FFT convolution: $O(N\log N)$ per iteration.
//!
//! **Preconditioner.** On the stick components, the inverse of the continuous half-space's
//! tangential transfer function: Cerruti's solution in Fourier space is
//! $\hat{\mathbf u} = |\mathbf k|^{-1}(aI - b\,\hat{\mathbf k}\hat{\mathbf k}^{\mathsf T})
//! \hat{\mathbf q}$ with $a = \sum_i 1/G_i$ and $b = \sum_i \nu_i/G_i$, so its inverse,
//! $|\mathbf k|\,(I/a + (1/(a-b) - 1/a)\,\hat{\mathbf k}\hat{\mathbf k}^{\mathsf T})$, grows
//! like $|\mathbf k|$ where $K$ decays like $1/|\mathbf k|$. It is applied by one unpadded
//! periodic FFT on the lattice's bounding box (a quarter of a padded product) with the
//! discrete wave number $2\sin(kh/2)/h$, scaled to the Jacobi diagonal. Slip tangents take
//! part in the same transform, each weighted by $w_d = (1 + (D_d/K_{tt}(0))^2)^{-1/2}$, plus
//! a quarter of the weighted Jacobi value, $\tfrac14(1 - w_d^2)/(K_{tt}(0) + D_d)$: a slip cell
//! next to the stick zone (slip still small, $D_d \ll K_{tt}(0)$) is coupled to its neighbours
//! as a stick component is, a cell far out in the slip zone ($D_d \gg K_{tt}(0)$) falls back
//! to its diagonal (the form and the quarter were measured best, see `SLIP_JACOBI` in
//! `newton/pcg.rs`). The restriction of an inverse is not the inverse of the restriction, so
//! the preconditioned system is not the identity near the stick boundary, but the spread of
//! its spectrum no longer grows like the lattice size. Measured on the Cattaneo sphere
//! (T = 0.5 fP, residual $10^{-8}$, nested start, `fast_probe N`): 22, 21, 23 and 31–32 CG steps
//! at 128 (T = 0.3 fP), 256, 512 and 1024 cells across, where Jacobi on the slip tangents took
//! 32, 41, 53 and 75; near gross slip (T = 0.99999 fP) 11 at 512 across (Jacobi 12). From a
//! cold start (no nesting, `fast_probe N 0.5 cold`) 42 and 49 at 128 and 256 across, where
//! Jacobi throughout took 128 and 210.
//! Inner tolerances follow Eisenstat & Walker (1996): loose while the active set still
//! moves, then no tighter than needed to bring the residual below the target.
//!
//! **Nested start** ([`FastProblem::solve`]): a lattice at least $2\times$
//! [`NEST_MIN_CELLS`] across starts from its 2 x 2 coarsened lattice's solution (its stick
//! and slip states and tractions), solved the same way to a looser residual; the fine
//! lattice then needs about four Newton steps instead of ten or more, whatever its size.
//! The influence coefficients are evaluated once, on the finest lattice
//! ([`stickslip_lattice::TensorConvolution::kernel`]): a lattice coarsened $k$ times sees the
//! same offsets in cells with cells $2^k$ times larger, and the coefficients are homogeneous
//! of degree 1 in the cell size, so every level plans its operator from the finest kernel
//! (`from_kernel`, the same operator to the bit).
//! Callers solving load paths start from their previous solution with
//! [`FastProblem::solve_from`] and [`WarmStart`].
//!
//! **Convergence criterion**: $\lVert\mathbf r\rVert_2 \le \varepsilon\,\lVert\mathbf q
//! \rVert_2$ (relative residual of the complementarity conditions, in traction units: on a
//! stick element $\mathbf r_k = -\rho\,\mathbf s_k$ is the traction that would cancel the
//! slip) and the load constraints to the same relative $\varepsilon$.
//!
//! The LP's one-direction assumption is available as [`TractionDirections::ParallelToForce`]
//! or [`TractionDirections::Fixed`]: each element's traction is then $F_k\mathbf t_k$ with
//! $|F_k| \le c_k$, only the displacement along $\mathbf t_k$ counts, and the rigid motion is
//! the LP's single mode ($g_k = 1$ for a force, the lever arm for a moment).
//!
//! Sources: FORMULAS.md E (Mindlin), F (influence coefficients), G (Lubkin) for the
//! references of the tests.

mod newton;
mod solver;

pub(crate) use solver::{resultant_moment, SOLVER_NAME};
pub use solver::{
    FastConfig, FastInfo, FastProblem, FastSolution, TractionDirections, WarmStart, NEST_MIN_CELLS,
};

//! A fast partial-slip solver for large grids: both traction components free on the Coulomb
//! disc $|\mathbf q_k| \le f p_k$, a tangential force in any direction and optionally a
//! twisting moment, the influence operator applied by zero-padded FFT convolution
//! ([`TensorConvolution`]).
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
//! Jacobi-preconditioned projected conjugate gradients (Gould, Hribar & Nocedal 2001,
//! *SIAM J. Sci. Comput.* 23) in which every product with $K$ is one FFT convolution:
//! $O(N\log N)$ per iteration.
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
mod operator;
mod solver;

pub(crate) use operator::fast_size;
pub use operator::{ConvScratch, TensorConvolution};
pub(crate) use solver::{resultant_moment, SOLVER_NAME};
pub use solver::{
    FastConfig, FastInfo, FastProblem, FastSolution, TractionDirections, WarmStart, NEST_MIN_CELLS,
};

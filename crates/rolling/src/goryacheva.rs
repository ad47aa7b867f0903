//! Goryacheva (1973): a viscoelastic cylinder rolling with stick and slip on a base of the
//! same material.
//!
//! Material law $\varepsilon + \alpha\dot\varepsilon = (\sigma + \beta\dot\sigma)/E$,
//! $\alpha \ge \beta > 0$ (relaxation times \[s\]); rolling speed $w > 0$ \[m/s\] in $+x$; creep
//! $\delta = (\omega R - w)/w$; friction $\rho$. Contact $(-a, b)$, length $l = a + b$,
//! centre shift $d = (b-a)/2$ (positive = forward); slip zone $(-a, c)$ at the trailing edge,
//! stick zone $(c, b)$ of length $m = b - c$. Sign conventions and negative creep are as in
//! [`crate::carter`](mod@crate::carter) ($\signed_friction = \rho\,\mathrm{sign}\,\delta$).
//!
//! # How the equations are solved
//! All equations are taken from Goryacheva, PMM 37(5) 1973 (seed 001), in the corrected forms
//! of FORMULAS.md section D, and used in the scaled forms that contain only the bounded ratios
//! $r(x) = I_1(x)/I_0(x)$ and $k(x) = K_0(x)/K_1(x)$, so that no Bessel argument (up to
//! $10^{300}$) can overflow.
//!
//! **Contact length (eq 19).** With $l_H = \sqrt{8KRP}$, $\lambda = l/l_H$,
//! $q = (\alpha-\beta)w/l_H$, $x_1 = l/(2\beta w)$, $x_2 = l/(2\alpha w)$, eq 19 divided by
//! $I_1(x_1)K_1(x_2)$ and multiplied by $r(x_1)/P$ reads
//! $$g(\lambda) = (1-\lambda^2)\,[1 + r(x_1)k(x_2)] - 4\lambda q\, r(x_1) = 0 .$$
//! *Bracket.* Write $g = 0$ as $h(\lambda) = (1-\lambda^2)/\lambda = 4q/(1/r + k)$; $h$
//! decreases. Since $k \in (0,1)$ and $1/r(x) \ge \max(1, 2/x)$, the right side is below
//! $\min(4q,\ \lambda(\alpha-\beta)/\beta)$; since $1/r(x) \le 1 + 2/x$ (Amos' bound
//! $r(x) \ge x/(1+\sqrt{1+x^2})$), it is above $\min(q,\ \lambda(\alpha-\beta)/(2\beta))$.
//! Hence every root lies in
//! $$\lambda_{lo} = \max\!\left(\sqrt{\beta/\alpha},\ \sqrt{1+4q^2}-2q\right) < \lambda <
//!   \lambda_{hi} = \max\!\left(\sqrt{2\beta/(\alpha+\beta)},\ \sqrt{1+q^2/4}-q/2\right),$$
//! with $g(\lambda_{lo}) > 0 > g(\lambda_{hi})$. The first entries are the fast asymptote
//! $l^2 = 8KRP\beta/\alpha$, the second ones variants of the slow asymptote
//! $l = \sqrt{8KRP + (\alpha-\beta)^2w^2} - (\alpha-\beta)w$ (FORMULAS.md D). Brent's method
//! then converges to a few ulps; no starting guess is needed.
//!
//! **Shift (eq 20)** with the root inserted: $d = (\alpha-\beta)w\,\varphi(l)$,
//! $\varphi(z) = \dfrac{r k}{1 + r k}$ at $x_1 = z/(2\beta w)$, $x_2 = z/(2\alpha w)$; so $d > 0$.
//!
//! **Stick length (eq 24).** Divided by $I_0(y_1)K_1(y_2)$ and multiplied by $2R/\signed_friction$, with
//! $e = 2|\delta|R/\rho$ (Carter's slip length):
//! $$f(m) = (l + 2d - e) - m - 2(\alpha-\beta)w\,\varphi(m) = 0 .$$
//! $m + 2(\alpha-\beta)w\varphi(m)$ increases strictly ($r$ and $k$ increase),
//! $f(0^+) = l + 2d - e$ and $f(l) = -e$: a unique root in $(0, l]$ exists iff $0 < e < l + 2d$. $e \ge l + 2d$ is
//! full slip ($m = 0$, $Q = -\signed_friction P$), $\delta = 0$ full stick ($m = l$, $Q = 0$).
//!
//! **Constants.** Eqs 25, 27 and 28 with the roots inserted are rearranged so that no
//! difference of large terms remains ($s = r(y_1)$, $\kappa = k(y_2)$, $y_1 = m/(2\beta w)$,
//! $y_2 = m/(2\alpha w)$, $\mu = m/l_H$):
//! $$C_2 = -\frac{m\signed_friction w}{2KR}\,\frac{\alpha(1-s) + \beta s(1+\kappa)}{1+s\kappa},\qquad
//!   Q = -\signed_friction P\left[(1-\mu^2) - \frac{4\mu q\,s}{1 + s\kappa}\right],$$
//! $$M_1 = P\left[d(1-\lambda^2) + w(\lambda^2\alpha-\beta)\right],\quad
//!   1-\lambda^2 = \frac{4\lambda q r}{1+rk},\quad
//!   \lambda^2\alpha - \beta = \frac{\beta(\alpha-\beta)(rk + I_2/I_0)}{\beta(1+rk) +
//!   (\alpha-\beta)\,2r/x_1},$$
//! ($r, k$ at $x_1, x_2$; $I_2/I_0 = 1 - 2r/x_1$), and $M^* = M_1 + QR$.

use crate::carter::{carter, CarterParams, CarterSolution};
use crate::error::{finite, normal, positive, Error};
use crate::kernel::{angle, ExpKernel};
use crate::ratios::{i2_over_i0, i_ratio, k_ratio, one_minus_i_ratio, two_i_ratio_over_x};
use crate::roots::brent;
use crate::{Regime, StressConfig};
use std::f64::consts::PI;
use stickslip_quad::Estimate;

/// Largest number of Brent iterations per root (never reached in the tests: see
/// [`SolveInfo`]).
const MAX_ITER: usize = 200;

/// Whether the material relaxes ($\alpha > \beta$) or is elastic ($\alpha = \beta$).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Response {
    /// $\alpha > \beta$: Goryacheva's viscoelastic solution.
    Viscoelastic,
    /// $\alpha = \beta$ exactly: the material is elastic with modulus $E$, and the problem is
    /// solved as Carter's ([`crate::carter`](mod@crate::carter)).
    Elastic,
}

/// Validated inputs of Goryacheva's problem (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoryachevaParams {
    /// The elastic part (material, radius, load, friction, creep), validated as Carter's.
    elastic: CarterParams,
    alpha: f64,
    beta: f64,
    speed: f64,
}

impl GoryachevaParams {
    /// Check and store the inputs.
    ///
    /// - `youngs_modulus` $E$ \[Pa\] $> 0$ and `poisson_ratio` $\nu$, $-1 < \nu \le 1/2$, of
    ///   both cylinder and base;
    /// - `radius` $R$ \[m\] $> 0$; `load` $P$ \[N/m\] $> 0$ (per unit length);
    /// - `friction` $\rho > 0$; `creep` $\delta = (\omega R - w)/w$, finite, either sign;
    /// - `alpha` $\alpha$ \[s\] and `beta` $\beta$ \[s\], $\alpha \ge \beta > 0$;
    /// - `speed` $w$ \[m/s\] $> 0$.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first offending input (including $\alpha < \beta$);
    /// [`Error::NonFinite`] when a derived scale ($l_H = \sqrt{8KRP}$, $l_H/(2\beta w)$,
    /// $(\alpha-\beta)w/l_H$) is not a normal `f64`.
    pub fn new(
        youngs_modulus: f64,
        poisson_ratio: f64,
        radius: f64,
        load: f64,
        friction: f64,
        creep: f64,
        alpha: f64,
        beta: f64,
        speed: f64,
    ) -> Result<Self, Error> {
        let elastic =
            CarterParams::new(youngs_modulus, poisson_ratio, radius, load, friction, creep)?;
        positive("beta", beta)?;
        positive("alpha", alpha)?;
        if alpha < beta {
            return Err(Error::OutOfDomain {
                name: "alpha",
                value: alpha,
                allowed: "alpha >= beta (retardation time at least the relaxation time)",
            });
        }
        positive("speed", speed)?;
        let p = GoryachevaParams { elastic, alpha, beta, speed };
        Scales::of(&p)?;
        Ok(p)
    }

    /// Compliance $K = 4(1-\nu^2)/(\pi E)$ \[1/Pa\] of the two identical bodies (Goryacheva
    /// 1973 eq 3; FORMULAS.md section D; see [`crate::carter::compliance`]).
    #[must_use]
    pub fn compliance(&self) -> f64 {
        self.elastic.compliance()
    }
    /// Elastic (Hertz) contact length $l_H = \sqrt{8KRP}$ \[m\], the root of eq 19 at
    /// $\alpha = \beta$ (Goryacheva 1973, elastic limit; FORMULAS.md section D).
    #[must_use]
    pub fn hertz_length(&self) -> f64 {
        (8.0 * self.compliance() * self.radius() * self.load()).sqrt()
    }
    /// The elastic part of the problem as Carter's parameters (same material, radius, load,
    /// friction and creep): what the contact would be at $\alpha = \beta$.
    #[must_use]
    pub fn elastic(&self) -> &CarterParams {
        &self.elastic
    }
    /// Radius $R$ \[m\].
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.elastic.radius()
    }
    /// Load $P$ \[N/m\].
    #[must_use]
    pub fn load(&self) -> f64 {
        self.elastic.load()
    }
    /// Friction $\rho$.
    #[must_use]
    pub fn friction(&self) -> f64 {
        self.elastic.friction()
    }
    /// Creep $\delta$.
    #[must_use]
    pub fn creep(&self) -> f64 {
        self.elastic.creep()
    }
    /// $\alpha$ \[s\].
    #[must_use]
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// $\beta$ \[s\].
    #[must_use]
    pub fn beta(&self) -> f64 {
        self.beta
    }
    /// Speed $w$ \[m/s\].
    #[must_use]
    pub fn speed(&self) -> f64 {
        self.speed
    }
}

/// Derived scales, all checked to be normal numbers.
#[derive(Debug, Clone, Copy)]
struct Scales {
    kr: f64,
    lh: f64,
}

impl Scales {
    fn of(p: &GoryachevaParams) -> Result<Self, Error> {
        let kr = normal("K R", p.compliance() * p.radius())?;
        let lh = normal("Hertz length l_H", p.hertz_length())?;
        normal("l_H/(2 beta w)", lh / (2.0 * p.beta * p.speed))?;
        finite("(alpha - beta) w / l_H", (p.alpha - p.beta) * p.speed / lh)?;
        Ok(Scales { kr, lh })
    }
}

/// The solution of eqs 19 and 20 alone (contact length and position).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLength {
    /// $\lambda = l/l_H$.
    pub ratio: f64,
    /// $l = a + b$ \[m\].
    pub length: f64,
    /// $d = (b-a)/2$ \[m\].
    pub shift: f64,
    /// $x_1 = l/(2\beta w)$.
    pub x1: f64,
    /// $x_2 = l/(2\alpha w)$.
    pub x2: f64,
    /// $1 - \lambda^2 = 4\lambda q r/(1+rk)$, without cancellation.
    pub one_minus_ratio_sq: f64,
    /// $I_1/I_0(x_1)$.
    r: f64,
    /// $K_0/K_1(x_2)$.
    k: f64,
    /// Bracket of $\lambda$ used.
    pub bracket: (f64, f64),
    /// Brent iterations.
    pub iterations: usize,
    /// $g(\lambda)$ at the returned root (dimensionless scaled eq 19).
    pub residual: f64,
}

/// $\sqrt{1+y^2} - y$ for $y \ge 0$, without cancellation or overflow.
fn sqrt1p_minus(y: f64) -> f64 {
    1.0 / (1.0f64.hypot(y) + y)
}

/// Solve the scaled eq 19 for $l$ and eq 20 for $d$ (see the [module docs](self) for the
/// equation and the bracket). `lh` is $l_H = \sqrt{8KRP}$ \[m\].
///
/// For $\alpha = \beta$ the bracket collapses to $\lambda = 1$, $d = 0$ (Hertz).
///
/// # Errors
/// [`Error::NonFinite`] if a result is not finite (not expected for validated inputs).
pub fn contact_length(alpha: f64, beta: f64, speed: f64, lh: f64) -> Result<ContactLength, Error> {
    let c1 = lh / (2.0 * beta * speed);
    let c2 = lh / (2.0 * alpha * speed);
    let q = (alpha - beta) * speed / lh;
    let g = |lam: f64| {
        let r = i_ratio(lam * c1);
        let k = k_ratio(lam * c2);
        (1.0 - lam) * (1.0 + lam) * (1.0 + r * k) - 4.0 * lam * q * r
    };
    let lo = (beta / alpha).sqrt().max(sqrt1p_minus(2.0 * q));
    let hi = (2.0 * beta / (alpha + beta)).sqrt().max(sqrt1p_minus(0.5 * q)).min(1.0);
    let (lam, iterations, residual) = if lo >= hi {
        (lo, 0, g(lo))
    } else {
        let (glo, ghi) = (g(lo), g(hi));
        if glo <= 0.0 {
            // The analysis puts the root above lo; a non-positive value here means the root is
            // within rounding of lo.
            (lo, 0, glo)
        } else if ghi >= 0.0 {
            (hi, 0, ghi)
        } else {
            let root = brent(g, lo, hi, glo, ghi, 0.0, MAX_ITER);
            (root.x, root.iterations, root.fx)
        }
    };
    let x1 = lam * c1;
    let x2 = lam * c2;
    let r = i_ratio(x1);
    let k = k_ratio(x2);
    let rk = r * k;
    let length = finite("contact length l", lam * lh)?;
    let shift = finite("shift d", (alpha - beta) * speed * (rk / (1.0 + rk)))?;
    Ok(ContactLength {
        ratio: lam,
        length,
        shift,
        x1,
        x2,
        one_minus_ratio_sq: 4.0 * lam * q * r / (1.0 + rk),
        r,
        k,
        bracket: (lo, hi),
        iterations,
        residual,
    })
}

/// Iterations and residuals of the two root solves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveInfo {
    /// Bracket $(\lambda_{lo}, \lambda_{hi})$ of $\lambda = l/l_H$ (eq 19).
    pub length_bracket: (f64, f64),
    /// Brent iterations for eq 19 (0 in the elastic case).
    pub length_iterations: usize,
    /// Scaled eq 19 residual $g(\lambda)$ at the root (dimensionless, terms of order 1).
    pub length_residual: f64,
    /// Brent iterations for eq 24 (0 when no root solve was needed).
    pub stick_iterations: usize,
    /// Scaled eq 24 residual $f(m)$ at the root \[m\].
    pub stick_residual: f64,
    /// Bessel arguments $x_1 = l/(2\beta w)$, $x_2 = l/(2\alpha w)$,
    /// $y_1 = m/(2\beta w)$, $y_2 = m/(2\alpha w)$.
    pub bessel_args: [f64; 4],
}

/// Goryacheva's solution.
#[derive(Debug, Clone, PartialEq)]
pub struct GoryachevaSolution {
    /// Contact length $l = a + b$ \[m\] (eq 19).
    pub contact_length: f64,
    /// Shift of the contact centre $d = (b - a)/2$ \[m\] (eq 20), $> 0$ = forward.
    pub shift: f64,
    /// Trailing-edge distance $a$ \[m\]: the contact is $(-a, b)$.
    pub rear: f64,
    /// Leading edge $b$ \[m\].
    pub front: f64,
    /// Stick-zone length $m = b - c$ \[m\] (eq 24).
    pub stick_length: f64,
    /// Start of the stick zone $c$ \[m\] ($c = b$ in full slip).
    pub stick_start: f64,
    /// Constant $C_2$ \[N/m\] (eq 25).
    pub c2: f64,
    /// Tangential force $Q = \int\tau\,dx$ \[N/m\] (eq 27).
    pub tangential_force: f64,
    /// Pressure moment $M_1 = \int x\sigma_y\,dx$ \[N\] (eq 28).
    pub moment_m1: f64,
    /// Rolling-friction moment $M^* = M_1 + QR$ \[N\].
    pub rolling_moment: f64,
    /// Elastic Hertz length $l_H = \sqrt{8KRP}$ \[m\].
    pub hertz_length: f64,
    /// Stick-slip, full slip or full stick.
    pub regime: Regime,
    /// Viscoelastic, or exactly elastic ($\alpha = \beta$).
    pub response: Response,
    /// Root-solve diagnostics.
    pub info: SolveInfo,
    stress: Stress,
}

/// What the stress formulas need.
#[derive(Debug, Clone, PartialEq)]
enum Stress {
    Elastic(CarterSolution),
    Viscoelastic { beta_w: f64, signed_friction: f64, sigma: ExpKernel, tau: ExpKernel },
}

/// Solve Goryacheva's problem: eqs 19, 20, 24, 25, 27, 28 (FORMULAS.md section D; see the
/// [module docs](self) for the scaled forms, brackets and rearrangements).
///
/// $\alpha = \beta$ is reported as [`Response::Elastic`] and solved as Carter's problem; the
/// three regimes are reported in [`GoryachevaSolution::regime`].
///
/// # Errors
/// [`Error::NonFinite`] if a result is not finite (guard; not expected for validated inputs).
pub fn solve(p: &GoryachevaParams) -> Result<GoryachevaSolution, Error> {
    let sc = Scales::of(p)?;
    let (alpha, beta, w) = (p.alpha, p.beta, p.speed);
    let friction = p.friction();
    let signed_friction = if p.creep() < 0.0 { -friction } else { friction };
    let kr = sc.kr;
    let lh = sc.lh;

    if alpha == beta {
        let cs = carter(&p.elastic);
        let a = cs.half_width;
        let m = cs.stick_length;
        return Ok(GoryachevaSolution {
            contact_length: 2.0 * a,
            shift: 0.0,
            rear: a,
            front: a,
            stick_length: m,
            stick_start: cs.stick_start,
            c2: -signed_friction * m * alpha * w / (2.0 * kr),
            tangential_force: cs.tangential_force,
            moment_m1: 0.0,
            rolling_moment: cs.rolling_moment,
            hertz_length: lh,
            regime: cs.regime,
            response: Response::Elastic,
            info: SolveInfo {
                length_bracket: (1.0, 1.0),
                length_iterations: 0,
                length_residual: 0.0,
                stick_iterations: 0,
                stick_residual: 0.0,
                bessel_args: [
                    a / (beta * w),
                    a / (alpha * w),
                    m / (2.0 * beta * w),
                    m / (2.0 * alpha * w),
                ],
            },
            stress: Stress::Elastic(cs),
        });
    }

    let cl = contact_length(alpha, beta, w, lh)?;
    let (l, d) = (cl.length, cl.shift);
    let q = (alpha - beta) * w / lh;
    let (r, k) = (cl.r, cl.k);
    let rk = r * k;
    let u = cl.one_minus_ratio_sq;

    // M1 (eq 28) without cancellation.
    // lambda^2 alpha - beta = beta (alpha-beta)(rk + I2/I0) / (beta (1+rk) + (alpha-beta) 2r/x1),
    // divided through by the larger of beta and alpha - beta so that nothing overflows.
    let (num, rho1) = (rk + i2_over_i0(cl.x1), two_i_ratio_over_x(cl.x1));
    let lam2a_minus_b = if alpha - beta >= beta {
        beta * num / (rho1 + (1.0 + rk) * (beta / (alpha - beta)))
    } else {
        (alpha - beta) * num / ((1.0 + rk) + ((alpha - beta) / beta) * rho1)
    };
    let m1 = finite("M1", p.load() * (d * u + w * lam2a_minus_b))?;

    // Stick length (eq 24).
    let phi = |z: f64| {
        let s = i_ratio(z / (2.0 * beta * w));
        let kk = k_ratio(z / (2.0 * alpha * w));
        s * kk / (1.0 + s * kk)
    };
    let slip = 2.0 * p.creep().abs() * p.radius() / friction;
    let t = (l + 2.0 * d) - slip;
    let (regime, m, stick_iterations, stick_residual) = if p.creep() == 0.0 {
        (Regime::FullStick, l, 0, 0.0)
    } else if t <= 0.0 {
        (Regime::FullSlip, 0.0, 0, t)
    } else {
        let f = |m: f64| (t - m) - 2.0 * (alpha - beta) * w * phi(m);
        let fl = f(l);
        if fl >= 0.0 {
            (Regime::StickSlip, l, 0, fl)
        } else {
            let root = brent(f, 0.0, l, t, fl, 0.0, MAX_ITER);
            (Regime::StickSlip, root.x, root.iterations, root.fx)
        }
    };
    let y1 = m / (2.0 * beta * w);
    let y2 = m / (2.0 * alpha * w);
    let s = i_ratio(y1);
    let kk = k_ratio(y2);
    let den2 = 1.0 + s * kk;
    let c2 = -(m * signed_friction * w / (2.0 * kr))
        * (alpha * one_minus_i_ratio(y1) + beta * s * (1.0 + kk))
        / den2;
    let mu = m / lh;
    let tangential_force = match regime {
        Regime::FullStick => 0.0,
        _ => -signed_friction * p.load() * ((1.0 - mu) * (1.0 + mu) - 4.0 * mu * q * s / den2),
    };
    let tangential_force = finite("Q", tangential_force)?;
    let rolling_moment = finite("M*", m1 + tangential_force * p.radius())?;

    // Stress kernels (eqs 12, 13), see crate::kernel.
    let half = 0.5 * l;
    let lw = l * w / (2.0 * kr);
    let sigma = ExpKernel {
        kappa: cl.x1,
        c0: p.load() * u,
        c1: half * w * (alpha + beta * rk) / ((1.0 + rk) * kr),
        fa: -lw * (alpha * one_minus_i_ratio(cl.x1) + beta * r * (1.0 + k)) / (1.0 + rk),
        fb: lw * ((alpha - beta) * r + alpha + beta * rk) / (1.0 + rk),
        c2: half * half / kr,
        c2_by_parts: -(half * half / kr) * (alpha - beta) / (beta * (1.0 + rk)),
    };
    let hm = 0.5 * m;
    let mw = signed_friction * hm * w / kr;
    let tau = ExpKernel {
        kappa: y1,
        c0: mw * (alpha - beta) * s / den2,
        c1: mw * (alpha + beta * s * kk) / den2,
        fa: -mw * (alpha * one_minus_i_ratio(y1) + beta * s * (1.0 + kk)) / den2,
        fb: mw * ((alpha - beta) * (1.0 + s) / den2 + beta),
        c2: signed_friction * hm * hm / kr,
        c2_by_parts: -(signed_friction * hm * hm / kr) * (alpha - beta) / (beta * den2),
    };
    let rear = half - d;
    let front = half + d;
    Ok(GoryachevaSolution {
        contact_length: l,
        shift: d,
        rear,
        front,
        stick_length: m,
        stick_start: if regime == Regime::FullStick { -rear } else { front - m },
        c2: finite("C2", c2)?,
        tangential_force,
        moment_m1: m1,
        rolling_moment,
        hertz_length: lh,
        regime,
        response: Response::Viscoelastic,
        info: SolveInfo {
            length_bracket: cl.bracket,
            length_iterations: cl.iterations,
            length_residual: cl.residual,
            stick_iterations,
            stick_residual,
            bessel_args: [cl.x1, cl.x2, y1, y2],
        },
        stress: Stress::Viscoelastic { beta_w: beta * w, signed_friction, sigma, tau },
    })
}

impl GoryachevaSolution {
    /// True pressure $\sigma_y(x)$ \[Pa\] at $x$ (eq 12), zero outside $(-a, b)$.
    ///
    /// Eq 12 integrates $\sigma^* = F/(\pi\sqrt{(a+t)(b-t)})$ from the trailing edge with the
    /// weight $e^{(x-t)/(\beta w)} \ge 1$, which overflows and cancels when
    /// $l \gg \beta w$. Because eq 18 makes $\int_{-a}^{b}\sigma^* e^{-t/(\beta w)}dt$ vanish,
    /// the same function is
    /// $$\sigma_y(x) = \frac{1}{\pi\beta w}\int_x^b \frac{F(t)\,e^{-(t-x)/(\beta w)}}
    ///   {\sqrt{(a+t)(b-t)}}\,dt,$$
    /// whose weight is $\le 1$; this is what is evaluated, through the angle substitution of
    /// `kernel` with $F = (P - \tfrac{l^2}{8KR}) + \tfrac{L(\alpha w-d)}{KR}\cos\theta +
    /// \tfrac{L^2}{KR}\sin^2\theta$, $L = l/2$. In the elastic case the Hertz closed form
    /// [`CarterSolution::pressure`] is returned (error 0, no evaluations).
    ///
    /// # Errors
    /// [`Error::Quadrature`] if the requested tolerance is not met.
    pub fn pressure(&self, x: f64, cfg: &StressConfig) -> Result<Estimate, Error> {
        match &self.stress {
            Stress::Elastic(cs) => Ok(Estimate { value: cs.pressure(x), error: 0.0, evals: 0 }),
            Stress::Viscoelastic { beta_w, sigma, .. } => {
                if x <= -self.rear || x >= self.front {
                    return Ok(Estimate { value: 0.0, error: 0.0, evals: 0 });
                }
                let th = angle(x, -self.rear, self.front);
                let j = sigma.integrate(th, cfg).map_err(|source| Error::Quadrature {
                    quantity: "pressure",
                    x,
                    source,
                })?;
                Ok(j.scaled(1.0 / (PI * beta_w)))
            }
        }
    }

    /// True shear $\tau_{xy}(x)$ \[Pa\] at $x$ (eq 13), zero outside $(-a, b)$:
    /// $\tau = -\signed_friction\sigma_y$ on the slip zone and, on the stick zone $(c, b)$,
    /// $$\tau = -\signed_friction\sigma_y + \frac{1}{\pi\beta w}\int_x^b
    ///   \left[\Big(\frac{\signed_friction}{2KR}(b-c-2t+2\alpha w) + \frac{\delta}{K}\Big)(t-c) + C_2\right]
    ///   \frac{e^{-(t-x)/(\beta w)}\,dt}{\sqrt{(t-c)(b-t)}},$$
    /// the form of eq 13 with weight $\le 1$ (equal to eq 13 by eq 23, as for
    /// [`pressure`](Self::pressure)). Elastic case: Carter's closed form.
    ///
    /// # Errors
    /// [`Error::Quadrature`] if the requested tolerance is not met.
    pub fn shear(&self, x: f64, cfg: &StressConfig) -> Result<Estimate, Error> {
        match &self.stress {
            Stress::Elastic(cs) => Ok(Estimate { value: cs.shear(x), error: 0.0, evals: 0 }),
            Stress::Viscoelastic { beta_w, signed_friction, tau, .. } => {
                let p = self.pressure(x, cfg)?;
                let mut out = p.scaled(-signed_friction);
                if self.regime != Regime::FullSlip && x > self.stick_start && x < self.front {
                    let th = angle(x, self.stick_start, self.front);
                    let j = tau.integrate(th, cfg).map_err(|source| Error::Quadrature {
                        quantity: "shear",
                        x,
                        source,
                    })?;
                    out = out.combine(j.scaled(1.0 / (PI * beta_w)));
                }
                Ok(out)
            }
        }
    }

    /// The stick zone $(c, b)$, if there is one.
    #[must_use]
    pub fn stick_zone(&self) -> Option<(f64, f64)> {
        (self.stick_length > 0.0).then_some((self.stick_start, self.front))
    }
}

//! The wheelset's motion and the creepages of each patch.
//!
//! The rail is at rest; the wheelset centre moves with $\mathbf v_c = (V, v_y, v_z)$ and
//! turns with $\boldsymbol\omega = R\,(\dot\varphi, \omega_p, \dot\psi)$ (CONTACT's
//! approximation of the angular velocity by the Euler-angle rates in wheelset axes; $R$ the
//! wheelset's rotation, $\omega_p$ the pitch rate, negative when rolling forward). The wheel
//! material at the patch's reference point $\mathbf q$ (the undeformed wheel surface on the
//! patch normal through the reference point) moves with
//! $\mathbf v_q = \mathbf v_c + \boldsymbol\omega\times(\mathbf q - \mathbf c)$.
//!
//! The creepages are the rigid slip of the rail (body 1) over the wheel (body 2) per unit
//! rolling distance, in the patch frame ([`crate::patch`]; Kalker's definition, CONTACT's
//! module 1):
//! $$\xi = \frac{-\mathbf v_q\cdot\mathbf e_x}{V_r},\qquad
//! \eta = \frac{-\mathbf v_q\cdot\mathbf e_s}{V_r},\qquad
//! \phi = \frac{-\boldsymbol\omega\cdot\mathbf e_n}{V_r},$$
//! with the rolling speed $V_r = \tfrac12\left(|v_{q,x} - u_x| + |u_x|\right)$ the mean of
//! the forward speed of the contact over the rail and of the wheel's circumferential speed
//! there, $\mathbf u = (R\,(0, \omega_p, 0))\times(\mathbf q - \mathbf c)$. For a wheelset
//! rolling forward at speed $V$ on a wheel of rolling radius $r$ these reduce to
//! $\xi \approx -(V + \omega_p r)/V$, $\eta \approx \psi$ at small yaw and
//! $\phi \approx \omega_p\sin\delta/V$ (the spin of a wheel tread inclined by the contact
//! angle).

use crate::error::{finite, Error, Result};
use crate::patch::Frame;
use crate::placement::PlacedWheel;
use nalgebra::Vector3;
use stickslip_rolling::Creepage;

/// The wheelset's velocities (track coordinates; CONTACT's `VS`, `VY`, `VZ`, `VROLL`,
/// `VPITCH`, `VYAW`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Forward speed $V$ of the wheelset centre (m/s, $> 0$: rolling in $+x$).
    pub speed: f64,
    /// Pitch rate $\omega_p$ (rad/s, about the axle; negative when rolling forward).
    pub pitch_rate: f64,
    /// Lateral velocity $v_y$ (m/s).
    pub lateral_velocity: f64,
    /// Vertical velocity $v_z$ (m/s).
    pub vertical_velocity: f64,
    /// Roll rate $\dot\varphi$ (rad/s).
    pub roll_rate: f64,
    /// Yaw rate $\dot\psi$ (rad/s).
    pub yaw_rate: f64,
    /// Creepages given directly (longitudinal, lateral, spin in the patch's frame of the
    /// problem's side, as [`crate::PatchSolution::creepage`] reports them), used instead of
    /// those of the velocities above; the rolling speed is then `speed`. Only a position
    /// with a single patch takes them ([`Error::OutOfDomain`] named `motion.creepage`
    /// otherwise: the creepages of two patches differ).
    pub creepage: Option<Creepage>,
}

impl Motion {
    /// Rolling forward at `speed` with the pitch rate `pitch_rate`, no other motion.
    #[must_use]
    pub fn rolling(speed: f64, pitch_rate: f64) -> Self {
        Self {
            speed,
            pitch_rate,
            lateral_velocity: 0.0,
            vertical_velocity: 0.0,
            roll_rate: 0.0,
            yaw_rate: 0.0,
            creepage: None,
        }
    }

    /// Rolling forward at `speed` with the creepages `creepage` given directly (a single
    /// patch; see [`Motion::creepage`]).
    #[must_use]
    pub fn with_creepage(speed: f64, creepage: Creepage) -> Self {
        Self { creepage: Some(creepage), ..Self::rolling(speed, 0.0) }
    }

    /// Free rolling at the wheel radius $r_0$ of the profile origin: $\omega_p = -V/r_0$.
    #[must_use]
    pub fn free_rolling(speed: f64, wheel_radius: f64) -> Self {
        Self::rolling(speed, -speed / wheel_radius)
    }

    pub(crate) fn validate(&self) -> Result<()> {
        for (name, v) in [
            ("motion.speed", self.speed),
            ("motion.pitch_rate", self.pitch_rate),
            ("motion.lateral_velocity", self.lateral_velocity),
            ("motion.vertical_velocity", self.vertical_velocity),
            ("motion.roll_rate", self.roll_rate),
            ("motion.yaw_rate", self.yaw_rate),
        ] {
            finite(name, v)?;
        }
        if let Some(c) = self.creepage {
            for (name, v) in [
                ("motion.creepage.longitudinal", c.longitudinal),
                ("motion.creepage.lateral", c.lateral),
                ("motion.creepage.spin", c.spin),
            ] {
                finite(name, v)?;
            }
        }
        if self.speed <= 0.0 {
            return Err(Error::OutOfDomain {
                name: "motion.speed",
                value: self.speed,
                allowed: "> 0 (rolling in +x; for rolling backwards turn the track round)",
            });
        }
        Ok(())
    }

    /// The same motion seen on the right side of a left-side problem (mirror in $y = 0$).
    pub(crate) fn mirrored(&self) -> Self {
        Self {
            lateral_velocity: -self.lateral_velocity,
            roll_rate: -self.roll_rate,
            yaw_rate: -self.yaw_rate,
            creepage: self.creepage.map(|c| Creepage {
                longitudinal: c.longitudinal,
                lateral: -c.lateral,
                spin: -c.spin,
            }),
            ..*self
        }
    }
}

/// The creepages at a patch (module docs), its rolling speed $V_r$ and the wheel's rolling
/// radius $|\mathbf q - \mathbf c|$ projected on the plane normal to the axle.
pub(crate) fn creepages(
    wheel: &PlacedWheel<'_>,
    motion: &Motion,
    f: &Frame,
    q: &Vector3<f64>,
) -> Result<(Creepage, f64)> {
    let r = wheel.rot;
    let arm = q - wheel.centre;
    let omega = r * Vector3::new(motion.roll_rate, motion.pitch_rate, motion.yaw_rate);
    let vc = Vector3::new(motion.speed, motion.lateral_velocity, motion.vertical_velocity);
    let vq = vc + omega.cross(&arm);
    let u = (r * Vector3::new(0.0, motion.pitch_rate, 0.0)).cross(&arm);
    let vs = vq.x - u.x;
    let vr = 0.5 * (vs.abs() + u.x.abs());
    let forward = (vs >= 0.0 && vs.abs() >= u.x.abs()) || (u.x <= 0.0 && u.x.abs() > vs.abs());
    if !forward || vr <= 0.0 {
        return Err(Error::OutOfDomain {
            name: "motion.pitch_rate",
            value: motion.pitch_rate,
            allowed: "a wheel rolling forward (the contact must move in +x over the rail)",
        });
    }
    Ok((
        Creepage {
            longitudinal: -vq.dot(&f.ex) / vr,
            lateral: -vq.dot(&f.es) / vr,
            spin: -omega.dot(&f.en) / vr,
        },
        vr,
    ))
}

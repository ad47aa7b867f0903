//! Placing the rail and the wheel in track coordinates, CONTACT's conventions.
//!
//! **Track coordinates.** $x$ along the track in the rolling direction, $y$ to the right
//! (seen in $+x$), $z$ down; right-handed. Half a wheelset on one rail: [`Side::Right`] or
//! [`Side::Left`]. The computation is done on the right side: a left side is its mirror
//! image in the plane $y = 0$ (the inputs $y$, yaw, roll and their rates change sign on the
//! way in, every lateral output, the contact angle, the lateral creepage, the spin and the
//! spin moment on the way out), as CONTACT does internally. Profiles are given in the
//! canonical right-side orientation ([`crate::profile`]).
//!
//! **The rail** (right side): the profile $(y_r, z_r)$ is rotated about the $x$ axis by the
//! installation angle $-\beta$ ($\beta$ the rail cant, positive when the rail leans towards
//! the track centre),
//! $$\begin{pmatrix}y\\z\end{pmatrix} = \begin{pmatrix}y_0\\z_0\end{pmatrix} +
//! \begin{pmatrix}\cos\beta & \sin\beta\\ {-\sin\beta} & \cos\beta\end{pmatrix}
//! \begin{pmatrix}y_r\\z_r\end{pmatrix},$$
//! then $z_0$ makes its highest point touch the track plane ($\min z = 0$) and $y_0$ puts
//! its gauge point at $y = G/2$ ($G$ the gauge). The gauge point is the point of the rail
//! nearest the track centre (smallest $y$) among those from the top down to the gauge
//! height $h_g$ on the gauge side ($z \le h_g$; on an ordinary gauge face the point at depth
//! $h_g$). CONTACT's user guide, "Track and roller geometry" and "Overview of wheel/rail
//! contact configurations".
//!
//! **The wheel** (right side): the profile $(y_w, z_w)$ is a surface of revolution about
//! the axle. In wheelset coordinates (origin on the axle at the wheelset centre, $x$
//! forward, $y$ along the axle, $z$ down) its points are
//! $$\mathbf p(t, \theta) = \big(\rho(t)\sin\theta,\ y_{off} + y_w(t),\ \rho(t)\cos\theta\big),
//! \qquad \rho = r_0 + z_w,\quad y_{off} = d_{fb}/2 - y_{fb},$$
//! with $r_0$ the wheel radius at the profile origin, $d_{fb}$ the flange back distance and
//! $y_{fb}$ the flange back position in the profile's own $y$ ($\theta = 0$ is straight
//! below the axle). The wheelset is rolled by $\varphi$ about $x$, then yawed by $\psi$
//! about its own vertical axis (CONTACT's roll-yaw-pitch Euler angles; the pitch angle does
//! not change a round wheel), and shifted to the centre $\mathbf c = (0, y_{ws}, z_{ws} - r_0)$:
//! $$\mathbf w(t, \theta) = \mathbf c + R_x(\varphi)R_z(\psi)\,\mathbf p(t, \theta).$$
//! $z_{ws} = 0$ puts the profile origin of the un-rolled wheel on the track plane.

use crate::error::{finite, positive, Error, Result};
use crate::profile::{Profile, Role};
use nalgebra::{Matrix3, Rotation3, Vector3};

/// Which half of the wheelset and track.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The left wheel on the left rail ($y < 0$).
    Left,
    /// The right wheel on the right rail ($y > 0$).
    Right,
}

impl Side {
    /// $+1$ for the right side, $-1$ for the left: the sign of $y$ and of the other lateral
    /// quantities when mapped to and from the right side.
    #[must_use]
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => -1.0,
            Side::Right => 1.0,
        }
    }
}

/// The track: the rail profile and how it is laid.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    rail: Profile,
    gauge: f64,
    gauge_height: f64,
    cant: f64,
}

impl Track {
    /// A track of gauge `gauge` (m, between the gauge points) measured `gauge_height` (m)
    /// below the track plane, rails canted by `cant` (rad, towards the track centre).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for a non-positive gauge or gauge height, a cant beyond
    /// $\pm 0.2$ rad; [`Error::ProfileCheck`] if `rail` is a wheel profile.
    pub fn new(rail: Profile, gauge: f64, gauge_height: f64, cant: f64) -> Result<Self> {
        positive("gauge", gauge)?;
        positive("gauge_height", gauge_height)?;
        finite("rail_cant", cant)?;
        if cant.abs() > 0.2 {
            return Err(Error::OutOfDomain {
                name: "rail_cant",
                value: cant,
                allowed: "|cant| <= 0.2 rad (rail inclinations are 1:20 to 1:40, about 0.05 and 0.025 rad)",
            });
        }
        if rail.role() != Role::Rail {
            return Err(Error::ProfileCheck {
                name: rail.name().to_string(),
                line: None,
                problem: "a wheel profile is given as the rail".to_string(),
                hint: "give a rail profile".to_string(),
            });
        }
        Ok(Self { rail, gauge, gauge_height, cant })
    }

    /// The rail profile.
    #[must_use]
    pub fn rail(&self) -> &Profile {
        &self.rail
    }

    /// Gauge (m).
    #[must_use]
    pub fn gauge(&self) -> f64 {
        self.gauge
    }

    /// Gauge measuring height below the track plane (m).
    #[must_use]
    pub fn gauge_height(&self) -> f64 {
        self.gauge_height
    }

    /// Rail cant (rad).
    #[must_use]
    pub fn cant(&self) -> f64 {
        self.cant
    }
}

/// The wheelset's wheel: its profile and dimensions.
#[derive(Debug, Clone, PartialEq)]
pub struct Wheelset {
    wheel: Profile,
    flange_back_distance: f64,
    flange_back_position: f64,
    wheel_radius: f64,
    flange: (f64, f64),
}

impl Wheelset {
    /// A wheelset with wheels of profile `wheel`, flange backs `flange_back_distance` (m)
    /// apart, the flange back at `flange_back_position` (m) of the profile's own $y$, and the
    /// profile origin at `wheel_radius` (m) from the axle.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for non-positive distances or radius; [`Error::ProfileCheck`] if
    /// `wheel` is a rail profile.
    pub fn new(
        wheel: Profile,
        flange_back_distance: f64,
        flange_back_position: f64,
        wheel_radius: f64,
    ) -> Result<Self> {
        positive("flange_back_distance", flange_back_distance)?;
        finite("flange_back_position", flange_back_position)?;
        positive("wheel_radius", wheel_radius)?;
        if wheel.role() != Role::Wheel {
            return Err(Error::ProfileCheck {
                name: wheel.name().to_string(),
                line: None,
                problem: "a rail profile is given as the wheel".to_string(),
                hint: "give a wheel profile".to_string(),
            });
        }
        let zmin = wheel.points().1.iter().copied().fold(f64::INFINITY, f64::min);
        if wheel_radius + zmin <= 0.0 {
            return Err(Error::OutOfDomain {
                name: "wheel_radius",
                value: wheel_radius,
                allowed: "larger than the wheel profile's height above its origin",
            });
        }
        let flange = steepest_flange(&wheel);
        Ok(Self { wheel, flange_back_distance, flange_back_position, wheel_radius, flange })
    }

    /// The steepest point of the flange's running face $(y_w, \gamma_{max})$: from the
    /// flange tip (the profile's lowest point, largest $z$) towards the tread, the point of
    /// the largest inclination $\gamma = \operatorname{atan}(-dz_w/dy_w)$ (Nadal's flange
    /// angle). A contact beyond it, towards the tip, is flange climb.
    #[must_use]
    pub fn flange(&self) -> (f64, f64) {
        self.flange
    }

    /// The wheel profile.
    #[must_use]
    pub fn wheel(&self) -> &Profile {
        &self.wheel
    }

    /// Flange back distance (m).
    #[must_use]
    pub fn flange_back_distance(&self) -> f64 {
        self.flange_back_distance
    }

    /// Flange back position in the profile's $y$ (m).
    #[must_use]
    pub fn flange_back_position(&self) -> f64 {
        self.flange_back_position
    }

    /// Wheel radius at the profile origin (m).
    #[must_use]
    pub fn wheel_radius(&self) -> f64 {
        self.wheel_radius
    }
}

fn steepest_flange(wheel: &Profile) -> (f64, f64) {
    let samples = wheel.samples();
    let ktip =
        (0..samples.len()).max_by(|&a, &b| samples[a][2].total_cmp(&samples[b][2])).unwrap_or(0);
    let (mut best, mut angle) = (samples[ktip][1], f64::NEG_INFINITY);
    for s in &samples[ktip..] {
        let d = wheel.eval(s[0]).d1;
        let g = (-d[1]).atan2(d[0]);
        if g > angle {
            angle = g;
            best = s[1];
        }
        // Past the flank: the inclination has fallen to half its largest value (the flange
        // root and the tread), so a field-side face beyond is not taken for the flange.
        if angle > 0.3 && g < 0.5 * angle {
            break;
        }
    }
    (best, angle)
}

/// The wheelset's position relative to the track (CONTACT's `Y`, `YAW`, `ROLL`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Position {
    /// Lateral displacement $y_{ws}$ of the wheelset centre (m, $+y$ to the right).
    pub lateral: f64,
    /// Yaw angle $\psi$ (rad, right-hand rule about $z$ down).
    pub yaw: f64,
    /// Roll angle $\varphi$ (rad, right-hand rule about $x$).
    pub roll: f64,
}

impl Position {
    pub(crate) fn validate(&self) -> Result<()> {
        finite("position.lateral", self.lateral)?;
        finite("position.yaw", self.yaw)?;
        finite("position.roll", self.roll)?;
        for (name, v) in [("position.yaw", self.yaw), ("position.roll", self.roll)] {
            if v.abs() > 0.1 {
                return Err(Error::OutOfDomain {
                    name,
                    value: v,
                    allowed: "|angle| <= 0.1 rad (a wheelset on its track)",
                });
            }
        }
        if self.lateral.abs() > 0.1 {
            return Err(Error::OutOfDomain {
                name: "position.lateral",
                value: self.lateral,
                allowed: "|lateral| <= 0.1 m",
            });
        }
        Ok(())
    }
}

/// The rail placed on the right side of the track (module docs).
#[derive(Debug, Clone)]
pub(crate) struct PlacedRail<'a> {
    pub profile: &'a Profile,
    /// $\cos\beta$, $\sin\beta$ of the rotation (module docs).
    c: f64,
    s: f64,
    pub offset: [f64; 2],
}

impl<'a> PlacedRail<'a> {
    /// Place the rail of `track` (module docs).
    pub fn new(track: &'a Track) -> Result<Self> {
        let rail = &track.rail;
        let (c, s) = (track.cant.cos(), track.cant.sin());
        let mut me = Self { profile: rail, c, s, offset: [0.0, 0.0] };
        // Highest point: the smallest rotated z over the samples, refined by Newton on z' = 0.
        let samples = rail.samples();
        let rot = |p: &[f64; 3]| me.rotate([p[1], p[2]]);
        let (kmin, _) = samples
            .iter()
            .enumerate()
            .map(|(k, p)| (k, rot(p)[1]))
            .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        let mut t = samples[kmin][0];
        for _ in 0..20 {
            let q = rail.eval(t);
            let d1 = me.rotate_vec(q.d1)[1];
            let d2 = me.rotate_vec(q.d2)[1];
            if d2 <= 0.0 {
                break;
            }
            let step = d1 / d2;
            t -= step;
            if step.abs() < 1e-15 {
                break;
            }
        }
        let (lo, hi) = rail.spline().range();
        t = t.clamp(lo, hi);
        let ztop = me.rotate(rail.eval(t).p)[1].min(rot(&samples[kmin])[1]);
        me.offset[1] = -ztop;
        // Gauge point: walk from the top towards the gauge side (decreasing t) while
        // z <= h_g, tracking the smallest y; the crossing of z = h_g refined by bisection.
        let hg = track.gauge_height;
        let depth = |p: [f64; 2]| me.rotate(p)[1] + me.offset[1];
        let mut ymin = f64::INFINITY;
        let mut crossed = false;
        let mut deepest = 0.0f64;
        for k in (0..=kmin).rev() {
            let p = [samples[k][1], samples[k][2]];
            let d = depth(p);
            if d > hg {
                // Crossing between samples k and k + 1.
                let (mut a, mut b) = (samples[k][0], samples[k + 1][0]);
                for _ in 0..80 {
                    let m = 0.5 * (a + b);
                    if depth(rail.eval(m).p) > hg {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                let yc = me.rotate(rail.eval(b).p)[0];
                ymin = ymin.min(yc);
                crossed = true;
                break;
            }
            deepest = deepest.max(d);
            ymin = ymin.min(me.rotate(p)[0]);
        }
        if !crossed {
            return Err(Error::Placement {
                what: format!(
                    "the rail profile {} has no gauge face at the gauge height: on its track-centre side (small y) it reaches only {deepest:.4e} m below its top, the gauge height is {hg:.4e} m",
                    rail.name()
                ),
                hint: "lower gauge_height, give the whole rail head, or mirror the profile's y if its gauge face is on the other side".to_string(),
            });
        }
        me.offset[0] = 0.5 * track.gauge - ymin;
        Ok(me)
    }

    /// The rail of `track` at a known offset (from [`PlacedRail::new`]).
    pub fn with_offset(track: &'a Track, offset: [f64; 2]) -> Self {
        Self { profile: &track.rail, c: track.cant.cos(), s: track.cant.sin(), offset }
    }

    fn rotate(&self, p: [f64; 2]) -> [f64; 2] {
        [self.c * p[0] + self.s * p[1], -self.s * p[0] + self.c * p[1]]
    }

    fn rotate_vec(&self, v: [f64; 2]) -> [f64; 2] {
        self.rotate(v)
    }

    /// The placed rail at parameter $t$: point, tangent and second derivative (track $y, z$).
    pub fn at(&self, t: f64) -> ([f64; 2], [f64; 2], [f64; 2]) {
        let q = self.profile.eval(t);
        let p = self.rotate(q.p);
        (
            [p[0] + self.offset[0], p[1] + self.offset[1]],
            self.rotate_vec(q.d1),
            self.rotate_vec(q.d2),
        )
    }

    /// A track point $(y, z)$ in the rail profile's own coordinates.
    pub fn to_profile(&self, p: [f64; 2]) -> [f64; 2] {
        let (y, z) = (p[0] - self.offset[0], p[1] - self.offset[1]);
        [self.c * y - self.s * z, self.s * y + self.c * z]
    }

    /// The placed dense samples $(t, y, z)$.
    pub fn samples(&self) -> Vec<[f64; 3]> {
        self.profile
            .samples()
            .iter()
            .map(|s| {
                let p = self.rotate([s[1], s[2]]);
                [s[0], p[0] + self.offset[0], p[1] + self.offset[1]]
            })
            .collect()
    }
}

/// The wheel placed on the right side for one wheelset position (module docs).
#[derive(Debug, Clone)]
pub(crate) struct PlacedWheel<'a> {
    pub profile: &'a Profile,
    pub r0: f64,
    pub y_off: f64,
    pub centre: Vector3<f64>,
    pub rot: Matrix3<f64>,
}

/// A point of the wheel surface with its derivatives in $t$ and $\theta$.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WheelPoint {
    pub w: Vector3<f64>,
    pub dt: Vector3<f64>,
    pub dtheta: Vector3<f64>,
    /// Radius $\rho$ at $t$.
    pub rho: f64,
}

impl<'a> PlacedWheel<'a> {
    /// The wheel of `ws` at the right-side position `pos` and height `z_ws`.
    pub fn new(ws: &'a Wheelset, pos: &Position, z_ws: f64) -> Self {
        let rot = Rotation3::from_axis_angle(&Vector3::x_axis(), pos.roll)
            * Rotation3::from_axis_angle(&Vector3::z_axis(), pos.yaw);
        Self {
            profile: &ws.wheel,
            r0: ws.wheel_radius,
            y_off: 0.5 * ws.flange_back_distance - ws.flange_back_position,
            centre: Vector3::new(0.0, pos.lateral, z_ws - ws.wheel_radius),
            rot: *rot.matrix(),
        }
    }

    /// The same wheel moved to height `z_ws`.
    pub fn at_height(&self, z_ws: f64) -> Self {
        let mut w = self.clone();
        w.centre.z = z_ws - self.r0;
        w
    }

    /// The surface point at $(t, \theta)$ and its derivatives.
    pub fn point(&self, t: f64, theta: f64) -> WheelPoint {
        let q = self.profile.eval(t);
        let rho = self.r0 + q.p[1];
        let (s, c) = theta.sin_cos();
        let p = Vector3::new(rho * s, self.y_off + q.p[0], rho * c);
        let dp_t = Vector3::new(q.d1[1] * s, q.d1[0], q.d1[1] * c);
        let dp_th = Vector3::new(rho * c, 0.0, -rho * s);
        WheelPoint {
            w: self.centre + self.rot * p,
            dt: self.rot * dp_t,
            dtheta: self.rot * dp_th,
            rho,
        }
    }

    /// The lowest point (largest $z$) of the wheel's circle at profile parameter $t$:
    /// $\theta^* = \operatorname{atan2}(R_{zx}, R_{zz})$. Returns $\theta^*$ and the point.
    pub fn lowest(&self, t: f64) -> (f64, Vector3<f64>) {
        let r = &self.rot;
        let theta = r[(2, 0)].atan2(r[(2, 2)]);
        (theta, self.point(t, theta).w)
    }
}

//! A body rolling without slipping on the floor y = 0: the small model that decides the prose
//! claims of Appendix A about rolling (before (42), secs. A.2, A.4 and A.5), which are about
//! bodies other than the ladder.
//!
//! The body is a rim (a circle or an ellipse, centred at the body frame's origin) carrying point
//! masses. At orientation φ (cos φ, sin φ rational, from t = tan(φ/2)) it touches the floor at
//! the rim point whose outward normal points down, R(−φ)(0, −1) = (−sin φ, −cos φ) in the body
//! frame. Rolling without slipping means the body's material point at the contact is at rest, so
//! every particle moves as v_i = ω ẑ × (x_i − x_P). The contact point P itself (on the floor)
//! moves with v_P = R(φ) dp/dt, p being the contact in the body frame: that rate, and every
//! acceleration, comes from automatic differentiation of these state functions along the motion
//! (cos φ → cos φ − sin φ ω ε, sin φ → sin φ + cos φ ω ε, ω → ω + ω̇ ε), never transcribed.
//!
//! The ellipse's contact point needs a square root (its support function); it is taken exactly,
//! so only orientations where it is rational are used ([`RollingBody::at`] returns `None`
//! elsewhere). Everything is exact rational arithmetic: a claim holds or fails with zero residual.

use crate::scalar::{Jet, Rational, Scalar};
use crate::system::{rate, Particle, Point, System};
use crate::vector::{sum, Vec3};
use num_traits::{Signed, Zero};

type Q = Rational;

/// A fraction n/d, the way the model's data are given (so they embed in any scalar type).
pub type Frac = (i64, i64);

/// A number type with an exact square root where one exists.
pub trait Root: Scalar {
    /// √self, or `None` when it is not in the type (or self ≤ 0).
    fn root(&self) -> Option<Self>;
}

impl Root for Q {
    fn root(&self) -> Option<Q> {
        if !self.is_positive() {
            return None;
        }
        let (n, d) = (self.numer().sqrt(), self.denom().sqrt());
        (&n * &n == self.numer().0 && &d * &d == self.denom().0).then(|| Q::new(n.into(), d.into()))
    }
}

impl<T: Root> Root for Jet<T> {
    /// √(a + a′ε) = √a + a′/(2√a) ε: the derivative rule of the square root.
    fn root(&self) -> Option<Self> {
        let r = self.re.root()?;
        let eps = self.eps.clone() / (T::int(2) * r.clone());
        Some(Jet::new(r, eps))
    }
}

/// The rim the body rolls on, centred at the body frame's origin.
#[derive(Clone, Copy, Debug)]
pub enum Rim {
    /// A circle of radius R.
    Circle(Frac),
    /// An ellipse with semi-axes a (along x) and b (along y).
    Ellipse(Frac, Frac),
}

impl Rim {
    /// The rim point whose outward unit normal is n: R n on a circle; (a² n_x, b² n_y)/h on an
    /// ellipse, h = √(a² n_x² + b² n_y²) its support function.
    pub fn support<T: Root>(&self, n: [T; 2]) -> Option<[T; 2]> {
        let [nx, ny] = n;
        match *self {
            Rim::Circle((r, d)) => Some([nx * T::ratio(r, d), ny * T::ratio(r, d)]),
            Rim::Ellipse((a, ad), (b, bd)) => {
                let (a2, b2) = (T::ratio(a * a, ad * ad), T::ratio(b * b, bd * bd));
                let h = (a2.clone() * nx.clone() * nx.clone()
                    + b2.clone() * ny.clone() * ny.clone())
                .root()?;
                Some([a2 * nx / h.clone(), b2 * ny / h])
            }
        }
    }
}

/// A rigid body: a rim and point masses (mass, body-frame position).
#[derive(Clone, Debug)]
pub struct RollingBody {
    /// The rim it rolls on.
    pub rim: Rim,
    /// The particles: mass and position in the body frame.
    pub particles: Vec<(Frac, [Frac; 2])>,
}

/// Positions relative to the contact, x_i − x_P, the particles' velocities and the contact's
/// velocity v_P, as functions of the state (cos φ, sin φ, ω).
struct Kinematics<T> {
    rel: Vec<Vec3<T>>,
    v: Vec<Vec3<T>>,
    v_p: Vec3<T>,
    dp: [T; 2],
}

/// The state (cos φ, sin φ, ω) lifted along the motion with angular acceleration ω̇.
fn lift_state<T: Scalar>(c: &T, s: &T, w: &T, wd: &T) -> [T::Dual; 3] {
    [
        T::lift(c.clone(), -(s.clone() * w.clone())),
        T::lift(s.clone(), c.clone() * w.clone()),
        T::lift(w.clone(), wd.clone()),
    ]
}

/// R(φ) v.
fn rotate<T: Scalar>(c: &T, s: &T, v: &[T; 2]) -> Vec3<T> {
    Vec3::planar(
        c.clone() * v[0].clone() - s.clone() * v[1].clone(),
        s.clone() * v[0].clone() + c.clone() * v[1].clone(),
    )
}

impl RollingBody {
    /// The contact in the body frame: the rim point with outward normal (−sin φ, −cos φ).
    pub fn contact_in_body<T: Root>(&self, c: &T, s: &T) -> Option<[T; 2]> {
        self.rim.support([-s.clone(), -c.clone()])
    }

    fn kinematics<T>(&self, c: &T, s: &T, w: &T) -> Option<Kinematics<T>>
    where
        T: Root,
        T::Dual: Root,
    {
        let p = self.contact_in_body(c, s)?;
        // dp/dt along the motion (ω̇ does not enter a first derivative of p(φ)).
        let [c1, s1, _] = lift_state(c, s, w, &T::int(0));
        let p1 = self.contact_in_body(&c1, &s1)?;
        let dp = [T::split(p1[0].clone()).1, T::split(p1[1].clone()).1];
        let z = Vec3::along_z(w.clone());
        let rel: Vec<Vec3<T>> = self
            .particles
            .iter()
            .map(|(_, q)| {
                let q = [T::ratio(q[0].0, q[0].1), T::ratio(q[1].0, q[1].1)];
                rotate(
                    c,
                    s,
                    &[q[0].clone() - p[0].clone(), q[1].clone() - p[1].clone()],
                )
            })
            .collect();
        let v = rel.iter().map(|r| z.cross(r)).collect();
        Some(Kinematics {
            rel,
            v,
            v_p: rotate(c, s, &dp),
            dp,
        })
    }

    /// The body at orientation t = tan(φ/2) with angular velocity ω and acceleration ω̇, the
    /// contact at the origin: `None` where the ellipse's support function is irrational.
    pub fn at(&self, t: &Q, omega: &Q, omega_dot: &Q) -> Option<Instant> {
        let den = Q::int(1) + t * t;
        let (c, s) = ((Q::int(1) - t * t) / den.clone(), Q::int(2) * t / den);
        let k = self.kinematics(&c, &s, omega)?;
        let [c1, s1, w1] = lift_state(&c, &s, omega, omega_dot);
        let k1 = self.kinematics(&c1, &s1, &w1)?;
        let particles = self
            .particles
            .iter()
            .enumerate()
            .map(|(i, ((m, d), _))| Particle {
                m: Q::ratio(*m, *d),
                x: k.rel[i].clone(),
                v: k.v[i].clone(),
                a: Vec3::<Q>::derivative_of(&k1.v[i]),
                // The jerk enters no quantity used here.
                j: Vec3::zero(),
            })
            .collect();
        let [dpx, dpy] = k.dp;
        let contact = Point {
            x: Vec3::zero(),
            v: k.v_p,
            a: Vec3::<Q>::derivative_of(&k1.v_p),
            j: Vec3::zero(),
        };
        let sys = System {
            particles,
            spin: None,
        };
        Some(Instant {
            sys,
            contact,
            omega: omega.clone(),
            omega_dot: omega_dot.clone(),
            body_contact_rate: Vec3::planar(dpx, dpy),
        })
    }
}

/// The rolling body at one instant.
#[derive(Clone, Debug)]
pub struct Instant {
    /// The particles, with velocities and accelerations of the rolling motion.
    pub sys: System<Q>,
    /// The contact point P on the floor, with its velocity and acceleration.
    pub contact: Point<Q>,
    /// ω.
    pub omega: Q,
    /// ω̇.
    pub omega_dot: Q,
    /// dp/dt, the rate at which the contact moves over the body (in the body frame).
    pub body_contact_rate: Vec3<Q>,
}

/// Gravity, (0, −g) with g = 10.
fn gravity() -> Vec3<Q> {
    Vec3::planar(Q::int(0), Q::int(-10))
}

impl Instant {
    /// The contact force F_P that the motion requires: m a_cm = F_P + m g.
    pub fn contact_force(&self) -> Vec3<Q> {
        let m = self.sys.total_mass();
        self.sys.cm_acceleration().scale(&m) - gravity().scale(&m)
    }
    /// Eq. (36): τ_P, the torque of the external forces (gravity on each particle, F_P at P)
    /// about the contact P.
    pub fn tau_p(&self) -> Q {
        let x_p = &self.contact.x;
        let g = sum(self
            .sys
            .particles
            .iter()
            .map(|q| (q.x.clone() - x_p.clone()).cross(&gravity().scale(&q.m))));
        (g + (x_p.clone() - x_p.clone()).cross(&self.contact_force())).z
    }
    /// Eq. (41), the law of motion: dL_cm/dt − τ_cm, τ_cm the torque of F_P about the centre
    /// of mass (gravity has none). Zero exactly on the motion.
    pub fn spin_law_residual(&self) -> Q {
        let d_l = rate::<Q>(self.sys.along_motion().spin_angular_momentum().z);
        let r = self.contact.x.clone() - self.sys.centre_of_mass();
        d_l - r.cross(&self.contact_force()).z
    }
    /// I_P, the moment of inertia about the contact.
    pub fn i_p(&self) -> Q {
        self.sys.moment_of_inertia_about(&self.contact.x)
    }
    /// Hu's equation I_P ω̇ = τ_P (sec. A.5): I_P ω̇ − τ_P.
    pub fn hu_residual(&self) -> Q {
        self.i_p() * self.omega_dot.clone() - self.tau_p()
    }
    /// (dL_P/dt, d(I_P ω)/dt) by automatic differentiation, P the moving contact.
    pub fn rates(&self) -> (Q, Q) {
        let (sys, p) = (self.sys.along_motion(), self.contact.along_motion());
        let l_p = rate::<Q>(sys.angular_momentum_about(&p).z);
        let w = Q::lift(self.omega.clone(), self.omega_dot.clone());
        (l_p, rate::<Q>(sys.moment_of_inertia_about(&p.x) * w))
    }
    /// The precise condition: the centre of mass on the contact normal through P (the vertical
    /// through P, the floor being horizontal).
    pub fn cm_on_contact_normal(&self) -> bool {
        (self.sys.centre_of_mass() - self.contact.x.clone())
            .x
            .is_zero()
    }
}

/// The instant of `body` at orientation t and angular velocity ω on its motion: ω̇ solved from
/// the law (41), which is affine in ω̇ (`None` off the exact orientations or if degenerate).
pub fn on_motion(body: &RollingBody, t: &Q, omega: &Q) -> Option<Instant> {
    let r0 = body.at(t, omega, &Q::int(0))?.spin_law_residual();
    let r1 = body.at(t, omega, &Q::int(1))?.spin_law_residual();
    let slope = r1 - r0.clone();
    (!slope.is_zero()).then(|| body.at(t, omega, &(-r0 / slope)))?
}

/// A disk of radius 2 with four unit masses at (±1, 0), (0, ±1) about its centre, and a mass 2
/// at (e, 0): the centre of mass is at (e/3, 0), on the x axis, its symmetry axis.
pub fn disk(e: Frac) -> RollingBody {
    let mut particles = vec![
        ((1, 1), [(1, 1), (0, 1)]),
        ((1, 1), [(-1, 1), (0, 1)]),
        ((1, 1), [(0, 1), (1, 1)]),
        ((1, 1), [(0, 1), (-1, 1)]),
    ];
    particles.push(((2, 1), [e, (0, 1)]));
    RollingBody {
        rim: Rim::Circle((2, 1)),
        particles,
    }
}

/// An elliptic cylinder, semi-axes 4 and 5/4, with unit masses at (±1, 0) and (0, ±1/2): the
/// centre of mass at the centre, both axes symmetry axes. Its support function is rational at
/// t = 0, 1 (the vertices) and t = ±1/3, ±3 (normals (±3/5, ±4/5)).
pub fn elliptic_cylinder() -> RollingBody {
    RollingBody {
        rim: Rim::Ellipse((4, 1), (5, 4)),
        particles: vec![
            ((1, 1), [(1, 1), (0, 1)]),
            ((1, 1), [(-1, 1), (0, 1)]),
            ((1, 1), [(0, 1), (1, 2)]),
            ((1, 1), [(0, 1), (-1, 2)]),
        ],
    }
}

//! Systems of particles and reference points: Appendix A, eqs. (29)-(41), in full generality.
//!
//! A [`System`] is any number of particles, each with mass, position, velocity, acceleration and
//! jerk; the force on particle i is `F_i = m_i a_i` (eq. 29), so every identity here is a
//! statement about kinematics and can be checked at arbitrary random states. A [`Point`] is a
//! reference point P with its own motion (position, velocity, acceleration, jerk): fixed in the
//! lab, moving, or riding on the centre of mass.
//!
//! Time derivatives are never written out: [`System::along_motion`] lifts every quantity q to
//! `q + q̇ ε` (x → x + v ε, v → v + a ε, a → a + j ε) and the ε part of any function of the lifted
//! state is its rate of change along the motion.

use crate::scalar::Scalar;
use crate::vector::{sum, Vec3};

/// One particle of a system: mass and motion.
#[derive(Clone, Debug)]
pub struct Particle<T> {
    /// Mass m_i (constant in time).
    pub m: T,
    /// Position x_i.
    pub x: Vec3<T>,
    /// Velocity v_i = dx_i/dt.
    pub v: Vec3<T>,
    /// Acceleration a_i = dv_i/dt.
    pub a: Vec3<T>,
    /// Jerk da_i/dt (needed only to differentiate forces).
    pub j: Vec3<T>,
}

impl<T: Scalar> Particle<T> {
    /// Eq. (29): the force on the particle, F_i = m_i a_i = dp_i/dt.
    pub fn force(&self) -> Vec3<T> {
        self.a.scale(&self.m)
    }
    /// Eq. (29): the momentum p_i = m_i v_i.
    pub fn momentum(&self) -> Vec3<T> {
        self.v.scale(&self.m)
    }
    /// The particle with every quantity lifted along its motion.
    pub fn along_motion(&self) -> Particle<T::Dual> {
        Particle {
            m: T::constant(self.m.clone()),
            x: self.x.lift(&self.v),
            v: self.v.lift(&self.a),
            a: self.a.lift(&self.j),
            j: self.j.constant(),
        }
    }
}

/// A reference point P and its motion in the lab frame.
#[derive(Clone, Debug)]
pub struct Point<T> {
    /// x_P.
    pub x: Vec3<T>,
    /// v_P.
    pub v: Vec3<T>,
    /// a_P.
    pub a: Vec3<T>,
    /// da_P/dt.
    pub j: Vec3<T>,
}

impl<T: Scalar> Point<T> {
    /// A point at rest at `x`.
    pub fn fixed(x: Vec3<T>) -> Self {
        Point {
            x,
            v: Vec3::zero(),
            a: Vec3::zero(),
            j: Vec3::zero(),
        }
    }
    /// The point lifted along its motion.
    pub fn along_motion(&self) -> Point<T::Dual> {
        Point {
            x: self.x.lift(&self.v),
            v: self.v.lift(&self.a),
            a: self.a.lift(&self.j),
            j: self.j.constant(),
        }
    }
}

/// A planar rigid motion about the z axis, when the system has one (used by eqs. (42), (58)).
#[derive(Clone, Debug)]
pub struct Spin<T> {
    /// Angular velocity ω (along ẑ).
    pub omega: T,
    /// Angular acceleration ω̇.
    pub omega_dot: T,
}

/// A system of particles (eq. 32).
#[derive(Clone, Debug)]
pub struct System<T> {
    /// The particles.
    pub particles: Vec<Particle<T>>,
    /// Present when the particles move as one planar rigid body spinning about ẑ.
    pub spin: Option<Spin<T>>,
}

impl<T: Scalar> System<T> {
    /// The system with every quantity lifted along its motion (ω → ω + ω̇ ε as well).
    pub fn along_motion(&self) -> System<T::Dual> {
        System {
            particles: self.particles.iter().map(Particle::along_motion).collect(),
            spin: self.spin.as_ref().map(|s| Spin {
                omega: T::lift(s.omega.clone(), s.omega_dot.clone()),
                omega_dot: T::constant(s.omega_dot.clone()),
            }),
        }
    }

    fn weighted(&self, f: impl Fn(&Particle<T>) -> Vec3<T>) -> Vec3<T> {
        sum(self.particles.iter().map(|p| f(p).scale(&p.m)))
    }

    /// Eq. (32), (64): the total mass m = Σ m_i.
    pub fn total_mass(&self) -> T {
        self.particles
            .iter()
            .fold(T::int(0), |a, p| a + p.m.clone())
    }
    /// Eq. (32), (72): the centre of mass, m x_cm = Σ m_i x_i.
    pub fn centre_of_mass(&self) -> Vec3<T> {
        self.weighted(|p| p.x.clone()).div(&self.total_mass())
    }
    /// Eq. (32): the centre-of-mass velocity, m v_cm = Σ m_i v_i.
    pub fn cm_velocity(&self) -> Vec3<T> {
        self.momentum().div(&self.total_mass())
    }
    /// Eq. (32): the centre-of-mass acceleration, m a_cm = Σ m_i a_i.
    pub fn cm_acceleration(&self) -> Vec3<T> {
        self.weighted(|p| p.a.clone()).div(&self.total_mass())
    }
    /// The centre of mass as a moving point (position, velocity, acceleration, jerk).
    pub fn cm_point(&self) -> Point<T> {
        let m = self.total_mass();
        Point {
            x: self.centre_of_mass(),
            v: self.cm_velocity(),
            a: self.cm_acceleration(),
            j: self.weighted(|p| p.j.clone()).div(&m),
        }
    }
    /// Eq. (65): the total momentum P = Σ m_i v_i.
    pub fn momentum(&self) -> Vec3<T> {
        self.weighted(|p| p.v.clone())
    }
    /// Eq. (32), (67): the total force F = Σ F_i.
    pub fn total_force(&self) -> Vec3<T> {
        sum(self.particles.iter().map(Particle::force))
    }
    /// Eq. (30), (33), (66): the angular momentum about the origin, L = Σ x_i × m_i v_i.
    pub fn angular_momentum(&self) -> Vec3<T> {
        self.angular_momentum_about(&Point::fixed(Vec3::zero()))
    }
    /// Eq. (34): the spin angular momentum L_cm = Σ m_i (x_i − x_cm) × (v_i − v_cm).
    pub fn spin_angular_momentum(&self) -> Vec3<T> {
        self.relative_angular_momentum_about(&self.cm_point())
    }
    /// Eq. (37), (77): L_P = Σ (x_i − x_P) × m_i v_i, which ignores the motion of P.
    pub fn angular_momentum_about(&self, p: &Point<T>) -> Vec3<T> {
        sum(self
            .particles
            .iter()
            .map(|q| (q.x.clone() - p.x.clone()).cross(&q.momentum())))
    }
    /// Eq. (39): L'_P = Σ (x_i − x_P) × m_i (v_i − v_P), relative to the moving point P.
    pub fn relative_angular_momentum_about(&self, p: &Point<T>) -> Vec3<T> {
        sum(self
            .particles
            .iter()
            .map(|q| (q.x.clone() - p.x.clone()).cross(&(q.v.clone() - p.v.clone()).scale(&q.m))))
    }
    /// Eq. (35), (68): the torque about the origin, τ = Σ x_i × F_i.
    pub fn torque(&self) -> Vec3<T> {
        self.torque_about(&Vec3::zero())
    }
    /// Eq. (36): the torque about the point at `x_p`, τ_P = Σ (x_i − x_P) × F_i.
    pub fn torque_about(&self, x_p: &Vec3<T>) -> Vec3<T> {
        sum(self
            .particles
            .iter()
            .map(|q| (q.x.clone() - x_p.clone()).cross(&q.force())))
    }
    /// The moment of inertia about the z axis through `x_p`: Σ m_i |(x_i − x_P)⊥|².
    pub fn moment_of_inertia_about(&self, x_p: &Vec3<T>) -> T {
        self.particles.iter().fold(T::int(0), |acc, q| {
            let r = q.x.clone() - x_p.clone();
            acc + q.m.clone() * (r.x.clone() * r.x + r.y.clone() * r.y)
        })
    }
}

/// The rate of change along the motion of a lifted scalar: its ε part.
pub fn rate<T: Scalar>(q: T::Dual) -> T {
    T::split(q).1
}

/// The rate of change along the motion of a lifted vector.
pub fn rate_vec<T: Scalar>(q: &Vec3<T::Dual>) -> Vec3<T> {
    Vec3::derivative_of(q)
}

//! The closed form of the golfer's nemesis (note sec. B.10, Milne sec. 421), derived in
//! cylindrical coordinates, independently of the Cartesian model of [`super::model`].
//!
//! The centre moves on the cylinder r = ρ = b − a with angle φ and height z; e_r (= n), e_φ, ẑ
//! turn with φ (ė_r = φ̇ e_φ, ė_φ = −φ̇ e_r). Write ω = ω_r e_r + ω_φ e_φ + ω_z ẑ and the contact
//! force F = F_r e_r + F_φ e_φ + F_z ẑ, applied at a e_r from the centre.
//!
//! * Rolling: v + ω × (a e_r) = 0 with v = ρ φ̇ e_φ + ż ẑ and ω × e_r = ω_z e_φ − ω_φ ẑ, so
//!   ρ φ̇ = −a ω_z and ż = a ω_φ; ω_r is free.
//! * Newton, along e_φ and ẑ: m ρ φ̈ = F_φ, m z̈ = F_z − m g.
//! * Euler, I = k m a²: the torque a e_r × F = a F_φ ẑ − a F_z e_φ has no e_r part, and
//!   dω/dt = (ω̇_r − ω_φ φ̇) e_r + (ω̇_φ + ω_r φ̇) e_φ + ω̇_z ẑ. So
//!   ω̇_r = ω_φ φ̇,  I (ω̇_φ + ω_r φ̇) = −a F_z,  I ω̇_z = a F_φ.
//!
//! The ẑ parts with ω_z = −ρ φ̇/a give −(I/a) ρ φ̈ = a m ρ φ̈, so φ̈ = 0: **the orbit rate
//! φ̇ = Ω is constant**. The e_φ part with ω_φ = ż/a and F_z = m (z̈ + g) gives
//! (1 + k) z̈ = −g − k a Ω ω_r; differentiated, with ω̇_r = ż Ω/a,
//!
//! > d³z/dt³ = −(k/(1 + k)) Ω² dz/dt,
//!
//! so z is harmonic with **ω_z = Ω √(k/(1 + k))** (√(2/7) Ω for a solid ball, √(2/5) Ω for a
//! hollow one) about the centre z_c = z₀ + z̈₀/ω_z², z̈₀ = −(g + k a Ω ω_r₀)/(1 + k): whatever
//! g, a and b, the ball comes back up to its starting height and vertical velocity every
//! 2π/ω_z, with no net sinking; g and the spin about the normal only set how deep it dips.

use super::Setup;

/// The height of the ball's centre on the rolling motion from a start (sec. B.10): the harmonic
/// motion that the derivation in the module docs gives.
#[derive(Clone, Copy, Debug)]
pub struct ClosedForm {
    /// z₀, the starting height.
    pub z0: f64,
    /// ż₀, the starting vertical velocity.
    pub w0: f64,
    /// z_c, the centre of the oscillation.
    pub centre: f64,
    /// ω_z = Ω √(k/(1 + k)).
    pub omega_z: f64,
    /// Ω, the orbit rate (constant).
    pub orbit_rate: f64,
}

impl ClosedForm {
    /// The closed form for `setup` with the moment-of-inertia factor `k` (the ball's own, or
    /// another to show a wrong one fails).
    pub fn of(setup: &Setup, k: f64) -> ClosedForm {
        let omega = setup.orbit_rate;
        let omega_z = omega * (k / (1.0 + k)).sqrt();
        let accel0 = -(setup.g + k * setup.ball.a * omega * setup.normal_spin) / (1.0 + k);
        ClosedForm {
            z0: setup.z0,
            w0: setup.sink_rate,
            centre: setup.z0 + accel0 / (omega_z * omega_z),
            omega_z,
            orbit_rate: omega,
        }
    }

    /// z(t) = z_c + (z₀ − z_c) cos ω_z t + (ż₀/ω_z) sin ω_z t.
    pub fn height(&self, t: f64) -> f64 {
        let (s, c) = (self.omega_z * t).sin_cos();
        self.centre + (self.z0 - self.centre) * c + self.w0 / self.omega_z * s
    }

    /// The amplitude √((z₀ − z_c)² + (ż₀/ω_z)²).
    pub fn amplitude(&self) -> f64 {
        (self.z0 - self.centre).hypot(self.w0 / self.omega_z)
    }

    /// The lowest height, z_c − amplitude: finite, the ball does not sink for ever.
    pub fn lowest(&self) -> f64 {
        self.centre - self.amplitude()
    }

    /// The vertical period 2π/ω_z.
    pub fn period(&self) -> f64 {
        std::f64::consts::TAU / self.omega_z
    }
}

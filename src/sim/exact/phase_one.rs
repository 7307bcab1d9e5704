//! The both-contacts motion from a start (θ₀, θ̇₀): set-up, θ(t), θ̇(t), t(θ), separation.
//! Formulas and their conditioning are derived in the parent module's docs.
use super::carlson::{carlson_rf, omega_time, End};
use super::jacobi::{Agm, Arg};
use super::twofold::{cos_minus_ratio, two_prod};
use num_dual::DualNum;
use std::f64::consts::FRAC_PI_2;

/// Smallest resolvable distance from the unstable equilibrium: below it the squares s₀², ρ²
/// that carry the energy would leave the normal range of f64.
const MIN_OFFSET: f64 = 1e-140;

/// Largest θ̇₀/(2Ω) accepted, so that its square (and 1 + its square) stay finite. Any start
/// with θ̇₀ ≥ Ω separates at once anyway.
const MAX_RATE_RATIO: f64 = 1e140;

/// The moment the wall force (6) = m a_x of the note, with a_x from (8), first vanishes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Separation {
    /// θ_s, rad: cos θ_s = (2/3) cos θ₀ + θ̇₀²/(3Ω²) (footnote 4 of the note, moving start).
    pub angle: f64,
    /// t_s, s, from the start.
    pub time: f64,
    /// θ̇_s, rad/s: at separation θ̇_s² = Ω² cos θ_s.
    pub rate: f64,
}

/// The exact solution of eq. (5), θ̈ = Ω² sin θ, while the ladder touches wall and floor.
#[derive(Clone, Debug)]
pub struct PhaseOne {
    theta0: f64,
    rate0: f64,
    big_omega2: f64,
    big_omega: f64,
    /// sin(θ₀/2), cos(θ₀/2).
    s0: f64,
    c0: f64,
    /// ρ = θ̇₀/(2Ω), so that θ̇² = 4Ω²(sin²(θ/2) − a) with a = s₀² − ρ².
    rho: f64,
    orbit: Orbit,
    /// cos θ₀ − θ̇₀²/Ω² from the caller, formed from inputs this type does not see (the scene's
    /// SI values, `sim::start_margin`); None: formed here in double-double.
    margin: Option<f64>,
}

/// The three kinds of pendulum orbit (φ = π − θ), by the sign of a = s₀² − ρ².
#[derive(Clone, Debug)]
enum Orbit {
    /// θ₀ = θ̇₀ = 0: the ladder stands still.
    Equilibrium,
    /// a = 0: tan(θ/4) = tan(θ₀/4) e^{Ωt}.
    Separatrix { tan_quarter0: f64 },
    /// a ≠ 0: the phase u = u0 + phase_rate·t runs from the origin (the turning point if a > 0;
    /// θ = 0 if a < 0, `rotation`: the ladder passed upright) to the quarter period K, where
    /// θ = π; v = v0 − phase_rate·t = K − u.
    Elliptic {
        rotation: bool,
        kc: f64,
        k: f64,
        agm: Box<Agm>,
        u0: f64,
        v0: f64,
        phase_rate: f64,
    },
}

/// cos θ_s = (2/3) cos θ₀ + θ̇₀²/(3Ω²): where the wall force m l sin θ (Ω² cos θ − θ̇²) of
/// eqs. (5), (6), (8) and the energy integral vanishes (footnote 4 of the note, generalised to a
/// moving start). When it is ≥ cos θ₀ the wall force is already ≤ 0 at the start.
pub fn separation_cos(theta0: f64, rate0: f64, big_omega2: f64) -> f64 {
    (2.0 * theta0.cos() + rate0 * rate0 / big_omega2) / 3.0
}

/// θ₀ ∈ [0, π/2), θ̇₀ ≥ 0 and Ω² in [1e-100, 1e100], all finite.
fn check_start(theta0: f64, rate0: f64, big_omega2: f64) -> Result<(), String> {
    if !(theta0.is_finite() && (0.0..FRAC_PI_2).contains(&theta0)) {
        return Err(format!(
            "start angle theta0 = {theta0} rad is not in [0, pi/2)"
        ));
    }
    if !(rate0.is_finite() && rate0 >= 0.0) {
        return Err(format!(
            "start rate theta0_dot = {rate0} rad/s is not finite and >= 0"
        ));
    }
    if !(big_omega2.is_finite() && (1e-100..=1e100).contains(&big_omega2)) {
        return Err(format!(
            "big_omega^2 = 3g/(4l) = {big_omega2} 1/s^2 is not in [1e-100, 1e100]"
        ));
    }
    Ok(())
}

/// A start off the equilibrium that f64 can follow: ρ = θ̇₀/(2Ω) whose square does not
/// overflow, and (sin(θ₀/2), ρ) not within [`MIN_OFFSET`] of the unstable equilibrium.
fn check_resolvable(
    theta0: f64,
    rate0: f64,
    big_omega: f64,
    s0: f64,
    rho: f64,
) -> Result<(), String> {
    if rho > MAX_RATE_RATIO {
        return Err(format!(
            "start rate θ̇0/Ω = {} exceeds {MAX_RATE_RATIO:e}; its square \
             would overflow",
            rate0 / big_omega
        ));
    }
    if s0.max(rho) < MIN_OFFSET {
        return Err(format!(
            "start (theta0 = {theta0}, θ̇0/Ω = {}) lies within {MIN_OFFSET:e} of \
             the unstable equilibrium; f64 cannot resolve it",
            rate0 / big_omega
        ));
    }
    Ok(())
}

/// The orbit through a start off the equilibrium, (s0, c0) = (sin, cos)(θ₀/2) and
/// ρ = θ̇₀/(2Ω): the separatrix when s0² = ρ², else a libration or a rotation.
fn moving_orbit(theta0: f64, big_omega: f64, (s0, c0): (f64, f64), rho: f64) -> Orbit {
    // a = s0² − ρ² as a product: no cancellation beyond that of s0 − ρ itself.
    let a = (s0 - rho) * (s0 + rho);
    if a == 0.0 {
        Orbit::Separatrix {
            tan_quarter0: (0.25 * theta0).tan(),
        }
    } else {
        // e = 1 − a = c0² + ρ², a sum: k² for a libration, 1/k² for a rotation.
        let e = c0 * c0 + rho * rho;
        let rotation = a < 0.0;
        let (kc, k, k2) = if rotation {
            let h = (-a).sqrt();
            (h / e.sqrt(), 1.0 / e.sqrt(), 1.0 / e)
        } else {
            (a.sqrt(), e.sqrt(), e)
        };
        let agm = Box::new(Agm::new(kc, k2));
        let (u0, v0, phase_rate) = if rotation {
            // Phase w = (Ω/k)(time since θ = 0); origin-to-start and start-to-bottom parts.
            let h = (-a).sqrt();
            let u0 = e.sqrt() * s0 * carlson_rf(c0 * c0 * h * h, rho * rho, h * h);
            let v0 = c0 * e.sqrt() * carlson_rf(e * s0 * s0, e, rho * rho);
            (u0, v0, big_omega * e.sqrt())
        } else {
            // Phase u = Ω (time since the turning point sin(θ/2) = k').
            let u0 = rho * carlson_rf(kc * kc * e, s0 * s0 * e, kc * kc * c0 * c0);
            let v0 = c0 * carlson_rf(s0 * s0 * e, e, rho * rho);
            (u0, v0, big_omega)
        };
        Orbit::Elliptic {
            rotation,
            kc,
            k,
            agm,
            u0,
            v0,
            phase_rate,
        }
    }
}

impl PhaseOne {
    /// The motion from θ₀ ∈ [0, π/2), θ̇₀ ≥ 0 with Ω² = 3g/(4l) > 0 (eq. (5)).
    pub fn new(theta0: f64, rate0: f64, big_omega2: f64) -> Result<PhaseOne, String> {
        check_start(theta0, rate0, big_omega2)?;
        let big_omega = big_omega2.sqrt();
        let (s0, c0) = (0.5 * theta0).sin_cos();
        let rho = 0.5 * rate0 / big_omega;
        let orbit = if theta0 == 0.0 && rate0 == 0.0 {
            Orbit::Equilibrium
        } else {
            check_resolvable(theta0, rate0, big_omega, s0, rho)?;
            moving_orbit(theta0, big_omega, (s0, c0), rho)
        };
        Ok(PhaseOne {
            theta0,
            rate0,
            big_omega2,
            big_omega,
            s0,
            c0,
            rho,
            orbit,
            margin: None,
        })
    }

    /// The same motion with its start's wall-force factor D₀ = Ω² cos θ₀ − θ̇₀² given (in
    /// this motion's units), for a start whose θ̇₀ or Ω² reached this type rounded (a scene
    /// scaled to its own units, θ̇₀ √(l/g)): near the release push the separation depends on
    /// the start through D₀ alone, which those roundings would change by up to κ u relative
    /// (κ = Ω² cos θ₀ / D₀; `sim::near_release`).
    pub fn with_start_margin(mut self, margin: f64) -> PhaseOne {
        self.margin = Some(margin / self.big_omega2);
        self
    }

    /// The start angle θ₀, rad.
    pub fn theta0(&self) -> f64 {
        self.theta0
    }

    /// The start rate θ̇₀, rad/s.
    pub fn rate0(&self) -> f64 {
        self.rate0
    }

    /// The complete integral K(k) of the orbit's modulus (∞ on the separatrix, 0 at rest).
    pub fn quarter_period(&self) -> f64 {
        match &self.orbit {
            Orbit::Equilibrium => 0.0,
            Orbit::Separatrix { .. } => f64::INFINITY,
            Orbit::Elliptic { agm, .. } => agm.quarter_period(),
        }
    }

    /// First time the wall force vanishes (footnote 4 of the note, for a moving start); `None`
    /// at the equilibrium θ₀ = θ̇₀ = 0, where the ladder never moves. If the wall force is
    /// already ≤ 0 at the start (θ̇₀² ≥ Ω² cos θ₀) separation is immediate: t_s = 0.
    pub fn separation(&self) -> Option<Separation> {
        if let Orbit::Equilibrium = self.orbit {
            return None;
        }
        // cos θ₀ − θ̇₀²/Ω² in double-double: near immediate separation it is a small difference.
        let margin = self
            .margin
            .unwrap_or_else(|| cos_minus_ratio(self.theta0.cos(), self.rate0, self.big_omega2));
        if margin <= 0.0 || margin.is_nan() {
            let (angle, rate) = (self.theta0, self.rate0);
            return Some(Separation {
                angle,
                time: 0.0,
                rate,
            });
        }
        // sin²(θ_s/2) − sin²(θ₀/2) = (cos θ₀ − cos θ_s)/2 = margin/6, a positive number.
        let d = margin / 6.0;
        let ss2 = self.s0 * self.s0 + d;
        let (ss, cs) = (ss2.sqrt(), (1.0 - ss2).sqrt());
        let angle = 2.0 * ss.atan2(cs);
        let (q, q_lo) = two_prod(self.rate0, self.rate0);
        let cos_s = (2.0 * self.theta0.cos() + (q + q_lo) / self.big_omega2) / 3.0;
        let rate = (self.big_omega2 * cos_s).sqrt();
        let to = End {
            s: ss,
            c: cs,
            r: (d + self.rho * self.rho).sqrt(),
        };
        let time = omega_time(self.start(), to, d) / self.big_omega;
        Some(Separation { angle, time, rate })
    }

    /// Time from the start until the motion reaches θ (≥ θ₀; below θ₀ the negative time at
    /// which the rising motion passed θ, NaN below the turning point). t_s = t(θ_s).
    pub fn time_to_angle(&self, theta: f64) -> f64 {
        if let Orbit::Equilibrium = self.orbit {
            return if theta == 0.0 { 0.0 } else { f64::INFINITY };
        }
        let (s, c) = (0.5 * theta).sin_cos();
        // sin²(θ/2) − sin²(θ₀/2) = sin((θ − θ₀)/2) sin((θ + θ₀)/2): no cancellation.
        let d = (0.5 * (theta - self.theta0)).sin() * (0.5 * (theta + self.theta0)).sin();
        let to = End {
            s,
            c,
            r: (d + self.rho * self.rho).sqrt(),
        };
        omega_time(self.start(), to, d) / self.big_omega
    }

    /// θ(t), rad, on the both-contacts motion (valid for 0 ≤ t ≤ t_s; beyond it the formula
    /// continues the motion the wall no longer enforces, up to θ = π).
    pub fn theta(&self, t: f64) -> f64 {
        self.theta_rate(t).0
    }

    /// θ̇(t), rad/s, on the both-contacts motion (same range as [`PhaseOne::theta`]).
    pub fn rate(&self, t: f64) -> f64 {
        self.theta_rate(t).1
    }

    /// The wall force over m l at time t, F_w/(m l) = sin θ (Ω² cos θ − θ̇²): eq. (6) with a_x
    /// from (8) and θ̈ from (5). Positive (the wall pushes) on 0 < t < t_s, zero at t_s.
    pub fn wall_force_per_ml(&self, t: f64) -> f64 {
        let (theta, rate) = self.theta_rate(t);
        theta.sin() * (self.big_omega2 * theta.cos() - rate * rate)
    }

    /// (θ(t), θ̇(t)) with one evaluation of the Jacobi functions.
    pub fn theta_rate(&self, t: f64) -> (f64, f64) {
        self.theta_rate_dual(t)
    }

    /// (θ(t), θ̇(t)) for t an f64 or a dual number: derivatives with respect to t come along,
    /// which is how the tests check eq. (5) on this solution.
    pub fn theta_rate_dual<D: DualNum<Primitive = f64> + Copy>(&self, t: D) -> (D, D) {
        let big_omega = self.big_omega;
        match &self.orbit {
            Orbit::Equilibrium => (t * 0.0, t * 0.0),
            Orbit::Separatrix { tan_quarter0 } => {
                let theta = ((t * big_omega).exp() * *tan_quarter0).atan() * 4.0;
                (theta, (theta * 0.5).sin() * (2.0 * big_omega))
            }
            Orbit::Elliptic {
                rotation,
                kc,
                k,
                agm,
                u0,
                v0,
                phase_rate,
            } => {
                let (u, v) = (t * *phase_rate + *u0, -(t * *phase_rate) + *v0);
                // Evaluate from the nearer end of [0, K]: that argument is the accurate one.
                let j = agm.eval(if u.re() <= v.re() {
                    Arg::FromZero(u)
                } else {
                    Arg::FromQuarter(v)
                });
                let kc = D::from(*kc);
                if *rotation {
                    // sin(θ/2) = k' sd(u), cos(θ/2) = cd(u), θ̇ = 2Ω (k'/k)/dn(u).
                    let theta = (kc * j.sn).atan2(j.cn) * 2.0;
                    (theta, (kc / *k) / j.dn * (2.0 * big_omega))
                } else {
                    // sin(θ/2) = k'/dn(u), cos(θ/2) = k cn(u)/dn(u), θ̇ = 2Ω k k' sn(u)/dn(u).
                    let theta = kc.atan2(j.cn * *k) * 2.0;
                    (theta, kc * j.sn / j.dn * (2.0 * big_omega * k))
                }
            }
        }
    }

    /// The same motion with the complementary modulus k' multiplied by `factor`: a deliberately
    /// wrong closed form, for tests that must see their checks fail.
    #[doc(hidden)]
    pub fn with_modulus_factor(&self, factor: f64) -> PhaseOne {
        let mut wrong = self.clone();
        if let Orbit::Elliptic { kc, k, agm, .. } = &mut wrong.orbit {
            *kc *= factor;
            **agm = Agm::new(*kc, *k * *k);
        }
        wrong
    }

    fn start(&self) -> End {
        End {
            s: self.s0,
            c: self.c0,
            r: self.rho,
        }
    }
}

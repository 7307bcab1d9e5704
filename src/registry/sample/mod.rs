//! The random states every check is evaluated at, in floats and in exact integers.
//!
//! A float sample is drawn in plain f64 (what a user would compute with) and carried both as f64
//! and as [`Bound`], whose error bound gives the check its tolerance. An exact sample is a set of
//! random integers, turned into a state by the same generic builder in [`Rational`](crate::scalar::Rational) (to evaluate)
//! and in [`Degree`](crate::scalar::Degree) (to bound the degree for the Schwartz-Zippel lemma). Exact points on the
//! unit circle come from sin θ = 2t/(1+t²), cos θ = (1−t²)/(1+t²).

mod particles;

pub use particles::particle_system;

use crate::ladder::floor_phase::Slide;
use crate::ladder::{Ladder, State};
use crate::scalar::{Bound, Scalar};
use crate::system::{Point, System};
use rand::Rng;

/// The sorts of ladder state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LadderSample {
    /// Any θ, θ̇, θ̈: the identity must hold for all motions.
    Kinematic,
    /// θ̈ from (5), θ̇ free (any start, any energy).
    OnShell,
    /// θ̈ from (5) and θ̇² from (10): the note's start at rest upright.
    OnShellFromRest,
}

impl LadderSample {
    /// True for the on-shell sorts (checked also off shell, where they must fail).
    pub fn on_shell(self) -> bool {
        self != LadderSample::Kinematic
    }
}

/// The sorts of particle system and reference point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParticleSample {
    /// Any particles, any moving point P.
    General,
    /// P on the centre of mass at this instant and moving with it (v_P = v_cm; a_P free).
    PAtCm,
    /// P at rest (v_P = a_P = 0) somewhere.
    PFixed,
    /// P passing through the origin at this instant (x_P = 0), moving.
    PAtOrigin,
    /// The centre of mass at the origin at this instant and P riding on it (the Rust checks of
    /// (87), (88) compute L_cm as L_P with this P).
    CmAtOriginPAtCm,
    /// No total force: Σ m_i a_i = 0.
    ForceFree,
    /// No total torque about the origin: the particles' torques cancel in sum
    /// ([`crate::print::condition::torque_free`]).
    TorqueFree,
    /// A planar rigid body turning about the moving contact point P (rolling, eq. 42).
    RollingAboutP,
    /// A planar rigid body with spin ω, ω̇ (eq. 58); P at rest.
    PlanarRigid,
}

/// The states a display's print is evaluated at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrintSample {
    /// Ladder states of this sort.
    Ladder(LadderSample),
    /// Particle systems of this sort.
    Particles(ParticleSample),
}

/// A float ladder sample: as f64 and with error bounds.
pub type FloatLadder = ((Ladder<f64>, State<f64>), (Ladder<Bound>, State<Bound>));
/// A float particle sample: as f64 and with error bounds.
pub type FloatParticles = ((System<f64>, Point<f64>), (System<Bound>, Point<Bound>));

/// Number of random f64 draws a ladder sample uses.
pub const LADDER_DRAWS: usize = 7;
/// Number of random values a particle sample uses per particle and for the rest.
pub const PER_PARTICLE: usize = 13;
/// Values after the particles: P's motion (12) and ω, ω̇ (2).
pub const EXTRA: usize = 14;

/// Raw random inputs of a float ladder sample: θ ∈ [0, π/2), m, l, g > 0, and three numbers in
/// [−1, 1] that scale θ̇, θ̈, θ⃛ to the ladder's own time scale √(l/g).
#[derive(Clone, Debug)]
pub struct RawLadder {
    /// θ, rad.
    pub theta: f64,
    /// m, l, g.
    pub mlg: [f64; 3],
    /// Unit-free rate, acceleration and jerk.
    pub unit: [f64; 3],
}

impl RawLadder {
    /// Draw one: m, l, g log-uniform over [1e-6, 1e6].
    pub fn draw(rng: &mut impl Rng) -> Self {
        let mut logu = || 10f64.powf(rng.gen_range(-6.0..6.0));
        let mlg = [logu(), logu(), logu()];
        RawLadder {
            theta: rng.gen_range(0.0..std::f64::consts::FRAC_PI_2),
            mlg,
            unit: [
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
            ],
        }
    }

    /// The state in f64 and with error bounds (same values).
    pub fn build(&self, sort: LadderSample) -> FloatLadder {
        let [m, l, g] = self.mlg;
        let rate_unit = (g / l).sqrt();
        let (s, c) = self.theta.sin_cos();
        let rate = match sort {
            // θ̇² = (3g/2l)(1 − cos θ) = (3g/l) sin²(θ/2): no cancellation near θ = 0.
            LadderSample::OnShellFromRest => (3.0 * g / l).sqrt() * (self.theta / 2.0).sin(),
            _ => 3.0 * self.unit[0] * rate_unit,
        };
        let accel = 3.0 * self.unit[1] * g / l;
        let jerk = 3.0 * self.unit[2] * (g / l) * rate_unit;
        // libm's sin, cos and sqrt are within one ulp (two roundoffs); θ̇ from rest is a product
        // of three such results.
        let float = float_state(sort, [m, l, g], [s, c, rate, accel, jerk], |x, _| x);
        let bound = float_state(sort, [m, l, g], [s, c, rate, accel, jerk], Bound::inexact);
        let rate_units = if sort == LadderSample::OnShellFromRest {
            7.0
        } else {
            0.0
        };
        let mut bound = bound;
        bound.1.rate = Bound::inexact(rate, rate_units);
        (float, bound)
    }
}

/// The floor phase's centre motion (X, Ẋ, Ẍ, X⃛) from four unit-free draws in [−1, 1), each
/// scaled by the ladder's own length and time, l and √(l/g), as [`RawLadder::build`] scales θ̇,
/// θ̈, θ⃛ (times 3): X is of the size of the ladder and its rates those of its fall, at any scale
/// of m, l, g.
pub fn floor_motion(unit: [f64; 4], l: f64, g: f64) -> [f64; 4] {
    let t = (l / g).sqrt();
    let scale = [l, l / t, l / (t * t), l / (t * t * t)];
    std::array::from_fn(|i| 3.0 * unit[i] * scale[i])
}

fn float_state<S: Scalar>(
    sort: LadderSample,
    [m, l, g]: [f64; 3],
    [s, c, rate, accel, jerk]: [f64; 5],
    mk: impl Fn(f64, f64) -> S,
) -> (Ladder<S>, State<S>) {
    let ladder = Ladder {
        m: mk(m, 0.0),
        l: mk(l, 0.0),
        g: mk(g, 0.0),
    };
    let mut st = State {
        sin: mk(s, 2.0),
        cos: mk(c, 2.0),
        rate: mk(rate, 0.0),
        accel: mk(accel, 0.0),
        jerk: mk(jerk, 0.0),
    };
    if sort.on_shell() {
        st.accel = crate::ladder::energy::angular_acceleration(&ladder, &st);
    }
    (ladder, st)
}

/// Build an exact ladder state from seven random integers (t, m, l, g, θ̇, θ̈, θ⃛) given in any
/// scalar type. From rest upright, g is solved from the energy of the three-particle model (not
/// from the note's (9) or (10)) so that θ̇ stays rational: m g l = Σ m_i v_i²/2 + g Σ m_i y_i.
pub fn exact_ladder<S: Scalar>(sort: LadderSample, v: [S; LADDER_DRAWS]) -> (Ladder<S>, State<S>) {
    let [t, m, l, g, rate, accel, jerk] = v;
    let one = S::int(1);
    let den = one.clone() + t.clone() * t.clone();
    let sin = S::int(2) * t.clone() / den.clone();
    let cos = (one.clone() - t.clone() * t) / den;
    let mut st = State {
        sin,
        cos,
        rate,
        accel,
        jerk,
    };
    let g = match sort {
        LadderSample::OnShellFromRest => {
            let sys = crate::ladder::particles::as_system(
                &Ladder {
                    m: m.clone(),
                    l: l.clone(),
                    g: one,
                },
                &st,
            );
            let (kinetic, height) =
                sys.particles
                    .iter()
                    .fold((S::int(0), S::int(0)), |(k, h), p| {
                        (
                            k + p.m.clone() * p.v.dot(&p.v) / S::int(2),
                            h + p.m.clone() * p.x.y.clone(),
                        )
                    });
            kinetic / (m.clone() * l.clone() - height)
        }
        _ => g,
    };
    let ladder = Ladder { m, l, g };
    if sort.on_shell() {
        st.accel = crate::ladder::energy::angular_acceleration(&ladder, &st);
    }
    (ladder, st)
}

/// Raw random inputs of a particle sample: the number of particles and their values in order
/// (per particle: m, x, v, a, j; then P's x, v, a, j; then ω, ω̇).
#[derive(Clone, Debug)]
pub struct RawParticles {
    /// Number of particles, 1..=8.
    pub n: usize,
    /// `n·PER_PARTICLE + EXTRA` values.
    pub values: Vec<f64>,
}

impl RawParticles {
    /// Draw one: masses log-uniform over [1e-3, 1e3], everything else uniform in [−10, 10].
    pub fn draw(rng: &mut impl Rng) -> Self {
        let n = rng.gen_range(1..=8);
        let values = (0..n * PER_PARTICLE + EXTRA)
            .map(|i| {
                if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                    10f64.powf(rng.gen_range(-3.0..3.0))
                } else {
                    rng.gen_range(-10.0..10.0)
                }
            })
            .collect();
        RawParticles { n, values }
    }
}

/// The float sample of a raw particle draw, as f64 and with (zero) input error bounds.
pub fn float_particles(sort: ParticleSample, raw: &RawParticles) -> FloatParticles {
    let bounds: Vec<Bound> = raw.values.iter().map(|&v| Bound::exact(v)).collect();
    (
        particle_system(sort, raw.n, &raw.values),
        particle_system(sort, raw.n, &bounds),
    )
}

/// A floor-phase state from a ladder state and the centre's motion (X, Ẋ, Ẍ, X⃛), in any scalar
/// type. On shell, θ̈ comes from (P3) and Ẍ = X⃛ = 0 from (P2); the ladder state must have been
/// built as [`LadderSample::Kinematic`].
pub fn floor_state<S: Scalar>(
    sort: LadderSample,
    ladder: &Ladder<S>,
    st: State<S>,
    v: [S; 4],
) -> (State<S>, Slide<S>) {
    let [x, rate, accel, jerk] = v;
    let mut st = st;
    let mut slide = Slide {
        x,
        rate,
        accel,
        jerk,
    };
    if sort.on_shell() {
        st.accel = crate::ladder::floor_phase::angular_acceleration(ladder, &st);
        slide.accel = S::int(0);
        slide.jerk = S::int(0);
    }
    (st, slide)
}

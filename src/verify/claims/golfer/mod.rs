//! The note's last prose claim (sec. B.10): Milne's "golfer's nemesis" (Vectorial Mechanics
//! sec. 421), a sphere rolling without slipping inside a vertical cylinder oscillates vertically,
//! so that a golf ball could roll down into the cup and then back up and out.
//!
//! Decided on a 3-D model of its own, not on the ladder: a uniform ball (mass m, radius a,
//! I = k m a², k = 2/5 solid, 2/3 hollow) inside a fixed vertical cylinder of radius b > a under
//! gravity g. [`model`] writes the Newton-Euler equations in Cartesian vectors with the contact
//! force solved from the rolling constraint; [`run`] integrates them with the crate's DOP853
//! (verify, layer 7, may use the simulator's integrators, layer 4: ARCHITECTURE.md);
//! [`closed_form`] derives the motion in cylindrical coordinates (constant orbit rate, the height
//! harmonic with ω_z = Ω √(k/(1 + k))); [`compare`] holds the run to it within an error model
//! (the run repeated at 100 and 10⁴ times tighter tolerances).
//!
//! The claim holds when the golf ball's run (a solid ball, 42.67 mm across, in a cup 108 mm
//! across, orbiting at 20 rad/s and entering at 0.3 m/s downward) keeps its orbit rate, finds one
//! lowest point per vertical period, returns to its starting height and vertical velocity after
//! each period 2π/ω_z, and follows z(t) all the way, each within the integrator's estimated
//! error (which must shrink with the tolerance), with the rolling constraint's drift within it
//! too; and the same ball on a frictionless wall (no rolling:
//! z̈ = −g) does not come back. Not an erratum: the note states it correctly.

use super::Claim;
use crate::sim::integrators::StepError;

pub mod closed_form;
pub mod compare;
pub mod model;
pub mod run;

use closed_form::ClosedForm;
use compare::{rounding_floor, Judgement, Readings};
use model::{Contact, Cylinder, Perturbation};

/// k of a solid ball, I = (2/5) m a².
pub const SOLID: f64 = 2.0 / 5.0;
/// k of a thin hollow ball, I = (2/3) m a².
pub const HOLLOW: f64 = 2.0 / 3.0;
/// The tolerance of the claim's run.
pub const RTOL: f64 = 1e-10;
/// The vertical periods the claim's run covers.
pub const PERIODS: usize = 4;
/// The samples per period at which a run is read.
pub const PER_PERIOD: usize = 32;

/// A uniform ball: mass m, radius a, moment of inertia k m a² about a diameter.
#[derive(Clone, Copy, Debug)]
pub struct Ball {
    /// m.
    pub m: f64,
    /// a.
    pub a: f64,
    /// k.
    pub k: f64,
}

/// The ball, the cylinder, gravity and the start (sec. B.10): the centre at (b − a, 0, z₀)
/// orbiting at rate Ω, moving down at ż₀, spinning at ω_r₀ about the normal, rolling.
#[derive(Clone, Copy, Debug)]
pub struct Setup {
    /// The ball.
    pub ball: Ball,
    /// b, the cylinder's radius.
    pub b: f64,
    /// g.
    pub g: f64,
    /// Ω, the starting orbit rate φ̇.
    pub orbit_rate: f64,
    /// z₀.
    pub z0: f64,
    /// ż₀ (negative: moving down).
    pub sink_rate: f64,
    /// ω_r₀, the starting spin about the outward normal.
    pub normal_spin: f64,
}

impl Setup {
    /// The golfer's nemesis: a golf ball (m = 45.93 g, a = 21.335 mm, solid) in a cup of radius
    /// b = 54 mm, g = 9.81 m/s², orbiting at Ω = 20 rad/s and entering at ż₀ = −0.3 m/s.
    pub fn golf() -> Setup {
        Setup {
            ball: Ball {
                m: 0.04593,
                a: 0.021335,
                k: SOLID,
            },
            b: 0.054,
            g: 9.81,
            orbit_rate: 20.0,
            z0: 0.0,
            sink_rate: -0.3,
            normal_spin: 0.0,
        }
    }

    /// The starting state (x, v, ω): x = (ρ, 0, z₀), ρ = b − a, v = (0, ρ Ω, ż₀), and the ω
    /// that satisfies v + ω × (a x̂) = 0 with ω_x = ω_r₀: (ω_r₀, ż₀/a, −ρ Ω/a).
    pub fn start(&self) -> [f64; 9] {
        let (a, rho) = (self.ball.a, self.b - self.ball.a);
        let (o, w0) = (self.orbit_rate, self.sink_rate);
        [
            rho,
            0.0,
            self.z0,
            0.0,
            rho * o,
            w0,
            self.normal_spin,
            w0 / a,
            -rho * o / a,
        ]
    }

    /// ℓ = b + |ż₀|/Ω + g/Ω²: a length the motion's sizes are of the order of, from the data
    /// alone (the error norm's scale).
    pub fn length(&self) -> f64 {
        let o = self.orbit_rate;
        self.b + self.sink_rate.abs() / o + self.g / (o * o)
    }

    /// The model of this setup with the given contact and term.
    pub fn model(&self, contact: Contact, perturbation: Perturbation) -> Cylinder {
        let l = self.length();
        let (v, w) = (l * self.orbit_rate, l * self.orbit_rate / self.ball.a);
        Cylinder {
            ball: self.ball,
            g: self.g,
            contact,
            perturbation,
            scale: [l, l, l, v, v, v, w, w, w],
        }
    }
}

/// A run of `setup` with `contact` and `perturbation` at tolerance `rtol`, sampled
/// [`PER_PERIOD`] times per period (on the dense output; steps end on each multiple of the
/// period) over `periods` periods of the closed form with moment-of-inertia factor `k`, held to
/// that closed form: its readings, their deviations, the error estimates from the same run at
/// rtol/100 and rtol/10⁴, and the rounding floor.
pub fn hold(
    setup: &Setup,
    (contact, perturbation): (Contact, Perturbation),
    k: f64,
    rtol: f64,
    periods: usize,
) -> Result<Judgement, StepError> {
    let cf = ClosedForm::of(setup, k);
    let dt = cf.period() / PER_PERIOD as f64;
    let samples: Vec<f64> = (1..=periods * PER_PERIOD).map(|j| j as f64 * dt).collect();
    let model = setup.model(contact, perturbation);
    let integrate = |tol| run::integrate(&model, setup.start(), tol, &samples, PER_PERIOD);
    let runs = [
        integrate(rtol)?,
        integrate(rtol / 1e2)?,
        integrate(rtol / 1e4)?,
    ];
    let [r0, r1, r2] = runs.each_ref().map(|r| Readings::of(setup, r, PER_PERIOD));
    let end = samples.last().copied().unwrap_or(0.0);
    Ok(Judgement {
        deviation: r0.gaps(&Readings::closed_form(setup, &cf, periods, PER_PERIOD)),
        estimate: r0.gaps(&r1),
        next_estimate: r1.gaps(&r2),
        floor: rounding_floor(setup, runs.iter().map(|r| r.steps).sum(), end),
        readings: r0,
        steps: runs[0].steps,
    })
}

/// Whether the run of [`hold`] at [`RTOL`] over [`PERIODS`] periods agrees with the closed form
/// (an integration that fails does not).
pub fn agrees(setup: &Setup, run: (Contact, Perturbation), k: f64) -> bool {
    hold(setup, run, k, RTOL, PERIODS).is_ok_and(|j| j.agrees())
}

/// Claim 47, sec. B.10: the golf ball rolling in the cup comes back up; without rolling it
/// does not.
pub fn claims() -> Vec<Claim> {
    let golf = Setup::golf();
    let rolls_back = agrees(&golf, (Contact::Rolling, Perturbation::None), golf.ball.k);
    let slides_down = !agrees(
        &golf,
        (Contact::Frictionless, Perturbation::None),
        golf.ball.k,
    );
    vec![Claim::checked(
        "sec. B.10",
        "Milne's golfer's nemesis (his sec. 421): a ball rolling without slipping inside a vertical cylinder oscillates vertically, ω_z = Ω√(k/(1+k)) (√(2/7) Ω solid), and comes back up to its starting height (on a frictionless wall it sinks)",
        rolls_back && slides_down,
    )]
}

//! The penalty contact model: the ladder as a free rigid body in the plane, held by two
//! one-sided springs instead of two constraints. **An extension beyond the note**, which treats
//! the wall and the floor as rigid (sec. 2.1); this model is the stiff test problem of
//! `ladder stability`.
//!
//! # Physics
//! Generalised coordinates: the centre B = (x, y) and the angle θ from the wall. The ends are
//! C = B + l(−sin θ, cos θ) (top) and D = B + l(sin θ, −cos θ) (foot). The wall x = 0 pushes on
//! C when C is inside it, the floor y = 0 on D likewise:
//!
//! * penetrations p_w = −x_C = l sin θ − x and p_f = −y_D = l cos θ − y;
//! * contact forces F = max(0, k p + c ṗ) while p > 0, else 0: a spring and a dashpot that can
//!   push but never pull (the dashpot may not make the force negative on the way out);
//! * m ẍ = F_w, m ÿ = F_f − m g, (m l²/3) θ̈ = l sin θ F_f − l cos θ F_w (torques about B of
//!   the forces at D and C).
//!
//! With p = 0 and ṗ = 0 imposed, these are the note's equations (5), (14), (15). The
//! *separation* of this model is where the wall force falls through zero after being positive,
//! the note's definition for the rigid case (footnote 4).
//!
//! # Numerics
//! Everything runs in units of l, g and m (lengths / l, times / √(l/g), forces / (m g)), so
//! that m, l, g anywhere in 1e-30..1e30 change nothing but the scaling back; the model then
//! depends on the dimensionless stiffness κ = k l/(m g) and damping γ = c √(l/g)/m only.
//!
//! **Force coordinates.** At large κ the penetrations are tiny (p ~ 1/κ): written as
//! p_w = sin θ − x with x in the state, the force κ p is κ times a *difference* of O(1)
//! numbers, and the rounding of x alone (u = 1.1e-16) becomes a force error κ u, 1e-4 m g at
//! κ = 1e12 and 0.1 m g at 1e15: spurious zeros of the wall force, separation angles that
//! move by 1e-5 when κ moves by an ulp. So the state carries the spring forces themselves:
//! y = [θ, f_w, f_f, θ̇, v_w, v_f] with f = κ p (units of m g) and v = κ ṗ, and
//! v̇ = κ p̈ where p̈_w = cos θ θ̈ − sin θ θ̇² − F_w and p̈_f = −sin θ θ̈ − cos θ θ̇² − F_f + 1
//! (from m ẍ = F_w, m ÿ = F_f − m g). The forces are then held to their own relative
//! precision; x and y are recovered as sin θ − f_w/κ and cos θ − f_f/κ where needed (energy).
//! The rigid model is the limit p̈ = 0 of the same equations.
//!
//! The contact oscillates at ω_c ~ √κ (in units of √(g/l)) while the fall takes O(1): explicit
//! methods need h ≲ 1/√κ, an implicit L-stable method does not. Radau5 ends each step on its
//! last stage, where the stiff components are in equilibrium with the slow ones (stiff
//! accuracy): its error control holds the forces to the tolerance in units of m g (the contact
//! layer's own scale), and the separation time, where F_w falls through zero at a rate of O(1),
//! follows. The model's own distance to the rigid limit is O(1/κ).
//!
//! **The kink.** max(0, ·) has a kink where the force is zero. Inside the right-hand side
//! ([`Law::OneSided`]) every stage, Newton iterate and finite-difference probe near a tiny
//! penetration may land on the wrong side of it: Newton stalls and steps are rejected. Since
//! both forces stay positive throughout the wall phase and the run ends the moment the wall
//! force falls through zero, the default ([`Law::Switched`]) integrates the smooth two-sided
//! spring and lets an *event* find the zero of the force (event-driven integration of a
//! switched system); lift-off at the floor, were it to happen, is an event too.
//!
//! The start is *pre-loaded*: the penetrations and their rates are set to the rigid model's
//! forces divided by k (and their rate of change), so the springs start in equilibrium with the
//! motion and no contact oscillation of size m g is excited (from p = 0 the springs would
//! bounce and the wall force would reach zero at the first rebound).

pub mod confirm;
pub mod plan;
pub mod run;
pub mod start;

use super::integrators::Ode;
use super::penalty::start::slow_forces;
pub use super::penalty::start::OMEGA2;
use super::rigid::event_safe_step;

use crate::ladder::Ladder;
use num_dual::DualNum;
use std::cell::Cell;

/// Dimensionless stiffness accepted by scenes: below 1 the springs are not contacts, above 1e15
/// the rounding of positions alone makes the force meaningless (κ·u ≳ 0.1).
pub const KAPPA_RANGE: (f64, f64) = (1.0, 1e15);
/// Longest dimensionless time a penalty run may take (the fall takes O(1) to O(50)).
pub const T_END: f64 = 1e4;

thread_local! {
    static MODELS_BUILT: Cell<u64> = const { Cell::new(0) };
}

/// How many penalty models this thread has built (tests check that rigid scenes build none).
pub fn models_built() -> u64 {
    MODELS_BUILT.with(Cell::get)
}

/// The contact in dimensionless form: κ = k l/(m g), γ = c √(l/g)/m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// κ, stiffness in units of m g / l.
    pub kappa: f64,
    /// γ, damping in units of m √(g/l).
    pub gamma: f64,
}

impl Contact {
    /// The dimensionless contact of `ladder` with stiffness `k` (N/m) and damping `c` (N·s/m).
    /// Quotients are formed pairwise so that no intermediate product of extreme m, l, g, k
    /// overflows.
    pub fn from_dimensional(ladder: &Ladder<f64>, k: f64, c: f64) -> Contact {
        let (m, l, g) = (ladder.m, ladder.l, ladder.g);
        Contact {
            kappa: (k / m) * (l / g),
            gamma: (c / m) * (l / g).sqrt(),
        }
    }
}

/// A one-sided spring-dashpot in force units: max(0, f + (γ/κ) v) while f = κ p > 0, zero
/// otherwise. (The kinks are where the force is zero; num-dual differentiates the active branch.)
pub fn one_sided<D: DualNum<Primitive = f64> + Copy>(contact: &Contact, f: D, rate: D) -> D {
    if f.re() <= 0.0 {
        return D::zero();
    }
    let total = f + rate * (contact.gamma / contact.kappa);
    if total.re() > 0.0 {
        total
    } else {
        D::zero()
    }
}

/// How the one-sidedness of the contacts enters the integration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Law {
    /// Event-driven: while a contact holds it is a plain (two-sided) spring-dashpot
    /// κ p + γ ṗ, smooth, and the moment its force falls through zero is an event that ends the
    /// phase (separation at the wall; lift-off at the floor is reported as an error). The
    /// integrators never see the kink of max(0, ·). The default.
    Switched,
    /// The clipped law [`one_sided`] inside the right-hand side: the kink is seen by every
    /// stage, every Newton iterate and every finite-difference probe (kept for comparison).
    OneSided,
}

/// The contact forces (F_w along +x at C, F_f along +y at D), in units of m g, under `law`.
pub fn contact_forces<D: DualNum<Primitive = f64> + Copy>(
    contact: &Contact,
    law: Law,
    y: &[D; 6],
) -> (D, D) {
    let damp = contact.gamma / contact.kappa;
    match law {
        Law::Switched => (y[1] + y[4] * damp, y[2] + y[5] * damp),
        Law::OneSided => (
            one_sided(contact, y[1], y[4]),
            one_sided(contact, y[2], y[5]),
        ),
    }
}

/// Energy in units of m g l: ½(ẋ² + ẏ²) + ⅙ θ̇² + y + ½ κ (p_w² + p_f²) (springs while
/// compressed), with x, y and their rates recovered from θ and the spring forces. Conserved
/// when γ = 0: the blow-up detector of explicit methods.
pub fn energy(contact: &Contact, y: &[f64; 6]) -> f64 {
    let k = contact.kappa;
    let (s, c) = y[0].sin_cos();
    // ẋ = cos θ θ̇ − ṗ_w, ẏ = −sin θ θ̇ − ṗ_f, height of B = cos θ − p_f.
    let (vx, vy) = (c * y[3] - y[4] / k, -(s * y[3]) - y[5] / k);
    let (fw, ff) = (y[1].max(0.0), y[2].max(0.0));
    0.5 * (vx * vx + vy * vy) + y[3] * y[3] / 6.0 + (c - y[2] / k) + (fw * fw + ff * ff) / (2.0 * k)
}

/// The penalty model as an ODE, dimensionless, in force coordinates:
/// y = [θ, f_w, f_f, θ̇, v_w, v_f] with f = κ p, v = κ ṗ (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct PenaltyModel {
    /// The contact parameters.
    pub contact: Contact,
    /// How the contacts' one-sidedness is treated.
    pub law: Law,
}

impl PenaltyModel {
    /// Build the model (counted by [`models_built`]).
    pub fn new(contact: Contact, law: Law) -> Self {
        MODELS_BUILT.with(|c| c.set(c.get() + 1));
        PenaltyModel { contact, law }
    }
}

impl Ode<6> for PenaltyModel {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 6]) -> [D; 6] {
        let (fw, ff) = contact_forces(&self.contact, self.law, y);
        let (s, c) = y[0].sin_cos();
        // (m l²/3) θ̈ = l (sin θ F_f − cos θ F_w), with m = l = 1.
        let alpha = (s * ff - c * fw) * 3.0;
        let w2 = y[3] * y[3];
        let k = self.contact.kappa;
        // p̈_w = d²(sin θ − x)/dt² = cos θ θ̈ − sin θ θ̇² − F_w, p̈_f = −sin θ θ̈ − cos θ θ̇² − F_f + 1.
        let wall_acc = c * alpha - s * w2 - fw;
        let floor_acc = -(s * alpha) - c * w2 - ff + 1.0;
        [y[3], y[4], y[5], alpha, wall_acc * k, floor_acc * k]
    }
    fn max_step(&self, y: &[f64; 6]) -> f64 {
        event_safe_step(OMEGA2.sqrt(), y[3])
    }
    /// Absolute control in the problem's own units: θ against 1 rad, forces against m g, rates
    /// against Ω (θ̇ in √(g/l), force rates in m g √(g/l)): the force, whose zero is the
    /// separation, is held to the tolerance itself.
    fn scale(&self, _y: &[f64; 6]) -> [f64; 6] {
        let w = OMEGA2.sqrt();
        [1.0, 1.0, 1.0, w, w, w]
    }
    /// The force rates v = κ ṗ: in the stiff limit the forces are fixed by the motion (p̈ ≈ 0
    /// is algebraic in them) to their rounding u m g, so an implicit step of size h knows their
    /// rates only to u/h (the collocation polynomial's slope). At κ = 1e12 and tolerance 1e-12
    /// a fixed weight made radau5's estimate grow as h shrank and the step collapse (a hang);
    /// with the weight divided by h the estimate's rounding floor is ~4u/(Ω τ) at any h.
    fn index2(&self) -> [bool; 6] {
        [false, false, false, false, true, true]
    }
}

/// The pre-loaded start: the rigid start (θ0, θ̇0) with the springs on the contact's slow
/// manifold, their forces and rates those of [`slow_forces`] (κ p + γ ṗ = F, κ ṗ = Ḟ).
pub fn preloaded_start(contact: &Contact, theta0: f64, rate0: f64) -> [f64; 6] {
    let (force, rate) = slow_forces(contact.kappa, theta0, rate0);
    let damp = contact.gamma / contact.kappa;
    [
        theta0,
        force[0] - damp * rate[0],
        force[1] - damp * rate[1],
        rate0,
        rate[0],
        rate[1],
    ]
}

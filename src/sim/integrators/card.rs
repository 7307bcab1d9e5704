//! What each integrator declares about itself, in its own file: its [`Card`]. The list in
//! [`super`] gathers the cards into [`super::TABLE`], which feeds the scene checks (names,
//! controls), the plans of penalty scenes (stiffness, stability), `ladder work-precision` (its
//! sweep), `ladder stability` (its stiff case) and the reliability campaign (the draw of a
//! scene's method). Nothing outside the integrators' own files names a method to decide what it
//! can do.

use super::Control;

/// How a method is driven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ControlKind {
    /// A fixed step (`step` or `scaled_step` in a scene).
    Step,
    /// An error tolerance (`tolerance` in a scene).
    Tolerance,
}

/// How a method behaves on a stiff oscillation, such as penalty springs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stiffness {
    /// Explicit: a step h stays stable on an undamped oscillation of angular frequency ω only
    /// while h ω ≤ `oscillation_limit` (the method's stability interval on the imaginary axis;
    /// 0 for a method that gains energy on every oscillation, as explicit Euler does).
    Explicit {
        /// Largest stable h ω on an undamped oscillation.
        oscillation_limit: f64,
    },
    /// Implicit and A-stable: every step is stable; the stiff part costs Newton iterations.
    Implicit,
}

/// The controls `ladder work-precision` runs a method at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sweep {
    /// Tolerances 10^(−k/per_decade) for k from `from`·per_decade to `to`·per_decade.
    Tolerances {
        /// Loosest tolerance exponent (10^−from).
        from: i32,
        /// Tightest tolerance exponent (10^−to).
        to: i32,
        /// Points per decade.
        per_decade: i32,
    },
    /// Steps `first`, `first`/2, … (`count` of them), in seconds.
    Steps {
        /// The largest step, s.
        first: f64,
        /// How many steps, each half the one before.
        count: i32,
    },
}

impl Sweep {
    /// The controls of the sweep, loosest first.
    pub fn controls(&self) -> Vec<Control> {
        match *self {
            Sweep::Tolerances {
                from,
                to,
                per_decade,
            } => (from * per_decade..=to * per_decade)
                .map(|k| Control::Tolerance(10f64.powf(-f64::from(k) / f64::from(per_decade))))
                .collect(),
            Sweep::Steps { first, count } => (0..count)
                .map(|k| Control::Fixed(first / 2f64.powi(k)))
                .collect(),
        }
    }
}

/// How an explicit adaptive method's steps on penalty springs are estimated before a run
/// (`sim::scene::work` explains the model and the sweeps that set these constants). A method
/// without a fit is refused on penalty springs: the plan could not promise the run ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PenaltyFit {
    /// Stability constant c: the steps at the edge of stability are c ω t_s.
    pub stability: f64,
    /// q + 1, with q the order of the error estimate.
    pub estimate_order: f64,
    /// The accuracy term's coefficients a, b.
    pub accuracy: (f64, f64),
    /// Least Ḟ_w0 T/τ the method needs from θ0 = 0 with a push (F_w0 = 0 there).
    pub wall_force_rate: f64,
}

/// One integrator, as it declares itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Card {
    /// The name scenes give it (`method = "..."`).
    pub name: &'static str,
    /// Its full name, for reports.
    pub title: &'static str,
    /// Fixed step or tolerance.
    pub control: ControlKind,
    /// Its classical order. None for a method whose order is chosen per run, as the Taylor
    /// method's is (by the tolerance, or by the scene's `order` key, which only such a method
    /// takes).
    pub order: Option<u32>,
    /// The order of its dense output (the interpolant between steps): the cubic Hermite
    /// polynomial of the fixed-step methods gives min(order, 4). None when it is chosen per
    /// run, as [`Card::order`].
    pub dense_order: Option<u32>,
    /// Its behaviour on stiff oscillations.
    pub stiffness: Stiffness,
    /// Whether it needs the model's Taylor recursions, which only the rigid wall and floor
    /// phases have (then scenes with penalty contact refuse it).
    pub rigid_only: bool,
    /// What `ladder work-precision` runs it at.
    pub sweep: Sweep,
    /// Its step-count fit on penalty springs (explicit adaptive methods only).
    pub penalty_fit: Option<PenaltyFit>,
    /// The control it is run at among the stiff cases of `ladder stability` (None: not there).
    pub stiff_case: Option<Control>,
}

impl Card {
    /// Whether it takes a tolerance rather than a step.
    pub fn is_adaptive(&self) -> bool {
        self.control == ControlKind::Tolerance
    }

    /// Whether it is implicit (A-stable on stiff oscillations).
    pub fn is_implicit(&self) -> bool {
        self.stiffness == Stiffness::Implicit
    }

    /// Whether it gains energy on every oscillation, whatever its step: an explicit method with
    /// no stable h ω at all (explicit Euler, |1 + i h ω| > 1).
    pub fn gains_energy_on_oscillations(&self) -> bool {
        matches!(self.stiffness, Stiffness::Explicit { oscillation_limit } if oscillation_limit == 0.0)
    }
}

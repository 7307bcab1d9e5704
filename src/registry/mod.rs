//! The registry: one entry per numbered equation (1)-(90) of the note.
//!
//! An entry names the equation (number, section, title, kind, printed LaTeX), the functions that
//! encode it, and its checks. A check is a generic function that evaluates the printed forms of
//! the display, side by side with independent references, as *chains* of values that must all be
//! equal; it is instantiated for every scalar type by the `ladder_fns!` and `particle_fns!`
//! macros, so the same code runs in f64, with running error bounds, in exact rationals and in
//! degree-counting mode. [`check`] runs the checks; [`sample`] draws the states.

pub mod check;
mod exact_point;
mod floor_eqs;
mod general_eqs;
mod jensen_eqs;
mod ladder_eqs;
mod latex;
pub mod law;
mod milne_eqs;
pub mod print_check;
pub mod prove;
pub mod sample;
pub mod side;
pub mod units;

pub use latex::printed_latex;
pub use law::Law;
pub use sample::{LadderSample, ParticleSample};
pub use side::{corrected, misprint, printed, reference, vector_chains, Chain, Role, Side};

use crate::ladder::floor_phase::Slide;
use crate::ladder::{Ladder, State};
use crate::scalar::{Bound, Degree, Dim, Modp, Rational, Sym};
use crate::system::{Point, System};
use serde::Serialize;

/// What sort of statement an equation is, which decides how it is checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Introduces a symbol; checked against an independent model of the same quantity.
    Definition,
    /// Geometry and differentiation: holds for any θ, θ̇, θ̈ (and any m, l, g), whatever the
    /// forces.
    Kinematic,
    /// Newton's second law for the whole ladder, F = m a_cm, solved for a contact force (or used
    /// in a torque of the contact forces): the force is what the motion requires, so it holds for
    /// any θ̈; only the torque law then picks out the motion.
    Newton,
    /// Holds only on the equation of motion (5) (and, where stated, the energy (10)); also shown
    /// to fail off it.
    OnShell,
    /// Holds for any system of particles and any reference point P.
    General,
    /// Milne's name for one of ours; checked by evaluating Milne's expression.
    Notation,
}

impl Kind {
    /// The kebab-case name used in the docs and the JSON.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Definition => "definition",
            Kind::Kinematic => "kinematic",
            Kind::Newton => "newton",
            Kind::OnShell => "on-shell",
            Kind::General => "general",
            Kind::Notation => "notation",
        }
    }
}

/// The chains of one ladder check, in one scalar type.
pub type LadderChains<S> = fn(&Ladder<S>, &State<S>) -> Vec<Chain<S>>;
/// The chains of one particle-system check, in one scalar type.
pub type ParticleChains<S> = fn(&System<S>, &Point<S>) -> Vec<Chain<S>>;

/// The chains of one floor-phase check (the ladder off the wall), in one scalar type.
pub type FloorChains<S> = fn(&Ladder<S>, &State<S>, &Slide<S>) -> Vec<Chain<S>>;

/// Declares a struct holding one check's chain function in every scalar type, so the three
/// kinds of check (ladder, particle system, floor phase) cannot drift apart field by field.
macro_rules! fns_in_every_scalar {
    ($(#[$doc:meta])* $name:ident, $chains:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy)]
        pub struct $name {
            /// In f64 (derivatives by num-dual).
            pub float: $chains<f64>,
            /// With running error bounds.
            pub bound: $chains<Bound>,
            /// In exact rationals.
            pub exact: $chains<Rational>,
            /// In residues modulo a prime (the fast path of the exact points).
            pub modular: $chains<Modp>,
            /// In degree-counting mode (Schwartz-Zippel).
            pub degree: $chains<Degree>,
            /// In symbolic rational functions (proofs).
            pub symbolic: $chains<Sym>,
            /// In physical dimensions (dimensional analysis).
            pub units: $chains<Dim>,
        }
    };
}

fns_in_every_scalar!(
    /// A ladder check instantiated in every scalar type.
    LadderFns,
    LadderChains
);
fns_in_every_scalar!(
    /// A particle-system check instantiated in every scalar type.
    ParticleFns,
    ParticleChains
);
fns_in_every_scalar!(
    /// A floor-phase check instantiated in every scalar type.
    FloorFns,
    FloorChains
);

/// Fills any of the structs above with one generic function, instantiated per scalar type.
#[doc(hidden)]
#[macro_export]
macro_rules! fns_of {
    ($kind:ident, $f:path) => {
        $crate::registry::$kind {
            float: $f,
            bound: $f,
            exact: $f,
            modular: $f,
            degree: $f,
            symbolic: $f,
            units: $f,
        }
    };
}

/// Instantiate a generic floor-phase check
/// `fn f<S: Scalar>(&Ladder<S>, &State<S>, &Slide<S>) -> Vec<Chain<S>>`.
#[macro_export]
macro_rules! floor_fns {
    ($f:path) => {
        $crate::fns_of!(FloorFns, $f)
    };
}

/// Instantiate a generic ladder check `fn f<S: Scalar>(&Ladder<S>, &State<S>) -> Vec<Chain<S>>`.
#[macro_export]
macro_rules! ladder_fns {
    ($f:path) => {
        $crate::fns_of!(LadderFns, $f)
    };
}

/// Instantiate a generic particle check `fn f<S: Scalar>(&System<S>, &Point<S>) -> Vec<Chain<S>>`.
#[macro_export]
macro_rules! particle_fns {
    ($f:path) => {
        $crate::fns_of!(ParticleFns, $f)
    };
}

/// How one check evaluates.
#[derive(Clone, Copy)]
pub enum Eval {
    /// At ladder states of the given sort.
    Ladder(LadderSample, LadderFns),
    /// At particle systems of the given sort.
    Particles(ParticleSample, ParticleFns),
    /// At states of the ladder off the wall (kinematic: all free; on-shell: (P2), (P3) hold).
    Floor(LadderSample, FloorFns),
}

/// One check of an equation.
#[derive(Clone, Copy)]
pub struct Check {
    /// What it checks, in a few words.
    pub name: &'static str,
    /// How it evaluates.
    pub eval: Eval,
}

/// A misprint of the note: the printed form fails; the corrected form is checked in its place.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Erratum {
    /// The printed form, LaTeX.
    pub printed: &'static str,
    /// The corrected form, LaTeX.
    pub corrected: &'static str,
    /// Why, in a sentence.
    pub why: &'static str,
}

/// One numbered equation of the note.
#[derive(Clone)]
pub struct Equation {
    /// Its number, 1..=90.
    pub number: u32,
    /// The section of the note ("2.1", "A.1", "B.7", ...).
    pub section: &'static str,
    /// A one-line title.
    pub title: &'static str,
    /// Its kind.
    pub kind: Kind,
    /// The Rust functions that encode it (paths below the crate root).
    pub functions: &'static [&'static str],
    /// Its checks.
    pub checks: Vec<Check>,
    /// Present when the printed form is wrong.
    pub erratum: Option<Erratum>,
    /// Which `=` of the display is the law of motion (the rest are algebra and kinematics);
    /// `None` when no `=` is (a definition, kinematics, Newton's law solved for a force) or the
    /// law sits inside a general identity of particles, whose model has F_i = m_i a_i built in.
    pub law: Option<Law>,
}

/// Numbers of the extension equations (beyond the note) start here: (P1) is 1001.
pub const EXTENSION_BASE: u32 = 1000;

impl Equation {
    /// The printed LaTeX, as in the note (for an extension, as in `equations/phase2.md`).
    pub fn latex(&self) -> &'static str {
        if self.number > EXTENSION_BASE {
            floor_eqs::latex(self.number - EXTENSION_BASE)
        } else {
            printed_latex(self.number)
        }
    }
    /// How the equation is cited: "(12)", or "(P3)" for an extension.
    pub fn label(&self) -> String {
        if self.number > EXTENSION_BASE {
            format!("(P{})", self.number - EXTENSION_BASE)
        } else {
            format!("({})", self.number)
        }
    }
}

/// The equations of the extension beyond the note: the floor phase, (P1)-(P5).
pub fn extensions() -> Vec<Equation> {
    floor_eqs::equations()
}

/// Shorthand used by the equation tables.
pub(crate) fn eq(
    number: u32,
    section: &'static str,
    title: &'static str,
    kind: Kind,
    functions: &'static [&'static str],
    checks: Vec<Check>,
) -> Equation {
    Equation {
        number,
        section,
        title,
        kind,
        functions,
        checks,
        erratum: None,
        law: None,
    }
}

/// A ladder check.
pub(crate) fn on_ladder(name: &'static str, sample: LadderSample, f: LadderFns) -> Check {
    Check {
        name,
        eval: Eval::Ladder(sample, f),
    }
}

/// A particle-system check.
pub(crate) fn on_particles(name: &'static str, sample: ParticleSample, f: ParticleFns) -> Check {
    Check {
        name,
        eval: Eval::Particles(sample, f),
    }
}

/// Every equation of the note, in order.
pub fn equations() -> Vec<Equation> {
    let mut all = ladder_eqs::equations();
    all.extend(general_eqs::equations());
    all.extend(jensen_eqs::equations());
    all.extend(milne_eqs::equations());
    all.sort_by_key(|e| e.number);
    for e in &mut all {
        e.law = law::law_of(e.number);
    }
    all
}

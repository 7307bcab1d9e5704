//! The registry: one entry per numbered display of the note, derived from its markdown.
//!
//! Each display's section in `equations/*.md` is its one home ([`source`]): number, title,
//! section, kind, the LaTeX as printed, the law step, an erratum, and the checks by name. An
//! entry here is built from that section; only the checks' chain functions are Rust ([`fns`]).
//! A chain function evaluates the printed forms of the display, side by side with independent
//! references, as *chains* of values that must all be equal; it is instantiated for every scalar
//! type by the `ladder_fns!` and `particle_fns!` macros, so the same code runs in f64, with
//! running error bounds, in exact rationals and in degree-counting mode. [`check`] runs the
//! checks; [`sample`] draws the states.

pub mod check;
pub mod exact_point;
mod floor_eqs;
pub mod fns;
mod general_eqs;
mod jensen_eqs;
mod ladder_eqs;
pub mod law;
mod milne_eqs;
pub mod print_check;
pub mod prove;
pub mod sample;
pub mod side;
pub mod source;
pub mod units;

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
    /// Every kind, in the order of the docs.
    pub const ALL: [Kind; 6] = [
        Kind::Definition,
        Kind::Kinematic,
        Kind::Newton,
        Kind::OnShell,
        Kind::General,
        Kind::Notation,
    ];

    /// The kind a `*Kind:*` line names, by its kebab-case name.
    pub fn from_name(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == name)
    }

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

/// One chain function in every scalar type, by the model it evaluates on.
#[derive(Clone, Copy)]
pub enum Fns {
    /// On the ladder of the note (both contacts hold).
    Ladder(LadderFns),
    /// On a system of particles and a moving point P.
    Particles(ParticleFns),
    /// On the ladder off the wall (the floor phase).
    Floor(FloorFns),
}

/// The table entry of a chain function: `named_fns!(Ladder<f64>, eq25)` is `("eq25", Fns::Ladder(..))`.
#[macro_export]
macro_rules! named_fns {
    (Ladder<f64>, $f:ident) => {
        (
            stringify!($f),
            $crate::registry::Fns::Ladder($crate::ladder_fns!($f)),
        )
    };
    (Particles, $f:ident) => {
        (
            stringify!($f),
            $crate::registry::Fns::Particles($crate::particle_fns!($f)),
        )
    };
    (Floor, $f:ident) => {
        (
            stringify!($f),
            $crate::registry::Fns::Floor($crate::floor_fns!($f)),
        )
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

/// One numbered display, built from its section of the markdown ([`source`]).
#[derive(Clone)]
pub struct Equation {
    /// Its number: N for (N), [`EXTENSION_BASE`] + k for (Pk).
    pub number: u32,
    /// The section of the note ("2.1", "A.1", "B.7", ...).
    pub section: &'static str,
    /// Its title, the heading of its section.
    pub title: &'static str,
    /// Its kind.
    pub kind: Kind,
    /// The physics functions that encode it (paths below the crate root), from `*Code:*`.
    pub functions: &'static [String],
    /// Its checks, from `*Rust:*`.
    pub checks: Vec<Check>,
    /// Present when the printed form is wrong.
    pub erratum: Option<Erratum>,
    /// Which `=` of the display is the law of motion (the rest are algebra and kinematics);
    /// `None` when no `=` is (a definition, kinematics, Newton's law solved for a force) or the
    /// law sits inside a general identity of particles, whose model has F_i = m_i a_i built in.
    pub law: Option<Law>,
    /// The display's LaTeX as printed, whitespace collapsed.
    pub latex: &'static str,
    /// For a display that begins with `=`, the last form of the display it continues.
    pub continues: Option<&'static str>,
    /// The states of its `*States:*` line, for a print checked alone.
    pub states: Option<sample::PrintSample>,
    /// What it assumes, from `*Premises:*`.
    pub premises: &'static [source::PremiseSpec],
    /// The markdown file of its section.
    pub file: &'static str,
    /// The line of its heading.
    pub line: usize,
}

/// Numbers of the extension equations (beyond the note) start here: (P1) is 1001.
pub const EXTENSION_BASE: u32 = 1000;

/// How display `number` is cited: "(12)", or "(P3)" for an extension.
pub fn label_of(number: u32) -> String {
    if number > EXTENSION_BASE {
        format!("(P{})", number - EXTENSION_BASE)
    } else {
        format!("({number})")
    }
}

impl Equation {
    /// The printed LaTeX, as in the note (for an extension, as in its markdown).
    pub fn latex(&self) -> &'static str {
        self.latex
    }
    /// How the equation is cited: "(12)", or "(P3)" for an extension.
    pub fn label(&self) -> String {
        label_of(self.number)
    }
    /// Where its section starts: `equations/05-point-d.md:47`.
    pub fn place(&self) -> String {
        format!("{}:{}", self.file, self.line)
    }
}

/// The printed LaTeX of display `n` of the note in use, or "" when it has none.
pub fn printed_latex(n: u32) -> &'static str {
    source::current()
        .section(n)
        .map_or("", |s| s.latex.as_str())
}

/// The symbol table of the note in use: `symbols.toml`'s entries and those its files declare.
pub fn symbol_table() -> &'static [crate::print::symbols::Entry] {
    &source::current().symbols
}

/// The equations of the extension beyond the note: the floor phase, (P1)-(P5).
pub fn extensions() -> Vec<Equation> {
    source::current().extensions()
}

/// A ladder check.
pub(crate) fn on_ladder(name: &'static str, sample: LadderSample, f: LadderFns) -> Check {
    Check {
        name,
        eval: Eval::Ladder(sample, f),
    }
}

/// Every display of the note in use, in order of number.
pub fn equations() -> Vec<Equation> {
    source::current().equations()
}

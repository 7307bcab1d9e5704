//! Dimensional analysis of every check: the same generic chains, evaluated in [`Dim`].
//!
//! The ladder gets its physical dimensions (m: M, l: L, g: L T⁻², sin θ and cos θ pure numbers,
//! θ̇: T⁻¹, θ̈: T⁻², θ⃛: T⁻³), particle systems theirs (masses M, positions L, velocities L T⁻¹,
//! accelerations L T⁻², jerks L T⁻³, spin T⁻¹ and T⁻²), and the floor phase's X, Ẋ, Ẍ, X⃛ are
//! L, L T⁻¹, L T⁻², L T⁻³. The states are built by the registry's own generic samplers
//! ([`exact_ladder`], [`particle_system`], [`floor_state`]), so on-shell states take θ̈ from (5)
//! *in dimensions* too. Then every side of every chain must have one dimension (no sum of
//! unlike terms) and all sides of a chain the same; a misprinted side may fail either way, and
//! that is recorded as the erratum's second witness.

use super::sample::{exact_ladder, floor_state, particle_system, LadderSample, ParticleSample};
use super::sample::{EXTRA, LADDER_DRAWS, PER_PARTICLE};
use super::{Chain, Check, Equation, Eval, Role};
use crate::ladder::floor_phase::Slide;
use crate::ladder::{Ladder, State};
use crate::scalar::{Dim, Dimension, Scalar};
use crate::system::{Point, System};
use serde::Serialize;

/// The verdict of dimensional analysis on one display.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Units {
    /// Every form has one dimension and all forms of each chain agree.
    Consistent,
    /// Some form adds unlike dimensions, or two forms of a chain differ (see the detail).
    Inconsistent,
    /// Consistent, and every form is a pure number.
    Dimensionless,
    /// Nothing to compare (no checks, or every side an exact zero).
    #[serde(rename = "not applicable")]
    NotApplicable,
}

impl Units {
    /// The kebab-case name used in the table and the JSON.
    pub fn name(self) -> &'static str {
        match self {
            Units::Consistent => "consistent",
            Units::Inconsistent => "inconsistent",
            Units::Dimensionless => "dimensionless",
            Units::NotApplicable => "not applicable",
        }
    }
}

/// What dimensional analysis found in one check (or one equation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UnitsFindings {
    /// Inconsistencies in sides that must hold (printed, reference, corrected): real defects.
    pub problems: Vec<String>,
    /// Per misprinted side: its label and, when units alone catch it, why.
    pub misprints: Vec<(&'static str, Option<String>)>,
    /// The dimension of each chain (`None` when every side is an exact zero).
    pub dimensions: Vec<Option<Dimension>>,
}

impl UnitsFindings {
    /// The verdict and, when inconsistent or not applicable, its detail.
    pub fn verdict(&self) -> (Units, Option<String>) {
        if let Some(p) = self.problems.first() {
            return (Units::Inconsistent, Some(p.clone()));
        }
        if let Some(why) = self.misprints.iter().find_map(|m| m.1.clone()) {
            return (Units::Inconsistent, Some(why));
        }
        let known: Vec<Dimension> = self.dimensions.iter().flatten().copied().collect();
        if known.is_empty() {
            let why = if self.dimensions.is_empty() {
                "no chains to compare"
            } else {
                "every side is an exact zero"
            };
            (Units::NotApplicable, Some(why.into()))
        } else if known.iter().all(|d| d.is_dimensionless()) {
            (Units::Dimensionless, None)
        } else {
            (Units::Consistent, None)
        }
    }
    fn extend(&mut self, other: UnitsFindings) {
        self.problems.extend(other.problems);
        self.misprints.extend(other.misprints);
        self.dimensions.extend(other.dimensions);
    }
}

fn d(m: i32, l: i32, t: i32) -> Dim {
    Dim::new(m, l, t)
}

/// The dimensions of the ladder sampler's draws (t, m, l, g, θ̇, θ̈, θ⃛). These are declarations,
/// not checks: t parametrises the unit circle (sin θ = 2t/(1 + t²)), so it is declared a pure
/// number. A wrong declaration is caught downstream, not here: a t with a dimension makes 1 + t²
/// a sum of unlike dimensions, and every form built on sin θ or cos θ inconsistent
/// (`planted_dimension_of_t_is_caught` in the tests below).
pub fn ladder_draw_dimensions() -> [Dim; LADDER_DRAWS] {
    [
        Dim::int(1),
        d(1, 0, 0),
        d(0, 1, 0),
        d(0, 1, -2),
        d(0, 0, -1),
        d(0, 0, -2),
        d(0, 0, -3),
    ]
}

/// The ladder with its dimensions, built by the registry's sampler for the given sort.
pub fn dimensioned_ladder(sort: LadderSample) -> (Ladder<Dim>, State<Dim>) {
    exact_ladder(sort, ladder_draw_dimensions())
}

/// A system of `n` particles with their dimensions and a reference point, of the given sort.
pub fn dimensioned_particles(sort: ParticleSample, n: usize) -> (System<Dim>, Point<Dim>) {
    // Per particle: m, x, v, a, j; then P's x, v, a, j; then ω, ω̇.
    let motion = |k: usize| d(0, 1, -(k as i32));
    let mut values: Vec<Dim> = Vec::with_capacity(n * PER_PARTICLE + EXTRA);
    for _ in 0..n {
        values.push(d(1, 0, 0));
        values.extend((0..12).map(|i| motion(i / 3)));
    }
    values.extend((0..12).map(|i| motion(i / 3)));
    values.extend([d(0, 0, -1), d(0, 0, -2)]);
    // The torque-free sampler takes its rates T⁻² as a component of a_i over a length.
    let (sys, p) = particle_system(sort, n, &values);
    (sys, p)
}

/// The ladder off the wall with its dimensions: X, Ẋ, Ẍ, X⃛ of the centre.
pub fn dimensioned_floor(sort: LadderSample) -> (Ladder<Dim>, State<Dim>, Slide<Dim>) {
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    let v = [d(0, 1, 0), d(0, 1, -1), d(0, 1, -2), d(0, 1, -3)];
    let (s, x) = floor_state(sort, &l, s, v);
    (l, s, x)
}

/// Particle systems are analysed with this many particles (any number gives the same dimensions).
pub const PARTICLES: usize = 3;

/// The chains of a check, evaluated in dimensions.
pub fn dimension_chains(check: &Check) -> Vec<Chain<Dim>> {
    match check.eval {
        Eval::Ladder(sort, f) => {
            let (l, s) = dimensioned_ladder(sort);
            (f.units)(&l, &s)
        }
        Eval::Particles(sort, f) => {
            let (sys, p) = dimensioned_particles(sort, PARTICLES);
            (f.units)(&sys, &p)
        }
        Eval::Floor(sort, f) => {
            let (l, s, x) = dimensioned_floor(sort);
            (f.units)(&l, &s, &x)
        }
    }
}

/// Judge chains of dimensions: every side consistent, all sides of a chain alike.
pub fn judge_chains(chains: &[Chain<Dim>]) -> UnitsFindings {
    let mut out = UnitsFindings::default();
    for chain in chains {
        // The chain's dimension: the first dimension among the sides that must hold.
        let holds = |role: Role| role != Role::Misprint;
        let base = chain
            .iter()
            .filter(|s| holds(s.role))
            .find_map(|s| s.value.dimension().map(|dim| (dim, s.label)));
        for side in chain {
            let finding = match (&side.value, base) {
                (Dim::Inconsistent(i), _) => {
                    let mut i = (**i).clone();
                    i.at.get_or_insert_with(|| format!("'{}'", side.label));
                    Some(format!("inconsistent: {i}"))
                }
                (Dim::Of(dim), Some((b, label))) if *dim != b => Some(format!(
                    "'{}' has dimension {dim}, '{label}' has {b}",
                    side.label
                )),
                _ => None,
            };
            if side.role == Role::Misprint {
                out.misprints.push((side.label, finding));
            } else if let Some(f) = finding {
                out.problems.push(f);
            }
        }
        out.dimensions.push(base.map(|b| b.0));
    }
    out
}

/// Dimensional analysis of one check.
pub fn check_units(check: &Check) -> UnitsFindings {
    judge_chains(&dimension_chains(check))
}

/// Dimensional analysis of one equation: all its checks.
pub fn equation_units(e: &Equation) -> UnitsFindings {
    let mut out = UnitsFindings::default();
    for c in &e.checks {
        let mut f = check_units(c);
        for p in &mut f.problems {
            *p = format!("{}: {p}", c.name);
        }
        out.extend(f);
    }
    out
}

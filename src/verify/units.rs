//! The errata's second witness: dimensional analysis of each misprint and its correction, and of
//! the prose claims that state a quantity with units (see [`crate::registry::units`]).
//!
//! A misprint the exact check catches by value may also be caught by units alone (a dropped mass
//! or length leaves terms that cannot be added, or a form of another dimension than the rest of
//! its chain); one that swaps like for like (θ̇² for θ̈ beside g/l, a dropped term) cannot be.

use crate::ladder::analysis::{angular_momentum_about, AngularMomentum, Reference};
use crate::ladder::forces::wall_force;
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::particles::{as_system, external_torque_about};
use crate::ladder::torque::{angular_momentum_about_a, eq13_moment_of_inertia_about_corner};
use crate::ladder::{Ladder, State};
use crate::registry::print_check::units::print_units;
use crate::registry::sample::LadderSample;
use crate::registry::units::{
    dimensioned_ladder, equation_units, judge_chains, Units, UnitsFindings,
};
use crate::registry::{corrected, misprint, printed, reference, Equation};
use crate::scalar::{sq, Dim, Scalar};
use crate::vector::Vec3;
use serde::Serialize;

/// Dimensional analysis of one erratum.
#[derive(Clone, Debug, Serialize)]
pub struct ErratumUnits {
    /// The printed form, as parsed from the print: `inconsistent` when units alone catch the
    /// misprint, else `consistent`.
    pub printed: Units,
    /// What units see in the printed form (the offending sum and the form's index in the print,
    /// or its dimension against its chain's), when inconsistent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub printed_detail: Option<String>,
    /// The Rust encoding of the printed form (its misprint side), judged the same way: must
    /// equal `printed`.
    pub printed_code: Units,
    /// The corrected form and every other side: must be `consistent` (or `dimensionless`).
    pub corrected: Units,
    /// What went wrong with the corrected form, if anything.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corrected_detail: Option<String>,
}

impl ErratumUnits {
    /// True when units alone would have caught the misprint.
    pub fn caught_by_units(&self) -> bool {
        self.printed == Units::Inconsistent
    }
    /// True when the print and its Rust encoding agree, and the corrected form is not
    /// inconsistent: the witness holds as recorded.
    pub fn holds(&self) -> bool {
        self.printed == self.printed_code && self.corrected != Units::Inconsistent
    }
    /// The line `equations/ERRATA.md` carries for this erratum (held in step by a test).
    pub fn doc_line(&self) -> String {
        let printed = match &self.printed_detail {
            Some(d) => format!(
                "printed form inconsistent ({})",
                d.trim_start_matches("inconsistent: ")
            ),
            None => {
                "printed form consistent (wrong in value only: units alone cannot see it)".into()
            }
        };
        format!(
            "- units: {printed}; corrected form {}",
            self.corrected.name()
        )
    }
}

/// The units witness of an erratum's equation: the printed form from the parsed print
/// ([`crate::registry::print_check::units`]), the corrected form from the Rust forms.
pub fn erratum_units(e: &Equation) -> ErratumUnits {
    let found = equation_units(e);
    let caught = |f: &UnitsFindings| f.misprints.iter().find_map(|m| m.1.clone());
    let code_detail = caught(&found);
    // A display without a print (none today) falls back on its Rust encoding.
    let printed_detail = match print_units(e, e.latex()) {
        Ok(p) => caught(&p),
        Err(_) => code_detail.clone(),
    };
    let verdict = |d: &Option<String>| {
        if d.is_some() {
            Units::Inconsistent
        } else {
            Units::Consistent
        }
    };
    let (corrected, corrected_detail) = match found.problems.first() {
        Some(p) => (Units::Inconsistent, Some(p.clone())),
        None => {
            let mut ok = found.clone();
            ok.misprints.clear();
            ok.verdict()
        }
    };
    ErratumUnits {
        printed: verdict(&printed_detail),
        printed_detail,
        printed_code: verdict(&code_detail),
        corrected,
        corrected_detail,
    }
}

/// Dimensional analysis of one prose claim that states a quantity.
#[derive(Clone, Debug, Serialize)]
pub struct ProseUnits {
    /// Where in the note.
    pub location: &'static str,
    /// The quantity as the note states it.
    pub stated: &'static str,
    /// The verdict on the stated form (for a prose erratum: on the printed wording).
    pub units: Units,
    /// The clash, when inconsistent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units_detail: Option<String>,
    /// For a prose erratum: the verdict on the corrected form.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corrected: Option<Units>,
}

/// Footnote 4 in dimensions: F_w = m l sin θ Ω² (3 cos θ − 2 cos θ0), zero at
/// cos θ = (2/3) cos θ0, with `big_omega_squared` for Ω² = 3g/4l. cos θ0 is not declared a pure
/// number: it is computed from the state by the energy from rest at θ0,
/// θ̇² = 2Ω² (cos θ0 − cos θ) (eq. (10) is its case θ0 = 0), as cos θ + θ̇²/(2Ω²), and must
/// come out a pure number. A wrong Ω² (or θ̇) makes that sum, or that requirement, fail.
pub fn footnote_4(l: &Ladder<Dim>, s: &State<Dim>, big_omega_squared: Dim) -> UnitsFindings {
    let rate2 = sq(&s.rate);
    let cos0 = (s.cos.clone() + rate2 / (Dim::int(2) * big_omega_squared.clone()))
        .require_dimensionless("cos θ0 = cos θ + θ̇²/(2Ω²)");
    let f_w = l.m.clone()
        * l.l.clone()
        * s.sin.clone()
        * big_omega_squared
        * (Dim::int(3) * s.cos.clone() - Dim::int(2) * cos0.clone());
    judge_chains(&[
        vec![
            reference("F_w, eq. (14)", wall_force(l, s)),
            printed("m l sin θ Ω² (3 cos θ − 2 cos θ0)", f_w),
        ],
        vec![
            reference("cos θ", s.cos.clone()),
            printed("(2/3) cos θ0", Dim::ratio(2, 3) * cos0),
        ],
    ])
}

/// The prose claims that state a quantity with units, each in dimensions against the quantity it
/// names (computed by the code's independent route).
pub fn prose_units() -> Vec<ProseUnits> {
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    vec![
        prose_row(
            "sec. 2.1, footnote 4",
            "F_w = m l sin θ Ω² (3 cos θ − 2 cos θ0), zero at cos θ = (2/3) cos θ0",
            footnote_4(&l, &s, l.big_omega2()),
            false,
        ),
        prose_row(
            "sec. 2.2",
            "x_cm × m v_cm about A = −m l² θ̇",
            orbital_about_a(&l, &s),
            false,
        ),
        prose_row("sec. 2.2", "L'_C = I_C θ̇", spin_about_c(&l, &s), false),
        prose_row(
            "sec. A.5",
            "L = L_A = −(2/3) m l θ̇ (printed; corrected −(2/3) m l² θ̇)",
            l_a_erratum(&l, &s),
            true,
        ),
        prose_row(
            "sec. A.5 (end)",
            "τ_A = τ_C + x_C × m a_cm",
            torque_a_from_c(&l, &s),
            false,
        ),
    ]
}

/// One prose claim's row: the verdict on its stated form and, for a prose erratum, whether its
/// corrected form is consistent.
fn prose_row(
    location: &'static str,
    stated: &'static str,
    f: UnitsFindings,
    erratum: bool,
) -> ProseUnits {
    let (units, units_detail) = f.verdict();
    ProseUnits {
        location,
        stated,
        units,
        units_detail,
        corrected: erratum.then_some(if f.problems.is_empty() {
            Units::Consistent
        } else {
            Units::Inconsistent
        }),
    }
}

/// Sec. A.5: L = L_A written as −(2/3) m l θ̇ (a prose erratum), corrected −(2/3) m l² θ̇,
/// against L_A of (12).
fn l_a_erratum(l: &Ladder<Dim>, s: &State<Dim>) -> UnitsFindings {
    let (m, len, w) = (l.m.clone(), l.l.clone(), s.rate.clone());
    judge_chains(&[vec![
        reference("(12): L_A", angular_momentum_about_a(l, s)),
        misprint(
            "−(2/3) m l θ̇",
            -(Dim::ratio(2, 3) * m.clone() * len.clone() * w.clone()),
        ),
        corrected("−(2/3) m l² θ̇", -(Dim::ratio(2, 3) * m * sq(&len) * w)),
    ]])
}

/// Sec. 2.2: the orbital angular momentum of the centre of mass about A is −m l² θ̇.
fn orbital_about_a(l: &Ladder<Dim>, s: &State<Dim>) -> UnitsFindings {
    let sys = as_system(l, s);
    let m = l.m.clone();
    let orbital = sys.centre_of_mass().cross(&sys.cm_velocity().scale(&m)).z;
    judge_chains(&[vec![
        reference("x_cm × m v_cm of the particles", orbital),
        printed("−m l² θ̇", -(m * sq(&l.l) * s.rate.clone())),
    ]])
}

/// Sec. 2.2: the spin angular momentum about C is L'_C = I_C θ̇, I_C of (13).
fn spin_about_c(l: &Ladder<Dim>, s: &State<Dim>) -> UnitsFindings {
    let c = Reference::Corner(Corner::C);
    judge_chains(&[vec![
        reference(
            "L'_C of the particles",
            angular_momentum_about(&c, AngularMomentum::Relative, l, s),
        ),
        printed(
            "I_C θ̇",
            eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone(),
        ),
    ]])
}

/// Sec. A.5 (end): the torque about A from the torque about C, τ_A = τ_C + x_C × m a_cm.
fn torque_a_from_c(l: &Ladder<Dim>, s: &State<Dim>) -> UnitsFindings {
    let sys = as_system(l, s);
    let x_c = corner_position(Corner::C, l, s);
    judge_chains(&[vec![
        reference(
            "τ_A of the external forces",
            external_torque_about(l, &sys, &Vec3::zero()).z,
        ),
        printed(
            "τ_C + x_C × m a_cm",
            (external_torque_about(l, &sys, &x_c) + x_c.cross(&sys.cm_acceleration().scale(&l.m)))
                .z,
        ),
    ]])
}

//! The note's quantitative claims made in prose (not in numbered displays), checked exactly but
//! for the last.
//!
//! Each claim is evaluated in exact rational arithmetic at three random ladder states (and, for
//! the claims about a root, as an identity in cos θ), on general particle systems or on rolling
//! bodies; the last, sec. B.10's ball rolling in a cylinder ([`golfer`]), is a motion, integrated
//! in f64 and held to its closed form within the integrator's estimated error. A claim that the
//! note states correctly must hold at every point; a prose erratum is recorded with the note's
//! wording and ours, and the check shows the printed version failing and the corrected one
//! holding.

use crate::ladder::analysis::{angular_momentum_about, AngularMomentum, Reference, ReferencePoint};
use crate::ladder::forces::wall_force;
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::particles::{as_system, external_torque_about};
use crate::ladder::torque::{
    angular_momentum_about_a, eq13_moment_of_inertia_about_corner, eq24_angular_momentum_about_d,
};
use crate::ladder::{Ladder, State};
use crate::registry::sample::{exact_ladder, LadderSample};
use crate::scalar::{sq, Rational, Scalar};
use crate::vector::Vec3;
use serde::Serialize;

pub mod appendix;
pub mod golfer;
pub mod hu;
pub mod rigid_e;
pub mod rolling;
pub mod sec2;

use std::borrow::Cow;

type Q = Rational;

/// One claim of the note's prose.
#[derive(Clone, Debug, Serialize)]
pub struct Claim {
    /// Where in the note.
    pub location: &'static str,
    /// The claim, in our words (written from the check's printed input where it has one).
    pub claim: Cow<'static, str>,
    /// For a prose erratum: what the note prints, and the correction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub erratum: Option<(&'static str, &'static str)>,
    /// Whether the claim (or, for an erratum, the correction) holds at every exact point.
    pub holds: bool,
    /// For an erratum: whether the printed version fails at every exact point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub printed_fails: Option<bool>,
    /// For a quantitative prose erratum: printed − corrected in the symbolic scalar, factored,
    /// as LaTeX (θ, θ̇ free), when the corrected form is also proved equal to the model's value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub difference_latex: Option<String>,
    /// The same difference in physical terms ("the printed term … lacks a factor l"), as markdown
    /// with `$…$` math ([`crate::scalar::Reading`]), when a reading fits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reading_latex: Option<String>,
    /// For a prose erratum: the printed wording is not wrong everywhere but imprecise (true in
    /// some cases it covers, false in others; the correction says exactly when).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub imprecise: bool,
}

impl Claim {
    /// A claim that the note states correctly; `holds` is its check's verdict.
    pub fn checked(
        location: &'static str,
        claim: impl Into<Cow<'static, str>>,
        holds: bool,
    ) -> Claim {
        Claim {
            location,
            claim: claim.into(),
            erratum: None,
            holds,
            printed_fails: None,
            difference_latex: None,
            reading_latex: None,
            imprecise: false,
        }
    }
    /// A prose erratum: the printed wording (shown failing when `printed_fails`) and the
    /// correction (shown holding when `holds`).
    pub fn erratum(
        location: &'static str,
        claim: impl Into<Cow<'static, str>>,
        (printed, corrected): (&'static str, &'static str),
        holds: bool,
        printed_fails: bool,
    ) -> Claim {
        Claim {
            erratum: Some((printed, corrected)),
            printed_fails: Some(printed_fails),
            ..Claim::checked(location, claim, holds)
        }
    }
    /// The same erratum, marked imprecise rather than wrong.
    pub fn imprecise(self) -> Claim {
        Claim {
            imprecise: true,
            ..self
        }
    }
    /// The verdict in words: holds, prose erratum (false or imprecise, or a wording slip), or
    /// FAILED when the check does not come out as recorded.
    pub fn verdict(&self) -> &'static str {
        match (self.holds, self.printed_fails, self.erratum.is_some()) {
            (true, None, true) => "PROSE ERRATUM (wording; the formula is right)",
            (true, None, false) => "holds",
            (true, Some(true), _) if self.imprecise => {
                "PROSE ERRATUM (imprecise): the printed wording fails in cases it covers, the correction holds"
            }
            (true, Some(true), _) => "PROSE ERRATUM: the printed wording fails, the correction holds",
            _ => "FAILED",
        }
    }
}

/// The prose L_A of sec. A.5 with l to the given power: −(2/3) m lᵏ θ̇ (printed k = 1, right k = 2).
fn la_prose<S: Scalar>(l: &Ladder<S>, s: &State<S>, k: u32) -> S {
    let lk = (0..k).fold(S::int(1), |p, _| p * l.l.clone());
    -(S::ratio(2, 3) * l.m.clone() * lk * s.rate.clone())
}

/// printed − corrected of the A.5 prose slip, factored LaTeX, if the corrected form is proved
/// to be the model's L_A (12) symbolically (else `None`: no difference to show).
pub fn la_prose_difference() -> Option<String> {
    let (l, s, _) = crate::registry::prove::symbolic_ladder(LadderSample::Kinematic);
    let corrected = la_prose(&l, &s, 2);
    let model = angular_momentum_about_a(&l, &s);
    (corrected.clone() - model)
        .is_zero()
        .then(|| crate::scalar::factored_latex(&(la_prose(&l, &s, 1) - corrected)))
}

/// The A.5 prose slip in physical terms (see [`Claim::reading_latex`]).
pub fn la_prose_reading() -> Option<String> {
    let (l, s, _) = crate::registry::prove::symbolic_ladder(LadderSample::Kinematic);
    crate::scalar::reading(&(la_prose(&l, &s, 1) - la_prose(&l, &s, 2))).map(|r| r.render(true))
}

/// The three exact ladder states every claim on the ladder is checked at, of the given sort
/// (fixed integers, so reproducible): m, l and g positive, and tan(θ/2), θ̇, θ̈ and θ⃛ each of
/// both signs among them, so a claim true for one sign of a rate only cannot pass.
pub fn states(sort: LadderSample) -> Vec<(Ladder<Q>, State<Q>)> {
    [
        [3, 7, 2, 11, -5, 13, 4],
        [-7, 5, 9, 2, 3, -4, 1],
        [12, 1, 5, 8, 7, 2, -6],
    ]
    .into_iter()
    .map(|v| exact_ladder(sort, v.map(Q::int)))
    .collect()
}

fn all(sort: LadderSample, f: impl Fn(&Ladder<Q>, &State<Q>) -> bool) -> bool {
    states(sort).iter().all(|(l, s)| f(l, s))
}

fn z(v: Vec3<Q>) -> Q {
    v.z
}

/// The wall force (14) on the motion from rest at θ0 (cos θ0 = c0), with θ̈ from (5) and
/// θ̇² = (3g/2l)(c0 − cos θ) from the energy. θ̇ enters (14) only as θ̇², which may have no
/// rational square root, so (14) is evaluated at θ̇ = 0 and θ̇ = 1 and combined linearly in θ̇².
fn wall_force_from_rest_at(l: &Ladder<Q>, s: &State<Q>, c0: &Q) -> Q {
    let rate2 = Q::int(3) * l.g.clone() / (Q::int(2) * l.l.clone()) * (c0.clone() - s.cos.clone());
    let at = |w: i64| {
        wall_force(
            l,
            &State {
                rate: Q::int(w),
                ..s.clone()
            },
        )
    };
    at(0) + (at(1) - at(0)) * rate2
}

/// Footnote 4 as an identity in θ: on the motion from rest at θ0 (cos θ0 = c0) the wall force
/// is m l sin θ Ω² (3 cos θ − k c0), so it vanishes at cos θ = (k/3) c0; the note says k = 2.
pub fn separates_where(c0: &Q, k: i64) -> bool {
    all(LadderSample::OnShell, |l, s| {
        let claimed = l.m.clone()
            * l.l.clone()
            * s.sin.clone()
            * l.big_omega2()
            * (Q::int(3) * s.cos.clone() - Q::int(k) * c0.clone());
        wall_force_from_rest_at(l, s, c0) == claimed
    })
}

/// Sec. 2.6: the wall force at C and the floor force at D (any values) have no torque about the
/// point `k`; the note says so for E.
pub fn contact_torques_vanish_about(k: Corner) -> bool {
    all(LadderSample::Kinematic, |l, s| {
        let p = corner_position(k, l, s);
        let (f_w, f_f) = (Q::int(5), Q::int(-3));
        let t_w =
            (corner_position(Corner::C, l, s) - p.clone()).cross(&Vec3::planar(f_w, Q::int(0)));
        let t_f = (corner_position(Corner::D, l, s) - p).cross(&Vec3::planar(Q::int(0), f_f));
        t_w.z == Q::int(0) && t_f.z == Q::int(0)
    })
}

/// Every prose claim, checked: the fall and rigid rotation of secs. 2.1-2.2, then the contact
/// points and errata of secs. 2.5-A.5 (the fourteen checked before issue 37), then the rest by
/// section ([`sec2`], [`rigid_e`], [`appendix`], [`hu`] on [`rolling`]), and last sec. B.10's
/// golfer's nemesis ([`golfer`]: a 3-D rolling ball integrated and held to its closed form).
pub fn claims() -> Vec<Claim> {
    [
        fall_and_rigid_rotation_claims(),
        contact_point_claims(),
        sec2::claims(),
        rigid_e::claims(),
    ]
    .into_iter()
    .flatten()
    .chain(appendix::claims())
    .chain(hu::claims())
    .chain(golfer::claims())
    .collect()
}

/// Secs. 2.1, 2.2 and footnote 4: six of the fourteen claims checked before issue 37.
fn fall_and_rigid_rotation_claims() -> Vec<Claim> {
    use LadderSample::*;
    let ok = Claim::checked;
    let on_circle = all(Kinematic, |l, s| {
        corner_position(Corner::B, l, s).dot(&corner_position(Corner::B, l, s)) == sq(&l.l)
    });
    // Footnote 4 (and sec. 2.1 with θ0 = 0): on the motion from rest at θ0 the wall force is
    // m l sin θ · (3g/4l)(3 cos θ − 2 cos θ0), an identity in θ: it vanishes at cos θ = (2/3) cos θ0.
    let separation = |c0: Q| separates_where(&c0, 2);
    let orbital_a = all(Kinematic, |l, s| {
        let sys = as_system(l, s);
        z(sys.centre_of_mass().cross(&sys.cm_velocity().scale(&l.m)))
            == -(l.m.clone() * sq(&l.l) * s.rate.clone())
    });
    let rigid_about = |k: Corner| {
        all(Kinematic, move |l, s| {
            angular_momentum_about(&Reference::Corner(k), AngularMomentum::Relative, l, s)
                == eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone()
        })
    };
    let not_rigid_about = |k: Corner| {
        all(Kinematic, move |l, s| {
            let lp = angular_momentum_about(&Reference::Corner(k), AngularMomentum::Relative, l, s);
            let i = eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone();
            lp != i.clone() && lp != -i
        })
    };
    vec![
        ok("sec. 2.1", "the centre of mass B moves on a circle of radius l about A", on_circle),
        ok("sec. 2.1", "from rest upright the ladder leaves the wall where cos θ = 2/3 (F_w ∝ 3 cos θ − 2)", separation(Q::int(1))),
        ok("footnote 4", "from rest at θ0 it leaves the wall where cos θ = (2/3) cos θ0 (F_w ∝ 3 cos θ − 2 cos θ0)", separation(Q::ratio(3, 5))),
        ok("sec. 2.2", "the orbital angular momentum of the centre of mass about A is −ml²θ̇", orbital_a),
        ok("sec. 2.2", "L'_C = I_C θ̇ and L'_D = I_D θ̇ (rigid rotation about C and D)", rigid_about(Corner::C) && rigid_about(Corner::D)),
        ok("sec. 2.2", "L_A is not ±I_A θ̇, nor L'_E ±I_E θ̇ (no rigid rotation about A or E)", not_rigid_about(Corner::A) && not_rigid_about(Corner::E)),
    ]
}

/// Secs. 2.5, 2.6, the figure, secs. A.2-A.5 and footnote 16: the other eight of the fourteen
/// claims checked before issue 37 (two of them prose errata).
fn contact_point_claims() -> Vec<Claim> {
    use LadderSample::*;
    let ok = Claim::checked;
    let contact_torques_about_e = contact_torques_vanish_about(Corner::E);
    let tau_a_from_tau_c = all(Kinematic, |l, s| {
        let sys = as_system(l, s);
        let x_c = corner_position(Corner::C, l, s);
        let tau_a = external_torque_about(l, &sys, &Vec3::zero());
        let tau_c = external_torque_about(l, &sys, &x_c);
        tau_a == tau_c + x_c.cross(&sys.cm_acceleration().scale(&l.m))
    });
    let only_a_at_rest = all(Kinematic, |l, s| {
        Corner::ALL.iter().all(|&k| {
            let a = Reference::Corner(k).motion(l, s).a;
            (k == Corner::A) == (a == Vec3::zero())
        })
    });
    let e_is_instant_centre = all(Kinematic, |l, s| {
        // The ladder's velocity field v_B + θ̇ ẑ × (x − x_B) vanishes at E.
        let sys = as_system(l, s);
        let x_b = sys.centre_of_mass();
        let v = sys.cm_velocity()
            + Vec3::along_z(s.rate.clone()).cross(&(corner_position(Corner::E, l, s) - x_b));
        v == Vec3::zero()
    });
    let contact_point_on_body = all(Kinematic, |l, s| {
        // Methods 1 and 2 (and 3, 4) coincide: the ladder's material point at C moves like the contact.
        let sys = as_system(l, s);
        let body = sys.cm_velocity()
            + Vec3::along_z(s.rate.clone())
                .cross(&(corner_position(Corner::C, l, s) - sys.centre_of_mass()));
        body == Reference::Corner(Corner::C).motion(l, s).v
    });
    let l_c_is_relative = all(Kinematic, |l, s| {
        let printed = crate::ladder::torque::eq21_angular_momentum_about_c(l, s)[1].clone();
        let c = Reference::Corner(Corner::C);
        printed == angular_momentum_about(&c, AngularMomentum::Relative, l, s)
            && printed != angular_momentum_about(&c, AngularMomentum::Absolute, l, s)
    });
    let d_label_printed = all(Kinematic, |l, s| {
        // (24) gives 4ml²θ̇/3, which is L'_D; it also equals L'_C, so the slip changes no number,
        // but only D is the point of sec. 2.5's analysis. Check the formula is L'_D.
        eq24_angular_momentum_about_d(l, s)[1]
            == angular_momentum_about(
                &Reference::Corner(Corner::D),
                AngularMomentum::Relative,
                l,
                s,
            )
    });
    let la_prose_printed_fails = all(Kinematic, |l, s| {
        angular_momentum_about_a(l, s) != la_prose(l, s, 1)
    });
    let la_prose_corrected = all(Kinematic, |l, s| {
        angular_momentum_about_a(l, s) == la_prose(l, s, 2)
    });
    vec![
        ok("sec. 2.6", "the floor and wall forces have no torque about E", contact_torques_about_e),
        ok("sec. 1, FIGURE", "only A is at rest; B, C, D, E accelerate", only_a_at_rest),
        ok("FIGURE", "E is the instantaneous centre of rotation of the ladder", e_is_instant_centre),
        ok("sec. A.2, A.4", "the ladder's material point at C moves with the contact point (methods 1 = 2, 3 = 4)", contact_point_on_body),
        ok("footnote 16", "the L_C of sec. 2.4 is L'_C of Appendix A, not L_C", l_c_is_relative),
        ok("sec. A.5 (end)", "τ_A = τ_C + x_C × m a_cm", tau_a_from_tau_c),
        Claim {
            erratum: Some(("about point C", "about point D")),
            ..ok("sec. 2.5", "(24) is introduced as 'the angular momentum about point C'; it is about D (a wording slip: L'_C = L'_D, so no number changes)", d_label_printed)
        },
        Claim {
            difference_latex: la_prose_difference(),
            reading_latex: la_prose_reading(),
            ..Claim::erratum("sec. A.5", "L = L_A written as −(2/3) m l θ̇: a factor l is missing", (r"-\frac{2}{3}m l \dot{\theta}", r"-\frac{2}{3}m l^2 \dot{\theta}"), la_prose_corrected, la_prose_printed_fails)
        },
    ]
}

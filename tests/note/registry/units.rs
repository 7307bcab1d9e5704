//! Dimensional analysis (issue 14): every check of the registry evaluated in physical dimensions.
//! Verified displays are consistent; the errata that drop a dimensional factor are caught by units
//! alone and their corrected forms are consistent; a planted slip (a dropped m) is reported.

use sliding_ladder::ladder::torque::angular_momentum_about_a;
use sliding_ladder::registry::sample::exact_ladder;
use sliding_ladder::registry::sample::LADDER_DRAWS;
use sliding_ladder::registry::sample::{LadderSample, ParticleSample};
use sliding_ladder::registry::units::{
    dimension_chains, dimensioned_ladder, dimensioned_particles, equation_units, judge_chains,
    Units,
};
use sliding_ladder::registry::units::{ladder_draw_dimensions, UnitsFindings};
use sliding_ladder::registry::Eval;
use sliding_ladder::registry::{equations, extensions, printed, reference, Role};
use sliding_ladder::scalar::{sq, Dim, Dimension, Scalar};

#[test]
fn every_display_has_a_units_verdict_and_only_misprints_are_inconsistent() {
    let mut caught = Vec::new();
    for e in equations().iter().chain(extensions().iter()) {
        let found = equation_units(e);
        assert!(
            found.problems.is_empty(),
            "{}: {:?}",
            e.label(),
            found.problems
        );
        let (units, detail) = found.verdict();
        match units {
            Units::Inconsistent => {
                assert!(
                    e.erratum.is_some(),
                    "{} inconsistent: {detail:?}",
                    e.label()
                );
                caught.push(e.number);
            }
            Units::NotApplicable => assert!(detail.is_some(), "{} needs a reason", e.label()),
            Units::Consistent | Units::Dimensionless => {}
        }
    }
    // The three errata that drop or misplace a dimensional factor: (49) a mass in a sum, (62) a
    // length, (68) a mass. (28) and (54) are wrong in value only.
    assert_eq!(caught, vec![49, 62, 68]);
    // The twelve derivations of the equation of motion: residuals and solved θ̈ consistent.
    for (name, checks) in sliding_ladder::derivation::derivations() {
        for c in &checks {
            let found = sliding_ladder::registry::units::check_units(c);
            assert!(found.problems.is_empty(), "{name}: {:?}", found.problems);
            assert_eq!(found.verdict().0, Units::Consistent, "{name}");
        }
    }
}

#[test]
fn the_misprint_of_49_is_named_with_both_dimensions() {
    let e = equations().into_iter().find(|e| e.number == 49).unwrap();
    let (units, detail) = equation_units(&e).verdict();
    assert_eq!(units, Units::Inconsistent);
    let detail = detail.unwrap();
    assert!(
        detail.starts_with("inconsistent: M L² T⁻¹ + L² T⁻¹ in '"),
        "{detail}"
    );
    assert!(detail.contains("(as printed)"), "{detail}");
}

#[test]
fn corrected_forms_of_every_erratum_are_consistent() {
    for e in equations().iter().filter(|e| e.erratum.is_some()) {
        let mut corrected = 0;
        for c in &e.checks {
            for chain in dimension_chains(c) {
                let base = chain
                    .iter()
                    .find(|s| s.role == Role::Reference)
                    .and_then(|s| s.value.dimension());
                for s in chain.iter().filter(|s| s.role == Role::Corrected) {
                    corrected += 1;
                    assert!(
                        s.value.inconsistency().is_none(),
                        "({}) {}",
                        e.number,
                        s.label
                    );
                    if let (Some(b), Some(d)) = (base, s.value.dimension()) {
                        assert_eq!(b, d, "({}) {}", e.number, s.label);
                    }
                }
            }
        }
        assert!(corrected > 0, "({}) has no corrected side", e.number);
    }
}

/// A planted slip: (12)'s L_A = −2ml²θ̇/3 with the m dropped, as a side beside the reference,
/// and as a sum with the correct form. Both are reported; the unplanted chain is consistent.
#[test]
fn a_dropped_mass_is_reported() {
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    let right = angular_momentum_about_a(&l, &s);
    let dropped = -(Dim::ratio(2, 3) * sq(&l.l) * s.rate.clone());
    let good = judge_chains(&[vec![
        reference("L_A", right.clone()),
        printed("−2ml²θ̇/3", right.clone()),
    ]]);
    assert!(good.problems.is_empty());
    assert_eq!(good.verdict().0, Units::Consistent);
    let side = judge_chains(&[vec![
        reference("L_A", right.clone()),
        printed("−2l²θ̇/3", dropped.clone()),
    ]]);
    assert_eq!(
        side.problems,
        vec!["'−2l²θ̇/3' has dimension L² T⁻¹, 'L_A' has M L² T⁻¹".to_string()]
    );
    let sum = judge_chains(&[vec![
        reference("L_A", right.clone() + right.clone()),
        printed("−2ml²θ̇/3 − 2l²θ̇/3", right + dropped),
    ]]);
    assert_eq!(sum.verdict().0, Units::Inconsistent);
    assert_eq!(
        sum.problems,
        vec!["inconsistent: M L² T⁻¹ + L² T⁻¹ in '−2ml²θ̇/3 − 2l²θ̇/3'".to_string()]
    );
}

/// Perturbing any sample's dimension is caught: a ladder with g of dimension L T⁻¹ makes the
/// equation of motion (5) inconsistent.
#[test]
fn a_wrong_dimension_of_g_is_caught_by_the_equation_of_motion() {
    let e5 = equations().into_iter().find(|e| e.number == 5).unwrap();
    let (mut l, s) = dimensioned_ladder(LadderSample::Kinematic);
    l.g = Dim::new(0, 1, -1);
    let s = s.with_accel(sliding_ladder::ladder::energy::angular_acceleration(&l, &s));
    let sliding_ladder::registry::Eval::Ladder(_, f) = e5.checks[0].eval else {
        panic!("(5) is a ladder check")
    };
    assert!(!judge_chains(&(f.units)(&l, &s)).problems.is_empty());
}

#[test]
fn dimensioned_samples_have_the_physical_dimensions() {
    let (l, s) = dimensioned_ladder(LadderSample::OnShellFromRest);
    assert_eq!(l.g, Dim::new(0, 1, -2), "g solved from the energy");
    assert_eq!(s.accel, Dim::new(0, 0, -2), "θ̈ from (5)");
    assert_eq!(s.sin, Dim::int(1));
    for sort in [
        ParticleSample::General,
        ParticleSample::TorqueFree,
        ParticleSample::PlanarRigid,
    ] {
        let (sys, p) = dimensioned_particles(sort, 2);
        let q = &sys.particles[1];
        assert_eq!(q.m, Dim::Of(Dimension::MASS));
        assert_eq!(q.x.x, Dim::new(0, 1, 0));
        assert_eq!(q.v.y, Dim::new(0, 1, -1));
        assert_eq!(q.a.x, Dim::new(0, 1, -2), "{sort:?}");
        assert_eq!(p.x.x, Dim::new(0, 1, 0));
    }
}

#[test]
fn a_chain_of_pure_numbers_is_dimensionless_and_of_zeros_not_applicable() {
    let pure = judge_chains(&[vec![
        printed("cos θ", Dim::int(1)),
        reference("2/3", Dim::ratio(2, 3)),
    ]]);
    assert_eq!(pure.verdict().0, Units::Dimensionless);
    let zeros = judge_chains(&[vec![printed("0", Dim::int(0)), reference("0", Dim::int(0))]]);
    assert_eq!(zeros.verdict().0, Units::NotApplicable);
    assert_eq!(judge_chains(&[]).verdict().0, Units::NotApplicable);
}

#[test]
fn errata_md_carries_the_units_witness_of_every_erratum() {
    use sliding_ladder::verify::units::erratum_units;
    let page = std::fs::read_to_string(sliding_ladder::docs::default_dir().join("ERRATA.md"))
        .expect("equations/ERRATA.md");
    let mut caught = Vec::new();
    for e in equations().iter().filter(|e| e.erratum.is_some()) {
        let u = erratum_units(e);
        assert_ne!(
            u.corrected,
            Units::Inconsistent,
            "({}): {:?}",
            e.number,
            u.corrected_detail
        );
        // The printed form as parsed from the print and as encoded in Rust: one verdict.
        assert_eq!(u.printed, u.printed_code, "({})", e.number);
        assert!(u.holds());
        assert!(
            page.contains(&format!("{}\n", u.doc_line())),
            "({}) ERRATA.md lacks the line\n{}",
            e.number,
            u.doc_line()
        );
        if u.caught_by_units() {
            caught.push(e.number);
        }
    }
    assert_eq!(caught, vec![49, 62, 68]);
}

#[test]
fn prose_quantities_have_consistent_units_except_the_a5_slip() {
    use sliding_ladder::verify::units::prose_units;
    let rows = prose_units();
    assert!(rows.len() >= 5);
    for r in &rows {
        if r.location == "sec. A.5" {
            assert_eq!(r.units, Units::Inconsistent);
            assert_eq!(r.corrected, Some(Units::Consistent));
            assert!(r.units_detail.as_deref().unwrap().contains("M L T⁻¹"));
        } else {
            assert_eq!(
                r.units,
                Units::Consistent,
                "{}: {:?}",
                r.location,
                r.units_detail
            );
        }
    }
}

/// The errata witness fails when the print and its Rust encoding disagree, or the corrected form
/// is inconsistent (`ladder errata` exits 1 then).
#[test]
fn an_errata_witness_that_disagrees_does_not_hold() {
    use sliding_ladder::verify::units::erratum_units;
    let e = equations().into_iter().find(|e| e.number == 49).unwrap();
    let good = erratum_units(&e);
    assert!(good.holds());
    let mut split = good.clone();
    split.printed_code = Units::Consistent;
    assert!(!split.holds());
    let mut bad = good;
    bad.corrected = Units::Inconsistent;
    assert!(!bad.holds());
}

/// Footnote 4's cos θ0 is computed from the state (energy from rest at θ0), not declared a pure
/// number: the right Ω² = 3g/4l passes, a planted Ω² without the 1/l (dimension L T⁻²) fails both
/// the sum cos θ + θ̇²/(2Ω²) and the footnote's F_w.
#[test]
fn footnote_4_fails_with_a_planted_wrong_big_omega_squared() {
    use sliding_ladder::verify::units::footnote_4;
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    let right = footnote_4(&l, &s, l.big_omega2());
    assert_eq!(right.verdict(), (Units::Consistent, None));
    let wrong = footnote_4(&l, &s, Dim::ratio(3, 4) * l.g.clone());
    let (units, detail) = wrong.verdict();
    assert_eq!(units, Units::Inconsistent);
    let detail = detail.unwrap();
    assert!(
        detail.contains("L T⁻²") || detail.contains("L⁻¹"),
        "{detail}"
    );
    assert!(wrong.problems.len() >= 2, "{:?}", wrong.problems);
}

/// The dimension M^m L^l T^t.
fn d(m: i32, l: i32, t: i32) -> Dim {
    Dim::new(m, l, t)
}

fn ladder_checks_with(draws: [Dim; LADDER_DRAWS]) -> Vec<UnitsFindings> {
    equations()
        .iter()
        .flat_map(|e| e.checks.iter())
        .filter_map(|c| match c.eval {
            Eval::Ladder(sort, f) => {
                let (l, s) = exact_ladder(sort, draws.clone());
                Some(judge_chains(&(f.units)(&l, &s)))
            }
            _ => None,
        })
        .collect()
}

#[test]
fn planted_dimension_of_t_is_caught() {
    // As declared, no ladder check has a problem.
    let fine = ladder_checks_with(ladder_draw_dimensions());
    assert!(!fine.is_empty());
    assert!(fine.iter().all(|f| f.problems.is_empty()), "{fine:?}");
    // t given a length: 1 + t² adds a pure number to an area, and the checks say so.
    let mut planted = ladder_draw_dimensions();
    planted[0] = d(0, 1, 0);
    let (_, s) = exact_ladder(LadderSample::Kinematic, planted.clone());
    assert!(matches!(s.sin, Dim::Inconsistent(_)), "{:?}", s.sin);
    let found = ladder_checks_with(planted);
    let failing = found.iter().filter(|f| !f.problems.is_empty()).count();
    assert!(failing * 2 > found.len(), "{failing} of {}", found.len());
    assert!(
        found
            .iter()
            .flat_map(|f| &f.problems)
            .any(|p| p.contains("L²")),
        "{found:?}"
    );
}

/// The declared dimensions of the draws (t, m, l, g, θ̇, θ̈, θ⃛), held to what each quantity is:
/// t a pure number, m a mass, l a length; each rate of θ is the one before over a time, θ̇ T a
/// pure angle, and g that of l θ̈. (Nothing downstream reads θ⃛'s dimension: a wrong sign of
/// its exponent passed every check before this test.)
#[test]
fn ladder_draw_dimensions_are_each_the_rate_of_the_one_before() {
    let [t, m, l, g, rate, accel, jerk] = ladder_draw_dimensions();
    let of = |x: Dim| x.dimension();
    let time = d(0, 0, 1);
    assert_eq!(of(t), Some(Dimension::new(0, 0, 0)));
    assert_eq!((of(m), of(l.clone())), (of(d(1, 0, 0)), of(d(0, 1, 0))));
    assert_eq!(
        of(rate.clone() * time.clone()),
        Some(Dimension::new(0, 0, 0))
    );
    assert_eq!(of(accel.clone() * time.clone()), of(rate));
    assert_eq!(of(jerk * time), of(accel.clone()));
    assert_eq!(of(g), of(l * accel));
}

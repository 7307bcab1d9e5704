//! Tests of `sliding_ladder::verify::claims` (src/verify/claims.rs).

use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::verify::claims::{claims, contact_torques_vanish_about, separates_where};

/// Exact rationals, the number type of the claims.
type Q = Rational;

#[test]
fn claims_hold_and_wrong_versions_fail() {
    assert!(claims()
        .iter()
        .all(|c| c.holds && c.printed_fails != Some(false)));
    // A root at (1/3) or (3/3) cos θ0 instead of (2/3) fails; so do torques about D.
    assert!(separates_where(&Q::ratio(3, 5), 2) && !separates_where(&Q::ratio(3, 5), 1));
    assert!(!separates_where(&Q::int(1), 3));
    assert!(contact_torques_vanish_about(Corner::E) && !contact_torques_vanish_about(Corner::D));
}

/// The rows of docs/prose-claims.md's table: (check column, verdict column).
fn documented_claims() -> Vec<(String, String)> {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/prose-claims.md"))
        .expect("docs/prose-claims.md");
    doc.lines()
        .filter(|l| l.starts_with("| ") && l[2..].starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            (cells[4].to_string(), cells[5].to_string())
        })
        .collect()
}

/// The counts come from their one home, the table of docs/prose-claims.md: every row with a
/// check is a claim of `claims()`, every row whose verdict is false, a slip or imprecise is an
/// erratum, and none of them fails as printed.
#[test]
fn the_prose_claims_are_the_documented_ones_and_every_erratum_fails_as_printed() {
    let all = claims();
    let rows = documented_claims();
    let checked: Vec<_> = rows.iter().filter(|(check, _)| check != "—").collect();
    assert_eq!(
        all.len(),
        checked.len(),
        "claims() against the table's checked rows"
    );
    let is_erratum = |v: &str| {
        v.starts_with("false") || v.starts_with("wording slip") || v.starts_with("**imprecise**")
    };
    let errata: Vec<_> = all.iter().filter(|c| c.erratum.is_some()).collect();
    assert_eq!(
        errata.len(),
        checked.iter().filter(|(_, v)| is_erratum(v)).count()
    );
    assert_eq!(
        errata.iter().filter(|c| c.imprecise).count(),
        checked
            .iter()
            .filter(|(_, v)| v.starts_with("**imprecise**"))
            .count()
    );
    assert!(!errata.is_empty() && all.iter().all(|c| c.verdict() != "FAILED"));
}

#[test]
fn the_sentence_about_e_is_true_of_l_prime_and_false_of_l() {
    use sliding_ladder::ladder::analysis::AngularMomentum::{Absolute, Relative};
    use sliding_ladder::verify::claims::rigid_e::{
        is_instant_centre_of_particles, orbital_test_decides, rigid_about,
    };
    assert!(!rigid_about(Corner::E, Relative) && rigid_about(Corner::E, Absolute));
    // Rigid about C and D only relative to their motion; never about A.
    assert!(rigid_about(Corner::C, Relative) && !rigid_about(Corner::C, Absolute));
    assert!(!rigid_about(Corner::A, Absolute) && !rigid_about(Corner::A, Relative));
    // The test decides with the body's own sense; with the opposite sense it does not.
    assert!(orbital_test_decides(1) && !orbital_test_decides(-1));
    assert!(is_instant_centre_of_particles(Corner::E));
    assert!(!is_instant_centre_of_particles(Corner::C));
}

#[test]
fn section_2_checks_report_false_for_the_wrong_point_or_value() {
    use sliding_ladder::ladder::analysis::AngularMomentum::{Absolute, Relative};
    use sliding_ladder::ladder::energy::moment_of_inertia_cm;
    use sliding_ladder::ladder::{Ladder, State};
    use sliding_ladder::verify::claims::sec2::{
        at_distance_l, footnote_3, leads_to, off_the_ladder, relative_l_is_l_a,
        rigid_about_points_on_ladder, spin_and_sense,
    };
    assert!(at_distance_l(Corner::E) && !at_distance_l(Corner::B));
    assert!(off_the_ladder(Corner::E) && !off_the_ladder(Corner::B));
    assert!(relative_l_is_l_a(Corner::E) && !relative_l_is_l_a(Corner::C));
    // (5) with 3g/(2l) in place of 3g/(4l) is not what the analysis about C gives.
    fn wrong(l: &Ladder<Q>, s: &State<Q>) -> Q {
        Q::ratio(3, 2) * l.g.clone() / l.l.clone() * s.sin.clone()
    }
    assert!(!leads_to(Corner::C, Relative, wrong));
    // The spin with I_cm = ml² (the sense still opposite) is not the printed one.
    assert!(spin_and_sense(moment_of_inertia_cm));
    assert!(!spin_and_sense(|l| l.m.clone() * l.l.clone() * l.l.clone()));
    // In the lab frame the moving points of the ladder are not in rigid rotation.
    assert!(rigid_about_points_on_ladder(Relative) && !rigid_about_points_on_ladder(Absolute));
    // (10) with 3g/(4l): its derivative no longer gives (5), though (9) is still conserved.
    assert!(footnote_3(&Q::ratio(3, 2)) && !footnote_3(&Q::ratio(3, 4)));
}

#[test]
fn appendix_checks_see_a_moving_point_and_a_perturbed_system() {
    use sliding_ladder::ladder::energy::moment_of_inertia_cm;
    use sliding_ladder::system::{Point, System};
    use sliding_ladder::vector::Vec3;
    use sliding_ladder::verify::claims::appendix::{
        cm_needs_no_coordinate_force, eq77_is_eq37, eq85_is_eq38, eq88_follows, eq90_is_eq40,
        fixed_point_law, fixed_point_same_l, general_systems, kinetic_energy_splits,
        method3_is_sec_2_4, method5_is_about_b, slipping_breaks_eq42, three_distinct_methods,
        Systems, JENSEN_METHODS,
    };
    /// The systems, each changed by `f`.
    fn changed(
        systems: &Systems,
        f: impl Fn(&mut System<Q>, &mut Point<Q>),
    ) -> Vec<(System<Q>, Point<Q>)> {
        let mut out = systems.to_vec();
        out.iter_mut().for_each(|(s, p)| f(s, p));
        out
    }
    let systems = general_systems();
    assert!(systems
        .iter()
        .all(|(s, p)| p.v != Vec3::zero() && s.particles.len() == 3));
    // Each system changed so that a check's negative half no longer holds.
    let p_at_rest = changed(&systems, |_, p| *p = Point::fixed(p.x.clone()));
    let cm_at_rest = changed(&systems, |s, _| {
        s.particles.iter_mut().for_each(|q| q.a = Vec3::zero())
    });
    let centred = changed(&systems, |s, _| {
        let cm = s.centre_of_mass();
        s.particles
            .iter_mut()
            .for_each(|q| q.x = q.x.clone() - cm.clone())
    });
    assert!(fixed_point_same_l(&systems) && !fixed_point_same_l(&p_at_rest));
    assert!(fixed_point_law(&systems) && !fixed_point_law(&p_at_rest));
    assert!(cm_needs_no_coordinate_force(&systems) && !cm_needs_no_coordinate_force(&cm_at_rest));
    assert!(eq88_follows(&systems) && !eq88_follows(&centred));
    // A printed sign or coefficient changed in one form (the other kept) fails.
    assert!(eq85_is_eq38((1, -1)) && !eq85_is_eq38((1, 1)) && !eq85_is_eq38((-1, -1)));
    assert!(eq77_is_eq37((-1, 1)) && !eq77_is_eq37((1, 1)) && !eq77_is_eq37((-1, -1)));
    assert!(eq90_is_eq40(1) && !eq90_is_eq40(-1));
    assert!(kinetic_energy_splits(moment_of_inertia_cm));
    assert!(!kinetic_energy_splits(|l| l.m.clone()
        * l.l.clone()
        * l.l.clone()));
    // The acceleration of the right point, the right corner.
    assert!(method5_is_about_b(Corner::B) && !method5_is_about_b(Corner::C));
    assert!(method3_is_sec_2_4(Corner::C) && !method3_is_sec_2_4(Corner::D));
    assert!(slipping_breaks_eq42(Corner::C) && !slipping_breaks_eq42(Corner::E));
    assert_eq!(three_distinct_methods(JENSEN_METHODS), (true, true));
    // Method 5 taken as L'_C (two methods alike), or method 1 as sec. 2's L_A (nothing new).
    use sliding_ladder::ladder::analysis::AngularMomentum::{Absolute, Relative};
    let alike = [
        (Corner::C, Absolute),
        (Corner::C, Relative),
        (Corner::C, Relative),
    ];
    assert!(!three_distinct_methods(alike).0);
    let nothing_new = [
        (Corner::A, Absolute),
        (Corner::C, Relative),
        (Corner::B, Absolute),
    ];
    assert_eq!(three_distinct_methods(nothing_new), (true, false));
}

/// The split of L_P and L'_P holds about the centre of mass and fails about a point at rest at
/// the origin; about P held at rest only the L_P half holds, so both halves are checked.
#[test]
fn orbital_plus_spin_holds_about_the_centre_of_mass_only() {
    use sliding_ladder::system::Point;
    use sliding_ladder::vector::Vec3;
    use sliding_ladder::verify::claims::appendix::orbital_plus_spin;
    assert!(orbital_plus_spin(|s, _| s.cm_point()));
    assert!(!orbital_plus_spin(|_, _| Point::fixed(Vec3::zero())));
    assert!(!orbital_plus_spin(|_, p| Point::fixed(p.x.clone())));
}

/// The wall force at C has no torque about C and one about B (the note's pair); about B it
/// is not free, and about C it is not needed.
#[test]
fn contact_force_needed_sees_which_point_the_wall_force_turns() {
    use sliding_ladder::verify::claims::appendix::contact_force_needed;
    assert!(contact_force_needed(Corner::C, Corner::B));
    assert!(contact_force_needed(Corner::C, Corner::D));
    assert!(!contact_force_needed(Corner::B, Corner::C));
    assert!(!contact_force_needed(Corner::C, Corner::C));
}

/// The printed coordinates hold, and a wrong multiple in either coordinate alone fails.
#[test]
fn coordinates_of_points_fails_a_wrong_x_or_y() {
    use sliding_ladder::verify::claims::sec2::{
        coordinates_of_points, coordinates_sentence, PRINTED_COORDINATES,
    };
    assert!(coordinates_of_points(&PRINTED_COORDINATES));
    assert!(coordinates_of_points(&[(Corner::A, 0, 0)]));
    assert!(!coordinates_of_points(&[(Corner::C, 0, 1)]));
    assert!(!coordinates_of_points(&[(Corner::D, 1, 0)]));
    assert!(!coordinates_of_points(&[
        (Corner::E, 2, 2),
        (Corner::B, 2, 2)
    ]));
    // The claim's sentence is written from the same table, in the note's wording.
    assert_eq!(
        coordinates_sentence(&PRINTED_COORDINATES[1..]),
        "C = (0, 2y_cm), D = (2x_cm, 0), E = (2x_cm, 2y_cm)"
    );
}

/// `Claim::verdict` in words: a false printed wording is called imprecise only when it is
/// marked so, a claim that holds is "holds", and a check that does not come out as recorded
/// is FAILED.
#[test]
fn claim_verdict_names_an_imprecise_erratum_only_when_marked() {
    use sliding_ladder::verify::claims::Claim;
    let wrong = Claim::erratum("A.5", "a claim", ("printed", "corrected"), true, true);
    let (plain, imprecise) = (wrong.verdict(), wrong.clone().imprecise().verdict());
    assert!(
        plain.starts_with("PROSE ERRATUM") && !plain.contains("imprecise"),
        "{plain}"
    );
    assert!(imprecise.contains("(imprecise)"), "{imprecise}");
    assert_eq!(Claim::checked("2.1", "a claim", true).verdict(), "holds");
    assert_eq!(Claim::checked("2.1", "a claim", false).verdict(), "FAILED");
    // A printed wording that does not fail is not an erratum as recorded.
    let unproven = Claim::erratum("A.5", "a claim", ("printed", "corrected"), true, false);
    assert_eq!(unproven.verdict(), "FAILED");
}

/// The claims' exact states are general: m, l, g positive in each, and tan(θ/2) (the sign of
/// sin θ), θ̇, θ̈ and θ⃛ each positive in one state and negative in another, so a claim that
/// holds for one sign of a rate only is exposed.
#[test]
fn states_take_both_signs_of_every_rate() {
    use sliding_ladder::registry::sample::LadderSample;
    use sliding_ladder::verify::claims::states;
    let all = states(LadderSample::Kinematic);
    assert_eq!(all.len(), 3);
    for (l, _) in &all {
        assert!(l.m.to_f64() > 0.0 && l.l.to_f64() > 0.0 && l.g.to_f64() > 0.0);
    }
    let signs = |f: fn(&sliding_ladder::ladder::State<Rational>) -> f64| {
        let v: Vec<f64> = all.iter().map(|(_, s)| f(s)).collect();
        (v.iter().any(|x| *x > 0.0), v.iter().any(|x| *x < 0.0))
    };
    assert_eq!(signs(|s| s.sin.to_f64()), (true, true), "sin θ");
    assert_eq!(signs(|s| s.rate.to_f64()), (true, true), "θ̇");
    assert_eq!(signs(|s| s.accel.to_f64()), (true, true), "θ̈");
    assert_eq!(signs(|s| s.jerk.to_f64()), (true, true), "θ⃛");
}

/// The appendix claims' exact systems are general, as their doc says: three systems of three
/// particles, every mass positive; every position, velocity, acceleration and jerk component
/// positive for some particle and negative for another; every component of P's position,
/// velocity, acceleration and jerk nonzero in each system and of both signs among them; no two
/// particles of a system at one place; and the three systems different. A claim that holds only
/// where one of these vanishes (P at rest, a particle unaccelerated) or keeps one sign is
/// exposed by them. (This test found a_P's z component zero in all three systems before the
/// draw was changed: a claim true only for a_P in the plane of x and y passed.)
#[test]
fn general_systems_are_general() {
    use sliding_ladder::vector::Vec3;
    use sliding_ladder::verify::claims::appendix::general_systems;
    let systems = general_systems();
    assert_eq!(systems.len(), 3);
    let comps = |v: &Vec3<Rational>| [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()];
    let both_signs =
        |values: Vec<f64>| values.iter().any(|x| *x > 0.0) && values.iter().any(|x| *x < 0.0);
    for (s, p) in &systems {
        assert_eq!(s.particles.len(), 3);
        assert!(s.particles.iter().all(|q| q.m.to_f64() > 0.0), "a mass ≤ 0");
        for (name, v) in [("v_P", &p.v), ("a_P", &p.a), ("j_P", &p.j)] {
            assert!(*v != Vec3::zero(), "{name} = 0: P is not moving generally");
        }
        for (i, a) in s.particles.iter().enumerate() {
            for b in &s.particles[i + 1..] {
                assert!(a.x != b.x, "two particles at one place");
            }
        }
    }
    // x, v, a and j of each particle and of P, in that order.
    let names = ["x", "v", "a", "j"];
    for (q, name) in names.iter().enumerate() {
        for k in 0..3 {
            let particles = systems
                .iter()
                .flat_map(|(s, _)| s.particles.iter())
                .map(|p| comps([&p.x, &p.v, &p.a, &p.j][q])[k])
                .collect();
            assert!(
                both_signs(particles),
                "{name}, component {k}: one sign only"
            );
            let point: Vec<f64> = systems
                .iter()
                .map(|(_, p)| comps([&p.x, &p.v, &p.a, &p.j][q])[k])
                .collect();
            assert!(
                point.iter().all(|x| *x != 0.0),
                "{name}_P, component {k}: 0 in a system"
            );
            assert!(both_signs(point), "{name}_P, component {k}: one sign only");
        }
    }
    assert!(systems[0].0.particles[0].x != systems[1].0.particles[0].x);
    assert!(systems[1].0.particles[0].x != systems[2].0.particles[0].x);
}

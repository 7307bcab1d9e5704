//! Appendix B (Milne, chap. 8), eqs. (64)-(90): every registered check holds, every side of every
//! chain is load-bearing (perturbing it is detected), and every statement restricted to a special
//! instant or system fails on general systems.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::registry::check::{exact_residual, run_check, Config};
use sliding_ladder::registry::sample::{particle_system, ParticleSample, EXTRA, PER_PARTICLE};
use sliding_ladder::registry::{equations, Chain, Equation, Eval, ParticleFns, Role};
use sliding_ladder::scalar::{Rational, Scalar};

const NUMBERS: std::ops::RangeInclusive<u32> = 64..=90;

fn milne_entries() -> Vec<Equation> {
    equations()
        .into_iter()
        .filter(|e| NUMBERS.contains(&e.number))
        .collect()
}

/// The particle checks of an entry (all of Appendix B's are particle checks).
fn particle_checks(e: &Equation) -> Vec<(&'static str, ParticleSample, ParticleFns)> {
    e.checks
        .iter()
        .map(|c| match c.eval {
            Eval::Particles(sample, f) => (c.name, sample, f),
            Eval::Ladder(..) | Eval::Floor(..) => {
                panic!("({}) {}: not a particle check", e.number, c.name)
            }
        })
        .collect()
}

/// Random exact inputs: n particles, integer coordinates of up to 40 bits, positive masses.
fn exact_values(rng: &mut impl Rng) -> (usize, Vec<Rational>) {
    let n = rng.gen_range(1..=5);
    let big = 1i64 << 40;
    let values = (0..n * PER_PARTICLE + EXTRA)
        .map(|i| {
            let v = if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                rng.gen_range(1..big)
            } else {
                rng.gen_range(-big..=big)
            };
            Rational::int(v)
        })
        .collect();
    (n, values)
}

fn exact_chains(
    f: &ParticleFns,
    sample: ParticleSample,
    rng: &mut impl Rng,
) -> Vec<Chain<Rational>> {
    let (n, values) = exact_values(rng);
    let (sys, p) = particle_system(sample, n, &values);
    (f.exact)(&sys, &p)
}

#[test]
fn every_number_from_64_to_90_is_registered_once() {
    let found: Vec<u32> = milne_entries().iter().map(|e| e.number).collect();
    assert_eq!(found, NUMBERS.collect::<Vec<_>>());
    for e in milne_entries() {
        assert!(!e.checks.is_empty(), "({}) has no check", e.number);
        assert!(!e.functions.is_empty(), "({}) names no function", e.number);
        assert!(e.section.starts_with("B."), "({}) section", e.number);
    }
}

#[test]
fn every_check_holds() {
    let cfg = Config {
        float_cases: 300,
        exact_points: 3,
        seed: 1948,
    };
    for e in milne_entries() {
        for c in &e.checks {
            let rep = run_check(c, &cfg);
            let what = format!("({}) {}: {rep:?}", e.number, c.name);
            if std::env::var("MILNE_SHOW").is_ok() {
                eprintln!(
                    "({}) res {:.3} deg {} sz {:.1e} {}",
                    e.number, rep.max_scaled_residual, rep.degree, rep.sz_bound, rep.worst_side
                );
            }
            assert!(rep.passed(), "{what}");
            assert_eq!(rep.float_cases, 300, "{what}");
            assert_eq!(rep.exact_failures, 0, "{what}");
            assert!(rep.sz_bound < 1e-30, "{what}");
        }
    }
}

#[test]
fn perturbing_any_side_is_detected() {
    let mut rng = ChaCha8Rng::seed_from_u64(301);
    let tiny = Rational::ratio(1, 1_000_000_007);
    let mut perturbed_sides = 0;
    for e in milne_entries() {
        for (name, sample, f) in particle_checks(&e) {
            let chains = exact_chains(&f, sample, &mut rng);
            let (ok, misprints) = exact_residual(&chains);
            assert!(ok, "({}) {name}: unperturbed chains must hold", e.number);
            assert!(misprints.iter().all(|m| m.1), "({}) {name}", e.number);
            for (ci, chain) in chains.iter().enumerate() {
                let load_bearing = chain.iter().filter(|s| s.role != Role::Misprint).count();
                assert!(load_bearing >= 2, "({}) {name}: chain {ci}", e.number);
                for (si, side) in chain.iter().enumerate() {
                    if side.role == Role::Misprint {
                        continue;
                    }
                    let mut bad = chains.clone();
                    bad[ci][si].value = side.value.clone() + tiny.clone();
                    let (still_ok, _) = exact_residual(&bad);
                    assert!(
                        !still_ok,
                        "({}) {name}: perturbing '{}' went unnoticed",
                        e.number, side.label
                    );
                    perturbed_sides += 1;
                }
            }
        }
    }
    // Each of the 27 equations has at least one vector chain (three components) of two sides.
    assert!(perturbed_sides >= 27 * 3 * 2, "{perturbed_sides}");
}

#[test]
fn the_misprint_of_68_is_wrong_and_its_correction_right() {
    let e = milne_entries()
        .into_iter()
        .find(|e| e.number == 68)
        .unwrap();
    let erratum = e.erratum.expect("(68) carries an erratum");
    assert!(erratum.printed.contains(r"\wedge \ddot"));
    assert!(erratum.corrected.contains(r"\wedge m \ddot"));
    let mut rng = ChaCha8Rng::seed_from_u64(296);
    let (_, sample, f) = particle_checks(&e)[0];
    let chains = exact_chains(&f, sample, &mut rng);
    let roles: Vec<Role> = chains[0].iter().map(|s| s.role).collect();
    assert!(roles.contains(&Role::Misprint) && roles.contains(&Role::Corrected));
    let (ok, misprints) = exact_residual(&chains);
    assert!(ok, "the corrected form must agree with τ");
    assert!(misprints.iter().all(|m| m.1), "the printed form must fail");
    // With every mass 1 the printed form happens to agree: the missing factor is the mass.
    let (n, mut values) = exact_values(&mut rng);
    for k in 0..n {
        values[k * PER_PARTICLE] = Rational::int(1);
    }
    let (sys, p) = particle_system(sample, n, &values);
    let (_, misprints) = exact_residual(&(f.exact)(&sys, &p));
    assert!(misprints.iter().all(|m| !m.1), "unit masses: {misprints:?}");
    // No other entry of Appendix B is an erratum.
    let others = milne_entries()
        .into_iter()
        .filter(|e| e.number != 68 && e.erratum.is_some())
        .count();
    assert_eq!(others, 0);
}

#[test]
fn restricted_statements_fail_on_general_systems() {
    let mut rng = ChaCha8Rng::seed_from_u64(303);
    let mut restricted = Vec::new();
    for e in milne_entries() {
        for (name, sample, f) in particle_checks(&e) {
            if sample == ParticleSample::General {
                continue;
            }
            restricted.push(e.number);
            for _ in 0..3 {
                let chains = exact_chains(&f, ParticleSample::General, &mut rng);
                let (ok, _) = exact_residual(&chains);
                assert!(!ok, "({}) {name} held on a general system", e.number);
            }
        }
    }
    restricted.dedup();
    assert_eq!(restricted, vec![70, 71, 84, 86, 87, 88, 89, 90]);
}

#[test]
fn eqs_87_and_88_need_the_centre_of_mass_at_the_origin() {
    // P riding on the centre of mass is not enough: the restriction x_cm = 0 is load-bearing,
    // since dL/dt − dL_cm/dt = x_cm × m a_cm.
    let mut rng = ChaCha8Rng::seed_from_u64(304);
    for e in milne_entries()
        .into_iter()
        .filter(|e| [87, 88].contains(&e.number))
    {
        let (name, sample, f) = particle_checks(&e)[0];
        assert_eq!(sample, ParticleSample::CmAtOriginPAtCm);
        for _ in 0..3 {
            let (ok, _) = exact_residual(&exact_chains(&f, ParticleSample::PAtCm, &mut rng));
            assert!(
                !ok,
                "({}) {name} held with the centre of mass off the origin",
                e.number
            );
        }
    }
}

//! Every identity of the registry at random states: floats within their error bound (1000+
//! cases per identity), exact rationals with zero residual.

use proptest::prelude::*;
use sliding_ladder::registry::check::{
    exact_residual, ladder_exact_chains, ladder_float_case, particle_exact_chains,
    particle_float_case, TOLERANCE_FACTOR,
};
use sliding_ladder::registry::{equations, Eval};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(1000)))]

    #[test]
    fn ladder_identities_hold_in_floats(raw in crate::common::raw_ladder()) {
        for e in equations() {
            for c in &e.checks {
                if let Eval::Ladder(sort, f) = c.eval {
                    let (scaled, side) = ladder_float_case(sort, &f, &raw);
                    prop_assert!(scaled <= TOLERANCE_FACTOR, "({}) {}: '{side}' off by {scaled:.3} error bounds at {raw:?}", e.number, c.name);
                }
            }
        }
    }

    #[test]
    fn particle_identities_hold_in_floats(raw in crate::common::raw_particles()) {
        for e in equations() {
            for c in &e.checks {
                if let Eval::Particles(sort, f) = c.eval {
                    let (scaled, side) = particle_float_case(sort, &f, &raw);
                    prop_assert!(scaled <= TOLERANCE_FACTOR, "({}) {}: '{side}' off by {scaled:.3} error bounds", e.number, c.name);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(32)))]

    #[test]
    fn ladder_identities_hold_exactly(ints in crate::common::exact_ladder_ints()) {
        for e in equations() {
            for c in &e.checks {
                if let Eval::Ladder(sort, f) = c.eval {
                    let (all_equal, misprints) = exact_residual(&ladder_exact_chains(sort, &f, ints));
                    prop_assert!(all_equal, "({}) {}: nonzero exact residual at {ints:?}", e.number, c.name);
                    for (label, differs) in misprints {
                        prop_assert!(differs, "({}) misprint '{label}' held at {ints:?}", e.number);
                    }
                }
            }
        }
    }

    #[test]
    fn particle_identities_hold_exactly((n, ints) in crate::common::exact_particle_ints()) {
        for e in equations() {
            for c in &e.checks {
                if let Eval::Particles(sort, f) = c.eval {
                    let (all_equal, misprints) = exact_residual(&particle_exact_chains(sort, &f, n, &ints));
                    prop_assert!(all_equal, "({}) {}: nonzero exact residual", e.number, c.name);
                    for (label, differs) in misprints {
                        prop_assert!(differs, "({}) misprint '{label}' held", e.number);
                    }
                }
            }
        }
    }
}

/// Planted float cases: a particle identity off by a factor 2 (2 m₁ = m₁) and a ladder one
/// (2 m = m) are reported far past the threshold, naming the side that differs from the first;
/// the true halves (m₁ = m₁, m = m) at 0. The proptests above read these helpers, so the
/// helpers must be able to fail.
mod planted_float {
    use sliding_ladder::ladder::{Ladder, State};
    use sliding_ladder::registry::{printed, reference, Chain};
    use sliding_ladder::scalar::Scalar;
    use sliding_ladder::system::{Point, System};

    pub fn doubled_mass<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Vec<Chain<S>> {
        let m1 = sys.particles[0].m.clone();
        vec![
            vec![printed("m₁", m1.clone()), reference("m₁ again", m1.clone())],
            vec![printed("2m₁", S::int(2) * m1.clone()), reference("m₁", m1)],
        ]
    }
    pub fn doubled_ladder<S: Scalar>(l: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
        vec![
            vec![printed("m", l.m.clone()), reference("m again", l.m.clone())],
            vec![
                printed("2m", S::int(2) * l.m.clone()),
                reference("m", l.m.clone()),
            ],
        ]
    }
}

#[test]
fn float_cases_report_a_planted_wrong_side_past_the_threshold() {
    use rand::SeedableRng;
    use sliding_ladder::registry::sample::{LadderSample, ParticleSample, RawLadder, RawParticles};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(12);
    for _ in 0..5 {
        let raw = RawParticles::draw(&mut rng);
        let f = sliding_ladder::particle_fns!(planted_float::doubled_mass);
        let (scaled, side) = particle_float_case(ParticleSample::General, &f, &raw);
        assert!(scaled > 1e6 * TOLERANCE_FACTOR, "{scaled}");
        assert_eq!(side, "m₁");
        let raw = RawLadder::draw(&mut rng);
        let f = sliding_ladder::ladder_fns!(planted_float::doubled_ladder);
        let (scaled, side) = ladder_float_case(LadderSample::Kinematic, &f, &raw);
        assert!(scaled > 1e6 * TOLERANCE_FACTOR, "{scaled}");
        assert_eq!(side, "m");
    }
}

/// The exact-chain helpers the exact proptests read evaluate a check at the integers given:
/// the planted 2m = m at m = 3 gives the chains (3, 3) and (6, 3); 2m₁ = m₁ with m₁ = 4 gives
/// (4, 4) and (8, 4) (by hand; the other integers do not enter).
#[test]
fn exact_chain_helpers_evaluate_at_the_integers_given() {
    use sliding_ladder::registry::sample::{LadderSample, ParticleSample, EXTRA, PER_PARTICLE};
    use sliding_ladder::scalar::{Rational, Scalar};
    let values = |chains: &[sliding_ladder::registry::Chain<Rational>]| -> Vec<Vec<Rational>> {
        chains
            .iter()
            .map(|c| c.iter().map(|s| s.value.clone()).collect())
            .collect()
    };
    let q = |n: i64| <Rational as Scalar>::int(n);
    let f = sliding_ladder::ladder_fns!(planted_float::doubled_ladder);
    let ladder = ladder_exact_chains(LadderSample::Kinematic, &f, [2, 3, 5, 7, 11, 13, 17]);
    assert_eq!(values(&ladder), vec![vec![q(3), q(3)], vec![q(6), q(3)]]);
    assert!(!exact_residual(&ladder).0);
    let mut ints = vec![1; PER_PARTICLE + EXTRA];
    ints[0] = 4;
    let f = sliding_ladder::particle_fns!(planted_float::doubled_mass);
    let particles = particle_exact_chains(ParticleSample::General, &f, 1, &ints);
    assert_eq!(values(&particles), vec![vec![q(4), q(4)], vec![q(8), q(4)]]);
    assert!(!exact_residual(&particles).0);
}

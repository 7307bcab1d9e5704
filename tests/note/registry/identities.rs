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

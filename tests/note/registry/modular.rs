//! The modular fast path of the exact checks (issue 10, item 4): every check evaluated modulo
//! p = 2⁶¹ − 1 gives the residues of its exact rational values, a perturbed side fails mod p, and
//! `run_check`'s modular points catch a false identity, fall back to rationals where a
//! denominator vanishes mod p, and fail a division by an exact zero.

use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::ladder_fns;
use sliding_ladder::registry::check::{exact_residual, run_check, Config, RATIONAL_POINTS};
use sliding_ladder::registry::sample::{
    exact_ladder, floor_state, particle_system, LadderSample, EXTRA, PER_PARTICLE,
};
use sliding_ladder::registry::{
    equations, extensions, printed, reference, Chain, Check, Eval, Role,
};
use sliding_ladder::scalar::{Modp, Rational, Scalar, MODULUS};

const INTS: [i64; 7] = [
    981_234_567_123,
    -77_123_456_789,
    29_876_543,
    1_134_567_891_011,
    -571_113_171_923,
    131_071,
    -(1 << 59) + 47,
];
const MOTION: [i64; 4] = [5_123_456_789, -3, 1 << 58, -7_777_777_777];

fn particle_ints(n: usize) -> Vec<i64> {
    (0..n * PER_PARTICLE + EXTRA)
        .map(|i| {
            let v = (i as i64 + 3) * 1_000_000_007 % 2_147_483_647;
            if i % PER_PARTICLE == 0 && i < n * PER_PARTICLE {
                v.abs() + 1
            } else {
                v - 1_000_000_000
            }
        })
        .collect()
}

/// The chains of check `c` in `S`, on shell as its sort says and (on-shell sorts) off shell.
fn chains_of<S: Scalar>(c: &Check, pick: impl Fn(&Eval) -> Vec<Vec<Chain<S>>>) -> Vec<Chain<S>> {
    pick(&c.eval).into_iter().flatten().collect()
}

fn rational(e: &Eval) -> Vec<Vec<Chain<Rational>>> {
    let q = |v: i64| Rational::int(v);
    match *e {
        Eval::Ladder(sort, f) => {
            let mut out = vec![];
            for s in [sort, LadderSample::Kinematic] {
                let (l, st) = exact_ladder(s, INTS.map(q));
                out.push((f.exact)(&l, &st));
            }
            out
        }
        Eval::Floor(sort, f) => {
            let (l, s0) = exact_ladder(LadderSample::Kinematic, INTS.map(q));
            let (s, x) = floor_state(sort, &l, s0, MOTION.map(q));
            vec![(f.exact)(&l, &s, &x)]
        }
        Eval::Particles(sort, f) => {
            let v: Vec<Rational> = particle_ints(3).into_iter().map(q).collect();
            let (sys, p) = particle_system(sort, 3, &v);
            vec![(f.exact)(&sys, &p)]
        }
    }
}

fn modular(e: &Eval) -> Vec<Vec<Chain<Modp>>> {
    let q = |v: i64| Modp::int(v);
    match *e {
        Eval::Ladder(sort, f) => {
            let mut out = vec![];
            for s in [sort, LadderSample::Kinematic] {
                let (l, st) = exact_ladder(s, INTS.map(q));
                out.push((f.modular)(&l, &st));
            }
            out
        }
        Eval::Floor(sort, f) => {
            let (l, s0) = exact_ladder(LadderSample::Kinematic, INTS.map(q));
            let (s, x) = floor_state(sort, &l, s0, MOTION.map(q));
            vec![(f.modular)(&l, &s, &x)]
        }
        Eval::Particles(sort, f) => {
            let v: Vec<Modp> = particle_ints(3).into_iter().map(q).collect();
            let (sys, p) = particle_system(sort, 3, &v);
            vec![(f.modular)(&sys, &p)]
        }
    }
}

fn every_check() -> Vec<(u32, Check)> {
    equations()
        .into_iter()
        .chain(extensions())
        .flat_map(|e| e.checks.into_iter().map(move |c| (e.number, c)))
        .collect()
}

/// Every side of every check, on and off shell: the residue mod p is the reduced rational value.
#[test]
fn every_side_is_the_residue_of_its_rational_value() {
    let mut sides = 0;
    for (n, c) in every_check() {
        let (exact, fast) = (chains_of(&c, rational), chains_of(&c, modular));
        assert_eq!(exact.len(), fast.len());
        for (ce, cm) in exact.iter().zip(&fast) {
            for (se, sm) in ce.iter().zip(cm) {
                assert_eq!(se.label, sm.label);
                assert!(sm.value.is_defined(), "({n}) {}: {}", c.name, sm.label);
                assert_eq!(
                    Modp::of_rational(&se.value),
                    sm.value,
                    "({n}) {}: {}",
                    c.name,
                    se.label
                );
                sides += 1;
            }
        }
    }
    assert!(sides > 500, "only {sides} sides compared");
}

/// Mod p the checks hold and can fail: every non-misprint side plus one breaks its chain; every
/// misprint differs.
#[test]
fn every_modular_chain_holds_and_a_perturbed_side_fails() {
    for (n, c) in every_check() {
        let chains = &modular(&c.eval)[0];
        let (ok, misprints) = exact_residual(chains);
        assert!(ok, "({n}) {} fails mod p", c.name);
        assert!(misprints.iter().all(|m| m.1), "({n}) {}", c.name);
        for (ci, chain) in chains.iter().enumerate() {
            for (k, side) in chain.iter().enumerate() {
                if side.role == Role::Misprint || chain.len() < 2 {
                    continue;
                }
                let mut bad = chains.clone();
                bad[ci][k].value = side.value + Modp::int(1);
                assert!(
                    !exact_residual(&bad).0,
                    "({n}) {}: {} + 1 passes",
                    c.name,
                    side.label
                );
            }
        }
    }
}

/// sin²θ + cos²θ = 1, multiplied and divided by p (nonzero in rationals, zero mod p).
fn through_p<S: Scalar>(_: &Ladder<S>, st: &State<S>) -> Vec<Chain<S>> {
    let p = S::int(MODULUS as i64);
    let unit = st.sin.clone() * st.sin.clone() + st.cos.clone() * st.cos.clone();
    vec![vec![
        printed("(s² + c²)·p/p", unit * p.clone() / p),
        reference("1", S::int(1)),
    ]]
}

/// A false identity: sin²θ + 2 cos²θ = 1.
fn false_identity<S: Scalar>(_: &Ladder<S>, st: &State<S>) -> Vec<Chain<S>> {
    let two_c2 = S::int(2) * st.cos.clone() * st.cos.clone();
    vec![vec![
        printed("s² + 2c²", st.sin.clone() * st.sin.clone() + two_c2),
        reference("1", S::int(1)),
    ]]
}

/// A division by an exact zero: (m − m)/(m − m) = 1.
fn by_zero<S: Scalar>(l: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
    let z = l.m.clone() - l.m.clone();
    vec![vec![
        printed("0/0", z.clone() / z),
        reference("1", S::int(1)),
    ]]
}

fn run(name: &'static str, f: sliding_ladder::registry::LadderFns, points: usize) -> usize {
    let check = Check {
        name,
        eval: Eval::Ladder(LadderSample::Kinematic, f),
    };
    let cfg = Config {
        float_cases: 0,
        exact_points: points,
        seed: 7,
    };
    let rep = run_check(&check, &cfg);
    assert_eq!(rep.exact_points, points);
    rep.exact_failures
}

#[test]
fn run_check_modular_points_fail_fall_back_and_hold() {
    let points = RATIONAL_POINTS + 6;
    // Every point of a false identity fails, the modular ones included.
    assert_eq!(run("false", ladder_fns!(false_identity), points), points);
    // A denominator that vanishes mod p only: redone in rationals, where the identity holds.
    assert_eq!(run("through p", ladder_fns!(through_p), points), 0);
    // A division by an exact zero fails everywhere (undefined mod p, a panic in rationals).
    assert_eq!(run("by zero", ladder_fns!(by_zero), points), points);
}

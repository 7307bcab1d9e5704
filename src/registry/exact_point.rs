//! The exact points of a check: random integers, evaluated in rationals or modulo a prime.
//!
//! A point is a set of random integers below 2⁶⁰ in magnitude (see
//! [`EXACT_HEIGHT`]), turned into a state by the generic builders of
//! [`super::sample`] in the number type it is evaluated in: [`Rational`] (exact), or [`Modp`]
//! (exact modulo p = 2⁶¹ − 1, the fast path; a point where a denominator vanishes mod p gives an
//! undefined residue, and is then redone in rationals). [`super::check`] says which points are
//! which and what the bound is.

use super::sample::{exact_ladder, floor_state, particle_system, LadderSample, ParticleSample};
use super::sample::{EXTRA, LADDER_DRAWS, PER_PARTICLE};
use super::{Chain, FloorChains, LadderChains, ParticleChains, Role};
use crate::scalar::{Modp, Rational, Scalar};
use num_traits::Zero;
use rand::Rng;

/// Exact coordinates are integers of magnitude below this, 2⁶⁰: every sample set then lies in an
/// interval of at most 2⁶¹ − 1 integers, whose residues modulo p = 2⁶¹ − 1 are distinct.
pub const EXACT_HEIGHT: i64 = 1 << 60;
/// The smallest sample set, the positive coordinates (masses, m, l, g) 1..2⁶⁰: 2⁶⁰ − 1 elements.
pub const EXACT_SET_SIZE: f64 = 1_152_921_504_606_846_975.0;
/// Exact points per check evaluated in rationals (the first ones); the rest are evaluated mod p.
pub const RATIONAL_POINTS: usize = 1;

/// Exact verdict, in rationals or residues: (every non-misprint side equal to the first, per
/// misprint side whether it differs).
pub fn exact_residual<S: Scalar + Zero>(chains: &[Chain<S>]) -> (bool, Vec<(&'static str, bool)>) {
    let mut all_equal = true;
    let mut misprints = Vec::new();
    for c in chains {
        let Some(base) = c.iter().position(|s| s.role != Role::Misprint) else {
            continue;
        };
        for s in c {
            let differs = !(s.value.clone() - c[base].value.clone()).is_zero();
            if s.role == Role::Misprint {
                misprints.push((s.label, differs));
            } else if differs {
                all_equal = false;
            }
        }
    }
    (all_equal, misprints)
}

/// A signed coordinate, |v| < 2⁶⁰.
pub(crate) fn signed(rng: &mut impl Rng) -> i64 {
    rng.gen_range(1 - EXACT_HEIGHT..EXACT_HEIGHT)
}

/// A positive coordinate, 0 < v < 2⁶⁰.
fn positive(rng: &mut impl Rng) -> i64 {
    rng.gen_range(1..EXACT_HEIGHT)
}

/// The integers of an exact ladder point: t, θ̇ nonzero; m, l, g positive; θ̈, θ⃛ any.
pub(crate) fn exact_ladder_ints(rng: &mut impl Rng) -> [i64; LADDER_DRAWS] {
    let mut signed_nonzero = || loop {
        let v = signed(rng);
        if v != 0 {
            break v;
        }
    };
    let (t, rate) = (signed_nonzero(), signed_nonzero());
    let (m, l, g) = (positive(rng), positive(rng), positive(rng));
    let (accel, jerk) = (signed(rng), signed(rng));
    [t, m, l, g, rate, accel, jerk]
}

/// An exact ladder point in rationals.
pub(crate) fn exact_ladder_draw(rng: &mut impl Rng) -> [Rational; LADDER_DRAWS] {
    exact_ladder_ints(rng).map(Rational::int)
}

/// The integers of an exact particle point: the number of particles (1..=8) and the values
/// (masses positive).
pub fn exact_particle_ints(rng: &mut impl Rng) -> (usize, Vec<i64>) {
    let n = rng.gen_range(1..=8);
    let values = (0..n * PER_PARTICLE + EXTRA)
        .map(|i| {
            if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                positive(rng)
            } else {
                signed(rng)
            }
        })
        .collect();
    (n, values)
}

/// An exact particle point in rationals.
pub(crate) fn exact_particle_draw(rng: &mut impl Rng) -> (usize, Vec<Rational>) {
    let (n, ints) = exact_particle_ints(rng);
    (n, ints.into_iter().map(Rational::int).collect())
}

/// An exact number type a point is evaluated in.
pub(crate) trait Exact: Scalar + Zero {
    /// False where the value is undefined (a residue after a division by zero mod p).
    fn defined(&self) -> bool {
        true
    }
}

impl Exact for Rational {}

impl Exact for Modp {
    fn defined(&self) -> bool {
        self.is_defined()
    }
}

/// What one exact point found.
#[derive(Default)]
pub(crate) struct PointVerdict {
    /// Every non-misprint side equal to the first.
    pub ok: bool,
    /// Per misprint, whether it differs.
    pub misprints: Vec<(&'static str, bool)>,
    /// On shell, the same point off the motion: (all chains held, where they break).
    pub off: Option<(bool, Option<Vec<u32>>)>,
}

/// Evaluate chains, a panic (a division by an exact zero, say, in a user's method) giving `Err`
/// and an undefined residue `Ok(None)`.
fn chains_at<S: Exact>(f: impl FnOnce() -> Vec<Chain<S>>) -> Result<Option<Vec<Chain<S>>>, ()> {
    let c = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).map_err(|_| ())?;
    Ok(c.iter().flatten().all(|s| s.value.defined()).then_some(c))
}

/// The verdict at chains evaluated on and (on shell) off the motion; `None` when a value is
/// undefined, so that the point is redone in rationals.
fn verdict<S: Exact>(
    on: impl FnOnce() -> Vec<Chain<S>>,
    off: Option<impl FnOnce() -> Vec<Chain<S>>>,
) -> Option<PointVerdict> {
    let (ok, misprints) = match chains_at(on) {
        Ok(Some(c)) => exact_residual(&c),
        Ok(None) => return None,
        Err(()) => (false, Vec::new()),
    };
    let off = match off.map(chains_at) {
        None => None,
        Some(Ok(Some(c))) => Some((exact_residual(&c).0, Some(super::law::breaks(&c)))),
        Some(Ok(None)) => return None,
        Some(Err(())) => Some((false, None)),
    };
    Some(PointVerdict { ok, misprints, off })
}

/// Point `k` of a check: modulo p past the first [`RATIONAL_POINTS`] (when defined there),
/// otherwise in rationals.
pub(crate) fn at_point(
    k: usize,
    modular: impl FnOnce() -> Option<PointVerdict>,
    rational: impl FnOnce() -> Option<PointVerdict>,
) -> PointVerdict {
    let fast = if k >= RATIONAL_POINTS {
        modular()
    } else {
        None
    };
    fast.or_else(rational).unwrap_or_default()
}

pub(crate) fn ladder_point<S: Exact>(
    sort: LadderSample,
    f: LadderChains<S>,
    ints: [i64; LADDER_DRAWS],
) -> Option<PointVerdict> {
    let (l, s) = exact_ladder(sort, ints.map(S::int));
    let off = sort.on_shell().then(|| {
        let (lk, sk) = exact_ladder(LadderSample::Kinematic, ints.map(S::int));
        move || f(&lk, &sk)
    });
    verdict(|| f(&l, &s), off)
}

pub(crate) fn floor_point<S: Exact>(
    sort: LadderSample,
    f: FloorChains<S>,
    ints: [i64; LADDER_DRAWS],
    motion: [i64; 4],
) -> Option<PointVerdict> {
    let (l, s0) = exact_ladder(LadderSample::Kinematic, ints.map(S::int));
    let (s, x) = floor_state(sort, &l, s0.clone(), motion.map(S::int));
    let off = sort.on_shell().then(|| {
        let (sk, xk) = floor_state(LadderSample::Kinematic, &l, s0, motion.map(S::int));
        let l = l.clone();
        move || f(&l, &sk, &xk)
    });
    verdict(|| f(&l, &s, &x), off)
}

pub(crate) fn particle_point<S: Exact>(
    sort: ParticleSample,
    f: ParticleChains<S>,
    n: usize,
    ints: &[i64],
) -> Option<PointVerdict> {
    let values: Vec<S> = ints.iter().map(|&v| S::int(v)).collect();
    let (sys, p) = particle_system(sort, n, &values);
    verdict(|| f(&sys, &p), None::<fn() -> Vec<Chain<S>>>)
}

//! Running the checks: floats against an error model, exact points with zero residual, and the
//! Schwartz-Zippel bound of every exact check.
//!
//! Float verdict: a chain passes when every side differs from the first by at most
//! `TOLERANCE_FACTOR · u · (e_side + e_first)`, where `e` is the running error bound of each side
//! (see [`Bound`]); the reported residual is the largest difference in units of that bound.
//! `TOLERANCE_FACTOR = 4`: the bounds are first-order, and the f64 values take their derivatives
//! through num-dual while the bounds go through `Jet<Bound>`, whose operation order differs, so
//! the two evaluations can each be off by up to their own bound (factor 2), doubled for the
//! dropped second-order terms.
//!
//! Exact verdict: the coordinates of an exact point are random integers below 2⁶⁰ in magnitude.
//! The first [`RATIONAL_POINTS`] points of a check are evaluated in exact rationals; the others
//! modulo the prime p = 2⁶¹ − 1 ([`Modp`](crate::scalar::Modp)): a rational point spends most of
//! its time reducing fractions of thousands of bits (`ladder verify --cases 10000
//! --exact-points 100` took 153 s of CPU with rational points only, 12.6 s with modular ones). A
//! point where a denominator vanishes mod p is evaluated in rationals instead. A false identity
//! whose residual numerator has degree ≤ d passes one point with probability at most d/N,
//! N = [`EXACT_SET_SIZE`] (Schwartz-Zippel): at a rational point always, at a modular point when
//! p does not divide every coefficient of that numerator (see [`Modp`](crate::scalar::Modp)); the
//! sample sets lie in an interval shorter than p, so their residues are distinct.
//! [`CheckReport::sz_bound_log10`] is the bound over all points,
//! [`CheckReport::sz_bound_rational_log10`] over the rational points alone (any p).

use super::exact_point::{
    at_point, exact_ladder_ints, exact_particle_ints, floor_point, ladder_point, particle_point,
    signed,
};
pub(crate) use super::exact_point::{exact_ladder_draw, exact_particle_draw};
use super::sample::LADDER_DRAWS;
use super::sample::{
    exact_ladder, particle_system, LadderSample, ParticleSample, RawLadder, RawParticles,
};
use super::{Chain, Check, Eval, Role};
use crate::scalar::{Bound, Degree, Rational, Scalar, UNIT_ROUNDOFF};
use rand::Rng;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

// The exact points' constants and verdict live with the points (`exact_point`), which this
// module drives; re-exported here, where the rest of the crate looks for them.
pub use super::exact_point::{exact_residual, EXACT_HEIGHT, EXACT_SET_SIZE, RATIONAL_POINTS};

/// A float chain passes when its scaled residual is at most this.
pub const TOLERANCE_FACTOR: f64 = 4.0;
/// How much checking to do.
#[derive(Clone, Copy, Debug)]
pub struct Config {
    /// Random float states per check.
    pub float_cases: usize,
    /// Random exact points per check.
    pub exact_points: usize,
    /// Seed of the random states (reproducible runs).
    pub seed: u64,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            float_cases: 1000,
            exact_points: 3,
            seed: 2019,
        }
    }
}

/// What one check found.
#[derive(Clone, Debug, Default)]
pub struct CheckReport {
    /// The check's name.
    pub name: &'static str,
    /// Float states evaluated.
    pub float_cases: usize,
    /// Float states at which some chain exceeded its tolerance.
    pub float_failures: usize,
    /// Largest residual over all float states, in units of the error bound.
    pub max_scaled_residual: f64,
    /// Where the largest residual occurred (chain side label).
    pub worst_side: &'static str,
    /// Exact points evaluated.
    pub exact_points: usize,
    /// Exact points at which some chain had a nonzero residual.
    pub exact_failures: usize,
    /// Labels of misprinted sides, and whether each was shown to fail at every exact point.
    pub misprints: Vec<(&'static str, bool)>,
    /// Largest numerator degree of a residual (Schwartz-Zippel).
    pub degree: u32,
    /// Probability that a false identity passed all exact points: (degree/set size)^points.
    pub sz_bound: f64,
    /// log10 of `sz_bound` (finite where `sz_bound` underflows to 0).
    pub sz_bound_log10: f64,
    /// log10 of the bound from the rational points alone, which holds whatever the prime.
    pub sz_bound_rational_log10: f64,
    /// For on-shell checks: whether every exact off-shell point failed, as it must.
    pub off_shell_fails: Option<bool>,
    /// For on-shell ladder checks: the `=` of the display (counted from 1) at which the chain
    /// breaks off the motion, when it is the same at every exact point ([`super::law::breaks`]);
    /// `Some(vec![])` never happens for a passing on-shell check.
    pub off_motion_breaks: Option<Vec<u32>>,
}

impl CheckReport {
    /// True when the check holds as it should.
    pub fn passed(&self) -> bool {
        self.float_failures == 0
            && self.exact_failures == 0
            && self.misprints.iter().all(|m| m.1)
            && self.off_shell_fails != Some(false)
    }
}

/// The largest scaled residual of float chains (f64 values, `Bound` errors), and its side label.
pub fn float_residual(values: &[Chain<f64>], bounds: &[Chain<Bound>]) -> (f64, &'static str) {
    let mut worst = (0.0, "");
    for (cv, cb) in values.iter().zip(bounds) {
        let Some(base) = cv.iter().position(|s| s.role != Role::Misprint) else {
            continue;
        };
        for (i, (sv, sb)) in cv.iter().zip(cb).enumerate() {
            if i == base || sv.role == Role::Misprint {
                continue;
            }
            let diff = (sv.value - cv[base].value).abs();
            let tol = UNIT_ROUNDOFF * (sb.value.e + cb[base].value.e);
            let scaled = if diff == 0.0 {
                0.0
            } else if tol > 0.0 && diff.is_finite() {
                diff / tol
            } else {
                f64::INFINITY
            };
            if scaled.is_nan() || scaled > worst.0 {
                worst = (scaled, sv.label);
            }
        }
    }
    worst
}

/// The largest degree of a residual of the chains, evaluated in [`Degree`] (Schwartz-Zippel).
pub(crate) fn residual_degree(chains: &[Chain<Degree>]) -> u32 {
    let mut d = 0;
    for c in chains {
        for s in c {
            d = d.max((s.value - c[0].value).num);
        }
    }
    d
}

/// Run one check: its float states against the error model, its exact points, and the
/// Schwartz-Zippel bound those points give.
pub fn run_check(check: &Check, cfg: &Config) -> CheckReport {
    // Each check gets its own stream, derived from the seed and its name.
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed ^ fnv1a(check.name));
    let mut rep = CheckReport {
        name: check.name,
        ..Default::default()
    };
    let mut misprint_ok: Vec<(&'static str, bool)> = Vec::new();
    match check.eval {
        Eval::Ladder(sort, f) => run_ladder(sort, f, cfg, &mut rng, &mut rep, &mut misprint_ok),
        Eval::Floor(sort, f) => run_floor(sort, f, cfg, &mut rng, &mut rep, &mut misprint_ok),
        Eval::Particles(sort, f) => {
            run_particles(sort, f, cfg, &mut rng, &mut rep, &mut misprint_ok);
        }
    }
    rep.misprints = misprint_ok;
    schwartz_zippel(&mut rep);
    rep
}

/// The FNV-1a hash of a check's name: what makes each check's random stream its own.
fn fnv1a(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

/// Fold one exact point's misprints into the running list: a misprint is shown wrong only if it
/// differs at every point.
fn note_misprints(misprint_ok: &mut Vec<(&'static str, bool)>, found: Vec<(&'static str, bool)>) {
    for (k, (label, differs)) in found.into_iter().enumerate() {
        match misprint_ok.get_mut(k) {
            Some(m) => m.1 &= differs,
            None => misprint_ok.push((label, differs)),
        }
    }
}

/// A ladder check: float states of its sort, the residual degree, and exact points, with the
/// `=` at which an on-shell chain breaks off the motion (the law step, [`super::law`]).
fn run_ladder(
    sort: LadderSample,
    f: super::LadderFns,
    cfg: &Config,
    rng: &mut ChaCha8Rng,
    rep: &mut CheckReport,
    misprint_ok: &mut Vec<(&'static str, bool)>,
) {
    for _ in 0..cfg.float_cases {
        let ((l, s), (lb, sb)) = RawLadder::draw(rng).build(sort);
        record_float(rep, (f.float)(&l, &s), (f.bound)(&lb, &sb));
    }
    let degree_chains = {
        let (l, s) = exact_ladder(sort, [Degree::variable(); LADDER_DRAWS]);
        (f.degree)(&l, &s)
    };
    rep.degree = residual_degree(&degree_chains);
    let mut off_shell_all_fail = true;
    let mut breaks: Option<Option<Vec<u32>>> = None;
    for k in 0..cfg.exact_points {
        let ints = exact_ladder_ints(rng);
        let pt = at_point(
            k,
            || ladder_point(sort, f.modular, ints),
            || ladder_point(sort, f.exact, ints),
        );
        rep.exact_points += 1;
        rep.exact_failures += usize::from(!pt.ok);
        note_misprints(misprint_ok, pt.misprints);
        if let Some((ok_off, here)) = pt.off {
            off_shell_all_fail &= !ok_off;
            // Keep the breaks only while every point agrees.
            breaks = Some(match breaks {
                None => here,
                Some(prev) if prev == here => prev,
                Some(_) => None,
            });
        }
    }
    if sort.on_shell() {
        rep.off_shell_fails = Some(off_shell_all_fail);
        rep.off_motion_breaks = breaks.flatten();
    }
}

/// A floor-phase check: ladder states with the centre's motion (X, Ẋ, Ẍ, X⃛) drawn in units of
/// l and √(l/g), then the residual degree and exact points.
fn run_floor(
    sort: LadderSample,
    f: super::FloorFns,
    cfg: &Config,
    rng: &mut ChaCha8Rng,
    rep: &mut CheckReport,
    misprint_ok: &mut Vec<(&'static str, bool)>,
) {
    for _ in 0..cfg.float_cases {
        let raw = RawLadder::draw(rng);
        let ((l, s), (lb, sb)) = raw.build(LadderSample::Kinematic);
        let unit: [f64; 4] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
        let v = super::sample::floor_motion(unit, l.l, l.g);
        let (s, x) = super::sample::floor_state(sort, &l, s, v);
        let (sb, xb) = super::sample::floor_state(sort, &lb, sb, v.map(Bound::exact));
        record_float(rep, (f.float)(&l, &s, &x), (f.bound)(&lb, &sb, &xb));
    }
    let vars = [Degree::variable(); 4];
    let (ld, sd) = exact_ladder(LadderSample::Kinematic, [Degree::variable(); LADDER_DRAWS]);
    let (sd, xd) = super::sample::floor_state(sort, &ld, sd, vars);
    rep.degree = residual_degree(&(f.degree)(&ld, &sd, &xd));
    let mut off_shell_all_fail = true;
    for k in 0..cfg.exact_points {
        let ints = exact_ladder_ints(rng);
        let motion: [i64; 4] = std::array::from_fn(|_| signed(rng));
        let pt = at_point(
            k,
            || floor_point(sort, f.modular, ints, motion),
            || floor_point(sort, f.exact, ints, motion),
        );
        rep.exact_points += 1;
        rep.exact_failures += usize::from(!pt.ok);
        note_misprints(misprint_ok, pt.misprints);
        if let Some((ok_off, _)) = pt.off {
            off_shell_all_fail &= !ok_off;
        }
    }
    if sort.on_shell() {
        rep.off_shell_fails = Some(off_shell_all_fail);
    }
}

/// A particle check: float systems of its sort, then exact points, each with the residual
/// degree of its particle count.
fn run_particles(
    sort: ParticleSample,
    f: super::ParticleFns,
    cfg: &Config,
    rng: &mut ChaCha8Rng,
    rep: &mut CheckReport,
    misprint_ok: &mut Vec<(&'static str, bool)>,
) {
    for _ in 0..cfg.float_cases {
        let raw = RawParticles::draw(rng);
        let ((sys, p), (sysb, pb)) = super::sample::float_particles(sort, &raw);
        record_float(rep, (f.float)(&sys, &p), (f.bound)(&sysb, &pb));
    }
    // The degree depends on the number of particles only.
    let mut degree_of = [None; 9];
    for k in 0..cfg.exact_points {
        let (n, ints) = exact_particle_ints(rng);
        let pt = at_point(
            k,
            || particle_point(sort, f.modular, n, &ints),
            || particle_point(sort, f.exact, n, &ints),
        );
        rep.exact_points += 1;
        rep.exact_failures += usize::from(!pt.ok);
        note_misprints(misprint_ok, pt.misprints);
        let d = *degree_of[n].get_or_insert_with(|| {
            let vars = vec![Degree::variable(); ints.len()];
            let (sd, pd) = particle_system(sort, n, &vars);
            residual_degree(&(f.degree)(&sd, &pd))
        });
        rep.degree = rep.degree.max(d);
    }
}

/// The Schwartz-Zippel bound of the exact points evaluated: (degree / set size)^points, and its
/// log10 over all points and over the rational points alone.
fn schwartz_zippel(rep: &mut CheckReport) {
    let points = rep.exact_points;
    rep.sz_bound = (f64::from(rep.degree.max(1)) / EXACT_SET_SIZE).powi(points as i32);
    let per_point = (f64::from(rep.degree.max(1)) / EXACT_SET_SIZE).log10();
    rep.sz_bound_log10 = points as f64 * per_point;
    rep.sz_bound_rational_log10 = points.min(RATIONAL_POINTS) as f64 * per_point;
}

/// Fold one float state's chains (values and their error bounds) into a report: the state is
/// counted; it fails when its scaled residual ([`float_residual`]) exceeds [`TOLERANCE_FACTOR`]
/// or is NaN (a value that overflowed must not pass); the worst residual and its side are kept.
pub fn record_float(rep: &mut CheckReport, values: Vec<Chain<f64>>, bounds: Vec<Chain<Bound>>) {
    rep.float_cases += 1;
    let (scaled, label) = float_residual(&values, &bounds);
    if scaled.is_nan() || scaled > TOLERANCE_FACTOR {
        rep.float_failures += 1;
    }
    if scaled.is_nan() || scaled > rep.max_scaled_residual {
        rep.max_scaled_residual = scaled;
        rep.worst_side = label;
    }
}

/// One float case of a ladder check at a given raw state: (scaled residual, worst side).
pub fn ladder_float_case(
    sort: LadderSample,
    f: &super::LadderFns,
    raw: &RawLadder,
) -> (f64, &'static str) {
    let ((l, s), (lb, sb)) = raw.build(sort);
    float_residual(&(f.float)(&l, &s), &(f.bound)(&lb, &sb))
}

/// One float case of a particle check at a given raw system: (scaled residual, worst side).
pub fn particle_float_case(
    sort: ParticleSample,
    f: &super::ParticleFns,
    raw: &RawParticles,
) -> (f64, &'static str) {
    let ((sys, p), (sysb, pb)) = super::sample::float_particles(sort, raw);
    float_residual(&(f.float)(&sys, &p), &(f.bound)(&sysb, &pb))
}

/// The exact chains of a ladder check at seven given integers (t, m, l, g, θ̇, θ̈, θ⃛).
pub fn ladder_exact_chains(
    sort: LadderSample,
    f: &super::LadderFns,
    ints: [i64; LADDER_DRAWS],
) -> Vec<Chain<Rational>> {
    let (l, s) = exact_ladder(sort, ints.map(Rational::int));
    (f.exact)(&l, &s)
}

/// The exact chains of a particle check at given integers (`n·PER_PARTICLE + EXTRA` of them).
pub fn particle_exact_chains(
    sort: ParticleSample,
    f: &super::ParticleFns,
    n: usize,
    ints: &[i64],
) -> Vec<Chain<Rational>> {
    let values: Vec<Rational> = ints.iter().map(|&v| Rational::int(v)).collect();
    let (sys, p) = particle_system(sort, n, &values);
    (f.exact)(&sys, &p)
}

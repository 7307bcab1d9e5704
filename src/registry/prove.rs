//! Proofs: every check's chains evaluated in the symbolic scalar [`Sym`], at symbolic states.
//!
//! A ladder state is the variables themselves (s, c, m, l, g, θ̇, θ̈, θ⃛). On shell, θ̈ is
//! replaced by the equation of motion (5), 3g s/(4l) (the normal form modulo θ̈ − 3gs/(4l), whose
//! leading term is θ̈), as the exact sampler does; from rest upright, a difference is further
//! reduced modulo θ̇² = g (ml − Σ mᵢyᵢ)/(Σ mᵢvᵢ²/2 at θ̇ = 1), the energy of the independent
//! three-particle model (not the note's (10), which is one of the displays checked), so it
//! reads A + θ̇ B with A, B free of θ̇ and is zero exactly when A = B = 0.
//!
//! A particle system is proved for [`PARTICLE_COUNTS`] particles, each with a symbolic mass,
//! position, velocity, acceleration and jerk, and a symbolic reference point P (its sort's
//! constraints built in by the same generic builder as the samples).
//!
//! A check is *proved* when, in every instance, every non-misprint side minus the first reduces to
//! zero, every misprint does not, and (on shell) the same chains with θ̈ free do not all reduce to
//! zero (the identity really needs the equation of motion).

use super::sample::{floor_state, particle_system, LadderSample, EXTRA, PER_PARTICLE};
use super::{Chain, Check, Eval, Role};
use crate::ladder::{Ladder, State};
use crate::scalar::poly::Var;
use crate::scalar::{Scalar, Sym};

/// The particle counts a general identity is proved for.
pub const PARTICLE_COUNTS: std::ops::RangeInclusive<usize> = 1..=4;

/// A quadratic relation `v² = r` that differences are reduced by.
pub type Relation = Option<(Var, Sym)>;

/// What the proof of one check found.
#[derive(Clone, Debug)]
pub struct CheckProof {
    /// The check's name.
    pub name: &'static str,
    /// Every non-misprint side equals the first, in every instance.
    pub proved: bool,
    /// The first nonzero difference (side label, side − first), when not proved.
    pub failure: Option<(&'static str, Sym)>,
    /// Each misprint with its reduced difference from the first side (nonzero: the erratum).
    pub misprints: Vec<(&'static str, Sym)>,
    /// On shell: whether the chains fail with θ̈ (and θ̇) free, as they must.
    pub off_shell_fails: Option<bool>,
    /// Why the check cannot be proved symbolically, if so.
    pub sampled_only: Option<String>,
    /// Seconds spent.
    pub seconds: f64,
}

impl CheckProof {
    /// Proved, every misprint shown wrong, and (on shell) needing the equation of motion.
    pub fn holds(&self) -> bool {
        self.proved
            && self.misprints.iter().all(|m| !m.1.is_zero())
            && self.off_shell_fails != Some(false)
    }
}

fn sym(text: &str, latex: &str) -> Sym {
    Sym::var(text, latex)
}

/// The symbolic ladder and state of a sort, with the relation its differences are reduced by.
pub fn symbolic_ladder(sort: LadderSample) -> (Ladder<Sym>, State<Sym>, Relation) {
    let ladder = Ladder {
        m: sym("m", "m"),
        l: sym("l", "l"),
        g: sym("g", "g"),
    };
    let mut st = State {
        sin: Sym::sin(),
        cos: Sym::cos(),
        rate: sym("θ̇", "\\dot\\theta"),
        accel: sym("θ̈", "\\ddot\\theta"),
        jerk: sym("θ⃛", "\\dddot\\theta"),
    };
    let mut relation = None;
    if sort.on_shell() {
        st.accel = crate::ladder::energy::angular_acceleration(&ladder, &st);
    }
    if sort == LadderSample::OnShellFromRest {
        let unit = State {
            rate: Sym::int(1),
            ..st.clone()
        };
        let sys = crate::ladder::particles::as_system(&ladder, &unit);
        let (kinetic, height) =
            sys.particles
                .iter()
                .fold((Sym::int(0), Sym::int(0)), |(k, h), p| {
                    (
                        k + p.m.clone() * p.v.dot(&p.v) / Sym::int(2),
                        h + p.m.clone() * p.x.y.clone(),
                    )
                });
        let r = ladder.g.clone() * (ladder.m.clone() * ladder.l.clone() - height) / kinetic;
        relation = Some((st.rate.as_var().expect("θ̇ is a variable"), r));
    }
    (ladder, st, relation)
}

/// The values of a symbolic particle sample: per particle m, x, v, a, j; then P's x, v, a, j and
/// ω, ω̇.
pub fn symbolic_particle_values(n: usize) -> Vec<Sym> {
    let mut out = Vec::with_capacity(n * PER_PARTICLE + EXTRA);
    let axes = ["x", "y", "z"];
    let motion = |who: &str, out: &mut Vec<Sym>| {
        for (q, lq) in [("", ""), ("v", "v"), ("a", "a"), ("j", "j")] {
            for ax in axes {
                let (text, latex) = if q.is_empty() {
                    (format!("{ax}_{who}"), format!("{ax}_{{{who}}}"))
                } else {
                    (format!("{q}{ax}_{who}"), format!("{lq}_{{{ax},{who}}}"))
                };
                out.push(sym(&text, &latex));
            }
        }
    };
    for i in 1..=n {
        out.push(sym(&format!("m_{i}"), &format!("m_{{{i}}}")));
        motion(&i.to_string(), &mut out);
    }
    motion("P", &mut out);
    out.push(sym("ω", "\\omega"));
    out.push(sym("ω̇", "\\dot\\omega"));
    out
}

/// `value` reduced modulo the relation (or as it is).
pub fn reduce(value: Sym, rel: &Relation) -> Sym {
    match rel {
        None => value,
        Some((v, r)) => {
            let (a, b) = value.reduce_square(*v, r);
            a + Sym::poly(crate::scalar::poly::Poly::var(*v)) * b
        }
    }
}

/// Judge chains: (all non-misprint sides equal the first, first failure, misprint differences).
#[allow(clippy::type_complexity)]
pub fn judge_chains(
    chains: &[Chain<Sym>],
    rel: &Relation,
) -> (bool, Option<(&'static str, Sym)>, Vec<(&'static str, Sym)>) {
    let mut failure = None;
    let mut misprints = Vec::new();
    for c in chains {
        let Some(base) = c.iter().position(|s| s.role != Role::Misprint) else {
            continue;
        };
        for (i, s) in c.iter().enumerate() {
            if i == base {
                continue;
            }
            let d = reduce(s.value.clone() - c[base].value.clone(), rel);
            if s.role == Role::Misprint {
                misprints.push((s.label, d));
            } else if !d.is_zero() && failure.is_none() {
                failure = Some((s.label, d));
            }
        }
    }
    (failure.is_none(), failure, misprints)
}

fn guarded<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).map_err(|e| {
        e.downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| e.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panicked".into())
    })
}

/// Prove one check: its chains in every symbolic instance of its sort, each non-misprint side
/// reduced against the first, and (on shell) the same chains with θ̈ free.
pub fn prove_check(check: &Check) -> CheckProof {
    let t = std::time::Instant::now();
    let mut out = CheckProof {
        name: check.name,
        proved: false,
        failure: None,
        misprints: Vec::new(),
        off_shell_fails: None,
        sampled_only: None,
        seconds: 0.0,
    };
    let result = guarded(|| {
        let (instances, off_shell) = symbolic_instances(check);
        judge_instances(&instances, off_shell)
    });
    match result {
        Ok((proved, failure, misprints, off)) => {
            out.proved = proved;
            out.failure = failure;
            out.misprints = misprints;
            out.off_shell_fails = off;
        }
        Err(why) => out.sampled_only = Some(format!("symbolic evaluation failed: {why}")),
    }
    out.seconds = t.elapsed().as_secs_f64();
    out
}

/// A check's chains in symbols: one instance per symbolic state of its sort (the ladder, the
/// floor phase, or [`PARTICLE_COUNTS`] particle systems) with the relation its differences are
/// reduced by, and for an on-shell check the chains at kinematic states (θ̈ free).
#[allow(clippy::type_complexity)]
fn symbolic_instances(
    check: &Check,
) -> (Vec<(Vec<Chain<Sym>>, Relation)>, Option<Vec<Chain<Sym>>>) {
    let mut instances: Vec<(Vec<Chain<Sym>>, Relation)> = Vec::new();
    let mut off_shell: Option<Vec<Chain<Sym>>> = None;
    match check.eval {
        Eval::Ladder(sort, f) => {
            let (l, s, rel) = symbolic_ladder(sort);
            instances.push(((f.symbolic)(&l, &s), rel));
            if sort.on_shell() {
                let (l, s, _) = symbolic_ladder(LadderSample::Kinematic);
                off_shell = Some((f.symbolic)(&l, &s));
            }
        }
        Eval::Floor(sort, f) => {
            let floor = |sort| {
                let (l, s, _) = symbolic_ladder(LadderSample::Kinematic);
                let v = [
                    sym("X", "X"),
                    sym("Ẋ", "\\dot X"),
                    sym("Ẍ", "\\ddot X"),
                    sym("X⃛", "\\dddot X"),
                ];
                let (s, x) = floor_state(sort, &l, s, v);
                (f.symbolic)(&l, &s, &x)
            };
            instances.push((floor(sort), None));
            if sort.on_shell() {
                off_shell = Some(floor(LadderSample::Kinematic));
            }
        }
        Eval::Particles(sort, f) => {
            for n in PARTICLE_COUNTS {
                let values = symbolic_particle_values(n);
                let (sys, p) = particle_system(sort, n, &values);
                instances.push(((f.symbolic)(&sys, &p), None));
            }
        }
    }
    (instances, off_shell)
}

/// The verdicts over every instance: all proved, the first failure, each misprint's difference
/// (a zero one kept if any instance has it: a misprint must be wrong in every instance), and
/// whether the chains fail off shell.
#[allow(clippy::type_complexity)]
fn judge_instances(
    instances: &[(Vec<Chain<Sym>>, Relation)],
    off_shell: Option<Vec<Chain<Sym>>>,
) -> (
    bool,
    Option<(&'static str, Sym)>,
    Vec<(&'static str, Sym)>,
    Option<bool>,
) {
    let mut proved = true;
    let mut failure = None;
    let mut misprints: Vec<(&'static str, Sym)> = Vec::new();
    for (chains, rel) in instances {
        let (ok, fail, mis) = judge_chains(chains, rel);
        proved &= ok;
        if failure.is_none() {
            failure = fail;
        }
        for (k, m) in mis.into_iter().enumerate() {
            match misprints.get_mut(k) {
                Some(prev) if !prev.1.is_zero() && m.1.is_zero() => *prev = m,
                Some(_) => {}
                None => misprints.push(m),
            }
        }
    }
    let off = off_shell.map(|chains| !judge_chains(&chains, &None).0);
    (proved, failure, misprints, off)
}

/// The difference printed − corrected of every chain of a check that holds both a misprint and
/// its correction, evaluated as functions of free variables: the ladder with θ, θ̇, θ̈ free
/// (whatever the check's sort: the difference of two forms, not a statement on the motion), a
/// particle system with one particle (the summand of a sum over particles). Empty when the check
/// has no misprint.
pub fn erratum_difference(check: &Check) -> Vec<Sym> {
    let chains = match check.eval {
        Eval::Ladder(_, f) => {
            let (l, s, _) = symbolic_ladder(LadderSample::Kinematic);
            (f.symbolic)(&l, &s)
        }
        Eval::Floor(..) => return Vec::new(), // the extension has no errata
        Eval::Particles(sort, f) => {
            let values = symbolic_particle_values(1);
            let (sys, p) = particle_system(sort, 1, &values);
            (f.symbolic)(&sys, &p)
        }
    };
    chains
        .iter()
        .filter_map(|c| {
            let bad = c.iter().find(|s| s.role == Role::Misprint)?;
            let good = c.iter().find(|s| s.role == Role::Corrected)?;
            Some(bad.value.clone() - good.value.clone())
        })
        .collect()
}

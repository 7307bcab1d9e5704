//! Proofs: every check of every equation evaluated in the symbolic scalar (src/registry/prove.rs).
//! Every identity reduces to zero; a planted false identity does not, and its difference prints.

use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::registry::prove::{prove_check, PARTICLE_COUNTS};
use sliding_ladder::registry::sample::LadderSample;
use sliding_ladder::registry::{equations, extensions, printed, reference, Chain, Check, Eval};
use sliding_ladder::scalar::{latex, text, Scalar};
use sliding_ladder::verify::proof::prove_equation;

#[test]
fn every_equation_is_proved_symbolically() {
    let t = std::time::Instant::now();
    let mut proved = 0;
    let all: Vec<_> = equations().into_iter().chain(extensions()).collect();
    for e in &all {
        let (v, _) = prove_equation(e);
        assert!(v.proved, "{}: {} ({:?})", e.label(), v.proof, v.problem);
        assert!(
            !v.proof.starts_with("sampled only"),
            "{}: {}",
            e.label(),
            v.proof
        );
        proved += 1;
    }
    eprintln!(
        "{proved} of {} equations proved ({:?} particles) in {:.2} s",
        all.len(),
        PARTICLE_COUNTS,
        t.elapsed().as_secs_f64()
    );
}

/// A planted false identity: the ladder's kinetic energy printed as m l² θ̇²/3 (it is 2/3).
fn planted<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    let wrong =
        S::ratio(1, 3) * l.m.clone() * l.l.clone() * l.l.clone() * s.rate.clone() * s.rate.clone();
    let model = sliding_ladder::ladder::particles::as_system(l, s);
    let kinetic = model.particles.iter().fold(S::int(0), |k, p| {
        k + p.m.clone() * p.v.dot(&p.v) / S::int(2)
    });
    vec![vec![
        printed("planted: m l² θ̇²/3", wrong),
        reference("particles", kinetic),
    ]]
}

#[test]
fn a_planted_false_identity_is_not_proved_and_its_difference_prints() {
    let check = Check {
        name: "planted",
        eval: Eval::Ladder(
            LadderSample::Kinematic,
            sliding_ladder::ladder_fns!(planted),
        ),
    };
    let p = prove_check(&check);
    assert!(!p.proved);
    let (label, diff) = p.failure.expect("a nonzero difference");
    assert_eq!(label, "particles");
    // particles − printed = (2/3 − 1/3) m l² θ̇², written by hand.
    assert_eq!(text(&diff), "1/3 m l^2 θ̇^2");
    assert_eq!(latex(&diff), "\\frac{1}{3} m l^{2} \\dot\\theta^{2}");
}

/// Issue 10: with 100 exact points the Schwartz-Zippel bound is far below the smallest f64
/// (about 1e-1400 for these checks), so it is carried as a power of ten; the summary line
/// prints that power, not the 0.0e0 the underflowed number gives.
#[test]
fn the_schwartz_zippel_bound_of_100_points_prints_as_a_power_of_ten() {
    use sliding_ladder::registry::check::{Config, EXACT_SET_SIZE};
    use sliding_ladder::verify::{summary::summary_line, verify_equations};
    let cfg = Config {
        float_cases: 2,
        exact_points: 100,
        ..Config::default()
    };
    let e12: Vec<_> = equations().into_iter().filter(|e| e.number == 12).collect();
    let rows = verify_equations(e12, &cfg);
    let r = &rows[0];
    // The float underflows: what a plain print of it would say.
    assert_eq!(r.sz_bound, 0.0);
    assert_eq!(format!("{:.1e}", r.sz_bound), "0.0e0");
    // Each point contributes at least log10(EXACT_SET_SIZE) − log10(degree) decades; a degree
    // below 100 leaves at least (log10 N − 2) × 100.
    let most = -(EXACT_SET_SIZE.log10() - 2.0) * 100.0;
    assert!(
        r.sz_bound_log10.is_finite() && r.sz_bound_log10 <= most,
        "{}",
        r.sz_bound_log10
    );
    let line = summary_line(&rows, &cfg, 0.0);
    let at = line.find("Schwartz-Zippel bound ≤ 1e").expect("the bound")
        + "Schwartz-Zippel bound ≤ 1e".len();
    let power: f64 = line[at..]
        .split([';', ' '])
        .next()
        .and_then(|s| s.parse().ok())
        .expect("a power of ten");
    assert_eq!(power, r.sz_bound_log10.ceil(), "{line}");
    assert!(power < -308.0, "{line}");
}

/// A planted identity about particles that holds for up to three particles and not for four:
/// Σ mᵢ over all particles against the same sum over the first three.
fn first_three<S: Scalar>(
    sys: &sliding_ladder::system::System<S>,
    _p: &sliding_ladder::system::Point<S>,
) -> Vec<Chain<S>> {
    let mass = |k: usize| {
        sys.particles
            .iter()
            .take(k)
            .fold(S::int(0), |a, q| a + q.m.clone())
    };
    vec![vec![
        printed("planted: Σ_{i≤3} m_i", mass(3)),
        reference("Σ m_i", mass(usize::MAX)),
    ]]
}

/// Issue 10 item 2: identities about particles are proved for exactly the counts the legend
/// states (1, 2, 3 and 4, written here by hand); an identity false only at four particles is
/// caught, so the fourth count is really evaluated.
#[test]
fn particle_identities_are_proved_for_the_counts_the_legend_states() {
    use sliding_ladder::registry::sample::ParticleSample;
    use sliding_ladder::verify::legend::{legend, proved_particle_counts};
    assert_eq!(PARTICLE_COUNTS.collect::<Vec<_>>(), vec![1, 2, 3, 4]);
    assert_eq!(proved_particle_counts(), "1, 2, 3 and 4 particles");
    let cfg = sliding_ladder::registry::check::Config::default();
    assert!(legend(&cfg).contains("identities about particles: for 1, 2, 3 and 4 particles"));
    let check = Check {
        name: "planted",
        eval: Eval::Particles(
            ParticleSample::General,
            sliding_ladder::particle_fns!(first_three),
        ),
    };
    let p = prove_check(&check);
    assert!(
        !p.proved,
        "a sum over three of four particles passed as proved"
    );
    let (_, diff) = p.failure.expect("a nonzero difference");
    assert_eq!(text(&diff), "m_4");
}

/// What `ladder verify --json` says of the proofs' reach and of the Schwartz-Zippel bound: the
/// particle counts the proofs cover, the worst bound as a power of ten in the summary, and no
/// per-display `sz_bound` of 0 where the number underflows (30 exact points: below 1e-308).
#[test]
fn the_json_states_the_particle_counts_and_no_underflowed_bound() {
    let run = |points: &str| -> serde_json::Value {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args([
                "verify",
                "--only",
                "12",
                "--cases",
                "2",
                "--exact-points",
                points,
                "--json",
            ])
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(0));
        serde_json::from_slice(&out.stdout).expect("JSON")
    };
    let deep = run("30");
    let s = &deep["summary"];
    assert_eq!(s["proof_particle_counts"], serde_json::json!([1, 2, 3, 4]));
    let row = &deep["equations"][0];
    let log10 = row["sz_bound_log10"]
        .as_f64()
        .expect("the bound's power of ten");
    assert!(log10 < -308.0, "{log10}");
    assert!(
        row.get("sz_bound").is_none(),
        "an underflowed bound: {}",
        row["sz_bound"]
    );
    assert_eq!(s["sz_bound_log10"].as_f64(), Some(log10.ceil()));
    // One exact point: the bound is a plain number, and it is there.
    let shallow = run("1");
    let b = shallow["equations"][0]["sz_bound"]
        .as_f64()
        .expect("a bound");
    assert!(b > 0.0 && b < 1e-10, "{b}");
}

/// Issue 10 item 5: the unit the JSON names for `max_residual` states the pass threshold the
/// checks use.
#[test]
fn the_residual_unit_states_the_threshold_in_use() {
    use sliding_ladder::registry::check::TOLERANCE_FACTOR;
    use sliding_ladder::verify::RESIDUAL_UNIT;
    assert!(RESIDUAL_UNIT.starts_with("error bounds: |lhs - rhs| / (u (e_lhs + e_rhs))"));
    assert!(
        RESIDUAL_UNIT.ends_with(&format!("pass <= {TOLERANCE_FACTOR}")),
        "{RESIDUAL_UNIT} against {TOLERANCE_FACTOR}"
    );
}

/// `CheckProof::holds` asks all three: proved, every misprint nonzero, and (on shell) failing
/// off the motion; each one missing alone makes it false.
#[test]
fn check_proof_holds_only_when_proved_every_misprint_wrong_and_needing_the_law() {
    use sliding_ladder::registry::prove::CheckProof;
    use sliding_ladder::scalar::symbolic::Sym;
    let good = CheckProof {
        name: "planted",
        proved: true,
        failure: None,
        misprints: vec![("misprint", Sym::var("m", "m"))],
        off_shell_fails: Some(true),
        sampled_only: None,
        seconds: 0.0,
    };
    assert!(good.holds());
    let unproved = CheckProof {
        proved: false,
        off_shell_fails: None,
        ..good.clone()
    };
    let misprint_right = CheckProof {
        misprints: vec![("misprint", Sym::int(0))],
        ..good.clone()
    };
    let holds_off_shell = CheckProof {
        off_shell_fails: Some(false),
        ..good.clone()
    };
    for p in [unproved, misprint_right, holds_off_shell] {
        assert!(!p.holds(), "{:?}", (p.proved, p.off_shell_fails));
    }
}

/// Σ mᵢ of the system, and its last particle's mass.
fn total_and_last<S: Scalar>(sys: &sliding_ladder::system::System<S>) -> (S, S) {
    let total = sys.particles.iter().fold(S::int(0), |a, q| a + q.m.clone());
    let last = sys.particles.last().expect("a particle").m.clone();
    (total, last)
}

/// A planted misprint wrong for 1, 2 and 3 particles and right for 4: Σ mᵢ, plus m_n below four
/// particles.
fn misprint_right_at_four<S: Scalar>(
    sys: &sliding_ladder::system::System<S>,
    _p: &sliding_ladder::system::Point<S>,
) -> Vec<Chain<S>> {
    let (total, last) = total_and_last(sys);
    let off = if sys.particles.len() < 4 {
        last
    } else {
        S::int(0)
    };
    vec![vec![
        printed("Σ m_i", total.clone()),
        sliding_ladder::registry::side::misprint(
            "planted: Σ m_i + m_n (n < 4)",
            total.clone() + off,
        ),
        reference("Σ m_i", total),
    ]]
}

/// A planted false identity wrong at every particle count, by a different term at each:
/// Σ mᵢ + m_n against Σ mᵢ (the difference is the last particle's mass, m_1 at one particle).
fn wrong_by_the_last<S: Scalar>(
    sys: &sliding_ladder::system::System<S>,
    _p: &sliding_ladder::system::Point<S>,
) -> Vec<Chain<S>> {
    let (total, last) = total_and_last(sys);
    vec![vec![
        printed("planted: Σ m_i + m_n", total.clone() + last),
        reference("Σ m_i", total),
    ]]
}

/// The proof of a planted check about general particle systems.
fn prove_planted(
    fns: sliding_ladder::registry::ParticleFns,
) -> sliding_ladder::registry::prove::CheckProof {
    use sliding_ladder::registry::sample::ParticleSample;
    prove_check(&Check {
        name: "planted",
        eval: Eval::Particles(ParticleSample::General, fns),
    })
}

/// A misprint must be wrong in every instance (every particle count): one right only at four
/// particles, the last count proved, is reported symbolically right, so the erratum fails.
#[test]
fn prove_check_keeps_a_misprint_right_in_any_one_instance() {
    let p = prove_planted(sliding_ladder::particle_fns!(misprint_right_at_four));
    assert!(p.proved, "{:?}", p.failure);
    assert_eq!(p.misprints.len(), 1);
    assert!(p.misprints[0].1.is_zero(), "{}", text(&p.misprints[0].1));
    assert!(!p.holds());
}

/// The failure reported is the first instance's (one particle): its difference is m_1.
#[test]
fn prove_check_reports_the_first_instance_that_fails() {
    let p = prove_planted(sliding_ladder::particle_fns!(wrong_by_the_last));
    assert!(!p.proved);
    let (label, diff) = p.failure.expect("a nonzero difference");
    assert_eq!(label, "Σ m_i");
    assert_eq!(text(&diff), "-m_1");
}

/// A check whose symbolic evaluation panics (as one that takes a square root of a symbol would):
/// with a fixed message, and with a formatted one.
fn panics_with_a_literal<S: Scalar>(_: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
    panic!("no symbolic square root")
}

fn panics_with_a_formatted_message<S: Scalar>(_: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
    panic!("no symbolic value at step {}", 3)
}

/// A check that cannot be evaluated in symbols is not proved: it is "sampled only", and the
/// reason quotes the panic's own message, whether the message was a literal or formatted.
#[test]
fn prove_check_of_a_check_that_panics_is_sampled_only_with_its_reason() {
    for (f, why) in [
        (
            sliding_ladder::ladder_fns!(panics_with_a_literal),
            "no symbolic square root",
        ),
        (
            sliding_ladder::ladder_fns!(panics_with_a_formatted_message),
            "no symbolic value at step 3",
        ),
    ] {
        let check = Check {
            name: "planted panic",
            eval: Eval::Ladder(LadderSample::Kinematic, f),
        };
        let p = prove_check(&check);
        assert!(!p.proved && !p.holds(), "{why}");
        assert_eq!(
            p.sampled_only.as_deref(),
            Some(format!("symbolic evaluation failed: {why}").as_str())
        );
    }
}

/// A planted from-rest identity that is false by θ̇ itself: θ̇ = 0.
fn rate_is_zero<S: Scalar>(_: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
    vec![vec![
        printed("planted: θ̇", s.rate.clone()),
        reference("0", S::int(0)),
    ]]
}

/// From rest, a difference is reduced modulo the energy's θ̇² = r to A + θ̇ B, and the failure
/// shows that reduced difference: for the planted θ̇ = 0 it is 0 − θ̇ = −θ̇ (A = 0, B = −1), with
/// its sign. A reduction to A − θ̇ B would still tell zero from nonzero, and show +θ̇.
#[test]
fn prove_check_from_rest_shows_the_reduced_difference_with_its_sign() {
    use sliding_ladder::registry::prove::symbolic_ladder;
    let check = Check {
        name: "planted from rest",
        eval: Eval::Ladder(
            LadderSample::OnShellFromRest,
            sliding_ladder::ladder_fns!(rate_is_zero),
        ),
    };
    let p = prove_check(&check);
    assert!(!p.proved);
    let (label, diff) = p.failure.expect("a nonzero difference");
    assert_eq!(label, "0");
    let (_, s, relation) = symbolic_ladder(LadderSample::OnShellFromRest);
    assert!(relation.is_some(), "from rest, θ̇² is reduced");
    assert!(
        (diff.clone() + s.rate.clone()).is_zero(),
        "the difference is {}, not −θ̇",
        text(&diff)
    );
}

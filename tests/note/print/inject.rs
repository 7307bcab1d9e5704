//! Typos injected into the print are caught (issue 9, item 6).
//!
//! CI runs a fixed-seed sample; the full sweep over every typo of every display is one command:
//! `cargo test --release --test note print::inject -- --ignored --nocapture` (its catch rate is in
//! README.md).

use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sliding_ladder::registry::check::Config;
use sliding_ladder::registry::equations;
use sliding_ladder::registry::print_check::{
    injections, run_injection, Detection, Injection, Typo,
};

fn quick() -> Config {
    Config {
        float_cases: 20,
        exact_points: 1,
        seed: 11,
    }
}

/// Run injections; return the number caught, the neutral typos and the misses.
fn sweep(list: &[Injection]) -> (usize, Vec<String>, Vec<String>) {
    let eqs = equations();
    let (mut caught, mut neutral, mut missed) = (0, Vec::new(), Vec::new());
    for inj in list {
        let e = eqs
            .iter()
            .find(|e| e.number == inj.number)
            .expect("registered");
        match run_injection(e, inj, &quick()) {
            Detection::Caught(why) => {
                // The report names the form (or why it no longer parses).
                assert!(
                    why.contains("form") || why.contains("parse") || why.contains("symbol"),
                    "{why}"
                );
                caught += 1;
            }
            Detection::Neutral => {
                neutral.push(format!("({}) {:?}: {}", inj.number, inj.typo, inj.latex))
            }
            Detection::Missed => {
                missed.push(format!("({}) {:?}: {}", inj.number, inj.typo, inj.latex))
            }
        }
    }
    (caught, neutral, missed)
}

fn all_injections() -> Vec<Injection> {
    equations()
        .iter()
        .flat_map(|e| injections(e.number, e.latex()))
        .collect()
}

#[test]
fn every_sort_of_typo_occurs_and_a_fixed_sample_is_caught() {
    let all = all_injections();
    for t in [
        Typo::Coefficient,
        Typo::Sign,
        Typo::SinCos,
        Typo::DropFactor,
    ] {
        assert!(all.iter().filter(|i| i.typo == t).count() > 10, "{t:?}");
    }
    let mut rng = ChaCha8Rng::seed_from_u64(2019);
    let sample: Vec<Injection> = all.choose_multiple(&mut rng, 24).cloned().collect();
    let (caught, neutral, missed) = sweep(&sample);
    assert!(missed.is_empty(), "{missed:#?}");
    assert!(caught >= 20, "caught {caught}, neutral {neutral:#?}");
}

#[test]
fn the_typo_in_25_is_named_with_its_form_and_residual() {
    let e = equations().into_iter().find(|e| e.number == 25).unwrap();
    let inj = injections(25, e.latex())
        .into_iter()
        .find(|i| i.typo == Typo::SinCos)
        .expect("a sin/cos in (25)");
    match run_injection(&e, &inj, &quick()) {
        Detection::Caught(why) => {
            assert!(why.contains("form") && why.contains("residual"), "{why}")
        }
        other => panic!("{other:?}"),
    }
}

#[test]
#[ignore = "full sweep, minutes: cargo test --release --test note print::inject -- --ignored --nocapture"]
fn full_sweep_catch_rate() {
    let all = all_injections();
    let (caught, neutral, missed) = sweep(&all);
    let counted = caught + missed.len();
    println!(
        "injection sweep: {} typos in {} displays; {caught} caught, {} neutral (value unchanged), {} missed; catch rate {:.1}% of the {counted} that change a value",
        all.len(),
        sliding_ladder::registry::equations().len(),
        neutral.len(),
        missed.len(),
        100.0 * caught as f64 / counted.max(1) as f64
    );
    for n in &neutral {
        println!("neutral: {n}");
    }
    for m in &missed {
        println!("missed: {m}");
    }
    assert!(missed.is_empty());
}

/// An edit that changes no form's value is neutral, not missed: (5) with its factors
/// reordered states the same equation. The same edit with a changed coefficient is caught.
#[test]
fn run_injection_calls_an_edit_that_changes_no_value_neutral() {
    let e = equations().into_iter().find(|e| e.number == 5).unwrap();
    let edit = |latex: &str| Injection {
        number: 5,
        typo: Typo::Coefficient,
        latex: latex.into(),
    };
    let same = edit(r"\ddot{\theta} = \sin \theta \frac{3g}{4l}");
    assert_eq!(run_injection(&e, &same, &quick()), Detection::Neutral);
    let changed = edit(r"\ddot{\theta} = \sin \theta \frac{3g}{5l}");
    assert!(matches!(
        run_injection(&e, &changed, &quick()),
        Detection::Caught(_)
    ));
}

/// An edit the check cannot see is missed, not neutral: (P9), F_w = (3mg/4) sin θ (3 cos θ − 2),
/// has no Rust form to disagree with, so both sides doubled still hold (and still break off the
/// motion) while every value changed.
#[test]
fn run_injection_calls_an_edit_that_changes_values_unseen_missed() {
    let e = sliding_ladder::registry::extensions()
        .into_iter()
        .find(|e| e.number == 1009)
        .unwrap();
    assert!(e.checks.is_empty(), "the case this test is about");
    let doubled = Injection {
        number: 1009,
        typo: Typo::Coefficient,
        latex: r"2 F_w = \frac{3mg}{2}\sin\theta(3\cos\theta - 2)".into(),
    };
    assert_eq!(run_injection(&e, &doubled, &quick()), Detection::Missed);
}

/// The typos of (5), θ̈ = (3g/4l) sin θ, counted by hand: the coefficients 3 and 4 each raised
/// by one, sin made cos, g and l each dropped from their product; no sign to flip. A display
/// with cos gets the other direction: (10)'s cos θ made sin θ.
#[test]
fn injections_makes_every_typo_of_each_sort_in_a_display() {
    let of = |n: u32| {
        let e = equations().into_iter().find(|e| e.number == n).unwrap();
        injections(n, e.latex())
    };
    let five = of(5);
    let count = |t: Typo| five.iter().filter(|i| i.typo == t).count();
    assert_eq!(
        [
            Typo::Coefficient,
            Typo::Sign,
            Typo::SinCos,
            Typo::DropFactor
        ]
        .map(count),
        [2, 0, 1, 2],
        "{five:#?}"
    );
    let sin_to_cos = five.iter().find(|i| i.typo == Typo::SinCos).unwrap();
    assert!(sin_to_cos.latex.contains(r"\cos") && !sin_to_cos.latex.contains(r"\sin"));
    let ten = of(10);
    assert!(
        ten.iter()
            .any(|i| i.typo == Typo::SinCos && i.latex.contains(r"\sin")),
        "{ten:#?}"
    );
}

/// A dropped factor is a bare m, l or g beside another factor: never a letter that carries an
/// index or power of its own (m in m₁) nor one inside an index (m in x_m). In `a = g m_1 + x_m l`,
/// by hand: g (beside m) and l (beside m) are dropped; the two m's never are.
#[test]
fn injections_drop_only_a_bare_factor_outside_any_index() {
    let drops: Vec<String> = injections(5, "a = g m_1 + x_m l")
        .into_iter()
        .filter(|i| i.typo == Typo::DropFactor)
        .map(|i| i.latex)
        .collect();
    assert_eq!(drops.len(), 2, "{drops:?}");
    for d in &drops {
        assert_eq!(d.matches('m').count(), 2, "an m was dropped: {d}");
    }
    assert!(drops.iter().any(|d| !d.contains('g')), "{drops:?}");
    assert!(drops.iter().any(|d| !d.contains('l')), "{drops:?}");
    // Nor is the index 1 of m₁ a coefficient to raise.
    let raised = injections(5, "a = g m_1 + x_m l")
        .into_iter()
        .filter(|i| i.typo == Typo::Coefficient)
        .count();
    assert_eq!(raised, 0);
}

/// Letters inside `\text{…}` are a word, not factors: in `a = m l v_{\text{cm}}` only the m and
/// the l of the product are dropped (two typos, by hand), never the m of "cm".
#[test]
fn injections_drop_no_letter_of_a_word_in_text() {
    let drops: Vec<String> = injections(5, r"a = m l v_{\text{cm}}")
        .into_iter()
        .filter(|i| i.typo == Typo::DropFactor)
        .map(|i| i.latex)
        .collect();
    assert_eq!(drops.len(), 2, "{drops:?}");
    assert!(drops.iter().all(|d| d.contains("cm")), "{drops:?}");
}

/// Each sign of a display is flipped once, + to − and − to +: `a = b + c - d` has two sign
/// typos, by hand `a = b - c - d` and `a = b + c + d`.
#[test]
fn injections_flip_every_plus_and_every_minus() {
    let signs: Vec<String> = injections(5, "a = b + c - d")
        .into_iter()
        .filter(|i| i.typo == Typo::Sign)
        .map(|i| i.latex.replace(' ', ""))
        .collect();
    assert_eq!(signs, ["a=b-c-d", "a=b+c+d"]);
}

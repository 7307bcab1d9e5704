//! The one-line summary of a verify run (counts, work done, proofs), shared by `ladder verify`
//! and the book's index page.

use super::{counts, EquationResult};
use crate::registry::check::Config;

/// One line: the counts and the work done.
pub fn summary_line(results: &[EquationResult], cfg: &Config, seconds: f64) -> String {
    let (v, e, d, f) = counts(results);
    let checks: usize = results.iter().map(|r| r.checks.len()).sum();
    let exact = results.iter().filter(|r| r.exact).count();
    let worst_sz = results
        .iter()
        .map(|r| r.sz_bound_log10)
        .fold(f64::NEG_INFINITY, f64::max);
    let worst_rational = results
        .iter()
        .map(|r| r.sz_bound_rational_log10)
        .fold(f64::NEG_INFINITY, f64::max);
    let (proved, sampled_only, proof_seconds) = proof_counts(results);
    format!(
        "{} equations: {v} verified, {e} erratum, {d} definition, {f} failed; {checks} checks, {} float cases each, {exact} exact (Schwartz-Zippel bound ≤ 1e{}; ≤ 1e{} from the rational points alone); {proved} proved symbolically, {sampled_only} sampled only ({proof_seconds:.2} s of proofs); {seconds:.2} s",
        results.len(),
        cfg.float_cases,
        worst_sz.ceil(),
        worst_rational.ceil()
    )
}

/// (equations proved, equations only sampled, seconds spent on proofs).
pub fn proof_counts(results: &[EquationResult]) -> (usize, usize, f64) {
    (
        results.iter().filter(|r| r.proved).count(),
        results
            .iter()
            .filter(|r| r.proof.starts_with("sampled only"))
            .count(),
        results.iter().map(|r| r.proof_seconds).sum(),
    )
}

/// (displays of the note whose print is proved symbolically, printed forms in them).
pub fn print_proof_counts(results: &[EquationResult]) -> (usize, usize) {
    let proved: Vec<_> = results
        .iter()
        .filter(|r| r.print_proved == Some(true))
        .collect();
    (proved.len(), proved.iter().map(|r| r.print_forms).sum())
}

/// The Schwartz-Zippel bound of the summary line in one plain sentence.
pub fn schwartz_zippel_sentence(results: &[EquationResult]) -> String {
    let worst = |f: fn(&EquationResult) -> f64| {
        results
            .iter()
            .map(f)
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil()
    };
    format!(
        "in plain words: if any of these identities were false, the chance that it still came out exactly zero at all of its random exact points is at most 1e{} (1e{} counting only the points evaluated in rationals)",
        worst(|r| r.sz_bound_log10),
        worst(|r| r.sz_bound_rational_log10)
    )
}

//! What the `ladder verify` table means, for a reader who is a physicist rather than a numerical
//! analyst: a legend for every column, the law-of-motion step of each on-shell display, and a
//! filter to show only some displays (`--only 25,28` or a section such as `--only 2.5`).

use super::EquationResult;
use crate::registry::check::{Config, TOLERANCE_FACTOR};

/// One line per column of [`super::table`], and what a row's status means.
pub fn legend(cfg: &Config) -> String {
    [
        "legend:".to_string(),
        "  eq        the note's equation number; (Pk) = beyond the note (equations/phase2.md)".into(),
        "  sec       the note's section".into(),
        "  kind      definition | kinematic (any θ, θ̇, θ̈) | newton (F = m a_cm: the force the motion".into(),
        "            requires, any θ̈) | on-shell (only on the motion) | general (any particles, any P) | notation".into(),
        format!("  checks    independent checks run; cases: random float states ({} per check)", cfg.float_cases),
        format!("  exact     'yes' = every check held with zero residual at {} random exact points: the first in rationals,", cfg.exact_points),
        "            the rest modulo the prime 2⁶¹ − 1 (a nonzero residue is a certain failure; see the summary's bound)".into(),
        format!("  residual  worst float difference in units of its own rounding-error bound; pass ≤ {TOLERANCE_FACTOR}"),
        "            (dimensionless: |a − b| / (u·(e_a + e_b)), u = 2⁻⁵³)".into(),
        "  status    verified | erratum (printed form fails, correction verified) | definition | FAILED".into(),
    ]
    .join("\n")
        + "\n"
}

/// For every on-shell display that marks one: which `=` is the law of motion, as confirmed off
/// the motion by this run.
pub fn law_lines(results: &[EquationResult]) -> String {
    let mut out = String::from(
        "the law and the algebra: in each display below one `=` is the law of motion; the others hold for any θ̈\n",
    );
    for r in results {
        if let (Some(step), Some(law)) = (r.law_step, r.law) {
            out.push_str(&format!(
                "{:>5}  {} `=`: {law}\n",
                r.label,
                crate::docs::ordinal(step)
            ));
        }
    }
    out
}

/// Keep the rows named by `spec`: comma-separated equation numbers ("25,28"), labels ("P3") or
/// sections ("2.5", "A.1"). Err names the first item that matches nothing.
pub fn only(results: Vec<EquationResult>, spec: &str) -> Result<Vec<EquationResult>, String> {
    let items: Vec<&str> = spec
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect();
    let hit = |r: &EquationResult, it: &str| {
        r.section == it
            || r.label.trim_matches(['(', ')']) == it
            || it.parse::<u32>().is_ok_and(|n| n == r.number)
    };
    if let Some(miss) = items.iter().find(|it| !results.iter().any(|r| hit(r, it))) {
        return Err(format!("--only: '{miss}' is no equation number or section"));
    }
    Ok(results
        .into_iter()
        .filter(|r| items.iter().any(|it| hit(r, it)))
        .collect())
}

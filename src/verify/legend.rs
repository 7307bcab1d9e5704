//! What the `ladder verify` table means, for a reader who is a physicist rather than a numerical
//! analyst: a legend for every column, the law-of-motion step of each on-shell display, and a
//! filter to show only some displays (`--only 25,28` or a section such as `--only 2.5`).

use super::EquationResult;
use crate::registry::check::{Config, TOLERANCE_FACTOR};
use crate::registry::prove::PARTICLE_COUNTS;

/// One entry per column of [`super::table::table`] (the test in `tests/note/verify/table.rs` holds every
/// column header to an entry here), and what a row's status means. One line per entry (the kinds
/// one each): `ladder verify` fills them to the terminal's width, continuing under the text.
pub fn legend(cfg: &Config) -> String {
    let f = TOLERANCE_FACTOR;
    let full = super::table::FULL_WIDTH;
    [
        "legend (rows are grouped under the book file that explains them):".to_string(),
        "  eq          the note's equation number; (Pk) = beyond the note (equations/phase2.md)".into(),
        "  sec         the note's section".into(),
        format!("  title       what the display says, in full, never cut (in a terminal under {full} columns, on its own line above the row's cells)"),
        "  kind        definition: introduces a symbol, checked against the independent model".into(),
        "              kinematic: geometry and derivatives, for any θ, θ̇, θ̈".into(),
        "              newton: F = m a_cm (the contact force the motion requires), so again for any θ̈".into(),
        "              on-shell: only on the motion θ̈ = Ω² sin θ (5)".into(),
        "              general: any system of particles, any point P".into(),
        "              notation: Milne's name for one of our quantities".into(),
        "  status      verified | erratum (the printed form fails, the correction passes) | definition | FAILED".into(),
        format!("  residual    worst float difference of the display's forms at {} random states per check, in units of its own rounding-error bound: |a − b| / (u·(e_a + e_b)), u = 2⁻⁵³, where e_a, e_b bound the rounding of a and b; shown beside the threshold: a check passes when it is ≤ {f}", cfg.float_cases),
        "  off motion  re-run with θ̈ left free instead of taken from (5): 'fails at =k' = the display breaks at its k-th `=`, the law of motion, and nowhere else (see the law lines below); 'fails' = breaks (a consequence of the law, no single `=`); 'any θ̈' = checked with θ̈ free, holds on the motion and off it; '—' = about any system of particles, no ladder".into(),
        format!("  exact       '0 at n pts' = residual exactly zero at n exact points ({} per check): the first in rationals, the rest modulo the prime 2⁶¹ − 1; '≠0 at k of n' = nonzero at k of them", cfg.exact_points),
        format!("  proof       proved = every check, and every printed form against its chain, reduces to zero symbolically, for all values of the variables (identities about particles: for {}; an erratum: its correction, and its printed form is shown to differ); sampled = no proof applies", proved_particle_counts()),
        "  units       consistent = every form has one dimension and the sides agree (inconsistent: why, below)".into(),
        "  print       k/n = k of the n forms of the printed display parsed and checked against each other (a * after it: a Rust form that equals none of them)".into(),
        "  line        the line of the display's section in the book file above its group".into(),
        "  checked:    (under a definition, under every row with --wide) what each check compares".into(),
    ]
    .join("\n")
        + "\n"
}

/// The numbers of particles an identity about a system of particles is proved for, in words
/// ("1, 2, 3 and 4 particles"), from [`PARTICLE_COUNTS`] itself so the legend cannot drift.
pub fn proved_particle_counts() -> String {
    let n: Vec<String> = PARTICLE_COUNTS.map(|n| n.to_string()).collect();
    match n.split_last() {
        Some((last, [])) => format!("{last} particle{}", if last == "1" { "" } else { "s" }),
        Some((last, rest)) => format!("{} and {last} particles", rest.join(", ")),
        None => "no particles".into(),
    }
}

/// The columns of the two layouts of [`super::table::table`] that `legend` text does not explain: a
/// column is explained by a line that starts with two spaces and its header, then a space.
pub fn unexplained_columns(legend: &str) -> Vec<&'static str> {
    super::table::COLUMNS
        .iter()
        .chain(super::table::NARROW_COLUMNS.iter())
        .map(|c| c.0)
        .filter(|h| !legend.lines().any(|l| l.starts_with(&format!("  {h} "))))
        .fold(Vec::new(), |mut out, h| {
            if !out.contains(&h) {
                out.push(h);
            }
            out
        })
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

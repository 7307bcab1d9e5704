//! The checks of a shown display: what `ladder verify` runs on it and what each found.

use super::super::Shown;
use std::fmt::Write;

/// The registry's checks of the display, then its print, units, proof and law rows.
pub(super) fn checks(o: &mut String, s: &Shown, v: &crate::verify::EquationResult) {
    let _ = writeln!(o, "\nchecks (what `ladder verify` runs on this display)");
    for c in &s.checks {
        check_detail(o, c);
    }
    let _ = writeln!(
        o,
        "  print: {} of {} forms parsed, {} held in chains ({} float states, {} exact point); {}",
        v.print_parsed,
        v.print_forms,
        v.print_checked,
        crate::registry::print_check::PRINT_FLOAT_CASES,
        crate::registry::print_check::PRINT_EXACT_POINTS,
        if v.print_matches_code {
            "every Rust form equals a printed form"
        } else {
            "some Rust form matches no printed form"
        }
    );
    let _ = writeln!(
        o,
        "  units: {}{}",
        v.units.name(),
        v.units_detail
            .as_ref()
            .map_or(String::new(), |d| format!(" ({d})"))
    );
    let _ = writeln!(o, "  proof: {}", v.proof);
    if let (Some(step), Some(law)) = (v.law_step, v.law) {
        let _ = writeln!(
            o,
            "  law: the {} `=` is the law of motion: {law}",
            crate::docs::ordinal(step)
        );
    }
}

/// One registry check: what it compares, its float and exact results, its misprints, whether
/// it fails off the motion, its proof and units.
fn check_detail(o: &mut String, c: &crate::show::checks::CheckDetail) {
    let _ = writeln!(
        o,
        "  {} [{}]{}",
        c.name,
        c.sample,
        if c.passed { "" } else { "  FAILED" }
    );
    let sides: Vec<String> = c.sides.iter().map(|(l, r)| format!("{l} ({r})")).collect();
    let _ = writeln!(o, "    compares: {}", sides.join(", "));
    let _ = writeln!(
        o,
        "    float: {} random states, worst residual {:.3} error bounds (pass ≤ {}){}, {} out of tolerance",
        c.float_cases,
        c.max_residual,
        c.tolerance,
        if c.worst_side.is_empty() { String::new() } else { format!(" at '{}'", c.worst_side) },
        c.float_failures
    );
    let _ = writeln!(
        o,
        "    exact: {} random points ({} in rationals, the rest modulo p = 2^61 − 1), {} with a nonzero residual (chance a false identity passes ≤ 1e{:.0})",
        c.exact_points,
        c.exact_points.min(crate::registry::check::RATIONAL_POINTS),
        c.exact_failures,
        c.sz_bound_log10.ceil()
    );
    for (label, failed) in &c.misprints {
        let _ = writeln!(
            o,
            "    misprint '{label}': {}",
            if *failed {
                "fails at every exact point, as recorded"
            } else {
                "DOES NOT FAIL"
            }
        );
    }
    if let Some(f) = c.fails_off_motion {
        let at = c.breaks_at.as_ref().map_or(String::new(), |b| {
            format!(
                ", breaking at `=` no. {}",
                b.iter().map(u32::to_string).collect::<Vec<_>>().join(", ")
            )
        });
        let _ = writeln!(
            o,
            "    off the motion: {}{at}",
            if f {
                "fails, as an on-shell identity must"
            } else {
                "HOLDS (the check cannot tell)"
            }
        );
    }
    let _ = writeln!(o, "    proof: {} · units: {}", c.proof, c.units);
}

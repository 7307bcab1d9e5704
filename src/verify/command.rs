//! The `verify` and `errata` subcommands: printing and exit codes.

use super::errata::errata;
use super::{counts, table, verify_all, EquationResult};
use crate::registry::check::Config;
use crate::registry::units::Units;
use serde_json::json;
use std::process::ExitCode;
use std::time::Instant;

/// Run `ladder verify`; exit 0 when every equation is verified, a definition or a recorded
/// erratum, 1 otherwise.
pub fn verify(json_out: bool, cfg: &Config, only: Option<&str>) -> ExitCode {
    let t = Instant::now();
    let results = match only.map(|spec| super::legend::only(verify_all(cfg), spec)) {
        None => verify_all(cfg),
        Some(Ok(r)) => r,
        Some(Err(msg)) => {
            eprintln!("ladder verify: {msg}");
            return ExitCode::from(2);
        }
    };
    let docs = crate::docs::check_book(&crate::docs::default_dir());
    let methods = crate::verify::check_methods(cfg);
    let extensions = crate::verify::verify_extensions(cfg);
    let seconds = t.elapsed().as_secs_f64();
    let (v, e, d, f) = counts(&results);
    let (proved, sampled_only, proof_seconds) = proof_counts(&results);
    if json_out {
        let out = json!({
            "equations": results,
            "summary": {"verified": v, "erratum": e, "definition": d, "failed": f,
                         "proved": proved, "sampled_only": sampled_only, "proof_seconds": proof_seconds,
                         "float_cases_per_check": cfg.float_cases, "exact_points_per_check": cfg.exact_points,
                         "seed": cfg.seed, "seconds": seconds,
                         "print": print_summary(&results)},
            "docs": {"problems": docs.problems, "sections": docs.equations_found, "examples_run": docs.examples_run},
            "methods": methods,
            "extensions": extensions,
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("JSON of plain data")
        );
    } else {
        print!("{}", table(&results));
        println!("{}", summary_line(&results, cfg, seconds));
        let (pd, nd, pf, nf, pm) = super::print_coverage(&results);
        println!(
            "print: {pd} of {nd} displays parsed in full, {pf} of {nf} printed forms parsed and checked, {pm} displays with every Rust form matching the print (equations/symbols.toml)"
        );
        print!("{}", super::legend::legend(cfg));
        print!("{}", super::legend::law_lines(&results));
        println!("beyond the note: the floor phase after the ladder leaves the wall (equations/phase2.md)");
        print!(
            "{}",
            table(&extensions)
                .lines()
                .skip(1)
                .map(|l| format!("{l}\n"))
                .collect::<String>()
        );
        let failed_methods: Vec<_> = methods.iter().filter(|m| !m.passed).collect();
        println!(
            "methods: {} derivations of the equation of motion checked (θ̈ solved from each equals (5); each residual vanishes on the motion only), {} failed",
            methods.len(),
            failed_methods.len()
        );
        for m in failed_methods {
            println!("  ! {}: {}", m.name, m.problems.join("; "));
        }
        println!(
            "docs: {} equations found in equations/*.md, {} example rows run, {} problems",
            docs.equations_found,
            docs.examples_run,
            docs.problems.len()
        );
        for p in &docs.problems {
            println!("  ! {p}");
        }
    }
    if f == 0 && docs.problems.is_empty() && results.len() == 90 && methods.iter().all(|m| m.passed)
    {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

fn print_summary(results: &[EquationResult]) -> serde_json::Value {
    let (pd, nd, pf, nf, pm) = super::print_coverage(results);
    json!({"displays_parsed": pd, "displays": nd, "forms_parsed": pf, "forms": nf, "displays_matching_code": pm})
}

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

/// Run `ladder errata`.
pub fn errata_command(json_out: bool, cfg: &Config) -> ExitCode {
    let list = errata(cfg);
    let prose = super::claims::claims();
    let all_good = prose
        .iter()
        .all(|c| c.holds && c.printed_fails != Some(false))
        && list
            .iter()
            .all(|r| r.units.corrected != Units::Inconsistent);
    if json_out {
        let prose_errata: Vec<_> = prose.iter().filter(|c| c.erratum.is_some()).collect();
        let out = json!({"errata": list, "prose": prose_errata, "claims": prose,
                         "prose_units": super::units::prose_units()});
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("JSON of plain data")
        );
    } else {
        println!(
            "misprinted equations (the printed form fails exactly; the corrected form holds):"
        );
        for r in &list {
            println!("({}) printed:   {}", r.number, r.printed);
            println!("     corrected: {}", r.corrected);
            println!("     why: {}", r.why);
            println!("     printed − corrected: {}", r.difference_text);
            println!(
                "     residual at an exact point: printed {} (= {:.6e}), corrected {}",
                r.printed_residual_exact, r.printed_residual, r.corrected_residual
            );
            println!("     {}", r.units.doc_line().trim_start_matches("- "));
        }
        println!("\nclaims made in the prose, checked exactly at three random states:");
        for c in &prose {
            let verdict = match (c.holds, c.printed_fails) {
                (true, None) if c.erratum.is_some() => {
                    "PROSE ERRATUM (wording; the formula is right)"
                }
                (true, None) => "holds",
                (true, Some(true)) => {
                    "PROSE ERRATUM: the printed wording fails, the correction holds"
                }
                _ => "FAILED",
            };
            println!("  {:<16} {}: {verdict}", c.location, c.claim);
            if let Some((printed, corrected)) = c.erratum {
                println!("  {:<16}   printed: {printed}   corrected: {corrected}", "");
            }
        }
    }
    if !json_out {
        println!("\nquantities stated in the prose, in dimensions (m: M, l: L, g: L T⁻², θ̇: T⁻¹):");
        for p in super::units::prose_units() {
            let detail = p
                .units_detail
                .map(|d| format!(" ({d})"))
                .unwrap_or_default();
            let fix = p
                .corrected
                .map(|c| format!("; corrected {}", c.name()))
                .unwrap_or_default();
            println!(
                "  {:<20} {}: {}{detail}{fix}",
                p.location,
                p.stated,
                p.units.name()
            );
        }
    }
    if all_good {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

//! `ladder errata`: the note's misprints (printed and corrected forms with their residuals), the
//! claims of its prose and the units it states; exit 1 when one of them does not hold as recorded.

use crate::registry::check::Config;
use crate::verify::errata::errata;
use clap::Args;
use serde_json::json;
use std::process::ExitCode;

/// The options of `ladder errata`.
#[derive(Args)]
pub struct ErrataArgs {
    /// Print JSON.
    #[arg(long)]
    json: bool,
}

/// Run `ladder errata` with its options.
pub fn run(a: ErrataArgs) -> ExitCode {
    errata_command(a.json, &Config::default())
}

/// Run `ladder errata`.
pub fn errata_command(json_out: bool, cfg: &Config) -> ExitCode {
    let list = errata(cfg);
    let prose = crate::verify::claims::claims();
    let all_good = prose
        .iter()
        .all(|c| c.holds && c.printed_fails != Some(false))
        && list.iter().all(|r| r.units.holds());
    if json_out {
        let prose_errata: Vec<_> = prose.iter().filter(|c| c.erratum.is_some()).collect();
        let out = json!({"errata": list, "prose": prose_errata, "claims": prose,
                         "prose_units": crate::verify::units::prose_units()});
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
            if r.units.printed != r.units.printed_code {
                println!(
                    "     ! units: the print's form is {}, its Rust encoding {}",
                    r.units.printed.name(),
                    r.units.printed_code.name()
                );
            }
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
        for p in crate::verify::units::prose_units() {
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

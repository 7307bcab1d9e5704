//! `ladder errata`: the note's misprints (printed and corrected forms with their residuals), the
//! claims of its prose and the units it states; exit 1 when one of them does not hold as recorded.

use crate::print::unicode::unicode;
use crate::registry::check::Config;
use crate::verify::claims::Claim;
use crate::verify::errata::{errata, ErratumReport};
use crate::verify::fill::fill;
use clap::Args;
use serde_json::json;
use std::process::ExitCode;

/// The options of `ladder errata`.
#[derive(Args)]
pub struct ErrataArgs {
    /// Print JSON.
    #[arg(long)]
    json: bool,
    /// Lay the text out for this many columns (default: the terminal's width, or 100 when the
    /// output is not a terminal).
    #[arg(long, value_parser = clap::value_parser!(u16).range(60..))]
    width: Option<u16>,
}

/// Run `ladder errata` with its options.
pub fn run(a: ErrataArgs) -> ExitCode {
    errata_command(a.json, &Config::default(), super::verify::columns(a.width))
}

/// Run `ladder errata`, its text filled to `columns`: the misprints, the prose claims and the
/// units the prose states; exit 1 when a claim or an erratum's units witness does not hold.
pub fn errata_command(json_out: bool, cfg: &Config, columns: usize) -> ExitCode {
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
        print!("{}", fill(&misprint_text(&list), columns));
        say(
            columns,
            "\nclaims made in the prose, checked (exactly at three random states, on general systems or rolling bodies; sec. B.10 by an integrated 3-D model held to its closed form):",
        );
        for c in &prose {
            print_claim(c, columns);
        }
        print_prose_units(columns);
    }
    if all_good {
        ExitCode::SUCCESS
    } else {
        let claims = prose
            .iter()
            .filter(|c| !(c.holds && c.printed_fails != Some(false)))
            .count();
        let units = list.iter().filter(|r| !r.units.holds()).count();
        eprintln!(
            "ladder errata: exit 1: {claims} prose claims do not hold as recorded, {units} errata fail their units witness"
        );
        ExitCode::from(1)
    }
}

/// Print one line of the text, filled to the terminal's width.
fn say(columns: usize, line: &str) {
    println!("{}", fill(line, columns));
}

/// One claim of the prose with its verdict; for a prose erratum the printed and corrected
/// wording and, when the correction is proved, the misprint's reading or difference.
fn print_claim(c: &Claim, columns: usize) {
    let verdict = c.verdict();
    say(
        columns,
        &format!("  {:<16} {}: {verdict}", c.location, c.claim),
    );
    if let Some((printed, corrected)) = c.erratum {
        // LaTeX in --json; here, as the terminal reads it (a wording erratum is words,
        // which the LaTeX reader would run together).
        let read = |t: &str| {
            if t.contains('\\') {
                unicode(t)
            } else {
                t.to_string()
            }
        };
        say(
            columns,
            &format!(
                "  {:<16}   printed: {}   corrected: {}",
                "",
                read(printed),
                read(corrected)
            ),
        );
    }
    if let Some(r) = &c.reading_latex {
        say(
            columns,
            &format!(
                "  {:<16}   misprint: {}   (for any state; the correction is proved symbolically)",
                "",
                crate::verify::errata_reading::plain(r)
            ),
        );
    } else if let Some(d) = &c.difference_latex {
        say(columns, &format!(
            "  {:<16}   printed − corrected = {}   (for any state; the correction is proved symbolically)",
            "",
            crate::print::unicode::unicode(d)
        ));
    }
}

/// The quantities the prose states, each with its dimensions (and the corrected form's, for a
/// prose erratum).
fn print_prose_units(columns: usize) {
    say(
        columns,
        "\nquantities stated in the prose, in dimensions (m: M, l: L, g: L T⁻², θ̇: T⁻¹):",
    );
    for p in crate::verify::units::prose_units() {
        let detail = p
            .units_detail
            .map(|d| format!(" ({d})"))
            .unwrap_or_default();
        let fix = p
            .corrected
            .map(|c| format!("; corrected {}", c.name()))
            .unwrap_or_default();
        say(
            columns,
            &format!(
                "  {:<20} {}: {}{detail}{fix}",
                p.location,
                p.stated,
                p.units.name()
            ),
        );
    }
}

/// The misprints as a teacher reads them: each formula in Unicode (the LaTeX is in `--json`),
/// which form of the display is misprinted, and the exact point its residual is taken at.
pub fn misprint_text(list: &[ErratumReport]) -> String {
    let mut out = String::from(
        "misprinted equations (the printed form fails exactly; the corrected form holds; LaTeX in --json):\n",
    );
    let eqs = crate::registry::equations();
    for r in list {
        let e = eqs.iter().find(|e| e.number == r.number);
        let page = crate::show::source::docs_page(r.number)
            .and_then(|p| p.line.map(|l| format!(" · {}:{l}", p.file)))
            .unwrap_or_default();
        out += &format!(
            "({}) {} · sec. {}{page}\n",
            r.number,
            e.map_or("", |e| e.title),
            e.map_or("", |e| e.section)
        );
        let which = match r.misprinted_form {
            Some(k) => format!("form {k} of the display"),
            None => "a form of the display".into(),
        };
        out += &format!(
            "     printed:   {}   ({which}, as printed)\n",
            unicode(r.printed)
        );
        out += &format!("     corrected: {}\n", unicode(r.corrected));
        out += &format!("     why: {}\n", r.why);
        let ladder = r.point.iter().any(|(n, _)| n == "sin θ");
        let legend = if ladder {
            "s = sin θ, c = cos θ"
        } else {
            "per particle: the term of particle 1 of the sum"
        };
        // In physical terms where a reading fits; a subtraction such as (1 − m) is not one.
        out += &match &r.reading {
            Some(reading) => format!("     misprint: {reading}   ({legend}; for any state)\n"),
            None => format!(
                "     printed − corrected = {}, in {}   ({legend}; for any state)\n",
                unicode(&r.difference_latex),
                r.residual_unit
            ),
        };
        let minus = |s: &str| s.replace('-', "−");
        let point: Vec<String> = r
            .point
            .iter()
            .map(|(n, v)| format!("{n} = {}", minus(v)))
            .collect();
        out += &format!("     at the exact point (SI units) {}:\n", point.join(", "));
        let of = r
            .residual_component
            .map(|c| format!(" ({c} component)"))
            .unwrap_or_default();
        out += &format!(
            "       residual{of}: {which} as printed − '{}' = {} {u} (≈ {} {u}); corrected − '{}' = {}\n",
            r.residual_against,
            minus(&r.printed_residual_exact),
            minus(&approx(r.printed_residual)),
            r.residual_against,
            minus(&r.corrected_residual),
            u = r.residual_unit
        );
        out += &format!("     {}\n", r.units.doc_line().trim_start_matches("- "));
        if r.units.printed != r.units.printed_code {
            out += &format!(
                "     ! units: the print's form is {}, its Rust encoding {}\n",
                r.units.printed.name(),
                r.units.printed_code.name()
            );
        }
    }
    out
}

/// Six decimals without trailing zeros: 331.776, −242.64, −1204.
fn approx(x: f64) -> String {
    let s = format!("{x:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

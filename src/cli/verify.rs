//! `ladder verify`: every equation checked, printed as a table or JSON, and the exit code.

use crate::registry::check::Config;
use crate::verify::fill::{fill, DEFAULT_WIDTH};
use crate::verify::summary::{
    print_proof_counts, proof_counts, schwartz_zippel_sentence, summary_line,
};
use crate::verify::table::render_for;
use crate::verify::{counts, print_coverage, verify_all, EquationResult};
use clap::Args;
use serde_json::json;
use std::process::ExitCode;
use std::time::Instant;

/// The options of `ladder verify`.
#[derive(Args)]
pub struct VerifyArgs {
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
    /// Random float states per check.
    #[arg(long, default_value_t = Config::default().float_cases)]
    cases: usize,
    /// Random exact rational points per check (at least 1).
    #[arg(long, default_value_t = Config::default().exact_points)]
    exact_points: usize,
    /// Seed of the random states.
    #[arg(long, default_value_t = Config::default().seed)]
    seed: u64,
    /// Show only these displays: equation numbers, labels beyond the note or sections, e.g.
    /// `25,28`, `P8` or `2.5`.
    #[arg(long)]
    only: Option<String>,
    /// Under every row, the checks run and the law of motion the display uses.
    #[arg(long)]
    wide: bool,
    /// Lay the text out for this many columns (default: the terminal's width, or 100 when the
    /// output is not a terminal); from 146 columns on, one line per display.
    #[arg(long, value_parser = clap::value_parser!(u16).range(60..))]
    width: Option<u16>,
}

/// The columns to lay text out for: `--width`, else the terminal's width, else
/// [`DEFAULT_WIDTH`] (a pipe, a file).
pub fn columns(width: Option<u16>) -> usize {
    width
        .map(usize::from)
        .or_else(|| {
            console::Term::stdout()
                .size_checked()
                .map(|(_, c)| usize::from(c))
        })
        .unwrap_or(DEFAULT_WIDTH)
}

/// Run `ladder verify` with its options.
pub fn run(a: VerifyArgs) -> ExitCode {
    // The exact points decide the exact verdict and find where an on-shell display breaks off
    // the motion (its law step): with none, every on-shell display would fail for a reason that
    // is not its own.
    if a.exact_points == 0 {
        eprintln!("ladder verify: --exact-points 0: at least 1 is needed (the exact verdict and each on-shell display's law step are found at exact points)");
        return ExitCode::from(2);
    }
    verify(
        a.json,
        &Config {
            float_cases: a.cases,
            exact_points: a.exact_points,
            seed: a.seed,
        },
        a.only.as_deref(),
        a.wide,
        columns(a.width),
    )
}

/// Run `ladder verify`; exit 0 when every equation is verified, a definition or a recorded
/// erratum, 1 otherwise.
pub fn verify(
    json_out: bool,
    cfg: &Config,
    only: Option<&str>,
    wide: bool,
    columns: usize,
) -> ExitCode {
    let t = Instant::now();
    let (results, extensions) = match only {
        None => (verify_all(cfg), crate::verify::verify_extensions(cfg)),
        Some(spec) => match verify_only(spec, cfg) {
            Ok(both) => both,
            Err(msg) => {
                eprintln!("ladder verify: {msg}");
                return ExitCode::from(2);
            }
        },
    };
    let docs = crate::docs::check_book(&crate::docs::note_dir());
    let methods = crate::verify::check_methods(cfg);
    let seconds = t.elapsed().as_secs_f64();
    let run = Run {
        results: &results,
        extensions: &extensions,
        docs: &docs,
        methods: &methods,
        cfg,
        seconds,
    };
    if json_out {
        println!(
            "{}",
            serde_json::to_string_pretty(&json_report(&run)).expect("JSON of plain data")
        );
    } else {
        print!("{}", text_report(&run, wide, columns));
    }
    let reasons = failure_reasons(&results, &extensions, docs.problems.len(), &methods);
    if reasons.is_empty() {
        ExitCode::SUCCESS
    } else {
        eprintln!("ladder verify: exit 1: {}", reasons.join("; "));
        ExitCode::from(1)
    }
}

/// What one run of `ladder verify` found, for its JSON and its text.
struct Run<'a> {
    results: &'a [EquationResult],
    extensions: &'a [EquationResult],
    docs: &'a crate::docs::BookReport,
    methods: &'a [crate::verify::MethodResult],
    cfg: &'a Config,
    seconds: f64,
}

/// `--only SPEC`: pick the displays first, the note's and those beyond it (from rows judged
/// without checks, which carry number, label and section), then run only their checks: the
/// note's rows and the extension's, each possibly empty.
fn verify_only(
    spec: &str,
    cfg: &Config,
) -> Result<(Vec<EquationResult>, Vec<EquationResult>), String> {
    let (note, beyond) = (crate::registry::equations(), crate::registry::extensions());
    let blank: Vec<_> = note
        .iter()
        .chain(&beyond)
        .map(|e| crate::verify::judge(e, &[]))
        .collect();
    let keep = crate::verify::legend::only(blank, spec)?;
    let picked = |eqs: Vec<crate::registry::Equation>| {
        let eqs = eqs
            .into_iter()
            .filter(|e| keep.iter().any(|r| r.number == e.number))
            .collect();
        crate::verify::verify_equations(eqs, cfg)
    };
    Ok((picked(note), picked(beyond)))
}

/// `ladder verify --json`: every row, the summary, the book's files, the derivations and the
/// extension beyond the note.
fn json_report(run: &Run) -> serde_json::Value {
    let (results, cfg) = (run.results, run.cfg);
    let (v, e, d, f) = counts(results);
    let (proved, sampled_only, proof_seconds) = proof_counts(results);
    json!({
        "equations": results,
        "summary": {"verified": v, "erratum": e, "definition": d, "failed": f,
                     "proved": proved, "sampled_only": sampled_only, "proof_seconds": proof_seconds,
                     "proof_particle_counts": crate::registry::prove::PARTICLE_COUNTS.collect::<Vec<_>>(),
                     "sz_bound_log10": worst_sz_log10(results, |r| r.sz_bound_log10),
                     "sz_bound_rational_log10": worst_sz_log10(results, |r| r.sz_bound_rational_log10),
                     "float_cases_per_check": cfg.float_cases, "exact_points_per_check": cfg.exact_points,
                     "seed": cfg.seed, "seconds": run.seconds,
                     "print": print_summary(results)},
        "docs": {"problems": run.docs.problems, "sections": run.docs.equations_found, "examples_run": run.docs.examples_run},
        "methods": run.methods,
        "extensions": run.extensions,
    })
}

/// One line of the text, filled to `columns`.
fn push_line(text: &mut String, s: &str, columns: usize) {
    text.push_str(&fill(s, columns));
    text.push('\n');
}

/// The note's rows, their summary, the Schwartz-Zippel sentence and the print coverage.
fn note_table(run: &Run, wide: bool, columns: usize) -> String {
    let (results, cfg) = (run.results, run.cfg);
    let mut text = render_for(results, wide, columns);
    push_line(&mut text, &summary_line(results, cfg, run.seconds), columns);
    push_line(
        &mut text,
        &format!("  {}", schwartz_zippel_sentence(results)),
        columns,
    );
    let (pd, nd, pf, nf, pm) = print_coverage(results);
    let (pp, ppf) = print_proof_counts(results);
    push_line(&mut text, &format!(
        "print: {pd} of {nd} displays parsed in full, {pf} of {nf} printed forms parsed and checked, {pm} displays with every Rust form matching the print (src/print/symbols.toml); {pp} of {nd} displays proved symbolically as printed ({ppf} forms)"
    ), columns);
    text
}

/// `ladder verify` as a teacher reads it: the table, the summary and its legend, the extension
/// beyond the note, the derivations and the book's files, filled to `columns`.
fn text_report(run: &Run, wide: bool, columns: usize) -> String {
    let (results, cfg) = (run.results, run.cfg);
    // `--only` may pick rows beyond the note alone: then there is no note table to sum up.
    let mut text = if results.is_empty() {
        String::new()
    } else {
        note_table(run, wide, columns)
    };
    text.push_str(&fill(&crate::verify::legend::legend(cfg), columns));
    if !results.is_empty() {
        text.push_str(&fill(&crate::verify::legend::law_lines(results), columns));
    }
    if !run.extensions.is_empty() {
        push_line(
            &mut text,
            "beyond the note: the floor phase after the ladder leaves the wall (equations/phase2.md)",
            columns,
        );
        text.extend(
            render_for(run.extensions, wide, columns)
                .lines()
                .skip(if columns >= crate::verify::table::FULL_WIDTH {
                    1
                } else {
                    2
                })
                .map(|l| format!("{l}\n")),
        );
    }
    let failed_methods: Vec<_> = run.methods.iter().filter(|m| !m.passed).collect();
    push_line(&mut text, &format!(
        "methods: {} derivations of the equation of motion checked (θ̈ solved from each equals (5); each residual vanishes on the motion only), {} failed",
        run.methods.len(),
        failed_methods.len()
    ), columns);
    for m in failed_methods {
        push_line(
            &mut text,
            &format!("  ! {}: {}", m.name, m.problems.join("; ")),
            columns,
        );
    }
    push_line(
        &mut text,
        &format!(
            "docs: {} equations found in {}/*.md, {} example rows run, {} problems",
            run.docs.equations_found,
            crate::docs::note_dir().display(),
            run.docs.examples_run,
            run.docs.problems.len()
        ),
        columns,
    );
    for p in &run.docs.problems {
        push_line(&mut text, &format!("  ! {p}"), columns);
    }
    push_line(&mut text, "details of one display: ladder show N (e.g. ladder show 25 --at \"m=2, l=1.5, theta=40deg\")", columns);
    text
}

/// Why `ladder verify` exits 1, one phrase per reason (empty: it exits 0).
fn failure_reasons(
    results: &[EquationResult],
    extensions: &[EquationResult],
    doc_problems: usize,
    methods: &[crate::verify::MethodResult],
) -> Vec<String> {
    let failed = |rs: &[EquationResult]| -> Vec<String> {
        rs.iter()
            .filter(|r| r.status == crate::verify::Status::Failed)
            .map(|r| match &r.doc {
                Some(at) => format!("{} ({at})", r.label),
                None => r.label.clone(),
            })
            .collect()
    };
    let mut out = Vec::new();
    let (note, ext) = (failed(results), failed(extensions));
    if !note.is_empty() {
        out.push(format!("failed: {}", note.join(", ")));
    }
    if !ext.is_empty() {
        out.push(format!("failed beyond the note: {}", ext.join(", ")));
    }
    if doc_problems > 0 {
        out.push(format!("{doc_problems} problems in the book's files"));
    }
    let bad: Vec<&str> = methods
        .iter()
        .filter(|m| !m.passed)
        .map(|m| m.name)
        .collect();
    if !bad.is_empty() {
        out.push(format!("methods failed: {}", bad.join(", ")));
    }
    out
}

/// The largest Schwartz-Zippel bound of the run as a power of ten (rounded up, as the summary
/// line prints it), which does not underflow where the bound itself would.
fn worst_sz_log10(results: &[EquationResult], f: fn(&EquationResult) -> f64) -> f64 {
    results
        .iter()
        .map(f)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
}

fn print_summary(results: &[EquationResult]) -> serde_json::Value {
    let (pd, nd, pf, nf, pm) = print_coverage(results);
    let (pp, ppf) = print_proof_counts(results);
    json!({"displays_parsed": pd, "displays": nd, "forms_parsed": pf, "forms": nf, "displays_matching_code": pm,
           "displays_proved": pp, "forms_proved": ppf})
}

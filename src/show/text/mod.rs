//! The terminal rendering of a shown display and of a search: the heading, the state and the
//! closing parts here; the forms' table in `forms.rs`, the checks in `checks.rs`.

use super::find::Hit;
use super::Shown;
use crate::verify::Status;
use std::fmt::Write;

mod checks;
mod forms;

use checks::checks;
use forms::forms_table;

fn status(s: Option<Status>) -> &'static str {
    match s {
        Some(Status::Verified) => "verified",
        Some(Status::Erratum) => "erratum",
        Some(Status::Definition) => "definition",
        Some(Status::Failed) => "FAILED",
        None => "checks not run (--values-only)",
    }
}

/// A state value: ten significant decimals at most, no trailing zeros.
fn short(x: f64) -> String {
    let s = format!("{x:.10}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.replace('-', "−")
    }
}

/// The whole display, for the terminal: its print and symbols, the state, the forms' values,
/// and (unless `--values-only`) the checks, then the erratum, code and problems.
pub fn render(s: &Shown) -> String {
    let mut o = String::new();
    heading(&mut o, s);
    state_lines(&mut o, s);
    forms_table(&mut o, s);
    let Some(v) = &s.verify else {
        let _ = writeln!(o, "\nchecks: not run (--values-only)");
        return finish(o, s);
    };
    checks(&mut o, s, v);
    finish(o, s)
}

/// The display's title line, print, reading, premises, blind symbols and symbol table.
fn heading(o: &mut String, s: &Shown) {
    let _ = writeln!(
        o,
        "{} {} · sec. {} · {} · {}",
        s.label,
        s.title,
        s.section,
        s.kind,
        status(s.status)
    );
    let _ = writeln!(
        o,
        "  printed: {}",
        s.latex.split_whitespace().collect::<Vec<_>>().join(" ")
    );
    let _ = writeln!(o, "  reads:   {}", s.unicode);
    for (k, line) in s.premises.iter().enumerate() {
        let _ = writeln!(
            o,
            "  {} {line}",
            if k == 0 { "assumes:" } else { "        " }
        );
    }
    for line in &s.indistinguishable {
        let _ = writeln!(o, "  blind:   {line}");
    }
    let _ = writeln!(o, "\nsymbols (src/print/symbols.toml)");
    for y in &s.symbols {
        let milne = if y.milne { " (Milne)" } else { "" };
        let _ = writeln!(
            o,
            "  {:<10} {}{milne} · {} · defined {}",
            y.unicode, y.meaning, y.unit, y.defined
        );
    }
}

/// The state the forms are evaluated at: how it was completed, its phase and warnings, whether
/// it is exact, and why the forms need not agree there.
fn state_lines(o: &mut String, s: &Shown) {
    let st = &s.state;
    let _ = writeln!(
        o,
        "\nat m = {} kg, l = {} m, g = {} m/s², θ = {} rad ({}°): θ̇ = {} rad/s, θ̈ = {} rad/s², θ⃛ = {} rad/s³",
        short(st.m), short(st.l), short(st.g), short(st.theta), short(st.theta_deg), short(st.theta_dot), short(st.theta_ddot), short(st.theta_dddot)
    );
    for h in &st.how {
        let _ = writeln!(o, "  {h}");
    }
    let ph = &st.phase;
    let _ = writeln!(
        o,
        "  phase: {} (F_w = {} N, F_f = {} N by (14), (15))",
        ph.phase,
        short(ph.wall_force),
        short(ph.floor_force)
    );
    for w in &ph.warnings {
        let _ = writeln!(o, "  warning: {w}");
    }
    match &st.why_not_exact {
        Some(w) => {
            let _ = writeln!(o, "  exact values: none here: {w}");
        }
        None => {
            let _ = writeln!(
                o,
                "  exact values: every input is rational, so each form is also evaluated exactly"
            );
        }
    }
    if let Some(p) = &s.place {
        let _ = writeln!(
            o,
            "  a general display, evaluated on the ladder's three particles with {}",
            p.point
        );
    }
    if let Some(a) = &s.assumption {
        let _ = writeln!(o, "  note: its forms need not agree here: {a}");
    }
}

/// The erratum, the code and docs locations and the problems.
fn finish(mut o: String, s: &Shown) -> String {
    if let Some(er) = &s.erratum {
        let _ = writeln!(o, "\nerratum");
        let _ = writeln!(o, "  printed:   {}", er.printed);
        let _ = writeln!(o, "  corrected: {}", er.corrected);
        let _ = writeln!(o, "  why: {}", er.why);
        // In physical terms where a reading fits; a subtraction such as (1 − m) is not one.
        match &er.reading {
            Some(r) => {
                let _ = writeln!(o, "  misprint: {r}");
            }
            None => {
                let _ = writeln!(
                    o,
                    "  printed − corrected: {}, in {}",
                    er.difference_text, er.residual_unit
                );
            }
        }
        let _ = writeln!(o, "  {}", er.units.doc_line().trim_start_matches("- "));
    }
    let _ = writeln!(o, "\ncode");
    for c in &s.code {
        let at = c.line.map_or(format!("{} (not found)", c.file), |l| {
            format!("{}:{l}", c.file)
        });
        let _ = writeln!(o, "  {:<48} {at}", c.name);
    }
    if let Some(d) = &s.docs {
        let _ = writeln!(o, "docs\n  {}:{}  {}", d.file, d.line.unwrap_or(0), d.name);
    }
    for p in &s.problems {
        let _ = writeln!(o, "! {p}");
    }
    o
}

/// The displays a word search found.
pub fn hits(query: &str, hits: &[Hit]) -> String {
    let mut o = String::new();
    let _ = writeln!(o, "{} displays match '{query}':", hits.len());
    for h in hits {
        let _ = writeln!(
            o,
            "  ({:>2})  sec. {:<5} {:<46} {}",
            h.number, h.section, h.title, h.why
        );
    }
    let _ = writeln!(o, "ladder show N for one of them in full");
    o
}

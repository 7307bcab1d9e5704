//! Below each numbered display, folded (`<details>`, no script): its live status from the
//! checks, the forms checked, the residual and the proof, the Rust functions (file and line),
//! and for an erratum the printed and corrected forms with their difference. The display itself
//! has the page's full width, so a long torque expansion is not squeezed beside the panel.

use super::code::{page_of, Location};
use super::math::mathml;
use super::pages::esc;
use crate::verify::errata::ErratumReport;
use crate::verify::{EquationResult, Status};

/// The status word used in the HTML (`data-status`) and the JSON of `ladder verify`.
pub fn status_name(s: Status) -> &'static str {
    match s {
        Status::Verified => "verified",
        Status::Erratum => "erratum",
        Status::Definition => "definition",
        Status::Failed => "failed",
    }
}

/// The anchor of a numbered display: `eq-12`, `eq-P3`.
pub fn anchor(label: &str) -> String {
    format!("eq-{}", label.trim_matches(|c| c == '(' || c == ')'))
}

/// A registered function and where it was found.
pub struct Function<'a> {
    /// Its path below the crate root.
    pub path: &'a str,
    /// Its file and line, when found.
    pub location: Option<Location>,
}

/// The numbered display (MathML in a `formula` box, its number beside it) and below it the
/// folded panel of its checks.
pub fn numbered_display(
    latex: &str,
    r: &EquationResult,
    functions: &[Function],
    erratum: Option<&ErratumReport>,
) -> Result<String, String> {
    let m = mathml(latex, true).map_err(|e| format!("{}: {e}", r.label))?;
    let status = status_name(r.status);
    Ok(format!(
        "<div class=\"eq\" id=\"display-{a}\" data-number=\"{n}\" data-status=\"{status}\" data-proved=\"{p}\" data-units=\"{u}\">\n\
<div class=\"display\"><div class=\"formula\">{m}</div><span class=\"eqno\">{label}</span></div>\n{panel}</div>\n",
        a = anchor(&r.label),
        n = r.number,
        p = r.proved,
        u = r.units.name(),
        label = esc(&r.label),
        panel = panel(r, functions, erratum)?
    ))
}

fn badges(r: &EquationResult) -> String {
    super::reader::badge(r.status)
}

/// The technical status, for the panel: the status of `ladder verify` and the proof, each word
/// linked to the glossary.
fn technical_status(r: &EquationResult) -> String {
    use super::reader::term;
    let mut s = format!(
        "<code>{}</code> in <code>ladder verify</code>",
        status_name(r.status)
    );
    if r.proved {
        s.push_str(&format!("; {}", term("proved", "proved symbolically")));
    }
    s
}

fn forms_checked(r: &EquationResult) -> String {
    let mut s = format!(
        "{} check{}: {}",
        r.checks.len(),
        if r.checks.len() == 1 { "" } else { "s" },
        esc(&r.checks.join("; "))
    );
    if r.print_forms > 0 {
        s.push_str(&format!(
            ". Print: {} of {} forms parsed, {} held against another printed form{}",
            r.print_parsed,
            r.print_forms,
            r.print_checked,
            if r.print_matches_code {
                "; every Rust form matches the print"
            } else {
                "; some Rust form matches no printed form"
            }
        ));
    }
    s
}

fn residual(r: &EquationResult) -> String {
    format!(
        "worst {:.3} error bounds over {} float states (pass ≤ 4); {} at {} {} \
({} chance of a false pass ≤ 1e{})",
        r.max_residual,
        r.cases,
        if r.exact { "zero" } else { "not zero" },
        r.exact_points,
        super::reader::term("exact", "exact points"),
        super::reader::term("schwartz-zippel", "Schwartz–Zippel"),
        r.sz_bound_log10.ceil()
    )
}

fn function_links(functions: &[Function]) -> String {
    functions
        .iter()
        .map(|f| match &f.location {
            Some(l) => format!(
                "<a href=\"{}#L{}\"><code>{}</code></a> <small>({}:{})</small>",
                esc(&page_of(&l.file)),
                l.line,
                esc(f.path),
                esc(&l.file),
                l.line
            ),
            None => format!(
                "<code>{}</code> <small>(not found in the source)</small>",
                esc(f.path)
            ),
        })
        .collect::<Vec<_>>()
        .join("<br />")
}

fn erratum_forms(e: &ErratumReport) -> Result<String, String> {
    let label = format!("({})", e.number);
    let m = |l: &str| mathml(l, false).map_err(|x| format!("{label}: {x}"));
    Ok(format!(
        "<div class=\"erratum-forms\"><dl>\
<dt>Printed</dt><dd>{}</dd><dt>Corrected</dt><dd>{}</dd>\
<dt>{}</dt><dd>{}</dd>\
<dt>At an exact point</dt><dd>printed residual {} {u}, corrected {}</dd>\
<dt>Why</dt><dd>{}</dd></dl></div>",
        m(e.printed)?,
        m(e.corrected)?,
        misprint_label(e),
        misprint(e).map_err(|x| format!("{label}: {x}"))?,
        esc(&e.printed_residual_exact),
        esc(&e.corrected_residual),
        esc(e.why),
        u = esc(&e.residual_unit)
    ))
}

/// The label of [`misprint`]: what the printed form lost, or (no reading fits) the difference.
pub fn misprint_label(e: &ErratumReport) -> &'static str {
    if e.reading_latex.is_some() {
        "Misprint"
    } else {
        "Printed − corrected"
    }
}

/// The misprint in physical terms (its formulas as inline MathML), or printed − corrected with
/// its unit when no reading fits: "lacks a factor m", never "(1 − m)".
pub fn misprint(e: &ErratumReport) -> Result<String, String> {
    match &e.reading_latex {
        Some(md) => markdown_math(md),
        None => Ok(format!(
            "{} <small>({})</small>",
            mathml(&e.difference_latex, false)?,
            esc(&e.residual_unit)
        )),
    }
}

/// Text with `$…$` math as HTML: the text escaped, each formula as inline MathML.
pub fn markdown_math(md: &str) -> Result<String, String> {
    md.split('$')
        .enumerate()
        .map(|(i, part)| {
            if i % 2 == 1 {
                mathml(part, false)
            } else {
                Ok(esc(part))
            }
        })
        .collect()
}

/// The units verdict: the print's (every printed form in dimensions, the offending sum and form
/// named), and whether the Rust forms' verdict agrees.
fn units(r: &EquationResult) -> String {
    let detail = |d: &Option<String>| {
        d.as_deref()
            .map(|d| format!(": {}", esc(d)))
            .unwrap_or_default()
    };
    let whose = if r.print_forms > 0 {
        " (every printed form in dimensions)"
    } else {
        " (the Rust forms; beyond the note there is no print)"
    };
    let code = if r.print_forms == 0 {
        String::new()
    } else if r.units_code == r.units {
        "; the Rust forms agree".into()
    } else {
        format!(
            "; the Rust forms disagree: {}{}",
            r.units_code.name(),
            detail(&r.units_code_detail)
        )
    };
    format!(
        "{}{}{whose}{code}",
        esc(r.units.name()),
        detail(&r.units_detail)
    )
}

fn panel(
    r: &EquationResult,
    functions: &[Function],
    erratum: Option<&ErratumReport>,
) -> Result<String, String> {
    use super::reader::{kind_term, term};
    let kind = match kind_term(r.kind.name()) {
        Some(id) => term(id, &esc(r.kind.name())),
        None => esc(r.kind.name()),
    };
    let mut rows = vec![
        ("Status".to_string(), technical_status(r)),
        ("Kind".to_string(), kind),
        (term("forms", "Forms checked"), forms_checked(r)),
        (term("residual", "Residual"), residual(r)),
        (
            term("proved", "Proof"),
            format!("{} ({:.3} s)", esc(&r.proof), r.proof_seconds),
        ),
        (term("units", "Units"), units(r)),
    ];
    if let (Some(step), Some(law)) = (r.law_step, r.law) {
        rows.push((
            term("law", "Law"),
            format!("at <code>=</code> no. {step}: {}", esc(law)),
        ));
    }
    if let Some(off) = r.fails_off_shell {
        rows.push((
            term("off-motion", "Off the motion"),
            if off {
                "fails, as it must"
            } else {
                "holds too: the check cannot tell"
            }
            .into(),
        ));
    }
    rows.push(("Code".into(), function_links(functions)));
    for p in &r.problems {
        rows.push(("Problem".into(), esc(p)));
    }
    let dl: String = rows
        .iter()
        .map(|(k, v)| format!("<dt>{k}</dt><dd>{v}</dd>"))
        .collect();
    let forms = match erratum {
        Some(e) => erratum_forms(e)?,
        None => String::new(),
    };
    Ok(format!(
        "<details class=\"checks\"><summary><span class=\"status\">{}</span> checks of {}</summary><dl>{dl}</dl>{forms}</details>\n",
        badges(r),
        esc(&r.label)
    ))
}

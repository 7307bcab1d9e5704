//! The terminal rendering of a shown display and of a search.

use super::find::Hit;
use super::Shown;
use crate::verify::Status;
use std::fmt::Write;

/// A number as Rust prints it (the shortest text that reads back to the same double: two forms
/// that agree to the last digit print the same), with a true minus sign.
fn num(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x}").replace('-', "−")
    }
}

fn value(v: &[f64]) -> String {
    match v {
        [x] => num(*x),
        many => format!(
            "({})",
            many.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// An exact value, shortened when it is long (the JSON has it in full).
fn exact(v: &[String]) -> String {
    let short = |s: &String| {
        if s.chars().count() > 32 {
            format!(
                "{}…({} chars)",
                s.chars().take(24).collect::<String>(),
                s.chars().count()
            )
        } else {
            s.clone()
        }
    };
    match v {
        [x] => short(x),
        many => format!(
            "({})",
            many.iter().map(short).collect::<Vec<_>>().join(", ")
        ),
    }
}

fn status(s: Option<Status>) -> &'static str {
    match s {
        Some(Status::Verified) => "verified",
        Some(Status::Erratum) => "erratum",
        Some(Status::Definition) => "definition",
        Some(Status::Failed) => "FAILED",
        None => "checks not run (--values-only)",
    }
}

/// `check: side` entries grouped by check: `check: side1; side2`.
fn encoded(enc: &[String]) -> String {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    for e in enc {
        let (c, side) = e.split_once(": ").unwrap_or(("", e));
        match groups.iter_mut().find(|g| g.0 == c) {
            Some(g) => g.1.push(format!("'{side}'")),
            None => groups.push((c.to_string(), vec![format!("'{side}'")])),
        }
    }
    groups
        .into_iter()
        .map(|(c, sides)| format!("{} of check '{c}'", sides.join(", ")))
        .collect::<Vec<_>>()
        .join("; ")
}

/// Where the first chain breaks: between consecutive forms of which one agrees and the next not.
fn breaks(s: &Shown) -> String {
    let chain: Vec<_> = s
        .forms
        .iter()
        .filter(|f| f.chain == 1 && f.role != "misprint")
        .collect();
    let mut eq = Vec::new();
    for w in chain.windows(2) {
        if w[0].agrees.unwrap_or(true) != w[1].agrees.unwrap_or(true) {
            eq.push(format!("between forms {} and {}", w[0].index, w[1].index));
        }
    }
    if eq.is_empty() {
        String::new()
    } else {
        format!("; the chain breaks {}", eq.join(" and "))
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

/// Every printed form with its value, unit, residual and agreement, then the verdict here.
fn forms_table(o: &mut String, s: &Shown) {
    let _ = writeln!(
        o,
        "\nforms, in print order (each held against the first of its chain; residual = |difference| in running error bounds, agrees when ≤ {})",
        crate::registry::check::TOLERANCE_FACTOR
    );
    let _ = writeln!(
        o,
        "  {:>2} {:>2}  {:<44} {:<26} {:<16} {:>9}  agrees",
        "#", "ch", "form", "value (SI)", "unit", "residual"
    );
    for (k, f) in s.forms.iter().enumerate() {
        form_row(o, s, k, f);
    }
    let verdict = match (s.forms_agree, s.forms_agree_exactly) {
        (true, Some(true)) => "every printed form agrees, in f64 and exactly".to_string(),
        (true, _) => "every printed form agrees".to_string(),
        (false, x) => format!(
            "printed forms DISAGREE{}{}",
            if x == Some(false) {
                " (exactly too)"
            } else {
                ""
            },
            breaks(s)
        ),
    };
    let mis = if s.forms.iter().any(|f| f.role == "misprint") {
        if s.misprints_differ {
            "; the recorded misprint differs (in value or units), as it must"
        } else {
            "; the recorded misprint AGREES here"
        }
    } else {
        ""
    };
    let _ = writeln!(o, "  here: {verdict}{mis}");
}

/// One row of the forms table, with its exact value, unit warning, error and encodings.
fn form_row(o: &mut String, s: &Shown, k: usize, f: &super::values::FormValue) {
    let tag = match f.role {
        "misprint" => " [misprint]",
        "continued" => " [from (56)]",
        _ => "",
    };
    let milne = if f.milne { "Milne: " } else { "" };
    let form = format!("{milne}{}{tag}", f.unicode);
    let agrees = match (f.agrees, f.exact_agrees) {
        (None, _) if f.error.is_none() => "—".to_string(),
        (Some(a), e) => format!(
            "{}{}",
            if a { "yes" } else { "NO" },
            match e {
                Some(true) => ", exactly",
                Some(false) => ", not exactly",
                None => "",
            }
        ),
        _ => "?".into(),
    };
    let residual = f.residual.map_or("—".into(), |r| {
        if r < 1e4 {
            format!("{r:.3}")
        } else {
            format!("{r:.2e}")
        }
    });
    let val = if f.error.is_some() {
        "—".to_string()
    } else {
        value(&f.value)
    };
    let _ = writeln!(
        o,
        "  {:>2} {:>2}  {:<44} {:<26} {:<16} {:>9}  {}",
        f.index, f.chain, form, val, f.unit, residual, agrees
    );
    if let Some(x) = &f.exact {
        let _ = writeln!(o, "  {:>5}  exactly {}", "", exact(x));
    }
    if f.role == "misprint" && f.agrees == Some(true) && f.unit.starts_with("inconsistent") {
        let _ = writeln!(
            o,
            "  {:>5}  equal in value at this state only: its units are inconsistent",
            ""
        );
    }
    if let Some(err) = &f.error {
        let _ = writeln!(o, "  {:>5}  not evaluated: {err}", "");
    }
    if let Some(enc) = s.encoded_by.get(k).filter(|v| !v.is_empty()) {
        let _ = writeln!(o, "  {:>5}  equals in the code: {}", "", encoded(enc));
    }
}

/// The registry's checks of the display, then its print, units, proof and law rows.
fn checks(o: &mut String, s: &Shown, v: &crate::verify::EquationResult) {
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
fn check_detail(o: &mut String, c: &super::checks::CheckDetail) {
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

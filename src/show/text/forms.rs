//! The forms of a shown display as a table: each printed form's value in every scalar, its
//! residual against the first of its chain, and the code that equals it.

use super::super::Shown;
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

/// Every printed form with its value, unit, residual and agreement, then the verdict here.
pub(super) fn forms_table(o: &mut String, s: &Shown) {
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
fn form_row(o: &mut String, s: &Shown, k: usize, f: &crate::show::values::FormValue) {
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

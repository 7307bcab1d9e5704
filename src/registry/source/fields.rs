//! The `*Field:* value` paragraphs of a display's section and the items of its `*Rust:*` list.
//! Fields are read from the markdown source (not the rendered text), so LaTeX and code spans
//! arrive as written; several fields may share a paragraph, separated by ` · `.

use super::{normalize_latex, CheckSpec, ErratumSpec, LawSpec, PointSpec, SymbolSpec};
use crate::registry::Kind;

/// Which list the next markdown list is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListNext {
    /// Not a list of fields.
    None,
    /// The checks of `*Rust:*`.
    Rust,
    /// The symbols of `*Symbols:*`.
    Symbols,
    /// The premises of `*Premises:*`.
    Premises,
}

/// What a file declares for all its displays: points and symbols, and what was wrong with them.
#[derive(Default)]
pub struct FileDecls {
    pub points: Vec<PointSpec>,
    pub symbols: Vec<SymbolSpec>,
    pub errors: Vec<(usize, String)>,
}

/// What the field paragraphs of one section said, and what was wrong with them (line, reason).
#[derive(Default)]
pub struct Fields {
    pub kind: Option<Kind>,
    /// A `*Kind:*` field was written (even one naming no kind).
    pub kind_written: bool,
    pub functions: Vec<String>,
    pub checks: Vec<CheckSpec>,
    pub law: Option<(LawSpec, usize)>,
    pub erratum: Option<ErratumSpec>,
    /// The line of the erratum's first field.
    pub erratum_line: usize,
    pub states: Option<(String, usize)>,
    pub premises: Vec<super::PremiseSpec>,
    pub errors: Vec<(usize, String)>,
}

/// The fields of a paragraph: (name, value), in order; empty when the paragraph does not begin
/// with a field (prose). A field is `*Name:*` at the start or after a `·`.
pub fn split_fields(raw: &str) -> Vec<(&str, &str)> {
    let marker = |at: usize| -> Option<(&str, usize)> {
        let rest = raw.get(at..)?.strip_prefix('*')?;
        let colon = rest.find(":*")?;
        let name = &rest[..colon];
        let ok = name.len() > 1
            && name.starts_with(|c: char| c.is_ascii_uppercase())
            && name.chars().all(|c| c.is_ascii_alphabetic());
        ok.then_some((name, at + 1 + colon + 2))
    };
    let mut marks: Vec<(&str, usize, usize)> = Vec::new();
    for (i, _) in raw.match_indices('*') {
        let starts = i == 0 || raw[..i].trim_end().ends_with('·');
        if let Some((name, value)) = marker(i).filter(|_| starts) {
            marks.push((name, i, value));
        }
    }
    if marks.first().is_none_or(|m| m.1 != 0) {
        return Vec::new();
    }
    (0..marks.len())
        .map(|k| {
            let end = marks.get(k + 1).map_or(raw.len(), |m| m.1);
            let value = raw[marks[k].2..end].trim().trim_end_matches('·').trim();
            (marks[k].0, value)
        })
        .collect()
}

/// Read a paragraph's fields into `f` (the section's) and `file` (the file's); which list, if
/// any, the paragraph announces.
pub fn read_paragraph(raw: &str, line: usize, f: &mut Fields, file: &mut FileDecls) -> ListNext {
    let mut next = ListNext::None;
    for (name, value) in split_fields(raw) {
        match name {
            "Kind" => read_kind(value, line, f),
            "Code" => f.functions.extend(code_spans(value).map(str::to_string)),
            "Law" => match read_law(value) {
                Ok(law) if f.law.is_none() => f.law = Some((law, line)),
                Ok(_) => f.errors.push((line, "a second *Law:* line".into())),
                Err(e) => f.errors.push((line, e)),
            },
            "Rust" => {
                next = ListNext::Rust;
                if !value.is_empty() {
                    read_check(value, line, f);
                }
            }
            "Premises" => {
                next = ListNext::Premises;
                if !value.is_empty() {
                    read_premise(value, line, f);
                }
            }
            // The name, then (optionally) why in words.
            "States" => {
                let name = value.split_whitespace().next().unwrap_or("");
                f.states = Some((name.trim_end_matches('.').to_string(), line));
            }
            "Misprint" | "Corrected" | "Why" => read_erratum(name, value, line, f),
            "Points" => read_points(value, line, file),
            "Symbols" => {
                next = ListNext::Symbols;
                if !value.is_empty() {
                    read_symbol(value, line, file);
                }
            }
            // Prose fields (`*Checked:*`, `*Figure:*`, ...) are for the reader.
            _ => {}
        }
    }
    next
}

/// One item of `*Premises:*` ([`super::premises`]).
pub(super) fn read_premise(raw: &str, line: usize, f: &mut Fields) {
    match super::premises::read_premise(raw, line) {
        Ok(p) => f.premises.push(p),
        Err(e) => f.errors.push((line, e)),
    }
}

/// `Q = ladder:1/4; R = lab:1/2,3/2`.
pub fn read_points(value: &str, line: usize, file: &mut FileDecls) {
    for item in value.split(';').map(str::trim).filter(|i| !i.is_empty()) {
        let parsed = item.split_once('=').and_then(|(name, point)| {
            let (name, point) = (name.trim(), point.trim());
            let ok = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric());
            ok.then_some((name, point))
        });
        let Some((name, point)) = parsed else {
            file.errors.push((
                line,
                format!("*Points:* '{item}' is not NAME = ladder:FRACTION or NAME = lab:X,Y"),
            ));
            continue;
        };
        match super::point_id(point) {
            Ok(id) => file.points.push(PointSpec {
                name: name.to_string(),
                point: id,
                line,
            }),
            Err(e) => file.errors.push((line, format!("*Points:* {name}: {e}"))),
        }
    }
}

/// One item of a `*Symbols:*` list:
/// `` - $L_Q$ = `relative_angular_momentum:Q.z` [M L^2 T^-1]: angular momentum about Q ``.
pub fn read_symbol(raw: &str, line: usize, file: &mut FileDecls) {
    let shape = "a symbol reads - $LaTeX$ = `quantity` [dimension]: meaning";
    let item = raw.trim_start();
    let item = item
        .strip_prefix(['-', '*', '+'])
        .unwrap_or(item)
        .trim_start();
    let parsed = (|| {
        let (latex, rest) = item.strip_prefix('$')?.split_once('$')?;
        let rest = rest.trim_start().strip_prefix('=')?.trim_start();
        let (quantity, rest) = rest.strip_prefix('`')?.split_once('`')?;
        let (dimension, rest) = rest.trim_start().strip_prefix('[')?.split_once(']')?;
        let meaning = rest.trim_start().strip_prefix(':')?.trim();
        let ok = !latex.trim().is_empty() && !quantity.trim().is_empty();
        ok.then(|| SymbolSpec {
            latex: latex.trim().to_string(),
            quantity: quantity.trim().to_string(),
            dimension: dimension.trim().to_string(),
            meaning: normalize_latex(meaning),
            line,
        })
    })();
    match parsed {
        Some(sym) => file.symbols.push(sym),
        None => file.errors.push((line, shape.into())),
    }
}

fn read_kind(value: &str, line: usize, f: &mut Fields) {
    f.kind_written = true;
    let word = value
        .split_whitespace()
        .next()
        .unwrap_or("")
        .trim_end_matches(['.', ',', '·']);
    match Kind::from_name(word) {
        Some(_) if f.kind.is_some() => f.errors.push((line, "a second *Kind:* line".into())),
        Some(k) => f.kind = Some(k),
        None => f.errors.push((
            line,
            format!(
                "unknown kind '{word}' (one of {})",
                Kind::ALL.map(Kind::name).join(", ")
            ),
        )),
    }
}

/// The code spans of a field: `` [`ladder::torque::torque_about_a`](…), … ``.
fn code_spans(value: &str) -> impl Iterator<Item = &str> {
    value
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|s| !s.is_empty())
}

/// `the 2nd `=` is the law of motion: the law in words. Every other `=` …`.
pub fn read_law(value: &str) -> Result<LawSpec, String> {
    let shape = "the *Law:* line reads \"the 2nd `=` is the law of motion: the law in words\"";
    let rest = value.strip_prefix("the ").ok_or(shape)?;
    let (ordinal, rest) = rest.split_once(' ').ok_or(shape)?;
    let digits: String = ordinal.chars().take_while(char::is_ascii_digit).collect();
    let suffix = &ordinal[digits.len()..];
    let step: u32 = digits.parse().map_err(|_| shape.to_string())?;
    if step == 0 || !["st", "nd", "rd", "th"].contains(&suffix) {
        return Err(shape.into());
    }
    let rest = rest.strip_prefix("`=`").ok_or(shape)?.trim_start();
    let rest = rest.strip_prefix("is the law of motion").unwrap_or(rest);
    let statement = rest.trim_start_matches(':').trim();
    // The sentence the book adds after the law is not part of it.
    let statement = [". Every other `=`", ". This is the only `=`"]
        .iter()
        .filter_map(|tail| statement.find(tail))
        .min()
        .map_or(statement, |k| &statement[..k]);
    Ok(LawSpec {
        step,
        statement: normalize_latex(statement.trim_end_matches('.')),
    })
}

fn read_erratum(name: &str, value: &str, line: usize, f: &mut Fields) {
    if f.erratum.is_none() {
        f.erratum_line = line;
    }
    let e = f.erratum.get_or_insert_with(|| ErratumSpec {
        printed: String::new(),
        corrected: String::new(),
        why: String::new(),
    });
    let math = || -> Result<String, String> {
        let inner = value
            .strip_prefix('$')
            .and_then(|v| v.strip_suffix('$'))
            .filter(|v| !v.trim().is_empty());
        inner
            .map(normalize_latex)
            .ok_or_else(|| format!("*{name}:* takes one LaTeX form between single `$`, as printed"))
    };
    let slot = match name {
        "Misprint" => &mut e.printed,
        "Corrected" => &mut e.corrected,
        _ => &mut e.why,
    };
    let text = if name == "Why" {
        Ok(normalize_latex(value))
    } else {
        math()
    };
    match text {
        Ok(_) if !slot.is_empty() => f.errors.push((line, format!("a second *{name}:*"))),
        Ok(t) => *slot = t,
        Err(err) => f.errors.push((line, err)),
    }
}

/// One item of the `*Rust:*` list: `` - `eq25` (on-shell): what it compares ``.
pub fn read_check(raw: &str, line: usize, f: &mut Fields) {
    let shape = "a check reads - `function` (states): what it compares";
    let item = raw.trim_start();
    let item = item
        .strip_prefix(['-', '*', '+'])
        .unwrap_or(item)
        .trim_start();
    let parsed = (|| {
        let rest = item.strip_prefix('`')?;
        let (function, rest) = rest.split_once('`')?;
        let rest = rest.trim_start().strip_prefix('(')?;
        let (sample, rest) = rest.split_once(')')?;
        let name = rest.trim_start().strip_prefix(':')?.trim();
        let ok = !function.trim().is_empty() && !sample.trim().is_empty() && !name.is_empty();
        ok.then(|| CheckSpec {
            function: function.trim().to_string(),
            sample: sample.trim().to_string(),
            name: normalize_latex(name),
            line,
        })
    })();
    match parsed {
        Some(c) => f.checks.push(c),
        None => f.errors.push((line, shape.into())),
    }
}

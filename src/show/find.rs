//! Which displays a query names: a number (`25`, `(25)`), a list or range (`25,28`, `23-25`), or
//! words, searched in the titles, the symbols each display uses (`L'_P`, as printed or as the
//! Unicode reading) and the symbols' meanings.

use crate::print::ast::Expr;
use crate::print::parser::{canonical, parse_display};
use crate::print::symbols::lookup;
use crate::registry::symbol_table as table;
use crate::registry::{equations, Equation};
use serde::Serialize;

/// What a query names.
#[derive(Debug, PartialEq)]
pub enum Query {
    /// Displays by number.
    Numbers(Vec<u32>),
    /// Words to search for.
    Words(String),
}

/// Read a query; a number that is not a display of the note in use is an error.
pub fn parse_query(q: &str) -> Result<Query, String> {
    let known: Vec<u32> = equations().iter().map(|e| e.number).collect();
    parse_query_in(q, &known)
}

/// The numbers `known`, consecutive runs joined: `1-90, 92`.
fn runs(known: &[u32]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut k = 0;
    while k < known.len() {
        let mut j = k;
        while j + 1 < known.len() && known[j + 1] == known[j] + 1 {
            j += 1;
        }
        out.push(if j == k {
            known[k].to_string()
        } else {
            format!("{}-{}", known[k], known[j])
        });
        k = j + 1;
    }
    out.join(", ")
}

/// [`parse_query`] against the given display numbers (sorted).
pub fn parse_query_in(q: &str, known: &[u32]) -> Result<Query, String> {
    let t = q.trim();
    let numeric = !t.is_empty() && t.chars().all(|c| c.is_ascii_digit() || " (),-".contains(c));
    if !numeric {
        return Ok(Query::Words(t.to_string()));
    }
    let mut out = Vec::new();
    for part in t.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let num = |s: &str| -> Result<u32, String> {
            let s = s.trim().trim_start_matches('(').trim_end_matches(')');
            match s.parse::<u32>() {
                Ok(n) if known.contains(&n) => Ok(n),
                _ => Err(format!(
                    "show: '{s}' is not a display of the note (its displays: {})",
                    runs(known)
                )),
            }
        };
        match part.split_once('-') {
            Some((a, b)) => {
                let (a, b) = (num(a)?, num(b)?);
                if a > b {
                    return Err(format!("show: the range {a}-{b} is empty"));
                }
                out.extend(known.iter().filter(|n| (a..=b).contains(n)));
            }
            None => out.push(num(part)?),
        }
    }
    if out.is_empty() {
        return Err("show: no display named".into());
    }
    Ok(Query::Numbers(out))
}

/// One display found by a word search.
#[derive(Clone, Debug, Serialize)]
pub struct Hit {
    /// Its number.
    pub number: u32,
    /// Its title.
    pub title: &'static str,
    /// Section.
    pub section: &'static str,
    /// Why it matched.
    pub why: String,
}

/// Every symbol key a display uses (in its statements, premises and conditions).
pub fn symbols_of(e: &Equation) -> Vec<(String, bool)> {
    fn walk(x: &Expr, milne: bool, out: &mut Vec<(String, bool)>) {
        use Expr::*;
        match x {
            Sym(k) => {
                if !out.iter().any(|(o, m)| o == k && *m == milne) {
                    out.push((k.clone(), milne));
                }
            }
            Neg(a) | Pow(a, _) | Sin(a) | Cos(a) | Sum(a) | Deriv(a) | ZComp(a) => {
                walk(a, milne, out)
            }
            Partial(a, v) => {
                walk(a, milne, out);
                walk(&Sym(v.clone()), milne, out);
            }
            Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
                walk(a, milne, out);
                walk(b, milne, out);
            }
            Tuple(v) => v.iter().for_each(|y| walk(y, milne, out)),
            At(a, c) => {
                walk(a, milne, out);
                c.iter().for_each(|y| walk(y, milne, out));
            }
            Int(_) | Const => {}
        }
    }
    let mut out = Vec::new();
    if let Ok(d) = parse_display(e.latex()) {
        for st in &d.statements {
            for f in st
                .chain
                .forms
                .iter()
                .chain(st.implies.iter().flat_map(|c| &c.forms))
            {
                walk(f, st.milne, &mut out);
            }
        }
    }
    out
}

/// True when `hay` contains every word of `words` (case-insensitive, whole words; a one-letter
/// word such as `D` must match in case).
fn has_words(hay: &str, words: &[&str]) -> bool {
    let tokens: Vec<&str> = hay
        .split(|c: char| !(c.is_alphanumeric() || c == '\'' || c == '_'))
        .filter(|t| !t.is_empty())
        .collect();
    words.iter().all(|w| {
        tokens.iter().any(|t| {
            if w.chars().count() == 1 {
                t == w
            } else {
                t.eq_ignore_ascii_case(w)
            }
        })
    })
}

/// Search the displays for `text`.
pub fn search(text: &str) -> Vec<Hit> {
    let words: Vec<&str> = text.split_whitespace().collect();
    // The query as a symbol: its canonical LaTeX (`L'_P` → `L'_{P}`) and its Unicode reading.
    let as_key = canonical(text)
        .ok()
        .and_then(|c| crate::print::parser::parse_expr(&c).ok());
    let key = match as_key {
        Some(Expr::Sym(k)) => Some(k),
        _ => None,
    };
    let plain = |s: &str| crate::print::unicode::unicode(s).replace(' ', "");
    let query_plain: String = text.split_whitespace().collect();
    let mut hits = Vec::new();
    for e in equations() {
        let mut why = Vec::new();
        if !words.is_empty() && has_words(e.title, &words) {
            why.push("title".to_string());
        }
        for (k, milne) in symbols_of(&e) {
            let entry = lookup(table(), &k, e.section, e.number, milne);
            let same_key = key.as_deref() == Some(k.as_str());
            let same_reading = !query_plain.is_empty() && plain(&k) == query_plain;
            if same_key || same_reading {
                why.push(format!("uses {}", crate::print::unicode::unicode(&k)));
            } else if let Some(en) = entry {
                if words.len() > 1 && has_words(&en.meaning, &words)
                    || words.len() == 1
                        && words[0].chars().count() > 3
                        && has_words(&en.meaning, &words)
                {
                    why.push(format!(
                        "{} is the {}",
                        crate::print::unicode::unicode(&k),
                        en.meaning
                    ));
                }
            }
        }
        why.dedup();
        if !why.is_empty() {
            hits.push(Hit {
                number: e.number,
                title: e.title,
                section: e.section,
                why: why.join("; "),
            });
        }
    }
    hits
}

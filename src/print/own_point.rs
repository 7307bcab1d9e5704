//! Symbols that must differ (issue 37, item 3): each display prints the symbols of its own
//! point and section, with the exceptions the note itself makes.
//!
//! On the ladder several quantities of different points take the same value at every state
//! (I_A = I_C = I_D = I_E by (13); L_C = L_D, both 4ml²θ̇/3; x_P is x_C in A.1), so a display that
//! writes another point's symbol says something else and no value can see it
//! ([`crate::registry::print_check::twins`] lists such pairs). The rule the note follows is
//! written down once, in `src/print/symbols.toml` (`[[section]]`: the points whose symbols each
//! section's displays print; `[[exception]]`: a display that names another point on purpose, with
//! the reason), and [`Rules::check`] holds every display to it.
//!
//! A symbol's point is its printed subscript ([`point_of`]): one of the note's points A, B, C, D,
//! E, the general P and the centre of mass cm. Other subscripts (a particle's i, a component x or
//! y, F_w, F_f, E₀) name no point. Milne's notation (App. B) is not read: his O and G are mapped to
//! ours by the symbol table, display by display.

use super::ast::Expr;
use serde::Deserialize;

/// The points a printed subscript can name.
pub const NOTE_POINTS: [&str; 7] = ["A", "B", "C", "D", "E", "P", "cm"];

/// The points whose symbols a section's displays print.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionPoints {
    /// Section prefix ("2.4", "A.1", "B"); the longest that matches applies.
    pub section: String,
    /// The section's own point.
    pub point: String,
    /// The points whose symbols its displays may print.
    pub allowed: Vec<String>,
    /// Why, from the note.
    pub why: String,
}

/// Why a display names a point its section does not.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum ExceptionKind {
    /// It compares these points on purpose: it must print a symbol of each.
    Compares,
    /// It defines a general point used later.
    Defines,
    /// A notation slip of the note (equations/ERRATA.md, "Notation slips").
    Slip,
}

/// A display that names another point's symbols on purpose.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointException {
    /// The display.
    pub equation: u32,
    /// What the exception is.
    pub kind: ExceptionKind,
    /// The points it may name besides its section's.
    pub points: Vec<String>,
    /// Only these printed symbols of those points (LaTeX; empty: any); canonical keys once read.
    #[serde(default)]
    pub symbols: Vec<String>,
    /// Why, from the note.
    pub why: String,
}

impl PointException {
    /// Does it allow this symbol (key) of this point?
    fn covers(&self, key: &str, point: &str) -> bool {
        self.points.iter().any(|p| p == point)
            && (self.symbols.is_empty() || self.symbols.iter().any(|s| s == key))
    }
}

/// The rules of `symbols.toml`.
#[derive(Clone, Debug, Default)]
pub struct Rules {
    /// Per section.
    pub sections: Vec<SectionPoints>,
    /// Per display.
    pub exceptions: Vec<PointException>,
}

/// Whether a display may print a symbol of a point.
#[derive(Clone, Copy, Debug)]
pub enum Allowance<'a> {
    /// No rule for the section (a user's own section): not checked.
    Unruled,
    /// Among the section's points.
    Section(&'a SectionPoints),
    /// Named on purpose by this display.
    Exception(&'a PointException),
    /// Another point's symbol, not allowed here.
    Foreign(&'a SectionPoints),
}

/// The point a symbol key names by its printed subscript, if any (`I_A` → A,
/// `\mathbf{x}_{\text{cm}}` → cm, `F_{C,y}` → C, `\mathbf{L}'_P` → P; `\mathbf{x}_i`, `a_x` → none).
pub fn point_of(key: &str) -> Option<&'static str> {
    let at = key.rfind('_')?;
    let rest = &key[at + 1..];
    let sub = match rest.strip_prefix('{') {
        Some(inner) => {
            let mut depth = 1;
            let end = inner.char_indices().find_map(|(i, c)| {
                depth += i32::from(c == '{') - i32::from(c == '}');
                (depth == 0).then_some(i)
            })?;
            &inner[..end]
        }
        None => rest.get(..1)?,
    };
    let sub = sub
        .strip_prefix(r"\text{")
        .and_then(|s| s.strip_suffix('}'))
        .unwrap_or(sub);
    let name = sub.split(',').next()?.trim();
    NOTE_POINTS.iter().copied().find(|p| *p == name)
}

/// Every symbol key of an expression, once each, in print order (conditions of an evaluation bar
/// and the variable of a partial derivative included).
pub fn symbol_keys(e: &Expr, out: &mut Vec<String>) {
    use Expr::*;
    let mut push = |k: &String| {
        if !out.contains(k) {
            out.push(k.clone());
        }
    };
    match e {
        Sym(k) => push(k),
        Partial(a, v) => {
            push(v);
            symbol_keys(a, out);
        }
        Neg(a) | Pow(a, _) | Sin(a) | Cos(a) | Sum(a) | Deriv(a) | ZComp(a) => symbol_keys(a, out),
        Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
            symbol_keys(a, out);
            symbol_keys(b, out);
        }
        Tuple(v) => v.iter().for_each(|x| symbol_keys(x, out)),
        At(a, conds) => {
            symbol_keys(a, out);
            conds.iter().for_each(|c| symbol_keys(c, out));
        }
        Int(_) | Const => {}
    }
}

fn in_section(section: &str, prefix: &str) -> bool {
    section == prefix || section.starts_with(&format!("{prefix}."))
}

impl Rules {
    /// The rule of a section (the longest prefix that matches).
    pub fn section_rule(&self, section: &str) -> Option<&SectionPoints> {
        self.sections
            .iter()
            .filter(|r| in_section(section, &r.section))
            .max_by_key(|r| r.section.len())
    }

    /// May display `number` of `section` print the symbol `key` (a symbol of `point`)?
    pub fn allows(&self, section: &str, number: u32, key: &str, point: &str) -> Allowance<'_> {
        let Some(rule) = self.section_rule(section) else {
            return Allowance::Unruled;
        };
        if rule.allowed.iter().any(|p| p == point) {
            return Allowance::Section(rule);
        }
        match self
            .exceptions
            .iter()
            .find(|x| x.equation == number && x.covers(key, point))
        {
            Some(x) => Allowance::Exception(x),
            None => Allowance::Foreign(rule),
        }
    }

    /// The problems of one display whose printed symbols (our notation) are `keys`: a symbol of a
    /// point its section does not print and no exception allows, and a display that compares
    /// points on purpose but no longer prints one of them. Empty when it follows the rule.
    pub fn check(&self, section: &str, number: u32, keys: &[String]) -> Vec<String> {
        let mut out = Vec::new();
        let points: Vec<&str> = keys.iter().filter_map(|k| point_of(k)).collect();
        for key in keys {
            let Some(point) = point_of(key) else {
                continue;
            };
            if let Allowance::Foreign(rule) = self.allows(section, number, key, point) {
                out.push(format!(
                    "symbols: {} in sec. {section} (point {}) is a quantity of point {point}, which the displays of this section do not name (they print the symbols of {}: {}; src/print/symbols.toml)",
                    super::unicode::unicode(key),
                    rule.point,
                    rule.allowed.join(", "),
                    rule.why
                ));
            }
        }
        for x in self.exceptions.iter().filter(|x| {
            x.equation == number
                && x.kind == ExceptionKind::Compares
                && self.section_rule(section).is_some()
        }) {
            for p in x.points.iter().filter(|p| !points.contains(&p.as_str())) {
                out.push(format!(
                    "symbols: ({number}) compares the points {} on purpose ({}), but prints no symbol of {p}",
                    x.points.join(", "),
                    x.why
                ));
            }
        }
        out
    }
}

/// Parse the `[[section]]` and `[[exception]]` tables of a symbol table's text (its `[[symbol]]`
/// entries are read by `symbols::parse_table`); a point that is not one of [`NOTE_POINTS`] is
/// an error naming it.
pub fn parse_rules(text: &str) -> Result<Rules, String> {
    #[derive(Deserialize)]
    struct File {
        #[serde(default)]
        section: Vec<SectionPoints>,
        #[serde(default)]
        exception: Vec<PointException>,
    }
    let mut f: File = toml::from_str(text).map_err(|e| format!("symbols.toml: {e}"))?;
    for x in &mut f.exception {
        for s in &mut x.symbols {
            *s = match super::parser::parse_expr(s) {
                Ok(Expr::Sym(k)) if point_of(&k).is_some() => k,
                _ => {
                    return Err(format!(
                        "symbols.toml: exception ({}): '{s}' is not a symbol of a point",
                        x.equation
                    ))
                }
            };
        }
    }
    let named = f
        .section
        .iter()
        .flat_map(|s| s.allowed.iter().chain(std::iter::once(&s.point)))
        .chain(f.exception.iter().flat_map(|x| &x.points));
    for p in named {
        if !NOTE_POINTS.contains(&p.as_str()) {
            return Err(format!(
                "symbols.toml: '{p}' is not a point of the note ({})",
                NOTE_POINTS.join(", ")
            ));
        }
    }
    Ok(Rules {
        sections: f.section,
        exceptions: f.exception,
    })
}

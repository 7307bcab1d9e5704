//! The symbol table: `src/print/symbols.toml`, embedded in the binary with `include_str!` and
//! read with serde + toml. Each entry maps a printed symbol to a quantity of the model, per
//! section where the note reuses a symbol with another meaning, and states where the note
//! defines it and its dimension and SI unit (used by the units check).

use super::ast::Expr;
use super::own_point::{parse_rules, PointException, Rules, SectionPoints};
use super::parser::parse_expr;
use serde::Deserialize;
use std::sync::OnceLock;

/// The table's text, as shipped.
pub const SYMBOLS_TOML: &str = include_str!("symbols.toml");

/// One entry of the symbol table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    /// The symbol as printed (LaTeX), e.g. `F_w`, `\mathbf{x}_{\text{cm}}`.
    pub latex: String,
    /// The model quantity it denotes (resolved by [`super::quantity`]).
    pub quantity: String,
    /// Its meaning, in words.
    pub meaning: String,
    /// Where the note defines it (section / equation).
    pub defined: String,
    /// Physical dimension, e.g. `M L^2 T^-1` (`1` for a pure number).
    pub dimension: String,
    /// SI unit, e.g. `kg m^2/s`.
    pub unit: String,
    /// Section prefixes where this meaning holds ("2", "A.4", "B"); empty: everywhere.
    #[serde(default)]
    pub sections: Vec<String>,
    /// Displays where this meaning holds (overrides a section's); empty: no restriction.
    #[serde(default)]
    pub equations: Vec<u32>,
    /// True for Milne's notation (the part of a display after `\text{Milne : }`).
    #[serde(default)]
    pub milne: bool,
    /// The canonical key (filled in when loading).
    #[serde(skip)]
    pub key: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    symbol: Vec<Entry>,
    /// The points each section's displays print (read by [`point_rules`]).
    #[serde(default)]
    #[allow(dead_code)]
    section: Vec<SectionPoints>,
    /// Displays that name another point on purpose (read by [`point_rules`]).
    #[serde(default)]
    #[allow(dead_code)]
    exception: Vec<PointException>,
}

/// Parse a symbol table; an entry whose `latex` is not one symbol is an error naming it.
pub fn parse_table(text: &str) -> Result<Vec<Entry>, String> {
    let file: File = toml::from_str(text).map_err(|e| format!("symbols.toml: {e}"))?;
    let mut out = Vec::new();
    for mut e in file.symbol {
        e.key = match parse_expr(&e.latex) {
            Ok(Expr::Sym(k)) => k,
            Ok(other) => {
                return Err(format!(
                    "symbols.toml: '{}' is not a symbol ({other:?})",
                    e.latex
                ))
            }
            Err(err) => return Err(format!("symbols.toml: '{}': {err}", e.latex)),
        };
        out.push(e);
    }
    Ok(out)
}

/// The shipped table (parsed once).
pub fn table() -> &'static [Entry] {
    static T: OnceLock<Vec<Entry>> = OnceLock::new();
    T.get_or_init(|| parse_table(SYMBOLS_TOML).expect("the shipped symbols.toml parses (tested)"))
}

/// The shipped rules of which points' symbols each section's displays print (parsed once).
pub fn point_rules() -> &'static Rules {
    static R: OnceLock<Rules> = OnceLock::new();
    R.get_or_init(|| parse_rules(SYMBOLS_TOML).expect("the shipped symbols.toml parses (tested)"))
}

/// The entry for a symbol key in a section (Milne's part or ours). The most specific entry wins:
/// Milne's over ours in Milne's part, a section-specific over a general one.
pub fn lookup<'a>(
    table: &'a [Entry],
    key: &str,
    section: &str,
    number: u32,
    milne: bool,
) -> Option<&'a Entry> {
    table
        .iter()
        .filter(|e| e.key == key && (!e.milne || milne))
        .filter(|e| e.sections.is_empty() || e.sections.iter().any(|s| in_section(section, s)))
        .filter(|e| e.equations.is_empty() || e.equations.contains(&number))
        .max_by_key(|e| {
            let longest = e
                .sections
                .iter()
                .filter(|s| in_section(section, s))
                .map(|s| s.len())
                .max();
            (e.milne, !e.equations.is_empty(), longest.unwrap_or(0))
        })
}

fn in_section(section: &str, prefix: &str) -> bool {
    section == prefix || section.starts_with(&format!("{prefix}."))
}

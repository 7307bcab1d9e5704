//! The points and symbols a file of markdown declares, turned into entries of the symbol table
//! beside those of `symbols.toml` ([`crate::print::symbols`]).

use super::{PointSpec, SourceError, SymbolSpec};
use crate::print::ast::Expr;
use crate::print::symbols::Entry;
use crate::scalar::Dimension;

/// Points the note names itself, which a file may not redefine.
const NOTE_POINTS: [&str; 10] = ["A", "B", "C", "D", "E", "O", "P", "cm", "Cfixed", "Gnow"];

/// The id of a point of the ladder (`ladder:1/4`, 0 = C, 1 = D) or of the lab (`lab:1/2,3/2`, in
/// units of l), or why it is neither.
pub fn point_id(text: &str) -> Result<String, String> {
    let t = text.trim();
    match crate::print::point::parse_point(t) {
        Some(_) => Ok(t.to_string()),
        None => Err(format!(
            "'{t}' is not ladder:FRACTION (between 0 = C and 1 = D) or lab:X,Y (in units of l)"
        )),
    }
}

/// A quantity with its point named by a file's points replaced by the point's id:
/// `torque:Q.z` with Q = ladder:1/4 is `torque:ladder:1/4.z`.
pub fn with_points(quantity: &str, points: &[PointSpec]) -> String {
    let (base, comp) = match quantity.rsplit_once('.') {
        Some((b, c)) if matches!(c, "x" | "y" | "z") => (b, Some(c)),
        _ => (quantity, None),
    };
    let Some((name, at)) = base.split_once(':') else {
        return quantity.to_string();
    };
    let at = points
        .iter()
        .find(|p| p.name == at)
        .map_or(at, |p| p.point.as_str());
    match comp {
        Some(c) => format!("{name}:{at}.{c}"),
        None => format!("{name}:{at}"),
    }
}

/// The symbol-table entries of one file, holding in its displays `numbers` only.
pub(super) fn entries(
    file: &str,
    points: &[PointSpec],
    symbols: &[SymbolSpec],
    numbers: &[u32],
    errors: &mut Vec<SourceError>,
) -> Vec<Entry> {
    let err = |line, reason| SourceError {
        file: file.to_string(),
        line,
        reason,
    };
    for p in points
        .iter()
        .filter(|p| NOTE_POINTS.contains(&p.name.as_str()))
    {
        errors.push(err(
            p.line,
            format!("*Points:* {} is a point of the note already", p.name),
        ));
    }
    let mut out = Vec::new();
    for s in symbols {
        let key = match crate::print::parser::parse_expr(&s.latex) {
            Ok(Expr::Sym(k)) => k,
            Ok(_) => {
                errors.push(err(
                    s.line,
                    format!("*Symbols:* ${}$ is not one symbol", s.latex),
                ));
                continue;
            }
            Err(e) => {
                errors.push(err(s.line, format!("*Symbols:* ${}$: {e}", s.latex)));
                continue;
            }
        };
        let dimension = match Dimension::parse(&s.dimension) {
            Ok(d) => d,
            Err(e) => {
                errors.push(err(s.line, format!("*Symbols:* ${}$: {e}", s.latex)));
                continue;
            }
        };
        out.push(Entry {
            latex: s.latex.clone(),
            quantity: with_points(&s.quantity, points),
            meaning: s.meaning.clone(),
            defined: format!("{file}:{}", s.line),
            dimension: s.dimension.clone(),
            unit: dimension.si_unit(),
            sections: Vec::new(),
            equations: numbers.to_vec(),
            milne: false,
            key,
        });
    }
    out
}

//! The `ladder verify` table as a teacher reads it: one row per display, grouped by the book file
//! that explains it, with the full title (wrapped in its column, never cut), the worst float
//! residual beside its pass threshold, what the display does off the motion, what the exact
//! points found, the proof, units, print and the line of the display's section. A definition
//! says on a second line what it was checked against; `--wide` says so for every row, with the
//! law of motion where the display uses one. [`super::legend::legend`] explains every column;
//! the test below holds the two in step.

use super::{EquationResult, OffMotion, Status};
use crate::registry::check::TOLERANCE_FACTOR;
use crate::registry::units::Units;
use crate::registry::Kind;

/// Width of the title column; a longer title wraps onto the next lines at a space.
pub const TITLE_WIDTH: usize = 40;

/// The columns, in order: (header, width, right-aligned).
pub const COLUMNS: [(&str, usize, bool); 12] = [
    ("eq", 5, true),
    ("sec", 5, false),
    ("title", TITLE_WIDTH, false),
    ("kind", 10, false),
    ("status", 10, false),
    ("residual", 11, true),
    ("off motion", 12, false),
    ("exact", 13, false),
    ("proof", 7, false),
    ("units", 12, false),
    ("print", 5, true),
    ("line", 5, true),
];

/// The table with one line per display (more where a title wraps or a definition says what
/// was checked).
pub fn table(results: &[EquationResult]) -> String {
    render(results, false)
}

/// The table; `wide` adds under every row the checks run and the law of motion it uses.
pub fn render(results: &[EquationResult], wide: bool) -> String {
    let mut out = row(&COLUMNS.map(|c| c.0.to_string()));
    let mut file = None;
    for r in results {
        let (f, line) = match r.doc.as_deref().and_then(|d| d.rsplit_once(':')) {
            Some((f, l)) => (Some(f), l),
            None => (None, "—"),
        };
        if f != file {
            out.push_str(&format!("── {}\n", f.unwrap_or("(no page in the book)")));
            file = f;
        }
        let title = wrap(r.title, TITLE_WIDTH);
        let cells = [
            r.label.clone(),
            r.section.to_string(),
            title[0].clone(),
            r.kind.name().to_string(),
            status(r.status).to_string(),
            residual(r.max_residual),
            off_motion(r),
            exact(r),
            proof(r),
            r.units.name().to_string(),
            print(r),
            line.to_string(),
        ];
        out.push_str(&row(&cells));
        let indent = " ".repeat(COLUMNS[0].1 + COLUMNS[1].1 + 2);
        for more in &title[1..] {
            out.push_str(&format!("{indent}{more}\n"));
        }
        if wide || r.kind == Kind::Definition {
            out.push_str(&format!("{indent}checked: {}\n", r.checks.join("; ")));
        }
        if let (true, Some(step), Some(law)) = (wide, r.law_step, r.law) {
            out.push_str(&format!(
                "{indent}law of motion at the {} `=`: {law}\n",
                crate::docs::ordinal(step)
            ));
        }
        for u in &r.print_unparsed {
            out.push_str(&format!("{indent}· print: {u}\n"));
        }
        for p in &r.problems {
            out.push_str(&format!("{indent}! {p}\n"));
        }
        if let (Units::Inconsistent, Some(d)) = (r.units, &r.units_detail) {
            out.push_str(&format!("{indent}units: {d}\n"));
        }
    }
    out
}

/// One line of cells padded to the columns (the last cell unpadded).
fn row(cells: &[String; 12]) -> String {
    let mut s = String::new();
    for (k, (c, (_, w, right))) in cells.iter().zip(COLUMNS).enumerate() {
        let pad = w.saturating_sub(width(c));
        if k > 0 {
            s.push(' ');
        }
        if right {
            s.push_str(&" ".repeat(pad));
            s.push_str(c);
        } else {
            s.push_str(c);
            if k + 1 < cells.len() {
                s.push_str(&" ".repeat(pad));
            }
        }
    }
    s.trim_end().to_string() + "\n"
}

/// Columns a string takes in a terminal: its characters less the combining marks (the dots of
/// θ̇ and θ̈, the hat of ẑ), which draw on the character before them.
pub fn width(s: &str) -> usize {
    s.chars()
        .filter(|c| !matches!(*c as u32, 0x300..=0x36F | 0x20D0..=0x20FF))
        .count()
}

/// Break `text` at spaces into lines of at most `width` characters (a longer word stays whole).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for w in text.split_whitespace() {
        let cur = lines.last_mut().expect("one line");
        if cur.is_empty() {
            cur.push_str(w);
        } else if self::width(cur) + 1 + self::width(w) <= width {
            cur.push(' ');
            cur.push_str(w);
        } else {
            lines.push(w.to_string());
        }
    }
    lines
}

/// The status as the table writes it.
pub fn status(s: Status) -> &'static str {
    match s {
        Status::Verified => "verified",
        Status::Erratum => "erratum",
        Status::Definition => "definition",
        Status::Failed => "FAILED",
    }
}

/// The worst residual beside the pass threshold: `0.255 ≤ 4` (or `7.2e13 > 4`), in error bounds.
pub fn residual(x: f64) -> String {
    let v = if x < 1000.0 {
        format!("{x:.3}")
    } else {
        format!("{x:.1e}")
    };
    let cmp = if x <= TOLERANCE_FACTOR { "≤" } else { ">" };
    format!("{v} {cmp} {TOLERANCE_FACTOR}")
}

/// The off-motion cell: `fails at =2` (the law's `=`), `fails`, `HOLDS`, `any θ̈` or `—`.
pub fn off_motion(r: &EquationResult) -> String {
    match (r.off_motion, r.law_step) {
        (OffMotion::Fails, Some(k)) => format!("fails at ={k}"),
        (OffMotion::Fails, None) => "fails".into(),
        (OffMotion::Holds, _) => "HOLDS".into(),
        (OffMotion::AnyMotion, _) => "any θ̈".into(),
        (OffMotion::NotApplicable, _) => "—".into(),
    }
}

/// The exact cell: `0 at 3 pts` (the residual was exactly zero at every exact point) or
/// `≠0 at 1 of 3`.
pub fn exact(r: &EquationResult) -> String {
    match (r.exact_points, r.exact_failures) {
        (0, _) => "none".into(),
        (n, 0) => format!("0 at {n} pts"),
        (n, f) => format!("≠0 at {f} of {n}"),
    }
}

/// The proof cell: `proved`, `sampled` (no symbolic proof applies) or `NO`.
pub fn proof(r: &EquationResult) -> String {
    if r.proved {
        "proved".into()
    } else if r.proof.starts_with("sampled") {
        "sampled".into()
    } else {
        "NO".into()
    }
}

/// The print cell: printed forms parsed and checked of those in the display, `*` when a Rust
/// form matches none of them, `—` beyond the note.
pub fn print(r: &EquationResult) -> String {
    if r.print_forms == 0 {
        "—".into()
    } else {
        format!(
            "{}/{}{}",
            r.print_parsed,
            r.print_forms,
            if r.print_matches_code { "" } else { "*" }
        )
    }
}

//! The `ladder verify` table as a teacher reads it: one row per display, grouped by the book file
//! that explains it, with the full title (wrapped, never cut), the worst float residual beside
//! its pass threshold, what the display does off the motion, what the exact points found, the
//! proof, units, print and the line of the display's section. A definition says under its row
//! what it was checked against; `--wide` says so for every row, with the law of motion where
//! the display uses one. In a terminal narrower than the one-line layout ([`FULL_WIDTH`]
//! columns; 100 is common) each display takes two lines, its title and then its cells
//! ([`render_for`]), so nothing wraps mid-cell. [`super::legend::legend`] explains every
//! column; `tests/note/verify/table.rs` holds the two in step.

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

/// The cells of the second line of a row in the layout for a narrower terminal (the title
/// takes the first line): (header, width, right-aligned), after [`NARROW_INDENT`].
pub const NARROW_COLUMNS: [(&str, usize, bool); 9] = [
    ("kind", 10, false),
    ("status", 10, false),
    ("residual", 10, true),
    ("off motion", 12, false),
    ("exact", 12, false),
    ("proof", 7, false),
    ("units", 12, false),
    ("print", 5, true),
    ("line", 4, true),
];

/// The indent of a row's cells (and of the lines under it) in the narrow layout.
pub const NARROW_INDENT: usize = 6;

/// Columns the one-line layout takes: every column and a space between each two.
pub const FULL_WIDTH: usize = {
    let mut w = COLUMNS.len() - 1;
    let mut k = 0;
    while k < COLUMNS.len() {
        w += COLUMNS[k].1;
        k += 1;
    }
    w
};

/// Columns the narrow layout's cells take (its titles wrap to the terminal's width).
pub const NARROW_WIDTH: usize = {
    let mut w = NARROW_INDENT + NARROW_COLUMNS.len() - 1;
    let mut k = 0;
    while k < NARROW_COLUMNS.len() {
        w += NARROW_COLUMNS[k].1;
        k += 1;
    }
    w
};

/// The table with one line per display (more where a title wraps or a definition says what
/// was checked).
pub fn table(results: &[EquationResult]) -> String {
    render(results, false)
}

/// The table in the one-line layout ([`FULL_WIDTH`] columns); `wide` adds under every row the
/// checks run and the law of motion it uses.
pub fn render(results: &[EquationResult], wide: bool) -> String {
    render_for(results, wide, FULL_WIDTH)
}

/// The table for a terminal `columns` wide: one line per display when [`FULL_WIDTH`] fits, else
/// each display's number, section and full title on one line and its cells on the next, so
/// that no line is wider than `columns` (down to [`NARROW_WIDTH`]). The lines under a row
/// (what a definition was checked against, the law, problems) are filled to `columns`.
pub fn render_for(results: &[EquationResult], wide: bool, columns: usize) -> String {
    let one_line = columns >= FULL_WIDTH;
    let mut out = if one_line {
        row(&COLUMNS, &COLUMNS.map(|c| c.0.to_string()))
    } else {
        format!("{:>5} {:<5} title\n", "eq", "sec")
            + &" ".repeat(NARROW_INDENT)
            + &row(&NARROW_COLUMNS, &NARROW_COLUMNS.map(|c| c.0.to_string()))
    };
    let indent = " ".repeat(if one_line {
        COLUMNS[0].1 + COLUMNS[1].1 + 2
    } else {
        NARROW_INDENT
    });
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
        let cells = [
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
        if one_line {
            out.push_str(&one_line_row(r, cells, &indent));
        } else {
            out.push_str(&narrow_row(r, &cells, &indent, columns));
        }
        for u in lines_under(r, wide) {
            out.push_str(&super::fill::fill_line(&format!("{indent}{u}"), columns));
            out.push('\n');
        }
    }
    out
}

/// A display in the one-line layout: number, section, the title's first line and the cells,
/// then the rest of the title under the title column.
fn one_line_row(r: &EquationResult, cells: [String; 9], indent: &str) -> String {
    let title = wrap(r.title, TITLE_WIDTH);
    let [c0, c1, c2, c3, c4, c5, c6, c7, c8] = cells;
    let all = [
        r.label.clone(),
        r.section.to_string(),
        title[0].clone(),
        c0,
        c1,
        c2,
        c3,
        c4,
        c5,
        c6,
        c7,
        c8,
    ];
    let mut out = row(&COLUMNS, &all);
    for more in &title[1..] {
        out.push_str(&format!("{indent}{more}\n"));
    }
    out
}

/// A display in the narrow layout: number, section and the full title (wrapped to the
/// terminal), then the cells on a line of their own.
fn narrow_row(r: &EquationResult, cells: &[String; 9], indent: &str, columns: usize) -> String {
    let head = COLUMNS[0].1 + COLUMNS[1].1 + 2;
    let title = wrap(r.title, columns.saturating_sub(head).max(TITLE_WIDTH));
    let mut out = format!("{:>5} {:<5} {}\n", r.label, r.section, title[0]);
    for more in &title[1..] {
        out.push_str(&format!("{}{more}\n", " ".repeat(head)));
    }
    out.push_str(indent);
    out.push_str(&row(&NARROW_COLUMNS, cells));
    out
}

/// The lines under a display's row: what a definition (or, with `wide`, any display) was
/// checked against, the law of motion it uses (`wide`), what of its print did not parse, its
/// problems, and a units clash.
fn lines_under(r: &EquationResult, wide: bool) -> Vec<String> {
    let mut under = Vec::new();
    if wide || r.kind == Kind::Definition {
        under.push(format!("checked: {}", r.checks.join("; ")));
    }
    if let (true, Some(step), Some(law)) = (wide, r.law_step, r.law) {
        under.push(format!(
            "law of motion at the {} `=`: {law}",
            crate::docs::ordinal(step)
        ));
    }
    under.extend(r.print_unparsed.iter().map(|u| format!("· print: {u}")));
    under.extend(r.problems.iter().map(|p| format!("! {p}")));
    if let (Units::Inconsistent, Some(d)) = (r.units, &r.units_detail) {
        under.push(format!("units: {d}"));
    }
    under
}

/// One line of cells padded to the columns (the last cell unpadded).
fn row<const N: usize>(columns: &[(&str, usize, bool); N], cells: &[String; N]) -> String {
    let mut s = String::new();
    for (k, (c, (_, w, right))) in cells.iter().zip(columns).enumerate() {
        let pad = w.saturating_sub(width(c));
        if k > 0 {
            s.push(' ');
        }
        if *right {
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

pub use super::fill::{width, wrap};

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

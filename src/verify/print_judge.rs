//! The print's side of an equation's verdict: whether every printed form parses and holds,
//! whether the Rust forms match the print, and the print's units (split from [`super`] so that
//! the judging of the checks and of the print each have a file).

use super::{judge, EquationResult, Status};
use crate::registry::check::{CheckReport, Config};
use crate::registry::units::Units;
use crate::registry::Equation;

/// Judge an equation and its print: the print's failures become the equation's problems.
pub fn judge_with_print(e: &Equation, reports: &[CheckReport], cfg: &Config) -> EquationResult {
    let r = judge(e, reports);
    if e.number > crate::registry::EXTENSION_BASE {
        return r;
    }
    judge_print(r, e, e.latex(), cfg)
}

/// Add the verdict on a display's print (given as LaTeX) to an equation's result.
pub fn judge_print(
    mut r: EquationResult,
    e: &Equation,
    latex: &str,
    cfg: &Config,
) -> EquationResult {
    let p = crate::registry::print_check::check_print(e, latex, cfg);
    r.print_forms = p.forms;
    r.print_parsed = p.parsed;
    r.print_checked = p.checked;
    r.print_matches_code = p.matches_code;
    r.print_unparsed = p.unparsed.clone();
    // Every display of the note parses today: a form that no longer parses or evaluates is a
    // defect of the print's copy (or of the symbol table), so it fails the display.
    let unparsed = p.unparsed.iter().map(|u| format!("print not parsed: {u}"));
    // A Rust form that equals no printed form disagrees with the print.
    let code = p
        .code_mismatches
        .iter()
        .map(|c| format!("print vs code: {c}"));
    let units = print_units_problems(&mut r, e, latex);
    let problems: Vec<String> = p
        .problems
        .into_iter()
        .chain(unparsed)
        .chain(code)
        .chain(units)
        .collect();
    if !problems.is_empty() {
        r.problems.extend(problems);
        r.status = Status::Failed;
    }
    r
}

/// The print's units verdict becomes the display's `units` (the Rust forms' stays as
/// `units_code`); returns the problems: a form that must hold and is inconsistent, or a verdict
/// that differs from the Rust forms'.
fn print_units_problems(r: &mut EquationResult, e: &Equation, latex: &str) -> Vec<String> {
    let found = match crate::registry::print_check::units::print_units(e, latex) {
        Ok(f) => f,
        // The print check reports a display that does not parse; units have nothing to judge.
        Err(err) => {
            r.units = Units::NotApplicable;
            r.units_detail = Some(format!("print not parsed: {err}"));
            return Vec::new();
        }
    };
    let mut problems: Vec<String> = found
        .problems
        .iter()
        .map(|p| format!("units (print): {p}"))
        .collect();
    (r.units, r.units_detail) = found.verdict();
    if r.units != r.units_code {
        problems.push(format!(
            "units: the print is {}, the Rust forms are {}{}",
            r.units.name(),
            r.units_code.name(),
            r.units_code_detail
                .as_deref()
                .map_or(String::new(), |d| format!(" ({d})"))
        ));
    }
    problems
}

//! `ladder show N`: one display of the note in depth (issue 15).
//!
//! For a display (1)-(90): its print (LaTeX and a Unicode reading), section, title, kind and
//! verdict; what each symbol means, with its unit (`src/print/symbols.toml`); every printed form
//! in order, evaluated at a state the user chooses (`--at`, [`at`], completed on the motion by
//! [`state`]) in f64, exactly when the state is rational, and with its SI unit ([`values`]); the
//! checks `ladder verify` runs on it, with their residuals and verdicts, run for this display
//! alone ([`checks`]); the Rust functions and the book page with file and line ([`source`]); and
//! for an erratum the printed and corrected forms and their difference. A word instead of a
//! number searches titles and symbols ([`find`]). [`answer`] is the one entry point (the command prints it: `cli::show`).
//!
//! Whether a display's forms must agree at the user's state is decided, not assumed
//! ([`expectation`]): an on-shell display needs the state on the motion, one checked only from
//! rest upright needs θ̇ from the energy with θ0 = 0, a general display needs its premise to hold
//! at the ladder's point P. Where they must agree and do not, the show fails (exit 1).

pub mod at;
pub mod checks;
pub mod find;
pub mod phase;
pub mod premises;
pub mod source;
pub mod state;
pub mod text;
pub mod values;

use crate::print::unicode;
use crate::registry::check::Config;
use crate::registry::{equations, Equation, Eval, LadderSample};
use crate::verify::errata::ErratumReport;
use crate::verify::{EquationResult, Status};
use serde::Serialize;

/// One symbol of a display, from the symbol table.
#[derive(Clone, Debug, Serialize)]
pub struct SymbolInfo {
    /// As printed (canonical LaTeX).
    pub latex: String,
    /// Its Unicode reading.
    pub unicode: String,
    /// What it means.
    pub meaning: String,
    /// Its SI unit.
    pub unit: String,
    /// Its dimension.
    pub dimension: String,
    /// Where the note defines it.
    pub defined: String,
    /// In Milne's notation.
    pub milne: bool,
}

/// One display, shown.
#[derive(Clone, Debug, Serialize)]
pub struct Shown {
    /// Its number.
    pub number: u32,
    /// "(25)".
    pub label: String,
    /// Section of the note.
    pub section: &'static str,
    /// Title.
    pub title: &'static str,
    /// Kind (definition, kinematic, newton, on-shell, general, notation).
    pub kind: &'static str,
    /// `ladder verify`'s verdict on it (`None` with `--values-only`, which runs no check).
    pub status: Option<Status>,
    /// The print, LaTeX as in the note.
    pub latex: &'static str,
    /// Its Unicode reading.
    pub unicode: String,
    /// Its symbols.
    pub symbols: Vec<SymbolInfo>,
    /// What it assumes: its `*Premises:*` and the states its print is checked at.
    pub premises: Vec<String>,
    /// Symbols of it that no state of the display tells from another (edits invisible here).
    pub indistinguishable: Vec<String>,
    /// The state the forms are evaluated at.
    pub state: state::Summary,
    /// For a general display: the ladder's point that plays P.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub place: Option<values::Place>,
    /// Whether the printed forms must agree at this state, and if not, why not.
    pub must_agree: bool,
    /// Why they need not agree here (an assumption the state does not meet).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub assumption: Option<String>,
    /// Every printed form, in print order, with its value, unit and agreement.
    pub forms: Vec<values::FormValue>,
    /// For each form (same order): the registry sides that encode it (`check: side`).
    pub encoded_by: Vec<Vec<String>>,
    /// The printed (non-misprint) forms all agree in f64 within the error model.
    pub forms_agree: bool,
    /// … and exactly, when the state is exact.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub forms_agree_exactly: Option<bool>,
    /// Every recorded misprint differs from its chain here, in value or in units (a dropped
    /// factor m is invisible in the numbers at m = 1 kg, never in the units).
    pub misprints_differ: bool,
    /// The registry's checks, in full.
    pub checks: Vec<checks::CheckDetail>,
    /// The display's row of `ladder verify` (its print check, proof, units, law step).
    pub verify: Option<EquationResult>,
    /// The Rust functions that encode it.
    pub code: Vec<source::Location>,
    /// Its page in the book.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub docs: Option<source::Location>,
    /// For an erratum: printed and corrected forms and their difference.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub erratum: Option<ErratumReport>,
    /// What went wrong (a check failed, or forms that must agree here do not).
    pub problems: Vec<String>,
}

/// The symbols of a display with their table entries (a dotted symbol without an entry of its
/// own is the time derivative of the undotted one).
pub fn symbol_infos(e: &Equation) -> Vec<SymbolInfo> {
    use crate::print::symbols::lookup;
    use crate::registry::symbol_table as table;
    use crate::scalar::Dimension;
    let mut out: Vec<SymbolInfo> = Vec::new();
    for (k, milne) in find::symbols_of(e) {
        let (entry, dots) = match lookup(table(), &k, e.section, e.number, milne) {
            Some(en) => (Some(en), 0),
            None => {
                let inner = k
                    .strip_prefix("\\dot{")
                    .map(|r| (r, 1))
                    .or_else(|| k.strip_prefix("\\ddot{").map(|r| (r, 2)));
                match inner {
                    Some((r, d)) => {
                        let base = r.replacen('}', "", 1);
                        (lookup(table(), &base, e.section, e.number, milne), d)
                    }
                    None => (None, 0),
                }
            }
        };
        let info = match entry {
            Some(en) if dots == 0 => SymbolInfo {
                latex: k.clone(),
                unicode: unicode::unicode(&k),
                meaning: en.meaning.clone(),
                unit: en.unit.clone(),
                dimension: en.dimension.clone(),
                defined: en.defined.clone(),
                milne,
            },
            Some(en) => {
                let dim = Dimension::parse(&en.dimension).map(|d| d * Dimension::new(0, 0, -dots));
                SymbolInfo {
                    latex: k.clone(),
                    unicode: unicode::unicode(&k),
                    meaning: format!(
                        "{} time derivative of: {}",
                        if dots == 1 { "first" } else { "second" },
                        en.meaning
                    ),
                    unit: dim.clone().map_or_else(|_| "?".into(), |d| d.si_unit()),
                    dimension: dim.map_or_else(|_| "?".into(), |d| d.to_string()),
                    defined: en.defined.clone(),
                    milne,
                }
            }
            None => SymbolInfo {
                latex: k.clone(),
                unicode: unicode::unicode(&k),
                meaning: "not in the symbol table".into(),
                unit: "?".into(),
                dimension: "?".into(),
                defined: "?".into(),
                milne,
            },
        };
        if !out
            .iter()
            .any(|o| o.latex == info.latex && o.meaning == info.meaning)
        {
            out.push(info);
        }
    }
    out
}

/// Must the display's forms agree at this state? `None` when they must, else the assumption
/// the state does not meet.
pub fn expectation(
    e: &Equation,
    st: &state::Summary,
    place: Option<&values::Place>,
) -> Option<String> {
    if let Some(p) = place.and_then(|p| p.premise_fails.clone()) {
        return Some(p);
    }
    let sorts: Vec<LadderSample> = e
        .checks
        .iter()
        .filter_map(|c| match c.eval {
            Eval::Ladder(s, _) => Some(s),
            _ => None,
        })
        .collect();
    if sorts.iter().all(|&s| s == LadderSample::Kinematic) {
        return None;
    }
    if !st.on_motion {
        return Some("the display holds on the motion (5) only, and θ̈ was given".into());
    }
    if sorts.contains(&LadderSample::OnShellFromRest) && st.theta0 != Some(0.0) {
        return Some("the display is checked on the note's motion, released at rest upright (θ0 = 0, θ̇ from (10)); this state is another motion".into());
    }
    None
}

/// Show display `number` at the state `at` (`None`: the book's worked example).
/// With `run_checks` false only the values are computed (no registry check, proof or print check).
pub fn show(
    number: u32,
    at: Option<&at::At>,
    cfg: &Config,
    run_checks: bool,
) -> Result<Shown, String> {
    let e = equations()
        .into_iter()
        .find(|e| e.number == number)
        .ok_or_else(|| format!("show: ({number}) is not a display of the note"))?;
    let point = state::build(&at.cloned().unwrap_or_else(state::default_at));
    let place = values::place_of(&e);
    let forms = finite_form_values(&e, &point)?;
    let (row, details) = if run_checks {
        let (r, d) = checks::run(&e, cfg);
        (Some(r), d)
    } else {
        (None, Vec::new())
    };
    let assumption = expectation(&e, &point.summary, place.as_ref());
    let agreement = Agreement::of(&forms, point.exact.is_some());
    let mut problems = row.as_ref().map_or_else(Vec::new, |r| r.problems.clone());
    if assumption.is_none() {
        problems.extend(disagreements(&forms));
    }
    let erratum = erratum_of(&e, cfg);
    Ok(Shown {
        number,
        label: e.label(),
        section: e.section,
        title: e.title,
        kind: e.kind.name(),
        status: row.as_ref().map(|r| r.status),
        latex: e.latex(),
        unicode: unicode::unicode(e.latex()),
        symbols: symbol_infos(&e),
        premises: premises::premise_lines(&e),
        indistinguishable: premises::twin_lines(&e),
        state: point.summary.clone(),
        must_agree: assumption.is_none(),
        assumption,
        place,
        encoded_by: checks::encodings(&e),
        forms,
        forms_agree: agreement.forms_agree,
        forms_agree_exactly: agreement.forms_agree_exactly,
        misprints_differ: agreement.misprints_differ,
        checks: details,
        verify: row,
        code: e.functions.iter().map(|f| source::function(f)).collect(),
        docs: source::docs_page(number),
        erratum,
        problems,
    })
}

/// Every printed form of `e` at `point`; a form that overflows a double is the state's fault,
/// not the print's, and is refused as bad input.
fn finite_form_values(
    e: &Equation,
    point: &state::Point,
) -> Result<Vec<values::FormValue>, String> {
    let forms = values::form_values(e, point)?;
    if let Some(f) = forms
        .iter()
        .find(|f| f.error.as_deref() == Some(values::NOT_FINITE))
    {
        return Err(format!(
            "show: at this state form {} of ({}) overflows a double; choose m, l, g nearer 1",
            f.index, e.number
        ));
    }
    Ok(forms)
}

/// A printed form of the display (its continued first form included), not a misprint.
fn is_printed(f: &&values::FormValue) -> bool {
    f.role == "printed" || f.role == "continued"
}

/// Whether the forms agree at the state: the printed ones in f64 and exactly, the misprints
/// differing in value or in units.
struct Agreement {
    forms_agree: bool,
    forms_agree_exactly: Option<bool>,
    misprints_differ: bool,
}

impl Agreement {
    /// The agreement of `forms`; exactly only when the state is exact.
    fn of(forms: &[values::FormValue], exact: bool) -> Self {
        Agreement {
            forms_agree: forms
                .iter()
                .filter(is_printed)
                .all(|f| f.agrees != Some(false) && f.error.is_none()),
            forms_agree_exactly: exact.then(|| {
                forms
                    .iter()
                    .filter(is_printed)
                    .all(|f| f.exact_agrees != Some(false))
            }),
            misprints_differ: forms.iter().filter(|f| f.role == "misprint").all(|f| {
                f.agrees == Some(false)
                    || f.exact_agrees == Some(false)
                    || f.unit.starts_with("inconsistent")
            }),
        }
    }
}

/// A problem for each printed form that disagrees with its chain (when they must agree).
fn disagreements(forms: &[values::FormValue]) -> Vec<String> {
    forms
        .iter()
        .filter(is_printed)
        .filter(|f| f.agrees == Some(false) || f.exact_agrees == Some(false))
        .map(|f| {
            format!(
                "form {} '{}' disagrees with its chain at this state (residual {:.3e} bounds)",
                f.index,
                f.unicode,
                f.residual.unwrap_or(f64::NAN)
            )
        })
        .collect()
}

/// For an erratum, its report from `ladder errata` (printed and corrected forms, difference).
fn erratum_of(e: &Equation, cfg: &Config) -> Option<ErratumReport> {
    e.erratum
        .is_some()
        .then(|| {
            crate::verify::errata::errata(cfg)
                .into_iter()
                .find(|r| r.number == e.number)
        })
        .flatten()
}

/// What `ladder show QUERY` finds: the displays a query names, shown at the state, or the
/// displays whose titles and symbols match its words.
pub enum Answer {
    /// The displays named by number, in the order asked.
    Shown(Vec<Shown>),
    /// Words: the displays they match (never empty).
    Matches { words: String, hits: Vec<find::Hit> },
}

impl Shown {
    /// A display shown failed: a check failed, or forms that must agree did not.
    pub fn failed(&self) -> bool {
        !self.problems.is_empty() || self.status == Some(Status::Failed)
    }
}

/// Answer `ladder show QUERY [--at STATE]`: an error is bad input (one line, for exit 2).
pub fn answer(
    query: &str,
    at_text: Option<&str>,
    values_only: bool,
    cfg: &Config,
) -> Result<Answer, String> {
    let at = at_text.map(at::parse_at).transpose()?;
    match find::parse_query(query)? {
        find::Query::Words(w) => {
            let hits = find::search(&w);
            if hits.is_empty() {
                return Err(format!("show: no display's title or symbols match '{w}'"));
            }
            Ok(Answer::Matches { words: w, hits })
        }
        find::Query::Numbers(numbers) => numbers
            .into_iter()
            .map(|n| show(n, at.as_ref(), cfg, !values_only))
            .collect::<Result<Vec<_>, _>>()
            .map(Answer::Shown),
    }
}

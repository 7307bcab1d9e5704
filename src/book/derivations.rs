//! The six derivations of the equation of motion side by side (`derivations.html`): Lagrange's
//! method (sec. 2.1) and the torque law about A, B, C, D and E (secs. 2.2-2.6). For each point
//! the page says what the analysis needs, where the law of motion enters and what it costs, every
//! entry computed when the book is built:
//!
//! * which forces have a torque about the point, from the force diagram of `report::diagram` at
//!   a state on the motion (a torque counts when it exceeds the rounding of its own terms);
//! * whether the point accelerates (a coordinate force −m a_P, by automatic differentiation);
//! * the angular momentum L′_P as a multiple of m l² θ̇, in exact rational arithmetic at two
//!   states (the same multiple at both, or "depends on θ");
//! * the display where the law enters and its `=`, from the checks run off the motion
//!   (`EquationResult::law_step`), and the size of that display: printed forms, and the terms of
//!   its longest form as the print parser reads them.

use super::pages::esc;
use super::reader::term;
use crate::ladder::analysis::{angular_momentum_about, AngularMomentum, Reference};
use crate::ladder::geometry::Corner;
use crate::ladder::{Ladder, State};
use crate::print::ast::Expr;
use crate::scalar::{Rational, Scalar};
use crate::verify::EquationResult;
use std::collections::BTreeMap;

/// The sections of the six derivations, in the note's order, with their reference point.
pub const DERIVATIONS: [(&str, Option<Corner>); 6] = [
    ("2.1", None),
    ("2.2", Some(Corner::A)),
    ("2.3", Some(Corner::B)),
    ("2.4", Some(Corner::C)),
    ("2.5", Some(Corner::D)),
    ("2.6", Some(Corner::E)),
];

/// What one torque analysis needs, from the model at a state on the motion.
#[derive(Clone, Debug, PartialEq)]
pub struct Needs {
    /// The forces with a torque about the point ("F_w", "F_f", "m g", "F_C", ...).
    pub torques: Vec<String>,
    /// True when the point accelerates (so a coordinate force −m a_P enters).
    pub accelerates: bool,
    /// L′_P / (m l² θ̇), exact, when it is the same at two states.
    pub l_coefficient: Option<Rational>,
}

/// The state the needs are read at: θ = 0.6 rad on the motion from rest upright (θ̇² of (10),
/// θ̈ of (5)), m = l = 1, g = 9.81.
fn sample() -> (Ladder<f64>, State<f64>) {
    let (l, g, th) = (1.0f64, 9.81f64, 0.6f64);
    let w2 = 0.75 * g / l;
    let st = State {
        sin: th.sin(),
        cos: th.cos(),
        rate: (2.0 * w2 * (1.0 - th.cos())).sqrt(),
        accel: w2 * th.sin(),
        jerk: w2 * th.cos() * (2.0 * w2 * (1.0 - th.cos())).sqrt(),
    };
    (Ladder { m: 1.0, l, g }, st)
}

/// L′_P / (m l² θ̇) about `k` at the rational state with (sin θ, cos θ) = (s, c), m = l = θ̇ = 1.
fn l_ratio(k: Corner, s: (i64, i64), c: (i64, i64)) -> Rational {
    let r = |n: i64, d: i64| Rational::ratio(n, d);
    let ladder = Ladder {
        m: r(1, 1),
        l: r(1, 1),
        g: r(3, 1),
    };
    let st = State {
        sin: r(s.0, s.1),
        cos: r(c.0, c.1),
        rate: r(1, 1),
        accel: r(0, 1),
        jerk: r(0, 1),
    };
    angular_momentum_about(
        &Reference::Corner(k),
        AngularMomentum::Relative,
        &ladder,
        &st,
    )
}

/// What the analysis about `k` needs.
pub fn needs(k: Corner) -> Needs {
    let (ladder, st) = sample();
    let d = crate::report::diagram::diagram(k.name(), &Reference::Corner(k), &ladder, &st);
    // A torque is zero when it is below the rounding of its terms: each is a product of a
    // position (≤ 2l) and a force (≤ the largest force), rounded a few times (8 u covers it).
    let biggest = d
        .arrows
        .iter()
        .map(|a| a.force.0.hypot(a.force.1))
        .fold(0.0, f64::max);
    let zero = 8.0 * f64::EPSILON * 2.0 * ladder.l * biggest;
    let torques = d
        .arrows
        .iter()
        .filter(|a| a.torque.abs() > zero)
        .map(|a| a.symbol.clone())
        .collect();
    let accelerates = d
        .arrows
        .iter()
        .any(|a| a.symbol == format!("F_{}", k.name()));
    let (a, b) = (l_ratio(k, (3, 5), (4, 5)), l_ratio(k, (5, 13), (12, 13)));
    Needs {
        torques,
        accelerates,
        l_coefficient: (a == b).then_some(a),
    }
}

/// The number of additive terms of a form (a − b + c has three).
pub fn terms(e: &Expr) -> usize {
    match e {
        Expr::Add(a, b) | Expr::Sub(a, b) => terms(a) + terms(b),
        Expr::Neg(a) => terms(a),
        _ => 1,
    }
}

/// (printed forms, terms of the longest form) of a display's LaTeX, as the print parser reads it.
pub fn size(latex: &str) -> Option<(usize, usize)> {
    let d = crate::print::parser::parse_display(latex).ok()?;
    let longest = d
        .statements
        .iter()
        .flat_map(|s| s.chain.forms.iter())
        .map(terms)
        .max()?;
    Some((d.form_count(), longest))
}

fn fraction(q: &Rational) -> String {
    if q.denom() == &1.into() {
        format!("{}", q.numer())
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

fn cell_needs(k: Option<Corner>) -> (String, String, String) {
    let Some(k) = k else {
        return (
            "none: energies T (2) and V (3) only".into(),
            "none".into(),
            "not needed: T = (2/3) m l² θ̇² (2)".into(),
        );
    };
    let n = needs(k);
    let contact: Vec<&str> = n
        .torques
        .iter()
        .filter(|s| *s == "F_w" || *s == "F_f")
        .map(String::as_str)
        .collect();
    let forces = if n.torques.is_empty() {
        "none".to_string()
    } else {
        n.torques.join(", ")
    };
    let newton = if contact.is_empty() {
        "no contact force has a torque: no Newton law needed".to_string()
    } else {
        format!(
            "{} from Newton's law for the centre of mass",
            contact.join(" and ")
        )
    };
    let own = format!("F_{}", k.name());
    let coord = match (n.accelerates, n.torques.contains(&own)) {
        (true, true) => term("coordinate-force", "−m a_P, with a torque"),
        (true, false) => format!(
            "{}, but no torque: it acts at the point itself",
            term("coordinate-force", "−m a_P")
        ),
        (false, _) => "none: the point is at rest".into(),
    };
    let l = match &n.l_coefficient {
        Some(q) => format!("L′ = {} m l² θ̇", fraction(q).replace('-', "−")),
        None => "L′ depends on θ".into(),
    };
    (
        format!("{forces}<br /><small>{newton}</small>"),
        coord,
        esc(&l),
    )
}

/// The link to result `r`'s display on its page.
fn display_link(r: &EquationResult, home: &BTreeMap<u32, String>) -> String {
    let a = super::panel::anchor(&r.label);
    let p = home.get(&r.number).cloned().unwrap_or_default();
    format!("<a href=\"{p}#{a}\">{}</a>", esc(&r.label))
}

/// Where the law of motion enters: the first display of the section with a law step, and
/// that step's `=`.
fn law_cell(with_law: &[&&EquationResult], home: &BTreeMap<u32, String>) -> String {
    match with_law.first() {
        Some(r) => format!(
            "{}, at <code>=</code> no. {}: {}",
            display_link(r, home),
            r.law_step.unwrap_or(0),
            esc(r.law.unwrap_or(""))
        ),
        None => "not found".into(),
    }
}

/// The working: the display with the law whose longest form has the most terms.
fn working_cell(with_law: &[&&EquationResult], home: &BTreeMap<u32, String>) -> String {
    with_law
        .iter()
        .filter_map(|r| Some((r, size(crate::registry::printed_latex(r.number))?)))
        .max_by_key(|(_, (_, t))| *t)
        .map(|(r, (f, t))| {
            let s = if t == 1 { "" } else { "s" };
            format!(
                "{}: {f} printed forms, {t} term{s} in the longest",
                display_link(r, home)
            )
        })
        .unwrap_or_else(|| "not parsed".into())
}

/// The section: how many displays it has and how many passed their checks.
fn section_cell(in_sec: &[&EquationResult]) -> String {
    let checked = in_sec
        .iter()
        .filter(|r| r.status != crate::verify::Status::Failed)
        .count();
    if checked == in_sec.len() {
        format!(
            "{} displays, all {}",
            in_sec.len(),
            term("checked", "checked")
        )
    } else {
        format!(
            "{} displays, {checked} {}",
            in_sec.len(),
            term("checked", "checked")
        )
    }
}

/// One derivation's column, for section `sec` about `k` (Lagrange when `None`): its heading
/// cell and its six cells, top to bottom.
fn column(
    sec: &str,
    k: Option<Corner>,
    results: &[EquationResult],
    home: &BTreeMap<u32, String>,
) -> (String, [String; 6]) {
    let name = match k {
        Some(k) => format!("about {}", k.name()),
        None => "Lagrange".into(),
    };
    let in_sec: Vec<&EquationResult> = results.iter().filter(|r| r.section == sec).collect();
    let page = in_sec.first().and_then(|r| home.get(&r.number));
    let link = |txt: &str| match page {
        Some(p) => format!("<a href=\"{p}\">{txt}</a>"),
        None => txt.to_string(),
    };
    let heading = format!("<th>{}</th>", link(&format!("{sec} {name}")));
    let (forces, coord, l) = cell_needs(k);
    let with_law: Vec<&&EquationResult> = in_sec.iter().filter(|r| r.law_step.is_some()).collect();
    let cells = [
        forces,
        coord,
        l,
        law_cell(&with_law, home),
        working_cell(&with_law, home),
        section_cell(&in_sec),
    ];
    (heading, cells)
}

/// The page: one column per derivation.
pub fn page(results: &[EquationResult], home: &BTreeMap<u32, String>) -> String {
    let mut head = String::from("<tr><th></th>");
    let mut rows: [String; 6] = Default::default();
    let labels = [
        "forces with a torque",
        "coordinate force",
        "angular momentum",
        "where the law enters",
        "the working",
        "the section",
    ];
    for (sec, k) in DERIVATIONS {
        let (heading, cells) = column(sec, k, results, home);
        head.push_str(&heading);
        for (row, c) in rows.iter_mut().zip(cells) {
            row.push_str(&format!("<td>{c}</td>"));
        }
    }
    head.push_str("</tr>\n");
    let body: String = labels
        .iter()
        .zip(&rows)
        .map(|(l, r)| format!("<tr><th>{l}</th>{r}</tr>\n"))
        .collect();
    format!(
        "<h1>Six derivations side by side</h1>\n\
<p>The note derives one equation of motion, θ̈ = (3g/4l) sin θ (5), six times. Lagrange's method \
never meets a contact force; each torque analysis meets the forces whose line of action misses its \
point, and about a point that accelerates it meets the {cf} −m a_P as well. The rows below are \
computed from the model when the book is built (at θ = 0.6 rad on the motion from rest), and the \
law's place from the checks: each display is evaluated {off}, and the chain breaks at the one \
<code>=</code> that is the {law}. The cost is the size of that display: how many forms it prints \
and how many terms must cancel in its longest form.</p>\n\
<table class=\"derivations\"><thead>{head}</thead><tbody>\n{body}</tbody></table>\n\
<p>Every column gives the same equation (the checks of each are on the <a href=\"methods.html\">\
methods page</a>); sec. 2.7 of the note, <a href=\"07-comments.html\">Comments</a>, says why every \
point must.</p>\n",
        cf = term("coordinate-force", "coordinate force"),
        off = term("off-motion", "off the motion"),
        law = term("law", "law of motion"),
    )
}

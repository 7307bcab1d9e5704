//! Dimensional analysis of the print itself (issue 14, item 2): every parsed printed form of
//! every display evaluated in dimensions, as `ladder verify` reports it (`units`), held against
//! the Rust forms' verdict (`units_code`); a dimensional slip planted in the printed LaTeX is
//! reported naming the printed form.

use sliding_ladder::print::quantity::{resolve, Model};
use sliding_ladder::print::symbols::{table, Entry};
use sliding_ladder::print::unicode::unicode;
use sliding_ladder::registry::check::Config;
use sliding_ladder::registry::print_check::units::print_units;
use sliding_ladder::registry::print_check::{injections, print_chains, Typo};
use sliding_ladder::registry::sample::{LadderSample, ParticleSample};
use sliding_ladder::registry::units::{
    dimensioned_ladder, dimensioned_particles, equation_units, Units,
};
use sliding_ladder::registry::{equations, Equation};
use sliding_ladder::scalar::{Dim, Dimension};
use sliding_ladder::verify::{judge, judge_print, Status};

fn quick() -> Config {
    Config {
        float_cases: 5,
        exact_points: 1,
        seed: 3,
    }
}

fn display(n: u32) -> Equation {
    equations().into_iter().find(|e| e.number == n).unwrap()
}

/// (12) L_A = −ml²θ̇ + ml²θ̇/3 with the m of its second term dropped: the second printed form
/// adds M L² T⁻¹ (m l² θ̇) to L² T⁻¹ (l² θ̇), so `ladder verify` reports it inconsistent in
/// form 2 and fails the display; the print as printed is consistent and agrees with the code.
#[test]
fn a_mass_dropped_from_the_printed_latex_is_reported_in_its_form() {
    let e = display(12);
    let asis = judge_print(judge(&e, &[]), &e, e.latex(), &quick());
    assert_eq!(asis.units, Units::Consistent, "{:?}", asis.units_detail);
    assert_eq!(asis.units_code, Units::Consistent);
    assert!(!asis.problems.iter().any(|p| p.starts_with("units")));

    let good = r"\frac{ml^2 \dot{\theta}}{3}";
    assert_eq!(e.latex().matches(good).count(), 1);
    let slip = e.latex().replace(good, r"\frac{l^2 \dot{\theta}}{3}");
    let r = judge_print(judge(&e, &[]), &e, &slip, &quick());
    assert_eq!(r.units, Units::Inconsistent);
    let detail = r.units_detail.clone().unwrap();
    assert!(detail.starts_with("inconsistent: "), "{detail}");
    assert!(detail.contains("M L² T⁻¹ + L² T⁻¹"), "{detail}");
    assert!(detail.ends_with(" in form 2"), "{detail}");
    // The offending sum is quoted as the reader sees it: both terms, the dropped m missing.
    assert!(
        detail.contains("ml²θ̇") && detail.contains("l²θ̇/3"),
        "{detail}"
    );
    assert_eq!(r.status, Status::Failed);
    assert!(r
        .problems
        .iter()
        .any(|p| p.starts_with("units (print): ") && p.ends_with(" in form 2")));
    // The Rust forms are untouched, so the two verdicts disagree, and that is said too.
    assert_eq!(r.units_code, Units::Consistent);
    assert!(r
        .problems
        .iter()
        .any(|p| p == "units: the print is inconsistent, the Rust forms are consistent"));
}

/// The printed form a one-token edit changed, counted from 1 over every chain.
fn edited_form(e: &Equation, latex: &str) -> Option<usize> {
    let (_, a) = print_chains(e.number, e.latex()).ok()?;
    let (_, b) = print_chains(e.number, latex).ok()?;
    let (a, b): (Vec<_>, Vec<_>) = (a.concat(), b.concat());
    (a.len() == b.len()).then_some(())?;
    a.iter()
        .zip(&b)
        .position(|(x, y)| x.text != y.text)
        .map(|k| k + 1)
}

/// Every factor m, l or g dropped from any printed form of any display (the injection sweep's
/// `DropFactor` typos) changes that form's dimension, so units alone report it and name the form
/// (an unlike sum or vector in it, or its dimension against its chain's). None escapes: every
/// printed form stands in a chain with another form of known dimension.
#[test]
fn every_dropped_factor_in_the_print_is_caught_by_units_naming_its_form() {
    let (mut caught, mut unparsed) = (0, 0);
    for e in equations() {
        for inj in injections(e.number, e.latex()) {
            if inj.typo != Typo::DropFactor {
                continue;
            }
            let Some(k) = edited_form(&e, &inj.latex) else {
                unparsed += 1; // the edit broke the parse: the print check reports that
                continue;
            };
            let found = print_units(&e, &inj.latex).unwrap();
            let mut said: Vec<String> = found.problems.clone();
            said.extend(found.misprints.iter().filter_map(|m| m.1.clone()));
            let names = |s: &String| {
                s.ends_with(&format!("in form {k}")) || s.contains(&format!("form {k} ("))
            };
            assert!(
                said.iter().any(names),
                "({}) form {k} lost a factor unseen by units: {}\n{said:?}",
                e.number,
                inj.latex
            );
            caught += 1;
        }
    }
    eprintln!("dropped factors: all {caught} caught by units, naming their form ({unparsed} no longer parse)");
    assert!(unparsed * 10 < caught, "{unparsed} edits do not parse");
    // The sweep is not empty: the note's print has hundreds of factors m, l, g in products.
    assert!(caught > 100, "only {caught} dropped factors");
}

/// Every display of the note: the print's verdict and the Rust forms' agree; only errata are
/// inconsistent, exactly those whose printed form drops or misplaces a dimensional factor, and
/// their misprinted form is named; every other verdict that is not `consistent` has a reason.
#[test]
fn the_print_and_the_code_agree_and_only_three_errata_are_inconsistent() {
    let mut caught = Vec::new();
    for e in equations() {
        let found = print_units(&e, e.latex()).unwrap();
        assert!(
            found.problems.is_empty(),
            "({}) {:?}",
            e.number,
            found.problems
        );
        let (print, detail) = found.verdict();
        let (code, code_detail) = equation_units(&e).verdict();
        assert_eq!(print, code, "({}) {detail:?} / {code_detail:?}", e.number);
        match print {
            Units::Inconsistent => {
                assert!(e.erratum.is_some(), "({}) {detail:?}", e.number);
                // The misprinted form is the one named.
                let mis = found
                    .misprints
                    .iter()
                    .find_map(|m| m.1.as_ref().map(|_| m.0));
                assert!(detail.unwrap().contains(mis.unwrap()), "({})", e.number);
                caught.push(e.number);
            }
            Units::NotApplicable => assert!(detail.is_some(), "({}) needs a reason", e.number),
            Units::Consistent | Units::Dimensionless => {}
        }
    }
    // By hand: (49) adds m l² θ̇/3 to l² θ̇ (…) (a mass dropped from a term), (62) subtracts
    // m l sin²θ θ̈ (M L T⁻²) from m l g sin θ (M L² T⁻²) (a length dropped), (68) writes Milne's
    // torque without his masses (L² T⁻² for M L² T⁻²). (28) and (54) are wrong in value only.
    assert_eq!(caught, vec![49, 62, 68]);
}

/// A form that is a pure number compared with one that is not is caught too: (1)'s I_cm set
/// equal to m l/3 (a length dropped) has M L against M L².
#[test]
fn a_form_of_another_dimension_than_its_chain_is_named_with_both() {
    let e = display(1);
    let slip = e.latex().replace("ml^2", "ml");
    let found = print_units(&e, &slip).unwrap();
    assert_eq!(found.verdict().0, Units::Inconsistent);
    assert_eq!(found.problems.len(), 1, "{:?}", found.problems);
    let p = &found.problems[0];
    assert!(
        p.starts_with("form 2 (ml/3) has dimension M L, form 1 (I_cm) has M L²"),
        "{p}"
    );
}

/// A vector written by components hides a clash from its value: in (60) the z component of
/// (0, 2l cos θ, 0) × (m a_x, a_y, 0) never multiplies a_y by anything but 0. The tuple itself is
/// checked, so a dropped m there is reported.
#[test]
fn a_vector_of_unlike_components_is_inconsistent() {
    let e = display(60);
    let good = "(m a_x, m a_y, 0)";
    assert_eq!(e.latex().matches(good).count(), 1, "{}", e.latex());
    let found = print_units(&e, &e.latex().replace(good, "(m a_x, a_y, 0)")).unwrap();
    let p = found.problems.first().expect("reported");
    assert!(
        p.starts_with("inconsistent: components M L T⁻² and L T⁻² in the vector (ma_x, a_y, 0)"),
        "{p}"
    );
    assert!(p.ends_with(" in form 1"), "{p}");
    assert!(print_units(&e, e.latex()).unwrap().problems.is_empty());
}

/// No LaTeX command survives the Unicode reading of any display (the reading names the forms
/// in the units verdict and in `ladder show`).
#[test]
fn every_display_reads_in_unicode() {
    for e in sliding_ladder::registry::equations() {
        let (n, u) = (e.number, unicode(e.latex()));
        assert!(!u.contains('\\') && !u.contains('{'), "({n}): {u}");
    }
}

/// The dimension of a symbol table entry's quantity, from the models: the ladder first, else a
/// system of particles (at particle 0 when the quantity is per particle). `Some(None)` when it
/// is an exact zero there (of any dimension), `None` when it resolves nowhere.
fn quantity_dimension(entry: &Entry) -> Option<Option<Dimension>> {
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    let (sys, p) = dimensioned_particles(ParticleSample::General, 3);
    let models = [Model::ladder(l, s), Model::particles(sys, p)];
    let mut zero = false;
    for m in &models {
        for i in [None, Some(0)] {
            let Ok(v) = resolve(&entry.quantity, i, m) else {
                continue;
            };
            let c = v.components();
            assert!(
                c.iter().all(|d| d.inconsistency().is_none()),
                "{}",
                entry.latex
            );
            match c.iter().find_map(Dim::dimension) {
                Some(d) => return Some(Some(d)),
                None => zero = true,
            }
        }
    }
    zero.then_some(None)
}

/// The symbol table (`src/print/symbols.toml`, which `ladder show` prints and the print's
/// check reads): every entry's stated dimension is the dimension of the model quantity it
/// denotes, and its SI unit spells that dimension. A wrong dimension or unit is caught. Two
/// sorts cannot be compared, and are counted: θ, which the model never holds (it carries sin θ
/// and cos θ; the angle is a pure number, `1`), and quantities that are an exact zero in the
/// models (a contact force component the ladder's point does not feel, a moved origin at rest
/// at the old one), which have any dimension.
#[test]
fn every_symbol_of_the_table_has_the_dimension_and_unit_it_states() {
    let (mut compared, mut zeros) = (0, Vec::new());
    for entry in table() {
        let stated =
            Dimension::parse(&entry.dimension).unwrap_or_else(|e| panic!("{}: {e}", entry.latex));
        assert_eq!(
            Dimension::from_si(&entry.unit),
            Ok(stated),
            "{}: the unit {} is not {}",
            entry.latex,
            entry.unit,
            entry.dimension
        );
        match quantity_dimension(entry) {
            Some(Some(found)) => {
                assert_eq!(
                    found, stated,
                    "{} ({}): the model gives {found}",
                    entry.latex, entry.quantity
                );
                compared += 1;
            }
            Some(None) => zeros.push(entry.quantity.clone()),
            None => {
                assert_eq!(
                    entry.quantity, "theta",
                    "{} resolves in no model",
                    entry.latex
                );
                assert!(stated.is_dimensionless());
            }
        }
    }
    eprintln!(
        "symbol table: {compared} of {} entries compared, exact zeros {zeros:?}",
        table().len()
    );
    assert!(
        zeros.len() <= 4 && compared + zeros.len() + 1 == table().len(),
        "{zeros:?}"
    );
    // Failable: an entry claiming the wall force is a momentum is caught.
    let mut wrong = table()
        .iter()
        .find(|e| e.quantity == "wall_force")
        .expect("F_w in the table")
        .clone();
    assert_eq!(
        quantity_dimension(&wrong),
        Some(Some(Dimension::new(1, 1, -2)))
    );
    wrong.dimension = "M L T^-1".into();
    assert_ne!(
        quantity_dimension(&wrong).flatten(),
        Dimension::parse(&wrong.dimension).ok()
    );
}

/// The reason a form is inconsistent names its own clash: a vector with unlike components is
/// named by its components only when that is the clash; in (m, l)·1/0 the clash is the division
/// by an exact zero, and that is what is said (registry 5/40's survivor named the components).
#[test]
fn print_units_names_the_clash_of_the_form_not_another_defect_in_it() {
    let e = display(12);
    let problems = |latex: &str| print_units(&e, latex).expect("parses").problems;
    assert_eq!(
        problems(r"L_A = (m, l)"),
        ["inconsistent: components M and L in the vector (m, l) in form 2"]
    );
    assert_eq!(
        problems(r"L_A = (m, l) \frac{1}{0}"),
        ["inconsistent: division by an exact zero in form 2"]
    );
}

//! `ladder errata` prints the exact point of each residual and names the misprinted form of the
//! display (issue 16, item 4). The point printed must be the point used: rebuilt from the
//! printed text alone, the printed and corrected forms, evaluated on it by the print evaluator
//! (an independent path from the registry's Rust forms), differ by exactly the printed residual.
//! The form named must be the one that holds the misprint in the display as printed.

use num_traits::Zero;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::print::eval::{evaluate, Ctx};
use sliding_ladder::print::parser::parse_expr;
use sliding_ladder::print::quantity::{Model, Value};
use sliding_ladder::registry::equations;
use sliding_ladder::scalar::Rational;
use sliding_ladder::verify::errata::{errata, misprinted_form, ErratumReport};
use std::rc::Rc;

fn q(s: &str) -> Rational {
    s.parse().unwrap_or_else(|_| panic!("not a rational: {s}"))
}

fn coordinate(r: &ErratumReport, name: &str) -> Rational {
    let v = r.point.iter().find(|(n, _)| n == name).expect(name);
    q(&v.1)
}

/// Split a LaTeX chain at the `=` outside braces.
fn forms(latex: &str) -> Vec<String> {
    let (mut depth, mut cur, mut out) = (0i32, String::new(), Vec::new());
    for c in latex.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            '=' if depth == 0 => {
                out.push(std::mem::take(&mut cur));
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    out.push(cur);
    out
}

fn squash(s: &str) -> String {
    s.chars()
        .filter(|c| !c.is_whitespace() && *c != '&')
        .collect::<String>()
        .replace("\\\\", "")
}

/// An erratum display and its misprinted slot: the printed form there and the corrected one.
fn misprinted_slot(number: u32) -> (sliding_ladder::registry::Equation, String, String) {
    let e = equations()
        .into_iter()
        .find(|e| e.number == number)
        .unwrap();
    let err = e.erratum.unwrap();
    let (p, c) = (forms(err.printed), forms(err.corrected));
    let k = (0..p.len())
        .find(|&k| squash(&p[k]) != squash(&c[k]))
        .unwrap();
    (e, p[k].clone(), c[k].clone())
}

/// printed − corrected of the misprinted slot, evaluated by the print evaluator at a ladder point.
fn slot_difference(number: u32, l: Ladder<Rational>, s: State<Rational>) -> Rational {
    let (e, p, c) = misprinted_slot(number);
    let ctx = Ctx {
        model: Rc::new(Model::ladder(l, s)),
        section: e.section,
        number,
        milne: false,
        index: None,
        table: sliding_ladder::print::symbols::table(),
    };
    let value = |t: &str| match evaluate(&parse_expr(t).unwrap(), &ctx).unwrap() {
        Value::Scalar(x) => x,
        Value::Vector(v) => v.z,
    };
    value(&p) - value(&c)
}

fn ladder_point(r: &ErratumReport) -> (Ladder<Rational>, State<Rational>) {
    let c = |n| coordinate(r, n);
    (
        Ladder {
            m: c("m"),
            l: c("l"),
            g: c("g"),
        },
        State {
            sin: c("sin θ"),
            cos: c("cos θ"),
            rate: c("θ̇"),
            accel: c("θ̈"),
            jerk: c("θ⃛"),
        },
    )
}

#[test]
fn the_printed_point_reproduces_the_printed_residual() {
    let mut ladder_errata = 0;
    for r in errata(&Default::default()) {
        if !r.point.iter().any(|(n, _)| n == "sin θ") {
            assert!(
                r.point.iter().any(|(n, _)| n == "m_1"),
                "({}) no point",
                r.number
            );
            continue;
        }
        ladder_errata += 1;
        let (l, s) = ladder_point(&r);
        assert_eq!(
            s.sin.clone() * s.sin.clone() + s.cos.clone() * s.cos.clone(),
            q("1")
        );
        assert!(r.corrected_residual == "0", "({})", r.number);
        let want = q(&r.printed_residual_exact);
        assert!(
            !want.is_zero(),
            "({}) a misprint with zero residual",
            r.number
        );
        assert_eq!(
            slot_difference(r.number, l.clone(), s.clone()),
            want,
            "({}): the printed point does not give the printed residual",
            r.number
        );
        // Another point gives another residual: the check can tell the point.
        let mut moved = s.clone();
        moved.rate += q("1");
        assert_ne!(slot_difference(r.number, l, moved), want, "({})", r.number);
    }
    assert_eq!(ladder_errata, 4);
}

#[test]
fn on_shell_errata_are_evaluated_on_the_motion() {
    for r in errata(&Default::default()) {
        let e = equations()
            .into_iter()
            .find(|e| e.number == r.number)
            .unwrap();
        if e.kind != sliding_ladder::registry::Kind::OnShell {
            continue;
        }
        let (l, s) = ladder_point(&r);
        // θ̈ = (3g/4l) sin θ, eq. (5).
        assert_eq!(s.accel, q("3/4") * l.g / l.l * s.sin, "({})", r.number);
    }
}

#[test]
fn the_named_form_holds_the_misprint_in_the_display_as_printed() {
    for r in errata(&Default::default()) {
        let e = equations()
            .into_iter()
            .find(|e| e.number == r.number)
            .unwrap();
        let k = r
            .misprinted_form
            .unwrap_or_else(|| panic!("({}) no form", r.number));
        let wrong = r.misprinted_form_latex.unwrap();
        if r.number == 68 {
            // Two statements (ours, then Milne's after `,\quad`): counted by the parser only.
            assert!(k > 1);
            continue;
        }
        let pieces = forms(e.latex());
        assert!(
            squash(&pieces[k - 1]).contains(&squash(wrong)),
            "({}) form {k} is '{}', the misprint '{wrong}'",
            r.number,
            pieces[k - 1]
        );
    }
    // A display without the misprint has no misprinted form.
    assert_eq!(misprinted_form(28, r"\frac{dL_E}{dt} = \tau_E"), None);
    assert_eq!(misprinted_form(25, r"a = b"), None);
}

#[test]
fn the_terminal_shows_unicode_and_json_keeps_latex() {
    let list = errata(&Default::default());
    let text = sliding_ladder::cli::errata::misprint_text(&list);
    assert!(
        !text.contains("\\frac") && !text.contains("\\theta"),
        "{text}"
    );
    assert!(text.contains("4ml²θ̇²/3"), "{text}");
    assert!(text.contains("form 3 of the display"), "{text}");
    assert!(
        text.contains("at the exact point (SI units) m = 3, l = 5, g = 7, sin θ = 4/5"),
        "{text}"
    );
    let json = serde_json::to_value(&list).unwrap();
    assert!(json[0]["printed"].as_str().unwrap().contains("\\tau_E"));
    assert_eq!(json[0]["misprinted_form"], 3);
}

#[test]
fn errata_md_names_the_form_the_residual_and_the_point_as_the_code_has_them() {
    let page = std::fs::read_to_string(sliding_ladder::docs::default_dir().join("ERRATA.md"))
        .expect("ERRATA.md");
    let list = errata(&Default::default());
    for r in &list {
        let line = format!(
            "- residual at the exact point of `ladder errata` (SI units): form {} as printed {} {}, corrected 0",
            r.misprinted_form.unwrap(),
            r.printed_residual_exact,
            r.residual_unit
        );
        assert!(page.contains(&line), "ERRATA.md lacks: {line}");
    }
    // The ladder point as the page states it: every coordinate but θ̈ (which depends on the
    // kind), from a kinematic erratum, (49).
    let r = list.iter().find(|r| r.number == 49).unwrap();
    let stated: Vec<String> = r
        .point
        .iter()
        .filter(|(n, _)| n != "θ̈" && n != "θ⃛")
        .map(|(n, v)| format!("{n} = {v}"))
        .collect();
    let flat = sliding_ladder::docs::normalize_latex(&page);
    assert!(
        flat.contains(&stated.join(", ")),
        "ERRATA.md does not state the point {stated:?}"
    );
}

#[test]
fn the_whole_terminal_output_of_ladder_errata_is_unicode() {
    // Every formula the terminal shows, the prose errata's included, is read into Unicode
    // (issue 16, item 4); the LaTeX stays in --json. Before, the prose erratum of sec. A.5
    // printed `-\frac{2}{3}m l \dot{\theta}` in the terminal.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("errata")
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    let latex: Vec<&str> = text.lines().filter(|l| l.contains('\\')).collect();
    assert!(latex.is_empty(), "LaTeX in the terminal: {latex:#?}");
    let a5 = sliding_ladder::print::unicode::unicode(r"-\frac{2}{3}m l^2 \dot{\theta}");
    assert!(text.contains(&format!("corrected: {a5}")), "{text}");
    // Plain words pass through unchanged.
    assert!(text.contains("printed: about point C   corrected: about point D"));
    let json = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["errata", "--json"])
        .output()
        .expect("runs");
    assert!(String::from_utf8_lossy(&json.stdout).contains(r"-\\frac{2}{3}m l^2 \\dot{\\theta}"));
}

/// The erratum about a system of particles, (68), a vector display: rebuilt from the printed
/// point alone (masses, positions, velocities, accelerations of the particles and of P), its
/// printed and corrected forms, evaluated by the print evaluator, differ first in the component
/// the report names, by exactly the printed residual (the components before it agree), and the
/// residual is measured against a side that is not the misprint. A report that named another
/// component, or measured at another point, fails here.
#[test]
fn the_particle_erratum_reproduces_its_residual_in_the_component_it_names() {
    use sliding_ladder::system::{Particle, Point, System};
    use sliding_ladder::vector::Vec3;
    let list = errata(&Default::default());
    let r = list
        .iter()
        .find(|r| r.point.iter().any(|(n, _)| n == "m_1"))
        .expect("an erratum about particles");
    let v3 = |name: &str| {
        let t = r
            .point
            .iter()
            .find(|(n, _)| n == name)
            .expect(name)
            .1
            .clone();
        let c: Vec<Rational> = t.trim_matches(['(', ')']).split(", ").map(q).collect();
        Vec3::new(c[0].clone(), c[1].clone(), c[2].clone())
    };
    let count = r.point.iter().filter(|(n, _)| n.starts_with("m_")).count();
    let particles = (1..=count)
        .map(|i| Particle {
            m: coordinate(r, &format!("m_{i}")),
            x: v3(&format!("x_{i}")),
            v: v3(&format!("v_{i}")),
            a: v3(&format!("a_{i}")),
            j: Vec3::zero(),
        })
        .collect();
    let sys = System {
        particles,
        spin: None,
    };
    let p = Point {
        x: v3("x_P"),
        v: v3("v_P"),
        a: v3("a_P"),
        j: Vec3::zero(),
    };
    let (e, printed, corrected) = misprinted_slot(r.number);
    let ctx = Ctx {
        model: Rc::new(Model::particles(sys, p)),
        section: e.section,
        number: e.number,
        // The misprint is in Milne's statement of the display, in his symbols.
        milne: true,
        index: None,
        table: sliding_ladder::print::symbols::table(),
    };
    let value = |t: &str| match evaluate(&parse_expr(t).unwrap(), &ctx).unwrap() {
        Value::Vector(v) => [v.x, v.y, v.z],
        Value::Scalar(_) => panic!("({}) is a vector display", e.number),
    };
    let (a, b) = (value(&printed), value(&corrected));
    let diff: Vec<Rational> = (0..3).map(|i| a[i].clone() - b[i].clone()).collect();
    let first = diff
        .iter()
        .position(|d| !d.is_zero())
        .expect("a nonzero component");
    assert_eq!(
        r.residual_component,
        Some(['x', 'y', 'z'][first]),
        "({})",
        r.number
    );
    assert_eq!(diff[first], q(&r.printed_residual_exact), "({})", r.number);
    assert_eq!(r.corrected_residual, "0");
    assert!(
        !r.residual_against.is_empty() && r.residual_against != "none",
        "({}): measured against '{}'",
        r.number,
        r.residual_against
    );
    // The scalar errata name no component.
    for s in list.iter().filter(|s| s.number != r.number) {
        assert_eq!(s.residual_component, None, "({})", s.number);
    }
}

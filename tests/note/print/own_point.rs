//! Symbols that must differ (issue 37, item 3): each display prints the symbols of its own point
//! and section, with the exceptions of `symbols.toml`. Every pristine display follows the rule;
//! another point's symbol planted into any display of a torque analysis is flagged, naming the
//! symbol and the section; a display that compares points and loses one is flagged too.

use sliding_ladder::print::ast::Expr;
use sliding_ladder::print::own_point::{parse_rules, point_of, ExceptionKind, NOTE_POINTS};
use sliding_ladder::print::parser::parse_expr;
use sliding_ladder::print::symbols::{point_rules, SYMBOLS_TOML};
use sliding_ladder::registry::equations;
use sliding_ladder::registry::print_check::{print_chains, symbol_check::own_points};

/// A symbol's key, as the parser makes it (`\mathbf{x}_P` → `\mathbf{x}_{P}`).
fn key(latex: &str) -> String {
    match parse_expr(latex) {
        Ok(Expr::Sym(k)) => k,
        other => panic!("{latex}: {other:?}"),
    }
}

/// The symbol keys of a display in our notation (Milne's part is his).
fn our_keys(n: u32, latex: &str) -> Vec<String> {
    let (_, chains) = print_chains(n, latex).expect("parses");
    let mut keys = Vec::new();
    for f in chains.iter().flatten().filter(|f| !f.milne) {
        sliding_ladder::print::own_point::symbol_keys(&f.expr, &mut keys);
    }
    keys
}

#[test]
fn a_symbols_point_is_its_printed_subscript() {
    // Written by hand from the symbol table's LaTeX.
    for (key, point) in [
        ("I_A", Some("A")),
        (r"\tau_E", Some("E")),
        (r"\mathbf{x}_{\text{cm}}", Some("cm")),
        (r"\ddot{y}_{\text{cm}}", Some("cm")),
        ("F_{C,y}", Some("C")),
        (r"\mathbf{L}'_P", Some("P")),
        (r"\tilde{\tau}_C", Some("C")),
        (r"\mathbf{x}_i", None),
        ("a_x", None),
        ("F_w", None),
        ("E_0", None),
        (r"\theta", None),
    ] {
        assert_eq!(point_of(key), point, "{key}");
    }
}

#[test]
fn every_display_of_the_note_has_a_rule_and_follows_it() {
    let rules = point_rules();
    let (mut with_points, mut bad) = (Vec::new(), Vec::new());
    for e in equations() {
        assert!(
            rules.section_rule(e.section).is_some(),
            "({}) sec. {} has no [[section]] in symbols.toml",
            e.number,
            e.section
        );
        let (_, chains) = print_chains(e.number, e.latex()).unwrap();
        let problems = own_points(&e, &chains);
        if !problems.is_empty() {
            bad.push((e.number, problems));
        }
        if our_keys(e.number, e.latex())
            .iter()
            .any(|k| point_of(k).is_some())
        {
            with_points.push(e.number);
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
    // The displays whose print names no point, read off the note by hand: their symbols are m, l,
    // g, θ and its rates, T, V, ℒ, E, F_w, F_f, a_x, a_y, particles' x_i, v_i, F_i, and Milne's
    // names. (57) names τ_P through the form it continues from (56).
    let none: Vec<u32> = equations()
        .iter()
        .map(|e| e.number)
        .filter(|n| !with_points.contains(n))
        .collect();
    assert_eq!(
        none,
        [
            3, 4, 5, 6, 9, 10, 14, 15, 29, 30, 31, 35, 54, 60, 61, 62, 63, 64, 65, 66, 68, 69, 70,
            71, 76
        ]
    );
}

/// `key` with the point `from` written as `to` (one-letter subscripts: `_{A}`, `_{A,x}`, `_A`).
fn swap_point(key: &str, from: &str, to: &str) -> Option<String> {
    for (a, b) in [
        (format!("_{{{from}}}"), format!("_{{{to}}}")),
        (format!("_{{{from},"), format!("_{{{to},")),
    ] {
        if key.contains(&a) {
            return Some(key.replacen(&a, &b, 1));
        }
    }
    let plain = format!("_{from}");
    key.ends_with(&plain)
        .then(|| format!("{}_{to}", &key[..key.len() - plain.len()]))
}

#[test]
fn another_points_symbol_planted_anywhere_is_flagged_naming_symbol_and_section() {
    let rules = point_rules();
    let mut planted = 0;
    for e in equations() {
        let rule = rules.section_rule(e.section).unwrap();
        let keys = our_keys(e.number, e.latex());
        for (i, key) in keys.iter().enumerate() {
            let Some(from) = point_of(key).filter(|p| p.len() == 1) else {
                continue;
            };
            for to in NOTE_POINTS.iter().filter(|p| p.len() == 1 && **p != from) {
                // A point this display may name (its section's, or an exception's) is no plant.
                let allowed = rule.allowed.iter().any(|a| a == to)
                    || rules
                        .exceptions
                        .iter()
                        .any(|x| x.equation == e.number && x.points.iter().any(|p| p == to));
                let Some(swapped) = swap_point(key, from, to).filter(|_| !allowed) else {
                    continue;
                };
                let mut edited = keys.clone();
                edited[i] = swapped.clone();
                let problems = rules.check(e.section, e.number, &edited);
                let shown = sliding_ladder::print::unicode::unicode(&swapped);
                let want = format!("{shown} in sec. {} (point {})", e.section, rule.point);
                assert!(
                    problems.iter().any(|p| p.contains(&want)),
                    "({}) {key} → {swapped}: {problems:?}",
                    e.number
                );
                planted += 1;
            }
        }
    }
    // Every point-subscripted symbol of a ruled display, swapped to each point not allowed there.
    assert!(planted > 300, "{planted} plants");
}

#[test]
fn a_display_that_compares_points_must_print_each() {
    let rules = point_rules();
    let keys = |v: &[&str]| v.iter().map(|s| key(s)).collect::<Vec<_>>();
    // (13) as printed, and with I_C → I_A (the planted swap of tests/note/print/planted.rs).
    let printed = keys(&["I_A", "I_C", "I_D", "I_E", r"I_{\text{cm}}"]);
    assert!(rules.check("2.2", 13, &printed).is_empty());
    let swapped = keys(&["I_A", "I_D", "I_E", r"I_{\text{cm}}"]);
    let p = rules.check("2.2", 13, &swapped);
    assert!(
        p.len() == 1 && p[0].contains("prints no symbol of C"),
        "{p:?}"
    );
    // The same symbols in (12), which compares nothing: C, D, E are foreign to sec. 2.2.
    assert_eq!(rules.check("2.2", 12, &printed).len(), 3);
}

#[test]
fn a_slip_is_allowed_for_its_own_symbol_only() {
    let rules = point_rules();
    let k = |s: &str| vec![key(s)];
    // (49) prints x_P where it means x_C (ERRATA.md, Notation slips): allowed; L_P is not.
    assert!(rules.check("A.1", 49, &k(r"\mathbf{x}_P")).is_empty());
    let p = rules.check("A.1", 49, &k(r"\mathbf{L}_P"));
    assert!(
        p.len() == 1 && p[0].contains("L_P in sec. A.1 (point C)"),
        "{p:?}"
    );
    // Nor x_P elsewhere in A.1.
    assert_eq!(rules.check("A.1", 46, &k(r"\mathbf{x}_P")).len(), 1);
}

#[test]
fn every_exception_is_used_by_its_display_and_every_slip_is_in_the_errata() {
    let rules = point_rules();
    let errata = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("equations/ERRATA.md"),
    )
    .unwrap();
    let slips = &errata[errata.find("## Notation slips").expect("section")..];
    for x in &rules.exceptions {
        let e = equations()
            .into_iter()
            .find(|e| e.number == x.equation)
            .expect("a display of the note");
        let points: Vec<&str> = our_keys(e.number, e.latex())
            .iter()
            .filter_map(|k| point_of(k))
            .collect();
        // Stale exceptions hide swaps: each names a point its display prints and its section
        // does not allow.
        let rule = rules.section_rule(e.section).unwrap();
        assert!(
            x.points
                .iter()
                .any(|p| points.contains(&p.as_str()) && !rule.allowed.contains(p)),
            "({}) {:?}: prints {points:?}",
            x.equation,
            x.points
        );
        if x.kind == ExceptionKind::Slip {
            assert!(
                slips.contains(&format!("**({})**", x.equation)),
                "({}) is not under Notation slips in ERRATA.md",
                x.equation
            );
        }
    }
}

#[test]
fn a_rule_naming_no_point_of_the_note_or_an_unknown_field_is_refused() {
    let base =
        "[[symbol]]\nlatex='m'\nquantity='m'\nmeaning='m'\ndefined='d'\ndimension='M'\nunit='kg'\n";
    let bad_point =
        format!("{base}[[section]]\nsection='2.4'\npoint='C'\nallowed=['C','Q']\nwhy='w'\n");
    let e = parse_rules(&bad_point).unwrap_err();
    assert!(e.contains("'Q' is not a point"), "{e}");
    let bad_field = format!(
        "{base}[[exception]]\nequation=1\nkind='compares'\npoints=['A']\nwhy='w'\nreason='r'\n"
    );
    assert!(parse_rules(&bad_field).is_err());
    let bad_symbol = format!(
        "{base}[[exception]]\nequation=1\nkind='slip'\npoints=['A']\nsymbols=['a_x']\nwhy='w'\n"
    );
    assert!(parse_rules(&bad_symbol)
        .unwrap_err()
        .contains("not a symbol of a point"));
    // The shipped table reads.
    assert!(!parse_rules(SYMBOLS_TOML).unwrap().sections.is_empty());
}

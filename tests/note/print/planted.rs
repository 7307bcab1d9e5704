//! The proof of absence (issue 37): each class of edit the print check used to miss is planted
//! into a copy of the print (`equations/*.md`, the one file that holds each display) and
//! `ladder verify --equations COPY` must flag exactly the planted displays, each with its reason;
//! an edit that leaves the display saying what the note means is left unflagged and `ladder show`
//! says why. A pristine copy is flagged nowhere.

use crate::common::tmp_dir;
use std::path::Path;
use std::process::Command;

/// (file, display, printed text, planted text, class, the reason verify must give).
type Plant = (
    &'static str,
    u32,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
);

const PLANTS: [Plant; 8] = [
    (
        "B-milne.md",
        84,
        r"\mathbf{L}_{\text{cm}} = \mathbf{L}'_{\text{cm}}, \quad",
        r"\mathbf{L}_P = \mathbf{L}'_{\text{cm}}, \quad",
        "a subscript swap between quantities equal on the old sample (P riding on the cm)",
        "differs from its chain",
    ),
    (
        "B-milne.md",
        86,
        r"\frac{d\mathbf{L}_P}{dt} \Big|_{\mathbf{x}_P=0} + \mathbf{v}_P",
        r"\frac{d\mathbf{L}_P}{dt} + \mathbf{v}_P",
        "a dropped evaluation bar",
        "premise",
    ),
    (
        "B-milne.md",
        70,
        r"\mathbf{F} = 0 \Rightarrow \mathbf{P} = \text{const}",
        r"\mathbf{F} = 0, \quad \mathbf{P} = \text{const}",
        "an implication made a conjunction",
        "form",
    ),
    (
        "B-milne.md",
        88,
        r"\frac{d\mathbf{L}}{dt} \Big|_{\mathbf{x}_{\text{cm}}=0} =",
        r"\frac{d\mathbf{L}}{dt} \Big|_{\mathbf{x}_P=\mathbf{x}_{\text{cm}}=0} =",
        "a premise strengthened",
        "premise",
    ),
    (
        "A1-method-1.md",
        54,
        "= m g l \\sin \\theta\n$$",
        "= m g l \\cos \\theta\n$$",
        "a typo in an erratum's correct side",
        "form 2 'mgl\\cos\\theta', a correct form of the erratum, differs from the independent torque",
    ),
    (
        "A5-method-5.md",
        62,
        r"+ 2m l^2 \cos^2 \theta \ddot{\theta} - 2m l^2 \cos \theta \sin \theta \dot{\theta}^2 = m l g",
        r"+ 2m l^2 \sin^2 \theta \ddot{\theta} - 2m l^2 \cos \theta \sin \theta \dot{\theta}^2 = m l g",
        "a typo in an erratum's correct side",
        "a correct form of the erratum, differs from the independent rate",
    ),
    (
        "02-point-a.md",
        13,
        "I_A = I_C = I_D",
        "I_A = I_A = I_D",
        "a subscript swap between quantities equal on the ladder (I_C → I_A)",
        "symbols: (13) compares the points A, C, D, E on purpose",
    ),
    (
        "05-point-d.md",
        24,
        r"L_D = I_D\dot{\theta}",
        r"L_C = I_D\dot{\theta}",
        "a subscript swap between quantities equal on the ladder (L_D → L_C, both 4ml²θ̇/3)",
        "symbols: L_C in sec. 2.5 (point D) is a quantity of point C",
    ),
];

/// An edit that leaves the display saying what the note means: x_P → x_C in (49) writes the
/// point the note means there (its x_P is a notation slip, equations/ERRATA.md), so nothing is
/// flagged and `ladder show` says so. (file, display, printed, planted, other symbol, why.)
const INVISIBLE: [(&str, u32, &str, &str, &str, &str); 1] = [(
    "A1-method-1.md",
    49,
    r"\mathbf{L}_C = \mathbf{L}_{\text{cm}} + (\mathbf{x}_{\text{cm}} - \mathbf{x}_P)",
    r"\mathbf{L}_C = \mathbf{L}_{\text{cm}} + (\mathbf{x}_{\text{cm}} - \mathbf{x}_C)",
    "x_C for x_P",
    "x_C is what the note means",
)];

fn copy_of_the_print(tag: &str) -> std::path::PathBuf {
    let dir = tmp_dir("planted", tag);
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("equations");
    for f in std::fs::read_dir(src).unwrap() {
        let f = f.unwrap().path();
        if f.extension().is_some_and(|x| x == "md") {
            std::fs::copy(&f, dir.join(f.file_name().unwrap())).unwrap();
        }
    }
    dir
}

fn plant(dir: &Path, file: &str, from: &str, to: &str) {
    let p = dir.join(file);
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains(from), "{file} has no '{from}'");
    std::fs::write(&p, text.replacen(from, to, 1)).unwrap();
}

/// `ladder verify --json` of the folder, of the displays in `only` when given.
fn verify(dir: &Path, only: Option<&str>) -> (Option<i32>, serde_json::Value, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["verify", "--json", "--equations"])
        .arg(dir)
        .args(only.map(|o| ["--only", o]).into_iter().flatten())
        .output()
        .unwrap();
    let json = serde_json::from_slice(&o.stdout).expect("verify --json");
    (
        o.status.code(),
        json,
        String::from_utf8_lossy(&o.stderr).into(),
    )
}

fn failed(json: &serde_json::Value) -> Vec<(u64, Vec<String>)> {
    json["equations"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["status"] == "failed")
        .map(|r| {
            let problems = r["problems"].as_array().unwrap();
            (
                r["number"].as_u64().unwrap(),
                problems
                    .iter()
                    .map(|p| p.as_str().unwrap().to_string())
                    .collect(),
            )
        })
        .collect()
}

#[test]
fn every_planted_class_is_flagged_with_its_reason_and_nothing_else() {
    // The displays to be planted pass in a pristine copy (the others are held below: only the
    // planted ones may fail).
    let clean = copy_of_the_print("clean");
    let mut planted: Vec<u64> = PLANTS.iter().map(|p| u64::from(p.1)).collect();
    planted.sort_unstable();
    planted.dedup();
    let only = planted
        .iter()
        .map(u64::to_string)
        .collect::<Vec<_>>()
        .join(",");
    let (code, json, err) = verify(&clean, Some(&only));
    assert_eq!(code, Some(0), "a pristine copy: {err}");
    assert!(failed(&json).is_empty());
    assert_eq!(
        json["equations"].as_array().map(Vec::len),
        Some(planted.len())
    );

    let dir = copy_of_the_print("all");
    for (file, _, from, to, _, _) in PLANTS {
        plant(&dir, file, from, to);
    }
    for (file, _, from, to, _, _) in INVISIBLE {
        plant(&dir, file, from, to);
    }
    let (code, json, err) = verify(&dir, None);
    assert_eq!(code, Some(1), "{err}");
    let flagged = failed(&json);
    let numbers: Vec<u64> = flagged.iter().map(|f| f.0).collect();
    assert_eq!(numbers, planted, "flagged exactly the planted displays");
    for (_, n, _, _, class, reason) in PLANTS {
        let problems = &flagged.iter().find(|f| f.0 == u64::from(n)).unwrap().1;
        // The reason names the form, the premise or the symbol that changed.
        assert!(
            problems.iter().any(|p| p.contains(reason)),
            "({n}) {class}: {problems:?}"
        );
        assert!(err.contains(&format!("({n})")), "({n}) {class}: {err}");
    }
}

#[test]
fn show_says_what_the_symbol_check_does_with_each_blind_pair() {
    let dir = copy_of_the_print("invisible");
    let show = |n: u32| -> Vec<String> {
        let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(["show", &n.to_string(), "--equations"])
            .arg(&dir)
            .output()
            .unwrap();
        String::from_utf8_lossy(&o.stdout)
            .lines()
            .filter(|l| l.contains("blind:"))
            .map(String::from)
            .collect()
    };
    // Asked of the print as it stands: what would writing the other symbol do?
    for (_, n, _, _, pair, why) in INVISIBLE {
        let blind = show(n);
        assert!(
            blind
                .iter()
                .any(|l| l.contains("invisible here") && l.contains(pair) && l.contains(why)),
            "({n}): {blind:?}"
        );
    }
    // The pairs of (13) and of a torque analysis: the values are blind, the symbol check is not.
    let caught = |n: u32, pair: &str| {
        let blind = show(n);
        assert!(
            blind
                .iter()
                .any(|l| l.contains(pair) && l.contains("the symbol check catches it")),
            "({n}) {pair}: {blind:?}"
        );
    };
    caught(13, "I_C for I_A");
    caught(24, "L_C for L_D");
    caught(21, "I_A for I_C");
}

/// A coefficient changed below a float's resolution, 3/4 → (3·10¹⁸ + 1)/(4·10¹⁸) in (5): every
/// float state rounds it to 3/4, so only the exact points see it, and the verdict names the
/// form that differs and its nonzero residual (not the chain's first form, which agrees with
/// itself).
#[test]
fn a_coefficient_changed_below_float_resolution_is_caught_exactly_naming_its_form() {
    let dir = copy_of_the_print("sub-ulp");
    plant(
        &dir,
        "01-lagrange.md",
        r"\ddot{\theta} = \frac{3g}{4l} \sin \theta",
        r"\ddot{\theta} = \frac{3000000000000000001g}{4000000000000000000l} \sin \theta",
    );
    let (code, json, err) = verify(&dir, Some("5"));
    assert_eq!(code, Some(1), "{err}");
    let flagged = failed(&json);
    assert_eq!(flagged.len(), 1, "{flagged:?}");
    let (n, problems) = &flagged[0];
    assert_eq!(*n, 5);
    let exact = problems
        .iter()
        .find(|p| p.contains("exactly (residual"))
        .unwrap_or_else(|| panic!("no exact residual: {problems:?}"));
    assert!(exact.contains("form 2"), "{exact}");
    assert!(!exact.contains("residual 0."), "{exact}");
    // The float states cannot see it: the worst float residual stays within its bound.
    let worst = json["equations"][0]["max_residual"]
        .as_f64()
        .expect("residual");
    assert!(worst <= 4.0, "floats cannot see it: {worst}");
}

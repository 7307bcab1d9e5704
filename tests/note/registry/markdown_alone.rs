//! A derivation in markdown alone (issue 36): a display (91) added as a new file in a copy of
//! `equations/`, with no Rust and no other file changed, is verified by `ladder verify`, shown by
//! `ladder show`, listed by `ladder errata` and typeset by `ladder book`, all with
//! `--equations DIR`; a wrong term makes it `failed`, exit 1, with the reason on stderr.
//!
//! The reference for (91) is independent of the crate: sympy, with θ(t) a free function, the
//! ladder's ends C = (0, 2l cos θ), D = (2l sin θ, 0), Q = C + (D − C)/4, the contact forces
//! F_w = m ẍ_B, F_f = mg + m ÿ_B that the motion requires, L'_Q = (ml²/3 + m(l/2)²) θ̇:
//! form 1 − d/dt L'_Q = 0, form 3 − form 2 = 0 and form 4 − form 3 = 0 for any θ(t), while
//! form 3 − form 2 = lm(3g sin θ − 4lθ̈)/3 vanishes exactly on the motion (5), θ̈ = 3g sin θ/(4l):
//! so the display holds on the motion, and off it breaks at its 2nd `=` only (script:
//! docs/note-as-source.md, "The reference for (91)").

use crate::common::copy_of_equations;
use serde_json::Value;
use std::process::{Command, Output};

/// Display (91): the torque analysis about Q, a quarter of the way from C to D, in a chapter
/// of its own that declares the point and its symbols.
const QUARTER_POINT: &str = r#"# Sec. 2.8 — Torque analysis about a quarter point Q, eq. (91)

Q is the point of the ladder a quarter of the way from C to D: at distance l/2 from the centre
of mass, so I_Q = I_cm + m(l/2)² = 7ml²/12, and the ladder turns rigidly about it.

*Points:* Q = ladder:1/4

*Symbols:*
- $L_Q$ = `relative_angular_momentum:Q.z` [M L^2 T^-1]: angular momentum about Q, velocities relative to Q
- $\tau_Q$ = `torque:Q.z` [M L^2 T^-2]: torque of gravity and the contact forces about Q
- $F_{Q,x}$ = `coordinate_force:Q.x` [M L T^-2]: x component of the coordinate force −m a_Q
- $F_{Q,y}$ = `coordinate_force:Q.y` [M L T^-2]: y component of the coordinate force −m a_Q

### (91) Torque analysis about Q

$$
\frac{dL_Q}{dt} = \frac{7ml^2\ddot{\theta}}{12} = \tau_Q + \frac{l\sin\theta}{2}F_{Q,y} + \frac{l\cos\theta}{2}F_{Q,x} = -\frac{mgl\sin\theta}{2} + \frac{3F_f l\sin\theta}{2} - \frac{F_w l\cos\theta}{2} + \frac{l\sin\theta}{2}F_{Q,y} + \frac{l\cos\theta}{2}F_{Q,x}
$$

Gravity at B has arm l sin θ/2 about Q, the floor's push at D arm 3l sin θ/2, the wall's push
at C arm l cos θ/2; the coordinate force −m a_Q at the centre of mass adds its torque.

*Kind:* on-shell
"#;

fn ladder(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("ladder runs")
}

fn row(v: &Value, label: &str) -> Value {
    v["equations"]
        .as_array()
        .and_then(|a| a.iter().find(|r| r["label"] == label))
        .cloned()
        .unwrap_or_else(|| panic!("no row {label}"))
}

#[test]
fn a_display_in_markdown_alone_is_verified_shown_listed_and_typeset() {
    let dir = copy_of_equations("alone");
    std::fs::write(dir.join("91-quarter-point.md"), QUARTER_POINT).expect("write");
    let d = dir.to_str().expect("utf-8 path");
    // (91) alone here; `ladder book` below verifies every display of the folder (exit 0).
    let out = ladder(&["verify", "--equations", d, "--json", "--only", "91"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let r = row(&v, "(91)");
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["proof"], "proved", "{r}");
    assert_eq!(r["off_motion"], "fails", "{r}");
    assert_eq!(
        r["law_step"], 2,
        "the law at the 2nd `=`, found off the motion: {r}"
    );
    assert_eq!(r["units"], "consistent", "{r}");
    assert_eq!(
        (r["print_forms"].as_u64(), r["print_parsed"].as_u64()),
        (Some(4), Some(4))
    );
    assert_eq!(r["exact_failures"], 0);
    assert!(
        r["doc"]
            .as_str()
            .is_some_and(|p| p.ends_with("91-quarter-point.md:14")),
        "{r}"
    );
    assert_eq!(v["summary"]["failed"], 0);
    assert!(
        v["docs"]["problems"].as_array().is_some_and(Vec::is_empty),
        "{}",
        v["docs"]
    );

    let show = ladder(&["show", "91", "--equations", d, "--json"]);
    assert!(
        show.status.success(),
        "{}",
        String::from_utf8_lossy(&show.stderr)
    );
    let s = String::from_utf8_lossy(&show.stdout);
    assert!(
        s.contains("\"number\": 91") && s.contains("Torque analysis about Q"),
        "{s}"
    );

    let errata = ladder(&["errata", "--equations", d]);
    assert!(
        errata.status.success(),
        "{}",
        String::from_utf8_lossy(&errata.stderr)
    );

    let book = dir.with_extension("book");
    let _ = std::fs::remove_dir_all(&book);
    let b = ladder(&[
        "book",
        "--equations",
        d,
        "--out",
        book.to_str().expect("utf-8"),
    ]);
    assert!(b.status.success(), "{}", String::from_utf8_lossy(&b.stderr));
    let page = std::fs::read_to_string(book.join("91-quarter-point.html")).expect("its page");
    assert!(
        page.contains(r#"data-number="91" data-status="verified""#),
        "no verified (91) on its page"
    );
    let _ = std::fs::remove_dir_all(&book);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_wrong_term_fails_with_exit_1_and_the_reason() {
    let dir = copy_of_equations("wrong");
    // The floor's torque about Q is 3F_f l sin θ/2; drop the 3.
    let wrong = QUARTER_POINT.replace(r"\frac{3F_f l\sin\theta}{2}", r"\frac{F_f l\sin\theta}{2}");
    assert_ne!(wrong, QUARTER_POINT);
    std::fs::write(dir.join("91-quarter-point.md"), wrong).expect("write");
    let d = dir.to_str().expect("utf-8 path");
    let out = ladder(&["verify", "--equations", d, "--only", "91", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("failed: (91) ("), "{err}");
    assert!(
        err.contains("91-quarter-point.md:14)"),
        "the verdict's file:line: {err}"
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let r = row(&v, "(91)");
    assert_eq!(r["status"], "failed");
    let problems = r["problems"].to_string();
    assert!(
        problems.contains("form 4") && problems.contains("exactly"),
        "{problems}"
    );
    let show = ladder(&["show", "91", "--equations", d]);
    assert_eq!(show.status.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_number_the_note_does_not_have_is_refused_with_its_displays() {
    let out = ladder(&["show", "91"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("'91' is not a display of the note"), "{err}");
}

/// A student's homework, in a folder of its own outside the crate: one display right, one with
/// a wrong coefficient (the equation of motion (5) has 3g/4l, not 3g/2l).
const HOMEWORK: &str = r#"# Sec. 2.1 — Homework: the ladder by energy

### (1) Kinetic energy

$$
T = \frac{m v_{\text{cm}}^2}{2} + \frac{I_{\text{cm}} \dot{\theta}^2}{2} = \frac{2m l^2 \dot{\theta}^2}{3}
$$

*Kind:* kinematic

### (2) Equation of motion

$$
\ddot{\theta} = \frac{3g}{2l} \sin \theta
$$

*Kind:* on-shell
"#;

#[test]
fn a_users_folder_outside_the_crate_gets_a_verdict_per_display_with_file_and_line() {
    let dir = std::env::temp_dir().join(format!("ladder-homework-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("homework.md"), HOMEWORK).expect("write");
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .current_dir(&dir)
        .args(["verify", "--equations", ".", "--json"])
        .output()
        .expect("ladder runs");
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["equations"].as_array().map(Vec::len), Some(2));
    let (one, two) = (row(&v, "(1)"), row(&v, "(2)"));
    assert_eq!(
        (&one["status"], &two["status"]),
        (&"verified".into(), &"failed".into())
    );
    assert_eq!(one["doc"], "./homework.md:3");
    assert_eq!(two["doc"], "./homework.md:11");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("failed: (2) (./homework.md:11)"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

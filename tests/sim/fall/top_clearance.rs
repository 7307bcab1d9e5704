//! A floor phase whose top goes through the wall is flagged (issue 17, item 4): the rigid floor
//! phase has no wall, so the exact motion keeps the top clear (x_C = X − l sin θ ≥ 0) and a
//! computed `top_clearance_min` below the rounding of X − l sin θ (4 u l,
//! `sim::outcome::TOP_CLEARANCE_ROUNDING`) is integration error that moved the top through the
//! wall. `ladder simulate` then says so on stderr and in the JSON (`failed`) and exits 1 (a
//! failed check: the input was valid, the computed motion is one the model forbids).
//!
//! The failing case is issue 17's own: symplectic Euler at h = 1e-4 s from θ0 = 0.3 reports
//! top_clearance_min ≈ −3.6e-7 m. The passing case, dop853 at 1e-14, keeps the top clear.

use serde_json::Value;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::outcome::top_inside_wall;
use sliding_ladder::sim::scene;

fn text(method: &str, control: &str) -> String {
    format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = 9.81\n[start]\nangle = 0.3\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\n{control}\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"flat_time\", \"top_clearance_min\"]\n"
    )
}

fn clearance(method: &str, control: &str) -> f64 {
    let sc = scene::parse("clearance.toml", &text(method, control)).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    o.floor_report.expect("monitor").top_clearance_min
}

#[test]
fn symplectic_euler_puts_the_top_inside_the_wall_and_is_flagged() {
    let c = clearance("symplectic-euler", "step = 1e-4");
    assert!(c < -1e-7, "{c}");
    let r = crate::common::simulate_scene(
        "clearance",
        "bad",
        Some(&text("symplectic-euler", "step = 1e-4")),
        &["--json"],
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(r.stderr.contains("inside the wall"), "{}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    let v: Value = serde_json::from_str(&r.stdout).unwrap();
    assert!(v["failed"].as_str().unwrap().contains("inside the wall"));
    assert_eq!(v["floor_phase"]["top_clearance_min"].as_f64(), Some(c));
}

#[test]
fn an_accurate_run_keeps_the_top_clear_and_exits_0() {
    let c = clearance("dop853", "tolerance = 1e-14");
    assert!(c > 0.0, "{c}");
    let r = crate::common::simulate_scene(
        "clearance",
        "good",
        Some(&text("dop853", "tolerance = 1e-14")),
        &["--json"],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.is_empty(), "{}", r.stderr);
    let v: Value = serde_json::from_str(&r.stdout).unwrap();
    assert!(v.get("failed").is_none(), "{v}");
}

#[test]
fn the_flag_follows_the_half_length() {
    // The same motion at l = 1e-20 m (times scale by √l: h = 1e-14 s): the clearance scales
    // with l and so does the bound, so the verdict is the same (a bound in metres would pass
    // every small ladder).
    let sc = scene::parse(
        "clearance.toml",
        &text("symplectic-euler", "step = 1e-14")
            .replace("half_length = 1.0", "half_length = 1e-20"),
    )
    .unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let r = o.floor_report.unwrap();
    assert!(r.top_clearance_min < -1e-27, "{}", r.top_clearance_min);
    assert!(top_inside_wall(&r, 1e-20).is_some());
}

//! A run to a time past flat (issue 38, item 2): the top strikes the floor, taken as a
//! perfectly inelastic impact (`sim::impact`), and the ladder slides on lying flat to the end
//! time, said on stderr and in the JSON. Before, the run stopped at flat (0.8945 s of the
//! 3192.75 s asked), exit 0, nothing said: `final.time` was 0.8945467579667191 and
//! `final.rate` 3.554 (main's `ladder simulate --json` on the scene below).
//!
//! **References, independent of the integrators.** The separation from the closed form
//! (`sim::exact::PhaseOne`), the floor phase's conservation laws: Ẋ = l cos θ_s θ̇_s (eq. (7),
//! no horizontal force), so X(t) = l sin θ_s + Ẋ (t − t_s) for every later t, sliding
//! included; at flat the energy m g l cos θ0 = ½ m Ẋ² + ½ m l² (4/3) θ̇_f², so the impact,
//! which takes (2/3) m l² θ̇_f², takes m g l cos θ0 − ½ m Ẋ²: all but the slide's energy. Error model: dop853 at τ over N steps,
//! 10 N τ relative, on each of these.
use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::impact::{impulses, lying_flat_floor_force, slide};
use sliding_ladder::sim::outcome::FlatState;
use sliding_ladder::sim::scene;
use std::f64::consts::FRAC_PI_2;

const T_END: f64 = 3192.75;

fn scene_text(end: &str, want: &str) -> String {
    format!(
        "[ladder]\nmass = 2.0\nhalf_length = 1.0\ngravity = 9.81\n[start]\nangle = 0.3\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"dop853\"\ntolerance = 1e-12\n[end]\n{end}\n[outputs]\nwant = [{want}]\n"
    )
}

#[test]
fn a_run_past_flat_goes_on_lying_flat() {
    let text = scene_text(
        &format!("at = \"time\"\ntime = {T_END}"),
        "\"final_state\", \"forces\"",
    );
    let sc = scene::parse("past-flat.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    assert_eq!(o.last, (T_END, FRAC_PI_2, 0.0));
    let slide = o.slide.expect("the slide after flat");
    let flat = o.flat.expect("flat");
    assert_eq!(slide.impact_time, flat.time);
    let (g, l) = (9.81f64, 1.0f64);
    let sep = PhaseOne::new(0.3, 0.0, 0.75 * g / l)
        .unwrap()
        .separation()
        .unwrap();
    let xdot = l * sep.angle.cos() * sep.rate;
    let x_end = l * sep.angle.sin() + xdot * (T_END - sep.time);
    let lost = (g * l * 0.3f64.cos() - 0.5 * xdot * xdot) / (g * l);
    let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
    let bound = 10.0 * n * 1e-12;
    assert!((slide.centre_velocity_x - xdot).abs() <= bound * xdot);
    assert!(
        (slide.centre_x_end - x_end).abs() <= bound * x_end,
        "{} against {x_end}",
        slide.centre_x_end
    );
    assert!(
        (slide.energy_lost - lost).abs() <= bound * lost,
        "{} against {lost}",
        slide.energy_lost
    );
    // The trace ends lying flat: θ = π/2 at rest, the foot carrying m g/2.
    let trace = o.trace.unwrap();
    let last = trace[trace.len() - 1];
    assert_eq!(
        (last.phase, last.t, last.theta, last.rate),
        (3, T_END, FRAC_PI_2, 0.0)
    );
    assert_eq!(last.forces, Some((0.0, 9.81)));
    // A run that ends at flat is not continued.
    let at_flat = scene::parse("flat.toml", &scene_text("at = \"flat\"", "\"flat_time\"")).unwrap();
    assert!(fall::run(&at_flat, fall::MAX_STEPS)
        .unwrap()
        .slide
        .is_none());
}

/// The command says so: exit 0, a note on stderr naming the moment it lay flat, the JSON's
/// `final` at the end time and its `lying_flat` record. Failed before: main printed
/// `final.time` = 0.8945 and nothing on stderr.
#[test]
fn the_command_says_the_ladder_went_on_lying_flat() {
    let dir = std::env::temp_dir().join(format!("ladder-impact-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("past-flat.toml");
    let text = scene_text(&format!("at = \"time\"\ntime = {T_END}"), "\"final_state\"");
    std::fs::write(&path, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["simulate", "--json"])
        .arg(&path)
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out.status.code(), Some(0));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("lay flat at t = 0.89454675796") && stderr.contains("perfectly inelastic"),
        "{stderr}"
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["final"]["time"], T_END);
    assert_eq!(v["final"]["rate"], 0.0);
    let impact = v["lying_flat"]["impact_time"].as_f64().unwrap();
    assert!((impact - 0.8945467579667191).abs() < 1e-9, "{impact}");
}

const LADDER: Ladder<f64> = Ladder {
    m: 3.0,
    l: 0.7,
    g: 9.81,
};

/// The impulses satisfy the two impulse-momentum laws of the rod and leave both ends at
/// rest vertically; both are upward. Checked in exact arithmetic on binary fractions (the
/// products are then exact): m = 3, l = 0.75, θ̇ = 2. A wrong split (½, ½) fails the
/// angular law.
#[test]
fn the_impulses_stop_both_ends_and_push_up() {
    let ladder = Ladder {
        m: 3.0,
        l: 0.75,
        g: 9.81,
    };
    let (m, l, w) = (3.0, 0.75, 2.0);
    let (pc, pd) = impulses(&ladder, w);
    let inertia = m * l * l / 3.0;
    // Linear: m ΔẎ = P_C + P_D with Ẏ from −l θ̇ to 0.
    assert_eq!(pc + pd, m * l * w);
    // Angular about the centre: C lies at l on the falling side, I Δθ̇ = −l (P_C − P_D).
    assert_eq!(l * (pc - pd), inertia * w);
    assert!(pc > 0.0 && pd > 0.0);
    // The angular law can fail: an even split (each ½ m l θ̇) leaves the rod turning.
    let even = 0.5 * m * l * w;
    assert_ne!(l * (even - even), inertia * w);
}

/// The energy the impact takes is the kinetic energy of the vertical and rotational motion
/// at flat, ½ m (l θ̇)² + ½ (m l²/3) θ̇², over m g l; the slide keeps Ẋ and moves X by
/// Ẋ (t − t_f). Error model: a few roundings of products of O(1) numbers.
#[test]
fn the_slide_keeps_the_horizontal_speed_and_loses_the_rest() {
    let flat = FlatState {
        time: 1.25,
        rate: 2.3,
        centre_x: 0.7,
        centre_velocity_x: 0.9,
        centre_velocity_y: -0.7 * 2.3,
    };
    let s = slide(&LADDER, &flat, 3.25);
    let (m, l, g) = (LADDER.m, LADDER.l, LADDER.g);
    let kinetic = 0.5 * m * (l * flat.rate).powi(2) + 0.5 * (m * l * l / 3.0) * flat.rate.powi(2);
    let u = f64::EPSILON;
    assert!((s.energy_lost - kinetic / (m * g * l)).abs() <= 8.0 * u * s.energy_lost);
    assert_eq!(s.centre_velocity_x, 0.9);
    assert!((s.centre_x_end - (0.7 + 0.9 * 2.0)).abs() <= 4.0 * u * 2.5);
    assert_eq!(s.impact_time, 1.25);
    assert_eq!(lying_flat_floor_force(&LADDER), 0.5 * m * g);
}

//! Starts given from the floor, `angle_from_floor = φ0` down to 1e-273 rad (issue 17, F7 of
//! the reliability campaign; the scenes are the campaign's, seed 1, scenes 479, 62 and 272):
//! each runs to flat and agrees with the near-flat closed form (`sim::exact::near_flat`,
//! derived from the equations of motion, not from the integrators). Before the fix the
//! adaptive run failed at t = 0 ("step size 0e0 too small": the error norm's squares
//! overflowed for a state of size 1e-273) and the fixed-step runs went on past flat to
//! θ = 3.14 and 4.39 rad (the separation root, ~1e-133 into a step of ~1, was given up after
//! 200 bisections at ~1e-60, where φ was already negative).
//!
//! **Error models.** dop853: N steps of local error τ, |Δt|/t ≤ 10 N (τ + u) (as in
//! `tests/sim/complement.rs`). Verlet: the fall is at constant acceleration −Ω² to f64
//! precision, which Störmer-Verlet integrates exactly, except that a step of h overshoots flat
//! to φ1 ≈ −Ω² h²/2, where the acceleration −Ω² cos φ1 is off by φ1²/2; that slope enters the
//! step's interpolant, on which the events are found: |Δt|/t ≤ φ1²/2 = Ω⁴ h⁴/8, plus rounding.

use sliding_ladder::sim::exact::near_flat::near_flat;
use sliding_ladder::sim::outcome::Outcome;
use sliding_ladder::sim::{fall, scene};

const U: f64 = f64::EPSILON / 2.0;

fn scene_text(ladder: (f64, f64, f64), start: &str, rate0: f64, integrator: &str) -> String {
    let (m, l, g) = ladder;
    format!(
        "[ladder]\nmass = {m:e}\nhalf_length = {l:e}\ngravity = {g:e}\n[start]\n{start}\nangular_velocity = {rate0:e}\n[contact]\nmodel = \"rigid\"\n[integrator]\n{integrator}\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"separation_time\", \"flat_time\", \"energy_error\"]\n"
    )
}

/// Runs the scene and returns the relative errors of its separation and flat times against
/// the near-flat closed form, with the run.
fn relative_errors(text: &str) -> (f64, f64, Outcome) {
    let sc = scene::parse("floor.toml", text).unwrap();
    let nf = near_flat(sc.ladder.big_omega2(), sc.phi0.unwrap(), sc.rate0).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).expect("runs to flat");
    let sep = o.separation.expect("separates");
    let flat = o.flat.expect("reaches flat");
    assert!(sep.time < flat.time);
    (
        (sep.time - nf.separation_time).abs() / nf.separation_time,
        (flat.time - nf.flat_time).abs() / nf.flat_time,
        o,
    )
}

/// The same start written as `angle` (the largest f64 below π/2 lies 1.6e-16 rad from the
/// floor, not φ0): another start, whose times must be far outside `bound` (so the check can
/// fail).
fn as_angle_is_seen(text: &str, phi0: f64, bound: f64) {
    let angle = text.replace(
        &format!("angle_from_floor = {phi0:e}"),
        &format!(
            "angle = {:?}",
            f64::from_bits(std::f64::consts::FRAC_PI_2.to_bits() - 1)
        ),
    );
    assert_ne!(angle, text);
    let sc = scene::parse("floor.toml", &angle).unwrap();
    let nf = near_flat(sc.ladder.big_omega2(), phi0, sc.rate0).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let flat = o.flat.unwrap();
    assert!((flat.time - nf.flat_time).abs() / nf.flat_time > 1e6 * bound);
}

#[test]
fn an_adaptive_run_from_1e_273_rad_off_the_floor_reaches_flat_on_time() {
    // Scene 479: dop853 at 1.5e-11, from rest, l = 1.9e-16 m, g = 5.1e24 m/s².
    let (phi0, tol) = (2.6115909312122267e-273, 1.5128687807983562e-11);
    let text = scene_text(
        (
            6.570714503017747e23,
            1.8972606810472013e-16,
            5.128184680680326e24,
        ),
        &format!("angle_from_floor = {phi0:e}"),
        0.0,
        &format!("method = \"dop853\"\ntolerance = {tol:e}"),
    );
    let (sep, flat, o) = relative_errors(&text);
    let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
    let bound = 10.0 * n * (tol + U);
    assert!(
        sep <= bound && flat <= bound,
        "{sep:e} {flat:e} > {bound:e}"
    );
    as_angle_is_seen(&text, phi0, bound);
    // The same start with the other adaptive methods.
    for method in ["dopri5", "radau5", "taylor"] {
        let t = text.replace("\"dop853\"", &format!("\"{method}\""));
        let (sep, flat, o) = relative_errors(&t);
        let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
        let bound = 10.0 * n * (tol + U);
        assert!(sep <= bound && flat <= bound, "{method}: {sep:e} {flat:e}");
    }
}

/// A Verlet run of step `h` (s) on `ladder` from φ0 with a push θ̇0, held to Ω⁴ h⁴/8.
fn verlet_case(ladder: (f64, f64, f64), phi0: f64, rate0: f64, h: f64) {
    let text = scene_text(
        ladder,
        &format!("angle_from_floor = {phi0:e}"),
        rate0,
        &format!("method = \"verlet\"\nstep = {h:e}"),
    );
    let big_omega2 = 0.75 * ladder.2 / ladder.1;
    let overshoot = 0.5 * big_omega2 * h * h;
    let bound = 0.5 * overshoot * overshoot + 16.0 * U;
    let (sep, flat, _) = relative_errors(&text);
    assert!(
        sep <= bound && flat <= bound,
        "{sep:e} {flat:e} > {bound:e}"
    );
    as_angle_is_seen(&text, phi0, bound);
}

#[test]
fn a_verlet_step_far_longer_than_the_fall_stops_at_flat() {
    // Scene 62: h = 0.84 √(l/g), the whole fall ~1e-133 √(l/g), with a push of the size of
    // the fall's own speed.
    verlet_case(
        (
            3.7466322923737965e6,
            8.204605504710625e-29,
            3.6219323510523077e-1,
        ),
        3.294305603486179e-267,
        2.5648991116859627e-120,
        1.2687576488865627e-14,
    );
}

#[test]
fn a_verlet_run_from_1e_97_rad_off_the_floor_stops_at_flat() {
    // Scene 272: h = 0.0065 √(l/g).
    verlet_case(
        (
            3.485202250880018e19,
            1.0608648005400477e5,
            9.625974240332245e20,
        ),
        1.545192732772846e-97,
        2.0918580672566102e-42,
        6.797388772627143e-11,
    );
}

/// Below the scenes' range (a subnormal φ0, refused by the scene check) the library still never
/// runs past flat: a separation rounded onto the floor (φ_s = 0) ends the run with a reason.
#[test]
fn a_separation_rounded_onto_the_floor_is_an_error_not_a_run_past_flat() {
    let text = scene_text(
        (
            6.570714503017747e23,
            1.8972606810472013e-16,
            5.128184680680326e24,
        ),
        "angle_from_floor = 1e-300",
        0.0,
        "method = \"symplectic-euler\"\nstep = 1e-22",
    );
    let mut sc = scene::parse("floor.toml", &text).unwrap();
    assert!(fall::run(&sc, fall::MAX_STEPS).unwrap().flat.is_some());
    sc.phi0 = Some(5e-324);
    let e = fall::run(&sc, fall::MAX_STEPS).unwrap_err().to_string();
    assert!(e.contains("located at or past flat"), "{e}");
    let refused = scene::parse("floor.toml", &text.replace("1e-300", "5e-324"));
    assert!(refused.is_err());
}

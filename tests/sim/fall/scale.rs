//! The whole fall is scale-invariant (issue 11): for random m, l, g in 1e-30..1e30, every
//! adaptive method and random tolerances τ in [1e-12, 1e-4], the run to flat never fails, the
//! separation angle is within its error bound of the closed form, and flat time / √(l/g) and the
//! energy error equal those of m = l = 1, g = 9.81 up to rounding, and so do the floor-phase
//! monitors in units of m g and l.
//!
//! **Error model of the angle** (the one of `ladder stability`'s extreme cases): an adaptive
//! method with relative tolerance τ on the scale max(θ, θ̇/ω) that takes N steps moves
//! cos θ_s = (2ω² cos θ + θ̇²)/(3ω²) — a function of the energy, so its local errors add up
//! without amplification — by at most 10 N τ max(θ_s, 1); rounding adds a few ulps.
//!
//! **Flat time and energy error** from rest: the run is done in the scene's own units, where
//! the scene at any scale is the same problem (θ0, θ̇0 √(l/g) = 0, τ). Only T = √(l/g) and the
//! product t T, then t / T, are rounded: 4 ulps. The energy error |ΔE|/(m g l) is computed in
//! those units and must be bit-identical.
//!
//! `PROPTEST_CASES` sets the number of random scenes (default 64, about a second in release).

use proptest::prelude::*;
use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::fall::{self, Outcome};
use sliding_ladder::sim::integrators::{is_adaptive, names, Control};
use sliding_ladder::sim::scene::output::Output;
use sliding_ladder::sim::scene::{ContactModel, End, Scene};

const U: f64 = f64::EPSILON / 2.0;

fn scene(ladder: Ladder<f64>, theta0: f64, rate0: f64, method: &str, tol: f64) -> Scene {
    Scene {
        file: "(scale sweep)".into(),
        ladder,
        theta0,
        phi0: None,
        rate0,
        method: method.into(),
        control: Some(Control::Tolerance(tol)),
        order: None,
        end: End::Flat,
        outputs: vec![
            Output::SeparationAngle,
            Output::FlatTime,
            Output::EnergyError,
            Output::FloorForceMin,
            Output::TopClearanceMin,
        ],
        contact: ContactModel::Rigid,
    }
}

/// cos θ_s from the energy integral, written out (footnote 4 with a push):
/// 2/3 cos θ0 + 4 l θ̇0² / (9 g).
fn theory_cosine(ladder: &Ladder<f64>, theta0: f64, rate0: f64) -> f64 {
    2.0 / 3.0 * theta0.cos() + 4.0 * ladder.l * rate0 * rate0 / (9.0 * ladder.g)
}

/// The angle error and its bound 10 N τ max(θ_s, 1) + 8 u, N the wall phase's steps.
fn angle_error_and_bound(sc: &Scene, o: &Outcome, tol: f64) -> (f64, f64) {
    let s = o.separation.expect("separates");
    let cs = theory_cosine(&sc.ladder, sc.theta0, sc.rate0);
    let n = o.work.wall.steps as f64;
    (
        (s.angle.cos() - cs).abs(),
        10.0 * n * tol * s.angle.max(1.0) + 8.0 * U,
    )
}

fn adaptive() -> Vec<&'static str> {
    names().filter(|m| is_adaptive(m)).collect()
}

fn unit_time(l: &Ladder<f64>) -> f64 {
    (l.l / l.g).sqrt()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(64)
    ))]
    /// From rest: no failure, the angle within its bound, flat time / T within 4 ulps and the
    /// energy error bit-identical to the m = l = 1, g = 9.81 run.
    #[test]
    fn the_fall_to_flat_does_not_depend_on_scale(
        em in -30.0..30.0f64, el in -30.0..30.0f64, eg in -30.0..30.0f64,
        theta0 in 0.01..1.5f64, et in -12.0..-4.0f64, k in 0usize..16,
    ) {
        let methods = adaptive();
        let method = methods[k % methods.len()];
        let tol = 10f64.powf(et);
        let ladder = Ladder { m: 10f64.powf(em), l: 10f64.powf(el), g: 10f64.powf(eg) };
        let unit = Ladder { m: 1.0, l: 1.0, g: 9.81 };
        let (sc, sc1) = (scene(ladder, theta0, 0.0, method, tol), scene(unit, theta0, 0.0, method, tol));
        let o = fall::run(&sc, fall::MAX_STEPS);
        prop_assert!(o.is_ok(), "{method} τ {tol:e} m {:e} l {:e} g {:e}: {:?}", ladder.m, ladder.l, ladder.g, o.err());
        let (o, o1) = (o.unwrap(), fall::run(&sc1, fall::MAX_STEPS).unwrap());
        let (err, bound) = angle_error_and_bound(&sc, &o, tol);
        prop_assert!(err <= bound, "{method} τ {tol:e}: cos θ_s off by {err:e} > {bound:e}");
        let (t, t1) = (o.flat.unwrap().time / unit_time(&ladder), o1.flat.unwrap().time / unit_time(&unit));
        prop_assert!((t - t1).abs() <= 4.0 * U * t1, "flat time / T {t} vs {t1}");
        prop_assert_eq!(o.energy_error, o1.energy_error);
        // The floor-phase monitors in units of m g and l: one product on the way out and one
        // quotient here, 4 ulps. (Mutation testing: `· l` → `/ l` for the clearance went unseen.)
        let (r, r1) = (o.floor_report.unwrap(), o1.floor_report.unwrap());
        let (f, f1) = (r.floor_force_min / (ladder.m * ladder.g), r1.floor_force_min / (unit.m * unit.g));
        prop_assert!((f - f1).abs() <= 4.0 * U * f1.abs(), "floor_force_min / (m g) {f} vs {f1}");
        let (c, c1) = (r.top_clearance_min / ladder.l, r1.top_clearance_min / unit.l);
        prop_assert!((c - c1).abs() <= 4.0 * U * c1.abs(), "top_clearance_min / l {c} vs {c1}");
    }

    /// With a push θ̇0 = f ω √(cos θ0), f in [0, 1) (faster and the wall would pull at once): no
    /// failure and the angle within its bound.
    #[test]
    fn pushed_starts_separate_at_the_closed_form_at_any_scale(
        el in -30.0..30.0f64, eg in -30.0..30.0f64,
        theta0 in 0.0..1.5f64, f in 0.0..0.999f64, et in -12.0..-4.0f64, k in 0usize..16,
    ) {
        let methods = adaptive();
        let method = methods[k % methods.len()];
        let tol = 10f64.powf(et);
        let ladder = Ladder { m: 1.0, l: 10f64.powf(el), g: 10f64.powf(eg) };
        let rate0 = f * (ladder.big_omega2() * theta0.cos()).sqrt();
        // θ0 = θ̇0 = 0 is the equilibrium (the scene check refuses it).
        prop_assume!(theta0 > 0.0 || rate0 > 0.0);
        let sc = scene(ladder, theta0, rate0, method, tol);
        let o = fall::run(&sc, fall::MAX_STEPS);
        prop_assert!(o.is_ok(), "{method} τ {tol:e}: {:?}", o.err());
        let (err, bound) = angle_error_and_bound(&sc, &o.unwrap(), tol);
        prop_assert!(err <= bound, "{method} τ {tol:e}: cos θ_s off by {err:e} > {bound:e}");
    }
}

/// The bound can fail: a closed form off by 2 % is rejected at the loosest tolerance of the
/// sweep and one off by 1e-6 at the tightest; and the slow scene of issue 11 (√(l/g) ≈ 3e16 s), which
/// failed in the floor phase before the run was done in its own units, now reaches flat.
#[test]
fn the_sweep_checks_can_fail() {
    let ladder = Ladder {
        m: 1e10,
        l: 1e28,
        g: 1e-5,
    };
    for method in adaptive() {
        for (tol, off) in [(1e-4, 0.02), (1e-12, 1e-6)] {
            let sc = scene(ladder, 0.3, 0.0, method, tol);
            let o = fall::run(&sc, fall::MAX_STEPS).expect("reaches flat");
            let (err, bound) = angle_error_and_bound(&sc, &o, tol);
            assert!(err <= bound);
            let wrong_cs = (1.0 + off) * theory_cosine(&ladder, 0.3, 0.0);
            let wrong = (o.separation.unwrap().angle.cos() - wrong_cs).abs();
            assert!(
                wrong > bound,
                "{method} τ {tol:e}: a wrong closed form passes: {wrong:e} ≤ {bound:e}"
            );
            assert!(o.flat.is_some());
        }
    }
}

/// The base scene at m = 1e10 kg, l = 1e28 m, g = 1e-5 m/s², with rk4 to an end time (`STEP` and
/// `TIME` stand for the step and the end time).
fn slow() -> String {
    crate::common::edited(
        crate::common::BASE,
        &[
            (
                "mass = 1.0\nhalf_length = 1.0\ngravity = 9.81",
                "mass = 1e10\nhalf_length = 1e28\ngravity = 1e-5",
            ),
            (
                "method = \"dop853\"\ntolerance = 1e-12",
                "method = \"rk4\"\nSTEP",
            ),
            ("at = \"separation\"", "at = \"time\"\nTIME"),
            ("\"separation_angle\", \"trajectory\"", "\"final_state\""),
        ],
    )
}

/// Steps and end times are limited in units of √(l/g) and may be given in them: a ladder with
/// √(l/g) = 1e16.5 s can be stepped and run to 2.5 time units (into the floor phase) either way, and gives the same
/// answer; a step of 1 s (1e-16 units) is refused, naming the range in both units.
#[test]
fn steps_and_end_times_in_the_scenes_own_units() {
    let unit = (1e28f64 / 1e-5).sqrt();
    let run = |step: &str, time: &str| {
        let text = slow().replace("STEP", step).replace("TIME", time);
        let sc = sliding_ladder::sim::scene::parse("slow.toml", &text).expect("valid");
        fall::run(&sc, fall::MAX_STEPS).expect("runs").last
    };
    let scaled = run("scaled_step = 1e-2", "scaled_time = 2.5");
    let si = run(
        &format!("step = {:e}", 1e-2 * unit),
        &format!("time = {:e}", 2.5 * unit),
    );
    assert!((scaled.0 / unit - 2.5).abs() <= 4.0 * U * 2.5, "{scaled:?}");
    assert!((scaled.1 - si.1).abs() <= 1e-12, "{scaled:?} vs {si:?}");
    assert!(scaled.1 > 0.3, "the ladder fell: {scaled:?}");
    let err = sliding_ladder::sim::scene::parse(
        "slow.toml",
        &slow()
            .replace("STEP", "step = 1.0")
            .replace("TIME", "scaled_time = 2.5"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("step") && err.contains("√(l/g)") && err.contains("3.16"),
        "{err}"
    );
    let both = sliding_ladder::sim::scene::parse(
        "slow.toml",
        &slow()
            .replace("STEP", "scaled_step = 1e-2")
            .replace("TIME", "time = 1.0\nscaled_time = 2.5"),
    )
    .unwrap_err()
    .to_string();
    assert!(both.contains("given together with"), "{both}");
}

/// The trace's forces in SI: each wall-phase sample's (F_w, F_f) is eqs. (14), (15) for the
/// scene's own ladder at the sample's (θ, θ̇), evaluated here in SI (m = 2, l = 3, g = 9.81).
/// The run evaluates them on the unit ladder and scales by m g; the two differ by a few
/// roundings of terms of size m g: 16 ε m g. (Mutation testing: the floor force's scaling
/// `· m g` → `/ m g` went unseen; no test read a force of the trace in SI.)
#[test]
fn the_traces_forces_are_eqs_14_15_in_si() {
    use sliding_ladder::sim::{rigid, scene};
    let ladder = Ladder {
        m: 2.0,
        l: 3.0,
        g: 9.81,
    };
    let text = "[ladder]\nmass = 2.0\nhalf_length = 3.0\ngravity = 9.81\n[start]\nangle = 0.3\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"dop853\"\ntolerance = 1e-10\n[end]\nat = \"separation\"\n[outputs]\nwant = [\"forces\"]\n";
    let o = fall::run(&scene::parse("forces.toml", text).unwrap(), fall::MAX_STEPS).unwrap();
    let trace = o.trace.unwrap();
    assert!(trace.len() > 10, "{} samples", trace.len());
    let scale = ladder.m * ladder.g;
    for p in &trace {
        let (w, f) = p.forces.expect("forces asked");
        let want = (
            rigid::wall_force(&ladder, p.theta, p.rate),
            rigid::floor_force(&ladder, p.theta, p.rate),
        );
        assert!(
            (w - want.0).abs() <= 16.0 * f64::EPSILON * scale
                && (f - want.1).abs() <= 16.0 * f64::EPSILON * scale,
            "t = {}: ({w}, {f}) against {want:?}",
            p.t
        );
    }
}

//! The `sweep` group of `ladder stability`: the whole fall to flat at random scales (issue 11).
//!
//! Each case draws m, l, g from 10^U(−30, 30), θ0 from U(0.01, 1.5), a tolerance τ from
//! 10^U(−12, −4) and one of the adaptive methods in turn (`campaign::pick_method`: seeded, the
//! same cases every run; a method added to the table takes over only the cases it wins), runs
//! the rigid scene to flat and judges two things against theory:
//!
//! * cos θ_s against the energy integral 2/3 cos θ0 (from rest). Error model (as in the
//!   `extreme` group): N accepted steps at relative tolerance τ on the scale max(θ, θ̇/Ω) move
//!   cos θ_s, a function of the energy, by at most 10 N τ max(θ_s, 1), plus 8 u of rounding;
//! * flat time / √(l/g) against the same scene at m = l = 1, g = 9.81: the run is done in the
//!   scene's own units (`sim::scaled`), where both scenes are one problem, so they may differ by
//!   the rounding of T = √(l/g) and of t T / T only: 4 u relative.

use crate::ladder::Ladder;
use crate::report::campaign::pick_method;
use crate::report::stability::case::{blank, Case, U};
use crate::sim::fall;
use crate::sim::integrators::{is_adaptive, names, Control};
use crate::sim::scene::output::Output;
use crate::sim::scene::{ContactModel, End, Scene};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// Cases in the sweep.
pub const SWEEP_CASES: usize = 24;

fn flat_scene(ladder: Ladder<f64>, theta0: f64, method: &str, tol: f64) -> Scene {
    Scene {
        file: "(built in: stability sweep)".into(),
        ladder,
        theta0,
        phi0: None,
        rate0: 0.0,
        method: method.into(),
        control: Some(Control::Tolerance(tol)),
        order: None,
        end: End::Flat,
        outputs: vec![Output::SeparationAngle, Output::FlatTime],
        contact: ContactModel::Rigid,
    }
}

/// One case of the sweep.
fn sweep_case(ladder: Ladder<f64>, theta0: f64, method: &str, tol: f64) -> Case {
    let mut c = blank(
        "sweep",
        format!(
            "to flat, θ0={theta0:.3} m={:.1e} l={:.1e} g={:.1e}",
            ladder.m, ladder.l, ladder.g
        ),
        format!("{method} tol {tol:.1e}"),
        "cos θ_s = 2/3 cos θ0; flat time/√(l/g) as at m=l=1, g=9.81".into(),
    );
    let unit = Ladder {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let t = Instant::now();
    let run = fall::run(&flat_scene(ladder, theta0, method, tol), fall::MAX_STEPS);
    c.seconds = t.elapsed().as_secs_f64();
    let reference = fall::run(&flat_scene(unit, theta0, method, tol), fall::MAX_STEPS);
    let (o, r) = match (run, reference) {
        (Ok(o), Ok(r)) => (o, r),
        (Err(e), _) | (_, Err(e)) => {
            c.reason = e.to_string();
            return c;
        }
    };
    let (Some(s), Some(f), Some(rf)) = (o.separation, o.flat, r.flat) else {
        c.reason = "did not reach flat".into();
        return c;
    };
    c.steps = o.work.wall.steps + o.work.floor.map_or(0, |w| w.steps);
    c.rhs_evals = o.work.wall.rhs_evals + o.work.floor.map_or(0, |w| w.rhs_evals);
    let time_unit = |l: &Ladder<f64>| (l.l / l.g).sqrt();
    let (tau, tau1) = (f.time / time_unit(&ladder), rf.time / time_unit(&unit));
    c.value = format!("θ_s = {:.12}, t_flat/√(l/g) = {tau:.15}", s.angle);
    let cs = 2.0 / 3.0 * theta0.cos();
    let angle_err = (s.angle.cos() - cs).abs();
    let angle_bound = 10.0 * o.work.wall.steps as f64 * tol * s.angle.max(1.0) + 8.0 * U;
    let time_err = ((tau - tau1) / tau1).abs();
    // Judge the worse of the two, each relative to its own bound.
    if time_err > 4.0 * U {
        c.judge(time_err, 4.0 * U);
        c.reason = format!("flat time/√(l/g) {tau} differs from {tau1} beyond rounding");
    } else {
        c.judge(angle_err, angle_bound);
        if c.reason.is_empty() {
            c.reason = format!("flat time/√(l/g) relative difference {time_err:.1e} ≤ 4u");
        }
    }
    c
}

/// The adaptive methods of the table when the sweep was first run (its cases took them in turn).
const FIRST_ADAPTIVE: [&str; 4] = ["dopri5", "dop853", "radau5", "taylor"];

/// The sweep's cases (seeded), calling `tick` before each.
pub fn sweep_cases(tick: &mut impl FnMut(&str, u64)) -> Vec<Case> {
    let methods: Vec<&str> = names().filter(|m| is_adaptive(m)).collect();
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    (0..SWEEP_CASES)
        .map(|i| {
            tick("sweep", 1);
            let mut e = || 10f64.powf(rng.gen_range(-30.0..30.0));
            let ladder = Ladder {
                m: e(),
                l: e(),
                g: e(),
            };
            let theta0 = rng.gen_range(0.01..1.5);
            let tol = 10f64.powf(rng.gen_range(-12.0..-4.0));
            // The adaptive methods as first published took the cases in turn.
            let first = &FIRST_ADAPTIVE[..];
            let method = pick_method(11, i as u64, first, i % first.len(), &methods);
            sweep_case(ladder, theta0, method, tol)
        })
        .collect()
}

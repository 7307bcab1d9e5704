//! radau5's cost on the penalty scene (θ0 = 0.3 from rest, γ = 0) for κ = 1e4..1e12 against the
//! rigid reference (the same method on the rigid wall phase), at tolerances 1e-10 and 1e-12:
//! steps, rejected steps, Jacobians, right-hand sides, the median wall time of 5 runs and
//! κ (θ_s − θ_rigid) (the model's constant, ≈ 1.39). README's "Stiff and extreme cases" quotes it.
//!
//! `cargo run --release --example radau5_penalty`

use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::penalty::confirm::rigid_separation_angle;
use sliding_ladder::sim::penalty::run::separation;
use sliding_ladder::sim::penalty::{Contact, Law};
use sliding_ladder::sim::scene::parse;
use std::time::Instant;

const RIGID: &str = "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = 1.0\n[start]\nangle = 0.3\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"radau5\"\ntolerance = TOL\n[end]\nat = \"separation\"\n[outputs]\nwant = [\"separation_angle\"]\n";

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let rigid = rigid_separation_angle(0.3, 0.0);
    println!(
        "| tolerance | κ | steps | rejected | Jacobians | rhs | median ms | κ (θ_s − θ_rigid) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for tol in [1e-10, 1e-12] {
        let scene = parse("rigid.toml", &RIGID.replace("TOL", &format!("{tol:e}"))).unwrap();
        let mut times = Vec::new();
        let mut out = None;
        for _ in 0..5 {
            let t = Instant::now();
            out = Some(fall::run(&scene, fall::MAX_STEPS).unwrap());
            times.push(t.elapsed().as_secs_f64() * 1e3);
        }
        let w = out.unwrap().work.wall;
        println!(
            "| {tol:e} | rigid | {} | {} | {} | {} | {:.2} | – |",
            w.steps,
            w.rejected,
            w.jacobians,
            w.rhs_evals,
            median(times)
        );
        for e in [4, 6, 8, 10, 12] {
            let kappa = 10f64.powi(e);
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..5 {
                let t = Instant::now();
                let contact = Contact { kappa, gamma: 0.0 };
                let control = Control::Tolerance(tol);
                last = Some(separation(
                    contact,
                    Law::Switched,
                    0.3,
                    0.0,
                    "radau5",
                    control,
                    10_000_000,
                ));
                times.push(t.elapsed().as_secs_f64() * 1e3);
            }
            let r = last.unwrap();
            let s = r.stats;
            let shift = r.result.map_or(f64::NAN, |x| kappa * (x.angle - rigid));
            println!(
                "| {tol:e} | 1e{e} | {} | {} | {} | {} | {:.2} | {shift:.3} |",
                s.steps,
                s.rejected,
                s.jacobians,
                s.rhs_evals,
                median(times)
            );
        }
    }
}

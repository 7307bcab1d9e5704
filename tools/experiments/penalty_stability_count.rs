//! The stability count of `sim::scene::work::explicit_penalty_steps`: at loose tolerances an
//! explicit adaptive method on penalty springs takes steps at the edge of its stability region,
//! c ω t_s of them (ω = 2√κ + 4γ per √(l/g), t_s the separation time). This prints the
//! measured steps / (ω t_s) for dopri5 and dop853 from θ0 = 0.0106 and 0.3 (θ̇0 = 4e-5) at
//! τ = 1e-4 and 1e-6, κ = 1e6..1e11, γ = 0 and 10, and each method's largest, against which
//! the constants c in `scene::work` are set (about 11 s in release).
//!
//! Run: `cargo run --release --example penalty_stability_count`.

use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::penalty::run::separate_with;
use sliding_ladder::sim::penalty::{preloaded_start, Contact, Law, PenaltyModel};

fn main() {
    for method in ["dopri5", "dop853"] {
        let mut range = (f64::INFINITY, 0.0f64);
        for gamma in [0.0, 10.0] {
            for kappa in [1e6, 1e8, 1e10, 1e11] {
                for tol in [1e-4, 1e-6] {
                    for theta0 in [0.0106, 0.3] {
                        let contact = Contact { kappa, gamma };
                        let model = PenaltyModel::new(contact, Law::Switched);
                        let y0 = preloaded_start(&contact, theta0, 4e-5);
                        let Some(mut st) =
                            AnyStepper::new(method, Control::Tolerance(tol), 0.0, y0)
                        else {
                            continue;
                        };
                        let run = separate_with(&model, &mut st, 100_000_000);
                        let Ok(s) = run.result else {
                            println!("{method} γ = {gamma} κ = {kappa:e} τ = {tol:e} θ0 = {theta0}: failed");
                            continue;
                        };
                        let omega = 2.0 * kappa.sqrt() + 4.0 * gamma;
                        let c = run.stats.steps as f64 / (omega * s.time);
                        range = (range.0.min(c), range.1.max(c));
                        println!(
                            "{method} γ = {gamma} κ = {kappa:e} τ = {tol:e} θ0 = {theta0}: {} steps ({} rejected), steps / (ω t_s) = {c:.3}",
                            run.stats.steps, run.stats.rejected
                        );
                    }
                }
            }
        }
        println!(
            "{method}: steps / (ω t_s) from {:.3} to {:.3}",
            range.0, range.1
        );
    }
}

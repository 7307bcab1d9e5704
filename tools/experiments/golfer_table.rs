//! The figures of docs/golfers-nemesis.md: the golf ball of sec. B.10 (Milne sec. 421), solid
//! and hollow, held to its closed form at several tolerances (each run's deviation from the
//! closed form, the estimates d and d′ from the runs at rtol/100 and rtol/10⁴, the measured
//! periods), and the wrong versions of the model refused.
//! `cargo run --release --example golfer_table`.

use sliding_ladder::verify::claims::golfer::closed_form::ClosedForm;
use sliding_ladder::verify::claims::golfer::compare::READINGS;
use sliding_ladder::verify::claims::golfer::model::{Contact, Perturbation};
use sliding_ladder::verify::claims::golfer::{hold, Ball, Setup, HOLLOW, PERIODS, RTOL, SOLID};

fn main() {
    table();
    wrong_versions();
}

/// Each wrong version of sec. 4 of the docs: its largest deviation over its allowance, and where.
fn wrong_versions() {
    let golf = Setup::golf();
    let hollow = Setup {
        ball: Ball {
            k: HOLLOW,
            ..golf.ball
        },
        ..golf
    };
    let off = Setup {
        ball: Ball {
            k: SOLID * 1.01,
            ..golf.ball
        },
        ..golf
    };
    let rolling = (Contact::Rolling, Perturbation::None);
    let cases = [
        (
            "frictionless wall",
            golf,
            (Contact::Frictionless, Perturbation::None),
            SOLID,
        ),
        ("solid run, hollow ω_z", golf, rolling, HOLLOW),
        ("hollow run, solid ω_z", hollow, rolling, SOLID),
        (
            "ω × (a n) dropped",
            golf,
            (Contact::Rolling, Perturbation::SpinTermDropped),
            SOLID,
        ),
        (
            "ṅ dropped",
            golf,
            (Contact::Rolling, Perturbation::NormalFrozen),
            SOLID,
        ),
        ("k off by 1 %", off, rolling, SOLID),
    ];
    println!("wrong versions at rtol {RTOL:.0e} (deviation / allowance, per reading):");
    for (name, setup, run, k) in cases {
        let j = hold(&setup, run, k, RTOL, PERIODS).expect("integrates");
        let allowed = j.allowed();
        let ratios: Vec<String> = (0..READINGS.len())
            .map(|i| format!("{:.1e}", j.deviation[i] / allowed[i]))
            .collect();
        println!(
            "  {name:<24} agrees: {:<5} {}",
            j.agrees(),
            ratios.join(" ")
        );
    }
}

/// The golf ball, solid and hollow, at four tolerances.
fn table() {
    for (name, k) in [("solid", SOLID), ("hollow", HOLLOW)] {
        let golf = Setup::golf();
        let setup = Setup {
            ball: Ball { k, ..golf.ball },
            ..golf
        };
        let cf = ClosedForm::of(&setup, k);
        println!(
            "{name} ball: ω_z = {:.15} rad/s, 2π/ω_z = {:.15} s, lowest z = {:.9} m, ℓ = {:.6} m",
            cf.omega_z,
            cf.period(),
            cf.lowest(),
            setup.length()
        );
        for rtol in [1e-6, 1e-8, 1e-10, 1e-12] {
            let j = hold(
                &setup,
                (Contact::Rolling, Perturbation::None),
                k,
                rtol,
                PERIODS,
            )
            .expect("integrates");
            println!(
                "  rtol {rtol:.0e}: {} steps, agrees: {}",
                j.steps,
                j.agrees()
            );
            let allowed = j.allowed();
            for (i, r) in READINGS.iter().enumerate() {
                println!(
                    "    {r:<38} dev {:.2e}  d {:.2e}  dev/d {:.3}  d′ {:.2e}  d′/d {:.4}  allowed {:.2e}",
                    j.deviation[i],
                    j.estimate[i],
                    j.deviation[i] / j.estimate[i],
                    j.next_estimate[i],
                    j.next_estimate[i] / j.estimate[i],
                    allowed[i]
                );
            }
            let p: Vec<String> = j
                .readings
                .periods
                .iter()
                .map(|p| format!("{p:.13}"))
                .collect();
            println!("    periods measured: {}", p.join(" "));
        }
    }
}

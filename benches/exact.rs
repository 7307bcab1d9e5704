//! Cost of the exact phase-one solution: `PhaseOne::new` + `separation()` for several starts,
//! `separation()` alone, θ(t), t(θ); and, as a peer in the same run, the textbook separation
//! time F(ψ_s|m)/Ω from `ellip::ellipf` for a start from rest (which loses digits near the
//! separatrix, see src/sim/exact/mod.rs). Run: `cargo bench --features bench --bench exact`.
use criterion::{criterion_group, criterion_main, Criterion};
use sliding_ladder::sim::exact::PhaseOne;
use std::hint::black_box;

/// (label, θ₀, θ̇₀, Ω²)
const STARTS: [(&str, f64, f64, f64); 6] = [
    ("rest_0.3", 0.3, 0.0, 1.0),
    ("rest_1e-12", 1e-12, 0.0, 1.0),
    (
        "rest_near_flat",
        std::f64::consts::FRAC_PI_2 - 1e-6,
        0.0,
        1.0,
    ),
    ("upright_rate_1e-10", 0.0, 1e-10, 1.0),
    ("moving_0.3_0.5", 0.3, 0.5, 7.3575),
    ("near_immediate", 0.0, 0.999999, 1.0),
];

/// Textbook form for a start from rest: m = k² = 1 − sin²(θ₀/2), sin²ψ = (s² − k'²)/(k²s²).
fn textbook_separation_time(theta0: f64, big_omega2: f64) -> f64 {
    let kp2 = (0.5 * theta0).sin().powi(2);
    let m = 1.0 - kp2;
    let cos_s = 2.0 / 3.0 * theta0.cos();
    let s2 = 0.5 * (1.0 - cos_s);
    let psi = ((s2 - kp2) / (m * s2)).sqrt().asin();
    ellip::ellipf(psi, m).unwrap_or(f64::NAN) / big_omega2.sqrt()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("new_and_separation");
    for (label, theta0, rate0, big_omega2) in STARTS {
        g.bench_function(label, |b| {
            b.iter(|| {
                let p = PhaseOne::new(black_box(theta0), black_box(rate0), black_box(big_omega2));
                p.unwrap().separation()
            })
        });
    }
    g.finish();

    let mut g = c.benchmark_group("separation_only");
    for (label, theta0, rate0, big_omega2) in STARTS {
        let p = PhaseOne::new(theta0, rate0, big_omega2).unwrap();
        g.bench_function(label, |b| b.iter(|| black_box(&p).separation()));
    }
    g.finish();

    let mut g = c.benchmark_group("trajectory");
    for (label, theta0, rate0, big_omega2) in STARTS {
        let p = PhaseOne::new(theta0, rate0, big_omega2).unwrap();
        let s = p.separation().unwrap();
        let (t, theta) = (0.5 * s.time, 0.5 * (theta0 + s.angle));
        g.bench_function(format!("theta_rate/{label}"), |b| {
            b.iter(|| p.theta_rate(black_box(t)))
        });
        g.bench_function(format!("time_to_angle/{label}"), |b| {
            b.iter(|| p.time_to_angle(black_box(theta)))
        });
    }
    g.finish();

    let mut g = c.benchmark_group("peer_textbook_ellipf");
    g.bench_function("rest_0.3", |b| {
        b.iter(|| textbook_separation_time(black_box(0.3), black_box(1.0)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! The whole of `ladder verify` without printing: every display's checks (float states, exact
//! points, the print, the symbolic proofs), the docs, the methods and the floor-phase extension,
//! as `ladder verify` runs them (two worker threads), for the default configuration (1000 float
//! states, 3 exact points per check) and the target of issue 10 (10,000 float states, 100 exact
//! points; goal ≤ 10 s). Run: `cargo bench --features bench --bench verify_all` (about 10 runs of each; only the
//! target: `cargo bench --features bench --bench verify_all -- target`). `proofs_only` is every symbolic proof
//! (each check of the 95 displays and each printed form, one thread) without the sampled checks:
//! its median divided by 95 is the time per proof. The machine is shared: quote the median and
//! the load (`uptime`) it was measured under.
use criterion::{criterion_group, criterion_main, Criterion};
use sliding_ladder::registry::check::Config;
use sliding_ladder::verify;
use std::hint::black_box;
use std::time::Duration;

/// What `ladder verify` computes, without the printing; returns the number of equations judged.
fn verify_everything(cfg: &Config) -> usize {
    let results = verify::verify_all(cfg);
    let docs = sliding_ladder::docs::check_book(&sliding_ladder::docs::default_dir());
    let methods = verify::check_methods(cfg);
    let extensions = verify::verify_extensions(cfg);
    assert!(
        docs.problems.is_empty(),
        "docs problems: {:?}",
        docs.problems
    );
    assert!(methods.iter().all(|m| m.passed), "a method failed");
    let (_, _, _, failed) = verify::counts(&results);
    assert_eq!(failed, 0, "an equation failed");
    results.len() + extensions.len()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("verify_all");
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(1));
    g.measurement_time(Duration::from_secs(1));
    let default = Config::default();
    let target = Config {
        float_cases: 10_000,
        exact_points: 100,
        ..Config::default()
    };
    for (label, cfg) in [("default_1000_3", default), ("target_10000_100", target)] {
        g.bench_function(label, |b| b.iter(|| verify_everything(black_box(&cfg))));
    }
    let mut eqs = sliding_ladder::registry::equations();
    eqs.extend(sliding_ladder::registry::extensions());
    g.bench_function("proofs_only", |b| {
        b.iter(|| {
            eqs.iter()
                .filter(|e| verify::proof::prove_equation(black_box(e)).0.proved)
                .count()
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

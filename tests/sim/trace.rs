//! Tests of `sliding_ladder::sim::trace` (src/sim/trace.rs).

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::outcome::Sample;
use sliding_ladder::sim::rigid;
use sliding_ladder::sim::trace::{Kept, TRACE_CAP};

fn sample(phase: u8, t: f64) -> Sample {
    Sample {
        phase,
        t,
        theta: t,
        rate: 0.0,
        centre_x: 0.0,
        forces: None,
    }
}

fn kept(phases: &[(u8, usize)]) -> Vec<Sample> {
    let mut k = Kept::default();
    let mut t = 0.0;
    for &(p, n) in phases {
        for _ in 0..n {
            k.offer(sample(p, t));
            t += 1.0;
        }
    }
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    };
    k.finish(&ladder, false).0
}

/// Fewer than 2 TRACE_CAP offered: every one kept, in order.
#[test]
fn a_short_trace_keeps_every_sample() {
    let v = kept(&[(1, 700), (2, 300)]);
    assert_eq!(v.len(), 1000);
    assert!(v.windows(2).all(|w| w[1].t == w[0].t + 1.0));
}

/// 1e6 offered over two phases: between TRACE_CAP and 2 TRACE_CAP kept, evenly spaced (no
/// gap over twice the mean), with the first, the last and each phase's first sample. The
/// check can fail: without the thinning all 1e6 would be kept.
#[test]
fn a_long_trace_is_thinned_evenly_and_keeps_its_ends() {
    let (n1, n2) = (600_001, 399_999);
    let v = kept(&[(1, n1), (2, n2)]);
    assert!((TRACE_CAP..2 * TRACE_CAP).contains(&v.len()), "{}", v.len());
    assert_eq!(v[0].t, 0.0);
    assert_eq!(v[v.len() - 1].t, (n1 + n2 - 1) as f64);
    assert!(v.iter().any(|s| s.t == n1 as f64 && s.phase == 2));
    let mean = (n1 + n2) as f64 / v.len() as f64;
    let widest = v.windows(2).map(|w| w[1].t - w[0].t).fold(0.0, f64::max);
    assert!(
        widest <= 2.0 * mean,
        "gap {widest} against a mean of {mean}"
    );
    assert!(v.windows(2).all(|w| w[1].t > w[0].t));
}

/// The forces are evaluated for the kept samples only: two per sample.
#[test]
fn forces_are_evaluated_for_kept_samples_only() {
    let mut k = Kept::default();
    for i in 0..100_000 {
        k.offer(sample(1, 1e-6 * i as f64));
    }
    let ladder = Ladder {
        m: 2.0,
        l: 0.5,
        g: 9.81,
    };
    let (v, evals) = k.finish(&ladder, true);
    assert_eq!(evals, 2 * v.len() as u64);
    let s = v[v.len() / 2];
    let want = (
        rigid::wall_force(&ladder, s.theta, s.rate),
        rigid::floor_force(&ladder, s.theta, s.rate),
    );
    assert_eq!(s.forces, Some(want));
}

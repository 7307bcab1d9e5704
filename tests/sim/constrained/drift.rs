//! `constrained::drift` records, at each checkpoint c, the largest constraint value max(|x_C|,
//! |y_D|) over the step-end states with t ≤ c, once per checkpoint: also when a step ends
//! exactly on a checkpoint (`ladder stability`'s drift tables have one row per checkpoint).
//!
//! Steps of 1/8 at RK4 end exactly on multiples of 1/8 (sums of 1/8 are exact in binary and
//! the event-safety cap 0.5/(|θ̇| + Ω) stays above 1/8 while |θ̇| < 3.1, here |θ̇| < 1.3), so
//! checkpoints 0.5, 1 and 2 are hit by step ends and 0.3 and 1.3 lie inside steps. The
//! reference is the same run stepped here by hand, with the constraints written from their
//! definition g₁ = x − sin θ, g₂ = y − cos θ (sim/constrained.rs): the recorded values are
//! the same floating-point numbers, so they are compared exactly.

use sliding_ladder::sim::constrained::{self, Constrained};
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Stepper};

const H: f64 = 0.125;
const THETA0: f64 = 0.4;
const CHECKPOINTS: [f64; 5] = [0.3, 0.5, 1.0, 1.3, 2.0];

/// (t, max(|g₁|, |g₂|)) at every step end of the unstabilised rod, from the start.
fn step_ends(model: &Constrained) -> Vec<(f64, f64)> {
    let t_end = CHECKPOINTS[CHECKPOINTS.len() - 1];
    let y0 = constrained::start(THETA0, 0.0);
    let mut st = AnyStepper::new("rk4", Control::Fixed(H), 0.0, y0).unwrap();
    let g = |y: [f64; 6]| (y[0] - y[2].sin()).abs().max((y[1] - y[2].cos()).abs());
    let mut out = vec![(0.0, g(y0))];
    while st.t() < t_end {
        st.step(model, t_end).unwrap();
        out.push((st.t(), g(st.y())));
    }
    out
}

/// The largest value over the states with t ≤ c (`inclusive`) or t < c.
fn max_up_to(ends: &[(f64, f64)], c: f64, inclusive: bool) -> f64 {
    ends.iter()
        .filter(|(t, _)| if inclusive { *t <= c } else { *t < c })
        .map(|e| e.1)
        .fold(0.0, f64::max)
}

#[test]
fn every_checkpoint_is_recorded_once_with_the_largest_drift_up_to_it() {
    let model = Constrained {
        alpha: 0.0,
        beta: 0.0,
    };
    let ends = step_ends(&model);
    for c in [0.5, 1.0, 2.0] {
        assert!(ends.iter().any(|e| e.0 == c), "no step ends at {c}");
    }
    let d = constrained::drift(
        &model,
        THETA0,
        0.0,
        "rk4",
        Control::Fixed(H),
        &CHECKPOINTS,
        1000,
    );
    assert!(d.error.is_none(), "{:?}", d.error);
    let want: Vec<(f64, f64)> = CHECKPOINTS
        .iter()
        .map(|&c| (c, max_up_to(&ends, c, true)))
        .collect();
    assert_eq!(d.points, want);
    // The comparison can fail: leaving out the state that lies on a checkpoint changes a
    // recorded value (the drift grows with t), so an off-by-one step would be seen.
    let strict: Vec<(f64, f64)> = CHECKPOINTS
        .iter()
        .map(|&c| (c, max_up_to(&ends, c, false)))
        .collect();
    assert_ne!(d.points, strict);
}

//! The ball's motion in the cylinder (sec. B.10) integrated by the crate's DOP853
//! ([`crate::sim::integrators::dop853`], adaptive, dense output of order 7): every accepted
//! the state at given sample times and the lowest points (ż = 0 going up), both on the dense
//! output.

use super::model::Cylinder;
use crate::sim::integrators::dop853::Dop853;
use crate::sim::integrators::{StepError, Stepper};

/// Index of ż in the state (x, v, ω).
const RISE: usize = 5;

/// One integrated run.
#[derive(Clone, Debug)]
pub struct Trace {
    /// The state at each sample time.
    pub at_samples: Vec<[f64; 9]>,
    /// The lowest points: (t, z) where ż crosses zero upward.
    pub lows: Vec<(f64, f64)>,
    /// Accepted steps.
    pub steps: u64,
}

/// The root of ż in [t0, t1] on the last step's interpolant, by bisection (ż(t0) < 0 ≤ ż(t1))
/// down to adjacent floats: (t, z there).
fn low_in_step(stepper: &Dop853<9>, t0: f64, t1: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (t0, t1);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if stepper.interpolate(mid)[RISE] < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let t = 0.5 * (lo + hi);
    (t, stepper.interpolate(t)[2])
}

/// Integrate `model` from `y0` at t = 0 with relative tolerance `rtol`, reading the state at
/// the increasing `samples` (on the dense output, so that they do not set the steps) and
/// ending steps exactly on every `stop_every`-th sample; the last sample ends the run.
pub fn integrate(
    model: &Cylinder,
    y0: [f64; 9],
    rtol: f64,
    samples: &[f64],
    stop_every: usize,
) -> Result<Trace, StepError> {
    let mut stepper = Dop853::new(0.0, y0, rtol);
    let mut trace = Trace {
        at_samples: Vec::with_capacity(samples.len()),
        lows: Vec::new(),
        steps: 0,
    };
    for stop in samples.chunks(stop_every).filter_map(|c| c.last()) {
        while stepper.t() < *stop {
            let (t0, before) = (stepper.t(), stepper.y()[RISE]);
            stepper.step(model, *stop)?;
            let (t1, y1) = (stepper.t(), stepper.y());
            stepper.prepare_dense(model);
            if before < 0.0 && y1[RISE] >= 0.0 {
                trace.lows.push(low_in_step(&stepper, t0, t1));
            }
            let due = samples[trace.at_samples.len()..]
                .iter()
                .take_while(|s| **s <= t1);
            let read: Vec<_> = due
                .map(|&s| if s == t1 { y1 } else { stepper.interpolate(s) })
                .collect();
            trace.at_samples.extend(read);
        }
    }
    trace.steps = stepper.stats().steps;
    Ok(trace)
}

//! `sim::integrators`: every method against known solutions, its step rules and counters.

mod adaptive;
mod any;
mod card;
mod convergence;
mod dense_lu;
mod dopri5;
mod error_norm;
mod fixed;
mod overflow;
mod radau5;
mod rhs_counts;
mod step_time;
mod taylor;
mod taylor_poly;
mod unit_free_steps;
mod verlet;

use sliding_ladder::sim::integrators::rms;

/// The error norm is Hairer's √(Σ r²/N) (*Solving ODEs I*, eq. (4.11)): the mean of the
/// squares, so a state whose every component is off by its tolerance scores exactly 1. The
/// scaled branch (squares that overflow) gives the same mean. Mutation testing: `sum / N` →
/// `sum · N` went unseen; every step was still held to a norm below 1, just N times stricter.
#[test]
fn the_error_norm_is_the_root_mean_square() {
    assert_eq!(rms(&[1.0; 6]), 1.0);
    assert_eq!(rms(&[3.0, 4.0]), 12.5f64.sqrt());
    assert_eq!(rms(&[0.0, 0.0, 0.0, 2.0]), 1.0);
    // Squares above f64::MAX: scaled by the largest, to a few ulps of the same mean.
    let big = rms(&[3e300, 4e300]);
    let want = 12.5f64.sqrt() * 1e300;
    assert!((big - want).abs() <= 4.0 * f64::EPSILON * want, "{big:e}");
    assert!(rms(&[f64::NAN, 1.0]).is_nan());
    assert_eq!(rms(&[f64::INFINITY, 1.0]), f64::INFINITY);
}

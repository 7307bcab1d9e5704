//! The defaults of `sim::event::Event`: an event that forms no polynomial of its own from a
//! Taylor step's series says so (`on_series` → None), and the run then refines its root on
//! the step's interpolant. A default that answered a made-up value would steer that root
//! (mutation testing: the default → Some((0, 0)) and Some((0, 1)) went unseen: every event of
//! the ladder that meets a Taylor step overrides it, and the lift-off event never fires).

use sliding_ladder::sim::event::{Direction, Event};
use sliding_ladder::sim::integrators::taylor_poly::Series;

/// A value that crosses zero once: y − 1.
struct Threshold;

impl Event<2> for Threshold {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        y[0] - 1.0
    }
    fn direction(&self) -> Direction {
        Direction::Rising
    }
}

#[test]
fn an_event_without_a_polynomial_of_its_own_says_so() {
    let series = Series::<2>::new(8);
    for tau in [0.0, 0.25, 1.0] {
        assert_eq!(Threshold.on_series(&series, tau), None, "τ = {tau}");
    }
}

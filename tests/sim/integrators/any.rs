//! `AnyStepper` (the stepper a scene's method name builds) hands on what its method has: the
//! Taylor method's series of the last step, from which the separation and flat events form
//! their own polynomials, and its carried (sin θ, cos θ). A dispatch that dropped them would
//! leave every result right to its tolerance (the events fall back to the step's interpolant),
//! so only a direct comparison sees it (mutation testing: `step_series` → None went unseen).

use sliding_ladder::sim::integrators::taylor::Taylor;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
#[test]
fn a_taylor_any_stepper_hands_on_its_series_and_trig_and_others_have_none() {
    let sys = WallPhase::new(&Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    });
    let (t0, y0, tol) = (0.0, [0.3, 0.1], 1e-12);
    let mut own = Taylor::new(t0, y0, tol);
    let mut any = AnyStepper::new("taylor", Control::Tolerance(tol), t0, y0).unwrap();
    for _ in 0..3 {
        own.step(&sys, 10.0).unwrap();
        any.step(&sys, 10.0).unwrap();
        let (a, b) = (
            any.step_series().expect("a Taylor step"),
            own.step_series().unwrap(),
        );
        assert_eq!((a.order, a.y, a.sin, a.cos), (b.order, b.y, b.sin, b.cos));
        assert_eq!(any.trig(), own.trig());
        assert!(any.trig().is_some());
    }
    let mut dop = AnyStepper::new("dop853", Control::Tolerance(tol), t0, y0).unwrap();
    dop.step(&sys, 10.0).unwrap();
    assert!(dop.step_series().is_none() && dop.trig().is_none());
}

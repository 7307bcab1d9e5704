//! A fixed step is taken as given and only the step that would pass the stop is cut to land on
//! it: from t = 5 with h = 2 towards 8 the steps end at 7 and 8. (Mutation testing: the test
//! for the last step, t + h ≥ t_stop → t · h ≥ t_stop, went unseen: the ladder's systems cap
//! the step below 1, where t · h < t < t_stop; a system without a cap takes longer steps.)

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, StepError, Stepper};

/// ẏ = 1, no step cap.
struct Clock;

impl Ode<1> for Clock {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + 1.0]
    }
}

#[test]
fn a_fixed_step_is_cut_only_to_land_on_the_stop() {
    // From 3 with h = 2 towards 6, t h = t_stop at the first step (mutation testing: the
    // landing test `t + h == t_stop` → `t · h == t_stop` jumped from 3 to 6 there).
    for (t0, t_stop, ends_want) in [(5.0, 8.0, [7.0, 8.0]), (3.0, 6.0, [5.0, 6.0])] {
        for method in ["euler", "rk4"] {
            let mut st = AnyStepper::new(method, Control::Fixed(2.0), t0, [t0]).unwrap();
            let mut ends = Vec::new();
            while st.t() < t_stop {
                st.step(&Clock, t_stop).unwrap();
                ends.push(st.t());
            }
            assert_eq!(ends, ends_want, "{method} from {t0}");
            assert_eq!(st.y(), [t_stop], "{method} from {t0}");
        }
    }
}

/// A fixed step below the rounding of t (4 ulps of t) cannot advance t and is refused with
/// StepTooSmall: h = 1 at t = 1e20, where t + 1 = t. (Mutation testing: the floor
/// 4 u max(|t|, 1) → 4 u / max(|t|, 1), the same for t ≤ 1, went unseen; it took the step and
/// left t where it was, so a run would loop to its step limit.)
#[test]
fn a_fixed_step_below_the_rounding_of_t_is_refused() {
    for method in ["euler", "rk4"] {
        let mut st = AnyStepper::new(method, Control::Fixed(1.0), 1e20, [0.0]).unwrap();
        let r = st.step(&Clock, 2e20);
        assert!(
            matches!(r, Err(StepError::StepTooSmall { t, h }) if t == 1e20 && h == 1.0),
            "{method}: {r:?}"
        );
        // 2^16 at 2^66 (1 ulp = 2^14) is 4 ulps: refused; 2^17 is taken.
        let mut st =
            AnyStepper::new(method, Control::Fixed(2f64.powi(16)), 2f64.powi(66), [0.0]).unwrap();
        assert!(st.step(&Clock, 2f64.powi(67)).is_err(), "{method}");
        let mut st =
            AnyStepper::new(method, Control::Fixed(2f64.powi(17)), 2f64.powi(66), [0.0]).unwrap();
        st.step(&Clock, 2f64.powi(67)).unwrap();
        assert_eq!(st.t(), 2f64.powi(66) + 2f64.powi(17), "{method}");
    }
}

/// The last step is cut to t_stop − t and lands on t_stop exactly, even where t + (t_stop − t)
/// rounds past it: from 0.7 towards 2.9 with h = 5 the step is 2.1999999999999997 and
/// 0.7 + 2.1999999999999997 = 2.9000000000000004. (Mutation testing: the landing test
/// `t + h == t_stop || h == t_stop − t` → `&&` went unseen: the run ended an ulp past its stop.)
#[test]
fn the_last_step_lands_on_the_stop_exactly() {
    assert_ne!(0.7 + (2.9 - 0.7), 2.9, "the case rounds past");
    for method in ["euler", "rk4"] {
        let mut st = AnyStepper::new(method, Control::Fixed(5.0), 0.7, [0.0]).unwrap();
        st.step(&Clock, 2.9).unwrap();
        assert_eq!(st.t(), 2.9, "{method}");
    }
}

/// The Taylor method's last step takes in a sliver: a step that would end within 1e-8 of
/// itself short of the stop is stretched to land on the stop, not followed by a step of a few
/// ulps. Here the stop lies 2 ulps past where the step would end; a second step of 2 ulps
/// (below 10 ε t, the rounding of t) would be refused with StepTooSmall, and one of 1e-9 h
/// would cost a whole series for nothing. (Mutation testing: the rule
/// `t + h ≥ t_stop || t_stop − (t + h) ≤ 1e-8 h` → `&&`, which drops the sliver, went unseen.)
#[test]
fn a_taylor_step_takes_in_a_sliver_before_the_stop() {
    use sliding_ladder::sim::integrators::taylor::Taylor;
    use sliding_ladder::sim::rigid::WallPhase;

    use sliding_ladder::ladder::Ladder;
    let sys = WallPhase::new(&Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    });
    let (t0, y0, tol) = (0.5, [0.3, 0.1], 1e-12);
    // The step the method takes from this state towards a far stop.
    let mut free = Taylor::new(t0, y0, tol);
    free.step(&sys, 100.0).unwrap();
    let end = free.t();
    assert!(end > t0 && end < 100.0);
    let h = end - t0;
    let two_ulps = f64::from_bits(end.to_bits() + 2);
    for t_stop in [two_ulps, end + 1e-9 * h] {
        let mut st = Taylor::new(t0, y0, tol);
        st.step(&sys, t_stop).unwrap();
        assert_eq!(st.t(), t_stop, "one step lands on the stop {t_stop}");
        assert_eq!(st.stats().steps, 1);
    }
}

/// The Taylor method refuses a step below the rounding of t (10 ε |t|), as the fixed steps
/// above do: on the ladder's wall phase its steps are capped below 1 √(l/g), so at t = 1e20
/// (an ulp is 16384) the step could not move t and is refused with StepTooSmall. (Mutation
/// testing: the refusal `h ≤ 10 ε |t| || h ≤ 0` → `&&` went unseen; it took the step and left
/// t at 1e20.)
#[test]
fn a_taylor_step_below_the_rounding_of_t_is_refused() {
    use sliding_ladder::sim::integrators::taylor::Taylor;
    use sliding_ladder::sim::rigid::WallPhase;

    use sliding_ladder::ladder::Ladder;
    let sys = WallPhase::new(&Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    });
    let mut st = Taylor::new(1e20, [0.3, 0.1], 1e-12);
    let r = st.step(&sys, 2e20);
    assert!(
        matches!(r, Err(StepError::StepTooSmall { t, h }) if t == 1e20 && h > 0.0),
        "{r:?}"
    );
    // The same state at t = 0 steps.
    let mut st = Taylor::new(0.0, [0.3, 0.1], 1e-12);
    st.step(&sys, 2e20).unwrap();
    assert!(st.t() > 0.0);
}

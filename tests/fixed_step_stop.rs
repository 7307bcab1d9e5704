//! A fixed step is taken as given and only the step that would pass the stop is cut to land on
//! it: from t = 5 with h = 2 towards 8 the steps end at 7 and 8. (Mutation testing: the test
//! for the last step, t + h ≥ t_stop → t · h ≥ t_stop, went unseen: the ladder's systems cap
//! the step below 1, where t · h < t < t_stop; a system without a cap takes longer steps.)

use num_dual::DualNum;
use sliding_ladder::sim::integrators::any::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};

/// ẏ = 1, no step cap.
struct Clock;

impl Ode<1> for Clock {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + 1.0]
    }
}

#[test]
fn a_fixed_step_is_cut_only_to_land_on_the_stop() {
    for method in ["euler", "rk4"] {
        let mut st = AnyStepper::new(method, Control::Fixed(2.0), 5.0, [5.0]).unwrap();
        let mut ends = Vec::new();
        while st.t() < 8.0 {
            st.step(&Clock, 8.0).unwrap();
            ends.push(st.t());
        }
        assert_eq!(ends, [7.0, 8.0], "{method}");
    }
}

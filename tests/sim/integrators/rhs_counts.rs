//! Every method counts its right-hand sides (`Stats::rhs_evals`, what work-precision reports
//! as the cost of a run) as the system sees them: a system that counts its own evaluations
//! must agree with the stepper's statistics exactly. Evaluations on dual numbers (radau5's
//! Jacobian by automatic differentiation) are counted as Jacobians, not here.
//! (Mutation testing: `rhs_evals += 1` → `*= 1` in the adaptive methods' first slope went
//! unseen; only Verlet's count had such a test, `tests/sim/integrators/verlet/step.rs`.)

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};
use std::cell::Cell;

/// ẏ = cos t − (y − sin t) (y = sin t from 0), counting its evaluations on f64.
struct Counted(Cell<u64>);

impl Ode<1> for Counted {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        if D::NDERIV == 0 {
            self.0.set(self.0.get() + 1);
        }
        [-y[0] + t.cos() + t.sin()]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

#[test]
fn each_method_counts_every_right_hand_side_it_evaluates() {
    let runs = [
        ("euler", Control::Fixed(0.01)),
        ("rk4", Control::Fixed(0.1)),
        ("dopri5", Control::Tolerance(1e-9)),
        ("dop853", Control::Tolerance(1e-9)),
        ("radau5", Control::Tolerance(1e-9)),
    ];
    for (method, control) in runs {
        let sys = Counted(Cell::new(0));
        let mut st = AnyStepper::new(method, control, 0.0, [0.0]).unwrap();
        while st.t() < 3.0 {
            st.step(&sys, 3.0).unwrap();
        }
        assert!(sys.0.get() > 0, "{method}");
        assert_eq!(st.stats().rhs_evals, sys.0.get(), "{method}");
    }
}

/// The wall phase's acceleration does not depend on the rate (θ̈ = Ω² sin θ, in θ and in the
/// complement), and its models say so (`Ode::accel_uses_velocity`), so Verlet's last kick is
/// explicit and reuses the slope at the new state: one evaluation a step, plus the first
/// slope. (Mutation testing: `ComplementWall::accel_uses_velocity` → true went unseen: the
/// implicit kick's iteration gives the same state at twice the cost or more.)
#[test]
fn verlet_evaluates_the_wall_phase_once_a_step() {
    use sliding_ladder::sim::complement::ComplementWall;
    use sliding_ladder::sim::rigid::WallPhase;

    use sliding_ladder::ladder::Ladder;
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    };
    fn count<S: Ode<2>>(sys: &S, y0: [f64; 2]) -> (u64, u64) {
        let mut st = AnyStepper::new("verlet", Control::Fixed(0.01), 0.0, y0).unwrap();
        while st.t() < 1.0 {
            st.step(sys, 1.0).unwrap();
        }
        (st.stats().steps, st.stats().rhs_evals)
    }
    let (steps, evals) = count(&WallPhase::new(&ladder), [0.3, 0.0]);
    assert_eq!(evals, steps + 1, "wall phase in θ");
    let (steps, evals) = count(&ComplementWall::new(&ladder), [1.2, 0.0]);
    assert_eq!(evals, steps + 1, "wall phase in the complement");
}

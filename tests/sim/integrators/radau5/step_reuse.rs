//! radau5 keeps its step size while Newton contracts fast and the controller would grow the
//! step by less than 20 % (Hairer & Wanner II, sec. IV.8; radau5.f's QUOT1 = 1, QUOT2 = 1.2), so
//! the LU factors of the step's linear systems are reused instead of formed again. On a linear
//! system with its exact Jacobian the first Newton iterate is exact and the contraction is
//! rounding, so the rule applies at every step whose proposal grows by 0-20 %: such steps repeat
//! the last size exactly, and most steps do; and the Jacobian, formed once at the start, is
//! kept for the whole run. (Mutation testing: the proposal's ratio h_new/h → h_new % h went
//! unseen; it is never in [1, 1.2] for h < 1, so every step took a new size and new factors.
//! So did `!keep_jac` → `keep_jac`, which dropped the Jacobian exactly when Newton contracted.)

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};

/// ẏ = −y: linear, so Newton's first iterate solves each step's system exactly.
struct Decay;

impl Ode<1> for Decay {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [-y[0]]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

#[test]
fn radau5_keeps_its_step_size_while_the_proposal_grows_by_less_than_a_fifth() {
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 0.0, [1.0]).unwrap();
    let mut sizes = Vec::new();
    while st.t() < 10.0 {
        let t0 = st.t();
        st.step(&Decay, 10.0).unwrap();
        sizes.push(st.t() - t0);
    }
    // A size read as a difference of times carries their rounding: 2 ulps of t ≤ 10.
    let rounding = 2.0 * f64::EPSILON * 16.0;
    let repeats = sizes
        .windows(2)
        .filter(|w| (w[1] - w[0]).abs() <= rounding)
        .count();
    assert_eq!(st.stats().jacobians, 1, "{:?}", st.stats());
    // Measured: 103 of 117 (the first steps grow by more); with the mutant 0.
    assert!(
        2 * repeats >= sizes.len(),
        "{repeats} of {} steps repeat the last size",
        sizes.len()
    );
}

/// ẏ = −y until t = 1, then ẏ = −1000 y: a step across t = 1 sees a stiffness 1000 times
/// larger than the one its size was chosen for (λ h in the hundreds), so its error estimate
/// is far above the tolerance and the step must be rejected and retried shorter.
struct Stiffens;

impl Ode<1> for Stiffens {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * if t < 1.0 { -1.0 } else { -1000.0 }]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

/// A rejected step is counted (the statistics work-precision reports; mutation testing:
/// `rejected += 1` → `*= 1` went unseen: no test looked for a rejection by radau5).
#[test]
fn radau5_counts_the_step_it_rejects_where_the_system_stiffens() {
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 0.0, [1.0]).unwrap();
    let mut before = None;
    while st.t() < 2.0 {
        if st.t() < 1.0 {
            before = Some(st.stats().rejected);
        }
        st.step(&Stiffens, 2.0).unwrap();
    }
    let before = before.unwrap();
    assert!(st.stats().rejected > before, "{:?}", st.stats());
}

/// Van der Pol's oscillator, ẍ = μ((1 − x²) ẋ − x), stiff for large μ; records the points
/// (t, y) at which its Jacobian is formed (its evaluations on dual numbers).
struct VanDerPol {
    mu: f64,
    jacobian_points: std::cell::RefCell<std::collections::HashSet<[u64; 3]>>,
}

impl Ode<2> for VanDerPol {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 2]) -> [D; 2] {
        if D::NDERIV > 0 {
            let point = [t.to_bits(), y[0].re().to_bits(), y[1].re().to_bits()];
            self.jacobian_points.borrow_mut().insert(point);
        }
        [y[1], (y[1] * (-y[0] * y[0] + 1.0) - y[0]) * self.mu]
    }
    fn scale(&self, _y: &[f64; 2]) -> [f64; 2] {
        [1.0, 1.0]
    }
}

/// After a rejected step radau5 forms a new Jacobian only when the one it holds is old (formed
/// at an earlier step): one formed at this step's start is already the best it can have, so no
/// Jacobian is ever formed twice at the same point. On Van der Pol (μ = 1000, 2 s, τ = 1e-4:
/// 69 rejections) the distinct points equal the count (measured: 185). (Mutation testing: with
/// the `!` of `if !self.jac_fresh` deleted it re-formed the fresh one and kept the old one: 230
/// Jacobians for the same 386 steps, harmless to results but waste.)
#[test]
fn radau5_never_forms_a_jacobian_twice_at_one_point() {
    let sys = VanDerPol {
        mu: 1000.0,
        jacobian_points: Default::default(),
    };
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-4), 0.0, [2.0, 0.0]).unwrap();
    while st.t() < 2.0 {
        st.step(&sys, 2.0).unwrap();
    }
    assert!(st.stats().rejected > 0, "{:?}", st.stats());
    let distinct = sys.jacobian_points.borrow().len() as u64;
    assert_eq!(st.stats().jacobians, distinct, "{:?}", st.stats());
}

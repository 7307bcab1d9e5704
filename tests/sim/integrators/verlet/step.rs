//! One Störmer-Verlet step on a velocity-free acceleration with two degrees of freedom, against
//! the method written out here: v½ = v0 + h/2 a(q0), q1 = q0 + h v½, v1 = v½ + h/2 a(q1).
//! The order fit of `tests/sim/integrators/convergence.rs` has one degree of freedom and the velocity-
//! dependent path of `tests/sim/integrators/verlet/velocity_dependent.rs` iterates the last kick to its fixed
//! point, so a last kick that read the wrong component's acceleration (mutation testing:
//! `f1[d + i]` → `f1[d − i]`, the same index for d = 1) was seen by neither. The step does the
//! same roundings as the formula: 2 ulps allowed.

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};

/// Two oscillators, ẍ = −x and ÿ = −4y: the accelerations differ, and neither uses a velocity.
struct Oscillators;

impl Ode<4> for Oscillators {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 4]) -> [D; 4] {
        [y[2], y[3], -y[0], y[1] * -4.0]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
}

fn accel(q: [f64; 2]) -> [f64; 2] {
    [-q[0], -4.0 * q[1]]
}

#[test]
fn a_verlet_step_kicks_each_velocity_with_its_own_acceleration() {
    let (h, y0) = (0.1, [0.3, -0.2, 0.7, 0.4]);
    let mut st = AnyStepper::new("verlet", Control::Fixed(h), 0.0, y0).unwrap();
    st.step(&Oscillators, 1.0).unwrap();
    let a0 = accel([y0[0], y0[1]]);
    let half = [y0[2] + 0.5 * h * a0[0], y0[3] + 0.5 * h * a0[1]];
    let q1 = [y0[0] + h * half[0], y0[1] + h * half[1]];
    let a1 = accel(q1);
    let want = [
        q1[0],
        q1[1],
        half[0] + 0.5 * h * a1[0],
        half[1] + 0.5 * h * a1[1],
    ];
    let got = st.y();
    for i in 0..4 {
        assert!(
            (got[i] - want[i]).abs() <= 2.0 * f64::EPSILON * want[i].abs(),
            "y{i}: {} against {}",
            got[i],
            want[i]
        );
    }
}

/// ẍ = −c ẋ + cos t: the acceleration uses the velocity and the time, so the last kick is
/// implicit, v1 = v½ + h/2 (−c v1 + cos(t + h)), and linear in v1: v1 = (v½ + h/2 cos(t + h)) /
/// (1 + c h/2), written out here. The fixed-point iteration stops at a change within 4 ulps:
/// 8 ulps allowed. (Mutation testing: the iteration's time `t + h` → `t · h` and `t − h` went
/// unseen: the other velocity-dependent test is autonomous.)
/// It counts its evaluations, which the step's statistics must match (the implicit kick's
/// iterations included: `*evals += 1` → `*evals *= 1` there went unseen).
/// The drive has an amplitude A (ẍ = −c ẋ + A cos t): the iteration's stop is relative, so a
/// motion scaled by a power of two takes the same iterations and the same bits, scaled
/// (mutation testing: the change `|Δv| / |v|` → `|Δv| % |v|`, an absolute change below 1,
/// went unseen at A = 1).
struct Driven(std::cell::Cell<u64>, f64);

const C: f64 = 0.8;

impl Ode<2> for Driven {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 2]) -> [D; 2] {
        self.0.set(self.0.get() + 1);
        [y[1], y[1] * -C + self.1 * t.cos()]
    }
}

#[test]
fn a_verlet_step_solves_its_implicit_kick_at_the_step_s_end_time() {
    let mut evals = Vec::new();
    for amplitude in [1.0, 2f64.powi(-40), 2f64.powi(40)] {
        let (t0, h, y0) = (0.7, 0.1, [0.3 * amplitude, -0.4 * amplitude]);
        let mut st = AnyStepper::new("verlet", Control::Fixed(h), t0, y0).unwrap();
        let sys = Driven(std::cell::Cell::new(0), amplitude);
        st.step(&sys, 2.0).unwrap();
        assert_eq!(st.stats().rhs_evals, sys.0.get(), "evaluations counted");
        assert!(sys.0.get() >= 3, "the implicit kick iterates");
        evals.push(sys.0.get());
        let half = y0[1] + 0.5 * h * (-C * y0[1] + amplitude * t0.cos());
        let q1 = y0[0] + h * half;
        let v1 = (half + 0.5 * h * amplitude * (t0 + h).cos()) / (1.0 + 0.5 * C * h);
        let got = st.y();
        assert!(
            (got[0] - q1).abs() <= 2.0 * f64::EPSILON * q1.abs(),
            "A = {amplitude:e}: {got:?}"
        );
        assert!(
            (got[1] - v1).abs() <= 8.0 * f64::EPSILON * v1.abs(),
            "A = {amplitude:e}: {got:?} against {v1}"
        );
    }
    assert!(evals.iter().all(|&n| n == evals[0]), "{evals:?}");
    // The fixed-point iteration contracts by q = h c/2 = 0.04 an iteration, so its change
    // falls below the stop's 4 u after ln(4u)/ln q = 10.8 iterations: with the first slope and
    // up to two more (the change lags the error by one), at most 14 evaluations (measured: 13;
    // mutation testing: the change |v − v_old| → |v + v_old|, which never stops, took 51).
    let q: f64 = 0.5 * 0.1 * C;
    let most = 1 + ((4.0 * f64::EPSILON).ln() / q.ln()).ceil() as u64 + 2;
    assert!(evals[0] <= most, "{evals:?}, at most {most}");
}

/// Two damped velocities, ẍ = −c ẋ and ÿ = −c ẏ: the implicit kick's stop compares each new
/// velocity with its own previous value, so with two degrees of freedom it stops as with one,
/// after the evaluations the contraction h c/2 predicts (mutation testing: `y1[d + i]` →
/// `y1[d − i]` in the change, the same index for one degree of freedom, compared the second
/// velocity with a position and never stopped: 51 evaluations).
struct Damped;

impl Ode<4> for Damped {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 4]) -> [D; 4] {
        [y[2], y[3], y[2] * -C, y[3] * -C]
    }
}

#[test]
fn a_verlet_step_with_two_damped_velocities_stops_its_kick_in_time() {
    let h = 0.1;
    let mut st = AnyStepper::new("verlet", Control::Fixed(h), 0.0, [0.3, -0.2, 0.7, 0.4]).unwrap();
    st.step(&Damped, 1.0).unwrap();
    let q: f64 = 0.5 * h * C;
    let most = 1 + ((4.0 * f64::EPSILON).ln() / q.ln()).ceil() as u64 + 2;
    assert!(
        st.stats().rhs_evals <= most,
        "{:?}, at most {most}",
        st.stats()
    );
    // Each velocity solves its own linear kick, v1 = v½/(1 + c h/2), v½ = v0 (1 − c h/2).
    for (i, v0) in [(2, 0.7), (3, 0.4)] {
        let v1 = v0 * (1.0 - q) / (1.0 + q);
        assert!(
            (st.y()[i] - v1).abs() <= 8.0 * f64::EPSILON * v1.abs(),
            "{:?}",
            st.y()
        );
    }
}

/// A velocity-free acceleration of time, ẍ = cos t: the last kick takes a(q1, t0 + h), as in
/// the formula above. (Mutation testing: that slope's time `t + h` → `t − h` went unseen:
/// the velocity-free systems here do not depend on t, and the driven one iterates its kick
/// from a fresh slope at t0 + h.) The same roundings as the formula: 2 ulps.
struct Forced;

impl Ode<2> for Forced {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 2]) -> [D; 2] {
        [y[1], y[0] * 0.0 + t.cos()]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
}

#[test]
fn a_verlet_step_kicks_with_the_acceleration_at_the_step_s_end() {
    let (t0, h, y0) = (0.7, 0.1, [0.3, -0.4]);
    let mut st = AnyStepper::new("verlet", Control::Fixed(h), t0, y0).unwrap();
    st.step(&Forced, 2.0).unwrap();
    let half = y0[1] + 0.5 * h * t0.cos();
    let q1 = y0[0] + h * half;
    let v1 = half + 0.5 * h * (t0 + h).cos();
    let got = st.y();
    assert!(
        (got[0] - q1).abs() <= 2.0 * f64::EPSILON * q1.abs(),
        "{got:?}"
    );
    assert!(
        (got[1] - v1).abs() <= 2.0 * f64::EPSILON * v1.abs(),
        "{got:?} against {v1}"
    );
}

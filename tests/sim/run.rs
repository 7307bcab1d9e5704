//! `sim::run::integrate_phase` on toy systems (mutation testing of `src/sim` found these gaps):
//! a phase ends at the earliest of its events when several cross within one step (the list
//! order must not matter), a system that sets no step limit (`Ode::max_step`'s default) lets an
//! adaptive method take steps as long as its error allows, and the explicit methods' stage
//! times are right (the ladder's systems do not depend on t, so only a system that does sees
//! them), a Taylor step's event rate is a time derivative, and radau5 gives up when Newton
//! cannot converge at any usable step.

use num_dual::DualNum;
use sliding_ladder::sim::event::{Direction, Event};
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};
use sliding_ladder::sim::run::{integrate_phase, Observer};

/// ẏ = 1: y = t.
struct Clock;

impl Ode<1> for Clock {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + 1.0]
    }
}

/// y rises through `self.0`.
struct Reaches(f64);

impl Event<1> for Reaches {
    fn value(&self, _t: f64, y: &[f64; 1]) -> f64 {
        y[0] - self.0
    }
    fn direction(&self) -> Direction {
        Direction::Rising
    }
}

#[test]
fn two_events_in_one_step_end_the_phase_at_the_earlier() {
    let (late, early) = (Reaches(0.7), Reaches(0.3));
    for (events, index) in [([&late as &dyn Event<1>, &early], 1), ([&early, &late], 0)] {
        // One step of 1 covers both crossings.
        let mut stepper = AnyStepper::new("rk4", Control::Fixed(1.0), 0.0, [0.0]).unwrap();
        let end = integrate_phase(&Clock, &mut stepper, &events, 10.0, 100, &mut ()).unwrap();
        assert_eq!(end.event, Some(index));
        assert!((end.t - 0.3).abs() <= 4.0 * f64::EPSILON, "{}", end.t);
    }
}

/// (y − 1)(y − 2): falls through zero at y = 1 and rises again at y = 2, so a step across both
/// ends on the same sign; only samples inside the step see the dip (as the floor force's lift-off
/// is watched: it could dip and recover within one step).
struct Dips;

impl Event<1> for Dips {
    fn value(&self, _t: f64, y: &[f64; 1]) -> f64 {
        (y[0] - 1.0) * (y[0] - 2.0)
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    fn interior_samples(&self) -> usize {
        3
    }
}

/// An event with interior samples is found inside a step whose ends show no crossing: one rk4
/// step of 3 on y = t (its dense output is exact on a line) samples 0.75, 1.5, 2.25 and brackets
/// the root 1 between the first two (mutation testing: `k > 0` → `k < 0`, never sampling, went
/// unseen: the rigid floor phase never lifts off). Brent's method finds it to 4 ulps.
#[test]
fn an_event_that_dips_within_one_step_is_found_by_its_interior_samples() {
    let mut stepper = AnyStepper::new("rk4", Control::Fixed(3.0), 0.0, [0.0]).unwrap();
    let events = [&Dips as &dyn Event<1>];
    let end = integrate_phase(&Clock, &mut stepper, &events, 10.0, 100, &mut ()).unwrap();
    assert_eq!(end.event, Some(0));
    assert!((end.t - 1.0).abs() <= 4.0 * f64::EPSILON, "{}", end.t);
}

/// dopri5 is exact on ẏ = 1 (from y = 1: the default error scale is |y|), so its steps grow by its largest factor each time (10): from
/// t = 0 to 1e6 that is a few dozen steps, where any finite default limit L would need 1e6/L.
#[test]
fn a_system_without_a_step_limit_is_not_limited() {
    let mut stepper = AnyStepper::new("dopri5", Control::Tolerance(1e-10), 0.0, [1.0]).unwrap();
    let never = Reaches(2e6);
    let events = [&never as &dyn Event<1>];
    let end = integrate_phase(&Clock, &mut stepper, &events, 1e6, 1000, &mut ()).unwrap();
    assert_eq!(end.event, None);
    assert_eq!(end.t, 1e6);
    assert!(
        stepper.stats().steps < 100,
        "{} steps",
        stepper.stats().steps
    );
}

/// ẏ = cos t − (y − sin t), whose motion is y = sin t: the right-hand side depends on t, which
/// none of the ladder's systems does, so the stage times of the explicit methods are seen only
/// here. It depends on y too (contracting, so errors are not amplified): a stage whose slope
/// enters the step only through later stages' states (dopri5's second, b2 = e2 = 0) changes the
/// step only through y (mutation testing: its time `t + c2 h` → `t + c2/h` went unseen with
/// ẏ = cos t). Each adaptive method (and its dense output, sampled inside every step) follows
/// y = sin t within its error model 10 N τ, in at most 10/τ^(1/(p+1)) steps, the count an
/// error constant of 1 gives for a method of order p (a wrong stage lowers the order).
struct Wave;

impl Ode<1> for Wave {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        [-y[0] + t.cos() + t.sin()]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

/// Records the largest |y − sin t| over the samples it is shown.
struct Worst(f64, u64);

impl Observer<1> for Worst {
    fn samples_per_step(&self) -> usize {
        3
    }
    fn observe(&mut self, t: f64, y: &[f64; 1]) {
        self.0 = self.0.max((y[0] - t.sin()).abs());
        self.1 += 1;
    }
}

#[test]
fn the_stage_times_of_each_method_are_right() {
    let tol = 1e-10;
    for (method, order) in [("dopri5", 5.0), ("dop853", 8.0)] {
        let mut stepper = AnyStepper::new(method, Control::Tolerance(tol), 0.0, [0.0]).unwrap();
        let mut worst = Worst(0.0, 0);
        integrate_phase(&Wave, &mut stepper, &[], 10.0, 100_000, &mut worst).unwrap();
        let n = stepper.stats().steps as f64;
        assert!(
            n <= 10.0 / tol.powf(1.0 / (order + 1.0)),
            "{method}: {n} steps"
        );
        assert!(
            worst.1 as f64 >= 3.0 * n,
            "{method}: dense samples {}",
            worst.1
        );
        assert!(
            worst.0 <= 10.0 * n * tol,
            "{method}: {:e} over {n} steps",
            worst.0
        );
    }
}

/// The Taylor method's `interpolate_rate` (which steers its Newton refinement of events) is the
/// derivative of its step's polynomial `interpolate`: checked against a central difference of
/// that polynomial (mutation testing of `src/sim`: `+` → `−` in it went unseen, the bracket kept
/// the events' roots). Error model of the difference: δ²/6 |y'''| + 2u |y|/δ with δ = 1e-4 and
/// |y'''| = O(1) on the wall phase in its own units, ~2e-9; the bound 1e-7 (|θ̇| + 1) leaves 50.
/// Checked on the stepper itself and through `AnyStepper`, which the runs use (its dispatch of
/// the rate → None went unseen: events fell back to Brent's method, the same root).
#[test]
fn the_taylor_rate_is_the_derivative_of_its_interpolant() {
    use sliding_ladder::sim::integrators::taylor::Taylor;
    let (t0, y0, tol) = (0.0, [0.3, 0.1], 1e-12);
    rate_is_the_derivative_of_the_interpolant(Taylor::new(t0, y0, tol));
    let any = AnyStepper::new("taylor", Control::Tolerance(tol), t0, y0).unwrap();
    rate_is_the_derivative_of_the_interpolant(any);
}

fn rate_is_the_derivative_of_the_interpolant(mut stepper: impl Stepper<2>) {
    use sliding_ladder::sim::rigid::WallPhase;

    use sliding_ladder::ladder::Ladder;
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    };
    let sys = WallPhase::new(&ladder);
    for _ in 0..3 {
        stepper.step(&sys, 10.0).unwrap();
        stepper.prepare_dense(&sys);
        let (t0, t1) = (stepper.t_prev(), stepper.t());
        let d = 1e-4;
        for f in [0.25, 0.5, 0.75] {
            let t = t0 + f * (t1 - t0);
            let rate = stepper.interpolate_rate(t).expect("Taylor has it");
            let (a, b) = (stepper.interpolate(t + d), stepper.interpolate(t - d));
            for i in 0..2 {
                let diff = (a[i] - b[i]) / (2.0 * d);
                let bound = 1e-7 * (rate[i].abs() + 1.0);
                assert!(
                    (rate[i] - diff).abs() <= bound,
                    "y{i} at {t}: rate {} against {diff}",
                    rate[i]
                );
                // It can fail: the rate is not 0 here, so its negative is far off.
                assert!(
                    (-rate[i] - diff).abs() > bound,
                    "y{i} at {t}: rate {}",
                    rate[i]
                );
            }
        }
    }
}

/// A Taylor step's event rate on one series (`taylor_poly::value_and_rate_on`, the flat event's
/// Newton refinement): the τ-derivative of c(τ/H) is c'(τ/H)/H. Written out for
/// c(x) = 1 + 2x + 3x² + 4x³ with H = 0.37: all terms positive, so a few ulps of each (16 u
/// of the sum) cover the rounding. Mutation testing found `d · (1/H)` → `d / (1/H)` unseen.
#[test]
fn a_taylor_series_rate_is_its_time_derivative() {
    use sliding_ladder::sim::integrators::taylor_poly::value_and_rate_on;
    let (h, tau) = (0.37f64, 0.21f64);
    let x = tau / h;
    let (v, d) = value_and_rate_on(&[1.0, 2.0, 3.0, 4.0, 99.0], 3, 1.0 / h, tau);
    let want_v = 1.0 + 2.0 * x + 3.0 * x * x + 4.0 * x * x * x;
    let want_d = (2.0 + 6.0 * x + 12.0 * x * x) / h;
    let u = f64::EPSILON / 2.0;
    assert!(
        (v - want_v).abs() <= 16.0 * u * want_v,
        "{v} against {want_v}"
    );
    assert!(
        (d - want_d).abs() <= 16.0 * u * want_d,
        "{d} against {want_d}"
    );
}

/// ẏ = −1e20 y whose Jacobian reads 0 (the value is taken off the dual number): radau5's
/// simplified Newton iteration is then a fixed-point iteration, which contracts only for
/// h < 1e-20, below the step floor 1e-14 max(|t|, 1). The step must give up with
/// `NewtonFailed`, not halve on towards zero (a step of 1e-20 is no integration).
struct BlindJacobian;

impl Ode<1> for BlindJacobian {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [D::from(-1e20 * y[0].re())]
    }
}

#[test]
fn radau5_gives_up_when_newton_cannot_converge_at_any_usable_step() {
    use sliding_ladder::sim::integrators::StepError;
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 0.0, [1.0]).unwrap();
    let r = st.step(&BlindJacobian, 1.0);
    assert!(
        matches!(r, Err(StepError::NewtonFailed { .. })),
        "{r:?} at t = {}",
        st.t()
    );
}

/// ẏ = e^{3t}: the probe of the starting step sees the time.
struct Exponential;

impl Ode<1> for Exponential {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + (3.0 * t).exp()]
    }
}

/// The starting step is Hairer, Nørsett & Wanner's (*Solving ODEs I*, sec. II.4, steps a-f),
/// written out here for ẏ = e^{3t}, y(0) = 1, τ = 1e-6, order 5: d0 = d1 = 1e6 (weights τ |y0|),
/// h0 = 0.01 d0/d1, the Euler probe at t0 + h0, d2 = |f1 − f0|/(τ h0), h1 = (0.01/max(d1, d2))^(1/6),
/// the step min(100 h0, h1). A handful of roundings, then a sixth root: 8 ulps. The systems of
/// the crate are autonomous, so only a system like this one sees the probe's time (mutation
/// testing: `t + h0` → `t − h0` and `t · h0` went unseen).
#[test]
fn the_starting_step_is_hairer_s() {
    use sliding_ladder::sim::integrators::initial_step;
    let tol = 1e-6f64;
    let (d0, d1) = (1.0 / tol, 1.0 / tol);
    let h0 = 0.01 * d0 / d1;
    let d2 = ((3.0 * h0).exp() - 1.0) / tol / h0;
    let want = (100.0 * h0).min((0.01 / d1.max(d2)).powf(1.0 / 6.0));
    let mut evals = 0;
    let got = initial_step(
        &Exponential,
        0.0,
        &[1.0],
        &[1.0],
        tol,
        5,
        f64::INFINITY,
        &mut evals,
    );
    assert!(
        (got - want).abs() <= 8.0 * f64::EPSILON * want,
        "{got} against {want}"
    );
    assert_eq!(evals, 1, "one probe");
}

/// A step the integrator cannot take ends the phase with that step's error (`RunError::Step`).
#[test]
fn a_failed_step_ends_the_phase_with_its_error() {
    use sliding_ladder::sim::integrators::StepError;
    use sliding_ladder::sim::run::RunError;
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 0.0, [1.0]).unwrap();
    let r = integrate_phase(&BlindJacobian, &mut st, &[], 1.0, 1000, &mut Worst(0.0, 0));
    assert!(
        matches!(r, Err(RunError::Step(StepError::NewtonFailed { .. }))),
        "{r:?}"
    );
}

/// An event that gives no rate says so (`Event::rate`'s default is None), so its root is
/// refined by Brent's method and never by Newton's with a made-up slope.
#[test]
fn an_event_without_a_rate_gives_none() {
    for y in [-1.0, 0.0, 0.3, 7.0] {
        assert_eq!(Reaches(0.5).rate(0.0, &[y], &[1.0]), None);
    }
}

/// ẋ = 1 − x from x = 0 (x = 1 − e^{−t} < 1), whose right-hand side is NaN past x = 1: a long
/// trial step's stages overshoot there although the motion never does. Counts the NaNs given.
struct Relax(std::cell::Cell<u64>);

impl Ode<1> for Relax {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        if y[0].re() > 1.0 {
            self.0.set(self.0.get() + 1);
            return [D::from(f64::NAN)];
        }
        [-y[0] + 1.0]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

/// dopri5 and dop853 reject a trial step whose stages or error are not finite and shrink it,
/// and go on to the end on the motion (`AdaptiveState::reject_non_finite`). Error model: the
/// global error of a run at tolerance τ on this contracting motion stays within a few τ; 10 τ
/// is allowed. Without the rejection a NaN would be accepted or the step never shrunk.
#[test]
fn non_finite_trial_steps_are_rejected_and_the_run_goes_on() {
    let tol = 1e-3;
    for method in ["dopri5", "dop853"] {
        let sys = Relax(std::cell::Cell::new(0));
        let mut st = AnyStepper::new(method, Control::Tolerance(tol), 0.0, [0.0]).unwrap();
        while st.t() < 40.0 {
            st.step(&sys, 40.0)
                .unwrap_or_else(|e| panic!("{method}: {e:?} at t = {}", st.t()));
            assert!(st.y()[0].is_finite(), "{method}: accepted {:?}", st.y());
        }
        let exact = 1.0 - (-40.0f64).exp();
        assert!(
            sys.0.get() > 0,
            "{method}: no stage overshot x = 1, the path is not run"
        );
        assert!(st.stats().rejected > 0, "{method}: {:?}", st.stats());
        assert!(
            (st.y()[0] - exact).abs() <= 10.0 * tol,
            "{method}: x(40) = {} against {exact}",
            st.y()[0]
        );
    }
}

/// At an equilibrium (ẏ = 0 and a zero state) the slope and its change are both zero, and
/// Hairer, Nørsett & Wanner's starting step takes its fall-back branch (step e: d1, d2 ≤ 1e-15
/// gives h1 = max(1e-6, 1e-3 h0)). Here h0 = 1e-6 (step b, d0 < 1e-5), so h1 = 1e-6 and the
/// step min(100 h0, h1) is exactly 1e-6. (Mutation testing: h0 · 1e-3 → h0 + 1e-3 went unseen;
/// it starts at 1e-4.)
#[test]
fn the_starting_step_at_an_equilibrium_is_hairer_s_fall_back() {
    assert_the_start_at_rest_is_1e_minus_6(0.0);
}

/// ẏ = 0: every state is an equilibrium.
struct Still;

/// Hairer's starting step for ẏ = 0 from y0 at tolerance 1e-6 and order 5 is exactly 1e-6,
/// found with one probe of the right-hand side.
fn assert_the_start_at_rest_is_1e_minus_6(y0: f64) {
    use sliding_ladder::sim::integrators::initial_step;
    let mut evals = 0;
    let got = initial_step(
        &Still,
        0.0,
        &[y0],
        &[0.0],
        1e-6,
        5,
        f64::INFINITY,
        &mut evals,
    );
    assert_eq!(got, 1e-6, "y0 = {y0}");
    assert_eq!(evals, 1, "one probe");
}

impl Ode<1> for Still {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0]
    }
}

/// ẏ = t³, a right-hand side of t alone.
struct Cubic;

impl Ode<1> for Cubic {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + t * t * t]
    }
}

/// rk4's stage times: on ẏ = p(t) a step is Simpson's rule, exact for a cubic p, so four steps
/// of 0.5 from t = 1 give y(3) = (3⁴ − 1⁴)/4 = 20 to rounding (the stage values are exact
/// dyadic numbers, the step's sum rounds a few times: 16 u of 20). A stage at the wrong time
/// is off by O(h) per step. (Mutation testing: the second stage's time t + h/2 → t − h/2 and
/// t · h/2 went unseen: the ladder's systems do not depend on t and the Wave test above runs
/// the adaptive methods only.)
#[test]
fn rk4_integrates_a_cubic_in_t_exactly() {
    let mut stepper = AnyStepper::new("rk4", Control::Fixed(0.5), 1.0, [0.0]).unwrap();
    integrate_phase(&Cubic, &mut stepper, &[], 3.0, 100, &mut ()).unwrap();
    assert_eq!(stepper.stats().steps, 4);
    let y = stepper.y()[0];
    assert!((y - 20.0).abs() <= 16.0 * f64::EPSILON * 20.0, "{y}");
}

/// Records the times it is shown.
struct Times(Vec<f64>);

impl Observer<1> for Times {
    fn samples_per_step(&self) -> usize {
        4
    }
    fn observe(&mut self, t: f64, _y: &[f64; 1]) {
        self.0.push(t);
    }
}

/// 2 − t, which falls through 0 at t = 2, watched at four samples inside each step (as the
/// lift-off event is).
struct FallsAtTwo;

impl Event<1> for FallsAtTwo {
    fn value(&self, t: f64, _y: &[f64; 1]) -> f64 {
        2.0 - t
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    fn interior_samples(&self) -> usize {
        4
    }
}

/// An event that falls exactly on a dense sample's time is observed once, at the event: the
/// observer's samples are those strictly before it. One rk4 step of 5 samples the event at
/// t = 1, 2, 3, 4, where its value 2 − t is exactly 0 at the second, so the root is that
/// sample's time, 2; the observer's own samples are at the same fifths and must show 1 and
/// then the event at 2, not 2 twice (mutation testing: `tj < t_stop` → `<=` went unseen, a
/// sample lands on an event's time only by such a coincidence).
#[test]
fn a_sample_at_the_event_s_time_is_not_observed_twice() {
    let mut stepper = AnyStepper::new("rk4", Control::Fixed(5.0), 0.0, [0.0]).unwrap();
    let events = [&FallsAtTwo as &dyn Event<1>];
    let mut times = Times(Vec::new());
    let end = integrate_phase(&Clock, &mut stepper, &events, 10.0, 100, &mut times).unwrap();
    assert_eq!((end.event, end.t), (Some(0), 2.0));
    assert_eq!(times.0, [1.0, 2.0]);
}

/// Every trial step on which Newton's iteration fails counts as a rejected step: the blind
/// Jacobian above fails at every size down to the floor, so the step that gives up has
/// rejected at least one trial, and each one formed no accepted step. (Mutation testing: the
/// count `rejected += 1` → `*=` on that path went unseen; a count starting at 0 stays 0.)
#[test]
fn radau5_counts_each_trial_newton_fails_on() {
    use sliding_ladder::sim::integrators::Stepper;
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 0.0, [1.0]).unwrap();
    assert!(st.step(&BlindJacobian, 1.0).is_err());
    let stats = st.stats();
    assert!(stats.rejected >= 1, "{stats:?}");
    assert_eq!(stats.steps, 0, "{stats:?}");
}

/// Hairer, Nørsett & Wanner's step b takes h0 = 1e-6 when either the state or the slope is
/// negligible (d0 or d1 below 1e-5), not only the state: at rest away from zero (ẏ = 0,
/// y0 = 1, so d0 = 1e6 and d1 = 0) the ratio 0.01 d0/d1 would be infinite. Then step e's
/// fall-back gives h1 = max(1e-6, 1e-3 h0) = 1e-6, and the step is exactly 1e-6. (Mutation
/// testing: the slope's test `d1 < 1e-5` → `d1 == 1e-5` went unseen; it started at ∞.)
#[test]
fn the_starting_step_at_rest_away_from_zero_is_hairer_s_fall_back() {
    assert_the_start_at_rest_is_1e_minus_6(1.0);
}

/// ẏ = y², a right-hand side of the state.
struct Square;

impl Ode<1> for Square {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * y[0]]
    }
}

/// Hairer's step c probes with an explicit Euler step forwards, y1 = y0 + h0 f0, and takes
/// the slope's change there. Written out for ẏ = y², y0 = 1, τ = 1e-6, order 5: d0 = d1 =
/// 1e6 (weights τ |y0|), h0 = 0.01, f1 = 1.01², d2 = |f1 − f0|/(τ h0) = 2.01e6, and the step
/// min(100 h0, (0.01/d2)^(1/6)); 8 ulps as above. (Mutation testing: the probe y0 − h0 f0
/// went unseen: the other systems of these tests do not depend on y, and backwards the
/// change is 1.99e6, a step 0.17 % longer.)
#[test]
fn the_starting_steps_probe_is_a_forward_euler_step() {
    use sliding_ladder::sim::integrators::initial_step;
    let tol = 1e-6f64;
    let (d0, d1) = (1.0 / tol, 1.0 / tol);
    let h0 = 0.01 * d0 / d1;
    let y1 = 1.0 + h0;
    let d2 = (y1 * y1 - 1.0) / tol / h0;
    let want = (100.0 * h0).min((0.01 / d1.max(d2)).powf(1.0 / 6.0));
    let mut evals = 0;
    let got = initial_step(
        &Square,
        0.0,
        &[1.0],
        &[1.0],
        tol,
        5,
        f64::INFINITY,
        &mut evals,
    );
    assert!(
        (got - want).abs() <= 8.0 * f64::EPSILON * want,
        "{got} against {want}"
    );
}

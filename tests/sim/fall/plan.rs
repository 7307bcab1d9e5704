//! The outputs decide what is computed and kept: a separation-only scene evaluates no force, keeps
//! no sample, never builds the floor phase, and its memory does not grow with the step count.

use sliding_ladder::report::work_precision::scene_at;
use sliding_ladder::sim::fall::{self, Plan};
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::scene::output::Output;
use sliding_ladder::sim::scene::End;

fn run(outputs: Vec<Output>, end: End, control: Control) -> fall::Outcome {
    let mut sc = scene_at(0.3, 0.0);
    sc.method = if matches!(control, Control::Fixed(_)) {
        "rk4".into()
    } else {
        "dop853".into()
    };
    sc.control = Some(control);
    sc.end = end;
    sc.outputs = outputs;
    fall::run(&sc, fall::MAX_STEPS).unwrap()
}

#[test]
fn separation_angle_only_computes_nothing_else() {
    for h in [1e-3, 1e-4] {
        let o = run(
            vec![Output::SeparationAngle],
            End::Separation,
            Control::Fixed(h),
        );
        assert_eq!(o.plan, Plan::default());
        assert_eq!(o.work.force_evals, 0);
        assert_eq!(o.work.stored_samples, 0);
        assert!(o.trace.is_none() && o.work.floor.is_none() && o.energy_error.is_none());
        assert!(
            o.work.wall.steps as f64 > 0.5 / h,
            "{} steps",
            o.work.wall.steps
        );
    }
}

#[test]
fn a_trace_is_kept_only_when_asked_and_grows_with_the_steps() {
    let few = run(
        vec![Output::Trajectory],
        End::Separation,
        Control::Fixed(1e-2),
    );
    let many = run(
        vec![Output::Trajectory],
        End::Separation,
        Control::Fixed(1e-3),
    );
    assert!(few.work.stored_samples > 0 && many.work.stored_samples > 5 * few.work.stored_samples);
    assert_eq!(
        few.work.force_evals, 0,
        "a trajectory without forces evaluates no force"
    );
    let forces = run(vec![Output::Forces], End::Separation, Control::Fixed(1e-2));
    assert_eq!(
        forces.work.force_evals,
        2 * forces.work.stored_samples as u64
    );
}

#[test]
fn the_floor_phase_is_built_only_for_its_outputs() {
    let sep = run(
        vec![Output::SeparationTime, Output::EnergyError],
        End::Separation,
        Control::Tolerance(1e-10),
    );
    assert!(sep.work.floor.is_none() && sep.flat.is_none());
    let flat = run(vec![Output::FlatTime], End::Flat, Control::Tolerance(1e-10));
    assert!(flat.work.floor.is_some() && flat.flat.is_some());
    // flat without monitors: only the lift-off watch evaluates the floor force
    assert!(flat.work.force_evals > 0 && flat.floor_report.is_none());
    // With the floor-force monitor the same run also searches each floor step for the force's
    // minimum (`sim::minimum::minimum_on`: both ends, SAMPLES_PER_STEP = 4 interior samples and
    // the two golden-section points before its first pass, 8 or more evaluations), and those
    // evaluations are counted too (mutation testing: the search's count was dropped unseen).
    let watched = run(
        vec![Output::FlatTime, Output::FloorForceMin],
        End::Flat,
        Control::Tolerance(1e-10),
    );
    let steps = watched.work.floor.unwrap().steps;
    assert_eq!(steps, flat.work.floor.unwrap().steps);
    assert!(
        watched.work.force_evals >= flat.work.force_evals + 8 * steps,
        "{} force evaluations with the monitor, {} without, {steps} floor steps",
        watched.work.force_evals,
        flat.work.force_evals
    );
}

#[test]
fn end_at_time_stops_there() {
    let o = run(
        vec![Output::FinalState],
        End::Time(0.2),
        Control::Tolerance(1e-12),
    );
    assert_eq!(o.last.0, 0.2);
    assert!(o.separation.is_none());
}

/// A trace is held to fewer than 2 TRACE_CAP samples however many steps the run takes (a
/// fixed-step run of 1e7 steps used to keep 5 samples a step: 4.2 GB of `forces.csv` for
/// campaign seed 1 scene 989), evenly spread from the start to the separation, whose state it
/// ends on; forces are evaluated for the kept samples only. The check can fail: 1.3e5 steps
/// offer 6.5e5 samples.
#[test]
fn a_long_run_keeps_a_bounded_evenly_spread_trace() {
    use sliding_ladder::sim::trace::TRACE_CAP;
    let o = run(
        vec![Output::Forces, Output::SeparationTime],
        End::Separation,
        Control::Fixed(5e-6),
    );
    let trace = o.trace.as_ref().unwrap();
    let s = o.separation.unwrap();
    assert!(o.work.wall.steps > 100_000, "{}", o.work.wall.steps);
    assert!(
        (TRACE_CAP..2 * TRACE_CAP).contains(&trace.len()),
        "{}",
        trace.len()
    );
    assert_eq!(o.work.force_evals, 2 * trace.len() as u64);
    let last = trace[trace.len() - 1];
    assert_eq!((last.t, last.theta), (s.time, s.angle));
    let mean = s.time / (trace.len() - 1) as f64;
    let widest = trace
        .windows(2)
        .map(|w| w[1].t - w[0].t)
        .fold(0.0, f64::max);
    assert!(
        widest <= 2.0 * mean,
        "gap {widest:e} against a mean of {mean:e}"
    );
}

/// The same wall steps, and fewer right-hand sides without the momentum balance than with it.
fn assert_dense_output_only_for_the_impulse(plain: &fall::Outcome, balance: &fall::Outcome) {
    assert_eq!(plain.work.wall.steps, balance.work.wall.steps);
    assert!(
        plain.work.wall.rhs_evals < balance.work.wall.rhs_evals,
        "{} rhs without the balance, {} with it, {} steps",
        plain.work.wall.rhs_evals,
        balance.work.wall.rhs_evals,
        plain.work.wall.steps
    );
}

/// The wall phase hands its steps' dense output to the observer only for the momentum balance
/// (the wall's impulse is integrated on it); DOP853's dense output costs three more stages on
/// a step that builds it, so a fall without it takes fewer right-hand sides over the same steps
/// (measured: 100 against 118 over 7 steps). (Mutation testing: `wants_steps` → true on the
/// wall phase went unseen.)
#[test]
fn the_wall_phase_builds_dense_output_only_for_the_impulse() {
    let plain = run(vec![Output::FlatTime], End::Flat, Control::Tolerance(1e-10));
    let balance = run(
        vec![Output::FlatTime, Output::MomentumError],
        End::Flat,
        Control::Tolerance(1e-10),
    );
    assert_dense_output_only_for_the_impulse(&plain, &balance);
}

/// A trace samples every step at its fifths: four dense points at t0 + j (t1 − t0)/5 and the
/// step's end. With rk4's fixed step h every wall-phase sample before the separation lies at
/// a multiple of h/5 (from t = 0), to the rounding of the step ends, which are sums of up to
/// n steps: n u t. (Mutation testing: the dense points at t0 + (t1 − t0)/j/5 went unseen: the
/// trace tests counted samples, not where they lie.)
#[test]
fn a_trace_samples_each_step_at_its_fifths() {
    let h = 1e-2;
    let o = run(vec![Output::Trajectory], End::Separation, Control::Fixed(h));
    let wall: Vec<f64> = o
        .trace
        .unwrap()
        .iter()
        .filter(|s| s.phase == 1)
        .map(|s| s.t)
        .collect();
    let sep = o.separation.unwrap().time;
    let (n, fifth) = (o.work.wall.steps as f64, wall[5] / 5.0);
    assert!(
        (fifth - h / 5.0).abs() <= 4.0 * f64::EPSILON * h,
        "the step is h: {fifth}"
    );
    let before: Vec<f64> = wall.into_iter().filter(|&t| t < sep).collect();
    assert!(
        before.len() as f64 >= 4.0 * (n - 1.0),
        "{} samples",
        before.len()
    );
    for (i, t) in before.iter().enumerate() {
        let bound = (n + 2.0) * f64::EPSILON * t;
        assert!(
            (t - i as f64 * fifth).abs() <= bound,
            "sample {i} at {t}, not {}",
            i as f64 * fifth
        );
    }
}

/// The wall impulse's quadrature (five-point Gauss-Legendre on pieces of each wall step,
/// `fall::observer`) evaluates the wall force at least five times a wall step, and those
/// evaluations are counted: a fall to flat asking for the momentum balance counts at least
/// 5 N_wall more than the same fall without it (the floor phase has no wall force to
/// integrate). Mutation testing: the wall phase's count `+=` → `*=` (of a count that starts
/// at 0) went unseen, no test counted a wall phase's evaluations.
#[test]
fn the_wall_impulses_force_evaluations_are_counted() {
    let plain = run(vec![Output::FlatTime], End::Flat, Control::Tolerance(1e-10));
    let balanced = run(
        vec![Output::FlatTime, Output::MomentumError],
        End::Flat,
        Control::Tolerance(1e-10),
    );
    let wall_steps = balanced.work.wall.steps;
    assert_eq!(wall_steps, plain.work.wall.steps, "the same run");
    assert!(
        balanced.work.force_evals >= plain.work.force_evals + 5 * wall_steps,
        "{} evaluations with the impulse, {} without, {wall_steps} wall steps",
        balanced.work.force_evals,
        plain.work.force_evals
    );
}

/// The floor phase's trace is as dense as the wall phase's: each step offers its end and four
/// dense points (`SAMPLES_PER_STEP`), also through the complement's observer (the floor phase
/// runs in φ = π/2 − θ), so a short fall keeps all of them: about five samples a floor step
/// (the last step, cut at flat, may offer fewer). Mutation testing: the complement observer's
/// `samples_per_step` → 0 and → 1 went unseen; the floor phase's trace then thinned to one or
/// two samples a step.
#[test]
fn the_floor_phases_trace_has_the_dense_samples_too() {
    let o = run(
        vec![Output::Trajectory, Output::FlatTime],
        End::Flat,
        Control::Tolerance(1e-10),
    );
    let t_s = o.separation.unwrap().time;
    let steps = o.work.floor.unwrap().steps as usize;
    let after = o
        .trace
        .as_ref()
        .unwrap()
        .iter()
        .filter(|p| p.t > t_s)
        .count();
    assert!(
        after >= 4 * steps && after <= 5 * steps + 1,
        "{after} samples after the separation in {steps} floor steps"
    );
}

/// A wall phase past π/4 runs in the complement φ = π/2 − θ and reaches the trace through the
/// complement's observer (`complement::InTheta`), with the same four dense points and the end of
/// each step (the last step, cut at the separation, may offer fewer). Mutation testing: that
/// observer's `samples_per_step` → 0 and → 1 went unseen; the wall phase's trace then thinned
/// to one or two samples a step.
#[test]
fn a_wall_phase_past_a_quarter_turn_keeps_the_dense_samples() {
    let mut sc = scene_at(1.0, 0.0);
    sc.method = "dop853".into();
    sc.control = Some(Control::Tolerance(1e-10));
    sc.end = End::Separation;
    sc.outputs = vec![Output::Trajectory, Output::SeparationTime];
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let steps = o.work.wall.steps as usize;
    let t_s = o.separation.unwrap().time;
    let during = o
        .trace
        .as_ref()
        .unwrap()
        .iter()
        .filter(|p| p.t > 0.0 && p.t < t_s)
        .count();
    assert!(steps >= 2, "{steps} wall steps");
    assert!(
        during >= 4 * steps && during <= 5 * steps,
        "{during} samples inside the wall phase in {steps} steps"
    );
}

/// The same economy in the complement: a wall phase past π/4 (θ0 = 1.0, run in φ = π/2 − θ)
/// builds DOP853's dense output (three more stages a step) only for the impulse. Mutation
/// testing: the complement observer's `wants_steps` → true went unseen.
#[test]
fn a_wall_phase_past_a_quarter_turn_builds_dense_output_only_for_the_impulse() {
    let at = |outputs: Vec<Output>| {
        let mut sc = scene_at(1.0, 0.0);
        sc.method = "dop853".into();
        sc.control = Some(Control::Tolerance(1e-10));
        sc.end = End::Flat;
        sc.outputs = outputs;
        fall::run(&sc, fall::MAX_STEPS).unwrap()
    };
    let plain = at(vec![Output::FlatTime]);
    let balance = at(vec![Output::FlatTime, Output::MomentumError]);
    assert_dense_output_only_for_the_impulse(&plain, &balance);
}

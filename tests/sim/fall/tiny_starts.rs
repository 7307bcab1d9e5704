//! Starts at subnormal and tiny angles or pushes (issue 17, item 3): every method reaches the
//! separation with the time of the exact solution, and a run that stops short of the end its
//! scene asks for says so (`unreached_end`: exit 1, stderr, JSON `incomplete`).
//!
//! **Reference, independent of the integrators.** Below |θ| ≈ 1e-9 the wall phase is linear to
//! f64 precision (sin θ = θ(1 − θ²/6), θ²/6 < 1e-18), so a start a = θ0 + θ̇0/ω reaches any
//! θ1 ≪ 1 like a start from rest at θ1 = a does, ln(θ1/a)/ω later than it: t_s(a) = t_s(θ1 from
//! rest) + ln(θ1/a)/ω, the first from the exact closed form (Carlson/Jacobi, src/sim/exact),
//! to O(θ1²) = 1e-24. The bound is the integrators' error model 10 N τ (N steps, local error τ).

use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall::{self, Outcome};
use sliding_ladder::sim::scene;

const G: f64 = 9.81;

fn omega() -> f64 {
    (0.75 * G).sqrt()
}

fn scene_text(method: &str, control: &str, angle: &str, rate: &str, end: &str) -> String {
    format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = {G}\n[start]\nangle = {angle}\nangular_velocity = {rate}\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\n{control}\n[end]\nat = \"{end}\"\n[outputs]\nwant = [\"separation_angle\", \"separation_time\"]\n"
    )
}

/// t_s for the linear start a (θ0 + θ̇0/ω) from the exact closed form at θ1 = 1e-12 from rest.
fn reference_time(a_over: f64, scaled_by: f64) -> f64 {
    // a = a_over / scaled_by, kept apart so that a subnormal a is not formed.
    let theta1 = 1e-12;
    let t1 = PhaseOne::new(theta1, 0.0, 0.75 * G)
        .unwrap()
        .separation()
        .unwrap()
        .time;
    t1 + ((theta1 * scaled_by).ln() - a_over.ln()) / omega()
}

fn run(method: &str, control: &str, angle: &str, rate: &str) -> Outcome {
    let sc = scene::parse(
        "tiny.toml",
        &scene_text(method, control, angle, rate, "separation"),
    )
    .unwrap();
    fall::run(&sc, fall::MAX_STEPS).unwrap()
}

#[test]
fn subnormal_starts_separate_at_the_exact_time() {
    let s = 2f64.powi(600);
    let v = 5e-324;
    // (angle, rate, a·2^600, the wrong a of a start twice as fast)
    let starts = [
        ("0.0", "5e-324", v * s / omega()),
        ("5e-324", "0.0", v * s),
        ("1e-300", "0.0", 1e-300 * s),
    ];
    let arccos = (2.0f64 / 3.0).acos();
    for (angle, rate, a) in starts {
        let want = reference_time(a, s);
        for (method, control, tau) in [
            ("dop853", "tolerance = 1e-12", 1e-12),
            ("radau5", "tolerance = 1e-12", 1e-12),
            ("dopri5", "tolerance = 1e-12", 1e-12),
            ("rk4", "step = 1e-2", 1e-10),
            // The closed form behind the lead-in: no steps, its error the rounding of the
            // logarithms (|ln a| ≤ 750) and of t_s, a few ulps of each, below 1e-15 of t_s.
            ("exact", "", 1e-15),
        ] {
            let o = run(method, control, angle, rate);
            let sep = o.separation.expect("separates");
            assert_eq!(
                o.last.0, sep.time,
                "{method}: the run ends at the separation"
            );
            let n = (o.work.wall.steps.max(1)) as f64;
            let bound = 10.0 * n * tau * want;
            assert!(
                (sep.time - want).abs() <= bound,
                "{method} {angle} {rate}: t_s = {} against {want} (bound {bound:e})",
                sep.time
            );
            assert!(
                (sep.angle - arccos).abs() <= 10.0 * n * tau,
                "{method}: {}",
                sep.angle
            );
            // The check can fail: the reference of a start twice as fast is ln 2/ω ≈ 0.26 s off.
            let wrong = reference_time(2.0 * a, s);
            assert!((sep.time - wrong).abs() > bound, "{method}");
        }
    }
}

#[test]
fn an_unreached_end_is_reported() {
    let sc = scene::parse(
        "tiny.toml",
        &scene_text("dop853", "tolerance = 1e-10", "0.3", "0.0", "flat"),
    )
    .unwrap();
    let mut o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    assert_eq!(sliding_ladder::sim::outcome::unreached_end(&sc, &o), None);
    o.flat = None;
    let why = sliding_ladder::sim::outcome::unreached_end(&sc, &o).expect("flat missing");
    assert!(why.contains("flat"), "{why}");
    o.separation = None;
    let why = sliding_ladder::sim::outcome::unreached_end(&sc, &o).expect("separation missing");
    assert!(why.contains("separation"), "{why}");
}

/// The trajectory of a tiny start keeps its dense samples after the lead-in (the phase runs
/// through `extreme::Shifted`, which must pass the observer's samples a step on): four inside
/// each step (the last, cut at the event, may keep fewer) and its end, as from an ordinary start.
#[test]
fn a_tiny_start_traces_every_step_densely() {
    for angle in ["1e-30", "0.3"] {
        let text = scene_text("dop853", "tolerance = 1e-10", angle, "0.0", "separation").replace(
            "want = [\"separation_angle\", \"separation_time\"]",
            "want = [\"trajectory\"]",
        );
        let sc = scene::parse("tiny.toml", &text).unwrap();
        let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
        let (rows, steps) = (o.trace.unwrap().len() as u64, o.work.wall.steps);
        assert!(
            rows >= 4 * steps,
            "θ0 = {angle}: {rows} rows for {steps} steps"
        );
    }
}

/// A scene from rest at `angle` (g = 9.81, l = 1) ending at `t_end` s, asking for the final state.
fn timed_scene(angle: f64, method: &str, tol: f64, t_end: f64) -> scene::Scene {
    scene::parse("tiny.toml", &timed_scene_text(angle, method, tol, t_end)).unwrap()
}

/// The text of [`timed_scene`].
fn timed_scene_text(angle: f64, method: &str, tol: f64, t_end: f64) -> String {
    format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = {G}\n[start]\nangle = {angle:e}\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\ntolerance = {tol:e}\n[end]\nat = \"time\"\ntime = {t_end}\n[outputs]\nwant = [\"final_state\"]\n"
    )
}

/// An `[end] time` before the linear lead-in hands over (issue 11, the 1e6-scene campaign: seed
/// 1 scenes 129565, 255978, 268153, 338810, 425812, radau5 at τ ≈ 1e-16 from θ0 = 1e-313 ..
/// 1e-159, took up to 1.2e6 steps to integrate hundreds of √(l/g) of growth): the run is the
/// linear motion in closed form, no steps. Reference: the linearised (5), θ̈ = Ω² θ, solved in
/// the test as θ0 cosh(Ω t) from rest (½ θ0 e^{Ω t} for the subnormal start, whose growth
/// e^{Ω t} ≈ 1e312 passes the largest f64: formed through logarithms here), exact to f64 below
/// 1e-9 (module docs). Bound: the argument Ω t and ln θ0 carry u each, so a few u (|ln θ0| + Ω t).
#[test]
fn an_end_within_the_lead_in_is_the_linear_motion() {
    let w = omega();
    for (angle, t_end) in [(1e-200f64, 150.0f64), (5e-324, 265.0), (1e-30, 15.0)] {
        let sc = timed_scene(angle, "radau5", 1e-14, t_end);
        // Without the closed form this run needs ~1e5 steps (it was integrated from θ0).
        let o = fall::run(&sc, 1).expect("no steps needed");
        assert_eq!(o.work.wall.steps, 0);
        assert!(o.separation.is_none());
        let (t, theta, rate) = o.last;
        assert_eq!(t, t_end);
        let x = w * t_end;
        let (want, want_rate) = match angle > 1e-300 {
            true => (angle * x.cosh(), angle * w * x.sinh()),
            false => {
                let half = 0.5 * (angle.ln() + x).exp();
                (half, w * half)
            }
        };
        assert!(want < 1e-9, "the end must lie within the lead-in: {want:e}");
        let bound = 8.0 * (angle.ln().abs() + x + 2.0) * f64::EPSILON;
        for (what, got, want) in [("θ", theta, want), ("θ̇", rate, want_rate)] {
            let rel = (got - want).abs() / want;
            assert!(
                rel <= bound,
                "{angle:e} {what}: {got:e} against {want:e} ({rel:e} > {bound:e})"
            );
        }
        // It can fail: the same start a tenth of a √(l/g) later is Ω/10 ≈ 27% further on.
        assert!((want * (0.1 * w).exp() - theta).abs() / want > bound);
    }
}

/// The plan's estimate of the wall phase's length in seconds (`phase_steps` for a fixed rk4
/// step h at g = 9.81, times h) from (θ0, θ̇0 in rad/s); its floor phase's steps must be 0.
fn estimated_wall_time(theta0: f64, rate0: f64) -> f64 {
    use sliding_ladder::ladder::Ladder;
    use sliding_ladder::sim::integrators::Control;
    use sliding_ladder::sim::scene::work::phase_steps;
    use sliding_ladder::sim::scene::{ContactModel, End};
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: G,
    };
    let h = 1e-3;
    let [wall, floor] = phase_steps(
        &ladder,
        (theta0, rate0),
        "rk4",
        Control::Fixed(h),
        End::Separation,
        ContactModel::Rigid,
    );
    assert_eq!(floor, 0.0, "no floor phase is run");
    wall * h
}

/// The plan's step estimate for a fixed step from a start below 1e-100 rad (`phase_steps`): the
/// time the linear growth takes to reach 1e-100, then the exact wall phase from there at rest,
/// over the step. Held against this file's reference (the same construction at 1e-12, through
/// the closed form), the two agree to O(θ1²) and the rounding of a logarithm and of the closed
/// form's time: 16 ulps of t_s (1 measured). Mutation testing: the lead-in's ln(grow)/Ω →
/// ln(grow) · Ω (25 % short) and → ln(grow) % Ω (a few √(l/g)) went unseen, and so did the
/// grown push in units of T, θ̇0 grow · T → θ̇0 grow / T (the pushed start 0.4 % short).
/// The plan's wall time from (θ0, θ̇0) is `want` s to 16 ulps.
fn assert_estimate(theta0: f64, rate0: f64, want: f64) {
    let got = estimated_wall_time(theta0, rate0);
    assert!(
        (got - want).abs() <= 16.0 * f64::EPSILON * want,
        "θ0 = {theta0:e}, θ̇0 = {rate0:e}: {got} s against {want} s"
    );
}

#[test]
fn a_tiny_start_s_step_estimate_is_its_separation_time_over_the_step() {
    // (θ0, θ̇0 in rad/s): from rest, and pushed from 0 (its linear start a = θ̇0/ω).
    let starts = [(1e-200, 0.0), (1e-250, 0.0), (1e-300, 0.0), (0.0, 1e-250)];
    for (theta0, rate0) in starts {
        assert_estimate(theta0, rate0, reference_time(theta0 + rate0 / omega(), 1.0));
    }
}

/// Above 1e-100 rad the plan's estimate of the wall phase is the closed form's separation time
/// in the scene's units, θ̇0 taken in units of 1/T: the same as the closed form in SI (Ω² =
/// 3g/4l) up to the rounding of the unit conversion and of the closed form, 16 ulps. Pushed
/// starts at g = 9.81 tell θ̇0 T from θ̇0/T (mutation testing: the latter went unseen: every
/// other estimate test starts at rest or has T = 1).
#[test]
fn a_pushed_start_s_step_estimate_is_its_separation_time_over_the_step() {
    for (theta0, rate0) in [(0.3, 0.5), (1e-6, 2.0), (0.0, 1.0)] {
        let exact = PhaseOne::new(theta0, rate0, 0.75 * G).unwrap();
        assert_estimate(theta0, rate0, exact.separation().unwrap().time);
    }
}

/// The lead-in is for tiny starts only: a start at or above `LINEAR_AMPLITUDE` in θ or θ̇/Ω, or
/// a ladder whose Ω is not a positive finite number, gets None and is integrated as it is
/// (mutation testing: two of the guard's `&&` → `||` went unseen: the callers ask only for
/// tiny starts, so only the contract itself shows the guard). Nor has a start that does not
/// move away from 0 one: pushed back towards the wall (θ0 + θ̇0/Ω ≤ 0, where the mutant
/// `||` → `&&` of the second guard returned a NaN hand-over time) or from a negative angle.
#[test]
fn a_start_that_is_not_tiny_has_no_lead_in() {
    use sliding_ladder::sim::lead_in::{linear_lead_in, LINEAR_AMPLITUDE};
    let amp = LINEAR_AMPLITUDE;
    assert!(
        linear_lead_in(0.75, 0.5 * amp, 0.0).is_some(),
        "a tiny start has one"
    );
    for (big_omega2, theta0, rate0) in [
        (0.75, 0.3, 0.0),
        (0.75, amp, 0.0),
        (0.75, 0.0, amp * 0.75f64.sqrt()),
        (0.0, 0.5 * amp, 0.0),
        (f64::INFINITY, 0.5 * amp, 0.0),
        (0.75, 0.0, -1e-12),
        (0.75, 1e-12, -2e-12),
        (0.75, -1e-12, 1e-11),
    ] {
        assert_eq!(
            linear_lead_in(big_omega2, theta0, rate0),
            None,
            "Ω² = {big_omega2}, θ0 = {theta0:e}, θ̇0 = {rate0:e}"
        );
    }
}

/// An `[end] time` after the lead-in hands over is integrated from the hand-over, not read off
/// the linear motion: from θ0 = 1e-30 at rest, the end lies 0.97 of the way to the
/// separation in time, where the exact motion has turned the ladder to 0.366 rad, far outside
/// the linear regime. Reference: the module's shift, θ(t) = θ₁(t − ln(θ1/θ0)/ω) with θ₁ the
/// exact closed form from rest at θ1 = 1e-12 (to O(θ1²)). Bound: the error model 10 N τ, N the
/// steps. (Mutation testing: the closed form's guard `t >= t_end` → true went unseen; it read
/// every timed end off the linear motion, θ = θ0 cosh Ω t: 0.3667 for 0.3657 here.)
#[test]
fn an_end_past_the_lead_in_is_integrated() {
    let (theta0, theta1, tol) = (1e-30f64, 1e-12f64, 1e-12);
    let exact = PhaseOne::new(theta1, 0.0, 0.75 * G).unwrap();
    let shift = (theta1 / theta0).ln() / omega();
    let t_end = shift + 0.97 * exact.separation().unwrap().time;
    let sc = timed_scene(theta0, "dop853", tol, t_end);
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let (t, theta, rate) = o.last;
    assert_eq!(t, t_end);
    let (want, want_rate) = (exact.theta(t_end - shift), exact.rate(t_end - shift));
    assert!(want > 0.2, "the end lies past the linear regime: {want}");
    let bound = 10.0 * o.work.wall.steps as f64 * tol;
    assert!((theta - want).abs() <= bound, "θ {theta} against {want}");
    assert!(
        (rate - want_rate).abs() <= bound * omega(),
        "θ̇ {rate} against {want_rate}"
    );
}

/// The hand-over state of the linear lead-in (`sim::lead_in::linear_lead_in`) is the linear
/// motion θ = θ0 cosh Ωt + (θ̇0/Ω) sinh Ωt, θ̇ = θ0 Ω sinh Ωt + θ̇0 cosh Ωt (written out here)
/// at the time it returns, with and without a push. The starts are 1e-10 to 1e-20 rad, where
/// the decaying part ½ b e^{−Ωt} is up to 3e-3 of the amplitude and so shows. Error model: the
/// returned t = ln(2A/a)/Ω (a = θ0 + θ̇0/Ω) carries the rounding of the logarithms, u |ln a|
/// each, which e^{Ωt} turns into a relative error; with exp, two halves and a few products,
/// 16 u (1 + Ωt + |ln a|). (Mutation testing:
/// the growing part's a = p + q → p − q, which changes only that small part, went unseen.)
#[test]
fn the_lead_in_hands_over_on_the_linear_motion() {
    use sliding_ladder::sim::lead_in::linear_lead_in;
    let w2 = 0.75f64;
    let w = w2.sqrt();
    for (theta0, rate0) in [(1e-10, 3e-11), (1e-10, 0.0), (2e-20, 1e-20), (1e-12, 5e-11)] {
        let (t, theta, rate) = linear_lead_in(w2, theta0, rate0).expect("a tiny start");
        let (ch, sh) = ((w * t).cosh(), (w * t).sinh());
        let (want, want_rate) = (theta0 * ch + rate0 / w * sh, theta0 * w * sh + rate0 * ch);
        let rel = 16.0 * f64::EPSILON * (1.0 + w * t + (theta0 + rate0 / w).ln().abs());
        assert!(
            (theta - want).abs() <= rel * want,
            "θ {theta:e} vs {want:e}"
        );
        assert!(
            (rate - want_rate).abs() <= rel * want_rate,
            "θ̇ {rate:e} vs {want_rate:e}"
        );
    }
}

/// The trace of a run that ends within the lead-in holds the start and the end, t_end, with
/// the run's final state (mutation testing: the lead-in's early return `t0 > 0` → `t0 < 0`
/// went unseen: the run then integrated a phase of zero length, the same final state, but the
/// trace lost its end).
#[test]
fn a_trace_that_ends_within_the_lead_in_keeps_its_end() {
    let text = timed_scene_text(1e-30, "dop853", 1e-12, 5.0).replace(
        "want = [\"final_state\"]",
        "want = [\"final_state\", \"trajectory\"]",
    );
    let sc = scene::parse("tiny.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let trace = o.trace.expect("a trace");
    let times: Vec<f64> = trace.iter().map(|s| s.t).collect();
    assert_eq!(times, [0.0, 5.0], "the start and the end");
    let end = trace[1];
    assert_eq!((end.t, end.theta, end.rate), o.last);
}

/// A run that ends within the linear lead-in reports its energy change like any other run
/// (mutation testing: `energy - e` → `energy + e` and `energy / e` in `fall::run_rigid`'s
/// lead-in exit went unseen, no test of that exit asked for the energy). The energy
/// E = ½ m l² (sin²θ + 1/3) θ̇² + m g l cos θ of the ladder below θ ≈ 1e-9 is m g l to O(θ²,
/// θ̇²/Ω²) ≤ 1e-18. The run works in units of m, l, g (`sim::scaled`), where that is 1 to
/// below half an ulp: both energies round to exactly 1 and the change is exactly 0.
#[test]
fn an_end_within_the_lead_in_keeps_the_energy() {
    let text = timed_scene_text(1e-30, "radau5", 1e-14, 15.0)
        .replace("[\"final_state\"]", "[\"final_state\", \"energy_error\"]");
    let sc = scene::parse("tiny.toml", &text).unwrap();
    let o = fall::run(&sc, 1).expect("no steps needed");
    assert_eq!(o.work.wall.steps, 0, "the end lies within the lead-in");
    let err = o.energy_error.expect("asked for");
    assert_eq!(err, 0.0, "energy change {err:e} m g l");
}

/// The trajectory of a tiny start is in the scene's time: the start at 0, the lead-in's
/// hand-over at its closed-form time t0, then the integrated phase's samples shifted by t0
/// (through `extreme::Shifted`), increasing to the separation time; each sample's angle on the
/// linear motion θ0 cosh(Ω t) while that holds (below 1e-6 rad, to 1e-12 relative and the
/// integration's 10 N τ). Mutation testing: the shift `t + t0` → `t − t0` went unseen, the
/// trace tests counted rows.
#[test]
fn a_tiny_starts_trace_is_in_the_scenes_time() {
    let text = scene_text("dop853", "tolerance = 1e-12", "1e-30", "0.0", "separation").replace(
        "want = [\"separation_angle\", \"separation_time\"]",
        "want = [\"trajectory\", \"separation_time\"]",
    );
    let sc = scene::parse("tiny.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let trace = o.trace.unwrap();
    assert_eq!(trace[0].t, 0.0);
    assert!(
        trace.windows(2).all(|w| w[1].t >= w[0].t),
        "the samples' times increase"
    );
    let last = trace[trace.len() - 1];
    assert_eq!(last.t, o.separation.unwrap().time);
    let w = omega();
    // The wall phase's errors are relative to the motion's size (`WallPhase::scale`), so
    // 10 N τ relative; the linearisation is good to θ²/6 < 2e-13 below 1e-6.
    let bound = 1e-12 + 10.0 * o.work.wall.steps as f64 * 1e-12;
    let mut checked = 0;
    for p in trace.iter().filter(|p| p.theta < 1e-6 && p.t > 0.0) {
        let want = 1e-30 * (w * p.t).cosh();
        assert!(
            (p.theta - want).abs() <= bound * want,
            "t = {}: θ {} against {want}",
            p.t,
            p.theta
        );
        checked += 1;
    }
    assert!(checked >= 3, "{checked} samples on the linear motion");
}

/// The momentum balance of a tiny start to flat holds to its error model
/// (tests/sim/fall/momentum_balance.rs): 4 (10 N τ + 4u) √g, N the steps of both phases. The lead-in
/// (closed form) lasts ln(1e-9/θ0)/ω ≈ 18 s here (g = 9.81, l = 1), and the integrated wall
/// phase's steps reach the impulse's quadrature through `extreme::Shifted`, shifted by that
/// time. Mutation
/// testing: the shifted step's start `t0 + shift` → `t0 − shift` went unseen (the quadrature
/// then ran over 2 × 18 s more, on the dense output far outside its step); the one tiny start
/// with a momentum check (campaign scene 995) had a push and a lead-in of 3e-9.
#[test]
fn a_tiny_starts_momentum_balance_holds_through_the_shift() {
    let text = scene_text("dop853", "tolerance = 1e-12", "1e-30", "0.0", "flat").replace(
        "want = [\"separation_angle\", \"separation_time\"]",
        "want = [\"momentum_error\", \"flat_state\"]",
    );
    let sc = scene::parse("tiny.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
    let bound = 4.0 * (10.0 * n * 1e-12 + 4.0 * f64::EPSILON) * G.sqrt();
    let e = o.momentum_error.unwrap();
    assert!(e <= bound, "momentum error {e:e} > {bound:e} ({n} steps)");
    // It measures something: the wall's impulse is the whole final momentum m Ẋ.
    let vx = o.flat.unwrap().centre_velocity_x;
    assert!(vx.abs() > 1e6 * bound, "{vx}");
}

/// A scene that ends at the separation and a run without one: reported too, naming the
/// separation. (Mutation testing: that arm's guard → false went unseen; the run was then
/// reported complete, exit 0, with no separation in it. The test above covers the flat end.)
#[test]
fn an_unreached_separation_is_reported() {
    let sc = scene::parse(
        "tiny.toml",
        &scene_text("dop853", "tolerance = 1e-10", "0.3", "0.0", "separation"),
    )
    .unwrap();
    let mut o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    assert_eq!(sliding_ladder::sim::outcome::unreached_end(&sc, &o), None);
    o.separation = None;
    let why = sliding_ladder::sim::outcome::unreached_end(&sc, &o).expect("separation missing");
    assert!(why.contains("without reaching the separation,"), "{why}");
}

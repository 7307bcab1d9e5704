//! Plan-time refusals (`sim::scene::work`): a request the run could not meet is refused up front
//! with exit 2 and the field, and each refusal is needed: the same scene run anyway fails, and a
//! scene just inside the stated limit is accepted and runs.

use sliding_ladder::report::campaign::judge::out_of_tolerance;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::scene::work::phase_steps;
use sliding_ladder::sim::scene::{parse, Scene};

const BASE: &str = "[ladder]
mass = 1.0
half_length = 1.0
gravity = 1.0
[start]
angle = 0.3
angular_velocity = 0.0
[contact]
CONTACT
[integrator]
METHOD
[end]
at = \"END\"
[outputs]
want = [\"separation_angle\"]
";

fn text(contact: &str, method: &str, end: &str) -> String {
    BASE.replace("CONTACT", contact)
        .replace("METHOD", method)
        .replace("END", end)
}

const SPRINGS: &str = "model = \"penalty\"\nstiffness = 1e8\ndamping = 0.0";

/// The number after `key` in `message` (e.g. the limit a refusal states).
fn number_after(message: &str, key: &str) -> f64 {
    let rest = &message[message.find(key).expect(key) + key.len()..];
    let end = rest.find([' ', ';', ',', ')']).unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

#[test]
fn a_fixed_step_on_stiff_springs_is_refused_and_would_fail() {
    // κ = 1e8: ω = 2e4, so h ≤ 0.2/ω = 1e-5.
    let bad = text(SPRINGS, "method = \"rk4\"\nstep = 1e-3", "separation");
    let e = parse("s.toml", &bad).unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.starts_with("s.toml:14: [integrator] step: penalty springs of k l/(m g) = 1e8"),
        "{msg}"
    );
    let limit = number_after(&msg, "a step ≤ ");
    assert!((limit - 1e-5).abs() <= 1e-20, "{msg}");
    // Run anyway (the check bypassed): the integration is unstable and the run fails.
    let inside = text(SPRINGS, "method = \"rk4\"\nstep = 0.99e-5", "separation");
    let mut sc = parse("s.toml", &inside).expect("inside the limit");
    let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
    assert!(out_of_tolerance(&sc, &o).is_empty());
    sc.control = Some(sliding_ladder::sim::integrators::Control::Fixed(1e-3));
    assert!(fall::run(&sc, fall::MAX_STEPS).is_err());
}

/// The dashpot counts in the contact's fastest rate, ω = 2√κ + 4γ (γ = c √(l/g)/m): κ = 1e8 and
/// γ = 5e3 give ω = 2e4 + 2e4 = 4e4, so h ≤ 0.2/ω = 5e-6, half the undamped springs' limit
/// (mutation testing: 2√κ − 4γ went unseen, every refusal test was undamped).
#[test]
fn the_dashpot_shortens_the_fixed_step_limit() {
    let damped = "model = \"penalty\"\nstiffness = 1e8\ndamping = 5e3";
    let bad = text(damped, "method = \"rk4\"\nstep = 6e-6", "separation");
    let msg = parse("s.toml", &bad).unwrap_err().to_string();
    // ω is stated to four digits (`{:.3e}`), the limit to f64.
    let omega = number_after(&msg, "2√κ + 4γ = ");
    assert!((omega - 4e4).abs() <= 5e-4 * 4e4, "{msg}");
    let limit = number_after(&msg, "a step ≤ ");
    assert!((limit - 5e-6).abs() <= 4.0 * f64::EPSILON * 5e-6, "{msg}");
    let inside = text(damped, "method = \"rk4\"\nstep = 4.9e-6", "separation");
    assert!(parse("s.toml", &inside).is_ok(), "inside the limit");
}

#[test]
fn explicit_euler_on_springs_needs_a_smaller_step_still() {
    let springs = "model = \"penalty\"\nstiffness = 1e2\ndamping = 0.0";
    let e = parse(
        "s.toml",
        &text(springs, "method = \"euler\"\nstep = 1e-3", "separation"),
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .contains("explicit Euler gains energy on every oscillation"),
        "{e}"
    );
    // The same step suits symplectic Euler (h ω = 0.02).
    assert!(parse(
        "s.toml",
        &text(
            springs,
            "method = \"symplectic-euler\"\nstep = 1e-3",
            "separation"
        )
    )
    .is_ok());
}

#[test]
fn an_explicit_method_on_the_stiffest_springs_from_a_tiny_start_is_refused() {
    let springs = "model = \"penalty\"\nstiffness = 1e12\ndamping = 0.0";
    let slow = text(
        springs,
        "method = \"dop853\"\ntolerance = 1e-8",
        "separation",
    )
    .replace("angle = 0.3", "angle = 1e-30");
    let e = parse("s.toml", &slow).unwrap_err().to_string();
    assert!(
        e.starts_with("s.toml:13: [integrator] method: penalty springs")
            && e.contains("allowed: method = \"radau5\""),
        "{e}"
    );
    // radau5 is accepted there, and from θ0 = 0.3 dop853 too (about 2e6 steps).
    assert!(parse("s.toml", &slow.replace("dop853", "radau5")).is_ok());
    let near = text(
        springs,
        "method = \"dop853\"\ntolerance = 1e-8",
        "separation",
    );
    assert!(parse("s.toml", &near).is_ok());
}

#[test]
fn a_step_too_small_for_the_fall_is_refused_at_the_stated_least_step() {
    let rigid = "model = \"rigid\"";
    let e = parse(
        "s.toml",
        &text(rigid, "method = \"rk4\"\nscaled_step = 1e-6", "flat")
            .replace("angle = 0.3", "angle = 1e-30"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("[integrator] step: the wall phase needs about"),
        "{e}"
    );
    let least = number_after(&e, "a step ≥ ");
    let at = |h: f64| {
        text(rigid, &format!("method = \"rk4\"\nstep = {h:e}"), "flat")
            .replace("angle = 0.3", "angle = 1e-30")
    };
    assert!(parse("s.toml", &at(least * 1.01)).is_ok());
    let no = at(least * 0.99);
    assert!(parse("s.toml", &no).is_err());
}

/// The estimate is the run: a fixed-step fall to flat takes the estimated steps in each phase
/// (within one step and the event's last partial step), so the refusal refuses what the run
/// would have hit.
#[test]
fn the_step_estimate_matches_the_run() {
    let sc = parse(
        "s.toml",
        &text(
            "model = \"rigid\"",
            "method = \"rk4\"\nscaled_step = 1e-3",
            "flat",
        )
        .replace("[\"separation_angle\"]", "[\"flat_time\"]"),
    )
    .unwrap();
    takes_the_estimate(&sc);
}

/// The campaign's F6: dop853 at tolerance 2.8e-16 on κ = 6.9e6 (θ0 = 0.4186) ran into the 1e7-step
/// limit after 15 s (release) while the stability count said 2.9e3 steps. The estimate now adds
/// the accuracy and rounding-floor counts and refuses it up front; the estimate follows runs of
/// both explicit methods within the fits' spread, erring high (each run takes a fraction of a
/// second).
#[test]
fn explicit_methods_at_tight_tolerances_on_stiff_springs_are_estimated_and_refused() {
    let springs = |kappa: &str, gamma: &str| {
        format!("model = \"penalty\"\nstiffness = {kappa}\ndamping = {gamma}")
    };
    let scene = |kappa: &str, gamma: &str, method: &str, tol: &str| {
        text(
            &springs(kappa, gamma),
            &format!("method = \"{method}\"\ntolerance = {tol}"),
            "separation",
        )
        .replace("angle = 0.3", "angle = 0.4186")
    };
    let e = parse("s.toml", &scene("6.9e6", "13.3", "dop853", "2.8e-16"))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("s.toml:13: [integrator] method: penalty springs")
            && e.contains("is explicit and its steps must resolve them to the tolerance"),
        "{e}"
    );
    assert!(number_after(&e, "about ") > 1e7, "{e}");
    for (kappa, method, tol) in [
        ("1e6", "dopri5", "1e-12"),
        ("1e4", "dop853", "1e-15"),
        ("1e6", "dop853", "1e-14"),
    ] {
        let sc = parse("s.toml", &scene(kappa, "0.0", method, tol)).unwrap();
        let est = estimate(&sc)[0];
        let got = fall::run(&sc, fall::MAX_STEPS).unwrap().work.wall.steps as f64;
        assert!(
            (0.8..2.5).contains(&(est / got)),
            "{method} κ = {kappa} τ = {tol}: estimated {est:.3e}, took {got:.3e}"
        );
    }
}

/// The campaign's scenes 714, 1031 and 1502 of seed 1 (tiny starts, dopri5/dop853 at loose
/// tolerances): the wall force where the integration starts (the lead-in's hand-over at
/// θ ≈ 2⁻³⁰, F_w0 = (3/4) θ to rounding and θ² ≈ 1e-18) is far below the tolerance, and the
/// run ends at a spurious zero. Refused up front naming the tolerance; the stated largest
/// tolerance F_w0/40 is accepted and runs within the judge's bound; the refused one, run
/// anyway, fails; radau5 at the refused tolerance is accepted. Near π/2 the wall force is as
/// small but the separation is near, and an early zero is within the bound: not refused.
#[test]
fn an_explicit_method_looser_than_the_starting_wall_force_is_refused() {
    let springs = "model = \"penalty\"\nstiffness = 1e4\ndamping = 0.0";
    let at = |method: &str, tol: f64| {
        text(
            springs,
            &format!("method = \"{method}\"\ntolerance = {tol:e}"),
            "separation",
        )
        .replace("angle = 0.3", "angle = 1e-12")
    };
    let e = parse("s.toml", &at("dopri5", 1e-6))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("s.toml:14: [integrator] tolerance: the wall force where the integration starts is 6.985e-10 m g, below 40 times the tolerance (4.000e-5 m g)")
            && e.contains("8.411e-1 rad before the separation"),
        "{e}"
    );
    let largest = number_after(&e, "tolerance ≤ ");
    // The hand-over: θ = ½ θ0 (e^{Ωt} + e^{−Ωt}) with ½ θ0 e^{Ωt} = A = 2⁻³⁰, from rest.
    let a = 2f64.powi(-30);
    let want = 0.75 * (a + 1e-24 / (4.0 * a)) / 40.0;
    assert!((largest - want).abs() <= 1e-15 * want, "{e}");
    for method in ["dopri5", "dop853"] {
        let sc = parse("s.toml", &at(method, largest)).expect("at the stated limit");
        let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
        assert!(out_of_tolerance(&sc, &o).is_empty(), "{method}");
        assert!(parse("s.toml", &at(method, largest * 1.01)).is_err());
        let mut anyway = sc.clone();
        anyway.control = Some(sliding_ladder::sim::integrators::Control::Tolerance(1e-6));
        assert!(fall::run(&anyway, fall::MAX_STEPS).is_err(), "{method}");
    }
    assert!(parse("s.toml", &at("radau5", 1e-6)).is_ok());
    // θ0 = π/2 − 1e-9: F_w0 = 7.5e-10 m g, θ_r = π/2 − 6.7e-10; springs of κ = 1e12, as κ = 1e4
    // would shift the separation by more than that (refused: `sim::penalty::plan`).
    let near = at("dopri5", 1e-6)
        .replace("angle = 1e-12", "angle = 1.5707963257948965")
        .replace("stiffness = 1e4", "stiffness = 1e12");
    let sc = parse("s.toml", &near).expect("near π/2: not refused");
    let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
    assert!(out_of_tolerance(&sc, &o).is_empty());
}

/// θ0 = 0 with a push (the campaign's F8): the rigid wall force starts at exactly 0 and grows
/// at Ḟ_w0 = θ̇0 (Ω² − θ̇0²) m g per √(l/g) (d/dt of (14)'s cos θ Ω² sin θ − sin θ θ̇² at
/// θ = 0, written out here rather than taken from the code), so the rule on F_w0 cannot see
/// it. dopri5 at τ = 1e-4 from θ̇0 = 1e-5 (Ḟ_w0/τ = 0.075) is refused naming the tolerance
/// and the largest one, Ḟ_w0/75; that one is accepted and runs within the judge's bound for
/// dopri5, as Ḟ_w0/3500 for dop853; the refused scene run anyway at τ = 1e-3 ends at a
/// spurious zero (and so does its second try at 1e-4, `penalty::confirm::retry_control`);
/// radau5 is accepted.
#[test]
fn a_push_from_zero_looser_than_the_wall_force_rate_is_refused() {
    let springs = "model = \"penalty\"\nstiffness = 3e4\ndamping = 0.0";
    let at = |method: &str, tol: f64| {
        text(
            springs,
            &format!("method = \"{method}\"\ntolerance = {tol:e}"),
            "separation",
        )
        .replace("angle = 0.3", "angle = 0.0")
        .replace("angular_velocity = 0.0", "angular_velocity = 1e-5")
    };
    let rate: f64 = 1e-5;
    let growth = rate * (0.75 - rate * rate);
    let e = parse("s.toml", &at("dopri5", 1e-4))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("s.toml:14: [integrator] tolerance: the wall force starts at 0 m g (θ0 = 0e0) and grows by 7.500e-6 m g in the first √(l/g), below 75 times the tolerance")
            && e.contains("8.411e-1 rad before the separation"),
        "{e}"
    );
    for (method, need) in [("dopri5", 75.0), ("dop853", 3500.0)] {
        let largest = number_after(
            &parse("s.toml", &at(method, 1e-4)).unwrap_err().to_string(),
            "tolerance ≤ ",
        );
        // Error model: Ḟ_w0 from a dual number (a sine, two products and a sum, ≤ 4 u).
        assert!(
            (largest - growth / need).abs() <= 4.0 * f64::EPSILON * largest,
            "{method}: {largest}"
        );
        let sc = parse("s.toml", &at(method, largest)).expect("at the stated limit");
        let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
        assert!(out_of_tolerance(&sc, &o).is_empty(), "{method}");
        assert!(parse("s.toml", &at(method, largest * 1.01)).is_err());
    }
    let mut anyway = parse("s.toml", &at("dopri5", 1e-8)).expect("inside the limit");
    anyway.control = Some(sliding_ladder::sim::integrators::Control::Tolerance(1e-3));
    let failed = fall::run(&anyway, fall::MAX_STEPS).unwrap_err().to_string();
    assert!(failed.contains("not resolved"), "{failed}");
    assert!(parse("s.toml", &at("radau5", 1e-4)).is_ok());
}

/// The five scenes of seed 1's 1e5 campaign that failed at run time before the θ0 = 0 rule
/// (F8: pushes from θ0 = 0, dopri5/dop853 at τ = 2e-7..3.5e-4) are refused up front.
#[test]
fn the_campaigns_pushes_from_zero_are_refused_up_front() {
    for index in [16562, 24057, 50003, 81135, 84325] {
        let scene = sliding_ladder::report::campaign::draw_first(1, index);
        let e = parse("s.toml", &scene).unwrap_err().to_string();
        assert!(
            e.starts_with(
                "s.toml:14: [integrator] tolerance: the wall force starts at 0 m g (θ0 = 0e0)"
            ),
            "{index}: {e}"
        );
    }
}

/// Springs softer than κ = 5 lift the foot before the wall lets go (the campaign's 14 failures
/// of seed 1, κ = 1.02..1.55): κ = 2 is refused naming the stiffness and the least k; the least
/// k is accepted and separates within the judge's bound; κ = 2 run anyway lifts off (radau5 at
/// 1e-10 from θ0 = 0.6 at rest: an integration error cannot be the cause).
#[test]
fn springs_too_soft_to_hold_the_foot_are_refused_and_would_lift_it() {
    let at = |k: f64| {
        text(
            &format!("model = \"penalty\"\nstiffness = {k:e}\ndamping = 0.0"),
            "method = \"radau5\"\ntolerance = 1e-10",
            "separation",
        )
        .replace("angle = 0.3", "angle = 0.6")
    };
    let e = parse("s.toml", &at(2.0)).unwrap_err().to_string();
    assert!(
        e.starts_with("s.toml:10: [contact] stiffness: k l/(m g) = 2e0 is too soft"),
        "{e}"
    );
    let least = number_after(&e, "k ≥ ");
    assert_eq!(least, 5.0, "{e}");
    let sc = parse("s.toml", &at(least)).expect("the least stiffness");
    let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
    assert!(out_of_tolerance(&sc, &o).is_empty());
    assert!(parse("s.toml", &at(least * 0.99)).is_err());
    let mut soft = sc.clone();
    soft.contact = sliding_ladder::sim::scene::ContactModel::Penalty {
        stiffness: 2.0,
        damping: 0.0,
    };
    let lifted = fall::run(&soft, fall::MAX_STEPS).unwrap_err().to_string();
    assert!(lifted.contains("lift off the floor"), "{lifted}");
}

/// A fixed-step run of `sc` takes the plan's estimated steps in each phase, within one step
/// and the event's last partial step; returns the estimate.
fn takes_the_estimate(sc: &Scene) -> [f64; 2] {
    let est = estimate(sc);
    let o = fall::run(sc, fall::MAX_STEPS).unwrap();
    let got = [o.work.wall.steps, o.work.floor.map_or(0, |w| w.steps)];
    for (e, g) in est.iter().zip(got) {
        assert!(
            (e - g as f64).abs() <= 2.0,
            "{:?}: estimated {est:?}, took {got:?}",
            sc.end
        );
    }
    est
}

/// The plan's step estimate for each phase of a parsed scene.
fn estimate(sc: &Scene) -> [f64; 2] {
    phase_steps(
        &sc.ladder,
        (sc.theta0, sc.rate0),
        &sc.method,
        sc.control.unwrap(),
        sc.end,
        sc.contact,
    )
}

/// radau5 below its rounding floor on stiff springs (the 1e6-scene campaign: seed 1 scenes
/// 42205, 44765, 335462, 406910, 421769, κ ≈ 1e11 at τ ≈ 1e-16, over 1e6 steps) is refused;
/// at the floor the run is short, below it the run takes over 20 times as many steps.
#[test]
fn radau5_below_its_rounding_floor_on_stiff_springs_is_refused_and_would_crawl() {
    let stiff = "model = \"penalty\"\nstiffness = 1e12\ndamping = 0.0";
    let e = parse(
        "s.toml",
        &text(
            stiff,
            "method = \"radau5\"\ntolerance = 5e-16",
            "separation",
        ),
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("s.toml:14: [integrator] tolerance: "), "{e}");
    let floor = number_after(&e, "allowed: tolerance ≥ ");
    assert_eq!(floor, 1e-15, "{e}");
    let at = text(
        stiff,
        "method = \"radau5\"\ntolerance = 1e-15",
        "separation",
    );
    let mut sc = parse("s.toml", &at).expect("at the floor");
    let o = fall::run(&sc, fall::MAX_STEPS).expect("runs");
    assert!(out_of_tolerance(&sc, &o).is_empty());
    let steps = o.work.wall.steps;
    assert!(steps < 5_000, "{steps} steps at the floor");
    // Run anyway below it (the check bypassed): 20 times the steps do not reach the separation.
    sc.control = Some(sliding_ladder::sim::integrators::Control::Tolerance(2e-16));
    let r = fall::run(&sc, 20 * steps);
    assert!(r.is_err(), "2e-16 ran in {:?}", r.map(|o| o.work.wall));
    // Softer springs keep the tolerances down to 1e-16 (κ = 1e8 is at most 4.6e4 steps).
    let soft = "model = \"penalty\"\nstiffness = 1e8\ndamping = 0.0";
    let soft = text(
        soft,
        "method = \"radau5\"\ntolerance = 1.1e-16",
        "separation",
    );
    assert!(parse("s.toml", &soft).is_ok());
}

/// The near-flat refusal (F3) takes the push in the ladder's own units, θ̇0 √(l/g): at
/// g = 9.81 m/s², l = 1 m, θ0 = π/2 − 1e-7 pushed at 3e-4 rad/s, the rigid separation lies
/// asin((2/3) cos θ0 + (4/9) θ̇0² l/g) = 7.08e-8 rad from flat (footnote 4 with the push,
/// computed here in SI), which springs of κ = 5e6 cannot tell (their shift is
/// 1.25/κ = 2.5e-7). The push read as θ̇0 √(g/l) would put it 4.6e-7 from flat and let the
/// scene run (mutation testing: that went unseen, the refusal's tests were from rest or at
/// l = g = 1).
#[test]
fn the_near_flat_refusal_reads_the_push_in_the_ladder_s_units() {
    let (theta0, rate0, g) = (std::f64::consts::FRAC_PI_2 - 1e-7, 3e-4, 9.81);
    let kappa = 5e6;
    let text = format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = {g}\n[start]\nangle = {theta0:e}\nangular_velocity = {rate0:e}\n[contact]\nmodel = \"penalty\"\nstiffness = {:e}\ndamping = 0.0\n[integrator]\nmethod = \"radau5\"\ntolerance = 1e-10\n[end]\nat = \"separation\"\n[outputs]\nwant = [\"separation_angle\"]\n",
        kappa * g
    );
    let msg = parse("s.toml", &text).unwrap_err().to_string();
    // The refusal names the stiffness's own line (10 here) and field.
    assert!(
        msg.starts_with("s.toml:10: [contact] stiffness: springs of κ"),
        "{msg}"
    );
    assert!(
        msg.contains("cannot tell this start's separation from flat"),
        "{msg}"
    );
    let room = (2.0 / 3.0 * theta0.cos() + 4.0 / 9.0 * rate0 * rate0 / g).asin();
    let stated = number_after(&msg, "more than the ");
    // Stated to four digits ({:.3e}).
    assert!(
        (stated - room).abs() <= 5e-4 * room,
        "{stated:e} against {room:e}: {msg}"
    );
}

/// An `[end] time` bounds the step estimate like the run: a fixed-step run ending inside the
/// wall phase, or inside the floor phase, takes the estimated steps in each phase (within one
/// step and the event's last partial step, as above). Mutation testing: the `End::Time` arm of
/// `phase_steps` deleted (every end estimated as the whole fall) went unseen; so did its
/// `t / unit` → `t % unit` and `t · unit` at l = g = 1, hence g = 4 too, where √(l/g) = 1/2.
#[test]
fn an_end_time_bounds_the_step_estimate_as_it_bounds_the_run() {
    use sliding_ladder::sim::scene::End;
    for gravity in ["1.0", "4.0"] {
        let mut sc = parse(
            "s.toml",
            &text(
                "model = \"rigid\"",
                "method = \"rk4\"\nscaled_step = 1e-3",
                "flat",
            )
            .replace("[\"separation_angle\"]", "[\"flat_time\"]")
            .replace("gravity = 1.0", &format!("gravity = {gravity}")),
        )
        .unwrap();
        let whole = fall::run(&sc, fall::MAX_STEPS).unwrap();
        let (t_s, t_flat) = (whole.separation.unwrap().time, whole.flat.unwrap().time);
        for t_end in [0.5 * t_s, 0.5 * (t_s + t_flat)] {
            sc.end = End::Time(t_end);
            let est = takes_the_estimate(&sc);
            // The check can fail: the whole fall's estimate is hundreds of steps more.
            let full = estimate(&Scene {
                end: End::Flat,
                ..sc.clone()
            });
            assert!(
                full[0] + full[1] > est[0] + est[1] + 100.0,
                "{full:?} {est:?}"
            );
        }
    }
}

/// A phase may take at most `MAX_STEPS` steps, that many included: an end time of exactly
/// 1e7 fixed steps (2⁻¹⁹ s and 1e7 × 2⁻¹⁹ s, both exact in binary, l = g = 1; the wall phase
/// from θ0 = 1e-8 lasts some 22 s) is accepted
/// (only parsed, not run), and the next smaller step, one more than 1e7 steps, is refused
/// (mutation testing: `n > MAX_STEPS` → `>=` went unseen, no estimate met the limit exactly).
#[test]
fn a_phase_of_exactly_the_most_steps_allowed_is_accepted() {
    let at = |h: f64| {
        text(
            "model = \"rigid\"",
            &format!("method = \"rk4\"\nstep = {h:e}"),
            "time\"\ntime = 19.073486328125\n#\"",
        )
        .replace("angle = 0.3", "angle = 1e-8")
    };
    let h = 2f64.powi(-19);
    let sc = parse("s.toml", &at(h)).expect("exactly 1e7 steps");
    assert_eq!(estimate(&sc), [1e7, 0.0]);
    let smaller = h * (1.0 - f64::EPSILON);
    let e = parse("s.toml", &at(smaller)).unwrap_err().to_string();
    assert!(
        e.contains("[integrator] step: the wall phase needs about"),
        "{e}"
    );
}

/// A penalty scene's fixed step is converted to the model's time unit √(l/g) (h' = h/√(l/g)):
/// at g = 4 (unit ½) the run takes the steps the plan estimates, t_s/h' up to the model's
/// shift of the separation, 4/(κ sin θ_r) rad (`sim::penalty::confirm`), over θ̇_r, in steps
/// (mutation testing: `h / unit` → `h · unit` in `fall::penalty::run` went unseen, every
/// fixed-step penalty test had l = g = 1; it takes four times the steps here).
#[test]
fn a_penalty_scenes_fixed_step_is_taken_in_the_models_time_unit() {
    use sliding_ladder::sim::penalty::confirm::{rigid_separation_angle, MODEL_CONSTANT};
    let springs = "model = \"penalty\"\nstiffness = 4e4\ndamping = 0.0"; // κ = k l/(m g) = 1e4
    let sc = parse(
        "s.toml",
        &text(
            springs,
            "method = \"rk4\"\nscaled_step = 5e-4",
            "separation",
        )
        .replace("gravity = 1.0", "gravity = 4.0"),
    )
    .unwrap();
    let est = estimate(&sc);
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let theta_r = rigid_separation_angle(0.3, 0.0);
    let rate_r = (0.75 * theta_r.cos()).sqrt();
    let shift = MODEL_CONSTANT / (1e4 * theta_r.sin()) / rate_r / 5e-4;
    let got = o.work.wall.steps as f64;
    assert!(
        (got - est[0]).abs() <= 2.0 + shift,
        "estimated {est:?}, took {got} (allowed {:.1} more or fewer)",
        2.0 + shift
    );
}

/// An explicit adaptive method's step count on penalty springs (`explicit_penalty_steps`) is a
/// rate times the span: each of its stability, accuracy and rounding counts is steps per
/// √(l/g) at the given κ and τ, times t. So doubling or octupling the span multiplies the
/// count exactly, to the rounding of a few products. Checked where the accuracy count leads
/// (dopri5 at κ = 1e6, τ = 1e-10: about 7,500 t against the stability count's 2,100 t), as it
/// does for tight tolerances (mutation testing: `a · t · κ^… τ^…` → `a · t + κ^… τ^…` went
/// unseen; it counts a fixed 25,000 steps plus 0.3 t).
#[test]
fn an_explicit_methods_step_count_is_proportional_to_the_span() {
    use sliding_ladder::sim::scene::work::explicit_penalty_steps;
    let (kappa, tol) = (1e6f64, 1e-10);
    let omega = 2.0 * kappa.sqrt();
    for method in ["dopri5", "dop853"] {
        let one = explicit_penalty_steps(method, kappa, omega, 0.5, tol);
        for k in [2.0, 4.0, 16.0] {
            let more = explicit_penalty_steps(method, kappa, omega, 0.5 * k, tol);
            assert!(
                (more - k * one).abs() <= 8.0 * f64::EPSILON * more,
                "{method}: {more} for {k} times the span of {one}"
            );
        }
    }
    // The accuracy count leads for dopri5 here: above the stability count 1.05 ω t.
    let count = explicit_penalty_steps("dopri5", kappa, omega, 1.0, tol);
    assert!(count > 2.0 * 1.05 * omega, "{count}");
}

/// A penalty scene's push is converted to the model's units (θ̇' = θ̇ √(l/g)): at g = 4 a push
/// of 0.5 rad/s is 0.25 per √(g/l), and the separation lands where footnote 4 with the push
/// puts it, cos θ_r = (2/3) cos θ0 + 4 l θ̇0²/(9 g), within the run's stated bound
/// (`sim::penalty::confirm`: 4/(κ sin θ_r) + 10 N (τ + u) + 10 u). Mutation testing:
/// `θ̇0 · unit` → `θ̇0 / unit` in `fall::penalty::run`, and the separation rate's way back to
/// SI, `θ̇_s / unit` → `θ̇_s · unit` and `θ̇_s % unit`, went unseen (l = g = 1 or no push in
/// every penalty test); it pushes four times as fast, θ̇' = 1 > Ω √(cos θ0) = 0.85, so the
/// wall would have to pull at once and the ladder is reported leaving at θ0, 0.54 rad early.
#[test]
fn a_penalty_scenes_push_is_taken_in_the_models_units() {
    use sliding_ladder::sim::penalty::confirm::{separation_bound, MODEL_CONSTANT};
    let springs = "model = \"penalty\"\nstiffness = 4e4\ndamping = 0.0"; // κ = 1e4
    let sc = parse(
        "s.toml",
        &text(
            springs,
            "method = \"radau5\"\ntolerance = 1e-10",
            "separation",
        )
        .replace("gravity = 1.0", "gravity = 4.0")
        .replace("angular_velocity = 0.0", "angular_velocity = 0.5"),
    )
    .unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let theta_r = (2.0 / 3.0 * 0.3f64.cos() + 4.0 * 0.5 * 0.5 / (9.0 * 4.0)).acos();
    let bound = separation_bound(1e4, theta_r, o.work.wall.steps, 1e-10);
    let angle = o.separation.unwrap().angle;
    assert!(
        (angle - theta_r).abs() <= bound,
        "θ_s {angle} against {theta_r} (bound {bound:e})"
    );
    // The rate in SI: at the rigid zero θ̇² = Ω² cos θ (Ω² = 3g/(4l) = 3 s⁻² here); the
    // springs move it by O(1/κ), measured 2.1/κ relative, held to MODEL_CONSTANT/κ.
    let rate = o.separation.unwrap().rate;
    let rigid_rate = (3.0 * angle.cos()).sqrt();
    assert!(
        (rate - rigid_rate).abs() <= MODEL_CONSTANT / 1e4 * rigid_rate,
        "θ̇_s {rate} rad/s against {rigid_rate}"
    );
}

/// The floor phase's estimate uses the separation of a pushed start: cos θ_s = (2/3) cos θ0 +
/// (4/9) θ̇0² (footnote 4 with the push, θ̇0 in √(g/l)), and a fixed-step run from a push
/// takes the estimated steps in each phase, as above (mutation testing: `+ (4/9) θ̇0²` → `−`
/// in `phase_steps` went unseen, every estimate of a floor phase started at rest).
#[test]
fn the_step_estimate_of_a_pushed_start_matches_the_run() {
    let sc = parse(
        "s.toml",
        &text(
            "model = \"rigid\"",
            "method = \"rk4\"\nscaled_step = 1e-3",
            "flat",
        )
        .replace("[\"separation_angle\"]", "[\"flat_time\"]")
        .replace("angular_velocity = 0.0", "angular_velocity = 0.5"),
    )
    .unwrap();
    takes_the_estimate(&sc);
}

/// The plan's separation time of a pushed start below 1e-100 (the linear lead-in to 1e-100,
/// then the closed form) in SI: the start's size is a = θ̇0 T/Ω (T = √(l/g), Ω = √(3/4)), and
/// the reference is the tiny starts' (tests/sim/fall/tiny_starts.rs): t_s = t_s(1e-12 from rest) +
/// ln(1e-12/a)/Ω, linear to O(θ²) below 1e-12. Both are sums of a few hundred T with a
/// logarithm's rounding: 16 ε relative. Read off a fixed step's count (t_s/h, h = T/100).
/// The start's size only splits t_s between the lead-in and the closed form, so an error in
/// it cancels (mutation testing found two such mutants equivalent); the rate handed to the
/// closed form does not: θ̇0 T → θ̇0/T there is 1.6 T off at T = 2 (tried by hand).
#[test]
fn a_pushed_tiny_starts_separation_time_is_the_linear_lead_in_s() {
    use sliding_ladder::ladder::Ladder;
    use sliding_ladder::sim::exact::PhaseOne;
    use sliding_ladder::sim::integrators::Control;
    use sliding_ladder::sim::scene::{ContactModel, End};
    let omega = 0.75f64.sqrt();
    let t1 = PhaseOne::new(1e-12, 0.0, 0.75)
        .unwrap()
        .separation()
        .unwrap()
        .time;
    for (l, g) in [(4.0f64, 1.0f64), (1e18, 1e-6)] {
        let ladder = Ladder { m: 1.0, l, g };
        let t = (l / g).sqrt();
        let rate0 = 1e-230;
        let steps = phase_steps(
            &ladder,
            (0.0, rate0),
            "rk4",
            Control::Fixed(0.01 * t),
            End::Separation,
            ContactModel::Rigid,
        )[0];
        let got = 0.01 * steps;
        let a = rate0 * t / omega;
        let want = t1 + (1e-12f64.ln() - a.ln()) / omega;
        assert!(
            (got - want).abs() <= 16.0 * f64::EPSILON * want,
            "l = {l}, g = {g}: {got} T against {want} T"
        );
    }
}

/// An explicit Euler scene with a fixed step on undamped springs of stiffness `k` (N/m).
fn euler_on_springs(k: f64, step: f64) -> String {
    text(
        &format!("model = \"penalty\"\nstiffness = {k:e}\ndamping = 0.0"),
        &format!("method = \"euler\"\nstep = {step:e}"),
        "separation",
    )
}

/// The exact closed form's t_s in √(l/g) from θ0 and θ̇0 (in √(g/l)).
fn exact_separation_time(theta0: f64, rate0: f64) -> f64 {
    use sliding_ladder::sim::exact::PhaseOne;
    let phase = PhaseOne::new(theta0, rate0, 0.75).unwrap();
    phase.separation().unwrap().time
}

/// The Euler refusal of `scene(step)` states the limit `want` (√(l/g)) in seconds (unit
/// `unit` s) and in √(l/g), each to 4 ε: a product and a quotient or root on each side, and
/// where `want` holds t_s, the plan's closed form takes Ω² = (√0.75)², an ulp below 0.75,
/// which moves a t_s from rest by half an ulp at most (at θ0 = 0.01, not at all). A step 1 %
/// inside is accepted, 1 % outside refused.
fn assert_euler_limit(scene: impl Fn(f64) -> String, want: f64, unit: f64) {
    let msg = parse("s.toml", &scene(10.0 * want * unit))
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("explicit Euler gains energy on every oscillation"),
        "{msg}"
    );
    let seconds = number_after(&msg, "a step ≤ ");
    let scaled = number_after(&msg, "s (");
    let close = |got: f64, want: f64| (got - want).abs() <= 4.0 * f64::EPSILON * want;
    assert!(close(scaled, want), "{msg}: want {want}");
    assert!(close(seconds, want * unit), "{msg}: want {} s", want * unit);
    let inside = scene(0.99 * want * unit);
    assert!(parse("s.toml", &inside).is_ok(), "inside the limit");
    let outside = scene(1.01 * want * unit);
    assert!(parse("s.toml", &outside).is_err(), "outside it");
}

/// Explicit Euler gains energy by (h ω)² a step, so over the wall phase's t_s/h steps its
/// drift is h ω² t_s: the stated limit is h ≤ 0.02/(ω² t_s) (in √(l/g)), below h ω ≤ 0.2 once
/// ω t_s > 0.1. Here k = 100 undamped at g = 4, l = m = 1 (T = 0.5 s, κ = k l/(m g) = 25,
/// ω = 2√κ = 10 exactly) and θ0 = 0.01 from rest (t_s ≈ 7 √(l/g), from the exact closed form,
/// the same the plan uses). Mutation testing: ω² t_s → ω²/t_s and → ω + ω t_s in `check_work`
/// went unseen, the one Euler refusal test asked only that a refusal came.
#[test]
fn explicit_eulers_step_limit_is_its_energy_gain_over_the_wall_phase() {
    let scene = |step: f64| {
        euler_on_springs(100.0, step)
            .replace("gravity = 1.0", "gravity = 4.0")
            .replace("angle = 0.3", "angle = 0.01")
    };
    let t_s = exact_separation_time(0.01, 0.0);
    assert!(
        t_s > 5.0,
        "t_s = {t_s}: far from 1, where ω² t_s and ω²/t_s agree"
    );
    assert_euler_limit(scene, 0.02 / (100.0 * t_s), 0.5);
}

/// Where the wall phase is short (ω t_s < 0.1) explicit Euler's limit is the springs' own,
/// h ω ≤ 0.2: from θ0 = 0.3 with a push of 0.84 √(g/l), just under the 0.846 that leaves the
/// wall at once, t_s ≈ 0.019 √(l/g), and the softest springs a scene takes (κ = 5, ω = 2√5)
/// give h ≤ 0.2/ω = 0.0447 √(l/g), below the energy bound 0.02/(ω² t_s). Mutation testing:
/// `0.2/ω` → `0.2 % ω` and → `0.2 ω` there went unseen, every Euler scene had ω t_s far
/// above 0.1.
#[test]
fn explicit_eulers_step_limit_on_a_short_wall_phase_is_the_springs() {
    let scene = |step: f64| {
        euler_on_springs(5.0, step).replace("angular_velocity = 0.0", "angular_velocity = 0.84")
    };
    let omega = 2.0 * 5f64.sqrt();
    let t_s = exact_separation_time(0.3, 0.84);
    assert!(omega * t_s < 0.1, "ω t_s = {}", omega * t_s);
    assert!(0.02 / (omega * omega * t_s) > 0.2 / omega);
    assert_euler_limit(scene, 0.2 / omega, 1.0);
}

//! The floor phase (beyond the note, equations/phase2.md): its equation of motion checked against
//! energy conservation with dual numbers, continuity at separation, and the whole fall: energy
//! and the horizontal momentum balance held, the floor force positive, the top clear of the wall.

use num_dual::{Dual64, DualNum};
use sliding_ladder::report::work_precision::scene_at;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::floor;
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::rigid;

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::scene::output::Output;
use sliding_ladder::sim::scene::End;

const LADDER: Ladder<f64> = Ladder {
    m: 1.3,
    l: 0.7,
    g: 9.81,
};

/// dE/dt along the floor-phase motion, by lifting (θ, θ̇) to dual numbers along the motion
/// (θ → θ + θ̇ε, θ̇ → θ̇ + θ̈ε, Ẋ constant), with θ̈ from `floor::angular_acceleration` plus `bump`.
fn energy_rate(theta: f64, rate: f64, vx: f64, bump: f64) -> f64 {
    let g_over_l = LADDER.g / LADDER.l;
    let acc = floor::angular_acceleration(g_over_l, theta, rate) + bump;
    let (m, l, g) = (LADDER.m, LADDER.l, LADDER.g);
    let th = Dual64::new(theta, rate);
    let w = Dual64::new(rate, acc);
    let s = th.sin();
    let e = (s * s + 1.0 / 3.0) * w * w * (0.5 * m * l * l)
        + th.cos() * (m * g * l)
        + 0.5 * m * vx * vx;
    e.eps
}

/// Energy is conserved exactly by the phase-2 equation (to rounding), and a perturbed θ̈ breaks it.
/// Scale of the cancelling terms: m l² θ̇ θ̈ ~ m g l θ̇, so allow 16 ulps of m g l (|θ̇| + 1).
#[test]
fn phase2_equation_conserves_energy_and_a_perturbed_one_does_not() {
    let scale = LADDER.m * LADDER.g * LADDER.l;
    for &(theta, rate) in &[(0.2, 0.5), (0.9, 2.1), (1.3, 3.0), (1.55, 0.1)] {
        let tol = 16.0 * f64::EPSILON * scale * (rate + 1.0);
        assert!(energy_rate(theta, rate, 0.8, 0.0).abs() <= tol);
        assert!(energy_rate(theta, rate, 0.8, 1e-6).abs() > tol);
    }
}

/// At separation (θ̇² = Ω² cos θ) the phase-2 θ̈ equals eq. (5)'s Ω² sin θ and the floor force
/// equals the wall phase's (mg/4 there); F_w is zero.
#[test]
fn phase2_continues_phase1_at_separation() {
    let w2 = LADDER.big_omega2();
    for theta in [0.5, 0.84, 1.2] {
        let rate = (w2 * f64::cos(theta)).sqrt();
        let a2 = floor::angular_acceleration(LADDER.g / LADDER.l, theta, rate);
        let a1: f64 = rigid::angular_acceleration(w2, theta);
        assert!(
            (a2 - a1).abs() <= 8.0 * f64::EPSILON * a1.abs(),
            "{a2} vs {a1}"
        );
        let f2 = floor::floor_force(&LADDER, theta, rate);
        let f1 = rigid::floor_force(&LADDER, theta, rate);
        let mg = LADDER.m * LADDER.g;
        assert!(
            (f2 - f1).abs() <= 16.0 * f64::EPSILON * mg
                && (f1 - mg / 4.0).abs() <= 16.0 * f64::EPSILON * mg
        );
        assert!(rigid::wall_force(&LADDER, theta, rate).abs() <= 16.0 * f64::EPSILON * mg);
    }
}

fn full_fall(theta0: f64, rate0: f64) -> fall::Outcome {
    let mut sc = scene_at(theta0, rate0);
    sc.ladder = LADDER;
    sc.control = Some(Control::Tolerance(1e-14));
    sc.end = End::Flat;
    sc.outputs = vec![
        Output::FlatTime,
        Output::FloorForceMin,
        Output::TopClearanceMin,
        Output::EnergyError,
        Output::MomentumError,
    ];
    fall::run(&sc, fall::MAX_STEPS).unwrap()
}

/// Whole fall with DOP853 at 1e-14: energy to 1e-13 of m g l (tolerance-proportional, ~100
/// steps), the horizontal momentum balance m Ẋ_end − m Ẋ_0 = ∫F_w dt to the error model,
/// the floor force positive, the top never back at the wall, and θ = π/2 at the end (to the
/// flat event's time resolution).
#[test]
fn the_whole_fall_conserves_and_stays_on_the_floor() {
    for (theta0, rate0) in [(0.0, 1e-6), (0.3, 0.0), (1.4, 0.0)] {
        let o = full_fall(theta0, rate0);
        let flat = o.flat.expect("reaches flat");
        assert!(flat.time > o.separation.unwrap().time);
        // θ = π/2 at the end to the event's time resolution (`sim::event`: Newton stops at 8
        // ulps of t), i.e. |θ̇| 8 ε t, plus the rounding of θ = π/2 − φ.
        let (t, theta, rate) = o.last;
        let resolution = rate.abs() * 8.0 * f64::EPSILON * t + 4.0 * f64::EPSILON;
        assert!(
            (theta - std::f64::consts::FRAC_PI_2).abs() <= resolution,
            "{theta0}: {:e} against {resolution:e}",
            theta - std::f64::consts::FRAC_PI_2
        );
        assert!(
            o.energy_error.unwrap() <= 1e-13,
            "energy {:e}",
            o.energy_error.unwrap()
        );
        // The momentum balance (tests/sim/fall/momentum_balance.rs): 4 (10 N τ + 4u) √(g/l)·l.
        let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
        let p_scale = (LADDER.g * LADDER.l).sqrt();
        let p_bound = 4.0 * (10.0 * n * 1e-14 + 4.0 * f64::EPSILON) * p_scale;
        assert!(
            o.momentum_error.unwrap() <= p_bound,
            "{:?}",
            o.momentum_error
        );
        let r = o.floor_report.unwrap();
        assert!(r.floor_force_min > 0.0, "floor force {}", r.floor_force_min);
        assert!(
            r.top_clearance_min > 0.0,
            "top clearance {}",
            r.top_clearance_min
        );
        assert!(o.work.force_evals > 0);
    }
}

/// The flat state has Ẋ = l cos θ_s θ̇_s (kept from separation) and, from energy conservation,
/// ½ m Ẋ² + (2/3) m l² θ̇² = m g l cos θ0 + (2/3) m l² θ̇0² at θ = π/2 (sin² + 1/3 = 4/3).
#[test]
fn flat_state_from_conservation_laws() {
    let o = full_fall(0.3, 0.0);
    let (s, f) = (o.separation.unwrap(), o.flat.unwrap());
    let l = LADDER.l;
    assert!(
        (f.centre_velocity_x - l * s.angle.cos() * s.rate).abs()
            <= 1e-15 * f.centre_velocity_x.abs() * 4.0
    );
    let (m, g) = (LADDER.m, LADDER.g);
    let lhs = 0.5 * m * f.centre_velocity_x.powi(2) + 2.0 / 3.0 * m * l * l * f.rate.powi(2);
    let rhs = m * g * l * 0.3f64.cos();
    assert!((lhs - rhs).abs() <= 1e-13 * rhs, "{lhs} vs {rhs}");
}

/// The floor phase's error scale (`Ode::scale`, the size each component's error is measured
/// against) is the motion's own: an angle of size max(|θ|, |θ̇|/Ω) (what θ̇ turns the ladder by
/// in a time 1/Ω), a length of max(|X|, |Ẋ|/Ω, l times that angle), and the rates Ω times those.
/// Checked where each maximum is taken by the other term, with l a ≠ l + a (mutation testing:
/// |θ̇|/Ω → |θ̇| % Ω and l a → l + a went unseen; they change only how tightly runs are
/// controlled).
#[test]
fn the_floor_phase_measures_errors_in_its_own_scales() {
    use sliding_ladder::sim::integrators::Ode;
    let ladder = Ladder {
        m: 1.0,
        l: 2.0,
        g: 24.0, // Ω² = 3g/(4l) = 9: Ω = 3
    };
    let sys = floor::FloorPhase::new(&ladder);
    // The simulator's floor phase in the complement, (φ, X, φ̇, Ẋ), measures the same way
    // (mutation testing: its |Ẋ|/Ω → |Ẋ| % Ω and |Ẋ| Ω went unseen).
    let comp = sliding_ladder::sim::complement::ComplementFloor::new(&ladder);
    // (θ, X, θ̇, Ẋ) → (angle, length): the rate's term wins, then the position's.
    for (y, angle, length) in [
        ([0.1, 0.5, 9.0, 0.3], 3.0, 6.0),
        ([0.5, 0.2, 0.3, 9.0], 0.5, 3.0),
    ] {
        let want = [angle, length, 3.0 * angle, 3.0 * length];
        assert_eq!(sys.scale(&y), want, "{y:?}");
        assert_eq!(comp.scale(&y), want, "complement {y:?}");
    }
}

/// The floor phase's energy (`floor::energy`) is the body's, ½ m (Ẋ² + Ẏ²) + ½ (m l²/3) θ̇² +
/// m g Y, with the centre's height Y = l cos θ and its rate Ẏ by a dual number along the
/// motion, not from the printed ½ m l² (sin²θ + 1/3) θ̇². All terms are positive for θ < π/2,
/// so the two agree to a few ulps of their sum. A run that ends by time inside the floor phase
/// reports the energy change to the whole fall's bound (1e-13 m g l at τ = 1e-14, above): at
/// its end cos θ is far from 0, so a wrong potential term shows there (mutation testing:
/// + m g l cos θ → − went unseen: every run that asked for the energy ended flat, cos θ = 0).
#[test]
fn the_floor_energy_is_the_bodys_and_a_run_ending_on_the_floor_keeps_it() {
    let (m, l, g) = (LADDER.m, LADDER.l, LADDER.g);
    for (theta, rate, vx) in [(0.2, 0.5, 0.8), (0.9, 2.1, -0.3), (1.4, 3.0, 1.7)] {
        let y = Dual64::new(theta, rate).cos() * l;
        let body = 0.5 * m * (vx * vx + y.eps * y.eps)
            + 0.5 * (m * l * l / 3.0) * rate * rate
            + m * g * y.re;
        let got = floor::energy(&LADDER, theta, rate, vx);
        assert!(
            (got - body).abs() <= 8.0 * f64::EPSILON * body,
            "θ {theta}: {got} against the body's {body}"
        );
    }
    let whole = full_fall(0.3, 0.0);
    let (t_s, t_flat) = (whole.separation.unwrap().time, whole.flat.unwrap().time);
    let mut sc = scene_at(0.3, 0.0);
    sc.ladder = LADDER;
    sc.control = Some(Control::Tolerance(1e-14));
    sc.end = End::Time(0.5 * (t_s + t_flat));
    sc.outputs = vec![Output::FinalState, Output::EnergyError];
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let theta_end = o.last.1;
    assert!(
        theta_end > whole.separation.unwrap().angle && theta_end.cos() > 0.1,
        "the end lies inside the floor phase, away from flat: θ = {theta_end}"
    );
    let err = o.energy_error.unwrap();
    assert!(err <= 1e-13, "energy {err:e}");
}

/// The energy error is |E_flat − E0| / (m g l), recomputed here from the flat state the run
/// reports, in SI (m = 2, l = 3, g = 9.81): E0 = m g l cos θ0 at rest, and at flat (θ = π/2)
/// E = ½ m (Ẋ² + Ẏ²) + ½ (m l²/3) θ̇². Explicit Euler at a step of 0.05 s gains some 0.3 %, so
/// the check has a number to compare. Error model: energies of size m g l, a few roundings
/// each and the flat state's conversion to SI: 32 ε. (Mutation testing: the unit
/// `m g l` → `m + g l`, 2 on the unit ladder the run uses, went unseen: every check of the
/// energy error was an upper bound.)
#[test]
fn the_energy_error_is_the_flat_states_energy_change() {
    use sliding_ladder::sim::scene;
    let (m, l, g, theta0) = (2.0, 3.0, 9.81, 0.3);
    let text = format!("[ladder]\nmass = {m}\nhalf_length = {l}\ngravity = {g}\n[start]\nangle = {theta0}\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"euler\"\nstep = 0.05\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"energy_error\", \"flat_state\"]\n");
    let sc = scene::parse("energy.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let f = o.flat.unwrap();
    let e0 = m * g * l * theta0.cos();
    let e_flat = 0.5 * m * (f.centre_velocity_x.powi(2) + f.centre_velocity_y.powi(2))
        + 0.5 * (m * l * l / 3.0) * f.rate * f.rate;
    let want = (e_flat - e0).abs() / (m * g * l);
    let got = o.energy_error.unwrap();
    assert!(want > 1e-3, "Euler's energy change {want}");
    assert!(
        (got - want).abs() <= 32.0 * f64::EPSILON * (e0 + e_flat) / (m * g * l),
        "{got} against {want}"
    );
}

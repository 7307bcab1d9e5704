//! Tests of `sliding_ladder::verify::claims::golfer` (src/verify/claims/golfer/): sec. B.10's
//! golfer's nemesis (Milne sec. 421), a ball rolling inside a vertical cylinder, its 3-D model
//! held to the closed form, and the wrong physics that the comparison refuses.

use sliding_ladder::verify::claims::golfer::closed_form::ClosedForm;
use sliding_ladder::verify::claims::golfer::compare::{Judgement, READINGS};
use sliding_ladder::verify::claims::golfer::model::{parts, Contact, Perturbation};
use sliding_ladder::verify::claims::golfer::{
    agrees, claims, hold, Ball, Setup, HOLLOW, PERIODS, RTOL, SOLID,
};

const ROLLING: (Contact, Perturbation) = (Contact::Rolling, Perturbation::None);

fn with_k(setup: Setup, k: f64) -> Setup {
    Setup {
        ball: Ball { k, ..setup.ball },
        ..setup
    }
}

/// Another cylinder, ball, gravity and start: the Moon's g, a 0.2 m ball of 2 kg in a 1 m
/// cylinder, a slower orbit, a start above z = 0 and a spin about the normal (which moves the
/// centre of the oscillation, not its frequency).
fn elsewhere(k: f64) -> Setup {
    Setup {
        ball: Ball { m: 2.0, a: 0.1, k },
        b: 0.5,
        g: 1.62,
        orbit_rate: 3.0,
        z0: 1.0,
        sink_rate: -0.5,
        normal_spin: 2.0,
    }
}

fn judged(setup: &Setup, run: (Contact, Perturbation), k: f64) -> Judgement {
    hold(setup, run, k, RTOL, PERIODS).expect("the run integrates")
}

/// The readings that fail, by name.
fn failing(j: &Judgement) -> Vec<&'static str> {
    let allowed = j.allowed();
    (0..READINGS.len())
        .filter(|&i| j.deviation[i] > allowed[i])
        .map(|i| READINGS[i])
        .collect()
}

#[test]
fn the_golf_ball_comes_back_up_as_the_closed_form_says() {
    let golf = Setup::golf();
    let j = judged(&golf, ROLLING, SOLID);
    assert!(j.agrees(), "failing: {:?}", failing(&j));
    // One lowest point per period, at a finite depth, and back at the start every period.
    let cf = ClosedForm::of(&golf, SOLID);
    assert_eq!(j.readings.lows.len(), PERIODS);
    assert!(j
        .readings
        .lows
        .iter()
        .all(|z| z.is_finite() && *z < golf.z0));
    assert_eq!(j.readings.periods.len(), PERIODS - 1);
    // ω_z = √(2/7) Ω for the solid ball.
    assert_eq!(cf.omega_z, golf.orbit_rate * (2.0f64 / 7.0).sqrt());
    let claim = claims().pop().expect("one claim");
    assert!(claim.location == "sec. B.10" && claim.holds && claim.erratum.is_none());
}

#[test]
fn another_ball_cylinder_and_gravity_agree_with_their_own_closed_form() {
    for k in [SOLID, HOLLOW] {
        let j = judged(&elsewhere(k), ROLLING, k);
        assert!(j.agrees(), "k = {k}: failing {:?}", failing(&j));
    }
}

#[test]
fn on_a_frictionless_wall_the_ball_falls_and_never_comes_back() {
    // (a) No rolling constraint, only a normal force: z̈ = −g, no lowest point, the check fails.
    let golf = Setup::golf();
    assert!(!agrees(
        &golf,
        (Contact::Frictionless, Perturbation::None),
        SOLID
    ));
    let j = judged(&golf, (Contact::Frictionless, Perturbation::None), SOLID);
    assert!(j.readings.lows.is_empty());
    assert!(failing(&j).contains(&"height back at each period"));
    // It falls as z₀ + ż₀ t − g t²/2: DOP853 is exact on a quadratic, so only rounding
    // separates them (8 ε per step on the largest term).
    let period = ClosedForm::of(&golf, SOLID).period();
    for (i, (z, w)) in j
        .readings
        .returns
        .iter()
        .zip(&j.readings.return_rate)
        .enumerate()
    {
        let t = (i + 1) as f64 * period;
        let size = golf.z0.abs() + golf.sink_rate.abs() * t + golf.g * t * t;
        let allowed = j.steps as f64 * 8.0 * f64::EPSILON * size;
        assert!((z - (golf.z0 + golf.sink_rate * t - golf.g * t * t / 2.0)).abs() <= allowed);
        assert!((w - (golf.sink_rate - golf.g * t)).abs() <= allowed / t);
    }
}

#[test]
fn the_solid_and_hollow_frequencies_are_told_apart() {
    // (b) ω_z = √(2/7) Ω solid, √(2/5) Ω hollow: each run fails the other's closed form.
    let golf = Setup::golf();
    let solid_as_hollow = judged(&golf, ROLLING, HOLLOW);
    assert!(!solid_as_hollow.agrees());
    assert!(failing(&solid_as_hollow).contains(&"period between lowest points"));
    let hollow = with_k(golf, HOLLOW);
    assert!(agrees(&hollow, ROLLING, HOLLOW) && !agrees(&hollow, ROLLING, SOLID));
}

#[test]
fn a_perturbed_term_of_the_model_fails_the_comparison() {
    // (c) The constraint without ω × (a n), the constraint's rate without ṅ, or k off by 1 %.
    let golf = Setup::golf();
    for p in [Perturbation::SpinTermDropped, Perturbation::NormalFrozen] {
        assert!(!agrees(&golf, (Contact::Rolling, p), SOLID), "{p:?}");
    }
    assert!(!agrees(&with_k(golf, SOLID * 1.01), ROLLING, SOLID));
    // The drift of the rolling constraint alone exposes ṅ dropped.
    let frozen = judged(&golf, (Contact::Rolling, Perturbation::NormalFrozen), SOLID);
    assert!(failing(&frozen).contains(&"rolling constraint (slip)"));
}

#[test]
fn the_contact_force_at_the_start_is_the_closed_forms() {
    // At the start n = x̂, e_φ = ŷ: F_r = −m ρ Ω² (the centripetal force), F_φ = m ρ φ̈ = 0,
    // F_z = m (g + z̈₀) with z̈₀ = −(g + k a Ω ω_r₀)/(1 + k). The model solves a 3 × 3 system
    // whose terms are of size m g and m ρ Ω²: a few ulps of those.
    for setup in [Setup::golf(), elsewhere(HOLLOW), elsewhere(SOLID)] {
        let Ball { m, a, k } = setup.ball;
        let (rho, o) = (setup.b - a, setup.orbit_rate);
        let f = setup
            .model(Contact::Rolling, Perturbation::None)
            .contact_force::<f64>(parts(&setup.start()));
        let z_accel = -(setup.g + k * a * o * setup.normal_spin) / (1.0 + k);
        let expected = [-m * rho * o * o, 0.0, m * (setup.g + z_accel)];
        let ulps = 32.0 * f64::EPSILON * m * (setup.g + rho * o * o);
        for i in 0..3 {
            assert!(
                (f[i] - expected[i]).abs() <= ulps,
                "{i}: {} vs {}",
                f[i],
                expected[i]
            );
        }
    }
}

#[test]
fn an_estimate_that_is_not_finite_allows_nothing() {
    // Two runs that do not find the same lowest points estimate no error: an infinite estimate
    // allows nothing.
    let golf = Setup::golf();
    let mut j = judged(&golf, ROLLING, SOLID);
    assert!(j.agrees());
    j.estimate[3] = f64::INFINITY;
    assert!(!j.agrees());
}

#[test]
fn an_estimate_that_does_not_shrink_with_the_tolerance_allows_nothing() {
    // A reading whose difference between tolerances falls only by half per factor 100 (as a
    // lowest point located only to within a step would) is no error estimate.
    let golf = Setup::golf();
    let mut j = judged(&golf, ROLLING, SOLID);
    assert!((0..READINGS.len()).all(|i| j.converges(i)));
    j.next_estimate[3] = j.estimate[3] / 2.0;
    assert!(!j.converges(3) && !j.agrees());
}

/// The error norm's length ℓ = b + |ż₀|/Ω + g/Ω², by hand for the golf setup: b = 0.054 m,
/// |ż₀|/Ω = 0.3/20 = 0.015 m, g/Ω² = 9.81/400 = 0.024525 m, so ℓ = 0.093525 m; the sink
/// rate enters by its size (a rising start gives the same ℓ).
#[test]
fn setup_length_is_the_radius_plus_the_sink_and_sag_lengths() {
    let golf = Setup::golf();
    assert!((golf.length() - 0.093525).abs() <= 4.0 * f64::EPSILON * 0.093525);
    let rising = Setup {
        sink_rate: -golf.sink_rate,
        ..golf
    };
    assert_eq!(rising.length(), golf.length());
}

/// The model's state scale (the error norm's, per component of x, v, ω) is the orbit's own
/// size: lengths ℓ, speeds ℓΩ (a point orbiting at Ω a distance ℓ from the axis), spins ℓΩ/a
/// (the spin that rolls the ball at that speed). By hand for the golf ball: ℓ = 0.093525 m,
/// Ω = 20 rad/s, a = 0.021335 m, so ℓΩ = 1.8705 m/s and ℓΩ/a = 1.8705/0.021335 rad/s; each
/// within a few roundings of the products and quotients that form it.
#[test]
fn setup_model_scales_the_state_by_the_orbits_lengths_speeds_and_spins() {
    use sliding_ladder::sim::integrators::Ode;
    let golf = Setup::golf();
    let model = golf.model(ROLLING.0, ROLLING.1);
    let scale = model.scale(&golf.start());
    let (l, v, w) = (0.093525, 1.8705, 1.8705 / 0.021335);
    let close = |a: f64, b: f64| (a - b).abs() <= 8.0 * f64::EPSILON * b;
    for k in 0..3 {
        assert!(close(scale[k], l), "x scale {}", scale[k]);
        assert!(close(scale[3 + k], v), "v scale {}", scale[3 + k]);
        assert!(close(scale[6 + k], w), "ω scale {}", scale[6 + k]);
    }
}

/// Each reading's rounding floor has the reading's dimension (height, returns, lows and radius
/// a length; the return rate and slip a velocity; periods a time; the orbit rate a rate):
/// rescale the setup's lengths by k and every length and velocity floor scales by k, the rest
/// stay; rescale its time by 1/k (Ω, ż₀ × k, g × k², the run's length / k) and velocities and
/// the orbit rate scale by k, times by 1/k, lengths stay.
#[test]
fn rounding_floor_has_each_readings_dimension() {
    use sliding_ladder::verify::claims::golfer::compare::rounding_floor;
    let golf = Setup::golf();
    let (steps, run) = (1000, 2.0);
    let base = rounding_floor(&golf, steps, run);
    let k = 8.0; // a power of two: the scalings are exact
    let longer = Setup {
        ball: Ball {
            a: golf.ball.a * k,
            ..golf.ball
        },
        b: golf.b * k,
        g: golf.g * k,
        z0: golf.z0 * k,
        sink_rate: golf.sink_rate * k,
        ..golf
    };
    let faster = Setup {
        g: golf.g * k * k,
        orbit_rate: golf.orbit_rate * k,
        sink_rate: golf.sink_rate * k,
        ..golf
    };
    // Length, time exponents of each reading, in READINGS' order.
    let dims = [
        (1, 0),
        (1, 0),
        (1, -1),
        (0, 1),
        (1, 0),
        (0, -1),
        (1, -1),
        (1, 0),
    ];
    let by_length = rounding_floor(&longer, steps, run);
    let by_time = rounding_floor(&faster, steps, run / k);
    for (i, (len, time)) in dims.iter().enumerate() {
        // Scaling by a power of two commutes with every rounding: the floors agree exactly.
        assert_eq!(
            by_length[i],
            base[i] * k.powi(*len),
            "{}: length",
            READINGS[i]
        );
        assert_eq!(
            by_time[i],
            base[i] * k.powi(-*time),
            "{}: time",
            READINGS[i]
        );
    }
}

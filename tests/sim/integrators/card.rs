//! The table of integrators (`sim::integrators::TABLE`): every card is held against the method
//! it describes. A card is read by the scene checks, the penalty plans, work-precision, the
//! stability report and the campaign, so a card that lies about its method misleads all of them.

use num_dual::DualNum;
use sliding_ladder::sim::integrators::card::{ControlKind, Stiffness};
use sliding_ladder::sim::integrators::{AnyStepper, Control, Ode, Stepper, TABLE};

/// q'' = −ω² q with ω = 1, as [q, v].
struct Oscillator;

impl Ode<2> for Oscillator {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
        [y[1], -y[0]]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
}

/// The largest |q| over steps n..2n against the largest over steps 0..n, for a fixed step h on
/// the oscillator from q = 1: near 1 when the step is stable, far above 1 when it is not
/// (infinite when the state leaves f64).
fn growth(method: &str, h: f64, n: usize) -> f64 {
    let mut s = AnyStepper::new(method, Control::Fixed(h), 0.0, [1.0, 0.0]).expect("a step");
    let mut peak = [0.0f64; 2];
    for i in 0..2 * n {
        if s.step(&Oscillator, f64::INFINITY).is_err() {
            return f64::INFINITY;
        }
        peak[i / n] = peak[i / n].max(s.y()[0].abs());
    }
    peak[1] / peak[0]
}

#[test]
fn every_card_names_a_method_that_starts_with_its_own_control_only() {
    for (i, c) in TABLE.iter().enumerate() {
        assert!(
            TABLE[..i].iter().all(|d| d.name != c.name),
            "{} twice",
            c.name
        );
        let (own, other) = match c.control {
            ControlKind::Step => (Control::Fixed(0.01), Control::Tolerance(1e-8)),
            ControlKind::Tolerance => (Control::Tolerance(1e-8), Control::Fixed(0.01)),
        };
        assert!(
            AnyStepper::<2>::new(c.name, own, 0.0, [1.0, 0.0]).is_some(),
            "{}",
            c.name
        );
        assert!(
            AnyStepper::<2>::new(c.name, other, 0.0, [1.0, 0.0]).is_none(),
            "{}",
            c.name
        );
        assert!(!c.sweep.controls().is_empty(), "{}: an empty sweep", c.name);
        for control in c.sweep.controls() {
            assert_eq!(
                matches!(control, Control::Tolerance(_)),
                c.is_adaptive(),
                "{}: its sweep is of the other control",
                c.name
            );
        }
    }
    assert!(
        AnyStepper::<2>::new("no-such-method", Control::Fixed(0.01), 0.0, [1.0, 0.0]).is_none()
    );
}

/// Each fixed-step card's oscillation limit is the method's: 1 % below it the oscillation stays
/// bounded over 20,000 steps, 1 % above it grows (a limit of 0: it grows at h ω = 0.5).
/// A card off by a few percent either way fails one of the two.
#[test]
fn every_fixed_step_cards_oscillation_limit_is_its_methods() {
    let n = 10_000;
    for c in TABLE.iter().filter(|c| !c.is_adaptive()) {
        let Stiffness::Explicit { oscillation_limit } = c.stiffness else {
            continue;
        };
        if oscillation_limit == 0.0 {
            let g = growth(c.name, 0.5, n);
            assert!(g > 10.0, "{}: grows by only {g} at h ω = 0.5", c.name);
            continue;
        }
        let below = growth(c.name, oscillation_limit * 0.99, n);
        let above = growth(c.name, oscillation_limit * 1.01, n);
        assert!(
            below < 1.5,
            "{}: grows by {below} 1 % below its limit",
            c.name
        );
        assert!(
            above > 10.0,
            "{}: grows by only {above} 1 % above its limit",
            c.name
        );
    }
}

/// dopri5's oscillation limit from its stability function R(z) = Σ_{k≤5} z^k/k! + z⁶/600
/// (Hairer, Nørsett & Wanner, *Solving ODEs I*, sec. IV.2): |R(i y)| ≤ 1 up to y = 0.997 and
/// not beyond 0.998. (dop853's 5.96 was computed the same way from its 12-stage tableau
/// offline; its adaptive stepper cannot be held to a fixed step here.)
#[test]
fn dopri5_cards_oscillation_limit_is_where_its_stability_function_leaves_the_unit_circle() {
    let card = TABLE.iter().find(|c| c.name == "dopri5").expect("dopri5");
    let Stiffness::Explicit { oscillation_limit } = card.stiffness else {
        panic!("dopri5 is explicit");
    };
    let modulus = |y: f64| {
        // R(i y) = Σ (i y)^k c_k: real part from even k, imaginary part from odd k.
        let c = [
            1.0,
            1.0,
            0.5,
            1.0 / 6.0,
            1.0 / 24.0,
            1.0 / 120.0,
            1.0 / 600.0,
        ];
        let (mut re, mut im) = (0.0, 0.0);
        for (k, ck) in c.iter().enumerate() {
            let p = ck * y.powi(k as i32);
            match k % 4 {
                0 => re += p,
                1 => im += p,
                2 => re -= p,
                _ => im -= p,
            }
        }
        re.hypot(im)
    };
    assert!(
        modulus(oscillation_limit) <= 1.0,
        "{}",
        modulus(oscillation_limit)
    );
    assert!(modulus(oscillation_limit + 1e-3) > 1.0);
    // And on the whole way there (sampled at 1000 points).
    assert!((0..1000).all(|k| modulus(oscillation_limit * f64::from(k) / 1000.0) <= 1.0));
}

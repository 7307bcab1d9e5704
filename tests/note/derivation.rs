//! Every derivation of the equation of motion passes its checks; a wrong one does not.

use sliding_ladder::derivation::{check_derivation, Derivation};
use sliding_ladder::ladder::energy::angular_acceleration;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::registry::check::Config;
use sliding_ladder::scalar::Scalar;
use sliding_ladder::verify::check_methods;

#[test]
fn the_notes_methods_all_give_the_equation_of_motion() {
    let cfg = Config {
        float_cases: 300,
        exact_points: 3,
        seed: 5,
    };
    let results = check_methods(&cfg);
    assert_eq!(results.len(), 12);
    for m in results {
        assert!(m.passed, "{}: {:?}", m.name, m.problems);
    }
}

/// 4ml²θ̈/3 = m g l sin θ with the factor 4/3 mistyped as 3/4: a plausible slip.
#[derive(Default)]
struct WrongInertia;

impl Derivation for WrongInertia {
    const NAME: &'static str = "wrong moment of inertia";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        T::ratio(3, 4) * l.m.clone() * l.l.clone() * l.l.clone() * s.accel.clone()
            - l.m.clone() * l.g.clone() * l.l.clone() * s.sin.clone()
    }
}

/// A residual that holds everywhere (θ̈ − θ̈): it never pins down the motion.
#[derive(Default)]
struct Vacuous;

impl Derivation for Vacuous {
    const NAME: &'static str = "vacuous";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        angular_acceleration(l, s) - angular_acceleration(l, s)
    }
}

#[test]
fn a_wrong_method_fails_its_checks() {
    let cfg = Config {
        float_cases: 50,
        exact_points: 2,
        seed: 5,
    };
    let wrong = check_derivation::<WrongInertia>(&cfg);
    assert!(wrong.iter().all(|r| !r.passed()), "{wrong:?}");
    let vacuous = check_derivation::<Vacuous>(&cfg);
    assert!(
        vacuous.iter().any(|r| r.off_shell_fails == Some(false)),
        "{vacuous:?}"
    );
}

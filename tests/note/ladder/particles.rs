//! Tests of `sliding_ladder::ladder::particles` (src/ladder/particles.rs).

use sliding_ladder::ladder::particles::as_system;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::scalar::Rational;
use sliding_ladder::scalar::Scalar;

#[test]
fn simpson_particles_have_the_rod_moment_of_inertia() {
    // Exact at θ with sin = 3/5, cos = 4/5: I_cm = m l²/3 for a uniform rod of length 2l
    // (∫ s² ds/(2l) over [-l, l] = l²/3), here with m = 6, l = 2: I_cm = 8.
    let r = Rational::int;
    let ladder = Ladder {
        m: r(6),
        l: r(2),
        g: r(10),
    };
    let st = State {
        sin: Rational::ratio(3, 5),
        cos: Rational::ratio(4, 5),
        rate: r(1),
        accel: r(0),
        jerk: r(0),
    };
    let sys = as_system(&ladder, &st);
    assert_eq!(sys.moment_of_inertia_about(&sys.centre_of_mass()), r(8));
    assert_eq!(sys.total_mass(), r(6));
}

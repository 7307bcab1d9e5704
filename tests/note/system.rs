//! Tests of `sliding_ladder::system` (src/system.rs).

use sliding_ladder::scalar::Rational;
use sliding_ladder::scalar::Scalar;
use sliding_ladder::system::{rate_vec, Particle, System};
use sliding_ladder::vector::Vec3;

fn v(x: i64, y: i64, z: i64) -> Vec3<Rational> {
    Vec3::new(Rational::int(x), Rational::int(y), Rational::int(z))
}

#[test]
fn one_particle_angular_momentum_rate_is_its_torque() {
    let p = Particle {
        m: Rational::int(2),
        x: v(1, 2, 3),
        v: v(-1, 0, 2),
        a: v(0, 5, 1),
        j: v(0, 0, 0),
    };
    let sys = System {
        particles: vec![p],
        spin: None,
    };
    let lifted = sys.along_motion();
    let dl = rate_vec::<Rational>(&lifted.angular_momentum());
    assert_eq!(dl, sys.torque());
    // A different acceleration gives a different torque: the comparison is not vacuous.
    let mut other = sys.clone();
    other.particles[0].a = v(0, 5, 2);
    assert_ne!(dl, other.torque());
}

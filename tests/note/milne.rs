//! Tests of `sliding_ladder::milne` (src/milne.rs).

use sliding_ladder::milne::{big_v, big_v_dot, r_ddot, r_dot, v, v_rel};
use sliding_ladder::scalar::Rational;
use sliding_ladder::scalar::Scalar;
use sliding_ladder::system::{Particle, Point};
use sliding_ladder::vector::Vec3;

fn v3(x: i64, y: i64, z: i64) -> Vec3<Rational> {
    Vec3::new(Rational::int(x), Rational::int(y), Rational::int(z))
}

#[test]
fn relative_rates_are_the_differences_of_the_motions() {
    let q = Particle {
        m: Rational::int(3),
        x: v3(1, 2, 3),
        v: v3(-1, 0, 2),
        a: v3(0, 5, 1),
        j: v3(1, 1, 1),
    };
    let o = Point {
        x: v3(2, 0, 0),
        v: v3(0, 1, 0),
        a: v3(4, 0, -1),
        j: v3(0, 0, 0),
    };
    assert_eq!(r_dot(&q, &o), v3(-1, -1, 2));
    assert_eq!(r_ddot(&q, &o), v3(-4, 5, 2));
    assert_eq!(big_v(&o), v3(0, 1, 0));
    assert_eq!(big_v_dot(&o), v3(4, 0, -1));
    // About the fixed origin the dots are the particle's own motion, not O's.
    assert_eq!(v(&q), q.v);
    assert_ne!(v_rel(&q, &o), q.v);
}

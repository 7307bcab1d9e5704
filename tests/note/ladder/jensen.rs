//! `jensen::velocity_term_c`, the extra term of eq. (38) about the top C, m (v_cm × v_C)_z
//! (eq. (48) times m), against the cross product of velocities written here from the geometry.
//! The registry lists it under eq. (48), whose check evaluates `eq48_cross` only, so nothing
//! else evaluates it. Exact arithmetic: the two agree exactly.
//!
//! Geometry (the note's, sec. 2): the foot on the floor at (2l sin θ, 0), the top C on the wall
//! at (0, 2l cos θ), the centre at (l sin θ, l cos θ); so v_cm = (l cos θ θ̇, −l sin θ θ̇) and
//! v_C = (0, −2l sin θ θ̇).

use sliding_ladder::ladder::jensen::velocity_term_c;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::scalar::{Rational, Scalar};

type Q = Rational;

/// sin θ = 2t/(1+t²), cos θ = (1−t²)/(1+t²) (rational points of the circle), rate θ̇.
fn state(t: (i64, i64), rate: (i64, i64)) -> State<Q> {
    let t = Q::ratio(t.0, t.1);
    let den = Q::int(1) + t.clone() * t.clone();
    State {
        sin: Q::int(2) * t.clone() / den.clone(),
        cos: (Q::int(1) - t.clone() * t) / den,
        rate: Q::ratio(rate.0, rate.1),
        accel: Q::ratio(3, 7),
        jerk: Q::int(1),
    }
}

/// m (v_cm × v_C)_z from the velocities above.
fn reference(l: &Ladder<Q>, s: &State<Q>) -> Q {
    let v_cm = (
        l.l.clone() * s.cos.clone() * s.rate.clone(),
        Q::int(0) - l.l.clone() * s.sin.clone() * s.rate.clone(),
    );
    let v_c = (
        Q::int(0),
        Q::int(-2) * l.l.clone() * s.sin.clone() * s.rate.clone(),
    );
    l.m.clone() * (v_cm.0 * v_c.1 - v_cm.1 * v_c.0)
}

#[test]
fn the_velocity_term_about_c_is_m_times_v_cm_cross_v_c() {
    let ladder = Ladder {
        m: Q::int(3),
        l: Q::ratio(5, 2),
        g: Q::ratio(49, 5),
    };
    for (t, rate) in [((1, 3), (-7, 4)), ((2, 5), (3, 2)), ((3, 4), (-1, 9))] {
        let s = state(t, rate);
        let want = reference(&ladder, &s);
        assert_eq!(
            velocity_term_c(&ladder, &s),
            want,
            "t = {t:?}, θ̇ = {rate:?}"
        );
        // The comparison can fail: without the mass, or with it added, the value differs.
        assert_ne!(want.clone() / ladder.m.clone(), want);
        assert_ne!(want.clone() / ladder.m.clone() + ladder.m.clone(), want);
    }
}

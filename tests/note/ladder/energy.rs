//! Tests of `sliding_ladder::ladder::energy` (src/ladder/energy.rs).
//!
//! The symbolic scalar on the ladder's state (the tests live here, above `scalar`, which must not
//! import the ladder).

use sliding_ladder::ladder::energy::rate_squared;
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::scalar::{Jet, Scalar, Sym};

fn ladder_state() -> (Ladder<Sym>, State<Sym>) {
    let ladder = Ladder {
        m: Sym::var("m", "m"),
        l: Sym::var("l", "l"),
        g: Sym::var("g", "g"),
    };
    let st = State {
        sin: Sym::sin(),
        cos: Sym::cos(),
        rate: Sym::var("θ̇", "\\dot\\theta"),
        accel: Sym::var("θ̈", "\\ddot\\theta"),
        jerk: Sym::var("θ⃛", "\\dddot\\theta"),
    };
    (ladder, st)
}

#[test]
fn time_derivatives_follow_the_motion() {
    let (_, st) = ladder_state();
    let lifted = st.along_motion();
    let d = |q: Jet<Sym>| Sym::split(q).1;
    // ṡ = c θ̇, ċ = −s θ̇, d/dt θ̇ = θ̈, d/dt θ̈ = θ⃛.
    assert_eq!(d(lifted.sin.clone()), st.cos.clone() * st.rate.clone());
    assert_eq!(d(lifted.cos.clone()), -(st.sin.clone() * st.rate.clone()));
    assert_eq!(d(lifted.rate.clone()), st.accel.clone());
    assert_eq!(d(lifted.accel.clone()), st.jerk.clone());
    // d/dt (s² + c²) = 0 exactly; d/dt (s c) = θ̇ (c² − s²) = θ̇ (1 − 2 s²).
    let one = d(lifted.sin.clone() * lifted.sin.clone() + lifted.cos.clone() * lifted.cos.clone());
    assert!(one.is_zero());
    let sc = d(lifted.sin.clone() * lifted.cos.clone());
    let expected = st.rate.clone() * (Sym::int(1) - Sym::int(2) * st.sin.clone() * st.sin.clone());
    assert_eq!(sc, expected);
    assert_ne!(sc, st.rate.clone());
}

#[test]
fn energy_relation_reduces_rate_squared() {
    let (ladder, st) = ladder_state();
    let rate_var = st.rate.as_var().expect("a variable");
    let r = rate_squared(&ladder, &st);
    // θ̇⁴ − r² ≡ 0 and θ̇³ − r θ̇ ≡ 0 modulo θ̇² = r; θ̇ itself is not.
    let t = st.rate.clone();
    let (a, b) = (t.clone() * t.clone() * t.clone() * t.clone() - r.clone() * r.clone())
        .reduce_square(rate_var, &r);
    assert!(a.is_zero() && b.is_zero());
    let (a, b) =
        (t.clone() * t.clone() * t.clone() - r.clone() * t.clone()).reduce_square(rate_var, &r);
    assert!(a.is_zero() && b.is_zero());
    let (a, b) = t.clone().reduce_square(rate_var, &r);
    assert!(a.is_zero() && !b.is_zero());
    // A quotient with θ̇ in the denominator: 1/θ̇ = θ̇/r.
    let (a, b) = (Sym::int(1) / t.clone() - t / r.clone()).reduce_square(rate_var, &r);
    assert!(a.is_zero() && b.is_zero(), "{a:?} {b:?}");
}

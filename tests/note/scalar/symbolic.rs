//! Tests of `sliding_ladder::scalar::symbolic` (src/scalar/symbolic.rs).

use sliding_ladder::scalar::symbolic::Sym;
use sliding_ladder::scalar::Scalar;

#[test]
fn pythagoras_is_proved_and_a_planted_error_is_not() {
    let (s, c) = (Sym::sin(), Sym::cos());
    assert!((s.clone() * s.clone() + c.clone() * c.clone() - Sym::int(1)).is_zero());
    let planted = s.clone() * s.clone() + c.clone() * c - Sym::ratio(101, 100);
    assert!(!planted.is_zero());
    assert_eq!(planted.to_f64(), -0.01);
    // tan² + 1 = 1/c², through quotients.
    let c = Sym::cos();
    let tan = s / c.clone();
    assert!((tan.clone() * tan + Sym::int(1) - Sym::int(1) / (c.clone() * c)).is_zero());
}

#[test]
fn fractions_cancel_and_compare_by_cross_multiplication() {
    let (m1, m2) = (Sym::var("m_1", "m_1"), Sym::var("m_2", "m_2"));
    let total = m1.clone() + m2.clone();
    let x = (m1.clone() * Sym::var("x_1", "x_1")) / total.clone();
    let back = x.clone() * total.clone();
    assert!(back.den.factors.is_empty(), "{back:?}");
    assert_eq!(back, m1.clone() * Sym::var("x_1", "x_1"));
    assert_ne!(x, m1 * Sym::var("x_1", "x_1") / (total + Sym::int(1)));
}

#[test]
fn as_var_names_a_bare_variable_and_nothing_else() {
    let (x, y) = (Sym::var("x_v", "x_v"), Sym::var("y_v", "y_v"));
    let vx = x.as_var().expect("x is a variable");
    assert_ne!(Some(vx), y.as_var());
    // A square, a product, a multiple, a sum and a quotient are not variables.
    for not_var in [
        x.clone() * x.clone(),
        x.clone() * y.clone(),
        Sym::int(2) * x.clone(),
        x.clone() + y.clone(),
        x.clone() / y.clone(),
    ] {
        assert_eq!(not_var.as_var(), None, "{not_var:?}");
    }
}

/// The surd in a denominator is rationalised: with v² = 2, 1/(1 + v) = v − 1 and
/// v/(1 + v) = 2 − v (multiply by 1 − v; by hand).
#[test]
fn reduce_square_rationalises_a_surd_in_the_denominator() {
    let v = Sym::var("v_r", "v_r");
    let var = v.as_var().expect("v is a variable");
    let two = Sym::int(2);
    let one_over = Sym::int(1) / (Sym::int(1) + v.clone());
    assert_eq!(
        one_over.reduce_square(var, &two),
        (Sym::int(-1), Sym::int(1))
    );
    let v_over = v.clone() / (Sym::int(1) + v.clone());
    assert_eq!(v_over.reduce_square(var, &two), (Sym::int(2), Sym::int(-1)));
    // A planted wrong relation (v² = 3) gives another pair: 1/(1 + √3) = (√3 − 1)/2.
    assert_eq!(
        one_over.reduce_square(var, &Sym::int(3)),
        (Sym::ratio(-1, 2), Sym::ratio(1, 2))
    );
}

/// A factor that divides the numerator exactly is divided out: (xy − 1)(x + 1)/(xy − 1) is the
/// plain polynomial x + 1, with no denominator left.
#[test]
fn an_exact_factor_of_the_numerator_is_divided_out() {
    let (x, y) = (Sym::var("x_d", "x_d"), Sym::var("y_d", "y_d"));
    let f = x.clone() * y.clone() - Sym::int(1);
    let q = f.clone() * (x.clone() + Sym::int(1)) / f;
    assert!(q.den.factors.is_empty(), "{q:?}");
    assert_eq!(q, x + Sym::int(1));
}

/// A monomial of the denominator that the numerator cancels whole leaves the denominator:
/// x y / x is y over 1, and y x / x² is y over x (by hand); no variable is kept at the power 0,
/// which would print as a factor and make a denominator that is 1 look otherwise.
#[test]
fn a_monomial_cancelled_whole_leaves_the_denominator() {
    use sliding_ladder::scalar::text;
    let (x, y) = (Sym::var("x_m", "x_m"), Sym::var("y_m", "y_m"));
    let q = x.clone() * y.clone() / x.clone();
    assert!(q.den.mono.is_empty(), "{q:?}");
    assert_eq!(text(&q), "y_m");
    let r = y.clone() * x.clone() / (x.clone() * x.clone());
    assert_eq!(r.den.mono.len(), 1, "{r:?}");
    assert_eq!(r.den.mono[0].1, 1, "{r:?}");
    assert_eq!(text(&r), text(&(y / x)));
}

//! Tests of `sliding_ladder::scalar::sym_reading` (src/scalar/sym_reading.rs).

use sliding_ladder::scalar::sym_reading::reading;
use sliding_ladder::scalar::Scalar;
use sliding_ladder::scalar::Sym;

fn v(name: &str) -> Sym {
    Sym::var(name, name)
}

#[test]
fn a_lost_mass_lacks_a_factor_and_a_rate_for_an_acceleration_is_swapped() {
    let (m, l, w, a) = (v("m"), v("l"), v("θ̇"), v("θ̈"));
    let (s, c) = (Sym::sin(), Sym::cos());
    // (49): printed l²θ̇(c² − s²), corrected m l²θ̇(c² − s²).
    let x = l.clone() * l.clone() * w.clone() * (c.clone() * c.clone() - s.clone() * s.clone());
    let d = x.clone() - m.clone() * x.clone();
    let r = reading(&d).expect("a reading");
    assert_eq!(r.kind(false), "a factor m");
    assert!(
        r.render(false).starts_with("the printed term l^2 θ̇"),
        "{}",
        r.render(false)
    );
    // (62): printed −ml s(…), corrected −2ml² s(…): a factor 2l.
    let y = m.clone() * l.clone() * s.clone() * (c.clone() * w.clone() * w.clone() + s * a.clone());
    let d = Sym::int(0) - y.clone() + Sym::int(2) * l.clone() * y;
    assert_eq!(reading(&d).unwrap().kind(false), "a factor 2 l");
    // (54): (4/3)ml²θ̇² printed where (4/3)ml²θ̈ belongs.
    let k = Sym::int(4) * m * l.clone() * l / Sym::int(3);
    let d = k.clone() * w.clone() * w - k * a;
    let r = reading(&d).unwrap();
    assert_eq!(r.kind(false), "θ̇^2 where θ̈ belongs");
    assert!(r.render(false).contains("4/3"), "{}", r.render(false));
}

#[test]
fn a_negative_lone_factor_keeps_its_parentheses() {
    // (68)'s y component: (m₁ − 1)(x − z) = (1 − m₁)·(−(x − z)).
    let (m, x, z) = (v("m_1"), v("x"), v("z"));
    let d = (m - Sym::int(1)) * (x - z);
    let r = reading(&d).unwrap();
    assert_eq!(r.term(false), "-(x - z)");
    assert_eq!(r.kind(false), "a factor m_1");
}

#[test]
fn a_missing_term_of_another_shape_has_no_reading() {
    // (28): 2cml²(cθ̈ − sθ̇²) is neither a lost parameter nor a rate for an acceleration.
    let (m, l, w, a) = (v("m"), v("l"), v("θ̇"), v("θ̈"));
    let (s, c) = (Sym::sin(), Sym::cos());
    let d = Sym::int(2) * c.clone() * m * l.clone() * l * (c * a - s * w.clone() * w);
    assert_eq!(reading(&d), None);
    // A rate lost as a factor is not a parameter: θ̇ (1 − θ̇) has no reading either.
    let w = v("θ̇");
    assert_eq!(reading(&(w.clone() - w.clone() * w)), None);
}

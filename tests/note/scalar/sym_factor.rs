//! Tests of `sliding_ladder::scalar::sym_factor` (src/scalar/sym_factor.rs).

use sliding_ladder::scalar::sym_factor::{factor, factored_text};
use sliding_ladder::scalar::Scalar;
use sliding_ladder::scalar::Sym;

fn v(t: &str) -> Sym {
    Sym::var(t, t)
}

#[test]
fn factors_a_dropped_mass_and_a_double_angle() {
    let (m, l, w) = (v("m"), v("l"), v("θ̇"));
    let (s, c) = (Sym::sin(), Sym::cos());
    let d = (Sym::int(1) - m) * l.clone() * l * w * (c.clone() * c - s.clone() * s);
    assert_eq!(factored_text(&d), "l^2 θ̇ (1 - m) (c^2 - s^2)");
    // The expanded normal form is what the factoring starts from.
    assert_eq!(
        sliding_ladder::scalar::text(&d),
        "2 s^2 m l^2 θ̇ - 2 s^2 l^2 θ̇ - m l^2 θ̇ + l^2 θ̇"
    );
}

#[test]
fn homogenises_one_minus_s_squared() {
    let (a, w) = (v("θ̈"), v("θ̇"));
    let (s, c) = (Sym::sin(), Sym::cos());
    let d = Sym::int(-2) * s.clone() * c.clone() * w.clone() * w + Sym::int(2) * c.clone() * c * a;
    assert_eq!(factored_text(&d), "2 c (c θ̈ - s θ̇^2)");
}

#[test]
fn an_irreducible_sum_stays_whole_and_every_form_expands_back() {
    let (m, l) = (v("m"), v("l"));
    let p = m.clone() * m.clone() + l.clone() * l.clone() + Sym::int(1);
    assert_eq!(factored_text(&p), "m^2 + l^2 + 1");
    let (s, c) = (Sym::sin(), Sym::cos());
    let g = v("g");
    for x in [
        p,
        m.clone() * l.clone() * Sym::ratio(-3, 4),
        -(m.clone() + l.clone()) * (s.clone() * s.clone() - Sym::ratio(1, 2)),
        (m.clone() - g.clone()) * (l.clone() + g) * (c.clone() + s.clone()) * c * s,
    ] {
        let f = factor(&x.num).expect("a product");
        assert_eq!(f.expand(), x.num, "{}", f.render(false));
    }
}

/// Two factors in disjoint variables with coefficients other than ±1 are found:
/// (2m + 3)(5l + 7) expands to 10ml + 14m + 15l + 21, and no entry of its coefficient matrix is
/// ±1, so the rank-one test must compare cross products, not quotients.
#[test]
fn factor_splits_a_product_whose_coefficients_are_not_units() {
    let (m, l) = (v("m"), v("l"));
    let x = (Sym::int(2) * m + Sym::int(3)) * (Sym::int(5) * l + Sym::int(7));
    let f = factor(&x.num).expect("a product");
    assert_eq!(f.factors.len(), 2, "{}", f.render(false));
    assert_eq!(f.expand(), x.num);
}

/// (1 − s²)², stored reduced as s⁴ − 2s² + 1, homogenises through (s² + c²)² to c⁴.
#[test]
fn homogenises_a_square_of_one_minus_s_squared_to_c_to_the_fourth() {
    let s = Sym::sin();
    let one_minus = Sym::int(1) - s.clone() * s;
    let x = one_minus.clone() * one_minus;
    assert_eq!(factored_text(&x), "c^4");
}

/// Random products of two to four factors, each a polynomial in its own variable with integer
/// coefficients other than ±1 (a x² + b x + c, or a x + c): `factor` finds every factor, one per
/// variable, and the product expands back. A common rational multiple is taken out whole.
#[test]
fn factor_finds_every_factor_of_random_products_in_disjoint_variables() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(41);
    let vars = ["m", "l", "g", "ω"];
    let nonunit = |rng: &mut rand_chacha::ChaCha8Rng| {
        let k: i64 = rng.gen_range(2..9);
        if rng.gen_bool(0.5) {
            k
        } else {
            -k
        }
    };
    for _ in 0..200 {
        let k = rng.gen_range(2..=4);
        let mut x = Sym::ratio(nonunit(&mut rng), 3);
        for name in &vars[..k] {
            let y = v(name);
            let linear = Sym::int(nonunit(&mut rng)) * y.clone() + Sym::int(nonunit(&mut rng));
            let f = if rng.gen_bool(0.5) {
                linear + Sym::int(nonunit(&mut rng)) * y.clone() * y
            } else {
                linear
            };
            x = x * f;
        }
        let f = factor(&x.num).expect("a product");
        assert_eq!(f.factors.len(), k, "{}", f.render(false));
        assert_eq!(f.expand(), x.num, "{}", f.render(false));
    }
}

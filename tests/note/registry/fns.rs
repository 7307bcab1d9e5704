//! Tests of `sliding_ladder::registry::fns` (src/registry/fns.rs).

use sliding_ladder::registry::fns::check_of;

#[test]
fn an_unknown_name_or_a_sample_of_the_wrong_model_is_refused() {
    assert!(check_of("eq25", "on-shell", "x").is_ok());
    let e = check_of("eq25_typo", "on-shell", "x").err().unwrap();
    assert!(e.contains("not a chain function"), "{e}");
    let e = check_of("eq25", "general", "x").err().unwrap();
    assert!(e.contains("kinematic, on-shell"), "{e}");
    assert!(check_of("eq29", "general", "x").is_ok());
    assert!(check_of("eq29", "on-shell", "x").is_err());
}

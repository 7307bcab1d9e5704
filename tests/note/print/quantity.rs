//! Tests of `sliding_ladder::print::quantity` (src/print/quantity/).

use sliding_ladder::print::quantity::{resolve, Model, Value};
use sliding_ladder::registry::sample::{exact_ladder, LadderSample};
use sliding_ladder::scalar::{Rational, Scalar};

/// A quantity id names a component only by `.x`, `.y` or `.z`: any other suffix is an unknown
/// quantity (an error), never read as a component. An extender's typo in `symbols.toml`
/// (`position:cm.w`) must not silently give z.
#[test]
fn resolve_reads_a_component_only_after_x_y_or_z() {
    let (l, s) = exact_ladder(
        LadderSample::Kinematic,
        [3, 7, 2, 11, -5, 13, 4].map(Rational::int),
    );
    let m = Model::ladder(l, s);
    let Ok(Value::Vector(v)) = resolve("position:cm", None, &m) else {
        panic!("x_cm is a vector");
    };
    let component = |id: &str| match resolve(id, None, &m) {
        Ok(Value::Scalar(c)) => c,
        other => panic!("{id}: {other:?}"),
    };
    assert_eq!(
        [".x", ".y", ".z"].map(|c| component(&format!("position:cm{c}"))),
        [v.x, v.y, v.z]
    );
    assert!(resolve("position:cm.w", None, &m).is_err());
}

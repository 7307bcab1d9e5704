//! Tests of `sliding_ladder::report::stability::scale` (src/report/stability/scale.rs).

use sliding_ladder::report::stability::scale::{sweep_cases, SWEEP_CASES};
use sliding_ladder::report::stability::Verdict;

#[test]
fn the_sweep_passes() {
    let cases = sweep_cases(&mut |_, _| {});
    assert_eq!(cases.len(), SWEEP_CASES);
    for c in &cases {
        assert_eq!(c.verdict, Verdict::Ok, "{c:?}");
    }
}

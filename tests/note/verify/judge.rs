//! Tests of `sliding_ladder::verify::judge` (src/verify/judge.rs): what a verdict says of its
//! checks.

use sliding_ladder::registry::check::{run_check, Config};
use sliding_ladder::registry::equations;
use sliding_ladder::verify::judge;

/// Each row lists its checks by the names the registry gives them, the words `ladder verify
/// --wide` and the book print under "Forms checked" (a report that lost its name would print
/// an empty line there).
#[test]
fn judge_lists_each_check_by_its_registered_name() {
    let cfg = Config {
        float_cases: 2,
        exact_points: 1,
        seed: 2019,
    };
    let mut seen = 0;
    for e in equations()
        .iter()
        .filter(|e| [2, 25, 48, 85].contains(&e.number))
    {
        let reports: Vec<_> = e.checks.iter().map(|c| run_check(c, &cfg)).collect();
        let row = judge(e, &reports);
        let names: Vec<&str> = e.checks.iter().map(|c| c.name).collect();
        assert_eq!(row.checks, names, "({})", e.number);
        assert!(
            row.checks.iter().all(|n| !n.trim().is_empty()),
            "({}): {:?}",
            e.number,
            row.checks
        );
        seen += 1;
    }
    assert_eq!(seen, 4);
}

//! Tests of `sliding_ladder::sim::integrators::dense_lu` (src/sim/integrators/dense_lu.rs).

use sliding_ladder::sim::integrators::dense_lu::{lu_factor, lu_solve};

/// A system whose elimination interchanges rows at the first *and* a later column, so the
/// stored multipliers are permuted after they were computed: x = (1, 2, 3) exactly.
#[test]
fn lu_solve_with_late_pivots() {
    let a = [1.0, 2.0, 3.0, 2.0, 1.0, 1.0, 4.0, 4.0, 1.0];
    let x = [1.0, 2.0, 3.0];
    let mut b: Vec<f64> = (0..3)
        .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
        .collect();
    let (mut m, mut piv) = (a.to_vec(), vec![0; 3]);
    assert!(lu_factor(&mut m, &mut piv, 3));
    assert_eq!(piv, vec![2, 2, 2], "both interchanges happen");
    lu_solve(&m, &piv, &mut b, 3);
    for i in 0..3 {
        assert!((b[i] - x[i]).abs() <= 8.0 * f64::EPSILON * 3.0, "{b:?}");
    }
}

/// A singular matrix (second row twice the first: the second pivot is exactly 0) and one
/// with a non-finite entry are refused, not factored into infinities (mutation testing:
/// the pivot test `== 0 || !finite` → `&&` went unseen; no test had a singular matrix).
/// The non-finite pivot may come at a later column, whose index p n + k the test must
/// read (mutation testing: p n − k, the same element at k = 0 only, went unseen).
#[test]
fn singular_and_non_finite_matrices_are_refused() {
    for a in [
        [1.0, 2.0, 2.0, 4.0],
        [0.0, 0.0, 0.0, 1.0],
        [f64::INFINITY, 1.0, 1.0, 1.0],
        [f64::NAN, 1.0, 1.0, 1.0],
        [1.0, 0.0, 0.0, f64::INFINITY],
        [1.0, 0.0, 0.0, f64::NAN],
    ] {
        let (mut m, mut piv) = (a.to_vec(), vec![0; 2]);
        assert!(!lu_factor(&mut m, &mut piv, 2), "{a:?}");
    }
}

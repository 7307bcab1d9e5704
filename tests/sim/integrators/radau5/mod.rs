//! `sim::integrators::radau5`: the implicit Radau IIA method.

mod domain;
mod step_reuse;

use sliding_ladder::sim::integrators::radau5::{u1, A};

/// U1 is the real eigenvalue of A⁻¹ (the error estimate's (U1/h I − J) rests on it), so
/// det(U1 A − I) = 0. Error model: six products of three entries of size at most 3, each
/// a few ulps: 6 · 27 · 3 u = 1.1e-13. (Mutation testing: 81^(1/3) − 9^(1/3) →
/// 81^(1/3) / 9^(1/3) went unseen; it gives det = 0.013.)
#[test]
fn u1_is_the_real_eigenvalue_of_the_inverse_of_a() {
    let u = u1();
    let m = |i: usize, j: usize| u * A[i][j] - if i == j { 1.0 } else { 0.0 };
    let det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1))
        - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))
        + m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
    assert!(det.abs() <= 6.0 * 27.0 * 3.0 * f64::EPSILON, "{det}");
}

//! Dense LU factorisation with partial pivoting, for RADAU5's stage system (3N x 3N, N = 2 or 4).
//!
//! Written by hand rather than taken from a linear-algebra crate: the systems are at most 12 x 12,
//! live in fixed scratch buffers reused every step (no allocation in the step loop), and need
//! only factor and solve; a dependency such as nalgebra would bring generic machinery for these
//! twenty lines.

/// LU factorisation with partial pivoting of the n x n row-major matrix `m` (in place).
/// Returns false when singular.
pub(super) fn lu_factor(m: &mut [f64], piv: &mut [usize], n: usize) -> bool {
    for k in 0..n {
        let p = (k..n)
            .max_by(|&a, &b| m[a * n + k].abs().total_cmp(&m[b * n + k].abs()))
            .unwrap_or(k);
        if m[p * n + k] == 0.0 || !m[p * n + k].is_finite() {
            return false;
        }
        piv[k] = p;
        if p != k {
            for j in 0..n {
                m.swap(k * n + j, p * n + j);
            }
        }
        for i in k + 1..n {
            let l = m[i * n + k] / m[k * n + k];
            m[i * n + k] = l;
            for j in k + 1..n {
                m[i * n + j] -= l * m[k * n + j];
            }
        }
    }
    true
}

/// Solve with the factors of [`lu_factor`], overwriting `b`.
pub(super) fn lu_solve(m: &[f64], piv: &[usize], b: &mut [f64], n: usize) {
    // `lu_factor` swaps whole rows, multipliers included (LAPACK's convention), so the stored L
    // belongs to the fully permuted matrix: apply every interchange before the substitution.
    for k in 0..n {
        b.swap(k, piv[k]);
    }
    for k in 0..n {
        for i in k + 1..n {
            b[i] -= m[i * n + k] * b[k];
        }
    }
    for k in (0..n).rev() {
        for j in k + 1..n {
            b[k] -= m[k * n + j] * b[j];
        }
        b[k] /= m[k * n + k];
    }
}

#[cfg(test)]
mod tests {
    use super::{lu_factor, lu_solve};

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
}

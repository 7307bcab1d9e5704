//! Dense LU factorisation with partial pivoting, for RADAU5's stage system (3N x 3N, N = 2 or 4).
//!
//! Written by hand rather than taken from a linear-algebra crate: the systems are at most 12 x 12,
//! live in fixed scratch buffers reused every step (no allocation in the step loop), and need
//! only factor and solve; a dependency such as nalgebra would bring generic machinery for these
//! twenty lines.

/// LU factorisation with partial pivoting of the n x n row-major matrix `m` (in place).
/// Returns false when singular.
pub fn lu_factor(m: &mut [f64], piv: &mut [usize], n: usize) -> bool {
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
pub fn lu_solve(m: &[f64], piv: &[usize], b: &mut [f64], n: usize) {
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

//! One Radau IIA(5) step's stages: the predictor, the simplified Newton iteration on the stage
//! equations, and the embedded error estimate (radau5.f's ESTRAD).

use super::{step_norm, Radau5, A, C, DD, MAX_NEWTON};
use crate::sim::integrators::dense_lu::lu_solve;
use crate::sim::integrators::{eval, Ode};

impl<const N: usize> Radau5<N> {
    /// Predictor of the stage increments z_a for the step `h` from `y`: the last collocation
    /// polynomial extrapolated (zero at the start).
    pub(super) fn predict(&self, y: &[f64; N], h: f64) -> [[f64; N]; 3] {
        let mut z = [[0.0; N]; 3];
        if self.have_prev {
            let hp = self.t - self.t_prev;
            for (a, za) in z.iter_mut().enumerate() {
                let u = self.collocation(1.0 + C[a] * h / hp);
                *za = std::array::from_fn(|i| u[i] - y[i]);
            }
        }
        z
    }

    /// Solve the stage equations z = h (A ⊗ f)(y + z) by simplified Newton with the factors of
    /// the step `h`, from the prediction in `z`; the observed contraction θ when it converged,
    /// `None` when it diverged or did not converge in [`MAX_NEWTON`] iterations.
    pub(super) fn newton<S: Ode<N>>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        h: f64,
        z: &mut [[f64; N]; 3],
    ) -> Option<f64> {
        let n3 = 3 * N;
        let fnewt = (10.0 * f64::EPSILON / self.newton_rtol).max(0.03);
        let mut prev_norm = f64::INFINITY;
        let mut contraction = 0.0;
        let mut eta = self.eta.max(f64::EPSILON).powf(0.8);
        for _ in 0..MAX_NEWTON {
            let mut fz = [[0.0; N]; 3];
            for a in 0..3 {
                let ya: [f64; N] = std::array::from_fn(|i| y[i] + z[a][i]);
                fz[a] = eval(sys, t + C[a] * h, &ya);
            }
            self.stats.rhs_evals += 3;
            let mut rhs = vec![0.0; n3];
            for a in 0..3 {
                for i in 0..N {
                    let hf: f64 = (0..3).map(|b| A[a][b] * fz[b][i]).sum();
                    rhs[a * N + i] = h * hf - z[a][i];
                }
            }
            lu_solve(&self.lu, &self.piv, &mut rhs, n3);
            let mut norm = 0.0f64;
            for a in 0..3 {
                let dz: [f64; N] = std::array::from_fn(|i| rhs[a * N + i]);
                norm = norm.max(step_norm(sys, &dz, y, y, self.newton_rtol, h));
                for i in 0..N {
                    z[a][i] += dz[i];
                }
            }
            if !norm.is_finite() {
                return None;
            }
            // Convergence test of radau5.f: η ‖Δz‖ ≤ κ with η = θ/(1−θ) from the observed
            // contraction θ; the first iteration uses the last step's η (damped), as there.
            if prev_norm.is_finite() {
                let rate = norm / prev_norm;
                if rate >= 1.0 {
                    return None;
                }
                contraction = rate;
                eta = rate / (1.0 - rate);
            }
            if norm == 0.0 || eta * norm <= fnewt {
                self.eta = eta;
                return Some(contraction);
            }
            prev_norm = norm;
        }
        None
    }

    /// The embedded error estimate of the step `h` from `y` to `y1` (radau5.f, ESTRAD):
    /// (U1/h I − J)⁻¹ (f0 + Σ DD_a z_a / h) in the step's norm, at least 1e-10; infinite when
    /// the factors are not those of `h`.
    pub(super) fn error_estimate<S: Ode<N>>(
        &mut self,
        sys: &S,
        t: f64,
        (y, y1): (&[f64; N], &[f64; N]),
        f0: &[f64; N],
        z: &[[f64; N]; 3],
        h: f64,
    ) -> f64 {
        let ok = self.lu_h == h;
        let f2: [f64; N] =
            std::array::from_fn(|i| (0..3).map(|a| DD[a] * z[a][i]).sum::<f64>() / h);
        let mut est: Vec<f64> = (0..N).map(|i| f0[i] + f2[i]).collect();
        let mut err = f64::INFINITY; // clamp, not max: NaN.max(1e-10) is 1e-10; NaN rejects
        if ok {
            lu_solve(&self.e1, &self.piv1, &mut est, N);
            let e: [f64; N] = std::array::from_fn(|i| est[i]);
            err = step_norm(sys, &e, y, y1, self.rtol, h).clamp(1e-10, f64::INFINITY);
            if err >= 1.0 {
                // The second estimate, (U1/h I − J)⁻¹ applied once more, filters the stiff
                // components. radau5.f forms it only on the first or a rejected step, so on
                // stiff springs (κ ≥ 1e8) nearly every step was first rejected on the raw
                // estimate and then accepted on this one (205 of 208 at κ = 1e12).
                let yt: [f64; N] = std::array::from_fn(|i| y[i] + e[i]);
                let ft = eval(sys, t, &yt);
                self.stats.rhs_evals += 1;
                let mut est2: Vec<f64> = (0..N).map(|i| ft[i] + f2[i]).collect();
                lu_solve(&self.e1, &self.piv1, &mut est2, N);
                let e2: [f64; N] = std::array::from_fn(|i| est2[i]);
                err = step_norm(sys, &e2, y, y1, self.rtol, h).clamp(1e-10, f64::INFINITY);
            }
        }
        err
    }
}

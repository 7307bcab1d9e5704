//! DOP853: the explicit Runge-Kutta method of order 8 by Dormand & Prince with the error
//! estimator of order 5 and 3 and a dense output of order 7.
//!
//! Source of the coefficients and of the step-size control: E. Hairer, S. P. Nørsett and
//! G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., sec. II.5 and II.6, and the
//! Fortran code `dop853.f` (Hairer & Wanner, version of 2004), whose parameter tables `C*`, `A*`,
//! `B*`, `BHH*`, `ER*`, `D*` are transcribed below under the same names (30-digit decimals,
//! rounded to f64 by the compiler). The error weights are `rtol * max(scale(y0), scale(y1))`, as in
//! [`super::error_norm`], with the combined 5th/3rd-order estimate of dop853.f.

use super::{all_finite, eval, initial_step, Ode, Stats, StepError, Stepper};

use super::dop853_tables::*;

/// `y + h * sum_j a[j] * k[idx[j]]`.
#[inline(always)]
fn combine<const N: usize>(
    y: &[f64; N],
    h: f64,
    a: &[f64],
    idx: &[usize],
    k: &[[f64; N]; 16],
) -> [f64; N] {
    std::array::from_fn(|i| {
        let mut s = 0.0;
        for (aj, &j) in a.iter().zip(idx) {
            s += aj * k[j][i];
        }
        y[i] + h * s
    })
}

/// The DOP853 integrator (adaptive, dense output of order 7).
#[derive(Clone, Debug)]
pub struct Dop853<const N: usize> {
    rtol: f64,
    t: f64,
    y: [f64; N],
    comp: [f64; N],
    f: Option<[f64; N]>,
    h: f64,
    facold: f64,
    last_rejected: bool,
    t_prev: f64,
    y_prev: [f64; N],
    k: [[f64; N]; 16],
    cont: Option<[[f64; N]; 8]>,
    stats: Stats,
}

impl<const N: usize> Dop853<N> {
    /// Start at `(t0, y0)` with relative tolerance `rtol`.
    pub fn new(t0: f64, y0: [f64; N], rtol: f64) -> Self {
        Dop853 {
            rtol,
            t: t0,
            y: y0,
            comp: [0.0; N],
            f: None,
            h: 0.0,
            facold: 1e-4,
            last_rejected: false,
            t_prev: t0,
            y_prev: y0,
            k: [[0.0; N]; 16],
            cont: None,
            stats: Stats::default(),
        }
    }
}

impl<const N: usize> Stepper<N> for Dop853<N> {
    fn t(&self) -> f64 {
        self.t
    }
    fn y(&self) -> [f64; N] {
        self.y
    }
    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError> {
        let (t, y) = (self.t, self.y);
        let f0 = match self.f {
            Some(f) => f,
            None => {
                self.stats.rhs_evals += 1;
                eval(sys, t, &y)
            }
        };
        if !all_finite(&f0) {
            return Err(StepError::NotFinite { t });
        }
        let h_max = sys.max_step(&y);
        if self.h == 0.0 {
            self.h = initial_step(
                sys,
                t,
                &y,
                &f0,
                self.rtol,
                8,
                h_max,
                &mut self.stats.rhs_evals,
            );
        }
        let mut k = [[0.0; N]; 16];
        k[0] = f0;
        loop {
            let mut h = self.h.min(h_max);
            // A remainder below 1e-8 h would only be a rounding-sized extra step: take it now.
            let last = t + h >= t_stop || t_stop - (t + h) <= 1e-8 * h;
            if last {
                h = t_stop - t;
            }
            if h <= 10.0 * f64::EPSILON * t.abs().max(1e-300) || h <= 0.0 {
                return Err(StepError::StepTooSmall { t, h });
            }
            k[1] = eval(sys, t + C2 * h, &combine(&y, h, &A2, &[0], &k));
            k[2] = eval(sys, t + C3 * h, &combine(&y, h, &A3, &[0, 1], &k));
            k[3] = eval(sys, t + C4 * h, &combine(&y, h, &A4, &I4, &k));
            k[4] = eval(sys, t + C5 * h, &combine(&y, h, &A5, &I5, &k));
            k[5] = eval(sys, t + C6 * h, &combine(&y, h, &A6, &I6, &k));
            k[6] = eval(sys, t + C7 * h, &combine(&y, h, &A7, &I7, &k));
            k[7] = eval(sys, t + C8 * h, &combine(&y, h, &A8, &I8, &k));
            k[8] = eval(sys, t + C9 * h, &combine(&y, h, &A9, &I9, &k));
            k[9] = eval(sys, t + C10 * h, &combine(&y, h, &A10, &I10, &k));
            k[10] = eval(sys, t + C11 * h, &combine(&y, h, &A11, &I11, &k));
            k[11] = eval(sys, t + h, &combine(&y, h, &A12, &I12, &k));
            self.stats.rhs_evals += 11;
            // Increment and the two error estimates (dop853.f, labels 41-42).
            let mut incr = [0.0; N];
            let mut y1 = [0.0; N];
            let mut e5 = [0.0; N];
            let mut e3 = [0.0; N];
            for i in 0..N {
                let (mut b, mut e) = (0.0, 0.0);
                for j in 0..8 {
                    b += B[j] * k[IB[j]][i];
                    e += ER[j] * k[IB[j]][i];
                }
                incr[i] = h * b + self.comp[i];
                y1[i] = y[i] + incr[i];
                e5[i] = e;
                e3[i] = b - BHH1 * k[0][i] - BHH2 * k[8][i] - BHH3 * k[11][i];
            }
            let (s0, s1) = (sys.scale(&y), sys.scale(&y1));
            let (mut err5, mut err3) = (0.0, 0.0);
            for i in 0..N {
                let sk = (self.rtol * s0[i].max(s1[i])).max(f64::MIN_POSITIVE);
                err5 += (e5[i] / sk).powi(2);
                err3 += (e3[i] / sk).powi(2);
            }
            let deno = if err5 + 0.01 * err3 > 0.0 {
                err5 + 0.01 * err3
            } else {
                1.0
            };
            let err = h * err5 / (N as f64 * deno).sqrt();
            if !err.is_finite() || !all_finite(&y1) {
                // Shrink hard: a non-finite trial step is treated as a large error.
                self.stats.rejected += 1;
                self.h = h * 0.1;
                self.last_rejected = true;
                continue;
            }
            let fac11 = err.powf(0.125);
            let fac = (fac11 / 0.9).clamp(1.0 / 6.0, 1.0 / 0.333);
            if err <= 1.0 {
                self.facold = err.max(1e-4);
                let mut h_new = h / fac;
                if self.last_rejected {
                    h_new = h_new.min(h);
                }
                self.last_rejected = false;
                // Compensated (Kahan) update keeps the state's rounding error from accumulating.
                for i in 0..N {
                    self.comp[i] = incr[i] - (y1[i] - y[i]);
                }
                let f1 = eval(sys, t + h, &y1);
                self.stats.rhs_evals += 1;
                k[12] = f1;
                self.k = k;
                self.cont = None;
                self.t_prev = t;
                self.y_prev = y;
                self.t = if last { t_stop } else { t + h };
                self.y = y1;
                self.f = Some(f1);
                self.h = if last { self.h } else { h_new };
                self.stats.steps += 1;
                return Ok(());
            }
            self.stats.rejected += 1;
            self.last_rejected = true;
            self.h = h / (1.0 / 0.333f64).min(fac11 / 0.9);
        }
    }

    fn prepare_dense<S: Ode<N>>(&mut self, sys: &S) {
        if self.cont.is_some() {
            return;
        }
        let (t, y, h) = (self.t_prev, self.y_prev, self.t - self.t_prev);
        let k = &mut self.k;
        k[13] = eval(sys, t + C14 * h, &combine(&y, h, &A14, &I14, k));
        k[14] = eval(sys, t + C15 * h, &combine(&y, h, &A15, &I15, k));
        k[15] = eval(sys, t + C16 * h, &combine(&y, h, &A16, &I16, k));
        self.stats.rhs_evals += 3;
        let mut cont = [[0.0; N]; 8];
        for i in 0..N {
            let ydiff = self.y[i] - y[i];
            let bspl = h * k[0][i] - ydiff;
            cont[0][i] = y[i];
            cont[1][i] = ydiff;
            cont[2][i] = bspl;
            cont[3][i] = ydiff - h * k[12][i] - bspl;
            for (r, row) in D.iter().enumerate() {
                let mut s = 0.0;
                for (dj, &j) in row.iter().zip(&ID) {
                    s += dj * k[j][i];
                }
                cont[4 + r][i] = h * s;
            }
        }
        self.cont = Some(cont);
    }

    fn interpolate(&self, t: f64) -> [f64; N] {
        let cont = self
            .cont
            .as_ref()
            .expect("prepare_dense before interpolate");
        let h = self.t - self.t_prev;
        let s = if h == 0.0 { 1.0 } else { (t - self.t_prev) / h };
        let s1 = 1.0 - s;
        // dop853.f, function CONTD8.
        std::array::from_fn(|i| {
            let cona = cont[4][i] + s * (cont[5][i] + s1 * (cont[6][i] + s * cont[7][i]));
            cont[0][i] + s * (cont[1][i] + s1 * (cont[2][i] + s * (cont[3][i] + s1 * cona)))
        })
    }

    fn restart(&mut self, t: f64, y: [f64; N]) {
        // Keep the step-size proposal: the dynamics change at an event, not their time scale.
        let (rtol, stats, h) = (self.rtol, self.stats, self.h);
        *self = Dop853::new(t, y, rtol);
        self.stats = stats;
        self.h = h;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}

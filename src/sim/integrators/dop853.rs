//! DOP853: the explicit Runge-Kutta method of order 8 by Dormand & Prince with the error
//! estimator of order 5 and 3 and a dense output of order 7.
//!
//! Source of the coefficients and of the step-size control: E. Hairer, S. P. Nørsett and
//! G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., sec. II.5 and II.6, and the
//! Fortran code `dop853.f` (Hairer & Wanner, version of 2004), whose parameter tables `C*`, `A*`,
//! `B*`, `BHH*`, `ER*`, `D*` are transcribed below under the same names (30-digit decimals,
//! rounded to f64 by the compiler). The error weights are `rtol * max(scale(y0), scale(y1))`, as in
//! [`super::error_norm`], with the combined 5th/3rd-order estimate of dop853.f.

use super::Integrator;
use super::adaptive::{trial_step, AdaptiveState, Controller};
use super::{all_finite, eval, Ode, Stats, StepError, Stepper};

use super::dop853_tables::*;
use super::card::{Card, ControlKind, Stiffness, Sweep, PenaltyFit};
use super::Control;

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

/// The step-size control of dop853.f: plain I control on the combined 5th/3rd-order estimate.
const CONTROL: Controller = Controller {
    expo: 0.125,
    beta: 0.0,
    fac_lo: 1.0 / 6.0,
    fac_hi: 1.0 / 0.333,
};


/// The card of Dormand-Prince 8(5,3) ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "dop853",
    title: "Dormand-Prince 8(5,3)",
    control: ControlKind::Tolerance,
    order: Some(8),
    // dop853.f: "dense output of order 7".
    dense_order: Some(7),
    // 5.96: the stability function 1 + z bᵀ(I − zA)⁻¹1 of the 12-stage tableau has |R(i y)| ≤ 1 up
    // to y ≈ 5.96 (computed from SciPy's copy of the same coefficients).
    stiffness: Stiffness::Explicit { oscillation_limit: 5.96 },
    rigid_only: false,
    // Half decades: its runs of at least 10 steps above the rounding floor span only 2-3 decades
    // of tolerance on the short scenes, too few decade points for the order fit
    // (`report::work_precision::fit`, rule 2).
    sweep: Sweep::Tolerances { from: 3, to: 16, per_decade: 2 },
    penalty_fit: Some(PenaltyFit { stability: 0.7, estimate_order: 8.0, accuracy: (0.3, 2.5), wall_force_rate: 3500.0 }),
    stiff_case: Some(Control::Tolerance(1e-10)),
};
/// The DOP853 integrator (adaptive, dense output of order 7).
#[derive(Clone, Debug)]
pub struct Dop853<const N: usize> {
    state: AdaptiveState<N>,
    comp: [f64; N],
    k: [[f64; N]; 16],
    cont: Option<[[f64; N]; 8]>,
}

impl<const N: usize> Dop853<N> {
    /// Start at `(t0, y0)` with relative tolerance `rtol`.
    pub fn new(t0: f64, y0: [f64; N], rtol: f64) -> Self {
        Dop853 {
            state: AdaptiveState::new(t0, y0, rtol),
            comp: [0.0; N],
            k: [[0.0; N]; 16],
            cont: None,
        }
    }
}

impl<const N: usize> Integrator<N> for Dop853<N> {
    fn start(t0: f64, y0: [f64; N], control: Control, _order: Option<usize>) -> Option<Self> {
        match control {
            Control::Tolerance(rtol) => Some(Dop853::new(t0, y0, rtol)),
            Control::Fixed(_) => None,
        }
    }
}

/// The error of a step `h` from `y` to `y1` (dop853.f, labels 41-42): the fifth-order estimate
/// `e5` damped by the third-order `e3`, err = h err5 / √(N (err5 + 0.01 err3)) with the sums of
/// squares of the estimates over rtol times the larger scale of `y` and `y1`.
fn combined_error<const N: usize, S: Ode<N>>(
    sys: &S,
    rtol: f64,
    (y, y1): (&[f64; N], &[f64; N]),
    (e5, e3): (&[f64; N], &[f64; N]),
    h: f64,
) -> f64 {
    let (s0, s1) = (sys.scale(y), sys.scale(y1));
    let (mut r5, mut r3) = ([0.0; N], [0.0; N]);
    for i in 0..N {
        let sk = (rtol * s0[i].max(s1[i])).max(f64::MIN_POSITIVE);
        (r5[i], r3[i]) = (e5[i] / sk, e3[i] / sk);
    }
    // The sums of squares in units of the largest ratio when that is huge: a state of
    // size 1e-273 (a start that close to the floor) gives ratios ~1e267 whose squares
    // overflow, and inf/inf made every trial NaN down to a step of 0 (issue 17, F7).
    // err = h big err5' / √(N deno') with the primed sums over ratios / big.
    let big = r5.iter().chain(&r3).fold(0.0f64, |m, r| m.max(r.abs()));
    let big = if big > 1e150 && big.is_finite() {
        big
    } else {
        1.0
    };
    let (mut err5, mut err3) = (0.0, 0.0);
    for i in 0..N {
        err5 += (r5[i] / big).powi(2);
        err3 += (r3[i] / big).powi(2);
    }
    let deno = if err5 + 0.01 * err3 > 0.0 {
        err5 + 0.01 * err3
    } else {
        1.0
    };
    h * big * err5 / (N as f64 * deno).sqrt()
}

impl<const N: usize> Stepper<N> for Dop853<N> {
    fn t(&self) -> f64 {
        self.state.t
    }
    fn y(&self) -> [f64; N] {
        self.state.y
    }
    fn t_prev(&self) -> f64 {
        self.state.t_prev
    }

    fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError> {
        let (t, y) = (self.state.t, self.state.y);
        let (f0, h_max) = self.state.start(sys, 8)?;
        let mut k = [[0.0; N]; 16];
        k[0] = f0;
        loop {
            let (h, last) = trial_step(self.state.h, h_max, t, t_stop)?;
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
            self.state.stats.rhs_evals += 11;
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
            let err = combined_error(sys, self.state.rtol, (&y, &y1), (&e5, &e3), h);
            if !err.is_finite() || !all_finite(&y1) {
                // Shrink hard: a non-finite trial step is treated as a large error.
                self.state.reject_non_finite(h);
                continue;
            }
            if let Some(h_new) = self.state.control(&CONTROL, h, err) {
                // Compensated (Kahan) update keeps the state's rounding error from accumulating.
                for i in 0..N {
                    self.comp[i] = incr[i] - (y1[i] - y[i]);
                }
                let f1 = eval(sys, t + h, &y1);
                self.state.stats.rhs_evals += 1;
                k[12] = f1;
                self.k = k;
                self.cont = None;
                self.state.accept(h, h_new, last, t_stop, y1, f1);
                return Ok(());
            }
        }
    }

    fn prepare_dense<S: Ode<N>>(&mut self, sys: &S) {
        if self.cont.is_some() {
            return;
        }
        let st = &self.state;
        let (t, y, h, y1) = (st.t_prev, st.y_prev, st.t - st.t_prev, st.y);
        let k = &mut self.k;
        k[13] = eval(sys, t + C14 * h, &combine(&y, h, &A14, &I14, k));
        k[14] = eval(sys, t + C15 * h, &combine(&y, h, &A15, &I15, k));
        k[15] = eval(sys, t + C16 * h, &combine(&y, h, &A16, &I16, k));
        self.state.stats.rhs_evals += 3;
        let mut cont = [[0.0; N]; 8];
        for i in 0..N {
            let ydiff = y1[i] - y[i];
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
        let (t_prev, h) = (self.state.t_prev, self.state.t - self.state.t_prev);
        let s = if h == 0.0 { 1.0 } else { (t - t_prev) / h };
        let s1 = 1.0 - s;
        // dop853.f, function CONTD8.
        std::array::from_fn(|i| {
            let cona = cont[4][i] + s * (cont[5][i] + s1 * (cont[6][i] + s * cont[7][i]));
            cont[0][i] + s * (cont[1][i] + s1 * (cont[2][i] + s * (cont[3][i] + s1 * cona)))
        })
    }

    fn stats(&self) -> Stats {
        self.state.stats
    }
}

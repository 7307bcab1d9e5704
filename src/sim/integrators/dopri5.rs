//! DOPRI5: the Dormand-Prince Runge-Kutta pair of order 5(4) with a free dense output of order 4.
//!
//! Source: J. R. Dormand and P. J. Prince, "A family of embedded Runge-Kutta formulae",
//! J. Comput. Appl. Math. 6 (1980); Hairer, Nørsett & Wanner, *Solving ODEs I*, Table II.5.2
//! (coefficients) and sec. II.6 (dense output), and the Fortran code `dopri5.f` (parameters
//! `D1`..`D7` of its dense output, the PI step-size control with `BETA = 0.04`).

use super::Integrator;
use super::adaptive::{trial_step, AdaptiveState, Controller};
use super::{all_finite, error_norm, eval, Ode, Stats, StepError, Stepper};
use super::card::{Card, ControlKind, Stiffness, Sweep, PenaltyFit};
use super::Control;

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
/// Weights of the 5th-order solution (stage 2 has weight 0); also the 7th stage's row (FSAL).
const B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
/// Difference between the 5th- and 4th-order weights, stages 1..7.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
/// Dense output weights (dopri5.f `D1`..`D7`).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

#[inline(always)]
fn combine<const N: usize>(y: &[f64; N], h: f64, a: &[f64], k: &[[f64; N]; 7]) -> [f64; N] {
    std::array::from_fn(|i| {
        let mut s = 0.0;
        for (j, aj) in a.iter().enumerate() {
            s += aj * k[j][i];
        }
        y[i] + h * s
    })
}

/// The PI step-size control of dopri5.f: expo1 = 0.2 - 0.75 * beta, beta = 0.04.
pub const CONTROL: Controller = Controller {
    expo: 0.2 - 0.75 * 0.04,
    beta: 0.04,
    fac_lo: 0.1,
    fac_hi: 5.0,
};


/// The card of Dormand-Prince 5(4) ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "dopri5",
    title: "Dormand-Prince 5(4)",
    control: ControlKind::Tolerance,
    order: Some(5),
    // dopri5.f: "dense output of order 4".
    dense_order: Some(4),
    // 0.997: R(z) = Σ_{k≤5} z^k/k! + z⁶/600 has |R(i y)| ≤ 1 only up to y ≈ 0.997
    // (`tests/sim/integrators/card.rs` holds it).
    stiffness: Stiffness::Explicit { oscillation_limit: 0.997 },
    rigid_only: false,
    sweep: Sweep::Tolerances { from: 3, to: 15, per_decade: 1 },
    penalty_fit: Some(PenaltyFit { stability: 1.05, estimate_order: 5.0, accuracy: (0.3, 0.05), wall_force_rate: 75.0 }),
    stiff_case: Some(Control::Tolerance(1e-10)),
};
/// The DOPRI5 integrator (adaptive, dense output of order 4).
#[derive(Clone, Debug)]
pub struct Dopri5<const N: usize> {
    state: AdaptiveState<N>,
    k: [[f64; N]; 7],
}

impl<const N: usize> Dopri5<N> {
    /// Start at `(t0, y0)` with relative tolerance `rtol`.
    pub fn new(t0: f64, y0: [f64; N], rtol: f64) -> Self {
        Dopri5 {
            state: AdaptiveState::new(t0, y0, rtol),
            k: [[0.0; N]; 7],
        }
    }
}

impl<const N: usize> Integrator<N> for Dopri5<N> {
    fn start(t0: f64, y0: [f64; N], control: Control, _order: Option<usize>) -> Option<Self> {
        match control {
            Control::Tolerance(rtol) => Some(Dopri5::new(t0, y0, rtol)),
            Control::Fixed(_) => None,
        }
    }
}

impl<const N: usize> Stepper<N> for Dopri5<N> {
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
        let (f0, h_max) = self.state.start(sys, 5)?;
        let mut k = [[0.0; N]; 7];
        k[0] = f0;
        loop {
            let (h, last) = trial_step(self.state.h, h_max, t, t_stop)?;
            k[1] = eval(sys, t + C2 * h, &combine(&y, h, &[A21], &k));
            k[2] = eval(sys, t + C3 * h, &combine(&y, h, &A3, &k));
            k[3] = eval(sys, t + C4 * h, &combine(&y, h, &A4, &k));
            k[4] = eval(sys, t + C5 * h, &combine(&y, h, &A5, &k));
            k[5] = eval(sys, t + h, &combine(&y, h, &A6, &k));
            let y1 = combine(&y, h, &B, &k);
            k[6] = eval(sys, t + h, &y1);
            self.state.stats.rhs_evals += 6;
            let e: [f64; N] =
                std::array::from_fn(|i| h * (0..7).map(|j| E[j] * k[j][i]).sum::<f64>());
            let err = error_norm(sys, &e, &y, &y1, self.state.rtol);
            if !err.is_finite() || !all_finite(&y1) {
                self.state.reject_non_finite(h);
                continue;
            }
            if let Some(h_new) = self.state.control(&CONTROL, h, err) {
                self.k = k;
                self.state.accept(h, h_new, last, t_stop, y1, k[6]);
                return Ok(());
            }
        }
    }

    fn prepare_dense<S: Ode<N>>(&mut self, _sys: &S) {}

    fn interpolate(&self, t: f64) -> [f64; N] {
        let st = &self.state;
        let h = st.t - st.t_prev;
        let s = if h == 0.0 { 1.0 } else { (t - st.t_prev) / h };
        let s1 = 1.0 - s;
        let k = &self.k;
        // dopri5.f, function CONTD5.
        std::array::from_fn(|i| {
            let ydiff = st.y[i] - st.y_prev[i];
            let bspl = h * k[0][i] - ydiff;
            let r4 = ydiff - h * k[6][i] - bspl;
            let r5 = h * (0..7).map(|j| D[j] * k[j][i]).sum::<f64>();
            st.y_prev[i] + s * (ydiff + s1 * (bspl + s * (r4 + s1 * r5)))
        })
    }

    fn stats(&self) -> Stats {
        self.state.stats
    }
}

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

const C2: f64 = 0.526001519587677318785587544488E-01;
const C3: f64 = 0.789002279381515978178381316732E-01;
const C4: f64 = 0.118350341907227396726757197510E+00;
const C5: f64 = 0.281649658092772603273242802490E+00;
const C6: f64 = 0.333333333333333333333333333333E+00;
const C7: f64 = 0.25E+00;
const C8: f64 = 0.307692307692307692307692307692E+00;
const C9: f64 = 0.651282051282051282051282051282E+00;
const C10: f64 = 0.6E+00;
const C11: f64 = 0.857142857142857142857142857142E+00;
const C14: f64 = 0.1E+00;
const C15: f64 = 0.2E+00;
const C16: f64 = 0.777777777777777777777777777778E+00;

const B: [f64; 8] = [
    5.42937341165687622380535766363E-2,  // B1
    4.45031289275240888144113950566E0,   // B6
    1.89151789931450038304281599044E0,   // B7
    -5.8012039600105847814672114227E0,   // B8
    3.1116436695781989440891606237E-1,   // B9
    -1.52160949662516078556178806805E-1, // B10
    2.01365400804030348374776537501E-1,  // B11
    4.47106157277725905176885569043E-2,  // B12
];
const BHH1: f64 = 0.244094488188976377952755905512E+00;
const BHH2: f64 = 0.733846688281611857341361741547E+00;
const BHH3: f64 = 0.220588235294117647058823529412E-01;
const ER: [f64; 8] = [
    0.1312004499419488073250102996E-01,  // ER1
    -0.1225156446376204440720569753E+01, // ER6
    -0.4957589496572501915214079952E+00, // ER7
    0.1664377182454986536961530415E+01,  // ER8
    -0.3503288487499736816886487290E+00, // ER9
    0.3341791187130174790297318841E+00,  // ER10
    0.8192320648511571246570742613E-01,  // ER11
    -0.2235530786388629525884427845E-01, // ER12
];

const A2: [f64; 1] = [5.26001519587677318785587544488E-2];
const A3: [f64; 2] = [
    1.97250569845378994544595329183E-2,
    5.91751709536136983633785987549E-2,
];
const A4: [f64; 2] = [
    2.95875854768068491816892993775E-2,
    8.87627564304205475450678981324E-2,
]; // 1, 3
const A5: [f64; 3] = [
    2.41365134159266685502369798665E-1,
    -8.84549479328286085344864962717E-1,
    9.24834003261792003115737966543E-1,
]; // 1, 3, 4
const A6: [f64; 3] = [
    3.7037037037037037037037037037E-2,
    1.70828608729473871279604482173E-1,
    1.25467687566822425016691814123E-1,
]; // 1, 4, 5
const A7: [f64; 4] = [
    3.7109375E-2,
    1.70252211019544039314978060272E-1,
    6.02165389804559606850219397283E-2,
    -1.7578125E-2,
]; // 1, 4, 5, 6
const A8: [f64; 5] = [
    3.70920001185047927108779319836E-2,
    1.70383925712239993810214054705E-1,
    1.07262030446373284651809199168E-1,
    -1.53194377486244017527936158236E-2,
    8.27378916381402288758473766002E-3,
]; // 1, 4..7
const A9: [f64; 6] = [
    6.24110958716075717114429577812E-1,
    -3.36089262944694129406857109825E0,
    -8.68219346841726006818189891453E-1,
    2.75920996994467083049415600797E1,
    2.01540675504778934086186788979E1,
    -4.34898841810699588477366255144E1,
]; // 1, 4..8
const A10: [f64; 7] = [
    4.77662536438264365890433908527E-1,
    -2.48811461997166764192642586468E0,
    -5.90290826836842996371446475743E-1,
    2.12300514481811942347288949897E1,
    1.52792336328824235832596922938E1,
    -3.32882109689848629194453265587E1,
    -2.03312017085086261358222928593E-2,
]; // 1, 4..9
const A11: [f64; 8] = [
    -9.3714243008598732571704021658E-1,
    5.18637242884406370830023853209E0,
    1.09143734899672957818500254654E0,
    -8.14978701074692612513997267357E0,
    -1.85200656599969598641566180701E1,
    2.27394870993505042818970056734E1,
    2.49360555267965238987089396762E0,
    -3.0467644718982195003823669022E0,
]; // 1, 4..10
const A12: [f64; 9] = [
    2.27331014751653820792359768449E0,
    -1.05344954667372501984066689879E1,
    -2.00087205822486249909675718444E0,
    -1.79589318631187989172765950534E1,
    2.79488845294199600508499808837E1,
    -2.85899827713502369474065508674E0,
    -8.87285693353062954433549289258E0,
    1.23605671757943030647266201528E1,
    6.43392746015763530355970484046E-1,
]; // 1, 4..11
const A14: [f64; 8] = [
    5.61675022830479523392909219681E-2,
    2.53500210216624811088794765333E-1,
    -2.46239037470802489917441475441E-1,
    -1.24191423263816360469010140626E-1,
    1.5329179827876569731206322685E-1,
    8.20105229563468988491666602057E-3,
    7.56789766054569976138603589584E-3,
    -8.298E-3,
]; // 1, 7..13
const A15: [f64; 8] = [
    3.18346481635021405060768473261E-2,
    2.83009096723667755288322961402E-2,
    5.35419883074385676223797384372E-2,
    -5.49237485713909884646569340306E-2,
    -1.08347328697249322858509316994E-4,
    3.82571090835658412954920192323E-4,
    -3.40465008687404560802977114492E-4,
    1.41312443674632500278074618366E-1,
]; // 1, 6, 7, 8, 11, 12, 13, 14
const A16: [f64; 8] = [
    -4.28896301583791923408573538692E-1,
    -4.69762141536116384314449447206E0,
    7.68342119606259904184240953878E0,
    4.06898981839711007970213554331E0,
    3.56727187455281109270669543021E-1,
    -1.39902416515901462129418009734E-3,
    2.9475147891527723389556272149E0,
    -9.15095847217987001081870187138E0,
]; // 1, 6, 7, 8, 9, 13, 14, 15

/// Dense-output rows D4..D7, columns for stages 1, 6..16 (dop853.f `D41`..`D716`).
const D: [[f64; 12]; 4] = [
    [
        -0.84289382761090128651353491142E+01,
        0.56671495351937776962531783590E+00,
        -0.30689499459498916912797304727E+01,
        0.23846676565120698287728149680E+01,
        0.21170345824450282767155149946E+01,
        -0.87139158377797299206789907490E+00,
        0.22404374302607882758541771650E+01,
        0.63157877876946881815570249290E+00,
        -0.88990336451333310820698117400E-01,
        0.18148505520854727256656404962E+02,
        -0.91946323924783554000451984436E+01,
        -0.44360363875948939664310572000E+01,
    ],
    [
        0.10427508642579134603413151009E+02,
        0.24228349177525818288430175319E+03,
        0.16520045171727028198505394887E+03,
        -0.37454675472269020279518312152E+03,
        -0.22113666853125306036270938578E+02,
        0.77334326684722638389603898808E+01,
        -0.30674084731089398182061213626E+02,
        -0.93321305264302278729567221706E+01,
        0.15697238121770843886131091075E+02,
        -0.31139403219565177677282850411E+02,
        -0.93529243588444783865713862664E+01,
        0.35816841486394083752465898540E+02,
    ],
    [
        0.19985053242002433820987653617E+02,
        -0.38703730874935176555105901742E+03,
        -0.18917813819516756882830838328E+03,
        0.52780815920542364900561016686E+03,
        -0.11573902539959630126141871134E+02,
        0.68812326946963000169666922661E+01,
        -0.10006050966910838403183860980E+01,
        0.77771377980534432092869265740E+00,
        -0.27782057523535084065932004339E+01,
        -0.60196695231264120758267380846E+02,
        0.84320405506677161018159903784E+02,
        0.11992291136182789328035130030E+02,
    ],
    [
        -0.25693933462703749003312586129E+02,
        -0.15418974869023643374053993627E+03,
        -0.23152937917604549567536039109E+03,
        0.35763911791061412378285349910E+03,
        0.93405324183624310003907691704E+02,
        -0.37458323136451633156875139351E+02,
        0.10409964950896230045147246184E+03,
        0.29840293426660503123344363579E+02,
        -0.43533456590011143754432175058E+02,
        0.96324553959188282948394950600E+02,
        -0.39177261675615439165231486172E+02,
        -0.14972683625798562581422125276E+03,
    ],
];

/// Stage indices (0-based) that the rows above combine, in order.
const I4: [usize; 2] = [0, 2];
const I5: [usize; 3] = [0, 2, 3];
const I6: [usize; 3] = [0, 3, 4];
const I7: [usize; 4] = [0, 3, 4, 5];
const I8: [usize; 5] = [0, 3, 4, 5, 6];
const I9: [usize; 6] = [0, 3, 4, 5, 6, 7];
const I10: [usize; 7] = [0, 3, 4, 5, 6, 7, 8];
const I11: [usize; 8] = [0, 3, 4, 5, 6, 7, 8, 9];
const I12: [usize; 9] = [0, 3, 4, 5, 6, 7, 8, 9, 10];
const IB: [usize; 8] = [0, 5, 6, 7, 8, 9, 10, 11];
const I14: [usize; 8] = [0, 6, 7, 8, 9, 10, 11, 12];
const I15: [usize; 8] = [0, 5, 6, 7, 10, 11, 12, 13];
const I16: [usize; 8] = [0, 5, 6, 7, 8, 12, 13, 14];
const ID: [usize; 12] = [0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15];

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

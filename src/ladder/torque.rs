//! Secs. 2.2-2.6: the torque analyses about A, B, C, D and E, as printed, eqs. (11)-(28).
//!
//! Each `eqNN_*` function returns the printed forms of one display in the order they appear, so
//! that a check can hold every printed equality against the others and against the independent
//! references (automatic differentiation of the printed angular momentum, and the three-particle
//! model). The contact forces inside them are the note's (14) and (15).

use super::energy::moment_of_inertia_cm;
use super::forces::{floor_force, wall_force};
use super::{Ladder, State};
use crate::scalar::{sq, Scalar};
use crate::vector::Vec3;

/// The symbols of the note at one state, cloned on use so formulas read like the print.
struct Sym<'a, T>(&'a Ladder<T>, &'a State<T>);

impl<T: Scalar> Sym<'_, T> {
    fn m(&self) -> T {
        self.0.m.clone()
    }
    fn g(&self) -> T {
        self.0.g.clone()
    }
    fn l(&self) -> T {
        self.0.l.clone()
    }
    fn s(&self) -> T {
        self.1.sin.clone()
    }
    fn c(&self) -> T {
        self.1.cos.clone()
    }
    /// θ̇
    fn w(&self) -> T {
        self.1.rate.clone()
    }
    /// θ̈
    fn wd(&self) -> T {
        self.1.accel.clone()
    }
    /// m l²
    fn ml2(&self) -> T {
        self.m() * sq(&self.0.l)
    }
    /// m g l sin θ
    fn mgls(&self) -> T {
        self.m() * self.g() * self.l() * self.s()
    }
    fn n(k: i64) -> T {
        T::int(k)
    }
}

/// Eq. (11): the torque about A, τ_A = 2 F_f l sin θ − m g l sin θ − 2 F_w l cos θ.
pub fn torque_about_a<T: Scalar>(ladder: &Ladder<T>, st: &State<T>, f_w: T, f_f: T) -> T {
    let k = Sym(ladder, st);
    Sym::<T>::n(2) * f_f * k.l() * k.s() - k.mgls() - Sym::<T>::n(2) * f_w * k.l() * k.c()
}

/// Eq. (12): L_A as printed, [−m l² θ̇ + m l² θ̇/3, −2 m l² θ̇/3].
pub fn eq12_angular_momentum_about_a<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 2] {
    let k = Sym(ladder, st);
    [
        -(k.ml2() * k.w()) + k.ml2() * k.w() / Sym::<T>::n(3),
        -(Sym::<T>::n(2) * k.ml2() * k.w()) / Sym::<T>::n(3),
    ]
}

/// Eq. (12), last form: the angular momentum about A, L_A = −2 m l² θ̇/3.
pub fn angular_momentum_about_a<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    let [_, last] = eq12_angular_momentum_about_a(ladder, st);
    last
}

/// Eq. (13): the moment of inertia about A, C, D or E, [I_cm + m l², 4 m l²/3].
pub fn eq13_moment_of_inertia_about_corner<T: Scalar>(ladder: &Ladder<T>) -> [T; 2] {
    let ml2 = ladder.m.clone() * sq(&ladder.l);
    [
        moment_of_inertia_cm(ladder) + ml2.clone(),
        T::int(4) * ml2 / T::int(3),
    ]
}

/// Eq. (16): the analysis about A as printed, in order: −2ml²θ̈/3, τ_A (eq. 11 with (14), (15)),
/// the expanded sum, m g l sin θ − 2 m l² θ̈.
pub fn eq16_torque_analysis_a<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 4] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let (s, c, w, wd, ml2) = (k.s(), k.c(), k.w(), k.wd(), k.ml2());
    let expanded = n(2) * k.mgls()
        - n(2) * ml2.clone() * sq(&s) * wd.clone()
        - n(2) * ml2.clone() * c.clone() * s.clone() * sq(&w)
        - k.mgls()
        - n(2) * ml2.clone() * sq(&c) * wd.clone()
        + n(2) * ml2.clone() * c * s * sq(&w);
    [
        -(n(2) * ml2.clone() * wd.clone()) / n(3),
        torque_about_a(ladder, st, wall_force(ladder, st), floor_force(ladder, st)),
        expanded,
        k.mgls() - n(2) * ml2 * wd,
    ]
}

/// Eq. (17): the coordinate force on the centre of mass seen from an accelerating point P,
/// F_P = −m a_P.
pub fn coordinate_force<T: Scalar>(m: &T, a_p: &Vec3<T>) -> Vec3<T> {
    a_p.scale(&(-m.clone()))
}

/// Eq. (18): the angular momentum about B, the centre of mass, L_B = I_cm θ̇.
pub fn angular_momentum_about_b<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    moment_of_inertia_cm(ladder) * st.rate.clone()
}

/// Eq. (19): the analysis about B as printed: m l² θ̈/3, τ_B = F_f l sin θ − F_w l cos θ, the
/// expanded sum, m g l sin θ − m l² θ̈.
pub fn eq19_torque_analysis_b<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 4] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let (s, c, w, wd, ml2) = (k.s(), k.c(), k.w(), k.wd(), k.ml2());
    let tau =
        floor_force(ladder, st) * k.l() * s.clone() - wall_force(ladder, st) * k.l() * c.clone();
    let expanded = k.mgls()
        - ml2.clone() * sq(&s) * wd.clone()
        - ml2.clone() * c.clone() * s.clone() * sq(&w)
        - ml2.clone() * sq(&c) * wd.clone()
        + ml2.clone() * c * s * sq(&w);
    [
        ml2.clone() * wd.clone() / n(3),
        tau,
        expanded,
        k.mgls() - ml2 * wd,
    ]
}

/// Eq. (20): the coordinate force for C as printed, [(0, −2m ÿ_cm) with ÿ_cm from (8),
/// (0, 2 m l sin θ θ̈ + 2 m l cos θ θ̇²)].
pub fn eq20_coordinate_force_c<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [Vec3<T>; 2] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let a = super::geometry::cm_acceleration(ladder, st);
    let ml = k.m() * k.l();
    [
        Vec3::planar(n(0), -(n(2) * k.m() * a.y)),
        Vec3::planar(
            n(0),
            n(2) * ml.clone() * k.s() * k.wd() + n(2) * ml * k.c() * sq(&k.w()),
        ),
    ]
}

/// Eq. (21): L_C = I_C θ̇ = 4 m l² θ̇/3 as printed (L'_C in Appendix A's notation).
pub fn eq21_angular_momentum_about_c<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 2] {
    let i_c = eq13_moment_of_inertia_about_corner(ladder)[1].clone();
    let k = Sym(ladder, st);
    [
        i_c * k.w(),
        Sym::<T>::n(4) * k.ml2() * k.w() / Sym::<T>::n(3),
    ]
}

/// Eq. (22): the analysis about C as printed: 4ml²θ̈/3, τ_C + F_C,y l sin θ,
/// −mgl sin θ + 2 F_f l sin θ + F_C,y l sin θ, the expanded sum, m g l sin θ.
pub fn eq22_torque_analysis_c<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 5] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let (s, c, w, wd, ml2) = (k.s(), k.c(), k.w(), k.wd(), k.ml2());
    let f_cy = eq20_coordinate_force_c(ladder, st)[1].y.clone();
    let tau_c = -k.mgls() + n(2) * floor_force(ladder, st) * k.l() * s.clone();
    let expanded = -k.mgls() + n(2) * k.mgls()
        - n(2) * ml2.clone() * sq(&s) * wd.clone()
        - n(2) * ml2.clone() * c.clone() * s.clone() * sq(&w)
        + n(2) * ml2.clone() * sq(&s) * wd.clone()
        + n(2) * ml2.clone() * c * s.clone() * sq(&w);
    [
        n(4) * ml2 * wd / n(3),
        tau_c.clone() + f_cy.clone() * k.l() * s.clone(),
        -k.mgls() + n(2) * floor_force(ladder, st) * k.l() * s.clone() + f_cy * k.l() * s,
        expanded,
        k.mgls(),
    ]
}

/// Eq. (23): the coordinate force for D as printed, [(−2m ẍ_cm, 0) with ẍ_cm from (8),
/// (−2 m l cos θ θ̈ + 2 m l sin θ θ̇², 0)].
pub fn eq23_coordinate_force_d<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [Vec3<T>; 2] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let a = super::geometry::cm_acceleration(ladder, st);
    let ml = k.m() * k.l();
    [
        Vec3::planar(-(n(2) * k.m() * a.x), n(0)),
        Vec3::planar(
            -(n(2) * ml.clone() * k.c() * k.wd()) + n(2) * ml * k.s() * sq(&k.w()),
            n(0),
        ),
    ]
}

/// Eq. (24): L_D = I_D θ̇ = 4 m l² θ̇/3 as printed (L'_D in Appendix A's notation).
pub fn eq24_angular_momentum_about_d<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 2] {
    eq21_angular_momentum_about_c(ladder, st)
}

/// Eq. (25): the analysis about D as printed: 4ml²θ̈/3, τ_D − F_D,x l cos θ,
/// mgl sin θ − 2 F_w l cos θ − F_D,x l cos θ, the expanded sum, m g l sin θ.
pub fn eq25_torque_analysis_d<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 5] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let (s, c, w, wd, ml2) = (k.s(), k.c(), k.w(), k.wd(), k.ml2());
    let f_dx = eq23_coordinate_force_d(ladder, st)[1].x.clone();
    let tau_d = k.mgls() - n(2) * wall_force(ladder, st) * k.l() * c.clone();
    let expanded = k.mgls() - n(2) * ml2.clone() * sq(&c) * wd.clone()
        + n(2) * ml2.clone() * c.clone() * s.clone() * sq(&w)
        + n(2) * ml2.clone() * sq(&c) * wd.clone()
        - n(2) * ml2.clone() * c.clone() * s * sq(&w);
    [
        n(4) * ml2 * wd / n(3),
        tau_d - f_dx.clone() * k.l() * c.clone(),
        k.mgls() - n(2) * wall_force(ladder, st) * k.l() * c.clone() - f_dx * k.l() * c,
        expanded,
        k.mgls(),
    ]
}

/// Eq. (26): the coordinate force for E as printed, [(−2m ẍ_cm, −2m ÿ_cm) with (8),
/// (−2ml cos θ θ̈ + 2ml sin θ θ̇², 2ml sin θ θ̈ + 2ml cos θ θ̇²)].
pub fn eq26_coordinate_force_e<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [Vec3<T>; 2] {
    let d = eq23_coordinate_force_d(ladder, st);
    let c = eq20_coordinate_force_c(ladder, st);
    [
        Vec3::planar(d[0].x.clone(), c[0].y.clone()),
        Vec3::planar(d[1].x.clone(), c[1].y.clone()),
    ]
}

/// Eq. (27): L_E as printed (L'_E in Appendix A's notation), [−ml²θ̇ + ml²θ̇/3, −2ml²θ̇/3].
pub fn eq27_angular_momentum_about_e<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 2] {
    eq12_angular_momentum_about_a(ladder, st)
}

/// The torque of the real forces about E: only gravity has an arm, τ_E = m g l sin θ
/// (the floor and wall forces act along lines through E, as sec. 2.6 says).
pub fn torque_about_e<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    Sym(ladder, st).mgls()
}

/// Eq. (28): the analysis about E as printed: −2ml²θ̈/3, τ_E − F_E,y l sin θ,
/// mgl sin θ + F_E,x l cos θ − F_E,y l sin θ, the expanded sum, mgl sin θ − 2ml²θ̈.
pub fn eq28_torque_analysis_e<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> [T; 5] {
    let k = Sym(ladder, st);
    let n = Sym::<T>::n;
    let (s, c, w, wd, ml2) = (k.s(), k.c(), k.w(), k.wd(), k.ml2());
    let f_e = eq26_coordinate_force_e(ladder, st)[1].clone();
    let expanded = k.mgls() - n(2) * ml2.clone() * sq(&c) * wd.clone()
        + n(2) * ml2.clone() * c.clone() * s.clone() * sq(&w)
        - n(2) * ml2.clone() * sq(&s) * wd.clone()
        - n(2) * ml2.clone() * c.clone() * s.clone() * sq(&w);
    [
        -(n(2) * ml2.clone() * wd.clone()) / n(3),
        torque_about_e(ladder, st) - f_e.y.clone() * k.l() * s.clone(),
        k.mgls() + f_e.x * k.l() * c - f_e.y * k.l() * s,
        expanded,
        k.mgls() - n(2) * ml2 * wd,
    ]
}

/// Eq. (28) corrected: the second form needs the x coordinate force's torque too,
/// τ_E + F_E,x l cos θ − F_E,y l sin θ.
pub fn eq28_second_form_corrected<T: Scalar>(ladder: &Ladder<T>, st: &State<T>) -> T {
    let k = Sym(ladder, st);
    let f_e = eq26_coordinate_force_e(ladder, st)[1].clone();
    torque_about_e(ladder, st) + f_e.x * k.l() * k.c() - f_e.y * k.l() * k.s()
}

/// The note's analysis about one of A-E as a residual: d/dt of the printed angular momentum
/// ((12), (18), (21), (24), (27), differentiated along the motion) minus the printed torque side
/// ((16), (19), (22), (25) second form; (28) third form, since its second form is misprinted).
pub fn analysis_residual<T: Scalar>(k: super::geometry::Corner, l: &Ladder<T>, s: &State<T>) -> T {
    use super::geometry::Corner;
    use crate::system::rate;
    let (lc, sl) = (l.constant(), s.along_motion());
    match k {
        Corner::A => {
            rate::<T>(angular_momentum_about_a(&lc, &sl)) - eq16_torque_analysis_a(l, s)[1].clone()
        }
        Corner::B => {
            rate::<T>(angular_momentum_about_b(&lc, &sl)) - eq19_torque_analysis_b(l, s)[1].clone()
        }
        Corner::C => {
            rate::<T>(eq21_angular_momentum_about_c(&lc, &sl)[1].clone())
                - eq22_torque_analysis_c(l, s)[1].clone()
        }
        Corner::D => {
            rate::<T>(eq24_angular_momentum_about_d(&lc, &sl)[1].clone())
                - eq25_torque_analysis_d(l, s)[1].clone()
        }
        Corner::E => {
            rate::<T>(eq27_angular_momentum_about_e(&lc, &sl)[1].clone())
                - eq28_torque_analysis_e(l, s)[2].clone()
        }
    }
}

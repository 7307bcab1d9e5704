//! The ball in the cylinder as Newton-Euler equations in Cartesian vectors (note sec. B.10,
//! Milne sec. 421), for the crate's integrators ([`Ode`]).
//!
//! State y = (x, v, ω): the ball's centre, its velocity and its angular velocity, nine numbers in
//! the lab frame (z up, the cylinder's axis the z axis). The forces are gravity −m g ẑ at the
//! centre and a contact force F at the contact point x + a n, n the outward horizontal unit
//! normal at the centre (x, y, 0)/√(x² + y²):
//!
//! > m dv/dt = F − m g ẑ,  k m a² dω/dt = (a n) × F.
//!
//! F is whatever keeps the contact's constraint C(x, v, ω) = 0 for all time. Rolling without
//! slipping: the ball's material point at the contact is at rest, C = v + ω × (a n), three
//! equations for the three components of F. A frictionless wall can push only along n, F = λ n,
//! and holds only the radial velocity, C = v · n. In both, dC/dt is affine in the force (through
//! dv/dt and dω/dt); it is computed by automatic differentiation of C along the motion (x + v ε,
//! v + v̇ ε, ω + ω̇ ε in dual numbers, so ṅ is never written down), its value at F = 0 and its
//! change for each basis force give a small linear system, and F solves dC/dt = 0. C = 0 at the
//! start then holds up to the integrator's error.
//!
//! Nothing here uses the cylindrical form of the motion (constant orbit rate, the harmonic
//! height) that [`super::closed_form`] derives; the cylinder's radius b enters only through the
//! start, whose centre is at distance b − a from the axis.
//!
//! The linear system (3 × 3, or 1 × 1) is solved by elimination without pivoting, written here
//! because it must run in the generic dual-number type of [`Ode::rhs`] (no linear-algebra crate
//! of the project takes it): its matrix is F ↦ F/m + (a²/I)(F − n (n · F)) for the rolling ball
//! and 1/m for the frictionless one, symmetric positive definite, where elimination needs no
//! pivot.

use super::Ball;
use crate::sim::integrators::Ode;
use num_dual::{Dual, DualNum};

/// A 3-vector of the model's scalars.
type V<T> = [T; 3];

/// How the cylinder holds the ball.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// Rolling without slipping: C = v + ω × (a n), any contact force.
    Rolling,
    /// A frictionless wall: C = v · n, a force along n only.
    Frictionless,
}

/// A deliberately wrong term of the model, to show that holding it to the closed form fails.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Perturbation {
    /// The model as derived.
    None,
    /// The rolling constraint without its ω × (a n) term (C = v).
    SpinTermDropped,
    /// The normal n held constant when C is differentiated along the motion (ṅ dropped).
    NormalFrozen,
}

/// The ball, the cylinder's wall and gravity (sec. B.10): the right-hand side of
/// (x, v, ω)' = (v, F/m − g ẑ, (a n × F)/(k m a²)).
#[derive(Clone, Copy, Debug)]
pub struct Cylinder {
    /// The ball.
    pub ball: Ball,
    /// Gravity g (down −ẑ).
    pub g: f64,
    /// Rolling or frictionless.
    pub contact: Contact,
    /// A wrong term, or none.
    pub perturbation: Perturbation,
    /// The sizes of the state's components for the error norm: a length for x, that length
    /// times the orbit rate for v, and that over a for ω.
    pub scale: [f64; 9],
}

fn add<T: DualNum<Primitive = f64> + Copy>(p: V<T>, q: V<T>) -> V<T> {
    [p[0] + q[0], p[1] + q[1], p[2] + q[2]]
}

fn times<T: DualNum<Primitive = f64> + Copy>(s: T, p: V<T>) -> V<T> {
    [s * p[0], s * p[1], s * p[2]]
}

fn cross<T: DualNum<Primitive = f64> + Copy>(p: V<T>, q: V<T>) -> V<T> {
    [
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    ]
}

fn dot<T: DualNum<Primitive = f64> + Copy>(p: V<T>, q: V<T>) -> T {
    p[0] * q[0] + p[1] * q[1] + p[2] * q[2]
}

/// The outward horizontal unit normal at the centre x: (x, y, 0)/√(x² + y²).
pub fn normal<T: DualNum<Primitive = f64> + Copy>(x: V<T>) -> V<T> {
    let r = (x[0] * x[0] + x[1] * x[1]).sqrt();
    [x[0] / r, x[1] / r, T::zero()]
}

/// The dual number re + eps ε.
fn lift<D: DualNum<Primitive = f64> + Copy>(re: V<D>, eps: V<D>) -> V<Dual<D>> {
    std::array::from_fn(|i| Dual::new(re[i], eps[i]))
}

/// Gaussian elimination without pivoting of `a` λ = `r` (`a` by rows; symmetric positive
/// definite here, see the module docs).
fn solve<D: DualNum<Primitive = f64> + Copy>(mut a: Vec<Vec<D>>, mut r: Vec<D>) -> Vec<D> {
    let n = r.len();
    for k in 0..n {
        let pivot = a[k].clone();
        for i in k + 1..n {
            let l = a[i][k] / pivot[k];
            for (aij, akj) in a[i].iter_mut().zip(&pivot).skip(k) {
                *aij -= l * *akj;
            }
            let rk = r[k];
            r[i] -= l * rk;
        }
    }
    for k in (0..n).rev() {
        let s = (k + 1..n).fold(r[k], |s, j| s - a[k][j] * r[j]);
        r[k] = s / a[k][k];
    }
    r
}

impl Cylinder {
    /// The constraint C(x, v, ω) of the contact (see [`Contact`]); `n` the normal to use.
    fn constraint<T: DualNum<Primitive = f64> + Copy>(&self, n: V<T>, v: V<T>, w: V<T>) -> Vec<T> {
        let a = T::from(self.ball.a);
        match (self.contact, self.perturbation) {
            (Contact::Frictionless, _) => vec![dot(v, n)],
            (Contact::Rolling, Perturbation::SpinTermDropped) => v.to_vec(),
            (Contact::Rolling, _) => add(v, cross(w, times(a, n))).to_vec(),
        }
    }

    /// The constraint at the state (x, v, ω): the residual that the motion keeps at zero.
    pub fn residual(&self, y: &[f64; 9]) -> Vec<f64> {
        let [x, v, w] = parts(y);
        self.constraint(normal(x), v, w)
    }

    /// dv/dt and dω/dt under the contact force `f` at x + a n.
    fn accelerations<D: DualNum<Primitive = f64> + Copy>(&self, n: V<D>, f: V<D>) -> (V<D>, V<D>) {
        let Ball { m, a, k } = self.ball;
        let gravity = [D::zero(), D::zero(), D::from(-self.g)];
        let dv = add(times(D::from(1.0 / m), f), gravity);
        let dw = times(
            D::from(1.0 / (k * m * a * a)),
            cross(times(D::from(a), n), f),
        );
        (dv, dw)
    }

    /// dC/dt along the motion from (x, v, ω) under the contact force `f`, by differentiating C
    /// in dual numbers.
    fn constraint_rate<D: DualNum<Primitive = f64> + Copy>(&self, y: [V<D>; 3], f: V<D>) -> Vec<D> {
        let [x, v, w] = y;
        let (dv, dw) = self.accelerations(normal(x), f);
        let n = match self.perturbation {
            Perturbation::NormalFrozen => normal(x).map(Dual::from_re),
            _ => normal(lift(x, v)),
        };
        self.constraint(n, lift(v, dv), lift(w, dw))
            .into_iter()
            .map(|c| c.eps)
            .collect()
    }

    /// The forces the contact can exert per unit multiplier: any (the three axes) when rolling,
    /// along n only when frictionless.
    fn force_basis<D: DualNum<Primitive = f64> + Copy>(&self, n: V<D>) -> Vec<V<D>> {
        let (o, i) = (D::zero(), D::one());
        match self.contact {
            Contact::Rolling => vec![[i, o, o], [o, i, o], [o, o, i]],
            Contact::Frictionless => vec![n],
        }
    }

    /// The contact force at the state: the F of the basis that makes dC/dt = 0.
    pub fn contact_force<D: DualNum<Primitive = f64> + Copy>(&self, y: [V<D>; 3]) -> V<D> {
        let basis = self.force_basis(normal(y[0]));
        let zero = [D::zero(); 3];
        let free = self.constraint_rate(y, zero);
        let rows: Vec<Vec<D>> = (0..free.len())
            .map(|i| {
                basis
                    .iter()
                    .map(|f| self.constraint_rate(y, *f)[i] - free[i])
                    .collect()
            })
            .collect();
        let lambda = solve(rows, free.iter().map(|c| -*c).collect());
        basis
            .iter()
            .zip(lambda)
            .fold(zero, |f, (b, l)| add(f, times(l, *b)))
    }
}

/// (x, v, ω) of the state.
pub fn parts<D: Copy>(y: &[D; 9]) -> [V<D>; 3] {
    [[y[0], y[1], y[2]], [y[3], y[4], y[5]], [y[6], y[7], y[8]]]
}

impl Ode<9> for Cylinder {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 9]) -> [D; 9] {
        let s = parts(y);
        let f = self.contact_force(s);
        let (dv, dw) = self.accelerations(normal(s[0]), f);
        let v = s[1];
        [v[0], v[1], v[2], dv[0], dv[1], dv[2], dw[0], dw[1], dw[2]]
    }

    fn scale(&self, _y: &[f64; 9]) -> [f64; 9] {
        self.scale
    }
}

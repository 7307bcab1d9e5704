//! Derivations: anything that yields the ladder's equation of motion from its state.
//!
//! The note derives the equation of motion (5) six ways, and Appendix A adds Jensen's methods.
//! Each is a [`Derivation`]: a residual of the ladder's state, affine in θ̈, that vanishes exactly
//! on the motion ("method" is the simulator's word for an integrator). Implementing the trait is
//! all a new derivation needs: [`DerivationChecks`] turns it into
//! registry checks (θ̈ solved from the residual equals (5) at random states, in floats within an
//! error bound and exactly in rationals; the residual vanishes on the motion and not off it),
//! and [`check_derivation`] runs them. `examples/midpoint_derivation.rs` adds one from outside the crate;
//! `docs/EXTENDING.md` walks through it.

use crate::ladder::analysis::{torque_equation, AngularMomentum, Reference};
use crate::ladder::energy::{angular_acceleration, lagrange_residual, NoteLagrangian};
use crate::ladder::geometry::Corner;
use crate::ladder::jensen::eq53_method_one_c;
use crate::ladder::torque::analysis_residual;
use crate::ladder::{solve_for_accel, Ladder, State};
use crate::ladder_fns;
use crate::registry::check::{run_check, CheckReport, Config};
use crate::registry::sample::LadderSample;
use crate::registry::{on_ladder, printed, reference, Chain, Check};
use crate::scalar::Scalar;
use std::marker::PhantomData;

/// A derivation of the equation of motion.
pub trait Derivation: Default + 'static {
    /// A short name, for reports.
    const NAME: &'static str;
    /// The method's equation as a residual (left side minus right side): zero on the motion,
    /// affine in θ̈.
    fn residual<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> T;
}

/// The registry checks of a method.
pub struct DerivationChecks<M>(PhantomData<M>);

impl<M: Derivation> DerivationChecks<M> {
    /// [θ̈ solved from the method, θ̈ of eq. (5)] at any state.
    pub fn solved<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        let m = M::default();
        vec![vec![
            reference("(5): (3g/4l) sin θ", angular_acceleration(l, s)),
            printed(
                "θ̈ solved from the method",
                solve_for_accel(l, s, |x| m.residual(l, x)),
            ),
        ]]
    }
    /// [the residual, 0] on the motion (and shown to fail off it).
    pub fn on_shell<S: Scalar>(l: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        vec![vec![
            printed("the method's residual", M::default().residual(l, s)),
            reference("0", S::int(0)),
        ]]
    }
    /// Both checks, ready for the registry.
    pub fn checks() -> Vec<Check> {
        vec![
            on_ladder(
                "θ̈ solved from the method equals (5)",
                LadderSample::Kinematic,
                ladder_fns!(Self::solved),
            ),
            on_ladder(
                "the residual vanishes on the motion, not off it",
                LadderSample::OnShell,
                ladder_fns!(Self::on_shell),
            ),
        ]
    }
}

/// Run a method's checks.
pub fn check_derivation<M: Derivation>(cfg: &Config) -> Vec<CheckReport> {
    DerivationChecks::<M>::checks()
        .iter()
        .map(|c| run_check(c, cfg))
        .collect()
}

/// Sec. 2.1: Lagrange's equation (4) by automatic differentiation of ℒ = T − V.
#[derive(Default)]
pub struct Lagrange;

impl Derivation for Lagrange {
    const NAME: &'static str = "Lagrange (4)";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        lagrange_residual(&NoteLagrangian, l, s)
    }
}

/// Secs. 2.2-2.6: the torque analysis about one of A-E as printed (const parameter 0..5 = A..E).
#[derive(Default)]
pub struct PrintedAnalysis<const K: usize>;

impl<const K: usize> Derivation for PrintedAnalysis<K> {
    const NAME: &'static str = [
        "about A (16)",
        "about B (19)",
        "about C (22)",
        "about D (25)",
        "about E (28)",
    ][K];
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        analysis_residual(Corner::ALL[K], l, s)
    }
}

/// A torque analysis about one of A-E from first principles with L'_P and eq. (40).
#[derive(Default)]
pub struct FirstPrinciples<const K: usize>;

impl<const K: usize> Derivation for FirstPrinciples<K> {
    const NAME: &'static str = [
        "L'_A, (40)",
        "L'_B, (40)",
        "L'_C, (40)",
        "L'_D, (40)",
        "L'_E, (40)",
    ][K];
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let (lhs, rhs) = torque_equation(
            &Reference::Corner(Corner::ALL[K]),
            AngularMomentum::Relative,
            l,
            s,
        );
        lhs - rhs
    }
}

/// Appendix A.1: Jensen's method 1 about C as printed, eq. (53).
#[derive(Default)]
pub struct JensenMethodOne;

impl Derivation for JensenMethodOne {
    const NAME: &'static str = "Jensen method 1 at C (53)";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let [lhs, rhs] = eq53_method_one_c(l, s);
        lhs - rhs
    }
}

/// The note's methods with their checks: (name, checks).
pub fn derivations() -> Vec<(&'static str, Vec<Check>)> {
    fn entry<M: Derivation>() -> (&'static str, Vec<Check>) {
        (M::NAME, DerivationChecks::<M>::checks())
    }
    vec![
        entry::<Lagrange>(),
        entry::<PrintedAnalysis<0>>(),
        entry::<PrintedAnalysis<1>>(),
        entry::<PrintedAnalysis<2>>(),
        entry::<PrintedAnalysis<3>>(),
        entry::<PrintedAnalysis<4>>(),
        entry::<FirstPrinciples<0>>(),
        entry::<FirstPrinciples<1>>(),
        entry::<FirstPrinciples<2>>(),
        entry::<FirstPrinciples<3>>(),
        entry::<FirstPrinciples<4>>(),
        entry::<JensenMethodOne>(),
    ]
}

//! One type for "any of the methods", chosen by name at run time (scenes, work-precision).

use super::dop853::Dop853;
use super::dopri5::Dopri5;
use super::euler::Euler;
use super::radau5::Radau5;
use super::rk4::Rk4;
use super::symplectic_euler::SymplecticEuler;
use super::taylor::Taylor;
use super::verlet::Verlet;
use super::{Control, Ode, Stats, StepError, Stepper};

/// Any integrator of this module.
///
/// Unboxed although the Taylor variant is large (its series buffers): one stepper per phase
/// lives on the stack, and boxing would add a heap allocation to every run.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum AnyStepper<const N: usize> {
    /// Explicit Euler.
    Euler(Euler<N>),
    /// Symplectic Euler.
    SymplecticEuler(SymplecticEuler<N>),
    /// Störmer-Verlet.
    Verlet(Verlet<N>),
    /// Classic RK4.
    Rk4(Rk4<N>),
    /// Dormand-Prince 5(4).
    Dopri5(Dopri5<N>),
    /// DOP853.
    Dop853(Dop853<N>),
    /// Radau IIA order 5.
    Radau5(Radau5<N>),
    /// Taylor series (models with [`super::Ode::taylor_series`] only).
    Taylor(Taylor<N>),
}

impl<const N: usize> AnyStepper<N> {
    /// The method called `name` (see [`super::RIGID_METHODS`]) with its step or tolerance, or None
    /// when the name is unknown or the control does not fit the method.
    #[inline]
    pub fn new(name: &str, control: Control, t0: f64, y0: [f64; N]) -> Option<Self> {
        Some(match (name, control) {
            ("euler", Control::Fixed(h)) => AnyStepper::Euler(Euler::new(t0, y0, h)),
            ("symplectic-euler", Control::Fixed(h)) => {
                AnyStepper::SymplecticEuler(SymplecticEuler::new(t0, y0, h))
            }
            ("verlet", Control::Fixed(h)) => AnyStepper::Verlet(Verlet::new(t0, y0, h)),
            ("rk4", Control::Fixed(h)) => AnyStepper::Rk4(Rk4::new(t0, y0, h)),
            ("dopri5", Control::Tolerance(r)) => AnyStepper::Dopri5(Dopri5::new(t0, y0, r)),
            ("dop853", Control::Tolerance(r)) => AnyStepper::Dop853(Dop853::new(t0, y0, r)),
            ("radau5", Control::Tolerance(r)) => AnyStepper::Radau5(Radau5::new(t0, y0, r)),
            ("taylor", Control::Tolerance(r)) => AnyStepper::Taylor(Taylor::new(t0, y0, r)),
            _ => return None,
        })
    }

    /// As [`AnyStepper::new`], with the Taylor method's order when `order` is given (other
    /// methods have none: the scene check refuses it for them, and it is ignored here).
    #[inline]
    pub fn with_order(
        name: &str,
        control: Control,
        order: Option<usize>,
        t0: f64,
        y0: [f64; N],
    ) -> Option<Self> {
        match (name, control, order) {
            ("taylor", Control::Tolerance(r), Some(p)) => {
                Some(AnyStepper::Taylor(Taylor::with_order(t0, y0, r, p)))
            }
            _ => Self::new(name, control, t0, y0),
        }
    }
}

macro_rules! each {
    ($self:expr, $s:ident => $e:expr) => {
        match $self {
            AnyStepper::Euler($s) => $e,
            AnyStepper::SymplecticEuler($s) => $e,
            AnyStepper::Verlet($s) => $e,
            AnyStepper::Rk4($s) => $e,
            AnyStepper::Dopri5($s) => $e,
            AnyStepper::Dop853($s) => $e,
            AnyStepper::Radau5($s) => $e,
            AnyStepper::Taylor($s) => $e,
        }
    };
}

impl<const N: usize> Stepper<N> for AnyStepper<N> {
    fn t(&self) -> f64 {
        each!(self, s => s.t())
    }
    fn y(&self) -> [f64; N] {
        each!(self, s => s.y())
    }
    fn t_prev(&self) -> f64 {
        each!(self, s => s.t_prev())
    }
    fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError> {
        each!(self, s => s.step(sys, t_stop))
    }
    fn prepare_dense<S: Ode<N>>(&mut self, sys: &S) {
        each!(self, s => s.prepare_dense(sys))
    }
    fn interpolate(&self, t: f64) -> [f64; N] {
        each!(self, s => s.interpolate(t))
    }
    fn interpolate_rate(&self, t: f64) -> Option<[f64; N]> {
        each!(self, s => s.interpolate_rate(t))
    }
    fn step_series(&self) -> Option<&super::taylor::Series<N>> {
        each!(self, s => s.step_series())
    }
    fn trig(&self) -> Option<(f64, f64)> {
        each!(self, s => s.trig())
    }
    fn stats(&self) -> Stats {
        each!(self, s => s.stats())
    }
}

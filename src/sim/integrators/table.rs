//! How the list of integrators (in [`super`]) becomes the table: from each line, naming a
//! module and its stepper type, the macro [`integrators!`] makes the module itself, a variant
//! of [`AnyStepper`](super::AnyStepper) (the stepper a scene's method name builds) and its
//! card in [`TABLE`](super::TABLE). A new integrator is its file, which declares its
//! [`Card`](super::card::Card) and implements [`Stepper`] and [`Integrator`], and one line of
//! the list.
//!
//! Written as a macro because the list must become an enum (a stepper is generic over the
//! model, so the methods cannot sit behind a trait object) as well as a table of cards.

use super::{Control, Stepper};

/// How the table starts an integrator of its list.
pub trait Integrator<const N: usize>: Stepper<N> + Sized {
    /// Start at `(t0, y0)` with `control`, or None when the control is not of the kind the
    /// method's card names. `order` is for a method that takes one (the Taylor method); others
    /// ignore it (the scene check refuses it for them).
    fn start(t0: f64, y0: [f64; N], control: Control, order: Option<usize>) -> Option<Self>;
}

/// The table from the list: see the module docs.
macro_rules! integrators {
    ($($module:ident :: $ty:ident),* $(,)?) => {
        $(pub mod $module;)*

        /// Any integrator of the table, chosen by name at run time (scenes, work-precision).
        ///
        /// Unboxed although the Taylor variant is large (its series buffers): one stepper per
        /// phase lives on the stack, and boxing would add a heap allocation to every run.
        #[allow(clippy::large_enum_variant)]
        #[derive(Clone, Debug)]
        pub enum AnyStepper<const N: usize> {
            $(
                #[doc = concat!("The stepper of `", stringify!($module), "`.")]
                $ty($module::$ty<N>),
            )*
        }

        /// Every integrator's card, in the order of the list.
        pub const TABLE: &[&card::Card] = &[$(&$module::CARD),*];

        impl<const N: usize> AnyStepper<N> {
            /// The method called `name` (a name of [`TABLE`]) with its step or tolerance, and
            /// the order of a method that takes one; None when the name is unknown or the
            /// control does not fit.
            pub fn with_order(
                name: &str,
                control: Control,
                order: Option<usize>,
                t0: f64,
                y0: [f64; N],
            ) -> Option<Self> {
                $(
                    if name == $module::CARD.name {
                        return <$module::$ty<N> as table::Integrator<N>>::start(t0, y0, control, order)
                            .map(AnyStepper::$ty);
                    }
                )*
                None
            }
        }

        impl<const N: usize> Stepper<N> for AnyStepper<N> {
            fn t(&self) -> f64 {
                match self { $(AnyStepper::$ty(s) => s.t(),)* }
            }
            fn y(&self) -> [f64; N] {
                match self { $(AnyStepper::$ty(s) => s.y(),)* }
            }
            fn t_prev(&self) -> f64 {
                match self { $(AnyStepper::$ty(s) => s.t_prev(),)* }
            }
            fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError> {
                match self { $(AnyStepper::$ty(s) => s.step(sys, t_stop),)* }
            }
            fn prepare_dense<S: Ode<N>>(&mut self, sys: &S) {
                match self { $(AnyStepper::$ty(s) => s.prepare_dense(sys),)* }
            }
            fn interpolate(&self, t: f64) -> [f64; N] {
                match self { $(AnyStepper::$ty(s) => s.interpolate(t),)* }
            }
            fn interpolate_rate(&self, t: f64) -> Option<[f64; N]> {
                match self { $(AnyStepper::$ty(s) => s.interpolate_rate(t),)* }
            }
            fn step_series(&self) -> Option<&taylor::Series<N>> {
                match self { $(AnyStepper::$ty(s) => s.step_series(),)* }
            }
            fn trig(&self) -> Option<(f64, f64)> {
                match self { $(AnyStepper::$ty(s) => s.trig(),)* }
            }
            fn stats(&self) -> Stats {
                match self { $(AnyStepper::$ty(s) => s.stats(),)* }
            }
        }
    };
}

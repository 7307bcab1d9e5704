//! Sides and chains: the values a check compares.

use crate::scalar::Scalar;
use crate::vector::Vec3;

/// What a value in a chain is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A form printed in the note.
    Printed,
    /// An independent reference (particle model, automatic differentiation, first principles).
    Reference,
    /// Our correction of a misprinted form.
    Corrected,
    /// A form printed in the note that is wrong: it must FAIL against the rest of the chain.
    Misprint,
}

/// One value of a chain, with a label saying where it comes from.
#[derive(Clone, Debug)]
pub struct Side<S> {
    /// Where the value comes from ("printed: -2ml²θ̈/3", "particles: Σ m_i v_i²/2").
    pub label: &'static str,
    /// The value.
    pub value: S,
    /// Its role.
    pub role: Role,
}

/// Values that must all be equal (all but the misprints, which must differ).
pub type Chain<S> = Vec<Side<S>>;

/// A printed form.
pub fn printed<S>(label: &'static str, value: S) -> Side<S> {
    Side {
        label,
        value,
        role: Role::Printed,
    }
}
/// An independent reference.
pub fn reference<S>(label: &'static str, value: S) -> Side<S> {
    Side {
        label,
        value,
        role: Role::Reference,
    }
}
/// A corrected form.
pub fn corrected<S>(label: &'static str, value: S) -> Side<S> {
    Side {
        label,
        value,
        role: Role::Corrected,
    }
}
/// A misprinted form (expected to fail).
pub fn misprint<S>(label: &'static str, value: S) -> Side<S> {
    Side {
        label,
        value,
        role: Role::Misprint,
    }
}

/// Split a chain of vectors into three chains of components (x, y, z).
pub fn vector_chains<S: Scalar>(sides: Vec<Side<Vec3<S>>>) -> Vec<Chain<S>> {
    let pick = |k: usize| -> Chain<S> {
        sides
            .iter()
            .map(|s| Side {
                label: s.label,
                value: s.value.components()[k].clone(),
                role: s.role,
            })
            .collect()
    };
    vec![pick(0), pick(1), pick(2)]
}

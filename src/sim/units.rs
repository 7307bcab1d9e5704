//! The scene's own units, T = √(l/g), l and m g: what a rigid scene is run in (see
//! [`super::scaled`] for why and for the conversions of a run). Below the scene, which limits
//! steps and end times in them.

use crate::ladder::Ladder;

/// The scene's units in SI: T = √(l/g) (s), l (m), m g (N).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Units {
    /// T = √(l/g), s.
    pub time: f64,
    /// l, m.
    pub length: f64,
    /// m g, N.
    pub force: f64,
}

/// The ladder with m = l = g = 1 (Ω² = 3/4), the one every rigid scene is run with.
pub const UNIT_LADDER: Ladder<f64> = Ladder {
    m: 1.0,
    l: 1.0,
    g: 1.0,
};

impl Units {
    /// The units of `ladder` (l/g stays within f64's range for l, g in 1e-30..1e30).
    pub fn of(ladder: &Ladder<f64>) -> Units {
        Units {
            time: (ladder.l / ladder.g).sqrt(),
            length: ladder.l,
            force: ladder.m * ladder.g,
        }
    }
}

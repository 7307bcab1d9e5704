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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_of_a_ladder() {
        let u = Units::of(&Ladder {
            m: 2.0,
            l: 4.0,
            g: 16.0,
        });
        assert_eq!(
            u,
            Units {
                time: 0.5,
                length: 4.0,
                force: 32.0
            }
        );
    }

    #[test]
    fn extreme_units_stay_finite() {
        let u = Units::of(&Ladder {
            m: 1e30,
            l: 1e30,
            g: 1e-30,
        });
        assert!((u.time / 1e30 - 1.0).abs() < 1e-15, "{u:?}");
        assert_eq!(u.force, 1.0);
    }
}

//! The outputs a scene may ask for. They decide what a run computes and keeps (see
//! `sim::fall::Plan`): nothing is evaluated or stored that no output needs.

use crate::sim::scene::parts::End;

/// One output of `ladder simulate`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// θ where the wall force reaches zero (JSON `separation.angle`).
    SeparationAngle,
    /// t there (`separation.time`).
    SeparationTime,
    /// θ̇ there (`separation.rate`).
    SeparationRate,
    /// Time when the ladder lies flat (`flat.time`).
    FlatTime,
    /// The state when flat: θ̇, centre x and ẋ (`flat.*`).
    FlatState,
    /// Smallest floor force over the floor phase (`floor_phase.floor_force_min`).
    FloorForceMin,
    /// Smallest distance of the top from the wall over the floor phase.
    TopClearanceMin,
    /// Horizontal momentum balance of the fall, |Δ(m Ẋ) − ∫F_w dt| / (m √(g l))
    /// (`fall::momentum_balance`).
    MomentumError,
    /// Energy change over the integrated phases, relative to m g l (`energy_error`); a run
    /// that goes on lying flat is measured up to flat (the impact's loss is `sim::impact`'s).
    EnergyError,
    /// Time and state at the end (`final.*`).
    FinalState,
    /// Evaluation counters (`work.*`).
    RhsEvals,
    /// θ and θ̇ against t (CSV + SVG with --out), at most 2 [`crate::sim::trace::TRACE_CAP`] samples.
    Trajectory,
    /// F_w and F_f against t and θ (CSV + SVG with --out), at the trajectory's samples.
    Forces,
}

const ALL: [(Output, &str); 13] = [
    (Output::SeparationAngle, "separation_angle"),
    (Output::SeparationTime, "separation_time"),
    (Output::SeparationRate, "separation_rate"),
    (Output::FlatTime, "flat_time"),
    (Output::FlatState, "flat_state"),
    (Output::FloorForceMin, "floor_force_min"),
    (Output::TopClearanceMin, "top_clearance_min"),
    (Output::MomentumError, "momentum_error"),
    (Output::EnergyError, "energy_error"),
    (Output::FinalState, "final_state"),
    (Output::RhsEvals, "rhs_evals"),
    (Output::Trajectory, "trajectory"),
    (Output::Forces, "forces"),
];

impl Output {
    /// The output called `name` in a scene.
    pub fn from_name(name: &str) -> Option<Output> {
        ALL.iter().find(|(_, n)| *n == name).map(|(o, _)| *o)
    }
    /// Its name in a scene.
    pub fn name(self) -> &'static str {
        ALL.iter().find(|(o, _)| *o == self).map_or("?", |(_, n)| n)
    }
    /// All names, for error messages.
    pub fn names() -> String {
        ALL.iter().map(|(_, n)| *n).collect::<Vec<_>>().join(", ")
    }
    /// Whether this output needs the floor phase (after separation).
    pub fn needs_floor_phase(self) -> bool {
        matches!(
            self,
            Output::FlatTime
                | Output::FlatState
                | Output::FloorForceMin
                | Output::TopClearanceMin
                | Output::MomentumError
        )
    }
    /// Whether `method` ending at `end` can produce this output; the reason when not.
    pub fn producible(self, method: &str, end: End) -> Result<(), String> {
        if method == "exact" {
            if end != End::Separation {
                return Err(
                    "method \"exact\" covers the wall phase only: use end.at = \"separation\""
                        .into(),
                );
            }
            return match self {
                Output::SeparationAngle | Output::SeparationTime | Output::SeparationRate | Output::FinalState => Ok(()),
                _ => Err("method \"exact\" gives only separation_angle, separation_time, separation_rate, final_state".into()),
            };
        }
        match (self, end) {
            (Output::FlatTime | Output::FlatState, End::Flat) => Ok(()),
            (Output::FlatTime | Output::FlatState, _) => Err("needs end.at = \"flat\"".into()),
            (o, End::Separation) if o.needs_floor_phase() => {
                Err("it belongs to the floor phase: needs end.at = \"flat\" or \"time\"".into())
            }
            _ => Ok(()),
        }
    }
}

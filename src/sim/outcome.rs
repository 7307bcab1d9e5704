//! What a run of a scene produces ([`Outcome`]) and what it must compute ([`Plan`]): the types
//! the fall, the penalty scenes and the unit conversions share, below all of them.

use super::integrators::Stats;
use super::scene::{End, Scene};
use crate::sim::scene::output::Output;

/// What a run must compute, decided by the scene's outputs alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plan {
    /// Build and integrate the floor phase.
    pub floor_phase: bool,
    /// Keep the trajectory (θ, θ̇ against t).
    pub trace: bool,
    /// Evaluate contact forces along the trace.
    pub forces: bool,
    /// Track the floor force and the top's clearance over the floor phase.
    pub floor_monitor: bool,
    /// Evaluate the energy at the ends.
    pub energy: bool,
    /// Integrate the wall's impulse for the momentum balance.
    pub momentum: bool,
}

impl Plan {
    /// The plan for `scene`.
    pub fn of(scene: &Scene) -> Plan {
        let wants = |o: Output| scene.outputs.contains(&o);
        Plan {
            floor_phase: scene.end != End::Separation && scene.method != "exact",
            trace: wants(Output::Trajectory) || wants(Output::Forces),
            forces: wants(Output::Forces),
            floor_monitor: wants(Output::FloorForceMin) || wants(Output::TopClearanceMin),
            energy: wants(Output::EnergyError),
            momentum: wants(Output::MomentumError),
        }
    }
}

/// One stored point of the motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// 1 (wall phase), 2 (floor phase) or 3 (lying flat after the impact, `sim::impact`).
    pub phase: u8,
    /// t, s.
    pub t: f64,
    /// θ, rad.
    pub theta: f64,
    /// θ̇, rad/s.
    pub rate: f64,
    /// X, the abscissa of the centre of mass, m: l sin θ (7) on the wall, the integrated X of
    /// the floor phase after, the slide's X lying flat.
    pub centre_x: f64,
    /// (F_w, F_f), N, when the forces were asked for.
    pub forces: Option<(f64, f64)>,
}

/// Counters of the work done, for the summary and for tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Integrator statistics, wall phase.
    pub wall: Stats,
    /// Integrator statistics, floor phase (None if it was never built).
    pub floor: Option<Stats>,
    /// Contact-force evaluations (traces, monitors, the lift-off watch).
    pub force_evals: u64,
    /// Samples kept in memory.
    pub stored_samples: usize,
}

/// The state at separation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeparationState {
    /// t_s.
    pub time: f64,
    /// θ_s.
    pub angle: f64,
    /// θ̇ at t_s.
    pub rate: f64,
}

/// The state when the ladder lies flat (θ = π/2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatState {
    /// Time.
    pub time: f64,
    /// θ̇.
    pub rate: f64,
    /// Centre's abscissa X.
    pub centre_x: f64,
    /// Ẋ.
    pub centre_velocity_x: f64,
    /// ẏ of the centre (= −l sin θ θ̇), its impact speed on the floor.
    pub centre_velocity_y: f64,
}

/// After flat, in a run to a later time (beyond the note; [`super::impact`]): the top struck
/// the floor, perfectly inelastically (no bounce, and no horizontal impulse from the
/// frictionless floor), and the ladder slid on lying flat at the centre's horizontal speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slide {
    /// When the ladder lay flat and its top struck the floor (= the flat time).
    pub impact_time: f64,
    /// Ẋ, unchanged by the impact, and the speed of the slide.
    pub centre_velocity_x: f64,
    /// X at the end time.
    pub centre_x_end: f64,
    /// The kinetic energy the impact took, (2/3) m l² θ̇², over m g l.
    pub energy_lost: f64,
}

/// What the floor-phase monitors saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloorReport {
    /// Smallest floor force seen (step ends and dense samples).
    pub floor_force_min: f64,
    /// Smallest abscissa of the top after the start of the phase (> 0: clear of the wall).
    pub top_clearance_min: f64,
}

/// Everything a run produced.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The plan that was followed.
    pub plan: Plan,
    /// Separation, if reached.
    pub separation: Option<SeparationState>,
    /// Flat, if reached.
    pub flat: Option<FlatState>,
    /// Lying flat after the impact, when the run's end time came after flat.
    pub slide: Option<Slide>,
    /// (t, θ, θ̇) at the end.
    pub last: (f64, f64, f64),
    /// |E_end − E_0| / (m g l), if asked.
    pub energy_error: Option<f64>,
    /// Horizontal momentum balance of the whole fall, if asked and the floor phase ran:
    /// |m Ẋ_end − m Ẋ_0 − ∫F_w dt| / (m √(g l)) (`fall::momentum_balance`).
    pub momentum_error: Option<f64>,
    /// Floor-phase monitors, if asked.
    pub floor_report: Option<FloorReport>,
    /// The trace, if asked.
    pub trace: Option<Vec<Sample>>,
    /// Work counters.
    pub work: Work,
}

/// Why the run did not reach the end the scene asked for (separation or flat), if it did not.
pub fn unreached_end(scene: &Scene, o: &Outcome) -> Option<String> {
    let missing = match scene.end {
        End::Separation if o.separation.is_none() => "the separation",
        End::Flat if o.separation.is_none() => "the separation (and so flat)",
        End::Flat if o.flat.is_none() => "flat",
        _ => return None,
    };
    Some(format!(
        "the run stopped at t = {} s, θ = {} rad without reaching {missing}, the end the scene asks for",
        o.last.0, o.last.1
    ))
}

/// The rounding of the top's computed abscissa X − l sin θ, in units of l: both terms are at
/// most about l where the top is near the wall, each is rounded once (u = 2^-53) and so is
/// their difference, so a clearance down to −4 u l is zero within rounding.
pub const TOP_CLEARANCE_ROUNDING: f64 = 4.0 * f64::EPSILON / 2.0;

/// Why the floor phase is not the model's motion, if its monitor saw the top of the ladder
/// inside the wall: the rigid floor phase has no wall (it is left for good at separation,
/// footnote 4), so the exact motion keeps the top clear, x_C = X − l sin θ ≥ 0, and a computed
/// minimum below −[`TOP_CLEARANCE_ROUNDING`]·l is integration error large enough to move the top
/// through the wall (e.g. symplectic Euler at h = 1e-4 s: −3.6e-7 m). The run's numbers are then
/// those of a motion the model forbids: a failed check, never a silent exit 0.
pub fn top_inside_wall(report: &FloorReport, half_length: f64) -> Option<String> {
    let c = report.top_clearance_min;
    (c < -TOP_CLEARANCE_ROUNDING * half_length).then(|| {
        format!(
            "the top of the ladder went {:.3e} m inside the wall during the floor phase (top_clearance_min = {c:e} m, below the rounding of −{:.1e} m): the integration is too inaccurate for the floor phase; use a smaller step or a tighter tolerance",
            -c,
            TOP_CLEARANCE_ROUNDING * half_length
        )
    })
}

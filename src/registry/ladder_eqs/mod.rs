//! Registry entries and checks for sec. 2, eqs. (1)-(28).

/// d/dt of a ladder quantity, by lifting the state along the motion.
macro_rules! d_dt {
    ($f:expr, $l:expr, $s:expr) => {
        rate::<S>($f(&$l.constant(), &$s.along_motion()))
    };
}

mod analyses;
mod lagrange;
use analyses::*;
use lagrange::*;

use super::sample::LadderSample;
use super::{eq, on_ladder, Equation, Erratum, Kind};
use crate::ladder_fns;

/// The entries for sec. 2.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    let k = |name, f| on_ladder(name, LadderSample::Kinematic, f);
    let on = |name, f| on_ladder(name, LadderSample::OnShell, f);
    let rest = |name, f| on_ladder(name, LadderSample::OnShellFromRest, f);
    let mut e28 = eq(
        28,
        "2.6",
        "Torque analysis about E",
        OnShell,
        &[
            "ladder::torque::eq28_torque_analysis_e",
            "ladder::torque::eq28_second_form_corrected",
            "ladder::torque::torque_about_e",
        ],
        vec![on(
            "AD of (27) = printed forms = particle torques",
            ladder_fns!(eq28),
        )],
    );
    e28.erratum = Some(Erratum {
        printed: r"\tau_E - F_{E,y} l \sin \theta",
        corrected: r"\tau_E + F_{E,x} l \cos \theta - F_{E,y} l \sin \theta",
        why: "the coordinate force F_E has an x component too; its torque F_E,x l cos θ is missing from form 3 of the display, τ_E − F_E,y l sin θ (form 4, mgl sin θ + F_E,x l cos θ − F_E,y l sin θ, has it)",
    });
    vec![
        eq(
            1,
            "2.1",
            "Moment of inertia about the centre of mass",
            Definition,
            &["ladder::energy::moment_of_inertia_cm"],
            vec![k("I_cm against the particle model", ladder_fns!(eq1))],
        ),
        eq(
            2,
            "2.1",
            "Kinetic energy",
            Kinematic,
            &[
                "ladder::energy::kinetic_energy_split",
                "ladder::energy::kinetic_energy_middle",
                "ladder::energy::kinetic_energy",
            ],
            vec![k(
                "three printed forms against Σ m_i v_i²/2",
                ladder_fns!(eq2),
            )],
        ),
        eq(
            3,
            "2.1",
            "Potential energy",
            Definition,
            &["ladder::energy::potential_energy"],
            vec![k("V against Σ m_i g y_i", ladder_fns!(eq3))],
        ),
        eq(
            4,
            "2.1",
            "Lagrange's equation",
            OnShell,
            &[
                "ladder::energy::lagrange_sides",
                "ladder::energy::lagrange_residual",
            ],
            vec![on(
                "both sides by AD, note's and particle ℒ",
                ladder_fns!(eq4),
            )],
        ),
        eq(
            5,
            "2.1",
            "Equation of motion",
            OnShell,
            &["ladder::energy::angular_acceleration"],
            vec![
                k("θ̈ solved from (4) by AD", ladder_fns!(eq5_from_lagrange)),
                on("θ̈ of the motion", ladder_fns!(eq5_on_shell)),
            ],
        ),
        eq(
            6,
            "2.1",
            "Wall force from the horizontal acceleration",
            Newton,
            &["ladder::forces::wall_force_from_acceleration"],
            vec![k("m a_x against Σ m_i a_i,x", ladder_fns!(eq6))],
        ),
        eq(
            7,
            "2.1",
            "Centre-of-mass coordinates",
            Definition,
            &["ladder::geometry::cm_position"],
            vec![k("against the particle model", ladder_fns!(eq7))],
        ),
        eq(
            8,
            "2.1",
            "Centre-of-mass acceleration",
            Kinematic,
            &["ladder::geometry::cm_acceleration"],
            vec![k("against AD² of (7) and particles", ladder_fns!(eq8))],
        ),
        eq(
            9,
            "2.1",
            "Conservation of energy",
            OnShell,
            &["ladder::energy::energy", "ladder::energy::initial_energy"],
            vec![
                rest("E_0 = T + V from rest upright", ladder_fns!(eq9)),
                on("dE/dt = 0 on the motion (AD)", ladder_fns!(eq9_conserved)),
            ],
        ),
        eq(
            10,
            "2.1",
            "Angular velocity from the energy",
            OnShell,
            &["ladder::energy::rate_squared"],
            vec![
                on(
                    "d/dt of (10) gives (5) (footnote 3)",
                    ladder_fns!(eq10_rate),
                ),
                rest("θ̇² from the particle energy", ladder_fns!(eq10_value)),
            ],
        ),
        eq(
            11,
            "2.2",
            "Torque equation about A",
            OnShell,
            &["ladder::torque::torque_about_a"],
            vec![
                on("dL_A/dt = τ_A", ladder_fns!(eq11)),
                k(
                    "τ_A with the forces the motion requires",
                    ladder_fns!(eq11_forces_from_motion),
                ),
            ],
        ),
        eq(
            12,
            "2.2",
            "Angular momentum about A",
            Kinematic,
            &[
                "ladder::torque::eq12_angular_momentum_about_a",
                "ladder::torque::angular_momentum_about_a",
            ],
            vec![k("against Σ x_i × m_i v_i", ladder_fns!(eq12))],
        ),
        eq(
            13,
            "2.2",
            "Moment of inertia about A, C, D, E",
            Definition,
            &["ladder::torque::eq13_moment_of_inertia_about_corner"],
            vec![k(
                "against the particle model about each corner",
                ladder_fns!(eq13),
            )],
        ),
        eq(
            14,
            "2.2",
            "Wall force",
            Newton,
            &[
                "ladder::forces::wall_force_via_acceleration",
                "ladder::forces::wall_force",
            ],
            vec![k("against Newton for the particles", ladder_fns!(eq14))],
        ),
        eq(
            15,
            "2.2",
            "Floor force",
            Newton,
            &[
                "ladder::forces::floor_force_via_acceleration",
                "ladder::forces::floor_force",
            ],
            vec![k("against Newton for the particles", ladder_fns!(eq15))],
        ),
        eq(
            16,
            "2.2",
            "Torque analysis about A",
            OnShell,
            &["ladder::torque::eq16_torque_analysis_a"],
            vec![on(
                "AD of (12) = printed forms = particle torques",
                ladder_fns!(eq16),
            )],
        ),
        eq(
            17,
            "2.3",
            "Coordinate force of an accelerating point",
            General,
            &["ladder::torque::coordinate_force"],
            vec![crate::registry::on_particles(
                "−m a_P against Newton in P's frame",
                crate::registry::ParticleSample::General,
                crate::particle_fns!(eq17),
            )],
        ),
        eq(
            18,
            "2.3",
            "Angular momentum about B",
            Kinematic,
            &["ladder::torque::angular_momentum_about_b"],
            vec![k("against L_cm of the particles", ladder_fns!(eq18))],
        ),
        eq(
            19,
            "2.3",
            "Torque analysis about B",
            OnShell,
            &["ladder::torque::eq19_torque_analysis_b"],
            vec![on(
                "AD of (18) = printed forms = particle torques",
                ladder_fns!(eq19),
            )],
        ),
        eq(
            20,
            "2.4",
            "Coordinate force for C",
            Kinematic,
            &["ladder::torque::eq20_coordinate_force_c"],
            vec![k("against −m a_C by AD", ladder_fns!(eq20))],
        ),
        eq(
            21,
            "2.4",
            "Angular momentum about C",
            Kinematic,
            &["ladder::torque::eq21_angular_momentum_about_c"],
            vec![k("against L'_C of the particles", ladder_fns!(eq21))],
        ),
        eq(
            22,
            "2.4",
            "Torque analysis about C",
            OnShell,
            &["ladder::torque::eq22_torque_analysis_c"],
            vec![on(
                "AD of (21) = printed forms = particle torques",
                ladder_fns!(eq22),
            )],
        ),
        eq(
            23,
            "2.5",
            "Coordinate force for D",
            Kinematic,
            &["ladder::torque::eq23_coordinate_force_d"],
            vec![k("against −m a_D by AD", ladder_fns!(eq23))],
        ),
        eq(
            24,
            "2.5",
            "Angular momentum about D",
            Kinematic,
            &["ladder::torque::eq24_angular_momentum_about_d"],
            vec![k("against L'_D of the particles", ladder_fns!(eq24))],
        ),
        eq(
            25,
            "2.5",
            "Torque analysis about D",
            OnShell,
            &["ladder::torque::eq25_torque_analysis_d"],
            vec![on(
                "AD of (24) = printed forms = particle torques",
                ladder_fns!(eq25),
            )],
        ),
        eq(
            26,
            "2.6",
            "Coordinate force for E",
            Kinematic,
            &["ladder::torque::eq26_coordinate_force_e"],
            vec![k("against −m a_E by AD", ladder_fns!(eq26))],
        ),
        eq(
            27,
            "2.6",
            "Angular momentum about E",
            Kinematic,
            &["ladder::torque::eq27_angular_momentum_about_e"],
            vec![k("against L'_E of the particles", ladder_fns!(eq27))],
        ),
        e28,
    ]
}

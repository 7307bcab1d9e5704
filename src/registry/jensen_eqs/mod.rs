//! Registry entries and checks for Jensen's methods applied to the ladder about C,
//! eqs. (43)-(55), (59)-(63).

mod checks;
use checks::*;

use super::sample::LadderSample;
use super::{eq, on_ladder, Equation, Erratum, Kind};
use crate::ladder_fns;

/// The entries for Jensen's methods on the ladder.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    let k = |name, f| on_ladder(name, LadderSample::Kinematic, f);
    let on = |name, f| on_ladder(name, LadderSample::OnShell, f);
    let mut e49 = eq(
        49,
        "A.1",
        "Method 1: L_C about the contact point",
        Kinematic,
        &[
            "ladder::jensen::eq49_angular_momentum_about_c",
            "ladder::jensen::eq49_corrected",
        ],
        vec![k("against L_C (37) of the particles", ladder_fns!(eq49))],
    );
    e49.erratum = Some(Erratum {
        printed: r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
        corrected: r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + m l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
        why: "the orbital term is (x_cm − x_C) × m v_cm; the mass m is missing (the term has the wrong dimensions); (53) differentiates the corrected form",
    });
    let mut e54 = eq(
        54,
        "A.1",
        "Method 1 reduced",
        OnShell,
        &[
            "ladder::jensen::eq54_printed",
            "ladder::jensen::eq54_corrected",
        ],
        vec![on("(53) reduced, on the motion", ladder_fns!(eq54))],
    );
    e54.erratum = Some(Erratum {
        printed: r"\frac{4m l^2 \dot{\theta}^2}{3} = m g l \sin \theta",
        corrected: r"\frac{4m l^2 \ddot{\theta}}{3} = m g l \sin \theta",
        why: "in (53) the term −4ml²θ̇² cos θ sin θ is on both sides and cancels; −2ml²θ̈ sin²θ is on the right only, and moved to the left it makes ml²θ̈ (1/3 + cos²θ + sin²θ) = 4ml²θ̈/3: θ̈, not θ̇²",
    });
    let mut e62 = eq(
        62,
        "A.5",
        "Hu's method about C, expanded",
        OnShell,
        &[
            "ladder::jensen::eq62_printed",
            "ladder::jensen::eq62_corrected",
        ],
        vec![on(
            "left side against printed and corrected right side",
            ladder_fns!(eq62),
        )],
    );
    e62.erratum = Some(Erratum {
        printed: r"m l g \sin \theta - m l \sin^2 \theta \ddot{\theta} - m l \cos \theta \sin \theta \dot{\theta}^2",
        corrected: r"m l g \sin \theta - 2m l^2 \sin^2 \theta \ddot{\theta} - 2m l^2 \cos \theta \sin \theta \dot{\theta}^2",
        why: "expanding the right side of (61) gives 2ml² on the θ̈ and θ̇² terms; the printed ml lacks a factor 2l (wrong dimensions)",
    });
    vec![
        eq(
            43,
            "A.1",
            "Centre of mass: position and velocity",
            Kinematic,
            &[
                "ladder::geometry::cm_position",
                "ladder::geometry::cm_velocity",
            ],
            vec![k("against particles and AD", ladder_fns!(eq43))],
        ),
        eq(
            44,
            "A.1",
            "The top C: position and velocity",
            Kinematic,
            &[
                "ladder::geometry::top_position",
                "ladder::geometry::top_velocity",
            ],
            vec![k("against geometry and AD", ladder_fns!(eq44))],
        ),
        eq(
            45,
            "A.1",
            "Centre of mass relative to C",
            Kinematic,
            &[
                "ladder::geometry::cm_from_top",
                "ladder::geometry::cm_velocity_from_top",
            ],
            vec![k("against references", ladder_fns!(eq45))],
        ),
        eq(
            46,
            "A.1",
            "(x_cm − x_C) × v_cm",
            Kinematic,
            &["ladder::geometry::eq46_cross"],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq46),
            )],
        ),
        eq(
            47,
            "A.1",
            "(x_cm − x_C) × (v_cm − v_C)",
            Kinematic,
            &["ladder::geometry::eq47_cross"],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq47),
            )],
        ),
        eq(
            48,
            "A.1",
            "v_cm × v_C",
            Kinematic,
            &[
                "ladder::geometry::eq48_cross",
                "ladder::jensen::velocity_term_c",
            ],
            vec![k(
                "against the cross product of references",
                ladder_fns!(eq48),
            )],
        ),
        e49,
        eq(
            50,
            "A.1",
            "I_C ω",
            Kinematic,
            &["ladder::jensen::eq50_rigid_angular_momentum_c"],
            vec![k("against the particles' I about C", ladder_fns!(eq50))],
        ),
        eq(
            51,
            "A.1",
            "Torque about C",
            Newton,
            &["ladder::jensen::eq51_torque_about_c"],
            vec![k("against τ_C of the particles", ladder_fns!(eq51))],
        ),
        eq(
            52,
            "A.1",
            "Torque side of (38) about C",
            Newton,
            &["ladder::jensen::eq52_modified_torque_c"],
            vec![k(
                "against τ_C + m v_cm × v_C of the particles",
                ladder_fns!(eq52),
            )],
        ),
        eq(
            53,
            "A.1",
            "Method 1 about C",
            OnShell,
            &["ladder::jensen::eq53_method_one_c"],
            vec![
                on("dL_C/dt by AD = both printed forms", ladder_fns!(eq53)),
                k(
                    "first form is d/dt of the corrected (49)",
                    ladder_fns!(eq53_first_form),
                ),
            ],
        ),
        e54,
        eq(
            55,
            "A.3",
            "Method 3: L'_C about the contact point",
            Kinematic,
            &["ladder::jensen::eq55_relative_angular_momentum_c"],
            vec![k("against L'_C (39) of the particles", ladder_fns!(eq55))],
        ),
        eq(
            59,
            "A.5",
            "Hu's method about C",
            OnShell,
            &["ladder::jensen::eq59_hu_method_c"],
            vec![on("dL_P/dt with P frozen at C = τ_C", ladder_fns!(eq59))],
        ),
        eq(
            60,
            "A.5",
            "Hu's method about C, in components",
            OnShell,
            &["ladder::jensen::eq60_hu_components"],
            vec![on("both sides on the motion", ladder_fns!(eq60))],
        ),
        eq(
            61,
            "A.5",
            "Hu's method about C, forces substituted",
            OnShell,
            &["ladder::jensen::eq61_hu_expanded"],
            vec![on("both sides on the motion", ladder_fns!(eq61))],
        ),
        e62,
        eq(
            63,
            "A.5",
            "Hu's method about C: the equation of motion",
            OnShell,
            &["ladder::jensen::eq63_equation_of_motion"],
            vec![on("both sides on the motion", ladder_fns!(eq63))],
        ),
    ]
}

//! Registry entries and checks for Appendix A's general identities, eqs. (29)-(42), (56)-(58):
//! any number of particles, any reference point P, every time derivative by automatic
//! differentiation along the motion.

mod momentum;
use momentum::*;
mod points;
use points::*;

use super::sample::ParticleSample::{self, PAtCm, PFixed, PlanarRigid, RollingAboutP};
use super::{eq, Equation, Kind};
use crate::particle_fns;

/// The entries for Appendix A's general identities.
pub(super) fn equations() -> Vec<Equation> {
    use Kind::*;
    vec![
        eq(
            29,
            "A",
            "Newton's second law for a particle",
            General,
            &["system::Particle::momentum", "system::Particle::force"],
            vec![gen(
                "d(mv)/dt by AD = m a = F",
                ParticleSample::General,
                particle_fns!(eq29),
            )],
        ),
        eq(
            30,
            "A",
            "Angular momentum of a particle",
            Definition,
            &["system::System::angular_momentum"],
            vec![gen(
                "x × p two ways and as a system",
                ParticleSample::General,
                particle_fns!(eq30),
            )],
        ),
        eq(
            31,
            "A",
            "Torque on a particle",
            General,
            &["system::Particle::force"],
            vec![gen(
                "dL/dt by AD = v × mv + x × dp/dt = x × F",
                ParticleSample::General,
                particle_fns!(eq31),
            )],
        ),
        eq(
            32,
            "A",
            "Centre of mass of a system",
            Definition,
            &[
                "system::System::total_mass",
                "system::System::centre_of_mass",
                "system::System::cm_velocity",
                "system::System::cm_acceleration",
                "system::System::total_force",
            ],
            vec![gen(
                "m, m x_cm, m v_cm and m a_cm (AD) against sums",
                ParticleSample::General,
                particle_fns!(eq32),
            )],
        ),
        eq(
            33,
            "A",
            "Orbital plus spin angular momentum",
            General,
            &[
                "system::System::angular_momentum",
                "system::System::spin_angular_momentum",
            ],
            vec![gen(
                "all four printed forms",
                ParticleSample::General,
                particle_fns!(eq33),
            )],
        ),
        eq(
            34,
            "A",
            "Angular momentum about the centre of mass",
            Definition,
            &["system::System::spin_angular_momentum"],
            vec![gen(
                "sum against L − x_cm × m v_cm",
                ParticleSample::General,
                particle_fns!(eq34),
            )],
        ),
        eq(
            35,
            "A",
            "Torque equation of a system",
            General,
            &["system::System::torque"],
            vec![gen(
                "dL/dt and Σ dL_i/dt by AD against Σ x_i × F_i",
                ParticleSample::General,
                particle_fns!(eq35),
            )],
        ),
        eq(
            36,
            "A",
            "Torque about a point P",
            General,
            &["system::System::torque_about"],
            vec![gen(
                "three printed forms",
                ParticleSample::General,
                particle_fns!(eq36),
            )],
        ),
        eq(
            37,
            "A",
            "Angular momentum L_P about P",
            General,
            &["system::System::angular_momentum_about"],
            vec![gen(
                "three printed forms",
                ParticleSample::General,
                particle_fns!(eq37),
            )],
        ),
        eq(
            38,
            "A",
            "Rate of change of L_P for a moving P",
            General,
            &[
                "system::System::angular_momentum_about",
                "system::System::torque_about",
            ],
            vec![gen(
                "dL_P/dt by AD against both forms",
                ParticleSample::General,
                particle_fns!(eq38),
            )],
        ),
        eq(
            39,
            "A",
            "Angular momentum L'_P relative to a moving P",
            General,
            &["system::System::relative_angular_momentum_about"],
            vec![gen(
                "four printed forms",
                ParticleSample::General,
                particle_fns!(eq39),
            )],
        ),
        eq(
            40,
            "A",
            "Rate of change of L'_P",
            General,
            &["system::System::relative_angular_momentum_about"],
            vec![gen(
                "dL'_P/dt by AD against both forms",
                ParticleSample::General,
                particle_fns!(eq40),
            )],
        ),
        eq(
            41,
            "A",
            "P at the centre of mass",
            General,
            &["system::System::cm_point"],
            vec![gen(
                "L_P = L'_P = L_cm and their rates = τ_cm",
                PAtCm,
                particle_fns!(eq41),
            )],
        ),
        eq(
            42,
            "A",
            "Rolling without slipping about P",
            General,
            &["system::System::moment_of_inertia_about"],
            vec![gen(
                "I_P ω against L_P and L'_P",
                RollingAboutP,
                particle_fns!(eq42),
            )],
        ),
        eq(
            56,
            "A.5",
            "Hu: rate of L_P for P at rest",
            General,
            &["system::System::angular_momentum_about"],
            vec![gen(
                "dL_P/dt by AD against three forms",
                PFixed,
                particle_fns!(eq56),
            )],
        ),
        eq(
            57,
            "A.5",
            "Hu: via the spin angular momentum",
            General,
            &["system::System::spin_angular_momentum"],
            vec![gen(
                "dL_P/dt = dL_cm/dt + (x_cm − x_P) × m a_cm",
                PFixed,
                particle_fns!(eq57),
            )],
        ),
        eq(
            58,
            "A.5",
            "Hu: torque about the centre of mass",
            General,
            &[
                "system::System::spin_angular_momentum",
                "system::System::moment_of_inertia_about",
            ],
            vec![gen(
                "dL_cm/dt = I_cm ω̇ = τ_cm for a rigid body",
                PlanarRigid,
                particle_fns!(eq58),
            )],
        ),
    ]
}

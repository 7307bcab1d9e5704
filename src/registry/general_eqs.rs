//! Registry entries and checks for Appendix A's general identities, eqs. (29)-(42), (56)-(58):
//! any number of particles, any reference point P, every time derivative by automatic
//! differentiation along the motion.

use super::sample::ParticleSample::{self, PAtCm, PFixed, PlanarRigid, RollingAboutP};
use super::{eq, on_particles, printed, reference, vector_chains, Chain, Check, Equation, Kind};
use crate::particle_fns;
use crate::scalar::Scalar;
use crate::system::{rate_vec, Particle, Point, System};
use crate::vector::{sum, Vec3};

type Chains<S> = Vec<Chain<S>>;

/// Per-particle vector chains, concatenated over all particles.
fn per_particle<S: Scalar>(
    sys: &System<S>,
    f: impl Fn(&Particle<S>) -> Vec<super::Side<Vec3<S>>>,
) -> Chains<S> {
    sys.particles
        .iter()
        .flat_map(|q| vector_chains(f(q)))
        .collect()
}

fn eq29<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    per_particle(sys, |q| {
        let lifted = q.along_motion();
        vec![
            reference("d(m v)/dt (AD)", rate_vec::<S>(&lifted.momentum())),
            printed("m a", q.a.scale(&q.m)),
            printed("F", q.force()),
        ]
    })
}

fn eq30<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    per_particle(sys, |q| {
        let one = System {
            particles: vec![q.clone()],
            spin: None,
        };
        vec![
            printed("x × p", q.x.cross(&q.momentum())),
            printed("x × m v", q.x.cross(&q.v.scale(&q.m))),
            reference(
                "one-particle system: L about the origin",
                one.angular_momentum(),
            ),
        ]
    })
}

fn eq31<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    per_particle(sys, |q| {
        let lifted = q.along_motion();
        let d_l = rate_vec::<S>(&lifted.x.cross(&lifted.momentum()));
        let d_p = rate_vec::<S>(&lifted.momentum());
        vec![
            reference("dL/dt (AD)", d_l),
            printed(
                "v × m v + x × dp/dt",
                q.v.cross(&q.v.scale(&q.m)) + q.x.cross(&d_p),
            ),
            printed("x × F", q.x.cross(&q.force())),
        ]
    })
}

fn eq32<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let lifted = sys.along_motion();
    let v_cm = rate_vec::<S>(&lifted.centre_of_mass());
    let a_cm = rate_vec::<S>(&rate_vec::<S::Dual>(
        &sys.along_motion().along_motion().centre_of_mass(),
    ));
    let weighted =
        |f: &dyn Fn(&Particle<S>) -> Vec3<S>| sum(sys.particles.iter().map(|q| f(q).scale(&q.m)));
    let mut c = vec![vec![
        printed("m", m.clone()),
        reference(
            "Σ m_i",
            sys.particles.iter().fold(S::int(0), |a, q| a + q.m.clone()),
        ),
    ]];
    c.extend(vector_chains(vec![
        printed("m x_cm", sys.centre_of_mass().scale(&m)),
        reference("Σ m_i x_i", weighted(&|q| q.x.clone())),
    ]));
    c.extend(vector_chains(vec![
        printed("m v_cm (v_cm by AD of x_cm)", v_cm.scale(&m)),
        reference("Σ m_i v_i", weighted(&|q| q.v.clone())),
    ]));
    c.extend(vector_chains(vec![
        printed("m a_cm (a_cm by AD² of x_cm)", a_cm.scale(&m)),
        printed("Σ m_i a_i", weighted(&|q| q.a.clone())),
        printed("Σ F_i = F", sum(sys.particles.iter().map(Particle::force))),
    ]));
    c
}

fn eq33<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (x_cm, v_cm) = (sys.centre_of_mass(), sys.cm_velocity());
    let l_cm = sys.spin_angular_momentum();
    let second = sum(sys.particles.iter().map(|q| {
        (q.x.clone() - x_cm.clone())
            .cross(&(q.v.clone() - v_cm.clone()))
            .scale(&q.m)
    })) + sum(sys.particles.iter().map(|q| q.x.cross(&v_cm).scale(&q.m)))
        + x_cm.cross(&sys.momentum())
        - sum(sys.particles.iter().map(|q| x_cm.cross(&v_cm).scale(&q.m)));
    let third = l_cm.clone() + x_cm.cross(&v_cm).scale(&m) + x_cm.cross(&v_cm.scale(&m))
        - x_cm.cross(&v_cm).scale(&m);
    vector_chains(vec![
        printed(
            "Σ L_i = Σ m_i x_i × v_i",
            sum(sys.particles.iter().map(|q| q.x.cross(&q.v).scale(&q.m))),
        ),
        printed("second line", second),
        printed(
            "L_cm + m x_cm × v_cm + x_cm × m v_cm − m x_cm × v_cm",
            third,
        ),
        printed("L_cm + x_cm × m v_cm", l_cm + x_cm.cross(&v_cm.scale(&m))),
    ])
}

fn eq34<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (x_cm, v_cm) = (sys.centre_of_mass(), sys.cm_velocity());
    let by_sum = sum(sys.particles.iter().map(|q| {
        (q.x.clone() - x_cm.clone())
            .cross(&(q.v.clone() - v_cm.clone()))
            .scale(&q.m)
    }));
    vector_chains(vec![
        printed("Σ m_i (x_i − x_cm) × (v_i − v_cm)", by_sum),
        reference("system: L_cm", sys.spin_angular_momentum()),
        reference(
            "L − x_cm × m v_cm",
            sys.angular_momentum() - x_cm.cross(&v_cm.scale(&m)),
        ),
    ])
}

fn eq35<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    let lifted = sys.along_motion();
    let each = sum(lifted
        .particles
        .iter()
        .map(|q| rate_vec::<S>(&q.x.cross(&q.momentum()))));
    vector_chains(vec![
        reference("dL/dt (AD)", rate_vec::<S>(&lifted.angular_momentum())),
        reference("Σ dL_i/dt (AD)", each),
        printed(
            "Σ x_i × F_i = Σ τ_i",
            sum(sys.particles.iter().map(|q| q.x.cross(&q.force()))),
        ),
        printed("τ", sys.torque()),
    ])
}

fn eq36<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    vector_chains(vec![
        printed("Σ (x_i − x_P) × F_i", sys.torque_about(&p.x)),
        printed("τ − x_P × F", sys.torque() - p.x.cross(&sys.total_force())),
        printed(
            "τ − x_P × m a_cm",
            sys.torque() - p.x.cross(&sys.cm_acceleration().scale(&m)),
        ),
    ])
}

fn eq37<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let mv = sys.cm_velocity().scale(&m);
    vector_chains(vec![
        printed("Σ (x_i − x_P) × m_i v_i", sys.angular_momentum_about(p)),
        printed("L − x_P × m v_cm", sys.angular_momentum() - p.x.cross(&mv)),
        printed(
            "L_cm + (x_cm − x_P) × m v_cm",
            sys.spin_angular_momentum() + (sys.centre_of_mass() - p.x.clone()).cross(&mv),
        ),
    ])
}

fn eq38<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (ls, lp) = (sys.along_motion(), p.along_motion());
    let d_l = rate_vec::<S>(&ls.angular_momentum());
    vector_chains(vec![
        reference(
            "dL_P/dt (AD, P moving)",
            rate_vec::<S>(&ls.angular_momentum_about(&lp)),
        ),
        printed(
            "dL/dt − x_P × m a_cm − v_P × m v_cm",
            d_l - p.x.cross(&sys.cm_acceleration().scale(&m))
                - p.v.cross(&sys.cm_velocity().scale(&m)),
        ),
        printed(
            "τ_P + m v_cm × v_P",
            sys.torque_about(&p.x) + sys.cm_velocity().scale(&m).cross(&p.v),
        ),
    ])
}

fn eq39<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (x_cm, v_cm) = (sys.centre_of_mass(), sys.cm_velocity());
    vector_chains(vec![
        printed(
            "Σ (x_i − x_P) × m_i (v_i − v_P)",
            sys.relative_angular_momentum_about(p),
        ),
        printed(
            "L − x_cm × m v_P − x_P × m (v_cm − v_P)",
            sys.angular_momentum()
                - x_cm.cross(&p.v.scale(&m))
                - p.x.cross(&(v_cm.clone() - p.v.clone()).scale(&m)),
        ),
        printed(
            "L_cm + (x_cm − x_P) × m (v_cm − v_P)",
            sys.spin_angular_momentum()
                + (x_cm.clone() - p.x.clone()).cross(&(v_cm - p.v.clone()).scale(&m)),
        ),
        printed(
            "L_P − (x_cm − x_P) × m v_P",
            sys.angular_momentum_about(p) - (x_cm - p.x.clone()).cross(&p.v.scale(&m)),
        ),
    ])
}

fn eq40<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (ls, lp) = (sys.along_motion(), p.along_motion());
    let r = sys.centre_of_mass() - p.x.clone();
    let d_lp = rate_vec::<S>(&ls.angular_momentum_about(&lp));
    vector_chains(vec![
        reference(
            "dL'_P/dt (AD)",
            rate_vec::<S>(&ls.relative_angular_momentum_about(&lp)),
        ),
        printed(
            "dL_P/dt − v_cm × m v_P − (x_cm − x_P) × m a_P",
            d_lp - sys.cm_velocity().cross(&p.v.scale(&m)) - r.cross(&p.a.scale(&m)),
        ),
        printed(
            "τ_P + (x_cm − x_P) × (−m a_P)",
            sys.torque_about(&p.x) + r.cross(&p.a.scale(&(-m))),
        ),
    ])
}

fn eq41<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let (ls, lp) = (sys.along_motion(), p.along_motion());
    let mut c = vector_chains(vec![
        printed("L_P", sys.angular_momentum_about(p)),
        printed("L'_P", sys.relative_angular_momentum_about(p)),
        printed("L_cm", sys.spin_angular_momentum()),
    ]);
    c.extend(vector_chains(vec![
        printed(
            "dL_P/dt (AD)",
            rate_vec::<S>(&ls.angular_momentum_about(&lp)),
        ),
        printed(
            "dL'_P/dt (AD)",
            rate_vec::<S>(&ls.relative_angular_momentum_about(&lp)),
        ),
        printed("dL_cm/dt (AD)", rate_vec::<S>(&ls.spin_angular_momentum())),
        printed("τ_cm", sys.torque_about(&sys.centre_of_mass())),
    ]));
    c
}

fn eq42<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let omega = sys
        .spin
        .as_ref()
        .expect("a rolling sample has a spin")
        .omega
        .clone();
    let i_w = Vec3::along_z(sys.moment_of_inertia_about(&p.x) * omega);
    let mut c = vector_chains(vec![
        reference("L_P (37)", sys.angular_momentum_about(p)),
        printed("I_P ω", i_w.clone()),
    ]);
    c.extend(vector_chains(vec![
        reference("L'_P (39)", sys.relative_angular_momentum_about(p)),
        printed(
            "I_P ω − (x_cm − x_P) × m v_P",
            i_w - (sys.centre_of_mass() - p.x.clone()).cross(&p.v.scale(&m)),
        ),
    ]));
    c
}

fn eq56<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (ls, lp) = (sys.along_motion(), p.along_motion());
    let moment = p.x.cross(&sys.cm_acceleration().scale(&m));
    vector_chains(vec![
        reference(
            "dL_P/dt (AD, P at rest)",
            rate_vec::<S>(&ls.angular_momentum_about(&lp)),
        ),
        printed(
            "dL/dt − x_P × m a_cm",
            rate_vec::<S>(&ls.angular_momentum()) - moment.clone(),
        ),
        printed("τ − x_P × m a_cm", sys.torque() - moment),
        printed("τ_P", sys.torque_about(&p.x)),
    ])
}

fn eq57<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let (ls, lp) = (sys.along_motion(), p.along_motion());
    vector_chains(vec![
        reference(
            "dL_P/dt (AD, P at rest)",
            rate_vec::<S>(&ls.angular_momentum_about(&lp)),
        ),
        printed(
            "dL_cm/dt + (x_cm − x_P) × m a_cm",
            rate_vec::<S>(&ls.spin_angular_momentum())
                + (sys.centre_of_mass() - p.x.clone()).cross(&sys.cm_acceleration().scale(&m)),
        ),
    ])
}

fn eq58<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
    let m = sys.total_mass();
    let x_cm = sys.centre_of_mass();
    let omega_dot = sys
        .spin
        .as_ref()
        .expect("a rigid sample has a spin")
        .omega_dot
        .clone();
    vector_chains(vec![
        reference(
            "dL_cm/dt (AD)",
            rate_vec::<S>(&sys.along_motion().spin_angular_momentum()),
        ),
        printed(
            "I_cm ω̇",
            Vec3::along_z(sys.moment_of_inertia_about(&x_cm) * omega_dot),
        ),
        printed(
            "τ_P + (x_cm − x_P) × (−m a_cm)",
            sys.torque_about(&p.x)
                + (x_cm.clone() - p.x.clone()).cross(&sys.cm_acceleration().scale(&(-m))),
        ),
        printed("τ_cm", sys.torque_about(&x_cm)),
    ])
}

fn gen(name: &'static str, sample: ParticleSample, f: super::ParticleFns) -> Check {
    on_particles(name, sample, f)
}

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

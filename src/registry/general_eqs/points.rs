//! Checks of eqs. (36)-(42), (56)-(58): reference points.

use crate::registry::{printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::{rate_vec, Particle, Point, System};
use crate::vector::Vec3;

pub(super) type Chains<S> = Vec<Chain<S>>;

/// Per-particle vector chains, concatenated over all particles.
pub(super) fn per_particle<S: Scalar>(
    sys: &System<S>,
    f: impl Fn(&Particle<S>) -> Vec<crate::registry::Side<Vec3<S>>>,
) -> Chains<S> {
    sys.particles
        .iter()
        .flat_map(|q| vector_chains(f(q)))
        .collect()
}

pub(super) fn eq36<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq37<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq38<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq39<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq40<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq41<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq42<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq56<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq57<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

pub(super) fn eq58<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Chains<S> {
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

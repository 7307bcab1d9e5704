//! Checks of eqs. (29)-(35): one particle, systems, the origin.

use crate::registry::{printed, reference, vector_chains};
use crate::scalar::Scalar;
use crate::system::{rate_vec, Particle, Point, System};
use crate::vector::{sum, Vec3};

use super::points::{per_particle, Chains};

pub(super) fn eq29<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
    per_particle(sys, |q| {
        let lifted = q.along_motion();
        vec![
            reference("d(m v)/dt (AD)", rate_vec::<S>(&lifted.momentum())),
            printed("m a", q.a.scale(&q.m)),
            printed("F", q.force()),
        ]
    })
}

pub(super) fn eq30<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

pub(super) fn eq31<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

pub(super) fn eq32<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

pub(super) fn eq33<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

pub(super) fn eq34<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

pub(super) fn eq35<S: Scalar>(sys: &System<S>, _: &Point<S>) -> Chains<S> {
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

//! Checks of secs. B.7-B.9 (Milne secs. 303-306): rates of change of the angular momenta about
//! a moving point, eqs. (85)-(90).
//!
//! Every d/dt is the rate along the motion of the printed quantity, by automatic
//! differentiation of the lifted system and point; the torque τ = Σ x_i × F_i of the forces is
//! added to each chain as a reference that involves no differentiation at all.

use super::d_dt;
use crate::milne;
use crate::registry::{printed, reference, vector_chains, Chain};
use crate::scalar::Scalar;
use crate::system::{rate_vec, Point, System};

/// (85): dL/dt = dL_P/dt + v_P × m v_cm + x_P × m a_cm, Milne's
/// dH(O')/dt = dH(O)/dt + ṙ_0 ∧ L + r_0 ∧ dL/dt.
pub(super) fn eq85<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    let d_l_p = d_dt(sys, p, |s, q| s.angular_momentum_about(q));
    let d_h_o = d_dt(sys, p, milne::h);
    let d_milne_l = d_dt(sys, p, |s, _| milne::l(s));
    vector_chains(vec![
        printed("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
        printed(
            "dL_P/dt (AD) + v_P × m v_cm + x_P × m a_cm",
            d_l_p
                + p.v.cross(&sys.cm_velocity().scale(&m))
                + p.x.cross(&sys.cm_acceleration().scale(&m)),
        ),
        printed(
            "Milne: dH(O')/dt (AD)",
            d_dt(sys, p, |s, _| milne::h(s, &milne::origin())),
        ),
        printed(
            "Milne: dH(O)/dt + ṙ_0 ∧ L + r_0 ∧ dL/dt (AD)",
            d_h_o + milne::big_v(p).cross(&milne::l(sys)) + milne::r_0(p).cross(&d_milne_l),
        ),
        reference("τ = Σ x_i × F_i", sys.torque()),
    ])
}

/// (86): with x_P = 0, dL/dt = dL_P/dt + v_P × m v_cm; Milne's, with O = O',
/// dH(O')/dt = dH(O)/dt + V ∧ L.
pub(super) fn eq86<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    vector_chains(vec![
        printed("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
        printed(
            "dL_P/dt|_{x_P=0} (AD) + v_P × m v_cm",
            d_dt(sys, p, |s, q| s.angular_momentum_about(q))
                + p.v.cross(&sys.cm_velocity().scale(&m)),
        ),
        printed(
            "Milne: dH(O')/dt (AD)",
            d_dt(sys, p, |s, _| milne::h(s, &milne::origin())),
        ),
        printed(
            "Milne: dH(O)/dt|_{O=O'} (AD) + V ∧ L",
            d_dt(sys, p, milne::h) + milne::big_v(p).cross(&milne::l(sys)),
        ),
        reference("τ = Σ x_i × F_i", sys.torque()),
    ])
}

/// Milne's dH(G')/dt about the fixed point G' where G is now.
fn d_h_g_prime<S: Scalar>(sys: &System<S>) -> crate::vector::Vec3<S> {
    d_dt(sys, &milne::g_prime(sys), milne::h)
}

/// (87): with the centre of mass (and P on it) at the origin, dL/dt = dL_cm/dt; Milne's
/// dH(G')/dt = dH(G)/dt, G moving with the lifted system.
pub(super) fn eq87<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed(
            "dL/dt|_{x_P=x_cm=0} (AD)",
            d_dt(sys, p, |s, _| s.angular_momentum()),
        ),
        printed(
            "dL_cm/dt (AD of L_P, P riding on the centre of mass)",
            d_dt(sys, p, |s, q| s.angular_momentum_about(q)),
        ),
        printed("Milne: dH(G')/dt (AD, G' fixed)", d_h_g_prime(sys)),
        printed(
            "Milne: dH(G)/dt|_{G=G'} (AD)",
            d_dt(sys, p, |s, _| milne::h(s, &milne::g(s))),
        ),
        reference("τ = Σ x_i × F_i", sys.torque()),
    ])
}

/// (87), Milne's line alone: it needs no origin at G, only G' fixed where G is now.
pub(super) fn eq87_milne_anywhere<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("Milne: dH(G')/dt (AD, G' fixed)", d_h_g_prime(sys)),
        printed(
            "Milne: dH(G)/dt|_{G=G'} (AD)",
            d_dt(sys, p, |s, _| milne::h(s, &milne::g(s))),
        ),
        reference(
            "τ_cm = Σ (x_i − x_cm) × F_i",
            sys.torque_about(&sys.centre_of_mass()),
        ),
    ])
}

/// (88): with the centre of mass at the origin, dL/dt = dL'_cm/dt; Milne's
/// dH(G')/dt = dH_r(G)/dt.
pub(super) fn eq88<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed(
            "dL/dt|_{x_cm=0} (AD)",
            d_dt(sys, p, |s, _| s.angular_momentum()),
        ),
        printed(
            "dL'_cm/dt (AD of L'_P, P riding on the centre of mass)",
            d_dt(sys, p, |s, q| s.relative_angular_momentum_about(q)),
        ),
        printed("Milne: dH(G')/dt (AD, G' fixed)", d_h_g_prime(sys)),
        printed(
            "Milne: dH_r(G)/dt (AD)",
            d_dt(sys, p, |s, _| milne::h_r(s, &milne::g(s))),
        ),
        reference("τ = Σ x_i × F_i", sys.torque()),
    ])
}

/// (88), Milne's line alone, G' fixed where G is now, any origin.
pub(super) fn eq88_milne_anywhere<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    vector_chains(vec![
        printed("Milne: dH(G')/dt (AD, G' fixed)", d_h_g_prime(sys)),
        printed(
            "Milne: dH_r(G)/dt (AD)",
            d_dt(sys, p, |s, _| milne::h_r(s, &milne::g(s))),
        ),
        reference(
            "τ_cm = Σ (x_i − x_cm) × F_i",
            sys.torque_about(&sys.centre_of_mass()),
        ),
    ])
}

/// (89): with x_P = 0, both lines of the display, each form a side.
pub(super) fn eq89<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    let big_m = milne::big_m(sys);
    let d_l_rel = d_dt(sys, p, |s, q| s.relative_angular_momentum_about(q));
    let d_moment = d_dt(sys, p, |s, q| {
        (s.centre_of_mass() - q.x.clone()).cross(&q.v.scale(&s.total_mass()))
    });
    let d_v_p = rate_vec::<S>(&p.along_motion().v);
    let d_h_r = d_dt(sys, p, milne::h_r);
    let d_milne_moment = d_dt(sys, p, |s, o| {
        milne::r_bar(s, o).cross(&milne::big_v(o).scale(&milne::big_m(s)))
    });
    vector_chains(vec![
        printed("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
        printed(
            "dL'_P/dt|_{x_P=0} + d/dt[(x_cm − x_P) × m v_P] + v_P × m v_cm (AD)",
            d_l_rel.clone() + d_moment + p.v.cross(&sys.cm_velocity().scale(&m)),
        ),
        printed(
            "dL'_P/dt|_{x_P=0} + x_cm × m dv_P/dt (AD)",
            d_l_rel + sys.centre_of_mass().cross(&d_v_p.scale(&m)),
        ),
        printed(
            "Milne: dH(O')/dt (AD)",
            d_dt(sys, p, |s, _| milne::h(s, &milne::origin())),
        ),
        printed(
            "Milne: dH_r(O)/dt + V ∧ L + d/dt[r̄ ∧ M V] (AD)",
            d_h_r.clone() + milne::big_v(p).cross(&milne::l(sys)) + d_milne_moment,
        ),
        printed(
            "Milne: dH_r(O)/dt + r̄ ∧ M dV/dt (AD)",
            d_h_r + milne::r_bar(sys, p).cross(&milne::big_v_dot(p).scale(&big_m)),
        ),
        reference("τ = Σ x_i × F_i", sys.torque()),
    ])
}

/// The right side of (90): dL/dt − x_cm × m a_P + x_P × m (a_P − a_cm), dL/dt by AD.
fn eq90_rhs<S: Scalar>(sys: &System<S>, p: &Point<S>) -> crate::vector::Vec3<S> {
    let m = sys.total_mass();
    d_dt(sys, p, |s, _| s.angular_momentum()) - sys.centre_of_mass().cross(&p.a.scale(&m))
        + p.x.cross(&(p.a.clone() - sys.cm_acceleration()).scale(&m))
}

/// (90): dL'_P/dt = dL/dt − x_cm × m a_P + x_P × m (a_P − a_cm), for any P.
pub(super) fn eq90<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    vector_chains(vec![
        printed(
            "dL'_P/dt (AD)",
            d_dt(sys, p, |s, q| s.relative_angular_momentum_about(q)),
        ),
        printed(
            "dL/dt (AD) − x_cm × m a_P + x_P × m (a_P − a_cm)",
            eq90_rhs(sys, p),
        ),
        reference(
            "τ_P + (x_cm − x_P) × (−m a_P) (eq. 40, from the forces)",
            sys.torque_about(&p.x) - (sys.centre_of_mass() - p.x.clone()).cross(&p.a.scale(&m)),
        ),
    ])
}

/// (90) at x_P = 0 gives back the last form of (89).
pub(super) fn eq90_reduces_to_89<S: Scalar>(sys: &System<S>, p: &Point<S>) -> Vec<Chain<S>> {
    let m = sys.total_mass();
    let d_l_rel = d_dt(sys, p, |s, q| s.relative_angular_momentum_about(q));
    // (90) solved for dL/dt: dL'_P/dt + x_cm × m a_P − x_P × m (a_P − a_cm).
    let solved = d_l_rel.clone() + sys.centre_of_mass().cross(&p.a.scale(&m))
        - p.x.cross(&(p.a.clone() - sys.cm_acceleration()).scale(&m));
    vector_chains(vec![
        reference("(90) solved for dL/dt", solved),
        printed(
            "(89): dL'_P/dt|_{x_P=0} + x_cm × m dv_P/dt (AD)",
            d_l_rel
                + sys
                    .centre_of_mass()
                    .cross(&rate_vec::<S>(&p.along_motion().v).scale(&m)),
        ),
        reference("dL/dt (AD)", d_dt(sys, p, |s, _| s.angular_momentum())),
    ])
}

/// The chain functions of this module, by the names the sections' `*Rust:*` lists use.
pub(in crate::registry) const FNS: &[(&str, crate::registry::Fns)] = &[
    crate::named_fns!(Particles, eq85),
    crate::named_fns!(Particles, eq86),
    crate::named_fns!(Particles, eq87),
    crate::named_fns!(Particles, eq87_milne_anywhere),
    crate::named_fns!(Particles, eq88),
    crate::named_fns!(Particles, eq88_milne_anywhere),
    crate::named_fns!(Particles, eq89),
    crate::named_fns!(Particles, eq90),
    crate::named_fns!(Particles, eq90_reduces_to_89),
];

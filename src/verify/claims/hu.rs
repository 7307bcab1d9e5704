//! The rolling claims of Appendix A decided on the model of [`super::rolling`]: sec. A.5's
//! "valid if the body has a symmetry axis" (Hu's I_P ω̇ = τ_P), (42), the contact wandering over
//! the body, sec. A.4's a_P and sec. A.2's "no difference at the moment".

use super::rolling::{disk, elliptic_cylinder, on_motion, Instant, RollingBody};
use crate::scalar::{Rational, Scalar};
use crate::system::{rate, Point};
use crate::vector::Vec3;
use num_traits::Zero;

type Q = Rational;

/// The three bodies with the orientations t at which each is evaluated, all on their motion
/// with ω = 2 and ω = −3: the centred disk, the disk with e = 3/2 (centre of mass at (1/2, 0)),
/// the elliptic cylinder (vertices and the rational non-vertex orientations).
pub fn sampled() -> Vec<(&'static str, Vec<Instant>)> {
    let q = |n: i64, d: i64| Q::new(n.into(), d.into());
    let disk_t = [q(0, 1), q(1, 3), q(2, 1), q(-3, 7), q(1, 1)];
    let ellipse_t = [q(0, 1), q(1, 1), q(1, 3), q(3, 1), q(-1, 3), q(-3, 1)];
    let run = |b: &RollingBody, ts: &[Q]| -> Vec<Instant> {
        ts.iter()
            .flat_map(|t| [2, -3].map(|w| on_motion(b, t, &Q::int(w))))
            .flatten()
            .collect()
    };
    vec![
        ("centred disk", run(&disk((0, 1)), &disk_t)),
        ("eccentric disk", run(&disk((3, 2)), &disk_t)),
        ("elliptic cylinder", run(&elliptic_cylinder(), &ellipse_t)),
    ]
}

/// The acceleration of the body's material point now at the contact: the no-slip field
/// ω ẑ × (x − x_P) differentiated along the motion there (x − x_P = 0, moving at −v_P).
pub fn material_contact_acceleration(i: &Instant) -> Vec3<Q> {
    let w = Vec3::along_z(Q::lift(i.omega.clone(), i.omega_dot.clone()));
    Vec3::<Q>::derivative_of(&w.cross(&Vec3::zero().lift(&-i.contact.v.clone())))
}

/// Hu's I_P ω̇ = τ_P at every sampled instant of the body named `name`.
pub fn hu_holds_throughout(name: &str) -> bool {
    sampled()
        .into_iter()
        .filter(|(n, _)| *n == name)
        .all(|(_, is)| !is.is_empty() && is.iter().all(|i| i.hu_residual().is_zero()))
}

/// Whether `condition` decides Hu's equation: at every sampled instant of every body,
/// I_P ω̇ = τ_P exactly when `condition` holds. The precise condition, the centre of mass on the
/// contact normal ([`Instant::cm_on_contact_normal`]), does; the note's "has a symmetry axis",
/// true of every sampled body, does not.
pub fn condition_decides(condition: impl Fn(&Instant) -> bool) -> bool {
    sampled()
        .iter()
        .flat_map(|(_, is)| is)
        .all(|i| i.hu_residual().is_zero() == condition(i))
}

/// The claims of this module.
pub fn claims() -> Vec<super::Claim> {
    use super::Claim;
    let all_instants = sampled();
    let every = |f: &dyn Fn(&Instant) -> bool| all_instants.iter().all(|(_, is)| is.iter().all(f));
    let eq42 = every(&|i| {
        let m = i.sys.total_mass();
        let (i_w, r) = (
            i.i_p() * i.omega.clone(),
            i.sys.centre_of_mass() - i.contact.x.clone(),
        );
        let (rates, l_p) = (i.rates(), i.sys.angular_momentum_about(&i.contact).z);
        l_p == i_w
            && i.sys.relative_angular_momentum_about(&i.contact).z
                == i_w - r.cross(&i.contact.v.scale(&m)).z
            && rates.0 == rates.1
            && i.spin_law_residual().is_zero()
    });
    let symmetric_fail =
        !hu_holds_throughout("eccentric disk") && !hu_holds_throughout("elliptic cylinder");
    let contact_wanders = every(&|i| i.body_contact_rate != Vec3::zero());
    let a_p_differs = every(&|i| material_contact_acceleration(i) != i.contact.a);
    // Sec. A.2: L_P about the contact on the floor and about the body's point there agree at the
    // instant; their rates differ by m v_cm × v_P (the term of (38) the body point lacks).
    let rate_about = |i: &Instant, p: &Point<Q>| {
        rate::<Q>(
            i.sys
                .along_motion()
                .angular_momentum_about(&p.along_motion())
                .z,
        )
    };
    let a2 = every(&|i| {
        let body_point = Point::fixed(i.contact.x.clone());
        let m = i.sys.total_mass();
        i.sys.angular_momentum_about(&i.contact) == i.sys.angular_momentum_about(&body_point)
            && rate_about(i, &i.contact) - rate_about(i, &body_point)
                == i.sys.cm_velocity().scale(&m).cross(&i.contact.v).z
    });
    let a2_rates_differ = !every(&|i| {
        let body_point = Point::fixed(i.contact.x.clone());
        rate_about(i, &i.contact) == rate_about(i, &body_point)
    });
    vec![
        Claim::erratum(
            "sec. A.5, before (56)",
            "Hu's I_P ω̇ = τ_P 'valid if the body has a symmetry axis': it holds exactly when the centre of mass is on the contact normal through P, at every instant only for a circular rim centred on the centre of mass; an eccentric disk and an elliptic cylinder have symmetry axes and fail",
            (
                "valid if the body has a symmetry axis",
                "valid when the centre of mass lies on the contact normal through P at every instant (a circular rim about the centre of mass)",
            ),
            hu_holds_throughout("centred disk") && condition_decides(Instant::cm_on_contact_normal),
            symmetric_fail,
        )
        .imprecise(),
        Claim::checked("sec. A.5", "not in general correct: L_P = I_P ω for a rolling body, yet I_P ω̇ ≠ τ_P (the eccentric disk)", eq42 && !hu_holds_throughout("eccentric disk")),
        Claim::checked("sec. A (42)", "rolling without slipping (disks, ellipse): L_P = I_P ω and L'_P = I_P ω − (x_cm − x_P) × m v_P", eq42),
        Claim::checked("sec. A (rolling)", "with a nonzero radius of curvature different points of the body touch the surface at different times (the contact moves over the body)", contact_wanders),
        Claim::checked("sec. A.4", "when rolling, a_P differs for the contact on the surface and the body's point there", a_p_differs),
        Claim::erratum(
            "sec. A.2",
            "'no difference at the moment' between P on the surface and on the body: L_P agrees at the instant, but when rolling moves the contact its rate does not (the surface point's (38) has m v_cm × v_P, the body point's none), so methods 1 and 2 differ",
            (
                "cannot see any difference at the moment",
                "L_P agrees at the instant; dL_P/dt differs by m v_cm × v_P unless the radius of curvature is zero (as for the ladder)",
            ),
            a2,
            a2_rates_differ,
        )
        .imprecise(),
    ]
}

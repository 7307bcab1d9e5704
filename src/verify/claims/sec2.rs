//! Claims of secs. 2.1-2.6 and their footnotes beyond the first fourteen: the spin and orbital
//! parts of L_A, the points' coordinates and distances, points on and off the ladder, (27) as
//! for A, footnote 3, and "which leads to the equation of motion (5)" after each analysis.
//! All exact, on the ladder's three-particle model (`ladder::particles`).

use super::{all, Claim};
use crate::ladder::analysis::{
    angular_momentum_about, solve_angular_acceleration, AngularMomentum, Reference,
};
use crate::ladder::energy::{angular_acceleration, energy, moment_of_inertia_cm};
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::particles::as_system;
use crate::ladder::torque::{angular_momentum_about_a, eq13_moment_of_inertia_about_corner};
use crate::ladder::{Ladder, State};
use crate::registry::sample::LadderSample::{Kinematic, OnShell};
use crate::scalar::{Rational, Scalar};
use crate::system::rate;

type Q = Rational;

/// Sec. 2.2: the spin L_cm = I_cm θ̇ = ml²θ̇/3, and it turns opposite to the orbital part
/// −ml²θ̇ (their signs differ for θ̇ ≠ 0); `i_cm` is the ladder's I_cm (printed: (8), ml²/3).
pub fn spin_and_sense(i_cm: impl Fn(&Ladder<Q>) -> Q) -> bool {
    all(Kinematic, |l, s| {
        let sys = as_system(l, s);
        let spin = sys.spin_angular_momentum().z;
        let orbital = sys.centre_of_mass().cross(&sys.cm_velocity().scale(&l.m)).z;
        spin == i_cm(l) * s.rate.clone() && spin.clone() * orbital < Q::int(0)
    })
}

/// Sec. 2.2 (13): whether corner `k` is at distance l from the centre of mass B at every exact
/// state; the note says so of A, C, D and E, so the parallel-axis theorem gives all four the
/// same I = I_cm + ml².
pub fn at_distance_l(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        let r = corner_position(k, l, s) - as_system(l, s).centre_of_mass();
        r.dot(&r) == l.l.clone() * l.l.clone()
    })
}

/// Secs. 2.3-2.6: B is the centre of mass; C = (0, 2y_cm), D = (2x_cm, 0), E = (2x_cm, 2y_cm).
/// Checked as printed in `claimed`: each corner k with (a, b) is at (a x_cm, b y_cm) at every
/// exact state.
pub fn coordinates_of_points(claimed: &[(Corner, i64, i64)]) -> bool {
    all(Kinematic, |l, s| {
        let cm = as_system(l, s).centre_of_mass();
        claimed.iter().all(|&(k, a, b)| {
            let at = corner_position(k, l, s);
            at.x == Q::int(a) * cm.x.clone() && at.y == Q::int(b) * cm.y.clone() && at.z == cm.z
        })
    })
}

/// The coordinates in `claimed` as the note writes them: `C = (0, 2y_cm)`.
pub fn coordinates_sentence(claimed: &[(Corner, i64, i64)]) -> String {
    let term = |n: i64, of: &str| match n {
        0 => "0".to_string(),
        1 => of.to_string(),
        n => format!("{n}{of}"),
    };
    let points: Vec<String> = claimed
        .iter()
        .map(|&(k, a, b)| format!("{} = ({}, {})", k.name(), term(a, "x_cm"), term(b, "y_cm")))
        .collect();
    points.join(", ")
}

/// The coordinates of B, C, D and E as secs. 2.3-2.6 print them, in multiples of (x_cm, y_cm).
pub const PRINTED_COORDINATES: [(Corner, i64, i64); 4] = [
    (Corner::B, 1, 1),
    (Corner::C, 0, 2),
    (Corner::D, 2, 0),
    (Corner::E, 2, 2),
];

/// Secs. 2.4, 2.5 ("since point C is located on the ladder, L_C = I_C θ̇"): about any point
/// fixed on the ladder, L'_P = I_P θ̇, for points at fractions 0, 1/3, 1 and 3/2 (past D) of the
/// way from C to D; I_P from the particles, the angular momentum as `def` defines it (printed:
/// relative to the point's motion).
pub fn rigid_about_points_on_ladder(def: AngularMomentum) -> bool {
    [(0, 1), (1, 3), (1, 1), (3, 2)].into_iter().all(|(n, d)| {
        all(Kinematic, |l, s| {
            let p = Reference::OnLadder(n, d);
            let x_p = crate::ladder::analysis::ReferencePoint::position(&p, l, s);
            angular_momentum_about(&p, def, l, s)
                == as_system(l, s).moment_of_inertia_about(&x_p) * s.rate.clone()
        })
    })
}

/// Sec. 2.6: whether corner `k` is off the ladder (the line through C and D) at every exact
/// state; the note says so of E.
pub fn off_the_ladder(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        let (c, d, e) = (
            corner_position(Corner::C, l, s),
            corner_position(Corner::D, l, s),
            corner_position(k, l, s),
        );
        (e - c.clone()).cross(&(d - c)).z != Q::int(0)
    })
}

/// Sec. 2.6, (27) "as for the analysis about point A": whether L'_k equals L_A (12) at every
/// exact state; the note says so of E.
pub fn relative_l_is_l_a(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        angular_momentum_about(&Reference::Corner(k), AngularMomentum::Relative, l, s)
            == angular_momentum_about_a(l, s)
    })
}

/// Footnote 3: d/dt of (10), θ̇² − (3g/2l)(1 − cos θ), is 2θ̇ (θ̈ − (3g/4l) sin θ) at any state
/// (so it gives (5) where θ̇ ≠ 0), and the energy (9) is constant on (5); `c10` is (10)'s
/// coefficient of g/l as printed (3/2).
pub fn footnote_3(c10: &Q) -> bool {
    let eq10 = |l: &Ladder<<Q as Scalar>::Dual>, s: &State<<Q as Scalar>::Dual>| {
        s.rate.clone() * s.rate.clone()
            - l.g.clone() * Q::constant(c10.clone()) / l.l.clone()
                * (<Q as Scalar>::Dual::int(1) - s.cos.clone())
    };
    let derivative = all(Kinematic, |l, s| {
        let d = rate::<Q>(eq10(&l.constant(), &s.along_motion()));
        d == Q::int(2) * s.rate.clone() * (s.accel.clone() - angular_acceleration(l, s))
    });
    let conserved = all(OnShell, |l, s| {
        rate::<Q>(energy(&l.constant(), &s.along_motion())) == Q::int(0)
    });
    derivative && conserved
}

/// The angular momentum each of sec. 2's analyses takes: L_A about A, L_B about B, and L' about
/// C, D and E (secs. 2.2-2.6).
pub const SEC2_ANALYSES: [(Corner, AngularMomentum); 5] = [
    (Corner::A, AngularMomentum::Absolute),
    (Corner::B, AngularMomentum::Absolute),
    (Corner::C, AngularMomentum::Relative),
    (Corner::D, AngularMomentum::Relative),
    (Corner::E, AngularMomentum::Relative),
];

/// Secs. 2.2-2.6 and A.1 ("which again leads to the equation of motion (5)"): the torque
/// analysis about `k` with angular momentum `def`, solved for θ̈, gives (5).
pub fn leads_to_eq5(k: Corner, def: AngularMomentum) -> bool {
    leads_to(k, def, angular_acceleration)
}

/// Whether the analysis about `k` with `def`, solved for θ̈, gives `eq5` at every exact state
/// (a test passes a wrong θ̈ to see it fail).
pub fn leads_to(k: Corner, def: AngularMomentum, eq5: fn(&Ladder<Q>, &State<Q>) -> Q) -> bool {
    all(Kinematic, |l, s| {
        solve_angular_acceleration(&Reference::Corner(k), def, l, s) == eq5(l, s)
    })
}

/// The claims of this module.
pub fn claims() -> Vec<Claim> {
    use AngularMomentum::{Absolute, Relative};
    let ok = Claim::checked;
    let sec2_analyses = SEC2_ANALYSES
        .into_iter()
        .all(|(k, def)| leads_to_eq5(k, def));
    let i13 = all(Kinematic, |l, _| {
        eq13_moment_of_inertia_about_corner(l)[1]
            == moment_of_inertia_cm(l) + l.m.clone() * l.l.clone() * l.l.clone()
    });
    vec![
        ok("sec. 2.2", "the spin about the centre of mass is I_cm θ̇ = ml²θ̇/3, opposite in sense to the orbital −ml²θ̇", spin_and_sense(moment_of_inertia_cm)),
        ok("sec. 2.2 (13)", "A, C, D, E are each at distance l from B, so the parallel-axis theorem gives one I = I_cm + ml² for all four", [Corner::A, Corner::C, Corner::D, Corner::E].into_iter().all(at_distance_l) && i13),
        Claim::checked("secs. 2.3-2.6", coordinates_sentence(&PRINTED_COORDINATES), coordinates_of_points(&PRINTED_COORDINATES)),
        ok("secs. 2.4, 2.5", "about any point fixed on the ladder L'_P = I_P θ̇ (why L_C, L_D are I θ̇)", rigid_about_points_on_ladder(Relative)),
        ok("sec. 2.6", "E is not on the ladder", off_the_ladder(Corner::E)),
        ok("sec. 2.6", "(27) is 'as for A': L'_E = L_A", relative_l_is_l_a(Corner::E)),
        ok("footnote 3", "d/dt of (10) gives (5), and the energy (9) is conserved on (5)", footnote_3(&Q::ratio(3, 2))),
        ok("secs. 2.2-2.6", "each torque analysis (A with L_A, B with L_B, C, D, E with L') solved for θ̈ gives (5)", sec2_analyses),
        ok("sec. A.1", "method 1 (L_C with (38)) solved for θ̈ gives (5)", leads_to_eq5(Corner::C, Absolute)),
    ]
}

//! Claims of Appendices A and B (and the general statements of secs. 2.2, 2.3) that are not
//! about rolling: on general particle systems (exact, three fixed systems of three particles
//! with every position, velocity, acceleration and jerk free, and a free moving point P), and on
//! the ladder for the comparisons of Jensen's methods.

use super::{all, Claim};
use crate::ladder::analysis::{angular_momentum_about, AngularMomentum, Reference};
use crate::ladder::geometry::{corner_position, Corner};
use crate::ladder::particles::{as_system, external_torque_about};
use crate::ladder::torque::{eq13_moment_of_inertia_about_corner, eq20_coordinate_force_c};
use crate::ladder::{Ladder, State};
use crate::registry::sample::LadderSample::Kinematic;
use crate::registry::sample::{particle_system, ParticleSample, EXTRA, PER_PARTICLE};
use crate::scalar::{Rational, Scalar};
use crate::system::{rate_vec, Point, System};
use crate::vector::Vec3;

type Q = Rational;

/// Three exact general systems of three particles with a moving point P (fixed integers,
/// masses positive, every other value free): every component of P's position, velocity,
/// acceleration and jerk nonzero in each system and of both signs among them, every component of
/// the particles' of both signs among them, no two particles of a system at one place.
pub fn general_systems() -> Vec<(System<Q>, Point<Q>)> {
    let n = 3;
    (0..3)
        .map(|seed: i64| {
            let values: Vec<Q> = (0..n * PER_PARTICLE + EXTRA)
                .map(|i| {
                    let v = (i as i64 * (7 + 5 * seed) + 9) % 19 - 9;
                    if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                        Q::from_integer((v.abs() + 1).into())
                    } else {
                        Q::from_integer(v.into())
                    }
                })
                .collect();
            particle_system(ParticleSample::General, n, &values)
        })
        .collect()
}

/// Systems with their moving points, as the checks below take them.
pub type Systems = [(System<Q>, Point<Q>)];

fn every(f: impl Fn(&System<Q>, &Point<Q>) -> bool) -> bool {
    every_of(&general_systems(), f)
}

fn every_of(systems: &Systems, f: impl Fn(&System<Q>, &Point<Q>) -> bool) -> bool {
    systems.iter().all(|(s, p)| f(s, p))
}

/// The point P held at rest where it is.
fn at_rest(p: &Point<Q>) -> Point<Q> {
    Point::fixed(p.x.clone())
}

/// Sec. 2.2 (in general): the angular momentum about a point is that of the centre-of-mass
/// motion plus that about the centre of mass, for L_P and (with velocities relative to P) L'_P.
/// Checked as a split about `centre` (drawn from each system and its point P): L_P is the
/// angular momentum relative to `centre` plus `centre`'s own motion carrying the whole mass,
/// L_P = L'_centre + (x_centre − x_P) × m v_centre, and L'_P the same with v_centre − v_P. The
/// note's centre is the centre of mass; about another point the split fails.
pub fn orbital_plus_spin(centre: impl Fn(&System<Q>, &Point<Q>) -> Point<Q>) -> bool {
    every(|s, p| {
        let c = centre(s, p);
        let (m, r) = (s.total_mass(), c.x.clone() - p.x.clone());
        let spin = s.relative_angular_momentum_about(&c);
        s.angular_momentum_about(p) == spin.clone() + r.cross(&c.v.scale(&m))
            && s.relative_angular_momentum_about(p)
                == spin + r.cross(&(c.v.clone() - p.v.clone()).scale(&m))
    })
}

/// Sec. A after (39), footnote 19: v_P = 0 ⇒ L'_P = L_P (and not so when P moves), on
/// `systems` whose points move.
pub fn fixed_point_same_l(systems: &Systems) -> bool {
    every_of(systems, |s, p| {
        let q = at_rest(p);
        s.relative_angular_momentum_about(&q) == s.angular_momentum_about(&q)
            && s.relative_angular_momentum_about(p) != s.angular_momentum_about(p)
    })
}

/// dL_P/dt (P moving as given) by automatic differentiation.
fn d_l_p(s: &System<Q>, p: &Point<Q>) -> Vec3<Q> {
    rate_vec::<Q>(&s.along_motion().angular_momentum_about(&p.along_motion()))
}

/// Sec. 2.2 (and B.2, "any fixed point"): about a point at rest only the lab's forces act:
/// dL_P/dt = τ_P; about a moving point (`systems`' own) that fails.
pub fn fixed_point_law(systems: &Systems) -> bool {
    every_of(systems, |s, p| {
        let q = at_rest(p);
        d_l_p(s, &q) == s.torque_about(&q.x) && d_l_p(s, p) != s.torque_about(&p.x)
    })
}

/// Sec. 2.3: about the centre of mass the coordinate force −m a_P has no torque, so
/// dL_cm/dt = τ_cm although the centre of mass accelerates (in each of `systems`).
pub fn cm_needs_no_coordinate_force(systems: &Systems) -> bool {
    every_of(systems, |s, _| {
        let cm = s.cm_point();
        let m = s.total_mass();
        let fictitious = (s.centre_of_mass() - cm.x.clone()).cross(&cm.a.scale(&(-m)));
        let d_spin = rate_vec::<Q>(&s.along_motion().spin_angular_momentum());
        fictitious == Vec3::zero() && d_spin == s.torque_about(&cm.x) && cm.a != Vec3::zero()
    })
}

/// Sec. B.7: (85) is the first form of (38) rearranged: both residuals vanish. `signs` are the
/// signs of v_P × m v_cm as (85) and (38) print it (+1, −1).
pub fn eq85_is_eq38(signs: (i64, i64)) -> bool {
    every(|s, p| {
        let m = s.total_mass();
        let d_l = rate_vec::<Q>(&s.along_motion().angular_momentum());
        let (v_p_mv, x_p_ma) = (
            p.v.cross(&s.cm_velocity().scale(&m)),
            p.x.cross(&s.cm_acceleration().scale(&m)),
        );
        let r85 = d_l.clone() - (d_l_p(s, p) + v_p_mv.scale(&Q::int(signs.0)) + x_p_ma.clone());
        let r38 = d_l_p(s, p) - (d_l - x_p_ma + v_p_mv.scale(&Q::int(signs.1)));
        r85 == Vec3::zero() && r38 == Vec3::zero()
    })
}

/// Sec. B.9: (90)'s right side is (40)'s τ'_P, and at x_P = 0 it is (89)'s dL/dt − x_cm × m a_P.
/// `k` is the coefficient of (90)'s last term x_P × m (a_P − a_cm) (printed: +1).
pub fn eq90_is_eq40(k: i64) -> bool {
    every(|s, p| {
        let m = s.total_mass();
        let rhs90 = |p: &Point<Q>| {
            rate_vec::<Q>(&s.along_motion().angular_momentum())
                - s.centre_of_mass().cross(&p.a.scale(&m))
                + p.x
                    .cross(&(p.a.clone() - s.cm_acceleration()).scale(&m))
                    .scale(&Q::int(k))
        };
        let tau_prime = s.torque_about(&p.x)
            + (s.centre_of_mass() - p.x.clone()).cross(&p.a.scale(&(-m.clone())));
        let origin = Point {
            x: Vec3::zero(),
            ..p.clone()
        };
        let eq89 = rate_vec::<Q>(&s.along_motion().angular_momentum())
            - s.centre_of_mass().cross(&p.a.scale(&m));
        rhs90(p) == tau_prime && rhs90(&origin) == eq89
    })
}

/// Sec. 2.1: the kinetic energy is that of the centre-of-mass motion plus that of the motion
/// relative to the centre of mass (any system), and on the ladder the latter is the rotation
/// I_cm θ̇²/2, with `i_cm` the ladder's I_cm (printed: (8), ml²/3).
pub fn kinetic_energy_splits(i_cm: impl Fn(&Ladder<Q>) -> Q) -> bool {
    let half = Q::ratio(1, 2);
    let kinetic = |s: &System<Q>, about: &Vec3<Q>| {
        s.particles.iter().fold(Q::int(0), |t, p| {
            let u = p.v.clone() - about.clone();
            t + half.clone() * p.m.clone() * u.dot(&u)
        })
    };
    let general = every(|s, _| {
        let v_cm = s.cm_velocity();
        kinetic(s, &Vec3::zero())
            == half.clone() * s.total_mass() * v_cm.dot(&v_cm) + kinetic(s, &v_cm)
    });
    let ladder = all(Kinematic, |l, st| {
        let s = as_system(l, st);
        kinetic(&s, &s.cm_velocity()) == half.clone() * i_cm(l) * st.rate.clone() * st.rate.clone()
    });
    general && ladder
}

/// Sec. B.5: (77), Σ (x_i − x_P) × m_i v_i, is (37): it equals (37)'s other forms
/// L − x_P × m v_cm and L_cm + (x_cm − x_P) × m v_cm; `signs` are the signs of their second
/// terms as printed (−1, +1).
pub fn eq77_is_eq37(signs: (i64, i64)) -> bool {
    every(|s, p| {
        let m = s.total_mass();
        let l_p = s.angular_momentum_about(p);
        let (first, second) = (
            p.x.cross(&s.cm_velocity().scale(&m)),
            (s.centre_of_mass() - p.x.clone()).cross(&s.cm_velocity().scale(&m)),
        );
        l_p == s.angular_momentum() + first.scale(&Q::int(signs.0))
            && l_p == s.spin_angular_momentum() + second.scale(&Q::int(signs.1))
    })
}

/// Sec. B.8: (84) in (87) gives (88): with the centre of mass at the origin at the instant,
/// dL/dt = dL'_cm/dt; with it elsewhere (and a_cm ≠ 0, in each of `systems`) they differ.
pub fn eq88_follows(systems: &Systems) -> bool {
    every_of(systems, |s, _| {
        let shifted = |by: Vec3<Q>| System {
            particles: s
                .particles
                .iter()
                .map(|q| crate::system::Particle {
                    x: q.x.clone() - by.clone(),
                    ..q.clone()
                })
                .collect(),
            spin: None,
        };
        let rates = |sys: &System<Q>| {
            let lifted = sys.along_motion();
            (
                rate_vec::<Q>(&lifted.angular_momentum()),
                rate_vec::<Q>(&lifted.relative_angular_momentum_about(&lifted.cm_point())),
            )
        };
        let (at_origin, elsewhere) = (rates(&shifted(s.centre_of_mass())), rates(s));
        at_origin.0 == at_origin.1 && elsewhere.0 != elsewhere.1
    })
}

/// The torque about `k` of a wall force at C alone (any value: 5).
fn wall_torque_about(k: Corner, l: &Ladder<Q>, s: &State<Q>) -> Q {
    let r = corner_position(Corner::C, l, s) - corner_position(k, l, s);
    r.cross(&Vec3::planar(Q::int(5), Q::int(0))).z
}

/// Sec. A (the point of contact), A.5 on (58): τ_C needs no wall force (the contact force at
/// C), τ_cm does. Checked for the two points given: the wall force has no torque about `free`
/// and a torque about `needed` at every exact state; the note's pair is (C, B).
pub fn contact_force_needed(free: Corner, needed: Corner) -> bool {
    all(Kinematic, |l, s| {
        wall_torque_about(free, l, s) == Q::int(0) && wall_torque_about(needed, l, s) != Q::int(0)
    })
}

/// Sec. A.5: (58) nominally about C, τ_C + (x_cm − x_C) × (−m a_cm), is τ_B of sec. 2.3; the
/// acceleration is that of the corner `accelerating` (printed: B, the centre of mass).
pub fn method5_is_about_b(accelerating: Corner) -> bool {
    all(Kinematic, |l, s| {
        let sys = as_system(l, s);
        let x_c = corner_position(Corner::C, l, s);
        let a =
            crate::ladder::analysis::ReferencePoint::motion(&Reference::Corner(accelerating), l, s)
                .a;
        let eff = (sys.centre_of_mass() - x_c.clone()).cross(&a.scale(&-l.m.clone()));
        let tau_b = external_torque_about(l, &sys, &sys.centre_of_mass());
        external_torque_about(l, &sys, &x_c) + eff == tau_b
    })
}

/// Sec. A.3: method 3 is sec. 2.4's analysis: the torque of −m a_C at the centre of mass is
/// (22)'s F_{C,y} l sin θ, F_C from (20); `k` is the point whose acceleration is taken
/// (printed: C).
pub fn method3_is_sec_2_4(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        let sys = as_system(l, s);
        let c = crate::ladder::analysis::ReferencePoint::motion(&Reference::Corner(k), l, s);
        let fict = (sys.centre_of_mass() - c.x)
            .cross(&c.a.scale(&-l.m.clone()))
            .z;
        fict == eq20_coordinate_force_c(l, s)[1].y.clone() * l.l.clone() * s.sin.clone()
    })
}

/// Sec. A before (42), footnote 15, (49)-(50): the ladder slips at C, and neither form of (42)
/// holds there: L_C ≠ I_C θ̇ and L'_C ≠ I_C θ̇ − (x_cm − x_C) × m v_C. Checked about the
/// corner `k` (the note's is C; about E, the instantaneous centre, (42) holds).
pub fn slipping_breaks_eq42(k: Corner) -> bool {
    all(Kinematic, |l, s| {
        let c = Reference::Corner(k);
        let i_w = eq13_moment_of_inertia_about_corner(l)[1].clone() * s.rate.clone();
        let sys = as_system(l, s);
        let m = crate::ladder::analysis::ReferencePoint::motion(&c, l, s);
        let moment = (sys.centre_of_mass() - m.x).cross(&m.v.scale(&l.m)).z;
        angular_momentum_about(&c, AngularMomentum::Absolute, l, s) != i_w.clone()
            && angular_momentum_about(&c, AngularMomentum::Relative, l, s) != i_w - moment
    })
}

/// Sec. A.6: Jensen's methods give three distinct angular momenta on the ladder (L_C for 1 and 2,
/// L'_C for 3 and 4, L_cm for 5), and only method 1's L_C is none of sec. 2's L_A, L_B, L'_C,
/// L'_D, L'_E. `methods` are the angular momenta of methods 1, 3 and 5 as the note names them:
/// [`JENSEN_METHODS`].
pub fn three_distinct_methods(methods: [(Corner, AngularMomentum); 3]) -> (bool, bool) {
    let mut three = true;
    let mut only_one_new = true;
    for (l, s) in super::states(Kinematic) {
        let at = |(k, d): (Corner, AngularMomentum)| {
            angular_momentum_about(&Reference::Corner(k), d, &l, &s)
        };
        let [m1, m3, m5] = methods.map(at);
        three &= m1 != m3 && m3 != m5 && m1 != m5;
        let sec2 = super::sec2::SEC2_ANALYSES.map(at);
        only_one_new &= sec2.iter().all(|x| *x != m1) && sec2.contains(&m3) && sec2.contains(&m5);
    }
    (three, only_one_new)
}

/// The angular momenta of Jensen's methods 1, 3 and 5 (sec. A.6): L_C, L'_C and L_cm (B).
pub const JENSEN_METHODS: [(Corner, AngularMomentum); 3] = [
    (Corner::C, AngularMomentum::Absolute),
    (Corner::C, AngularMomentum::Relative),
    (Corner::B, AngularMomentum::Absolute),
];

/// The claims of this module.
pub fn claims() -> Vec<Claim> {
    let ok = Claim::checked;
    let (three, only_one) = three_distinct_methods(JENSEN_METHODS);
    let systems = general_systems();
    vec![
        ok("sec. 2.2", "(any system, any point) L_P and L'_P are the orbital part of the centre of mass plus the spin L_cm", orbital_plus_spin(|s, _| s.cm_point())),
        ok("sec. 2.2, B.2", "(any system) about a point at rest dL_P/dt = τ_P with the lab's forces only; not about a moving point", fixed_point_law(&systems)),
        ok("sec. 2.3, 2.7", "(any system) about the centre of mass the coordinate force has no torque: dL_cm/dt = τ_cm though a_cm ≠ 0", cm_needs_no_coordinate_force(&systems)),
        ok("sec. A (39), fn. 19", "(any system) v_P = 0 gives L'_P = L_P; a moving P does not", fixed_point_same_l(&systems)),
        ok("sec. A (contact), A.5", "τ_C needs no contact force at C (the wall's torque about C is 0); τ_cm of (58) does", contact_force_needed(Corner::C, Corner::B)),
        ok("sec. A.5", "(58) nominally about C is the analysis about B: τ_C + (x_cm − x_C) × (−m a_cm) = τ_B", method5_is_about_b(Corner::B)),
        ok("sec. A.3", "method 3 is sec. 2.4's analysis: the torque of −m a_C is (22)'s F_C,y l sin θ", method3_is_sec_2_4(Corner::C)),
        ok("sec. A (42), fn. 15, A.1", "with slipping (the ladder at C) neither form of (42) holds: L_C ≠ I_C θ̇ (49)-(50), L'_C ≠ I_C θ̇ − (x_cm − x_C) × m v_C", slipping_breaks_eq42(Corner::C)),
        ok("sec. A.6", "only three of the five methods are distinct on the ladder (L_C, L'_C, L_cm differ pairwise)", three),
        ok("sec. A.6", "only method 1 is not one of sec. 2's analyses (its L_C is none of L_A, L_B, L'_C, L'_D, L'_E)", only_one),
        ok("sec. 2.1", "the kinetic energy is that of the centre-of-mass motion plus that relative to it (any system), the latter I_cm θ̇²/2 on the ladder", kinetic_energy_splits(crate::ladder::energy::moment_of_inertia_cm)),
        ok("sec. B.5", "(any system) (77) is the same as (37)", eq77_is_eq37((-1, 1))),
        ok("sec. B.8", "(any system) (84) in (87) gives (88): at x_cm = 0, dL/dt = dL'_cm/dt (elsewhere not)", eq88_follows(&systems)),
        ok("sec. B.7", "(any system) (85) is the first form of (38) rearranged", eq85_is_eq38((1, -1))),
        ok("sec. B.9", "(any system) (90) is (40) in another form, and reduces to (89) at x_P = 0", eq90_is_eq40(1)),
    ]
}

//! A particle system and its reference point P built from a sample's values in any scalar type
//! (f64 and `Bound` from a [`RawParticles`](super::RawParticles), rationals and degrees from
//! random integers, symbols for the proofs), with the premise of its sort imposed.

use super::ParticleSample;
use crate::scalar::Scalar;
use crate::system::{Particle, Point, Spin, System};
use crate::vector::Vec3;

/// Reads sample values in order.
struct Reader<'a, S> {
    values: &'a [S],
    at: usize,
}

impl<S: Scalar> Reader<'_, S> {
    fn scalar(&mut self) -> S {
        let v = self.values[self.at].clone();
        self.at += 1;
        v
    }
    fn vec(&mut self, planar: bool) -> Vec3<S> {
        let (x, y, z) = (self.scalar(), self.scalar(), self.scalar());
        Vec3::new(x, y, if planar { S::int(0) } else { z })
    }
}

/// Build a particle system and reference point of the given sort from values in any scalar type
/// (f64 and `Bound` from a [`RawParticles`](super::RawParticles), rationals and degrees from
/// random integers). `values` holds `n·PER_PARTICLE + EXTRA` numbers, exactly: a caller whose
/// layout differs from `read`'s (more values, as well as fewer) is a defect, not a sample.
pub fn particle_system<S: Scalar>(
    sort: ParticleSample,
    n: usize,
    values: &[S],
) -> (System<S>, Point<S>) {
    use ParticleSample::*;
    assert_eq!(
        values.len(),
        n * super::PER_PARTICLE + super::EXTRA,
        "particle_system: {n} particles take n·PER_PARTICLE + EXTRA values"
    );
    let planar = matches!(sort, RollingAboutP | PlanarRigid);
    let (mut particles, p, omega, omega_dot) = read(values, n, planar);
    let (p, spin) = match sort {
        General | PAtCm | CmAtOriginPAtCm | PFixed | PAtOrigin | ForceFree | TorqueFree => {
            (p, None)
        }
        RollingAboutP => {
            let spin = roll_about_p(&mut particles, &p, omega, omega_dot);
            (p, Some(spin))
        }
        PlanarRigid => {
            let (p, spin) = turn_rigidly(&mut particles, p, omega, omega_dot);
            (p, Some(spin))
        }
    };
    let mut sys = System { particles, spin };
    let p = impose_premise(sort, &mut sys, p);
    (sys, p)
}

/// The values in their order: per particle m, x, v, a, j; then P's x, v, a, j; then ω, ω̇
/// (z components zero when `planar`).
fn read<S: Scalar>(values: &[S], n: usize, planar: bool) -> (Vec<Particle<S>>, Point<S>, S, S) {
    let mut r = Reader { values, at: 0 };
    let particles: Vec<Particle<S>> = (0..n)
        .map(|_| Particle {
            m: r.scalar(),
            x: r.vec(planar),
            v: r.vec(planar),
            a: r.vec(planar),
            j: r.vec(planar),
        })
        .collect();
    let p = Point {
        x: r.vec(planar),
        v: r.vec(planar),
        a: r.vec(planar),
        j: r.vec(planar),
    };
    let (omega, omega_dot) = (r.scalar(), r.scalar());
    (particles, p, omega, omega_dot)
}

/// Rolling without slipping (eq. 42): the body's material point at P is at rest, so every
/// particle moves as v_i = ω ẑ × (x_i − x_P); P itself (the contact) moves with v_P.
fn roll_about_p<S: Scalar>(
    particles: &mut [Particle<S>],
    p: &Point<S>,
    omega: S,
    omega_dot: S,
) -> Spin<S> {
    let w = Vec3::along_z(S::int(1)).scale(&omega);
    for q in particles.iter_mut() {
        q.v = w.cross(&(q.x.clone() - p.x.clone()));
    }
    Spin { omega, omega_dot }
}

/// A rigid body (eq. 58): v_i = v_c + ω ẑ × r_i, a_i = a_c + ω̇ ẑ × r_i − ω² r_i, and the jerk
/// that follows with ω̈ = 0; the centre's motion is P's random motion, P then fixed.
fn turn_rigidly<S: Scalar>(
    particles: &mut [Particle<S>],
    p: Point<S>,
    omega: S,
    omega_dot: S,
) -> (Point<S>, Spin<S>) {
    let z = Vec3::along_z(S::int(1));
    let sys = System {
        particles: particles.to_vec(),
        spin: None,
    };
    let cm = sys.centre_of_mass();
    for q in particles.iter_mut() {
        let r_i = q.x.clone() - cm.clone();
        let r_dot = z.scale(&omega).cross(&r_i);
        let w2 = omega.clone() * omega.clone();
        q.v = p.v.clone() + r_dot.clone();
        q.a = p.a.clone() + z.scale(&omega_dot).cross(&r_i) - r_i.scale(&w2);
        q.j = p.j.clone() + z.scale(&omega_dot).cross(&r_dot)
            - r_i.scale(&(S::int(2) * omega.clone() * omega_dot.clone()))
            - r_dot.scale(&w2);
    }
    (Point::fixed(p.x), Spin { omega, omega_dot })
}

/// Each sort changes a general draw only as its premise requires: a condition at an instant
/// sets a position or velocity and leaves the rates above it free.
fn impose_premise<S: Scalar>(
    sort: ParticleSample,
    sys: &mut System<S>,
    mut p: Point<S>,
) -> Point<S> {
    use ParticleSample::*;
    match sort {
        PAtCm => {
            // P on the centre of mass now, moving with it (v_P = v_cm); a_P stays free.
            p.x = sys.centre_of_mass();
            p.v = sys.cm_velocity();
            p
        }
        PFixed => Point::fixed(p.x),
        PAtOrigin => {
            p.x = Vec3::zero();
            p
        }
        CmAtOriginPAtCm => {
            // The centre of mass at the origin now, P riding on it: the Rust checks of (87),
            // (88) take L_cm as L_P with this P (a device of theirs, not a premise: their
            // prints are checked on general states, the bars imposed where printed).
            let cm = sys.centre_of_mass();
            for q in &mut sys.particles {
                q.x = q.x.clone() - cm.clone();
            }
            sys.cm_point()
        }
        ForceFree => {
            crate::print::condition::force_free(sys);
            p
        }
        // The particles' torques cancel in sum, not each.
        TorqueFree => {
            crate::print::condition::torque_free(sys);
            p
        }
        General | RollingAboutP | PlanarRigid => p,
    }
}

//! `registry::sample`: the states the checks draw.

use num_dual::{Dual3, DualNum};
use sliding_ladder::registry::sample::{particle_system, ParticleSample, EXTRA, PER_PARTICLE};

type D = Dual3<f64>;

/// A particle's position at time t of the rigid motion the `PlanarRigid` sample claims: the
/// centre on its cubic c + v t + a t²/2 + j t³/6, the body turned by φ(t) = ω t + ω̇ t²/2 (ω̈ = 0)
/// about it. Written as a motion and differentiated by dual numbers, not from the sample's
/// formulas.
fn rigid_position(t: D, centre: [[f64; 2]; 4], r: [f64; 2], omega: f64, omega_dot: f64) -> [D; 2] {
    let c = |k: usize| {
        let [x, v, a, j] = centre.map(|p| D::from_re(p[k]));
        x + t * v + t * t * a * 0.5 + t * t * t * j * (1.0 / 6.0)
    };
    let phi = t * omega + t * t * omega_dot * 0.5;
    let (s, co) = (phi.sin(), phi.cos());
    [c(0) + co * r[0] - s * r[1], c(1) + s * r[0] + co * r[1]]
}

#[test]
fn particle_system_planar_rigid_moves_every_particle_with_one_rigid_turn() {
    let n = 4;
    // Fixed values of both signs, masses positive (the draw's layout: PER_PARTICLE a particle).
    let values: Vec<f64> = (0..n * PER_PARTICLE + EXTRA)
        .map(|i| {
            let v = ((i * 37 % 19) as f64 - 9.0) / 7.0;
            if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                v.abs() + 0.5
            } else {
                v
            }
        })
        .collect();
    let (sys, _) = particle_system(ParticleSample::PlanarRigid, n, &values);
    let spin = sys.spin.clone().expect("a rigid body spins");
    let (omega, omega_dot) = (spin.omega, spin.omega_dot);
    assert!(
        omega.abs() > 0.1 && omega_dot.abs() > 0.1,
        "{omega} {omega_dot}"
    );
    let mass: f64 = sys.particles.iter().map(|q| q.m).sum();
    let mean = |f: &dyn Fn(&sliding_ladder::system::Particle<f64>) -> [f64; 2]| -> [f64; 2] {
        let s = sys.particles.iter().fold([0.0, 0.0], |acc, q| {
            let v = f(q);
            [acc[0] + q.m * v[0], acc[1] + q.m * v[1]]
        });
        [s[0] / mass, s[1] / mass]
    };
    // The centre's motion, as the mass-weighted mean of the particles' (the turn adds nothing).
    let centre = [
        mean(&|q| [q.x.x, q.x.y]),
        mean(&|q| [q.v.x, q.v.y]),
        mean(&|q| [q.a.x, q.a.y]),
        mean(&|q| [q.j.x, q.j.y]),
    ];
    for (i, q) in sys.particles.iter().enumerate() {
        let r = [q.x.x - centre[0][0], q.x.y - centre[0][1]];
        let at = rigid_position(D::new(0.0, 1.0, 0.0, 0.0), centre, r, omega, omega_dot);
        // The terms of a derivative are at most the centre's and |r| (1 + |ω| + |ω̇|)³; their
        // rounding is a few ulps of that.
        let size = centre.iter().flatten().map(|x| x.abs()).sum::<f64>()
            + r[0].hypot(r[1]) * (1.0 + omega.abs() + omega_dot.abs()).powi(3);
        let tol = 64.0 * f64::EPSILON * size;
        for (k, d) in at.iter().enumerate() {
            let sample = [[q.v.x, q.v.y][k], [q.a.x, q.a.y][k], [q.j.x, q.j.y][k]];
            let motion = [d.v1, d.v2, d.v3];
            for (order, (s, m)) in sample.iter().zip(motion).enumerate() {
                assert!(
                    (s - m).abs() <= tol,
                    "particle {i}, component {k}, derivative {}: sample {s}, motion {m}, tol {tol}",
                    order + 1
                );
            }
        }
    }
}

/// `RawParticles::draw` gives 1 to 8 particles, each with its values (the mass first, log-uniform
/// over [10⁻³, 10³]) and the point P its own EXTRA, and nothing more.
#[test]
fn raw_particles_draw_gives_each_particle_and_the_point_their_values() {
    use rand::SeedableRng;
    use sliding_ladder::registry::sample::RawParticles;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(222);
    for _ in 0..200 {
        let r = RawParticles::draw(&mut rng);
        assert!((1..=8).contains(&r.n), "{}", r.n);
        assert_eq!(r.values.len(), r.n * PER_PARTICLE + EXTRA);
        for (i, v) in r.values.iter().enumerate() {
            let mass = i < r.n * PER_PARTICLE && i % PER_PARTICLE == 0;
            let range = if mass { 1e-3..=1e3 } else { -10.0..=10.0 };
            assert!(range.contains(v), "value {i} = {v}");
        }
    }
}

/// A float ladder is built from its raw draw as `RawLadder` documents: the three unit-free
/// numbers scale θ̇, θ̈, θ⃛ by the ladder's own rates √(g/l), g/l and (g/l)^{3/2} (times 3).
/// By hand for m = 2, l = 4, g = 9 (√(g/l) = 3/2) and u = (1/2, −1/4, 1): θ̇ = 9/4,
/// θ̈ = −27/16, θ⃛ = 81/8, all exact in binary. From rest, θ̇ is the energy's (10),
/// √((3g/2l)(1 − cos θ)), to a few ulps.
#[test]
fn raw_ladder_build_scales_the_unit_draws_to_the_ladders_rates() {
    use sliding_ladder::registry::sample::{LadderSample, RawLadder};
    let raw = RawLadder {
        theta: 0.7,
        mlg: [2.0, 4.0, 9.0],
        unit: [0.5, -0.25, 1.0],
    };
    let ((l, s), (_, sb)) = raw.build(LadderSample::Kinematic);
    assert_eq!((l.m, l.l, l.g), (2.0, 4.0, 9.0));
    assert_eq!((s.sin, s.cos), 0.7f64.sin_cos());
    assert_eq!((s.rate, s.accel, s.jerk), (2.25, -1.6875, 10.125));
    assert_eq!(sb.rate.v, s.rate);
    let ((_, rest), _) = raw.build(LadderSample::OnShellFromRest);
    let energy = (1.5 * 9.0 / 4.0 * (1.0 - 0.7f64.cos())).sqrt();
    // Each side is a few roundings of a value of size `energy`; 1 − cos θ loses about
    // 1/(1 − cos θ) ≈ 4.3 ulps more on the energy's side.
    assert!(
        (rest.rate - energy).abs() <= 16.0 * f64::EPSILON * energy,
        "{} {energy}",
        rest.rate
    );
    // On the motion θ̈ is (5)'s, (3g/4l) sin θ, whatever the draw.
    let ((_, on), _) = raw.build(LadderSample::OnShell);
    let eq5 = 0.75 * 9.0 / 4.0 * 0.7f64.sin();
    assert!((on.accel - eq5).abs() <= 4.0 * f64::EPSILON * eq5);
}

/// The floor phase's float draws scale as the ladder's do: X by l, Ẋ by l/t, Ẍ by l/t², X⃛ by
/// l/t³ with t = √(l/g), times 3. By hand for l = 4, g = 16 (t = 1/2: scales 4, 8, 16, 32) and
/// u = (1/2, −1/4, 1, −1): X = 6, Ẋ = −6, Ẍ = 48, X⃛ = −96, all exact in binary. A time scale
/// of √(l·g), or a scale divided otherwise, gives other values.
#[test]
fn floor_motion_scales_the_unit_draws_by_the_ladders_length_and_time() {
    use sliding_ladder::registry::sample::floor_motion;
    assert_eq!(
        floor_motion([0.5, -0.25, 1.0, -1.0], 4.0, 16.0),
        [6.0, -6.0, 48.0, -96.0]
    );
    // Another ladder, the same unit draws: l = 1, g = 4 (t = 1/2: scales 1, 2, 4, 8).
    assert_eq!(
        floor_motion([0.5, -0.25, 1.0, -1.0], 1.0, 4.0),
        [1.5, -1.5, 12.0, -24.0]
    );
}

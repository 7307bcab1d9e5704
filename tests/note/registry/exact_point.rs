//! `registry::exact_point`: the random integers of an exact point.

use rand::SeedableRng;
use sliding_ladder::registry::exact_point::{exact_particle_ints, EXACT_HEIGHT};
use sliding_ladder::registry::sample::{EXTRA, PER_PARTICLE};

#[test]
fn exact_particle_ints_draws_every_mass_positive_and_every_value_in_range() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    // Which slots took a negative value: a particle's slot by its place in the block (0 is the
    // mass), P's and the spin's values by their place after the particles.
    let (mut particle_negative, mut extra_negative) = ([false; PER_PARTICLE], [false; EXTRA]);
    let mut systems_of_many = 0;
    for _ in 0..200 {
        let (n, v) = exact_particle_ints(&mut rng);
        assert!((1..=8).contains(&n), "{n} particles");
        assert_eq!(v.len(), n * PER_PARTICLE + EXTRA);
        systems_of_many += usize::from(n > 1);
        for (i, x) in v.iter().enumerate() {
            assert!(x.abs() < EXACT_HEIGHT, "value {i}: {x}");
            if i < n * PER_PARTICLE && i % PER_PARTICLE == 0 {
                // Each particle's mass, the first value of its block, not only the first one's.
                assert!(*x > 0, "mass of particle {}: {x}", i / PER_PARTICLE + 1);
            } else if *x < 0 && i < n * PER_PARTICLE {
                particle_negative[i % PER_PARTICLE] = true;
            } else if *x < 0 {
                extra_negative[i - n * PER_PARTICLE] = true;
            }
        }
    }
    // Every other value is signed, P's first coordinate as much as the rest (a premise the
    // draws added, such as x_P > 0, would weaken every check that reads them); and systems of
    // several particles were drawn.
    assert!(
        particle_negative[1..].iter().all(|&b| b),
        "{particle_negative:?}"
    );
    assert!(extra_negative.iter().all(|&b| b), "{extra_negative:?}");
    assert!(systems_of_many > 0);
}

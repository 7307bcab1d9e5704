//! The samples a fall keeps for its `trajectory` and `forces` outputs, held to a bounded count.
//!
//! Every step offers its end and `SAMPLES_PER_STEP` (4) dense points. A
//! fixed-step run of millions of steps offered them all: campaign seed 1 scene 989 (symplectic
//! Euler, 7.6e6 steps to separation) kept 3.8e7 samples and wrote a 4.2 GB `forces.csv` in 52 s,
//! where the run without that output took 0.28 s. So the trace keeps every `stride`-th offered
//! sample and, when it holds 2 [`TRACE_CAP`], drops every other one and doubles the stride: it
//! ends with between [`TRACE_CAP`] and 2 [`TRACE_CAP`] samples (all of them when fewer were
//! offered), evenly spread over the offered ones, with the first sample of each phase and the
//! last one always kept. The forces are evaluated afterwards, for the kept samples only.
//! (No crate does this streaming thinning; it is a dozen lines.)

use super::floor;
use super::outcome::Sample;
use super::rigid;

use crate::ladder::Ladder;
/// A trace keeps at least this many samples (when offered as many) and fewer than twice it.
pub const TRACE_CAP: usize = 10_000;

/// A trace under construction: the kept samples and how it thins.
#[derive(Debug)]
pub(super) struct Kept {
    samples: Vec<Sample>,
    /// Keep one offered sample in `stride` (a power of two).
    stride: u64,
    /// Samples offered so far.
    offered: u64,
    /// The last sample offered and whether it was kept.
    last: Option<(Sample, bool)>,
}

impl Default for Kept {
    fn default() -> Self {
        Kept {
            samples: Vec::new(),
            stride: 1,
            offered: 0,
            last: None,
        }
    }
}

impl Kept {
    /// Offer one sample of the motion, in time order.
    pub(super) fn offer(&mut self, s: Sample) {
        let first_of_phase = self.last.is_none_or(|(l, _)| l.phase != s.phase);
        let keep = first_of_phase || self.offered % self.stride == 0;
        if keep {
            self.samples.push(s);
        }
        self.offered += 1;
        self.last = Some((s, keep));
        if self.samples.len() >= 2 * TRACE_CAP {
            self.thin();
        }
    }

    /// Drop every other kept sample (never the first of a phase) and double the stride.
    fn thin(&mut self) {
        let mut prev_phase = None;
        let mut k = 0usize;
        self.samples.retain(|s| {
            let keep = k % 2 == 0 || prev_phase != Some(s.phase);
            prev_phase = Some(s.phase);
            k += 1;
            keep
        });
        self.stride *= 2;
    }

    /// The kept samples with the last one offered, and their forces (F_w, F_f) when `forces`
    /// (eqs. (14), (15) on the wall, the floor phase's normal force after it, m g/2 at the foot
    /// once the ladder lies flat, phase 3: `super::impact`), in the ladder's units; returns them
    /// with the force evaluations spent.
    pub(super) fn finish(mut self, ladder: &Ladder<f64>, forces: bool) -> (Vec<Sample>, u64) {
        if let Some((s, false)) = self.last {
            self.samples.push(s);
        }
        let mut evals = 0;
        if forces {
            for s in &mut self.samples {
                s.forces = Some(match s.phase {
                    1 => (
                        rigid::wall_force(ladder, s.theta, s.rate),
                        rigid::floor_force(ladder, s.theta, s.rate),
                    ),
                    2 => (0.0, floor::floor_force(ladder, s.theta, s.rate)),
                    _ => (0.0, super::impact::lying_flat_floor_force(ladder)),
                });
                evals += 2;
            }
        }
        (self.samples, evals)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(phase: u8, t: f64) -> Sample {
        Sample {
            phase,
            t,
            theta: t,
            rate: 0.0,
            centre_x: 0.0,
            forces: None,
        }
    }

    fn kept(phases: &[(u8, usize)]) -> Vec<Sample> {
        let mut k = Kept::default();
        let mut t = 0.0;
        for &(p, n) in phases {
            for _ in 0..n {
                k.offer(sample(p, t));
                t += 1.0;
            }
        }
        let ladder = Ladder {
            m: 1.0,
            l: 1.0,
            g: 1.0,
        };
        k.finish(&ladder, false).0
    }

    /// Fewer than 2 TRACE_CAP offered: every one kept, in order.
    #[test]
    fn a_short_trace_keeps_every_sample() {
        let v = kept(&[(1, 700), (2, 300)]);
        assert_eq!(v.len(), 1000);
        assert!(v.windows(2).all(|w| w[1].t == w[0].t + 1.0));
    }

    /// 1e6 offered over two phases: between TRACE_CAP and 2 TRACE_CAP kept, evenly spaced (no
    /// gap over twice the mean), with the first, the last and each phase's first sample. The
    /// check can fail: without the thinning all 1e6 would be kept.
    #[test]
    fn a_long_trace_is_thinned_evenly_and_keeps_its_ends() {
        let (n1, n2) = (600_001, 399_999);
        let v = kept(&[(1, n1), (2, n2)]);
        assert!((TRACE_CAP..2 * TRACE_CAP).contains(&v.len()), "{}", v.len());
        assert_eq!(v[0].t, 0.0);
        assert_eq!(v[v.len() - 1].t, (n1 + n2 - 1) as f64);
        assert!(v.iter().any(|s| s.t == n1 as f64 && s.phase == 2));
        let mean = (n1 + n2) as f64 / v.len() as f64;
        let widest = v.windows(2).map(|w| w[1].t - w[0].t).fold(0.0, f64::max);
        assert!(
            widest <= 2.0 * mean,
            "gap {widest} against a mean of {mean}"
        );
        assert!(v.windows(2).all(|w| w[1].t > w[0].t));
    }

    /// The forces are evaluated for the kept samples only: two per sample.
    #[test]
    fn forces_are_evaluated_for_kept_samples_only() {
        let mut k = Kept::default();
        for i in 0..100_000 {
            k.offer(sample(1, 1e-6 * i as f64));
        }
        let ladder = Ladder {
            m: 2.0,
            l: 0.5,
            g: 9.81,
        };
        let (v, evals) = k.finish(&ladder, true);
        assert_eq!(evals, 2 * v.len() as u64);
        let s = v[v.len() / 2];
        let want = (
            rigid::wall_force(&ladder, s.theta, s.rate),
            rigid::floor_force(&ladder, s.theta, s.rate),
        );
        assert_eq!(s.forces, Some(want));
    }
}

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
pub struct Kept {
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
    pub fn offer(&mut self, s: Sample) {
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
    pub fn finish(mut self, ladder: &Ladder<f64>, forces: bool) -> (Vec<Sample>, u64) {
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

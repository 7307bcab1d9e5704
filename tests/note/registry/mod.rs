//! `sliding_ladder::registry`: every display's checks at random states, exact points, proofs and units.

mod complete;
mod identities;
mod law;
mod milne;
mod modular;
mod perturbation;
mod prove;
mod units;

//! `sim::near_release`: pushes just below the release push, against mpmath references.

mod pushes;
mod pushes_below;

//! A "method": anything that yields the ladder's equation of motion from its state.

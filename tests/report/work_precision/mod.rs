//! `report::work_precision*`: error against work, the order fits, the figure and the peers.

mod figure;
mod fit;
#[cfg(feature = "peers")]
mod peers;
mod radau5_order;
mod runs;

//! The peers in work-precision (issue 12, item 3; `cargo test --features peers --test
//! work_precision::peers`): ode_solvers' DOP853 and Dopri5 are measured in the same run as this
//! crate's methods, their error falls with the tolerance, and the figure draws them dashed in
//! their partner's colour. Without the feature the peers are absent (tested in
//! `work_precision_figure.rs`).
#![cfg(feature = "peers")]

use sliding_ladder::report::work_precision::fit::Point;
use sliding_ladder::report::work_precision::report::{panel, report};
use sliding_ladder::report::work_precision::{scene_at, Timing, PEERS_OF};

const ONCE: Timing = Timing {
    budget: 0.0,
    min: 1,
    max: 1,
};

#[test]
fn the_peers_run_beside_ours_and_are_drawn_dashed() {
    let rep = report(&scene_at(0.1, 0.0), ONCE, |_| {}).unwrap();
    for (peer, of) in PEERS_OF {
        let runs: Vec<_> = rep.runs.iter().filter(|r| r.method == peer).collect();
        let ours = rep.runs.iter().filter(|r| r.method == of).count();
        assert_eq!(runs.len(), ours, "{peer}: one run per tolerance of {of}");
        // Converging: the error at the tightest tolerance is far below the loosest one's.
        let (first, last) = (runs[0].error(), runs[runs.len() - 1].error());
        assert!(last < 1e-6 * first, "{peer}: {first:e} .. {last:e}");
        assert!(runs.iter().all(|r| r.rhs_evals > 0 && r.seconds > 0.0));
        // Not on the front: their task (θ at the given t_s) is not ours.
        assert!(rep.pareto.iter().all(|r| r.method != peer));
    }
    let (chart, series) = panel(&rep);
    for (peer, of) in PEERS_OF {
        assert!(series.iter().any(|s| s.name == peer));
        assert!(chart.peers.contains(&(peer.to_string(), of.to_string())));
    }
}

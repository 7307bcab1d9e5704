use sliding_ladder::registry::{
    check::{run_check, Config},
    equations,
};
#[test]
fn print_all() {
    let cfg = Config {
        float_cases: 200,
        exact_points: 3,
        seed: 1,
    };
    let t0 = std::time::Instant::now();
    for e in equations() {
        for c in &e.checks {
            let t = std::time::Instant::now();
            let r = run_check(c, &cfg);
            if e.number > 28 {
                println!("({:2}) {:50} pass={} ffail={} max={:.3} worst={} exfail={} mis={:?} deg={} sz={:.1e} off={:?} {:?}", e.number, c.name, r.passed(), r.float_failures, r.max_scaled_residual, r.worst_side, r.exact_failures, r.misprints, r.degree, r.sz_bound, r.off_shell_fails, t.elapsed());
            }
        }
    }
    println!("total {:?}", t0.elapsed());
}

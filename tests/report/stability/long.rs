//! The memory of a scene that asks only for scalars is flat in the number of steps: a counting
//! global allocator records the peak of live heap bytes during `fall::run`.
//!
//! The counts are per thread (the run is single-threaded), so the other tests of this binary,
//! running beside it, do not enter the measurement. 1e3 and 1e5 steps always; 1e7 with
//! `LADDER_SLOW=1` (`LADDER_SLOW=1 cargo test --release --test report stability::long --
//! --nocapture` prints them).

use sliding_ladder::report::stability::long::memory_scene;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::scene::output::Output;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    // Const-initialised cells without destructors: reading them never allocates, as an
    // allocator's own bookkeeping must not.
    static LIVE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let _ = LIVE.try_with(|live| {
                let now = live.get() + layout.size() as isize;
                live.set(now);
                let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
            });
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        let _ = LIVE.try_with(|live| live.set(live.get() - layout.size() as isize));
    }
}

#[global_allocator]
static A: Counting = Counting;

/// Peak live heap bytes of this thread above its level at the start, while `f` runs.
fn peak_during(f: impl FnOnce()) -> usize {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    f();
    (PEAK.with(Cell::get) - base).max(0) as usize
}

/// (steps, peak bytes) of the scalar-only scene run for `seconds` (1e6 steps per second).
fn measure(seconds: f64, trajectory: bool) -> (u64, usize) {
    let mut scene = memory_scene(seconds);
    if trajectory {
        scene.outputs.push(Output::Trajectory);
    }
    let mut steps = 0;
    let peak = peak_during(|| {
        let o = fall::run(&scene, 20_000_000).expect("runs");
        steps = o.work.wall.steps;
    });
    (steps, peak)
}

#[test]
fn scalar_only_memory_is_flat_from_1e3_to_1e5_steps_and_a_trace_is_not() {
    let (n3, p3) = measure(1e-3, false);
    let (n5, p5) = measure(1e-1, false);
    println!("scalar-only scene: {n3} steps peak {p3} B, {n5} steps peak {p5} B");
    assert!(n3 >= 1_000 && n5 >= 100_000, "{n3} {n5}");
    // Model: storing anything per step would add ≥ 8 B × 99 000 steps ≈ 792 kB. Only this
    // thread is counted; 4 kB of slack (its printing, say) is 0.5% of the smallest growth.
    const SLACK: usize = 4096;
    assert!(
        p5 <= p3 + SLACK,
        "peak heap grew with the steps: {p3} B -> {p5} B"
    );
    if std::env::var("LADDER_SLOW").is_ok() {
        let (n7, p7) = measure(10.0, false);
        println!("scalar-only scene: {n7} steps peak {p7} B");
        assert!(n7 >= 10_000_000);
        assert!(
            p7 <= p3 + SLACK,
            "peak heap grew with the steps: {p3} B -> {p7} B"
        );
    }
    // The measurement can fail: a scene that keeps its trajectory grows with the steps.
    let (_, t3) = measure(1e-3, true);
    let (_, t5) = measure(1e-1, true);
    println!("with a trajectory: peak {t3} B at 1e3 steps, {t5} B at 1e5");
    assert!(t5 > t3 + 8 * 99_000, "{t3} {t5}");
}

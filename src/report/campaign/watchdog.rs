//! The campaign's per-scene watchdog: a hung scene is named and the campaign goes on.

/// The campaign's per-scene watchdog: runs each job on a thread of its own and stops waiting
/// for one still running after its time limit, so that a scene that hangs (an endless loop no
/// step count sees, as `sim::minimum::minimum_on` once had at t ≈ 2e15) is counted over budget
/// and named, not a stalled campaign. The job it gave up on is left to finish on its own
/// thread (Rust cannot stop a thread); a new thread takes the next job, and a result that
/// comes late is dropped with the old channel.
pub struct Watchdog<J, R> {
    work: std::sync::Arc<dyn Fn(J) -> R + Send + Sync>,
    jobs: std::sync::mpsc::Sender<J>,
    results: std::sync::mpsc::Receiver<R>,
}

impl<J: Send + 'static, R: Send + 'static> Watchdog<J, R> {
    /// A watchdog over `work`, which should not panic (the campaign catches its panics).
    pub fn new(work: impl Fn(J) -> R + Send + Sync + 'static) -> Self {
        let work: std::sync::Arc<dyn Fn(J) -> R + Send + Sync> = std::sync::Arc::new(work);
        let (jobs, results) = Self::spawn(&work);
        Watchdog {
            work,
            jobs,
            results,
        }
    }

    fn spawn(
        work: &std::sync::Arc<dyn Fn(J) -> R + Send + Sync>,
    ) -> (std::sync::mpsc::Sender<J>, std::sync::mpsc::Receiver<R>) {
        let (jobs, job_rx) = std::sync::mpsc::channel::<J>();
        let (result_tx, results) = std::sync::mpsc::channel();
        let work = work.clone();
        std::thread::spawn(move || {
            for job in job_rx {
                if result_tx.send(work(job)).is_err() {
                    break;
                }
            }
        });
        (jobs, results)
    }

    /// `work(job)`, or `None` if it has not returned within `limit` (or its thread died).
    pub fn run(&mut self, job: J, limit: std::time::Duration) -> Option<R> {
        let answer = match self.jobs.send(job) {
            Ok(()) => self.results.recv_timeout(limit).ok(),
            Err(_) => None,
        };
        if answer.is_none() {
            (self.jobs, self.results) = Self::spawn(&self.work);
        }
        answer
    }
}

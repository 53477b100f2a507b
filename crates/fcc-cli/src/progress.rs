//! Progress for long steps that report nothing themselves (a Verilator
//! build, a Yosys run): a line on stderr when the step starts, one every
//! `every` while it runs, and one with the time taken when it ends.

use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// A running step. Dropping it (or [`Heartbeat::done`]) ends the ticking.
pub struct Heartbeat {
    what: String,
    start: Instant,
    stop: Option<Sender<()>>,
    thread: Option<JoinHandle<()>>,
}

impl Heartbeat {
    /// Say that `what` starts, then say it is still running every 20 s.
    pub fn start(what: &str) -> Heartbeat {
        Self::with(what, Duration::from_secs(20), |line| eprintln!("{line}"))
    }

    /// As [`start`](Self::start), with the interval and the output given.
    pub fn with(what: &str, every: Duration, out: impl Fn(&str) + Send + 'static) -> Heartbeat {
        out(&format!("{what} ..."));
        let (tx, rx) = channel::<()>();
        let start = Instant::now();
        let thread = std::thread::spawn(move || {
            while let Err(RecvTimeoutError::Timeout) = rx.recv_timeout(every) {
                out(&format!(
                    "  ... still running, {:.0} s",
                    start.elapsed().as_secs_f64()
                ));
            }
        });
        Heartbeat {
            what: what.to_string(),
            start,
            stop: Some(tx),
            thread: Some(thread),
        }
    }

    /// Stop ticking and say how long the step took.
    pub fn done(mut self) {
        self.stop_thread();
        eprintln!(
            "{}: done in {:.1} s",
            self.what,
            self.start.elapsed().as_secs_f64()
        );
    }

    fn stop_thread(&mut self) {
        drop(self.stop.take());
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

impl Drop for Heartbeat {
    fn drop(&mut self) {
        self.stop_thread();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    #[test]
    fn a_long_step_reports_while_it_runs_and_stops_when_done() {
        let lines = Arc::new(Mutex::new(Vec::<String>::new()));
        let sink = lines.clone();
        let hb = Heartbeat::with("building", Duration::from_millis(20), move |l| {
            sink.lock().unwrap().push(l.to_string())
        });
        std::thread::sleep(Duration::from_millis(110));
        drop(hb);
        let n = lines.lock().unwrap().len();
        std::thread::sleep(Duration::from_millis(60));
        let got = lines.lock().unwrap().clone();
        assert_eq!(got.len(), n, "ticks after the step ended: {got:?}");
        assert_eq!(got[0], "building ...");
        assert!(got.len() >= 3, "{got:?}");
        assert!(got[1].starts_with("  ... still running"), "{got:?}");
    }
}

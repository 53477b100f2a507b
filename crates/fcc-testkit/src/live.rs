//! `fcc live` children for the tests: started on a port of the system's
//! choice, fed by `fcc replay`, bounded in time and killed when dropped.

use std::io::{BufRead, BufReader, Read};
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

/// No child runs longer than this.
pub const LIMIT: Duration = Duration::from_secs(120);

/// A child that is killed when dropped (a failed assertion included).
pub struct Guard(pub Option<Child>);

impl Drop for Guard {
    fn drop(&mut self) {
        if let Some(c) = &mut self.0 {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

impl Guard {
    /// Wait for the child to end within [`LIMIT`], then kill it; its output.
    pub fn wait(mut self) -> Output {
        let mut c = self.0.take().expect("a child");
        let start = Instant::now();
        // Read both pipes on threads so a full pipe never blocks the child.
        let mut out = c.stdout.take().expect("piped");
        let mut err = c.stderr.take().expect("piped");
        let o = std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = out.read_to_end(&mut v);
            v
        });
        let e = std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = err.read_to_end(&mut v);
            v
        });
        let status = loop {
            if let Some(st) = c.try_wait().expect("wait") {
                break st;
            }
            if start.elapsed() > LIMIT {
                let _ = c.kill();
                break c.wait().expect("wait");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        Output {
            status,
            stdout: o.join().unwrap_or_default(),
            stderr: e.join().unwrap_or_default(),
        }
    }
}

/// Start `exe live ARGS` on a port of the system's choice; the child, the
/// port (read from its `listening on udp ADDR:PORT` line on stderr) and
/// the stderr read so far.
pub fn start_live(exe: &str, args: &[&str]) -> (Guard, u16, Vec<u8>) {
    let mut c = Command::new(exe)
        .arg("live")
        .args(["--udp", "127.0.0.1:0"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start fcc live");
    let mut err = BufReader::new(c.stderr.take().expect("piped"));
    let mut first = Vec::new();
    let port = loop {
        let mut line = String::new();
        let n = err.read_line(&mut line).expect("read stderr");
        first.extend_from_slice(line.as_bytes());
        if n == 0 {
            let _ = c.kill();
            panic!(
                "fcc live ended before listening: {}",
                String::from_utf8_lossy(&first)
            );
        }
        if let Some(addr) = line.strip_prefix("listening on udp ") {
            let port = addr
                .split_whitespace()
                .next()
                .and_then(|a| a.rsplit_once(':'))
                .and_then(|(_, p)| p.parse::<u16>().ok());
            match port {
                Some(p) => break p,
                None => {
                    let _ = c.kill();
                    panic!("no port in `{line}`");
                }
            }
        }
    };
    // Give stderr back to the guard, with what was read past the line.
    first.extend_from_slice(err.buffer());
    c.stderr = Some(err.into_inner());
    (Guard(Some(c)), port, first)
}

/// Replay `capture` (with `replay_args`) to `exe live ARGS` at half the
/// recorded rate (no loss however busy the machine); live's output and its
/// whole stderr.
pub fn live_on_replay(
    exe: &str,
    capture: &Path,
    args: &[&str],
    replay_args: &[&str],
) -> (Output, String) {
    let (live, port, first) = start_live(exe, args);
    let to = format!("127.0.0.1:{port}");
    let mut replay = vec![
        "replay",
        crate::s(capture),
        "--udp",
        to.as_str(),
        "--rate",
        "0.5",
    ];
    replay.extend(replay_args);
    let r = crate::run_in(exe, None, &replay);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let out = live.wait();
    let err = String::from_utf8_lossy(&first).into_owned() + &String::from_utf8_lossy(&out.stderr);
    (out, err)
}

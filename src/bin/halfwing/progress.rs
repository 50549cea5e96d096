//! A line on stderr when a step takes more than a second.

use std::sync::mpsc::{Sender, channel};
use std::time::Duration;

/// Prints `halfwing: MESSAGE...` unless dropped within a second.
pub struct Progress {
    done: Option<Sender<()>>,
}

impl Progress {
    pub fn start(message: String) -> Self {
        let (done, finished) = channel::<()>();
        std::thread::spawn(move || {
            if finished.recv_timeout(Duration::from_secs(1)).is_err() {
                eprintln!("halfwing: {message}...");
            }
        });
        Progress { done: Some(done) }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(done) = self.done.take() {
            let _ = done.send(());
        }
    }
}

//! Progress on stderr for long runs: shown only once a run has lasted [`PROGRESS_AFTER`], and
//! only when stderr is a terminal (a log file or a pipe gets no escape sequences).

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// A run shorter than this shows no progress.
const PROGRESS_AFTER: Duration = Duration::from_secs(1);

/// A progress indicator that appears late, if at all, and is cleared at the end.
pub(crate) struct Progress {
    start: Instant,
    terminal: bool,
    bar: Option<ProgressBar>,
}

impl Progress {
    /// Starts the clock.
    pub(crate) fn new() -> Self {
        Self {
            start: Instant::now(),
            terminal: std::io::stderr().is_terminal(),
            bar: None,
        }
    }

    /// Whether stderr is a terminal (if not, nothing is ever shown).
    pub(crate) fn is_terminal(&self) -> bool {
        self.terminal
    }

    /// The indicator to update: made by `make`, from the time elapsed since the start, once the
    /// run has lasted [`PROGRESS_AFTER`]; `None` before then, and when stderr is no terminal.
    pub(crate) fn bar(
        &mut self,
        make: impl FnOnce(Duration) -> ProgressBar,
    ) -> Option<&ProgressBar> {
        if !self.terminal {
            return None;
        }
        if self.bar.is_none() && self.start.elapsed() >= PROGRESS_AFTER {
            self.bar = Some(make(self.start.elapsed()));
        }
        self.bar.as_ref()
    }

    /// Clears the indicator, if it was shown.
    pub(crate) fn finish(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

/// `bar` drawn with `template` (indicatif's syntax; a template it refuses leaves its default).
pub(crate) fn styled(bar: ProgressBar, template: &str) -> ProgressBar {
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    bar
}

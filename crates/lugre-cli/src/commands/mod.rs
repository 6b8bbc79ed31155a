//! The commands, one module each. A command uses the shared flags (`args`), files and streams
//! (`io`), figures (`plot`) and formatting (`fmt`, `numbers`, `hysteresis`), never another
//! command: what two commands share lives in one of those.

pub mod cycles;
pub mod fit;
pub mod loops;
pub mod paper;
pub mod simulate;

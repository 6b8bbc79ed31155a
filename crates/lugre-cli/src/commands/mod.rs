//! The commands, one module each. A command uses the shared flags (`args`), files and streams
//! (`io`), figures (`plot`) and formatting (`fmt`, `numbers`, `hysteresis`), never another
//! command: what two commands share lives in one of those.

pub(crate) mod cycles;
pub(crate) mod dynamics;
pub(crate) mod fit;
pub(crate) mod loops;
pub(crate) mod paper;
pub(crate) mod simulate;
pub(crate) mod sweep;

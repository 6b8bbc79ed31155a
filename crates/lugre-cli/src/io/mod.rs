//! Files and streams: CSV out (data files are read by `lugre-io`), the JSON writer, atomic files, the spool, and progress on
//! stderr.

pub(crate) mod atomic;
pub(crate) mod csv;
pub(crate) mod json;
pub(crate) mod progress;
pub(crate) mod spool;

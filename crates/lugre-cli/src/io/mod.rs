//! Files and streams: CSV in and out, the JSON writer, atomic files, the spool, and progress on
//! stderr.

pub mod atomic;
pub mod csv;
pub mod json;
pub mod progress;
pub mod spool;

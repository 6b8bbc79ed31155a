//! Files and streams: the CSV reader, the JSON writer, atomic files and the spool.

pub mod atomic;
pub mod csv;
pub mod json;
pub mod spool;

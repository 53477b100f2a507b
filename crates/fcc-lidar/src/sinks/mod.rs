//! Writers of clustered frames in the formats viewers already open: one
//! file per format, used by `fcc cluster` and `fcc live` alike.

mod cdr;
pub mod mcap;

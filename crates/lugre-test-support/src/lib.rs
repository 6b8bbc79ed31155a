//! What lugre's test suites share and the library does not export: the tolerances every
//! comparison uses ([`prec`], one place for all of them), reference forms written
//! independently of the library's kernel ([`mod@reference`]), and the module graph the layout
//! tests check ([`layout`]).
//!
//! A dev-dependency only (`publish = false`); it depends on nothing, so the core's own unit
//! tests can use it too.

pub mod layout;
pub mod prec;
pub mod reference;
pub mod timing;

//! Window-system bindings: how a context gets a drawable and how the drawable is shown.
//! OSMesa renders into the caller's memory; GLX (later) into X windows.

pub mod osmesa;

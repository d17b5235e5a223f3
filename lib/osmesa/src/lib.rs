#![allow(non_snake_case)] // the crate is named after the library file (libOSMesa.so / libGL.so)
//! libOSMesa.so.8: the tessera engine under Mesa's off-screen library name and soname.
//!
//! Every entry point (gl*, OSMesa*, glX*) is defined in the `tessera` crate; linking it here
//! makes the cdylib export them. Both drop-in libraries export the full set, so a process that
//! loads both resolves every call to whichever was loaded first and sees one consistent state.
pub use tessera;

//! The hard-case suite: numerically hard inputs with analytic expectations, run through the
//! whole draw path in every accuracy mode.

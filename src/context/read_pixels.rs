//! glReadPixels.

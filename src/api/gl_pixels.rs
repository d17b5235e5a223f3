//! Entry points for glReadPixels and glPixelStore.

//! GL pixel transfer: the client-side formats and types of glReadPixels (and later
//! glDrawPixels/glTexImage), and packing rows of framebuffer values into client memory
//! with the glPixelStore layout rules.

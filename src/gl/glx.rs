//! The constants of `<GL/glx.h>` and its extensions that tessera implements: framebuffer
//! configuration attributes and their values, glXQueryContext/glXQueryDrawable keys,
//! glXCreateContextAttribsARB keys and bits, glXGetConfig's return codes and the GLX error
//! codes the X server numbers from the extension's first error.
use std::ffi::c_int;

// Framebuffer configuration attributes and values.
pub const GLX_USE_GL: i32 = 1;
pub const GLX_BUFFER_SIZE: i32 = 2;
pub const GLX_LEVEL: i32 = 3;
pub const GLX_RGBA: i32 = 4;
pub const GLX_DOUBLEBUFFER: i32 = 5;
pub const GLX_STEREO: i32 = 6;
pub const GLX_AUX_BUFFERS: i32 = 7;
pub const GLX_RED_SIZE: i32 = 8;
pub const GLX_GREEN_SIZE: i32 = 9;
pub const GLX_BLUE_SIZE: i32 = 10;
pub const GLX_ALPHA_SIZE: i32 = 11;
pub const GLX_DEPTH_SIZE: i32 = 12;
pub const GLX_STENCIL_SIZE: i32 = 13;
pub const GLX_ACCUM_RED_SIZE: i32 = 14;
pub const GLX_ACCUM_GREEN_SIZE: i32 = 15;
pub const GLX_ACCUM_BLUE_SIZE: i32 = 16;
pub const GLX_ACCUM_ALPHA_SIZE: i32 = 17;
pub const GLX_CONFIG_CAVEAT: i32 = 0x20;
pub const GLX_X_VISUAL_TYPE: i32 = 0x22;
pub const GLX_TRANSPARENT_TYPE: i32 = 0x23;
pub const GLX_TRANSPARENT_INDEX_VALUE: i32 = 0x24;
pub const GLX_TRANSPARENT_RED_VALUE: i32 = 0x25;
pub const GLX_TRANSPARENT_GREEN_VALUE: i32 = 0x26;
pub const GLX_TRANSPARENT_BLUE_VALUE: i32 = 0x27;
pub const GLX_TRANSPARENT_ALPHA_VALUE: i32 = 0x28;
pub const GLX_DONT_CARE: i32 = -1;
pub const GLX_NONE: i32 = 0x8000;
pub const GLX_TRUE_COLOR: i32 = 0x8002;
pub const GLX_DIRECT_COLOR: i32 = 0x8003;
pub const GLX_VISUAL_ID: i32 = 0x800B;
pub const GLX_SCREEN: i32 = 0x800C;
pub const GLX_DRAWABLE_TYPE: i32 = 0x8010;
pub const GLX_RENDER_TYPE: i32 = 0x8011;
pub const GLX_X_RENDERABLE: i32 = 0x8012;
pub const GLX_FBCONFIG_ID: i32 = 0x8013;
pub const GLX_RGBA_TYPE: i32 = 0x8014;
pub const GLX_MAX_PBUFFER_WIDTH: i32 = 0x8016;
pub const GLX_MAX_PBUFFER_HEIGHT: i32 = 0x8017;
pub const GLX_MAX_PBUFFER_PIXELS: i32 = 0x8018;
pub const GLX_WINDOW_BIT: i32 = 1;
pub const GLX_PIXMAP_BIT: i32 = 2;
pub const GLX_PBUFFER_BIT: i32 = 4;
pub const GLX_RGBA_BIT: i32 = 1;
pub const GLX_SAMPLE_BUFFERS: i32 = 100000;
pub const GLX_SAMPLES: i32 = 100001;
pub const GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB: i32 = 0x20B2;
pub const GLX_SWAP_METHOD_OML: i32 = 0x8060;
pub const GLX_SWAP_COPY_OML: i32 = 0x8062;

// Return codes, query keys and glXCreateContextAttribsARB keys.
pub const GLX_BAD_ATTRIBUTE: c_int = 2;
pub const GLX_BAD_VISUAL: c_int = 4;
pub const GLX_BAD_CONTEXT: c_int = 5;
pub const GLX_VENDOR: c_int = 1;
pub const GLX_VERSION: c_int = 2;
pub const GLX_EXTENSIONS: c_int = 3;
pub const GLX_WIDTH: c_int = 0x801D;
pub const GLX_HEIGHT: c_int = 0x801E;
pub const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
pub const GLX_LARGEST_PBUFFER: c_int = 0x801C;
pub const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
pub const GLX_PBUFFER_WIDTH: c_int = 0x8041;
pub const GLX_SHARE_CONTEXT_EXT: c_int = 0x800A;
pub const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
pub const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;
pub const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
pub const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
pub const GLX_CONTEXT_FLAGS_ARB: c_int = 0x2094;
pub const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
pub const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 1;
pub const GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB: c_int = 2;
pub const GLX_CONTEXT_DEBUG_BIT_ARB: c_int = 1;
pub const GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB: c_int = 2;
pub const GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB: c_int = 4;
pub const GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB: c_int = 0x8256;
pub const GLX_NO_RESET_NOTIFICATION_ARB: c_int = 0x8261;
pub const GLX_COLOR_INDEX_TYPE: c_int = 0x8015;
/// GLXBadProfileARB (glxproto.h), a GLX error code.
pub const GLX_BAD_PROFILE_ARB: u8 = 13;

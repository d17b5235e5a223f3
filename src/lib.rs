//! tessera: a software OpenGL implementation that programs use without recompiling, shipped
//! as drop-in `libOSMesa.so.8` and `libGL.so.1` (see the README).
//!
//! The folders are the GL pipeline, and data flows one way, top to bottom. A room imports
//! only itself and the rooms below it (`tests/rooms.rs` checks it in CI); every room but the
//! FFI edge (`api`, `winsys`) denies unsafe code, and in the engine only the wrapper around
//! caller-owned pixel memory (`framebuffer/external.rs`) and the calls of code compiled per
//! SIMD level (`simd/dispatch.rs`) may use it.
//!
//! ```text
//! api          extern "C": gl*, OSMesa*, glX*; caller memory in one module (api/caller_memory.rs)
//! winsys       OSMesa buffers, GLX drawables on a run-time loaded Xlib, refusal notices
//! context      the GL state machine: typed state, errors, objects, attrib stacks, glGet*;
//!              at a draw: validate, snapshot, hand over (context/draw.rs), flush the scene
//! vertex       vertices → primitives: transform and lighting (transform.rs, lighting.rs),
//!              texgen, clipping (clip.rs), viewport (viewport.rs), culling (cull.rs),
//!              polygon offset (offset.rs), polygon modes (outline.rs), lines and stipple
//!              (line.rs), points (point.rs)
//! setup        window-space primitives → jobs: fixed-point edges (triangle.rs, line.rs),
//!              attribute planes (plane.rs), the scene and its per-tile bins (scene.rs)
//! raster       tile workers on the shared pool (mod.rs), coverage walking into spans (walk.rs)
//! fragment     a covered span → the framebuffer, GL's stage order written once (pipeline.rs):
//!              scissor, alpha (alpha.rs), stencil (stencil.rs), depth (mod.rs), fog (fog.rs),
//!              blending (blend.rs), logic op, dither, write masks (output.rs), multisample
//! glsl         the GLSL 1.10/1.20 front end: preprocessor, lexer, parser (semantic analysis
//!              and lowering onto the shading IR next)
//! shader       programs: the shading IR (ir.rs), its validator, text dump and the
//!              16-lane executor (exec.rs) with tessera's own exp2/log2/sin/cos (math.rs)
//! texture      texture storage, sampling (sampler.rs) and the texture environments (env.rs)
//! pixel        GL pixel transfer: client formats and types, pack and unpack
//! framebuffer  buffers and pixel formats, the only code that touches raw pixel memory
//! simd         the instruction-set level (SSE2, SSE4.1, AVX2; TESSERA_SIMD) and per_level!,
//!              which compiles a hot block once per level and runs the CPU's copy (dispatch.rs)
//! pool         the worker threads every scene shares, spawned once and parked between scenes
//! gl           the GL vocabulary: enums, C types, limits, OSMesa/GLX constants, small value types
//! ```
//!
//! See `../shared/DESIGN.md` and the README for the rules that make it fast and exact.
//! `shader` gains the fixed-function generators and the GLSL front end next.

pub mod api;
pub mod context;
pub mod fragment;
pub mod framebuffer;
pub mod gl;
pub mod glsl;
pub mod pixel;
pub mod pool;
pub mod raster;
pub mod setup;
pub mod shader;
pub mod simd;
pub mod texture;
pub mod vertex;
pub mod winsys;

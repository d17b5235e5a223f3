//! The GL state machine: typed state, the sticky error flag, attribute stacks, glGet*, and the
//! binding to a drawable.
//!
//! Every GL command arrives here already translated to Rust values by `api`; the methods in
//! this module and its children validate arguments exactly as the GL 2.1 compatibility
//! specification says, record the specified error and change nothing when invalid, and
//! otherwise change state or hand work to the framebuffer.
//!
//! Drawing is not done here: at a draw, `draw` validates, compiles the fragment state,
//! snapshots the state vertex processing reads into typed inputs and hands the vertices to
//! `crate::vertex`, which owns transformation, lighting, clipping, primitive setup and the
//! viewport transform; this module keeps the pending scene and renders it at flush points.

#![deny(unsafe_code)]

pub mod accum;
pub mod attrib;
pub mod buffers;
pub mod builtin_uniforms;
pub mod capabilities;
pub mod current;
pub mod debug;
pub mod draw;
pub mod evaluators;
pub mod fragment_state;
pub mod framebuffer_object;
pub mod get;
#[cfg(test)]
mod hard_case_tests;
pub mod hints;
pub mod lighting;
pub mod lists;
pub mod matrix;
pub mod multisample;
pub mod pixel_buffers;
pub mod pixel_rect;
pub mod programs;
pub mod queries;
pub mod raster_pos;
pub mod raster_state;
pub mod read_pixels;
pub mod selection;
pub mod shader_objects;
pub mod share;
pub mod state;
pub mod strings;
pub mod texture;
pub mod texture_env;
pub mod transform;
pub mod vertex_input;
#[cfg(test)]
mod watertight_tests;

use crate::framebuffer::{Drawable, Framebuffer, FramebufferConfig};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use state::{PixelStoreState, State};
use std::sync::{Arc, Mutex};

/// What the window system asked for when the context was created.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContextConfig {
    /// The layers of the drawables this context renders to.
    pub visual: FramebufferConfig,
}

/// One GL context.
pub struct Context {
    pub state: State,
    pub pixel_store: PixelStoreState,
    /// The matrix stacks (not part of any attribute group).
    pub matrices: matrix::MatrixStacks,
    config: ContextConfig,
    error: GLenum,
    attrib_stack: Vec<attrib::SavedAttribs>,
    client_attrib_stack: Vec<attrib::SavedClientAttribs>,
    /// Between glBegin and glEnd, where most commands are GL_INVALID_OPERATION.
    pub inside_begin_end: bool,
    /// The materials of glBegin once a glMaterial between glBegin and glEnd changed them:
    /// what a GLSL shader's gl_FrontMaterial and gl_BackMaterial read until glEnd's draw is
    /// made (per-vertex materials are fixed-function lighting's alone, as in Mesa).
    pub(crate) begin_materials: Option<[crate::vertex::lighting::Material; 2]>,
    drawable: Option<Arc<Mutex<Drawable>>>,
    /// The drawable pixels are read from (glReadPixels, glCopyPixels, glCopyTexImage) when
    /// it is not the draw drawable (glXMakeContextCurrent with a separate read drawable).
    read_drawable: Option<Arc<Mutex<Drawable>>>,
    /// Primitives recorded since the last flush point.
    scene: Option<crate::setup::Scene>,
    /// The last rendered scene, emptied: the next scene records into its storage.
    spare_scene: Option<crate::setup::Scene>,
    /// Whether the pending scene starts with a clear of every pixel and channel of the
    /// front-left color: then what it draws does not depend on the image before it
    /// (`draw::Context::flush_for_presentation`).
    scene_overwrites_front: bool,
    /// The window's shape and samples while a scene renders on another thread during a long
    /// draw (`draw::Context::record_in_segments`): what the draw's recording asks of the
    /// window, without waiting for the drawable's lock.
    window_pinned: Option<((usize, usize, FramebufferConfig), usize)>,
    /// A clear of every depth and stencil value of the window's framebuffer that no draw
    /// has needed yet (`draw::Context::carry_clear`): kept out of the scenes until a draw
    /// tests depth or stencil, or something reads the buffer.
    carried_clear: Option<crate::setup::jobs::clear::ClearJob>,
    /// Viewport and scissor are initialised to the drawable's size at the first bind only.
    bound_once: bool,
    /// Immediate mode and client vertex arrays (`vertex_input`).
    pub vertex_input: vertex_input::VertexInput,
    /// The buffer objects (one table, so that it can become shared between contexts).
    pub buffers: share::Shared<crate::vertex::buffer_objects::BufferTable>,
    /// The accuracy mode of the draws (`TESSERA_ACCURACY` at creation, `tesseraSetAccuracy`).
    pub accuracy: crate::setup::accuracy::Accuracy,
    /// The texture objects (`texture`).
    pub textures: share::Shared<texture::TextureTable>,
    /// The compiled fixed-function programs (`programs`), shared like the textures.
    pub programs: share::Shared<programs::ProgramCaches>,
    /// Display lists: the (shareable) name space and the list being compiled.
    pub lists: lists::ListState,
    /// Occlusion queries.
    pub queries: queries::QueryState,
    /// The render mode and selection state.
    pub selection: selection::Selection,
    /// The evaluator maps (glMap1/glMap2).
    pub evaluators: evaluators::EvalMaps,
    /// Framebuffer and renderbuffer objects and their bindings.
    pub fbo: framebuffer_object::FramebufferObjects,
    /// GLSL shader and program objects, shared like the textures.
    pub shader_objects: share::Shared<shader_objects::ShaderObjects>,
    /// The GLSL program in use (glUseProgram), or none.
    pub program_in_use: shader_objects::ProgramInUse,
    /// The per-vertex stage's buffers, kept between draws: the recording thread's and the
    /// helper's of a draw split in two (`draw::Context::draw_part`).
    vertex_scratch: [crate::vertex::transform::VertexScratch; 2],
    /// The last draw's per-vertex stage, reused by the next draw with the same unlit
    /// transform state (`draw::Context::draw_part`).
    stage_cache: Option<Box<crate::vertex::transform::StageCache>>,
}

impl Context {
    pub fn new(config: ContextConfig) -> Context {
        debug::print_config_once();
        let buffer = if config.visual.double_buffered { GL_BACK } else { GL_FRONT };
        Context {
            state: State::new(buffer),
            pixel_store: PixelStoreState::default(),
            matrices: matrix::MatrixStacks::default(),
            config,
            error: GL_NO_ERROR,
            attrib_stack: Vec::new(),
            client_attrib_stack: Vec::new(),
            inside_begin_end: false,
            begin_materials: None,
            drawable: None,
            read_drawable: None,
            scene: None,
            spare_scene: None,
            carried_clear: None,
            scene_overwrites_front: false,
            window_pinned: None,
            bound_once: false,
            vertex_input: vertex_input::VertexInput::default(),
            buffers: Default::default(),
            accuracy: crate::setup::accuracy::Accuracy::from_env(),
            textures: share::Shared::new(texture::TextureTable::new()),
            programs: Default::default(),
            lists: Default::default(),
            queries: Default::default(),
            selection: Default::default(),
            evaluators: Default::default(),
            fbo: framebuffer_object::FramebufferObjects::new(buffer),
            shader_objects: Default::default(),
            program_in_use: Default::default(),
            vertex_scratch: Default::default(),
            stage_cache: None,
        }
    }

    pub fn config(&self) -> &ContextConfig {
        &self.config
    }

    /// Records `error` unless an earlier error is still unread (GL's sticky error flag).
    pub fn error(&mut self, error: GLenum) {
        if self.error == GL_NO_ERROR {
            self.error = error;
        }
    }

    /// glGetError: returns and clears the recorded error.
    pub fn take_error(&mut self) -> GLenum {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    /// For commands that are illegal between glBegin and glEnd: records
    /// GL_INVALID_OPERATION and returns false when inside.
    pub fn check_outside_begin_end(&mut self) -> bool {
        if self.inside_begin_end {
            self.error(GL_INVALID_OPERATION);
            false
        } else {
            true
        }
    }

    /// Binds the drawable this context renders to (None: unbind). At the first bind the
    /// viewport and scissor box become the drawable's size.
    pub fn bind_drawable(&mut self, drawable: Option<Arc<Mutex<Drawable>>>) {
        let same = match (&drawable, &self.drawable) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            _ => false,
        };
        if !same {
            // What was recorded belongs to the old drawable.
            self.flush_rendering();
        }
        if let Some(d) = &drawable {
            self.config.visual = *d.lock().unwrap_or_else(|p| p.into_inner()).framebuffer.config();
            if !self.bound_once {
                let guard = d.lock().unwrap_or_else(|p| p.into_inner());
                let (w, h) = (guard.framebuffer.width() as i32, guard.framebuffer.height() as i32);
                drop(guard);
                self.state.viewport.rect = [0, 0, w, h];
                self.state.scissor.rect = [0, 0, w, h];
                self.bound_once = true;
            }
        }
        self.drawable = drawable;
        self.read_drawable = None;
    }

    /// Binds the drawable pixels are read from, after `bind_drawable` (None or the draw
    /// drawable itself: reads come from the draw drawable). GLX requires it to have the
    /// context's configuration, so it has the same layers as the draw drawable.
    pub fn bind_read_drawable(&mut self, read: Option<Arc<Mutex<Drawable>>>) {
        let separate = match (&read, &self.drawable) {
            (Some(r), Some(d)) => !Arc::ptr_eq(r, d),
            (r, _) => r.is_some(),
        };
        self.read_drawable = if separate { read } else { None };
    }
    pub fn drawable(&self) -> Option<&Arc<Mutex<Drawable>>> {
        self.drawable.as_ref()
    }

    /// Runs `f` on the window's framebuffer; `None` when no drawable is bound. (Draws and
    /// reads go through `with_framebuffer`/`with_read_framebuffer`, which pick the bound
    /// framebuffer object instead when there is one.)
    pub fn with_window_framebuffer<R>(&self, f: impl FnOnce(&mut Framebuffer) -> R) -> Option<R> {
        let drawable = self.drawable.as_ref()?;
        let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
        Some(f(guard.framebuffer_to_read()))
    }

    /// The size and layers of the window's framebuffer (`read`: the one pixels are read
    /// from); `None` when no drawable is bound.
    pub fn window_shape(&self, read: bool) -> Option<(usize, usize, FramebufferConfig)> {
        if let Some((shape, _)) = self.window_pinned.filter(|_| !read || self.read_drawable.is_none()) {
            return Some(shape);
        }
        let drawable =
            if read { self.read_drawable.as_ref().or(self.drawable.as_ref()) } else { self.drawable.as_ref() };
        let guard = drawable?.lock().unwrap_or_else(|p| p.into_inner());
        Some((guard.framebuffer.width(), guard.framebuffer.height(), *guard.framebuffer.config()))
    }

    /// As `with_window_framebuffer`, for drawing: the drawable's next presentation shows
    /// what `f` drew (an OSMesa buffer is written only when something was drawn).
    pub fn draw_into_window_framebuffer<R>(&self, f: impl FnOnce(&mut Framebuffer) -> R) -> Option<R> {
        let drawable = self.drawable.as_ref()?;
        let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
        Some(f(guard.framebuffer_to_draw()))
    }

    /// Runs `f` on the window-system framebuffer pixels are read from: the read drawable's
    /// when one is bound apart from the draw drawable, else the draw drawable's; `None` without either.
    /// Rendering recorded for the draw drawable must have been flushed by the caller.
    pub fn with_window_read_framebuffer<R>(&self, f: impl FnOnce(&mut Framebuffer) -> R) -> Option<R> {
        let drawable = self.read_drawable.as_ref().or(self.drawable.as_ref())?;
        let mut guard = drawable.lock().unwrap_or_else(|p| p.into_inner());
        Some(f(guard.framebuffer_to_read()))
    }

    /// glFlush: completes pending rendering and presents the drawable (rendering in place
    /// into the memory it is presented in where the drawable allows, see
    /// [`Drawable::render_for_presentation`]).
    pub fn flush(&mut self) {
        self.flush_for_presentation();
        if let Some(drawable) = &self.drawable {
            drawable.lock().unwrap_or_else(|p| p.into_inner()).present();
        }
    }

    /// A context bound to a fresh `width` × `height` drawable of `visual` (for tests).
    #[cfg(test)]
    pub(crate) fn with_test_drawable(
        visual: FramebufferConfig,
        width: usize,
        height: usize,
    ) -> (Context, Arc<Mutex<Drawable>>) {
        let framebuffer = Framebuffer::new(visual, width, height).expect("test framebuffer");
        let drawable = Arc::new(Mutex::new(Drawable::new(framebuffer, None)));
        let mut ctx = Context::new(ContextConfig { visual });
        ctx.bind_drawable(Some(drawable.clone()));
        (ctx, drawable)
    }

    /// glFinish: as glFlush, and returns only when rendering is complete.
    pub fn finish(&mut self) {
        self.flush();
    }
}

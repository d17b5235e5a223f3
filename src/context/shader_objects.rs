//! GLSL shader and program objects (GL 2.1 section 2.15): their one name space, shared by a
//! share group; source, compile status and info logs; attachment; link and validate status;
//! the program each context uses; and GL's deferred deletion.
//!
//! Shaders and programs are one [`NameTable`] of [`Object`]s, because GL gives them one name
//! space: a program's name passed where a shader is expected is GL_INVALID_OPERATION, a name
//! that is neither GL_INVALID_VALUE ([`ShaderObjects::shader`], [`ShaderObjects::program`]).
//!
//! Deletion is deferred as GL 2.1 section 2.15.1 says: a shader attached to a program is only
//! flagged (GL_DELETE_STATUS) and goes when its last program lets go of it; a program current
//! in some context is flagged and goes when the last context stops using it, detaching (and
//! so perhaps deleting) its shaders. A context's use is a [`ProgramInUse`], which also keeps
//! the executable of the link that was current at glUseProgram time (a failed relink keeps
//! the last good one in use) and lets go of the program when the context is destroyed.
//!
//! Compiling runs the GLSL front end (`crate::glsl`) over the source; its info log is worded
//! like Mesa's (recursion within a shader included). Linking (`crate::glsl::link`) makes the
//! program interface: active uniforms and attributes, locations, and the layout of the
//! uniform values each program keeps (reset by each link; set by glUniform*), then lowers
//! each stage onto the shading IR ([`crate::glsl::lower`]) and places the varyings
//! ([`crate::glsl::varyings`]): the [`Executable`] the draws run.
use super::builtin_uniforms::BuiltinUniform;
use super::share::Shared;
use super::Context;
use crate::gl::enums::*;
use crate::gl::names::NameTable;
use crate::gl::types::*;
use crate::glsl::link::{self, Linked};
use crate::glsl::lower::{lower, Lowered};
use crate::glsl::varyings::{self, VaryingLayout};
use crate::glsl::{Checked, Stage};
use crate::shader::fast::Compiled;
use crate::shader::validate::validate;
use std::sync::Arc;

/// The largest generic vertex attribute index plus one (GL_MAX_VERTEX_ATTRIBS, as Mesa's 16).
pub const MAX_VERTEX_ATTRIBS: u32 = 16;

/// The stage of a glCreateShader type.
fn stage_of(kind: GLenum) -> Option<Stage> {
    match kind {
        GL_VERTEX_SHADER => Some(Stage::Vertex),
        GL_FRAGMENT_SHADER => Some(Stage::Fragment),
        _ => None,
    }
}

/// GL_SHADER_TYPE of a stage.
fn shader_type(stage: Stage) -> GLenum {
    match stage {
        Stage::Vertex => GL_VERTEX_SHADER,
        Stage::Fragment => GL_FRAGMENT_SHADER,
    }
}

/// A shader object.
#[derive(Debug)]
pub struct Shader {
    stage: Stage,
    /// The source of the last glShaderSource, its pieces joined (`None`: never given).
    source: Option<String>,
    compiled: bool,
    /// The checked program of the last successful compile (what glLinkProgram links).
    checked: Option<Arc<Checked>>,
    info_log: String,
    /// glDeleteShader while attached: deleted when the last program detaches it.
    delete_pending: bool,
    /// How many programs it is attached to.
    attachments: u32,
}

/// What a successful link made: the executable a context runs while the program is in use.
#[derive(Debug, Default)]
pub struct Executable {
    /// The stages the program replaces (a missing one stays fixed-function, as GL 2.1 says).
    pub vertex: bool,
    pub fragment: bool,
    /// The program interface: the linked shaders, active uniforms (their locations and the
    /// layout of their values in [`Program`]'s value words) and attributes.
    pub interface: Arc<Linked>,
    /// The vertex and fragment stages lowered onto the shading IR and compiled (`None` for a
    /// fixed-function stage).
    pub vertex_program: Option<Arc<StageProgram>>,
    pub fragment_program: Option<Arc<StageProgram>>,
    /// Where the varyings travel between the stages.
    pub varyings: VaryingLayout,
    /// Each sampler the stages read: the index of its value (the texture unit) among the
    /// program's uniform words and the target it reads, for the draws' validation
    /// ([`sampler_unit_conflict`]).
    pub sampler_slots: Vec<(usize, usize)>,
}

/// One stage of a linked program: its lowering (the program and what its uniform, input,
/// output and sampler slots are, by GL name), the compiled form the draws run, and where
/// each uniform word's value comes from (resolved once, at link).
#[derive(Debug)]
pub struct StageProgram {
    pub lowered: Lowered,
    pub compiled: Compiled,
    pub uniform_sources: Vec<UniformSource>,
}

/// Where a program's uniform word comes from at a draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum UniformSource {
    /// Built-in state (GLSL 1.20 section 7.5).
    Builtin(BuiltinUniform),
    /// The program's uniform values, at this word.
    Value(usize),
    /// Nothing GL names (0).
    Zero,
}

impl Context {
    /// The uniform words of `stage` at a draw in the current state: built-in state through
    /// one [`BuiltinValues`](super::builtin_uniforms::BuiltinValues) (shared matrices
    /// computed once), the program's own values from its uniform storage.
    pub fn stage_uniforms(&self, stage: &StageProgram) -> Vec<u32> {
        let builtins = self.builtin_values();
        let needs_values = stage.uniform_sources.iter().any(|s| matches!(s, UniformSource::Value(_)));
        let values = if needs_values { self.program_in_use.uniform_values().unwrap_or_default() } else { Vec::new() };
        stage
            .uniform_sources
            .iter()
            .map(|source| match source {
                UniformSource::Builtin(b) => builtins.word(b),
                UniformSource::Value(i) => values.get(*i).copied().unwrap_or(0),
                UniformSource::Zero => 0,
            })
            .collect()
    }
}

impl Executable {
    /// Lowers and compiles the stages of a successful link and places its varyings; an
    /// error is the link's info log.
    pub fn new(linked: Linked) -> Result<Executable, String> {
        let stage = |stage: Stage| -> Result<Option<Arc<StageProgram>>, String> {
            let units: Vec<&Checked> = linked.shaders.iter().filter(|s| s.stage == stage).map(|s| s.as_ref()).collect();
            if units.is_empty() {
                return Ok(None);
            }
            let lowered = lower(&units).map_err(|e| format!("error: {e}\n"))?;
            // GL 2.0 section 2.15.3: a stage may use no more samplers than it has image
            // units (Mesa's linker says it in these words).
            let (name, units_of_stage) = match stage {
                Stage::Vertex => ("vertex", crate::glsl::Limits::TESSERA.max_vertex_texture_image_units),
                Stage::Fragment => ("fragment", crate::glsl::Limits::TESSERA.max_texture_image_units),
            };
            if lowered.samplers.len() > units_of_stage as usize {
                return Err(format!("error: Too many {name} shader texture samplers\n"));
            }
            validate(&lowered.program).map_err(|e| format!("error: internal: invalid program: {e:?}\n"))?;
            super::programs::print_linked(stage, &lowered.program);
            let compiled = Compiled::new(&lowered.program);
            let uniform_sources = lowered
                .uniforms
                .iter()
                .map(|w| {
                    if let Some(b) = BuiltinUniform::resolve(&w.name, w.index) {
                        UniformSource::Builtin(b)
                    } else if let Some((_, first)) = linked.element(&w.name) {
                        UniformSource::Value(first + w.index as usize)
                    } else {
                        UniformSource::Zero
                    }
                })
                .collect();
            Ok(Some(Arc::new(StageProgram { lowered, compiled, uniform_sources })))
        };
        let vertex_program = stage(Stage::Vertex)?;
        let fragment_program = stage(Stage::Fragment)?;
        let varyings = varyings::layout(
            vertex_program.as_ref().map(|p| &p.lowered),
            fragment_program.as_ref().map(|p| &p.lowered),
        )?;
        let sampler_slots = [&vertex_program, &fragment_program]
            .into_iter()
            .flatten()
            .flat_map(|stage| &stage.lowered.samplers)
            .filter_map(|s| Some((linked.element(&s.name)?.1, sampler_target(s.kind))))
            .collect();
        Ok(Executable {
            vertex: linked.vertex,
            fragment: linked.fragment,
            interface: Arc::new(linked),
            vertex_program,
            fragment_program,
            varyings,
            sampler_slots,
        })
    }
}

/// A program object.
#[derive(Debug, Default)]
pub struct Program {
    /// The attached shaders, in attach order.
    shaders: Vec<u32>,
    link_status: bool,
    validate_status: bool,
    info_log: String,
    /// The executable of the last successful link.
    executable: Option<Arc<Executable>>,
    /// The uniform values of that executable, one word per component as
    /// [`Linked::at_location`] lays them out; reset by each successful link.
    uniform_values: Vec<u32>,
    /// glBindAttribLocation's bindings, used by the next link.
    attribute_bindings: Vec<(String, u32)>,
    /// glDeleteProgram while in use: deleted when no context uses it.
    delete_pending: bool,
    /// How many contexts use it (glUseProgram).
    users: u32,
}

/// A shader or a program: they share one name space.
#[derive(Debug)]
pub enum Object {
    Shader(Shader),
    Program(Program),
}

/// The shader and program objects of a share group.
#[derive(Debug, Default)]
pub struct ShaderObjects {
    names: NameTable<Object>,
}

/// Why a name was refused, as the GL error it records.
type Refused = GLenum;

impl ShaderObjects {
    /// The shader `name`: GL_INVALID_VALUE for no object, GL_INVALID_OPERATION for a program.
    fn shader(&mut self, name: u32) -> Result<&mut Shader, Refused> {
        match self.names.get_mut(name) {
            Some(Object::Shader(shader)) => Ok(shader),
            Some(Object::Program(_)) => Err(GL_INVALID_OPERATION),
            None => Err(GL_INVALID_VALUE),
        }
    }

    /// The program `name`: GL_INVALID_VALUE for no object, GL_INVALID_OPERATION for a shader.
    fn program(&mut self, name: u32) -> Result<&mut Program, Refused> {
        match self.names.get_mut(name) {
            Some(Object::Program(program)) => Ok(program),
            Some(Object::Shader(_)) => Err(GL_INVALID_OPERATION),
            None => Err(GL_INVALID_VALUE),
        }
    }

    fn create(&mut self, object: Object) -> u32 {
        let mut object = Some(object);
        match self.names.generate_objects(1, || object.take().expect("one name")) {
            Ok(names) => names[0],
            Err(_) => 0,
        }
    }

    /// Deletes shader `name` if it is flagged and no program holds it any more.
    fn collect_shader(&mut self, name: u32) {
        if let Ok(shader) = self.shader(name) {
            if shader.delete_pending && shader.attachments == 0 {
                self.names.delete(name);
            }
        }
    }

    /// Deletes program `name` if it is flagged and no context uses it, detaching its shaders.
    fn collect_program(&mut self, name: u32) {
        let Ok(program) = self.program(name) else { return };
        if !(program.delete_pending && program.users == 0) {
            return;
        }
        let shaders = std::mem::take(&mut program.shaders);
        self.names.delete(name);
        for shader in shaders {
            if let Ok(s) = self.shader(shader) {
                s.attachments -= 1;
            }
            self.collect_shader(shader);
        }
    }
}

/// The program a context uses (glUseProgram), holding its place in the program's user count.
/// Dropping it (context destruction) lets go of the program.
#[derive(Debug, Default)]
pub struct ProgramInUse {
    name: u32,
    executable: Option<Arc<Executable>>,
    objects: Option<Shared<ShaderObjects>>,
}

impl ProgramInUse {
    /// The program's name (GL_CURRENT_PROGRAM), 0 for fixed-function processing.
    pub fn name(&self) -> u32 {
        self.name
    }

    /// The executable in use, `None` for fixed-function processing.
    pub fn executable(&self) -> Option<&Arc<Executable>> {
        self.executable.as_ref()
    }

    /// Stops using the program (the caller holds the table locked).
    fn release(&mut self, objects: &mut ShaderObjects) {
        let name = std::mem::take(&mut self.name);
        self.executable = None;
        self.objects = None;
        if let Ok(program) = objects.program(name) {
            program.users -= 1;
            objects.collect_program(name);
        }
    }
}

impl Drop for ProgramInUse {
    fn drop(&mut self) {
        if let Some(objects) = self.objects.take() {
            self.release(&mut objects.lock());
        }
    }
}

/// Writes `text` as glGet*InfoLog and glGetShaderSource do: at most `buffer_size - 1` bytes
/// and a NUL into `write`'s buffer; returns the count written without the NUL.
pub fn copy_out(text: &str, buffer_size: usize) -> (usize, Vec<u8>) {
    if buffer_size == 0 {
        return (0, Vec::new());
    }
    let count = text.len().min(buffer_size - 1);
    let mut bytes = Vec::with_capacity(count + 1);
    bytes.extend_from_slice(&text.as_bytes()[..count]);
    bytes.push(0);
    (count, bytes)
}

/// GL's length of a string value: its bytes and the NUL, or 0 for an empty string.
fn length_with_nul(text: &str) -> GLint {
    if text.is_empty() {
        0
    } else {
        GLint::try_from(text.len() + 1).unwrap_or(GLint::MAX)
    }
}

impl super::Context {
    /// Runs `f` on the share group's shader objects; its error, if any, is recorded.
    /// Between glBegin and glEnd it records GL_INVALID_OPERATION instead.
    fn with_shader_objects<R>(&mut self, f: impl FnOnce(&mut ShaderObjects) -> Result<R, Refused>) -> Option<R> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let result = f(&mut self.shader_objects.lock());
        match result {
            Ok(value) => Some(value),
            Err(error) => {
                self.error(error);
                None
            }
        }
    }

    /// glCreateShader: 0 (and GL_INVALID_ENUM) for a type that is not a shader stage.
    pub fn create_shader(&mut self, kind: GLenum) -> u32 {
        if !self.check_outside_begin_end() {
            return 0;
        }
        let Some(stage) = stage_of(kind) else {
            self.error(GL_INVALID_ENUM);
            return 0;
        };
        let shader = Shader {
            stage,
            source: None,
            compiled: false,
            checked: None,
            info_log: String::new(),
            delete_pending: false,
            attachments: 0,
        };
        let name = self.shader_objects.lock().create(Object::Shader(shader));
        if name == 0 {
            self.error(GL_OUT_OF_MEMORY);
        }
        name
    }

    /// glCreateProgram.
    pub fn create_program(&mut self) -> u32 {
        if !self.check_outside_begin_end() {
            return 0;
        }
        let name = self.shader_objects.lock().create(Object::Program(Program::default()));
        if name == 0 {
            self.error(GL_OUT_OF_MEMORY);
        }
        name
    }

    /// glShaderSource, given the pieces already read from the caller, or the error the
    /// arguments make once the shader is found (a negative count or a NULL array:
    /// GL_INVALID_VALUE; a NULL piece: GL_INVALID_OPERATION, as Mesa).
    pub fn shader_source(&mut self, shader: u32, pieces: Result<Vec<Vec<u8>>, GLenum>) {
        self.with_shader_objects(|objects| {
            let shader = objects.shader(shader)?;
            let pieces = pieces?;
            let mut source = Vec::with_capacity(pieces.iter().map(Vec::len).sum());
            for piece in &pieces {
                source.extend_from_slice(piece);
            }
            // GLSL source is ASCII; other bytes reach the compiler, which refuses them.
            shader.source = Some(String::from_utf8_lossy(&source).into_owned());
            Ok(())
        });
    }

    /// glCompileShader: compiles the source with the GLSL front end and keeps its log.
    pub fn compile_shader(&mut self, shader: u32) {
        let Some((stage, source)) = self.with_shader_objects(|objects| {
            let shader = objects.shader(shader)?;
            Ok((shader.stage, shader.source.clone()))
        }) else {
            return;
        };
        // Compile without the table locked: a long compile must not stall other contexts.
        let (checked, info_log) = match source {
            None => (None, String::new()),
            Some(source) => compile(stage, &source),
        };
        self.with_shader_objects(|objects| {
            // The shader may have been deleted meanwhile by another context: then nothing.
            if let Ok(shader) = objects.shader(shader) {
                shader.compiled = checked.is_some();
                shader.checked = checked;
                shader.info_log = info_log;
            }
            Ok(())
        });
    }

    /// glDeleteShader: deleted at once, or flagged while attached to a program.
    pub fn delete_shader(&mut self, name: u32) {
        if name == 0 {
            return;
        }
        self.with_shader_objects(|objects| {
            let shader = objects.shader(name)?;
            shader.delete_pending = true;
            objects.collect_shader(name);
            Ok(())
        });
    }

    /// glDeleteProgram: deleted at once, or flagged while some context uses it.
    pub fn delete_program(&mut self, name: u32) {
        if name == 0 {
            return;
        }
        self.with_shader_objects(|objects| {
            let program = objects.program(name)?;
            program.delete_pending = true;
            objects.collect_program(name);
            Ok(())
        });
    }

    /// glIsShader.
    pub fn is_shader(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && matches!(self.shader_objects.lock().names.get(name), Some(Object::Shader(_)))
    }

    /// glIsProgram.
    pub fn is_program(&mut self, name: u32) -> bool {
        self.check_outside_begin_end() && matches!(self.shader_objects.lock().names.get(name), Some(Object::Program(_)))
    }

    /// glAttachShader.
    pub fn attach_shader(&mut self, program: u32, shader: u32) {
        self.with_shader_objects(|objects| {
            let attached = objects.program(program)?.shaders.contains(&shader);
            let attaching = objects.shader(shader)?;
            if attached {
                return Err(GL_INVALID_OPERATION);
            }
            attaching.attachments += 1;
            objects.program(program)?.shaders.push(shader);
            Ok(())
        });
    }

    /// glDetachShader: a flagged shader goes with its last attachment.
    pub fn detach_shader(&mut self, program: u32, shader: u32) {
        self.with_shader_objects(|objects| {
            objects.program(program)?;
            objects.shader(shader)?;
            let shaders = &mut objects.program(program)?.shaders;
            let index = shaders.iter().position(|&s| s == shader).ok_or(GL_INVALID_OPERATION)?;
            shaders.remove(index);
            objects.shader(shader)?.attachments -= 1;
            objects.collect_shader(shader);
            Ok(())
        });
    }

    /// glGetAttachedShaders: at most `max_count` names, in attach order.
    pub fn attached_shaders(&mut self, program: u32, max_count: GLsizei) -> Option<Vec<u32>> {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            let max_count = usize::try_from(max_count).map_err(|_| GL_INVALID_VALUE)?;
            Ok(program.shaders.iter().copied().take(max_count).collect())
        })
    }

    /// glGetShaderiv.
    pub fn get_shader(&mut self, shader: u32, pname: GLenum) -> Option<GLint> {
        self.with_shader_objects(|objects| {
            let shader = objects.shader(shader)?;
            Ok(match pname {
                GL_SHADER_TYPE => shader_type(shader.stage) as GLint,
                GL_DELETE_STATUS => shader.delete_pending as GLint,
                GL_COMPILE_STATUS => shader.compiled as GLint,
                GL_INFO_LOG_LENGTH => length_with_nul(&shader.info_log),
                GL_SHADER_SOURCE_LENGTH => shader.source.as_deref().map_or(0, length_with_nul),
                _ => return Err(GL_INVALID_ENUM),
            })
        })
    }

    /// glGetProgramiv.
    pub fn get_program(&mut self, program: u32, pname: GLenum) -> Option<GLint> {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            Ok(match pname {
                GL_DELETE_STATUS => program.delete_pending as GLint,
                GL_LINK_STATUS => program.link_status as GLint,
                GL_VALIDATE_STATUS => program.validate_status as GLint,
                GL_INFO_LOG_LENGTH => length_with_nul(&program.info_log),
                GL_ATTACHED_SHADERS => program.shaders.len() as GLint,
                // A program that did not link lists nothing (Mesa clears its interface).
                GL_ACTIVE_ATTRIBUTES
                | GL_ACTIVE_ATTRIBUTE_MAX_LENGTH
                | GL_ACTIVE_UNIFORMS
                | GL_ACTIVE_UNIFORM_MAX_LENGTH => {
                    let Some(linked) = program.linked() else { return Ok(0) };
                    let longest = |names: &mut dyn Iterator<Item = &String>| {
                        names.map(|n| n.len() as GLint + 1).max().unwrap_or(0)
                    };
                    match pname {
                        GL_ACTIVE_ATTRIBUTES => linked.attributes.len() as GLint,
                        GL_ACTIVE_ATTRIBUTE_MAX_LENGTH => longest(&mut linked.attributes.iter().map(|a| &a.name)),
                        GL_ACTIVE_UNIFORMS => linked.uniforms.len() as GLint,
                        _ => longest(&mut linked.uniforms.iter().map(|u| &u.name)),
                    }
                }
                _ => return Err(GL_INVALID_ENUM),
            })
        })
    }

    /// glGetShaderInfoLog's text.
    pub fn shader_info_log(&mut self, shader: u32) -> Option<String> {
        self.with_shader_objects(|objects| Ok(objects.shader(shader)?.info_log.clone()))
    }

    /// glGetShaderSource's text (empty when no source was given).
    pub fn shader_source_text(&mut self, shader: u32) -> Option<String> {
        self.with_shader_objects(|objects| Ok(objects.shader(shader)?.source.clone().unwrap_or_default()))
    }

    /// glGetProgramInfoLog's text.
    pub fn program_info_log(&mut self, program: u32) -> Option<String> {
        self.with_shader_objects(|objects| Ok(objects.program(program)?.info_log.clone()))
    }

    /// glLinkProgram. A context that uses the program keeps its executable until it calls
    /// glUseProgram again, except that a successful relink of the program in use becomes
    /// current at once (GL 2.1 section 2.15.2).
    pub fn link_program(&mut self, program: u32) {
        let Some(executable) = self.with_shader_objects(|objects| {
            let shaders = objects.program(program)?.shaders.clone();
            let mut checked = Vec::with_capacity(shaders.len());
            let mut uncompiled = false;
            for &name in &shaders {
                match &objects.shader(name)?.checked {
                    Some(c) if !uncompiled => checked.push(c.clone()),
                    _ => uncompiled = true,
                }
            }
            let bindings = objects.program(program)?.attribute_bindings.clone();
            let result = if uncompiled {
                Err("error: linking with uncompiled/unspecialized shader".to_string())
            } else {
                link::link(&checked, &bindings).and_then(Executable::new)
            };
            let program = objects.program(program)?;
            match result {
                Ok(executable) => {
                    program.link_status = true;
                    program.info_log = String::new();
                    program.uniform_values = executable.interface.initial_values.clone();
                    program.executable = Some(Arc::new(executable));
                    Ok(program.executable.clone())
                }
                Err(log) => {
                    program.link_status = false;
                    program.info_log = log;
                    Ok(None)
                }
            }
        }) else {
            return;
        };
        if self.program_in_use.name == program {
            if let Some(executable) = executable {
                self.program_in_use.executable = Some(executable);
            }
        }
    }

    /// glValidateProgram: whether the program could run in the current state (linked).
    pub fn validate_program(&mut self, program: u32) {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            let conflict = match &program.executable {
                Some(executable) if program.link_status => sampler_unit_conflict(executable, &program.uniform_values),
                _ => None,
            };
            program.validate_status = program.link_status && conflict.is_none();
            program.info_log = match conflict {
                _ if !program.link_status => "error: program not linked\n".to_string(),
                // Mesa's words (the spec's), with the unit.
                Some(unit) => {
                    format!("active samplers with a different type refer to the same texture image unit ({unit})\n")
                }
                None => String::new(),
            };
            Ok(())
        });
    }

    /// glUseProgram: 0 returns to fixed-function processing; a program that did not link
    /// is GL_INVALID_OPERATION.
    pub fn use_program(&mut self, name: u32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let objects = self.shader_objects.clone();
        let mut table = objects.lock();
        let executable = if name == 0 {
            None
        } else {
            let program = match table.program(name) {
                Ok(program) => program,
                Err(error) => {
                    drop(table);
                    self.error(error);
                    return;
                }
            };
            if !program.link_status {
                drop(table);
                self.error(GL_INVALID_OPERATION);
                return;
            }
            program.users += 1;
            program.executable.clone()
        };
        // Let go of the previous program after taking the new one (it may be the same).
        let mut previous = std::mem::take(&mut self.program_in_use);
        previous.release(&mut table);
        if name != 0 {
            self.program_in_use = ProgramInUse { name, executable, objects: Some(objects.clone()) };
        }
    }

    /// glBindAttribLocation: takes effect at the next link.
    pub fn bind_attrib_location(&mut self, program: u32, index: u32, name: &[u8]) {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            if index >= MAX_VERTEX_ATTRIBS {
                return Err(GL_INVALID_VALUE);
            }
            if name.starts_with(b"gl_") {
                return Err(GL_INVALID_OPERATION);
            }
            let name = String::from_utf8_lossy(name).into_owned();
            program.attribute_bindings.retain(|(n, _)| *n != name);
            program.attribute_bindings.push((name, index));
            Ok(())
        });
    }

    /// The interface of a linked program, GL_INVALID_OPERATION if it did not link.
    fn linked_interface(&mut self, program: u32) -> Option<Arc<Linked>> {
        self.with_shader_objects(|objects| objects.program(program)?.linked().cloned().ok_or(GL_INVALID_OPERATION))
    }

    /// glGetAttribLocation: -1 for built-ins and names that are not active attributes.
    pub fn attrib_location(&mut self, program: u32, name: &str) -> GLint {
        self.linked_interface(program).map_or(-1, |l| l.attribute_location(name).map_or(-1, |i| i as GLint))
    }

    /// glGetUniformLocation: -1 for built-in state and names that are no active element.
    pub fn uniform_location(&mut self, program: u32, name: &str) -> GLint {
        self.linked_interface(program).map_or(-1, |l| l.uniform_location(name).map_or(-1, |i| i as GLint))
    }

    /// glGetActiveUniform and glGetActiveAttrib: the name, size and type of entry `index`
    /// (GL_INVALID_VALUE past the end or for a negative buffer size).
    pub fn active_variable(
        &mut self,
        program: u32,
        index: u32,
        buffer_size: GLsizei,
        uniform: bool,
    ) -> Option<(String, GLint, GLenum)> {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            if buffer_size < 0 {
                return Err(GL_INVALID_VALUE);
            }
            let linked = program.linked().ok_or(GL_INVALID_VALUE)?;
            let index = index as usize;
            if uniform {
                let u = linked.uniforms.get(index).ok_or(GL_INVALID_VALUE)?;
                Ok((u.name.clone(), u.size as GLint, u.gl_type()))
            } else {
                let a = linked.attributes.get(index).ok_or(GL_INVALID_VALUE)?;
                Ok((a.name.clone(), 1, a.gl_type()))
            }
        })
    }

    /// glUniform* and glUniformMatrix* on the current program: `values` holds `count`
    /// elements of `form`'s shape, as the caller gave them. Location -1 does nothing.
    pub fn set_uniform(&mut self, location: GLint, count: GLsizei, form: UniformForm, values: &[u32]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if count < 0 {
            self.error(GL_INVALID_VALUE);
            return;
        }
        let current = self.program_in_use.name;
        let units = crate::glsl::Limits::default().max_combined_texture_image_units;
        let result = (|| {
            let mut objects = self.shader_objects.lock();
            let program = objects.program(current).map_err(|_| GL_INVALID_OPERATION)?;
            if location == -1 {
                return Ok(());
            }
            let linked = program.linked().ok_or(GL_INVALID_OPERATION)?.clone();
            let (u, first) =
                u32::try_from(location).ok().and_then(|l| linked.at_location(l)).ok_or(GL_INVALID_OPERATION)?;
            let element = linked.locations[location as usize].1;
            store_uniform(u, element, first, count as usize, form, values, units, &mut program.uniform_values)
        })();
        if let Err(error) = result {
            self.error(error);
        }
    }

    /// How many elements a glUniform*v call at `location` can set on the current program (0
    /// when it sets none): the array's remaining elements, 1 for a non-array.
    pub fn uniform_room(&mut self, location: GLint) -> usize {
        let current = self.program_in_use.name;
        let mut objects = self.shader_objects.lock();
        let Ok(program) = objects.program(current) else { return 0 };
        let Some(linked) = program.linked() else { return 0 };
        let Some(&(index, element)) = usize::try_from(location).ok().and_then(|l| linked.locations.get(l)) else {
            return 0;
        };
        (linked.uniforms[index].size - element) as usize
    }

    /// glGetUniformfv and glGetUniformiv: the element's components, converted to `float`.
    pub fn get_uniform(&mut self, program: u32, location: GLint, float: bool) -> Option<Vec<u32>> {
        self.with_shader_objects(|objects| {
            let program = objects.program(program)?;
            let linked = program.linked().ok_or(GL_INVALID_OPERATION)?;
            let (u, first) =
                u32::try_from(location).ok().and_then(|l| linked.at_location(l)).ok_or(GL_INVALID_OPERATION)?;
            let words = &program.uniform_values[first..first + u.words()];
            let base = u.ty.base().unwrap_or(crate::glsl::hir::Scalar::Int);
            Ok(words.iter().map(|&w| convert_word(w, base, float)).collect())
        })
    }
}

/// The shape of a glUniform* call: its element type and whether it sets a matrix transposed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UniformForm {
    /// glUniform{1,2,3,4}f[v]: components.
    Float(u8),
    /// glUniform{1,2,3,4}i[v].
    Int(u8),
    /// glUniformMatrix{C}x{R}fv: columns, rows, transpose.
    Matrix(u8, u8, bool),
}

impl UniformForm {
    /// Values per element.
    pub fn components(self) -> usize {
        match self {
            UniformForm::Float(n) | UniformForm::Int(n) => n as usize,
            UniformForm::Matrix(c, r, _) => (c * r) as usize,
        }
    }
}

/// A stored word as glGetUniformfv (`float`) or glGetUniformiv returns it (floats rounded to
/// the nearest integer, as Mesa does).
fn convert_word(w: u32, base: crate::glsl::hir::Scalar, float: bool) -> u32 {
    use crate::glsl::hir::Scalar;
    match (base, float) {
        (Scalar::Float, true) => w,
        (Scalar::Float, false) => (f32::from_bits(w).round() as i32) as u32,
        (_, true) => (w as i32 as f32).to_bits(),
        (_, false) => w,
    }
}

/// Checks a glUniform* call against the element it names, as Mesa does, and stores the
/// values: a matching component count and kind (bools take either; samplers only
/// glUniform1i with a unit below `units`), one element for a non-array, elements past the
/// array's end dropped.
#[allow(clippy::too_many_arguments)]
fn store_uniform(
    u: &link::ActiveUniform,
    element: u32,
    first: usize,
    count: usize,
    form: UniformForm,
    values: &[u32],
    units: i32,
    storage: &mut [u32],
) -> Result<(), Refused> {
    use crate::glsl::hir::{Scalar, Type};
    let fits = match (&u.ty, form) {
        (Type::Sampler(_), f) => f == UniformForm::Int(1),
        (Type::Matrix(c, r), UniformForm::Matrix(fc, fr, _)) => (*c, *r) == (fc, fr),
        (Type::Matrix(..), _) | (_, UniformForm::Matrix(..)) => false,
        (t, UniformForm::Float(n)) => t.vector_size() == n && t.base() != Some(Scalar::Int),
        (t, UniformForm::Int(n)) => t.vector_size() == n && t.base() != Some(Scalar::Float),
    };
    if !fits {
        return Err(GL_INVALID_OPERATION);
    }
    if !u.is_array && count > 1 {
        return Err(GL_INVALID_OPERATION);
    }
    let n = form.components();
    let count = count.min((u.size - element) as usize).min(values.len() / n.max(1));
    if let Type::Sampler(_) = u.ty {
        if values[..count].iter().any(|&v| v as i32 >= units || (v as i32) < 0) {
            return Err(GL_INVALID_VALUE);
        }
    }
    let base = u.ty.base();
    for e in 0..count {
        let src = &values[e * n..(e + 1) * n];
        let dst = &mut storage[first + e * n..first + (e + 1) * n];
        for (i, d) in dst.iter_mut().enumerate() {
            let v = match form {
                // Transposed: the caller's rows are the stored columns.
                UniformForm::Matrix(c, r, true) => src[(i % r as usize) * c as usize + i / r as usize],
                _ => src[i],
            };
            *d = match (base, form) {
                (Some(Scalar::Bool), UniformForm::Float(_)) => (f32::from_bits(v) != 0.0) as u32,
                (Some(Scalar::Bool), _) => (v != 0) as u32,
                _ => v,
            };
        }
    }
    Ok(())
}

impl Program {
    /// The interface of the last link, if it succeeded.
    fn linked(&self) -> Option<&Arc<Linked>> {
        self.executable.as_ref().filter(|_| self.link_status).map(|e| &e.interface)
    }
}

/// The first texture unit that two samplers the program's stages read give different
/// targets (GL 2.0 section 2.15.4, "Validation": two active samplers of different types on
/// one unit make draws GL_INVALID_OPERATION and glValidateProgram fail; glRasterPos, which
/// the spec names too, is not refused, as in Mesa). Shadow and plain
/// samplers of one dimensionality read the same target, and do not conflict (as Mesa).
pub fn sampler_unit_conflict(executable: &Executable, values: &[u32]) -> Option<u32> {
    let slots = &executable.sampler_slots;
    // Pairs in order: a program has few samplers (GL_MAX_TEXTURE_IMAGE_UNITS per stage).
    for (i, &(slot, target)) in slots.iter().enumerate() {
        let Some(&unit) = values.get(slot) else { continue };
        let clash = slots[..i].iter().any(|&(s, t)| t != target && values.get(s) == Some(&unit));
        if clash {
            return Some(unit);
        }
    }
    None
}

/// The texture target index (1D, 2D, 3D, cube map) a sampler type reads.
pub fn sampler_target(kind: crate::glsl::lex::Sampler) -> usize {
    use crate::glsl::lex::Sampler as Kind;
    match kind {
        Kind::S1D | Kind::S1DShadow => 0,
        Kind::S2D | Kind::S2DShadow => 1,
        Kind::S3D => 2,
        Kind::Cube => 3,
    }
}

impl Context {
    /// The validation a draw command (glBegin, the array draws) makes of the
    /// program in use: false, with GL_INVALID_OPERATION, when two of its samplers of
    /// different types share a texture unit ([`sampler_unit_conflict`]).
    pub(crate) fn check_program_samplers(&mut self) -> bool {
        let Some(executable) = self.program_in_use.executable() else { return true };
        // Two samplers at least, or there is nothing to compare (and no lock to take).
        if executable.sampler_slots.len() < 2 {
            return true;
        }
        let in_use = &self.program_in_use;
        let conflict = in_use.with_uniform_values(|values| sampler_unit_conflict(executable, values)).flatten();
        if conflict.is_some() {
            self.error(GL_INVALID_OPERATION);
        }
        conflict.is_none()
    }
}

impl ProgramInUse {
    /// `f` of the uniform values of the program in use, under the share group's lock.
    pub fn with_uniform_values<T>(&self, f: impl FnOnce(&[u32]) -> T) -> Option<T> {
        let objects = self.objects.as_ref()?;
        let mut table = objects.lock();
        table.program(self.name).ok().map(|p| f(&p.uniform_values))
    }

    /// The uniform values of the program in use, for the draw path (a copy taken under the
    /// share group's lock).
    pub fn uniform_values(&self) -> Option<Vec<u32>> {
        let objects = self.objects.as_ref()?;
        let mut table = objects.lock();
        table.program(self.name).ok().map(|p| p.uniform_values.clone())
    }
}

/// Compiles `source` for `stage` with the GLSL front end: the checked shader if it compiled,
/// and the info log (empty on success without warnings, as Mesa's).
pub fn compile(stage: Stage, source: &str) -> (Option<Arc<Checked>>, String) {
    let mut log = crate::glsl::InfoLog::default();
    let checked = crate::glsl::compile_shader(source, stage, &crate::glsl::Options::default(), &mut log);
    let Some(checked) = checked.filter(|_| !log.has_errors()).map(Arc::new) else { return (None, log.text()) };
    // Recursion within the shader is a compile error, as Mesa reports it.
    let recursive = link::recursive_functions(&checked);
    if recursive.is_empty() {
        return (Some(checked), log.text());
    }
    let mut text = log.text();
    for signature in recursive {
        text.push_str(&format!("0:0(0): error: function `{signature}' has static recursion\n"));
    }
    (None, text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::{Context, ContextConfig};
    use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};

    fn context() -> Context {
        let depth_stencil = DepthStencilFormat::Packed24 { depth: true, stencil: true };
        let visual = FramebufferConfig::single_buffered(ColorFormat::Unorm8 { alpha: true }, depth_stencil, 0);
        Context::new(ContextConfig { visual })
    }

    /// A linked program of one compiled vertex shader, the shader already flagged deleted.
    fn linked_program(ctx: &mut Context) -> (u32, u32) {
        let shader = ctx.create_shader(GL_VERTEX_SHADER);
        ctx.shader_source(shader, Ok(vec![b"void main() { gl_Position = vec4(0.0); }".to_vec()]));
        ctx.compile_shader(shader);
        let program = ctx.create_program();
        ctx.attach_shader(program, shader);
        ctx.link_program(program);
        ctx.delete_shader(shader);
        assert_eq!(ctx.get_program(program, GL_LINK_STATUS), Some(1));
        (program, shader)
    }

    #[test]
    fn a_destroyed_context_lets_go_of_the_deleted_program_it_used() {
        let mut first = context();
        let mut second = context();
        second.join_share_group(&first.share_group());
        let (program, shader) = linked_program(&mut first);
        second.use_program(program);
        first.delete_program(program);
        // Flagged: the second context still uses it, and it holds the flagged shader.
        assert!(first.is_program(program) && first.is_shader(shader));
        assert_eq!(first.get_program(program, GL_DELETE_STATUS), Some(1));
        drop(second);
        assert!(!first.is_program(program), "gone with its last user");
        assert!(!first.is_shader(shader), "its flagged shader went with it");
        assert_eq!(first.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn using_the_same_program_again_keeps_one_use() {
        let mut ctx = context();
        let (program, _) = linked_program(&mut ctx);
        ctx.use_program(program);
        ctx.use_program(program);
        ctx.delete_program(program);
        assert!(ctx.is_program(program));
        ctx.use_program(0);
        assert!(!ctx.is_program(program), "one glUseProgram(0) releases it");
        assert_eq!(ctx.program_in_use.name(), 0);
    }

    #[test]
    fn draws_with_a_linked_program_run_without_error() {
        let mut ctx = context();
        let program = program_of(&mut ctx, GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(1.0); }");
        assert_eq!(ctx.get_program(program, GL_LINK_STATUS), Some(1));
        ctx.use_program(program);
        ctx.draw_vertices(
            crate::gl::enums::GL_POINTS,
            &[crate::context::draw::replay::vertex(0.0, 0.0, 0.0, [1.0; 4])],
        );
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn samplers_name_the_eight_texture_image_units() {
        let mut ctx = context();
        let source = "uniform sampler2D a;\nuniform sampler1D b;\n\
            void main() { gl_FragColor = texture2D(a, vec2(0.5)) + texture1D(b, 0.5); }";
        let program = program_of(&mut ctx, GL_FRAGMENT_SHADER, source);
        assert_eq!(ctx.get_program(program, GL_LINK_STATUS), Some(1));
        ctx.use_program(program);
        let (a, b) = (ctx.uniform_location(program, "a"), ctx.uniform_location(program, "b"));
        ctx.set_uniform(a, 1, UniformForm::Int(1), &[7]);
        ctx.set_uniform(b, 1, UniformForm::Int(1), &[4]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(ctx.check_program_samplers());
        // Past GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS: refused, the value kept.
        ctx.set_uniform(a, 1, UniformForm::Int(1), &[8]);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        // Two types on unit 7: the draw-time validation refuses it.
        ctx.set_uniform(b, 1, UniformForm::Int(1), &[7]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(!ctx.check_program_samplers());
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
    }

    /// A program of `source` compiled as the only shader of `kind` (which must compile), linked.
    fn program_of(ctx: &mut Context, kind: GLenum, source: &str) -> u32 {
        let shader = ctx.create_shader(kind);
        ctx.shader_source(shader, Ok(vec![source.as_bytes().to_vec()]));
        ctx.compile_shader(shader);
        assert_eq!(ctx.get_shader(shader, GL_COMPILE_STATUS), Some(1), "{source}");
        let program = ctx.create_program();
        ctx.attach_shader(program, shader);
        ctx.link_program(program);
        program
    }

    /// Links `source` as the only shader of `kind`; the link status and the info log.
    fn link_one(ctx: &mut Context, kind: GLenum, source: &str) -> (bool, String) {
        let program = program_of(ctx, kind, source);
        let linked = ctx.get_program(program, GL_LINK_STATUS) == Some(1);
        (linked, ctx.program_info_log(program).unwrap_or_default())
    }

    #[test]
    fn a_stage_uses_no_more_samplers_than_its_image_units() {
        let mut ctx = context();
        let fragment = |n: usize| {
            let sum: Vec<String> = (0..n).map(|i| format!("texture2D(t[{i}], vec2(0.5))")).collect();
            format!("uniform sampler2D t[{n}];\nvoid main() {{ gl_FragColor = {}; }}", sum.join(" + "))
        };
        assert_eq!(link_one(&mut ctx, GL_FRAGMENT_SHADER, &fragment(8)), (true, String::new()));
        let (linked, log) = link_one(&mut ctx, GL_FRAGMENT_SHADER, &fragment(9));
        assert!(!linked && log.contains("Too many fragment shader texture samplers"), "{log}");
        // An unused ninth sampler is not active and does not count.
        let unused = "uniform sampler2D t[9];\nvoid main() { gl_FragColor = texture2D(t[0], vec2(0.5)); }";
        assert!(link_one(&mut ctx, GL_FRAGMENT_SHADER, unused).0);
        // GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS is 0: a vertex shader that samples cannot link.
        let vertex = "uniform sampler2D t;\n\
            void main() { gl_Position = texture2DLod(t, vec2(0.5), 0.0); }";
        let (linked, log) = link_one(&mut ctx, GL_VERTEX_SHADER, vertex);
        assert!(!linked && log.contains("Too many vertex shader texture samplers"), "{log}");
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    /// The first draw with a new program (issue #20 wants it under 5 ms for a 200-line
    /// shader): the Phong pair of `tests/glsl/phong.{vert,frag}` compiled, linked and drawn
    /// through the GL entry points, each phase timed (printed with `--nocapture`).
    #[test]
    fn a_200_line_shader_pair_compiles_links_and_draws() {
        let sources = [
            (GL_VERTEX_SHADER, include_str!("../../tests/glsl/phong.vert")),
            (GL_FRAGMENT_SHADER, include_str!("../../tests/glsl/phong.frag")),
        ];
        let mut best = [std::time::Duration::MAX; 3];
        for _ in 0..5 {
            let mut ctx = context();
            let start = std::time::Instant::now();
            let program = ctx.create_program();
            for (kind, source) in sources {
                let shader = ctx.create_shader(kind);
                ctx.shader_source(shader, Ok(vec![source.as_bytes().to_vec()]));
                ctx.compile_shader(shader);
                assert_eq!(ctx.get_shader(shader, GL_COMPILE_STATUS), Some(1), "{:?}", ctx.shader_info_log(shader));
                ctx.attach_shader(program, shader);
            }
            let compiled = start.elapsed();
            ctx.link_program(program);
            assert_eq!(ctx.get_program(program, GL_LINK_STATUS), Some(1), "{:?}", ctx.program_info_log(program));
            let linked = start.elapsed();
            ctx.use_program(program);
            let vertex = |x: f32, y: f32| crate::context::draw::replay::vertex(x, y, 0.0, [1.0; 4]);
            ctx.draw_vertices(GL_TRIANGLES, &[vertex(-1.0, -1.0), vertex(1.0, -1.0), vertex(0.0, 1.0)]);
            assert_eq!(ctx.take_error(), GL_NO_ERROR);
            let drawn = start.elapsed();
            for (b, t) in best.iter_mut().zip([compiled, linked - compiled, drawn - linked]) {
                *b = (*b).min(t);
            }
        }
        println!("phong pair, best of 5: compile {:?}, link {:?}, first draw {:?}", best[0], best[1], best[2]);
    }

    #[test]
    fn commands_between_begin_and_end_are_invalid_operations() {
        let mut ctx = context();
        ctx.inside_begin_end = true;
        assert_eq!(ctx.create_program(), 0);
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert!(!ctx.is_shader(1));
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn copy_out_truncates_and_terminates() {
        assert_eq!(copy_out("hello", 0), (0, vec![]));
        assert_eq!(copy_out("hello", 1), (0, vec![0]));
        assert_eq!(copy_out("hello", 3), (2, b"he\0".to_vec()));
        assert_eq!(copy_out("hello", 6), (5, b"hello\0".to_vec()));
        assert_eq!(copy_out("hello", 60), (5, b"hello\0".to_vec()));
    }

    #[test]
    fn string_lengths_count_the_nul_except_when_empty() {
        assert_eq!(length_with_nul(""), 0);
        assert_eq!(length_with_nul("a"), 2);
    }
}

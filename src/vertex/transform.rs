//! The per-vertex stage of a draw: the draw's fixed-function vertex program
//! ([`super::program`]: object to eye and clip coordinates, the fog coordinate, texgen and
//! the texture matrices, colours clamped or lit) run over its vertices, sixteen at a time.
//!
//! Its input is a [`Transform`] that `context` snapshots at the draw: the matrices by value
//! (as Mesa's validated products, computed once per draw) and the lighting state and
//! glMaterial marks by reference, so nothing per light or per vertex is copied.
//! [`VertexStage::new`] makes the state's key, has the caller look its compiled program up
//! (the share group's cache) and fills the uniform words, once per draw (once per run of
//! vertices between glMaterial calls inside glBegin/glEnd, whose materials are uniforms),
//! or [`StageCache`] keeps the last draw's for the next unlit draw with the same state;
//! [`VertexStage::run`] gathers 16 vertices at a time into the program's input words
//! (structure of arrays), runs the compiled program on the live lanes and scatters its
//! outputs into [`FixedClipVertex`]es.
//!
//! One program has a second, hand-written form: an unlit draw with no texture unit and the
//! fog coordinate passed through (position and colours only) runs the program's
//! arithmetic written out (`Direct`), tested bit for bit against the program. Otherwise
//! the per-vertex code the programs replaced is kept only as the reference the generated
//! programs are tested against (`super::program::reference`, test builds).
use super::clip::{FixedClipVertex, FIXED_SLOTS};
use super::lighting::{Lighting, LightingState, Material, NormalScaling};
use super::program::{CompiledVertex, VertexInput, VertexKey, VertexOutput, VertexProgram};
use super::texgen::{Gen, TexCoordUnit, TexGen};
use super::Vertex;
use crate::shader::exec::{Io, NoTextures, Word, ALL_LANES, LANES};
use crate::shader::fast::{BoundRun, Compiled, Registers};
use crate::shader::lower::R;
use glam::{Mat4, Vec4};
use std::sync::Arc;

/// Where the fog coordinate of a vertex comes from (GL_FOG_COORD_SRC and
/// GL_FOG_DISTANCE_MODE_NV).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogSource {
    /// glFogCoord's value (GL_FOG_COORD).
    Attribute,
    /// The eye distance (GL_EYE_RADIAL_NV).
    Radial,
    /// The signed eye z (GL_EYE_PLANE).
    Plane,
    /// |eye z| (GL_EYE_PLANE_ABSOLUTE_NV, the default).
    PlaneAbsolute,
}

/// The lighting pass of a draw (GL_LIGHTING on).
pub struct LightingInput<'a> {
    pub state: &'a LightingState,
    /// The inverse modelview, column-major.
    pub modelview_inverse: [f32; 16],
    pub normals: NormalScaling,
    /// glMaterial between glBegin and glEnd: from which vertex on each front and back
    /// material applies.
    pub material_marks: &'a [(usize, [Material; 2])],
}

/// What the per-vertex stage of a draw reads.
pub struct Transform<'a> {
    pub modelview: Mat4,
    /// Projection × modelview as Mesa computes it.
    pub model_project: Mat4,
    /// Colors are clamped to [0, 1] (GL_CLAMP_VERTEX_COLOR).
    pub clamp_color: bool,
    /// The fog coordinate's source when GL_FOG is on (`None`: the attribute passes through).
    pub fog: Option<FogSource>,
    pub texgen: TexGen<'a>,
    pub lighting: Option<LightingInput<'a>>,
}

/// The buffers of one run of the per-vertex stage: the executor's registers, the input and
/// output words of one batch, and the clip-space vertices, each allocated once per run of
/// the stage (not per batch). They are not kept between draws in a thread-local: the
/// allocator's caches then kept growing across create/draw/destroy cycles of contexts
/// (capi reliability_leaks measured a few KiB per 2000 cycles), and four allocations per
/// draw cost little beside a draw.
#[derive(Default)]
struct Scratch {
    registers: Registers,
    inputs: Vec<Word>,
    outputs: Vec<Word>,
    clip: Vec<FixedClipVertex>,
    /// The records of one batch, made in place ([`Run::transform_bound`]).
    batch: Vec<FixedClipVertex>,
    /// The program `registers` were last prepared for (held, so that no other program can
    /// be allocated where it was).
    program: Option<Arc<CompiledVertex>>,
    /// The uniform values `registers` were prepared with.
    prepared: Vec<u32>,
}

/// The buffers of the per-vertex stage kept between draws by their owner (a context, one
/// per thread that may run the stage for it: [`VertexStage::run_in`]), so that a small draw
/// (a glBegin/glEnd pair of a few vertices) does not allocate and zero the executor's
/// registers and its vertex buffers each time. Owned by the context, not by the thread, they
/// go with it (see [`Scratch`]). The registers start from zeros again whenever the program
/// changes, so a program never sees another's values; with the same program, what a run
/// reads it has written itself (its inputs, all sixteen lanes, and its uniform values,
/// prepared at each run) or is what the program never writes (still zero).
#[derive(Default)]
pub struct VertexScratch(Scratch);

/// The vertices of a draw from vertex `from` on, up to the next run: one program and one
/// set of uniform values (glMaterial between glBegin and glEnd starts a new run).
struct Run {
    from: usize,
    program: Arc<CompiledVertex>,
    uniforms: Vec<u32>,
    /// Lit without two-sided lighting: the back colours are the front ones (as the clipper
    /// and flat shading read them).
    lit_one_sided: bool,
    /// The program's arithmetic written out, for the programs that are only the two
    /// matrix products and the colour clamp ([`Direct`]); `None` runs the program.
    direct: Option<Direct>,
}

/// What the vertex program of an unlit draw with no texture unit and the fog coordinate
/// passed through computes, written out in Rust with the same arithmetic: clip and eye
/// coordinates as glam's `Mat4 * Vec4` ([`super::program`]'s `matrix_times` is that
/// product, every operation rounded in order), the colours clamped as `Builder::clamp01`
/// (`0 < c ? min(c, 1) : 0`), everything else copied. The position-and-colour draws (most
/// meshes, small_triangles) ran the program through the executor, gathering sixteen
/// vertices into its registers and scattering its outputs: about 195 instructions a vertex
/// against about 70 here (LTO build, callgrind). The program stays the definition: the
/// tests compare the two bit for bit on random matrices and vertices, special values
/// included.
#[derive(Clone, Copy, Debug)]
struct Direct {
    modelview: Mat4,
    model_project: Mat4,
    clamp_color: bool,
}

impl Direct {
    /// The direct form of the unlit program of `t`, when it has one.
    fn of(t: &Transform) -> Option<Direct> {
        let plain_fog = matches!(t.fog, None | Some(FogSource::Attribute));
        (t.lighting.is_none() && t.texgen.units.is_empty() && plain_fog).then_some(Direct {
            modelview: t.modelview,
            model_project: t.model_project,
            clamp_color: t.clamp_color,
        })
    }

    /// Appends the clip-space vertices of `vertices` to `clip`.
    fn transform(&self, vertices: &[Vertex], clip: &mut Vec<FixedClipVertex>) {
        // `0 < c ? (1 < c ? 1 : c) : 0` on the four channels at once (NaN and -0 give +0),
        // without a branch per channel.
        #[inline(always)]
        fn clamp01(c: [f32; 4]) -> [f32; 4] {
            let c = Vec4::from_array(c);
            let at_most_one = Vec4::select(Vec4::ONE.cmplt(c), Vec4::ONE, c);
            Vec4::select(Vec4::ZERO.cmplt(c), at_most_one, Vec4::ZERO).to_array()
        }
        let clamp = self.clamp_color;
        let colour = |c: [f32; 4]| if clamp { clamp01(c) } else { c };
        clip.extend(vertices.iter().map(|v| {
            let position = Vec4::from_array(v.position);
            FixedClipVertex {
                clip: (self.model_project * position).to_array(),
                eye: (self.modelview * position).to_array(),
                color: colour(v.color),
                secondary_color: colour(v.secondary_color),
                back_colors: [[0.0; 4]; 2],
                tex_coords: v.tex_coords,
                fog_coord: v.fog_coord,
                point_size: 0.0,
                edge_flag: v.edge_flag,
            }
        }));
    }
}

/// A draw's vertex processing, ready to run: its program(s), looked up once per draw, and
/// their uniform values, filled once.
pub struct VertexStage {
    first: Run,
    /// Further runs, after glMaterial calls between glBegin and glEnd (empty otherwise).
    more: Vec<Run>,
}

impl VertexStage {
    /// Prepares the per-vertex stage of a draw of `vertex_count` vertices with the state of
    /// `t`; `program` returns the compiled program of a key (the share group's cache).
    pub fn new(
        t: &Transform,
        vertex_count: usize,
        mut program: impl FnMut(&VertexKey) -> Arc<CompiledVertex>,
    ) -> VertexStage {
        let Some(input) = &t.lighting else {
            let compiled = program(&VertexKey::of(t, None));
            let uniforms = compiled.generated.uniform_values(t, None);
            return VertexStage {
                first: Run { from: 0, program: compiled, uniforms, lit_one_sided: false, direct: Direct::of(t) },
                more: Vec::new(),
            };
        };
        let mut lighting = Lighting::new(input.state, input.modelview_inverse, input.normals);
        let marks = input.material_marks;
        let mut runs: Vec<Run> = Vec::new();
        let (mut from, mut next_mark) = (0, 0);
        let mut previous_key: Option<VertexKey> = None;
        loop {
            // Every mark at or before the run's first vertex applies (the last one wins).
            while next_mark < marks.len() && marks[next_mark].0 <= from {
                lighting.set_materials(&marks[next_mark].1);
                next_mark += 1;
            }
            let key = VertexKey::of(t, Some(&lighting));
            let compiled = match runs.last() {
                Some(previous) if previous_key.as_ref() == Some(&key) => previous.program.clone(),
                _ => program(&key),
            };
            previous_key = Some(key);
            let uniforms = compiled.generated.uniform_values(t, Some(&lighting));
            runs.push(Run { from, program: compiled, uniforms, lit_one_sided: !lighting.two_side(), direct: None });
            match marks.get(next_mark) {
                Some(&(index, _)) if index < vertex_count => from = index,
                _ => break,
            }
        }
        let mut runs = runs.into_iter();
        let first = runs.next().expect("at least one run");
        VertexStage { first, more: runs.collect() }
    }

    /// The stage with every run through its program, none in its [`Direct`] form (tests).
    #[cfg(test)]
    pub fn through_programs(mut self) -> VertexStage {
        self.first.direct = None;
        self.more.iter_mut().for_each(|r| r.direct = None);
        self
    }

    /// Whether the stage's first run is in the [`Direct`] form (tests).
    #[cfg(test)]
    pub fn runs_directly(&self) -> bool {
        self.first.direct.is_some()
    }

    /// Runs the stage on `vertices`, the draw's vertices from index `first` on (a part of
    /// the draw, when it is split between threads), and hands their clip-space vertices to
    /// `then`.
    pub fn run<T>(&self, vertices: &[Vertex], first: usize, then: impl FnOnce(&[FixedClipVertex]) -> T) -> T {
        self.run_with(vertices, first, &mut Scratch::default(), then)
    }

    /// [`VertexStage::run`] in the buffers `scratch` (kept by the caller between draws).
    pub fn run_in<T>(
        &self,
        scratch: &mut VertexScratch,
        vertices: &[Vertex],
        first: usize,
        then: impl FnOnce(&[FixedClipVertex]) -> T,
    ) -> T {
        self.run_with(vertices, first, &mut scratch.0, then)
    }

    fn run_with<T>(
        &self,
        vertices: &[Vertex],
        first: usize,
        scratch: &mut Scratch,
        then: impl FnOnce(&[FixedClipVertex]) -> T,
    ) -> T {
        scratch.clip.clear();
        scratch.clip.reserve(vertices.len());
        let run_at = |i: usize| if i == 0 { Some(&self.first) } else { self.more.get(i - 1) };
        let relative = |index: usize| index.saturating_sub(first).min(vertices.len());
        for i in 0..=self.more.len() {
            let run = run_at(i).expect("a run");
            let end = run_at(i + 1).map_or(vertices.len(), |next| relative(next.from));
            let start = relative(run.from);
            if start < end {
                run.transform(&vertices[start..end], scratch);
            }
        }
        then(&scratch.clip)
    }
}

/// Whether two matrices are the same bit for bit: what decides a uniform's value (a
/// comparison of floats would take -0.0 for 0.0, whose products may differ in sign). A
/// plain loop: it runs at every draw, and iterator adapters stay calls in builds without LTO.
fn same_bits(a: &Mat4, b: &Mat4) -> bool {
    let (a, b) = (a.to_cols_array(), b.to_cols_array());
    let mut difference = 0;
    for i in 0..16 {
        difference |= a[i].to_bits() ^ b[i].to_bits();
    }
    difference == 0
}

/// Whether two units' texture-coordinate work is the same, bit for bit.
fn same_unit(a: &TexCoordUnit, b: &TexCoordUnit) -> bool {
    let same_plane = |p: &[f32; 4], q: &[f32; 4]| p.iter().zip(q).all(|(x, y)| x.to_bits() == y.to_bits());
    let mut same = a.unit == b.unit && a.needs_normal == b.needs_normal;
    for c in 0..4 {
        same &= match (&a.gen[c], &b.gen[c]) {
            (Some(Gen::Object(p)), Some(Gen::Object(q))) | (Some(Gen::Eye(p)), Some(Gen::Eye(q))) => same_plane(p, q),
            (Some(Gen::Sphere), Some(Gen::Sphere))
            | (Some(Gen::Reflection), Some(Gen::Reflection))
            | (Some(Gen::Normal), Some(Gen::Normal))
            | (None, None) => true,
            _ => false,
        };
    }
    same && match (&a.matrix, &b.matrix) {
        (Some(m), Some(n)) => same_bits(m, n),
        (None, None) => true,
        _ => false,
    }
}

/// Everything an unlit draw's per-vertex stage is made from (its program's key and its
/// uniform values read nothing else), kept bit for bit.
struct UnlitInputs {
    modelview: Mat4,
    model_project: Mat4,
    clamp_color: bool,
    fog: Option<FogSource>,
    units: Vec<TexCoordUnit>,
    texgen_inverse: Mat4,
    normalize: bool,
    rescale_normal: bool,
}

impl UnlitInputs {
    fn of(t: &Transform) -> UnlitInputs {
        UnlitInputs {
            modelview: t.modelview,
            model_project: t.model_project,
            clamp_color: t.clamp_color,
            fog: t.fog,
            units: t.texgen.units.to_vec(),
            texgen_inverse: t.texgen.modelview_inverse,
            normalize: t.texgen.normalize,
            rescale_normal: t.texgen.rescale_normal,
        }
    }

    fn matches(&self, t: &Transform) -> bool {
        t.lighting.is_none()
            && self.clamp_color == t.clamp_color
            && self.fog == t.fog
            && self.normalize == t.texgen.normalize
            && self.rescale_normal == t.texgen.rescale_normal
            && same_bits(&self.model_project, &t.model_project)
            && same_bits(&self.modelview, &t.modelview)
            && same_bits(&self.texgen_inverse, &t.texgen.modelview_inverse)
            && self.units.len() == t.texgen.units.len()
            && self.units.iter().zip(t.texgen.units).all(|(a, b)| same_unit(a, b))
    }
}

/// The per-vertex stage of the last draw, kept by its owner (a context) for the next: an
/// unlit draw whose transform state is the same, bit for bit, reuses its program and
/// uniform values instead of making its key, looking the program up in the share group's
/// cache (under its lock) and filling the uniforms again: most of a small draw's fixed
/// cost (a glBegin/glEnd pair of a few vertices). Lit draws are made afresh each time
/// (their uniforms come from the whole lighting state and the glMaterial calls between
/// glBegin and glEnd).
pub struct StageCache {
    /// `None` for a lit stage, which is never reused.
    inputs: Option<UnlitInputs>,
    stage: VertexStage,
}

impl StageCache {
    /// The stage of a draw of `vertex_count` vertices with the state `t`: `previous`'s when
    /// it was made from the same unlit state, otherwise a new one ([`VertexStage::new`]).
    /// Boxed, so that it moves in and out of its owner as a pointer.
    pub fn reuse_or_new(
        previous: Option<Box<StageCache>>,
        t: &Transform,
        vertex_count: usize,
        program: impl FnMut(&VertexKey) -> Arc<CompiledVertex>,
    ) -> Box<StageCache> {
        if let Some(previous) = previous.filter(|p| p.inputs.as_ref().is_some_and(|i| i.matches(t))) {
            return previous;
        }
        let stage = VertexStage::new(t, vertex_count, program);
        Box::new(StageCache { inputs: t.lighting.is_none().then(|| UnlitInputs::of(t)), stage })
    }

    /// The stage, ready to run.
    pub fn stage(&self) -> &VertexStage {
        &self.stage
    }
}

impl Run {
    /// Appends the clip-space vertices of `vertices` to `scratch.clip`.
    fn transform(&self, vertices: &[Vertex], scratch: &mut Scratch) {
        if let Some(direct) = &self.direct {
            return direct.transform(vertices, &mut scratch.clip);
        }
        let same_program = scratch.program.as_ref().is_some_and(|p| Arc::ptr_eq(p, &self.program));
        if !same_program {
            scratch.registers = Registers::default();
            scratch.program = Some(self.program.clone());
        }
        // The uniform values once for the run, not per batch; not again for a run of the
        // program that last ran here with the same uniforms (the batches of a run leave them
        // as they are, and so do the runs: a draw of a few vertices with the state of the
        // draw before it).
        if !same_program || scratch.prepared != self.uniforms {
            self.program.compiled.prepare(&mut scratch.registers, &self.uniforms);
            scratch.prepared.clone_from(&self.uniforms);
        }
        match &self.program.binding {
            Some(binding) => self.transform_bound(binding, vertices, scratch),
            None => self.transform_staged(vertices, scratch),
        }
    }

    /// 16 vertices at a time: their attributes written straight into the program's input
    /// registers, the program run, the clip-space vertices made from its output registers.
    fn transform_bound(&self, binding: &Binding, vertices: &[Vertex], scratch: &mut Scratch) {
        let compiled = &self.program.compiled;
        for batch in vertices.chunks(LANES) {
            let words = scratch.registers.words_mut();
            gather4(batch, words, binding.position, |v| v.position);
            gather4(batch, words, binding.normal, |v| [v.normal[0], v.normal[1], v.normal[2], 0.0]);
            gather4(batch, words, binding.color, |v| v.color);
            gather4(batch, words, binding.secondary_color, |v| v.secondary_color);
            gather4(batch, words, [binding.fog_coord, None, None, None], |v| [v.fog_coord, 0.0, 0.0, 0.0]);
            for (unit, &registers) in binding.tex_coords.iter().enumerate() {
                gather4(batch, words, registers, |v| v.tex_coords[unit]);
            }
            let lanes = if batch.len() == LANES { ALL_LANES } else { (1u16 << batch.len()) - 1 };
            compiled.run_bound_run(&binding.bound, &mut scratch.registers, &self.uniforms, lanes);
            let w = scratch.registers.words();
            let base = scratch.clip.len();
            // The batch's records are made in place in a buffer of sixteen (every field
            // written; the sixteen standard outputs by 4×4 transposes of their words), then
            // appended at once: a record built on the stack and pushed is a copy more.
            let n = batch.len().min(LANES);
            if scratch.batch.len() != LANES {
                scratch.batch = vec![EMPTY; LANES];
            }
            let records = &mut scratch.batch[..n];
            let group = |g: usize| -> [&Word; 4] { std::array::from_fn(|j| &w[binding.standard[4 * g + j] as usize]) };
            transpose_out(group(0), records, |c| &mut c.clip);
            transpose_out(group(1), records, |c| &mut c.eye);
            transpose_out(group(2), records, |c| &mut c.color);
            transpose_out(group(3), records, |c| &mut c.secondary_color);
            let fog = &w[binding.standard[16] as usize];
            // Plain indexed loops: iterator adapters stay calls in builds without LTO.
            for lane in 0..n {
                let (v, c) = (&batch[lane], &mut records[lane]);
                c.back_colors = if self.lit_one_sided { [c.color, c.secondary_color] } else { [[0.0; 4]; 2] };
                // The units' slots (a fixed-function record has no others).
                c.tex_coords = v.tex_coords;
                c.fog_coord = f32::from_bits(fog[lane]);
                c.edge_flag = v.edge_flag;
            }
            scratch.clip.extend_from_slice(records);
            let out = &mut scratch.clip[base..];
            for &(what, r) in &binding.scattered {
                scatter(what, &w[r as usize], out);
            }
        }
    }

    /// 16 vertices at a time gathered into the program's input words, run, and scattered
    /// back (programs [`Binding::of`] does not bind).
    fn transform_staged(&self, vertices: &[Vertex], scratch: &mut Scratch) {
        let generated = &self.program.generated;
        scratch.inputs.resize(generated.inputs.len(), [0; LANES]);
        scratch.outputs.resize(generated.outputs.len(), [0; LANES]);
        for batch in vertices.chunks(LANES) {
            for (word, &source) in scratch.inputs.iter_mut().zip(&generated.inputs) {
                gather(source, batch, word);
            }
            let lanes = if batch.len() == LANES { ALL_LANES } else { (1u16 << batch.len()) - 1 };
            let mut io = Io {
                inputs: &scratch.inputs,
                uniforms: &self.uniforms,
                outputs: &mut scratch.outputs,
                textures: &NoTextures,
            };
            self.program.compiled.run_prepared(&mut scratch.registers, &mut io, lanes);
            let base = scratch.clip.len();
            // What the program does not write: texture coordinates of units without texgen
            // or texture matrix, the edge flag, and the back colours of unlit vertices.
            scratch.clip.extend(batch.iter().map(|v| FixedClipVertex {
                clip: [0.0; 4],
                eye: [0.0; 4],
                color: [0.0; 4],
                secondary_color: [0.0; 4],
                back_colors: [[0.0; 4]; 2],
                tex_coords: v.tex_coords,
                fog_coord: 0.0,
                point_size: 0.0,
                edge_flag: v.edge_flag,
            }));
            let out = &mut scratch.clip[base..];
            for (word, &what) in scratch.outputs.iter().zip(&generated.outputs) {
                scatter(what, word, out);
            }
            if self.lit_one_sided {
                for c in out {
                    c.back_colors = [c.color, c.secondary_color];
                }
            }
        }
    }
}

/// Where a vertex program's inputs and outputs live in its register file
/// ([`Compiled::bind`]), for [`Run::transform_bound`]: per attribute the registers of its
/// components (`None`: not read), the registers of the sixteen outputs every program has
/// first (clip and eye coordinates, primary and secondary colours) and of the fog
/// coordinate, its last output, and the others' (back colours, texture coordinates).
#[derive(Clone, Debug)]
pub struct Binding {
    bound: BoundRun,
    position: [Option<R>; 4],
    normal: [Option<R>; 4],
    color: [Option<R>; 4],
    secondary_color: [Option<R>; 4],
    fog_coord: Option<R>,
    tex_coords: Vec<[Option<R>; 4]>,
    standard: [R; 17],
    scattered: Vec<(VertexOutput, R)>,
}

impl Binding {
    /// The binding of `generated`'s compiled form `compiled`, if it can be bound.
    pub fn of(generated: &VertexProgram, compiled: &Compiled) -> Option<Binding> {
        let outputs = &generated.outputs;
        let standard_layout = outputs.len() >= 17
            && outputs[..16].iter().enumerate().all(|(i, &o)| o == STANDARD_OUTPUTS[i])
            && outputs.last() == Some(&VertexOutput::FogCoord);
        if !standard_layout {
            return None;
        }
        let bound = compiled.bind_run(generated.inputs.len(), outputs.len())?;
        let mut binding = Binding {
            position: [None; 4],
            normal: [None; 4],
            color: [None; 4],
            secondary_color: [None; 4],
            fog_coord: None,
            tex_coords: Vec::new(),
            standard: [0; 17],
            scattered: Vec::new(),
            bound,
        };
        for (&source, &register) in generated.inputs.iter().zip(&binding.bound.inputs) {
            let Some(r) = register else { continue };
            match source {
                VertexInput::Position(k) => binding.position[k as usize & 3] = Some(r),
                VertexInput::Normal(k) => binding.normal[(k as usize).min(2)] = Some(r),
                VertexInput::Color(k) => binding.color[k as usize & 3] = Some(r),
                VertexInput::SecondaryColor(k) => binding.secondary_color[k as usize & 3] = Some(r),
                VertexInput::FogCoord => binding.fog_coord = Some(r),
                VertexInput::TexCoord { unit, k } => {
                    let unit = unit as usize;
                    if binding.tex_coords.len() <= unit {
                        binding.tex_coords.resize(unit + 1, [None; 4]);
                    }
                    binding.tex_coords[unit][k as usize & 3] = Some(r);
                }
                // The lighting-only programs' input, which no vertex program reads.
                VertexInput::Eye(_) => return None,
            }
        }
        let registers = &binding.bound.outputs;
        binding.standard[..16].copy_from_slice(&registers[..16]);
        binding.standard[16] = registers[registers.len() - 1];
        binding.scattered =
            outputs[16..outputs.len() - 1].iter().copied().zip(registers[16..].iter().copied()).collect();
        Some(binding)
    }
}

/// Writes the words of `registers` (the components of an attribute, `None` for those the
/// program does not read) with the attribute `get` of the vertices of `batch` (lanes past
/// the batch get zeros: the program runs them, but nothing reads their results).
#[inline(always)]
fn gather4(batch: &[Vertex], words: &mut [Word], registers: [Option<R>; 4], get: impl Fn(&Vertex) -> [f32; 4]) {
    if registers[0].is_none() && registers[1].is_none() && registers[2].is_none() && registers[3].is_none() {
        return;
    }
    // Four vertices at a time: their attribute vectors are the columns of a matrix whose
    // transpose's columns are four lanes of the component words (glam's SSE shuffles).
    let mut t = [[0.0f32; LANES]; 4];
    let n = batch.len().min(LANES);
    for quad in 0..LANES / 4 {
        let column = |i: usize| {
            let lane = 4 * quad + i;
            if lane < n {
                Vec4::from_array(get(&batch[lane]))
            } else {
                Vec4::ZERO
            }
        };
        let m = Mat4::from_cols(column(0), column(1), column(2), column(3)).transpose();
        for (k, word) in t.iter_mut().enumerate() {
            word[4 * quad..4 * quad + 4].copy_from_slice(&m.col(k).to_array());
        }
        if 4 * quad + 4 >= n {
            break;
        }
    }
    for k in 0..4 {
        if let Some(r) = registers[k] {
            let word = &mut words[r as usize];
            for lane in 0..LANES {
                word[lane] = t[k][lane].to_bits();
            }
        }
    }
}

/// Transposes the four words `words` (a group of four standard outputs) into the field
/// `field` of the records `out` (one per lane).
#[inline(always)]
fn transpose_out(
    words: [&Word; 4],
    out: &mut [FixedClipVertex],
    field: impl Fn(&mut FixedClipVertex) -> &mut [f32; 4],
) {
    for quad in 0..LANES / 4 {
        let column = |j: usize| {
            let w = &words[j];
            let x = |i: usize| f32::from_bits(w[4 * quad + i]);
            Vec4::new(x(0), x(1), x(2), x(3))
        };
        let m = Mat4::from_cols(column(0), column(1), column(2), column(3)).transpose();
        for i in 0..4 {
            if let Some(c) = out.get_mut(4 * quad + i) {
                *field(c) = m.col(i).to_array();
            }
        }
        if 4 * quad + 4 >= out.len() {
            break;
        }
    }
}

/// A record every field of which the batch overwrites.
const EMPTY: FixedClipVertex = FixedClipVertex {
    clip: [0.0; 4],
    eye: [0.0; 4],
    color: [0.0; 4],
    secondary_color: [0.0; 4],
    back_colors: [[0.0; 4]; 2],
    tex_coords: [[0.0; 4]; FIXED_SLOTS],
    fog_coord: 0.0,
    point_size: 0.0,
    edge_flag: false,
};

/// The first sixteen outputs of every vertex program.
const STANDARD_OUTPUTS: [VertexOutput; 16] = {
    let mut outputs = [VertexOutput::FogCoord; 16];
    let mut k = 0;
    while k < 4 {
        outputs[k] = VertexOutput::Clip(k as u8);
        outputs[4 + k] = VertexOutput::Eye(k as u8);
        outputs[8 + k] = VertexOutput::Color(k as u8);
        outputs[12 + k] = VertexOutput::SecondaryColor(k as u8);
        k += 1;
    }
    outputs
};

/// Input word `source` of the vertices of `batch` (lanes past the batch keep old values:
/// the program runs them, but nothing reads their results).
#[inline]
fn gather(source: VertexInput, batch: &[Vertex], word: &mut Word) {
    // Plain indexed loops: iterator adapters stay calls in builds without LTO.
    #[inline(always)]
    fn fill(word: &mut Word, batch: &[Vertex], get: impl Fn(&Vertex) -> f32) {
        let n = batch.len().min(LANES);
        for i in 0..n {
            word[i] = get(&batch[i]).to_bits();
        }
    }
    match source {
        VertexInput::Position(k) => fill(word, batch, |v| v.position[k as usize & 3]),
        VertexInput::Normal(k) => fill(word, batch, |v| v.normal[(k as usize).min(2)]),
        VertexInput::Color(k) => fill(word, batch, |v| v.color[k as usize & 3]),
        VertexInput::SecondaryColor(k) => fill(word, batch, |v| v.secondary_color[k as usize & 3]),
        VertexInput::TexCoord { unit, k } => fill(word, batch, |v| v.tex_coords[unit as usize][k as usize & 3]),
        VertexInput::FogCoord => fill(word, batch, |v| v.fog_coord),
        // The lighting-only programs' input, which no vertex program reads.
        VertexInput::Eye(_) => *word = [0; LANES],
    }
}

/// Output word `what` into the clip-space vertices `out` of a batch.
#[inline]
fn scatter(what: VertexOutput, word: &Word, out: &mut [FixedClipVertex]) {
    #[inline(always)]
    fn put(word: &Word, out: &mut [FixedClipVertex], set: impl Fn(&mut FixedClipVertex, f32)) {
        let n = out.len().min(LANES);
        for i in 0..n {
            set(&mut out[i], f32::from_bits(word[i]));
        }
    }
    match what {
        VertexOutput::Clip(k) => put(word, out, |c, x| c.clip[k as usize & 3] = x),
        VertexOutput::Eye(k) => put(word, out, |c, x| c.eye[k as usize & 3] = x),
        VertexOutput::Color(k) => put(word, out, |c, x| c.color[k as usize & 3] = x),
        VertexOutput::SecondaryColor(k) => put(word, out, |c, x| c.secondary_color[k as usize & 3] = x),
        VertexOutput::BackColor { which, k } => {
            put(word, out, |c, x| c.back_colors[which as usize & 1][k as usize & 3] = x)
        }
        VertexOutput::TexCoord { unit, k } => put(word, out, |c, x| c.tex_coords[unit as usize][k as usize & 3] = x),
        VertexOutput::FogCoord => put(word, out, |c, x| c.fog_coord = x),
    }
}

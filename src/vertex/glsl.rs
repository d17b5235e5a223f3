//! The per-vertex stage of a draw whose program has a GLSL vertex shader (GL 2.1 section
//! 2.15): the shader replaces the fixed-function transform, lighting, texgen, texture
//! matrices, fog coordinate and point size; clipping, perspective division, the viewport,
//! flat shading, two-sided colour selection and primitive assembly stay as they are.
//!
//! [`GlslStage::new`] wires the lowered program's interface once per draw: each input word
//! to the vertex attribute it reads ([`Input`]: the built-in `gl_Vertex` … `gl_FogCoord`, or
//! a generic attribute at its linked location, generic attribute 0 being the position), each
//! output word to the field of the [`ClipVertex`] it becomes ([`Output`]). [`GlslStage::run`]
//! gathers 16 vertices at a time into the input words, runs the compiled program with the
//! uniform words the caller filled (prepared once per run), and scatters its outputs.
//!
//! What GL leaves undefined is made deterministic: an output the shader does not write is 0
//! (the colours too), and without `gl_ClipVertex` user clip planes test `gl_Position`, as
//! Mesa's draw module does. `gl_TexCoord[i]` and user varyings travel in the record's
//! texture coordinate slots at the index the program's varying layout gives them; those
//! beyond the record's slots are not stored.
use super::clip::ClipVertex;
use super::generic::{GenericRows, GenericValues};
use super::Vertex;
use crate::gl::limits::{MAX_TEXTURE_COORDS, MAX_TEXTURE_UNITS};
use crate::glsl::lower::Word as InterfaceWord;
use crate::shader::exec::{Io, NoTextures, ALL_LANES, LANES};
use crate::shader::fast::{Compiled, Registers};

thread_local! {
    /// A thread's register file for [`GlslStage::run`], kept between runs (a run's reads
    /// reach only words its program writes first or zeroes: the contents left by another
    /// program are never read).
    static REGISTERS: std::cell::Cell<Registers> = std::cell::Cell::new(Registers::default());
}

/// What one input word of the program reads (`k`: the component).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Input {
    Position(u8),
    Normal(u8),
    Color(u8),
    SecondaryColor(u8),
    TexCoord {
        unit: u8,
        k: u8,
    },
    FogCoord,
    /// Generic attribute `attribute` (1 and up: 0 is the position).
    Generic {
        attribute: u8,
        k: u8,
    },
    /// A value no vertex carries (`gl_MultiTexCoord` of a unit beyond the fixed-function
    /// ones reads (0, 0, 0, 1)).
    Constant(f32),
}

/// Which colour field an output word writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorOutput {
    Front,
    FrontSecondary,
    Back,
    BackSecondary,
}

/// Where one output word of the program goes (`k`: the component).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Output {
    Position(u8),
    ClipVertex(u8),
    Color(ColorOutput, u8),
    FogFragCoord,
    PointSize,
    /// Scalar `index` of the varying slots (slot `index / 4`, component `index % 4`).
    Varying(u16),
    /// Not stored (a varying the next stage does not read, or beyond the record's slots).
    None,
}

/// A generic attribute's place: its first location, and the rows of each of its columns
/// (a matrix takes one location per column; 4 for a scalar or vector: every word is in its
/// first location).
#[derive(Clone, Copy, Debug)]
pub struct AttributePlace {
    pub location: u32,
    pub column_rows: u32,
}

impl Input {
    /// The input word `word` of a vertex shader; `attribute` gives a user attribute's place.
    pub fn of(word: &InterfaceWord, attribute: impl Fn(&str) -> Option<AttributePlace>) -> Input {
        let k = word.index.min(3) as u8;
        match word.name.as_str() {
            "gl_Vertex" => Input::Position(k),
            "gl_Normal" => Input::Normal(k.min(2)),
            "gl_Color" => Input::Color(k),
            "gl_SecondaryColor" => Input::SecondaryColor(k),
            "gl_FogCoord" => Input::FogCoord,
            name => {
                if let Some(unit) = name.strip_prefix("gl_MultiTexCoord").and_then(|u| u.parse::<usize>().ok()) {
                    return if unit < MAX_TEXTURE_UNITS {
                        Input::TexCoord { unit: unit as u8, k }
                    } else if unit < MAX_TEXTURE_COORDS {
                        // The sets past the fixed-function units travel with the generic
                        // attributes (crate::vertex::generic).
                        Input::Generic { attribute: crate::vertex::generic::tex_coord_slot(unit) as u8, k }
                    } else {
                        Input::Constant(if k == 3 { 1.0 } else { 0.0 })
                    };
                }
                let Some(place) = attribute(name) else { return Input::Constant(0.0) };
                let rows = place.column_rows.max(1);
                let location = place.location + word.index / rows;
                let k = (word.index % rows) as u8;
                match location {
                    0 => Input::Position(k),
                    l if (l as usize) < crate::gl::limits::MAX_VERTEX_ATTRIBS => {
                        Input::Generic { attribute: l as u8, k }
                    }
                    _ => Input::Constant(0.0),
                }
            }
        }
    }
}

impl Output {
    /// The output word `word` of a vertex shader; `varying` gives the scalar index of a word
    /// that travels in the varying slots (`None`: not stored).
    pub fn of(word: &InterfaceWord, varying: impl Fn(&str, u32) -> Option<u16>) -> Output {
        let k = word.index.min(3) as u8;
        match word.name.as_str() {
            "gl_Position" => Output::Position(k),
            "gl_ClipVertex" => Output::ClipVertex(k),
            "gl_FrontColor" => Output::Color(ColorOutput::Front, k),
            "gl_BackColor" => Output::Color(ColorOutput::Back, k),
            "gl_FrontSecondaryColor" => Output::Color(ColorOutput::FrontSecondary, k),
            "gl_BackSecondaryColor" => Output::Color(ColorOutput::BackSecondary, k),
            "gl_FogFragCoord" => Output::FogFragCoord,
            "gl_PointSize" => Output::PointSize,
            name => match varying(name, word.index) {
                Some(index) if (index as usize) < 4 * crate::glsl::varyings::VARYING_SLOTS => Output::Varying(index),
                _ => Output::None,
            },
        }
    }
}

/// A draw's GLSL vertex stage, ready to run.
pub struct GlslStage<'a> {
    compiled: &'a Compiled,
    inputs: Vec<Input>,
    outputs: Vec<Output>,
    uniforms: Vec<u32>,
    /// GL_CLAMP_VERTEX_COLOR: the colour outputs are clamped to [0, 1].
    clamp_color: bool,
    /// GL_VERTEX_PROGRAM_TWO_SIDE: the back colours are gl_BackColor and
    /// gl_BackSecondaryColor (else the front ones, for both faces).
    two_side: bool,
    /// The shader writes gl_ClipVertex (else user clip planes test gl_Position).
    writes_clip_vertex: bool,
    /// Whether any input reads a generic attribute.
    reads_generic: bool,
}

impl<'a> GlslStage<'a> {
    /// The stage of `compiled`, whose input and output words are `inputs` and `outputs`
    /// ([`Input::of`], [`Output::of`]), with the uniform words `uniforms`.
    pub fn new(
        compiled: &'a Compiled,
        inputs: Vec<Input>,
        outputs: Vec<Output>,
        uniforms: Vec<u32>,
        clamp_color: bool,
        two_side: bool,
    ) -> GlslStage<'a> {
        let writes_clip_vertex = outputs.iter().any(|o| matches!(o, Output::ClipVertex(_)));
        let reads_generic = inputs.iter().any(|i| matches!(i, Input::Generic { .. }));
        GlslStage { compiled, inputs, outputs, uniforms, clamp_color, two_side, writes_clip_vertex, reads_generic }
    }

    /// Whether the program reads generic attributes (an array draw then makes their rows).
    pub fn reads_generic(&self) -> bool {
        self.reads_generic
    }

    /// Runs the program on `vertices`, whose generic attributes `rows` and `current` hold
    /// ([`GenericRows::of`]), and hands their clip-space vertices to `then`.
    pub fn run<T>(
        &self,
        vertices: &[Vertex],
        rows: &GenericRows,
        current: &GenericValues,
        then: impl FnOnce(&[ClipVertex]) -> T,
    ) -> T {
        // The thread's file, not a new one per run (a new file is 16 KiB to allocate and
        // zero per draw).
        let mut registers = REGISTERS.take();
        self.compiled.prepare(&mut registers, &self.uniforms);
        let mut inputs = vec![[0u32; LANES]; self.inputs.len()];
        let mut outputs = vec![[0u32; LANES]; self.outputs.len()];
        let mut clip = Vec::with_capacity(vertices.len());
        for batch in vertices.chunks(LANES) {
            for (word, &input) in inputs.iter_mut().zip(&self.inputs) {
                for (lane, v) in batch.iter().enumerate() {
                    word[lane] = read(input, v, rows, current).to_bits();
                }
            }
            let lanes = if batch.len() == LANES { ALL_LANES } else { (1u16 << batch.len()) - 1 };
            for word in outputs.iter_mut() {
                *word = [0; LANES];
            }
            let mut io = Io { inputs: &inputs, uniforms: &self.uniforms, outputs: &mut outputs, textures: &NoTextures };
            self.compiled.run_prepared(&mut registers, &mut io, lanes);
            let base = clip.len();
            clip.extend(batch.iter().map(|v| ClipVertex { edge_flag: v.edge_flag, ..ZERO }));
            let out = &mut clip[base..];
            for (word, &what) in outputs.iter().zip(&self.outputs) {
                for (lane, c) in out.iter_mut().enumerate() {
                    write(what, c, f32::from_bits(word[lane]));
                }
            }
            for c in out.iter_mut() {
                self.finish(c);
            }
        }
        REGISTERS.set(registers);
        then(&clip)
    }

    /// What follows the outputs' stores: the clip vertex, the colours' clamp and the back
    /// colours of one-sided drawing.
    fn finish(&self, c: &mut ClipVertex) {
        if !self.writes_clip_vertex {
            c.eye = c.clip;
        }
        if self.clamp_color {
            let clamp = |v: &mut [f32; 4]| v.iter_mut().for_each(|x| *x = x.clamp(0.0, 1.0));
            clamp(&mut c.color);
            clamp(&mut c.secondary_color);
            c.back_colors.iter_mut().for_each(clamp);
        }
        if !self.two_side {
            c.back_colors = [c.color, c.secondary_color];
        }
    }
}

/// Input `input` of vertex `v`.
#[inline]
fn read(input: Input, v: &Vertex, rows: &GenericRows, current: &GenericValues) -> f32 {
    match input {
        Input::Position(k) => v.position[k as usize & 3],
        Input::Normal(k) => v.normal[(k as usize).min(2)],
        Input::Color(k) => v.color[k as usize & 3],
        Input::SecondaryColor(k) => v.secondary_color[k as usize & 3],
        Input::TexCoord { unit, k } => v.tex_coords[unit as usize % MAX_TEXTURE_UNITS][k as usize & 3],
        Input::FogCoord => v.fog_coord,
        Input::Generic { attribute, k } => rows.of(v, current)[attribute as usize][k as usize & 3],
        Input::Constant(x) => x,
    }
}

/// Stores output `what` of value `x` into `c`.
#[inline]
fn write(what: Output, c: &mut ClipVertex, x: f32) {
    match what {
        Output::Position(k) => c.clip[k as usize & 3] = x,
        Output::ClipVertex(k) => c.eye[k as usize & 3] = x,
        Output::Color(which, k) => {
            let field = match which {
                ColorOutput::Front => &mut c.color,
                ColorOutput::FrontSecondary => &mut c.secondary_color,
                ColorOutput::Back => &mut c.back_colors[0],
                ColorOutput::BackSecondary => &mut c.back_colors[1],
            };
            field[k as usize & 3] = x;
        }
        Output::FogFragCoord => c.fog_coord = x,
        Output::PointSize => c.point_size = x,
        Output::Varying(index) => {
            let index = index as usize;
            if let Some(slot) = c.tex_coords.get_mut(index / 4) {
                slot[index % 4] = x;
            }
        }
        Output::None => {}
    }
}

/// A record of zeros (what the shader does not write).
const ZERO: ClipVertex = ClipVertex {
    clip: [0.0; 4],
    eye: [0.0; 4],
    color: [0.0; 4],
    secondary_color: [0.0; 4],
    back_colors: [[0.0; 4]; 2],
    tex_coords: [[0.0; 4]; crate::glsl::varyings::VARYING_SLOTS],
    fog_coord: 0.0,
    point_size: 0.0,
    edge_flag: true,
};

#[cfg(test)]
mod tests {
    use super::*;

    fn word(name: &str, index: u32) -> InterfaceWord {
        InterfaceWord { name: name.to_string(), index }
    }

    #[test]
    fn inputs_name_built_in_attributes_and_generic_locations() {
        let places = |name: &str| match name {
            "v" => Some(AttributePlace { location: 3, column_rows: 4 }),
            "m" => Some(AttributePlace { location: 5, column_rows: 3 }),
            "p" => Some(AttributePlace { location: 0, column_rows: 4 }),
            _ => None,
        };
        let input = |name: &str, index: u32| Input::of(&word(name, index), places);
        assert_eq!(input("gl_Vertex", 3), Input::Position(3));
        assert_eq!(input("gl_Normal", 2), Input::Normal(2));
        assert_eq!(input("gl_SecondaryColor", 1), Input::SecondaryColor(1));
        assert_eq!(input("gl_FogCoord", 0), Input::FogCoord);
        assert_eq!(input("gl_MultiTexCoord3", 1), Input::TexCoord { unit: 3, k: 1 });
        // Sets beyond the fixed-function ones travel with the generic attributes; sets
        // beyond GL_MAX_TEXTURE_COORDS do not exist and read (0, 0, 0, 1).
        assert_eq!(input("gl_MultiTexCoord6", 2), Input::Generic { attribute: 18, k: 2 });
        assert_eq!(input("gl_MultiTexCoord4", 0), Input::Generic { attribute: 16, k: 0 });
        assert_eq!(input("gl_MultiTexCoord8", 2), Input::Constant(0.0));
        assert_eq!(input("gl_MultiTexCoord8", 3), Input::Constant(1.0));
        assert_eq!(input("v", 2), Input::Generic { attribute: 3, k: 2 });
        // A mat3 takes three locations, one per column of three words.
        assert_eq!(input("m", 0), Input::Generic { attribute: 5, k: 0 });
        assert_eq!(input("m", 4), Input::Generic { attribute: 6, k: 1 });
        assert_eq!(input("m", 8), Input::Generic { attribute: 7, k: 2 });
        // Generic attribute 0 is the position.
        assert_eq!(input("p", 1), Input::Position(1));
    }

    #[test]
    fn outputs_name_record_fields_and_varying_slots() {
        let varying = |name: &str, index: u32| match name {
            "gl_TexCoord[1]" => Some(4 + index as u16),
            "far" => Some(4 * crate::glsl::varyings::VARYING_SLOTS as u16),
            "last" => Some(4 * crate::glsl::varyings::VARYING_SLOTS as u16 - 1),
            _ => None,
        };
        let output = |name: &str, index: u32| Output::of(&word(name, index), varying);
        assert_eq!(output("gl_Position", 2), Output::Position(2));
        assert_eq!(output("gl_ClipVertex", 0), Output::ClipVertex(0));
        assert_eq!(output("gl_BackSecondaryColor", 3), Output::Color(ColorOutput::BackSecondary, 3));
        assert_eq!(output("gl_FogFragCoord", 0), Output::FogFragCoord);
        assert_eq!(output("gl_PointSize", 0), Output::PointSize);
        assert_eq!(output("gl_TexCoord[1]", 3), Output::Varying(7));
        assert_eq!(output("last", 0), Output::Varying(4 * crate::glsl::varyings::VARYING_SLOTS as u16 - 1));
        // Beyond the record's slots, or read by no later stage: not stored.
        assert_eq!(output("far", 0), Output::None);
        assert_eq!(output("unread", 0), Output::None);
    }
}

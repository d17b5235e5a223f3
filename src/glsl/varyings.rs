//! Where a linked program's varyings travel between its stages: each varying word the
//! fragment stage reads gets a place among the vertex record's varying slots, the vector
//! slots that fixed-function texture coordinates use too (slot `k / 4`, component `k % 4`
//! for the scalar index `k`).
//!
//! The rule is fixed so that either stage may be fixed-function (GL 2.1 section 2.15):
//! `gl_TexCoord[i]` is always slot `i`, where fixed-function vertex processing writes unit
//! `i`'s coordinates and fixed-function texturing reads them. The other varyings the fragment
//! shader reads are packed word by word, in the order of the fragment program's input slots,
//! into the components of the slots no `gl_TexCoord` element of either stage names. The
//! built-in varyings with fields of their own in the vertex record (the colours, the fog
//! coordinate, the position, the point size, the clip vertex) and the fragment stage's own
//! inputs (`gl_FragCoord`, `gl_FrontFacing`, `gl_PointCoord`) are not placed here.
//!
//! A vertex output that the fragment stage does not read has no place: the vertex stage
//! need not store it.
use super::lower::{Lowered, Word};

/// Vector slots a vertex record carries between the stages (fixed-function texture
/// coordinates and GLSL varyings alike).
pub const VARYING_SLOTS: usize = 16;

/// Scalar varying components a program may pass (GL_MAX_VARYING_FLOATS).
pub const MAX_VARYING_FLOATS: usize = 4 * VARYING_SLOTS;

/// The built-in varyings whose values travel in fields of their own, not in the slots.
const OWN_FIELDS: [&str; 14] = [
    "gl_Position",
    "gl_PointSize",
    "gl_ClipVertex",
    "gl_FrontColor",
    "gl_BackColor",
    "gl_FrontSecondaryColor",
    "gl_BackSecondaryColor",
    "gl_FogFragCoord",
    "gl_Color",
    "gl_SecondaryColor",
    "gl_FragCoord",
    "gl_FrontFacing",
    "gl_PointCoord",
    "gl_FragDepth",
];

/// The places of a program's varyings.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VaryingLayout {
    /// Each placed word and its scalar index (`slot * 4 + component`).
    pub words: Vec<(Word, u16)>,
}

impl VaryingLayout {
    /// The scalar index of word `index` of the varying element `name` (`v`, `a[2]`,
    /// `gl_TexCoord[1]`); `None` when it has none (see the module docs).
    pub fn index_of(&self, name: &str, index: u32) -> Option<u16> {
        if let Some(slot) = tex_coord_slot(name) {
            return Some((slot * 4 + index) as u16);
        }
        self.words.iter().find(|(w, _)| w.name == name && w.index == index).map(|&(_, k)| k)
    }
}

/// The slot of a `gl_TexCoord[i]` element.
fn tex_coord_slot(name: &str) -> Option<u32> {
    name.strip_prefix("gl_TexCoord[")?.strip_suffix(']')?.parse().ok()
}

/// Whether a word travels in the slots (user varyings and `gl_TexCoord`).
pub fn in_slots(name: &str) -> bool {
    let base = name.split('[').next().unwrap_or(name);
    !OWN_FIELDS.contains(&base)
}

/// Places the varyings of a program whose vertex and fragment stages are `vertex` and
/// `fragment` (`None`: fixed-function). An error when they need more than
/// [`MAX_VARYING_FLOATS`] components, worded as the link's other limits.
pub fn layout(vertex: Option<&Lowered>, fragment: Option<&Lowered>) -> Result<VaryingLayout, String> {
    let mut used = [false; 4 * VARYING_SLOTS];
    let stage_words = vertex.map(|v| &v.outputs).into_iter().chain(fragment.map(|f| &f.inputs));
    for words in stage_words {
        for w in words {
            let Some(slot) = tex_coord_slot(&w.name) else { continue };
            if slot as usize >= VARYING_SLOTS {
                return Err(format!("error: gl_TexCoord[{slot}] is beyond the {VARYING_SLOTS} varying slots\n"));
            }
            used[slot as usize * 4..slot as usize * 4 + 4].fill(true);
        }
    }
    let mut layout = VaryingLayout::default();
    let Some(fragment) = fragment else { return Ok(layout) };
    let mut next = 0usize;
    for w in &fragment.inputs {
        if !in_slots(&w.name) || tex_coord_slot(&w.name).is_some() || layout.words.iter().any(|(p, _)| p == w) {
            continue;
        }
        while next < used.len() && used[next] {
            next += 1;
        }
        if next == used.len() {
            let components = used.iter().filter(|&&u| u).count() + 1;
            return Err(format!(
                "error: fragment shader uses too many input components ({components} > {MAX_VARYING_FLOATS})\n"
            ));
        }
        used[next] = true;
        layout.words.push((w.clone(), next as u16));
    }
    Ok(layout)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shader::ir::{Program, Stage};

    fn lowered(stage: Stage, inputs: &[(&str, u32)], outputs: &[(&str, u32)]) -> Lowered {
        let words = |list: &[(&str, u32)]| list.iter().map(|&(n, i)| Word { name: n.to_string(), index: i }).collect();
        Lowered {
            program: Program::new(stage),
            uniforms: Vec::new(),
            inputs: words(inputs),
            outputs: words(outputs),
            samplers: Vec::new(),
        }
    }

    #[test]
    fn tex_coords_keep_their_slots_and_user_varyings_fill_the_others() {
        let vs = lowered(
            Stage::Vertex,
            &[],
            &[("gl_Position", 0), ("gl_TexCoord[0]", 0), ("gl_TexCoord[0]", 1), ("v", 0), ("v", 1), ("w", 0)],
        );
        let fs = lowered(
            Stage::Fragment,
            &[("gl_Color", 0), ("v", 1), ("gl_TexCoord[2]", 3), ("w", 0), ("v", 0), ("gl_FragCoord", 0)],
            &[("gl_FragColor", 0)],
        );
        let layout = layout(Some(&vs), Some(&fs)).unwrap();
        // Slots 0 and 2 belong to gl_TexCoord; v and w pack into slot 1 in input order.
        assert_eq!(layout.index_of("v", 1), Some(4));
        assert_eq!(layout.index_of("w", 0), Some(5));
        assert_eq!(layout.index_of("v", 0), Some(6));
        assert_eq!(layout.index_of("gl_TexCoord[2]", 3), Some(11));
        assert_eq!(layout.index_of("gl_TexCoord[0]", 1), Some(1));
        assert_eq!(layout.index_of("gl_Color", 0), None);
        assert_eq!(layout.index_of("gl_FragCoord", 0), None);
    }

    #[test]
    fn a_fixed_function_fragment_stage_places_only_tex_coords() {
        let vs = lowered(Stage::Vertex, &[], &[("gl_TexCoord[1]", 0), ("v", 0)]);
        let layout = layout(Some(&vs), None).unwrap();
        assert!(layout.words.is_empty());
        assert_eq!(layout.index_of("gl_TexCoord[1]", 0), Some(4));
        assert_eq!(layout.index_of("v", 0), None);
    }

    #[test]
    fn more_components_than_the_slots_hold_is_an_error() {
        let names: Vec<String> = (0..=MAX_VARYING_FLOATS).map(|i| format!("a[{i}]")).collect();
        let inputs: Vec<(&str, u32)> = names.iter().map(|n| (n.as_str(), 0)).collect();
        let fs = lowered(Stage::Fragment, &inputs, &[]);
        let error = layout(None, Some(&fs)).unwrap_err();
        assert!(error.contains("too many input components"), "{error}");
        let fits = lowered(Stage::Fragment, &inputs[..MAX_VARYING_FLOATS], &[]);
        assert_eq!(layout(None, Some(&fits)).unwrap().words.len(), MAX_VARYING_FLOATS);
    }
}

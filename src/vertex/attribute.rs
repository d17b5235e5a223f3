//! The scalar vertex attributes a draw interpolates beyond color (its varyings): which
//! attribute each is, and its value at a vertex of any stage.
use crate::setup::jobs::line::LineVertex;
use crate::setup::jobs::triangle::WindowVertex;

/// A scalar vertex attribute that a draw's later stages read per fragment: a channel of the
/// secondary color (GL_COLOR_SUM), the fog coordinate (GL_FOG), or a component of a unit's
/// texture coordinates (the unit has a texture target enabled), or the clip w (a GLSL
/// fragment shader's `gl_FragCoord.w` is 1 over it, interpolated perspective-correctly),
/// or a component of `gl_PointCoord` (0 at a vertex; a point sprite replaces it by its s or t,
/// [`crate::vertex::point::PointSprites`]).
///
/// Plain numbers rather than an enum with payloads, so that every byte of a list of them is
/// initialised: valgrind's memcheck (tools/memcheck.sh) flags the optimised code's reads of
/// the payload bytes another variant leaves undefined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Attribute {
    kind: AttributeKind,
    unit: u8,
    component: u8,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AttributeKind {
    SecondaryColor,
    FogCoord,
    TexCoord,
    ClipW,
    PointCoord,
}

impl Attribute {
    pub const FOG_COORD: Attribute = Attribute { kind: AttributeKind::FogCoord, unit: 0, component: 0 };
    pub const CLIP_W: Attribute = Attribute { kind: AttributeKind::ClipW, unit: 0, component: 0 };

    pub fn secondary_color(component: usize) -> Attribute {
        Attribute { kind: AttributeKind::SecondaryColor, unit: 0, component: component as u8 }
    }

    pub fn point_coord(component: usize) -> Attribute {
        Attribute { kind: AttributeKind::PointCoord, unit: 0, component: component as u8 }
    }

    /// The component (s 0, t 1) of a `gl_PointCoord` attribute.
    pub fn point_coordinate(self) -> Option<usize> {
        (self.kind == AttributeKind::PointCoord).then_some(self.component as usize)
    }

    pub fn tex_coord(unit: usize, component: usize) -> Attribute {
        Attribute { kind: AttributeKind::TexCoord, unit: unit as u8, component: component as u8 }
    }

    /// The texture unit and component of a texture coordinate attribute.
    pub fn texture_coordinate(self) -> Option<(usize, usize)> {
        (self.kind == AttributeKind::TexCoord).then_some((self.unit as usize, self.component as usize))
    }

    /// This attribute among a vertex's secondary color, fog coordinate and texture coordinates
    /// (a slot the record lacks, beyond a fixed-function vertex's units, is zero: see
    /// [`crate::vertex::clip::ClipVertex`]). The clip w is 1 over the vertex's `inv_w`.
    #[inline(always)]
    pub fn pick(self, secondary_color: &[f32; 4], fog_coord: f32, tex_coords: &[[f32; 4]], inv_w: f32) -> f32 {
        match self.kind {
            AttributeKind::ClipW => 1.0 / inv_w,
            AttributeKind::PointCoord => 0.0,
            AttributeKind::SecondaryColor => secondary_color[self.component as usize],
            AttributeKind::FogCoord => fog_coord,
            AttributeKind::TexCoord => {
                tex_coords.get(self.unit as usize).map_or(0.0, |t| t[self.component as usize & 3])
            }
        }
    }

    #[inline(always)]
    pub fn of<const N: usize>(self, v: &WindowVertex<N>) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords, v.inv_w)
    }

    /// The attribute at a line or point vertex.
    pub fn of_line<const N: usize>(self, v: &LineVertex<N>) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords, v.inv_w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glsl::varyings::VARYING_SLOTS;

    /// A slot beyond a fixed-function record's units reads as the zero a full record holds
    /// there (a GLSL fragment shader may read gl_TexCoord[5] after fixed-function vertex
    /// processing); the slots the record has read as they are.
    #[test]
    fn slots_a_record_lacks_read_as_zero() {
        let vertex = |tex_coords| WindowVertex::<4> {
            x: 0.0,
            y: 0.0,
            z: 0.0,
            inv_w: 1.0,
            color: [0.0; 4],
            secondary_color: [0.0; 4],
            tex_coords,
            fog_coord: 0.0,
        };
        let v = vertex([[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0], [0.0; 4], [9.0, 10.0, 11.0, 12.0]]);
        assert_eq!(Attribute::tex_coord(1, 2).of(&v), 7.0);
        assert_eq!(Attribute::tex_coord(3, 3).of(&v), 12.0);
        for unit in 4..VARYING_SLOTS {
            assert_eq!(Attribute::tex_coord(unit, 0).of(&v), 0.0);
        }
    }
}

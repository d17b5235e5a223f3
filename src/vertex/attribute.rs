//! The scalar vertex attributes a draw interpolates beyond color (its varyings): which
//! attribute each is, and its value at a vertex of any stage.
use crate::setup::jobs::line::LineVertex;
use crate::setup::jobs::triangle::WindowVertex;

/// A scalar vertex attribute that a draw's later stages read per fragment: a channel of the
/// secondary color (GL_COLOR_SUM), the fog coordinate (GL_FOG), or a component of a unit's
/// texture coordinates (the unit has a texture target enabled).
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
}

impl Attribute {
    pub const FOG_COORD: Attribute = Attribute { kind: AttributeKind::FogCoord, unit: 0, component: 0 };

    pub fn secondary_color(component: usize) -> Attribute {
        Attribute { kind: AttributeKind::SecondaryColor, unit: 0, component: component as u8 }
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
    /// [`crate::vertex::clip::ClipVertex`]).
    #[inline(always)]
    pub fn pick(self, secondary_color: &[f32; 4], fog_coord: f32, tex_coords: &[[f32; 4]]) -> f32 {
        match self.kind {
            AttributeKind::SecondaryColor => secondary_color[self.component as usize],
            AttributeKind::FogCoord => fog_coord,
            AttributeKind::TexCoord => {
                tex_coords.get(self.unit as usize).map_or(0.0, |t| t[self.component as usize & 3])
            }
        }
    }

    #[inline(always)]
    pub fn of<const N: usize>(self, v: &WindowVertex<N>) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords)
    }

    /// The attribute at a line or point vertex.
    pub fn of_line<const N: usize>(self, v: &LineVertex<N>) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords)
    }
}

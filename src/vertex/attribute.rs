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

    /// This attribute among a vertex's secondary color, fog coordinate and texture coordinates.
    /// The clip w is 1 over the vertex's `inv_w`.
    pub fn pick(self, secondary_color: &[f32; 4], fog_coord: f32, tex_coords: &[[f32; 4]], inv_w: f32) -> f32 {
        match self.kind {
            AttributeKind::ClipW => 1.0 / inv_w,
            AttributeKind::PointCoord => 0.0,
            AttributeKind::SecondaryColor => secondary_color[self.component as usize],
            AttributeKind::FogCoord => fog_coord,
            AttributeKind::TexCoord => tex_coords[self.unit as usize][self.component as usize],
        }
    }

    pub fn of(self, v: &WindowVertex) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords, v.inv_w)
    }

    /// The attribute at a line or point vertex.
    pub fn of_line(self, v: &LineVertex) -> f32 {
        self.pick(&v.secondary_color, v.fog_coord, &v.tex_coords, v.inv_w)
    }
}

//! The snapshots a draw hands to vertex processing: the typed inputs of the per-vertex
//! stage ([`Transform`]) and of everything after it ([`Geometry`]), and the line stipple
//! where a draw starts, taken from the context's state once per draw.
use super::super::Context;
use crate::framebuffer::format::DepthEncoding;
use crate::gl::enums::*;
use crate::gl::limits::MAX_LINE_WIDTH;
use crate::gl::types::GLenum;
use crate::vertex::attribute::Attribute;
use crate::vertex::clip::{ClipPlanes, ClipVertex};
use crate::vertex::geometry::Geometry;
use crate::vertex::lighting::NormalScaling;
use crate::vertex::line::LineStipple;
use crate::vertex::point::{point_size, PointAttenuation, PointSprites};
use crate::vertex::texgen::{TexCoordUnit, TexGen};
use crate::vertex::transform::{FogSource, LightingInput, Transform, VertexStage};
use crate::vertex::viewport::Viewport;
use crate::vertex::Vertex;
use glam::Mat4;

impl Context {
    /// GL_LINE_STIPPLE's state at the start of a draw, when enabled.
    pub(super) fn active_line_stipple(&self) -> Option<LineStipple> {
        let lp = &self.state.line_point;
        lp.line_stipple.then_some(LineStipple {
            factor: lp.line_stipple_factor.clamp(1, 256),
            pattern: lp.line_stipple_pattern,
            counter: 0,
        })
    }

    /// What the per-vertex stage reads for a draw into a float (`float_color`) or fixed-point
    /// color buffer, with texgen and the texture matrices applied to the units `tex_units`.
    /// Call after the matrices are validated.
    pub(super) fn transform_input<'a>(&'a self, float_color: bool, tex_units: &'a [TexCoordUnit]) -> Transform<'a> {
        let transform = &self.state.transform;
        let lighting = &self.state.lighting;
        let fog = &self.state.fog;
        let clamp_color = match lighting.clamp_vertex_color {
            GL_FIXED_ONLY => !float_color,
            c => c == GL_TRUE as GLenum,
        };
        let needs_normal = tex_units.iter().any(|u| u.needs_normal);
        // The fog coordinate is computed for fog, and for a GLSL fragment shader reading
        // gl_FogFragCoord (as Mesa's fixed-function vertex program does for what the
        // fragment program reads).
        let fog_coord =
            fog.enabled || (self.fragment_shader().is_some() && self.varyings_needed().contains(&Attribute::FOG_COORD));
        Transform {
            modelview: self.matrices.modelview(),
            model_project: self.matrices.model_project(),
            clamp_color,
            fog: fog_coord.then_some(match (fog.coord_src, fog.distance_mode) {
                (GL_FOG_COORD, _) => FogSource::Attribute,
                (_, GL_EYE_RADIAL_NV) => FogSource::Radial,
                (_, GL_EYE_PLANE) => FogSource::Plane,
                _ => FogSource::PlaneAbsolute,
            }),
            texgen: TexGen {
                units: tex_units,
                modelview_inverse: if needs_normal { self.matrices.modelview_inverse() } else { Mat4::IDENTITY },
                normalize: transform.normalize,
                rescale_normal: transform.rescale_normal,
            },
            lighting: lighting.enabled.then(|| LightingInput {
                state: lighting,
                modelview_inverse: self.matrices.modelview_inverse().to_cols_array(),
                normals: if transform.normalize {
                    NormalScaling::Normalize
                } else if transform.rescale_normal {
                    NormalScaling::Rescale(self.matrices.normal_rescale())
                } else {
                    NormalScaling::None
                },
                material_marks: &self.vertex_input.material_marks,
            }),
        }
    }

    /// The per-vertex stage of a draw of `vertex_count` vertices with the state `input`: its
    /// vertex program from the share group's cache (generated on a miss), and its uniforms.
    pub(super) fn vertex_stage(&self, input: &Transform, vertex_count: usize) -> VertexStage {
        VertexStage::new(input, vertex_count, |key| self.programs.lock().vertex(key))
    }

    /// Vertices to clip space as a draw transforms them, with texgen and the texture matrices
    /// applied to the coordinates of `tex_units` (glRasterPos: every unit).
    pub(in crate::context) fn transform_units(
        &self,
        vertices: &[Vertex],
        float_color: bool,
        tex_units: &[TexCoordUnit],
    ) -> Vec<ClipVertex> {
        let input = self.transform_input(float_color, tex_units);
        self.vertex_stage(&input, vertices.len()).run(vertices, 0, |c| c.iter().map(ClipVertex::widen).collect())
    }

    /// The per-draw geometry constants.
    pub(super) fn geometry(&self, depth_bits: u32, height: usize) -> Geometry {
        // glClipControl decides the depth mapping and the sign of y (ARB_clip_control).
        let viewport = Viewport::new(self.state.viewport.rect, self.depth_transform(), self.viewport_y_sign(), height);
        let (guard_x, guard_y) = viewport.guard_band();
        let transform = &self.state.transform;
        let user = (0..transform.clip_planes.len())
            .filter(|&i| transform.clip_planes[i])
            .map(|i| transform.clip_plane_equations[i].map(|c| c as f32))
            .collect();
        let polygon = &self.state.polygon;
        let planes =
            ClipPlanes { guard_x, guard_y, clip_z: !transform.depth_clamp, zero_to_one: self.clip_zero_to_one(), user };
        let lp = &self.state.line_point;
        let depth = if self.draw_config().depth_stencil.is_float_depth() {
            DepthEncoding::Float
        } else {
            DepthEncoding::Unorm(depth_bits)
        };
        // Mesa's offset stage scales units by twice the depth buffer's resolution; a float
        // buffer's resolution depends on the primitive, so its units are scaled there.
        let units_scale = match depth {
            DepthEncoding::Float => 1.0,
            DepthEncoding::Unorm(0) => 0.0,
            DepthEncoding::Unorm(bits) => (2.0 / ((1u64 << bits) - 1) as f64) as f32,
        };
        let varyings = self.varyings_needed();
        let texture = &self.state.texture;
        let sprite = lp.point_sprite.then(|| {
            let coord_replace = |unit: usize| texture.unit_state.get(unit).is_some_and(|u| u.env.coord_replace);
            PointSprites::new(&varyings, coord_replace, lp.point_sprite_coord_origin == GL_LOWER_LEFT)
        });
        Geometry {
            accuracy: self.accuracy,
            smooth_lines: lp.line_smooth,
            smooth_points: lp.point_smooth,
            sprite,
            smooth_polygons: polygon.smooth,
            per_sample: false,
            varyings,
            viewport,
            line_planes: ClipPlanes { guard_x: 1.0, guard_y: 1.0, ..planes.clone() },
            planes,
            height: height as i32,
            line_width: lp.line_width.min(MAX_LINE_WIDTH),
            point_size: point_size(lp.point_size, lp.point_size_min, lp.point_size_max),
            program_point_size: None,
            point_attenuation: (lp.point_distance_attenuation != [1.0, 0.0, 0.0]).then_some(PointAttenuation {
                size: lp.point_size,
                coefficients: lp.point_distance_attenuation,
                min: lp.point_size_min,
                max: lp.point_size_max,
            }),
            // A culled face's mode does not matter; Mesa gives it the other face's, which
            // decides whether quads are split as filled quads or as outlines.
            mode_front: if polygon.cull_face && polygon.cull_face_mode == GL_FRONT {
                polygon.mode_back
            } else {
                polygon.mode_front
            },
            mode_back: if polygon.cull_face && polygon.cull_face_mode == GL_BACK {
                polygon.mode_front
            } else {
                polygon.mode_back
            },
            offset_line: polygon.offset_line.then_some((polygon.offset_factor, polygon.offset_units * units_scale)),
            offset_point: polygon.offset_point.then_some((polygon.offset_factor, polygon.offset_units * units_scale)),
            first_vertex: self.state.lighting.provoking_vertex == GL_FIRST_VERTEX_CONVENTION,
            flat: self.state.lighting.shade_model == GL_FLAT,
            two_side: self.state.lighting.enabled && self.state.lighting.two_side,
            cull: polygon.cull_face.then_some(polygon.cull_face_mode),
            // GL_UPPER_LEFT mirrors y, and with it every polygon's window winding: the facing
            // rule is mirrored too (ARB_clip_control), as Mesa flips front_ccw.
            front_ccw: (polygon.front_face == GL_CCW) != (self.viewport_y_sign() < 0.0),
            offset: polygon.offset_fill.then_some((polygon.offset_factor, polygon.offset_units)),
            offset_clamp: polygon.offset_clamp,
            depth,
        }
    }
}

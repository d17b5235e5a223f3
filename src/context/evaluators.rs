//! Evaluators (GL 2.1 section 5.1): the one- and two-dimensional maps (glMap1/glMap2), their
//! queries (glGetMap), the grids (glMapGrid) and the commands that evaluate them
//! (glEvalCoord, glEvalPoint, glEvalMesh).
//!
//! glEvalCoord makes the vertex glVertex would make, with each attribute whose map is enabled
//! replaced by the map's value (for the texture coordinates and the vertex, the enabled map of
//! the most components wins; with GL_AUTO_NORMAL a 2D vertex map also gives the normal);
//! the current attributes stay as they were. Without an enabled vertex map it does nothing.
//! The polynomials are in `vertex::bezier`. The enables and grids are GL_EVAL_BIT state
//! (`state.eval`); the maps belong to no attribute group.
//!
//! Deliberate choices where Mesa 22 and the specification differ or the specification is
//! silent:
//! - glEvalMesh2(GL_FILL) draws each row as a GL_TRIANGLE_STRIP, as Mesa does (the
//!   specification's GL_QUAD_STRIP splits into the same triangles; only the flat-shading
//!   provoking vertex of every other triangle differs), and glEvalMesh2(GL_LINE) draws the
//!   rows along u before the columns, as Mesa.
//! - A grid coordinate is `i · Δu + u1` with `Δu = (u2 − u1)/n` in single precision, and exactly
//!   `u2` for `i = n` as the specification says (Mesa accumulates `u += Δu`).
//! - GL_AUTO_NORMAL takes the derivatives with respect to the normalized parameter, as Mesa:
//!   a domain with u2 < u1 does not flip the normal.
//! - GL_MAP*_INDEX maps are stored, queried and enabled, but vertices carry no color index
//!   (there is no color-index rendering), so they change nothing drawn.
//! - glMap1/glMap2 with any target while the active texture unit is not GL_TEXTURE0 is
//!   GL_INVALID_OPERATION, and a NULL `points` GL_INVALID_VALUE, as in Mesa.
use super::get::Value;
use super::Context;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
use crate::vertex::bezier::{self, Point, MAX_EVAL_ORDER};

/// Components per control point of the nine maps, in enum order.
const COMPONENTS: [usize; 9] = [4, 1, 3, 1, 2, 3, 4, 3, 4];
const COLOR_4: usize = 0;
const NORMAL: usize = 2;
const TEXTURE_COORD_1: usize = 3;
const TEXTURE_COORD_4: usize = 6;
const VERTEX_3: usize = 7;
const VERTEX_4: usize = 8;

/// The map a target names: its dimension (1 or 2) and its index in enum order.
fn map_slot(target: GLenum) -> Option<(usize, usize)> {
    match target {
        GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => Some((1, (target - GL_MAP1_COLOR_4) as usize)),
        GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => Some((2, (target - GL_MAP2_COLOR_4) as usize)),
        _ => None,
    }
}

/// Components per control point of a map target (`None` for other enums): how much the API
/// edge reads per point.
pub fn map_components(target: GLenum) -> Option<usize> {
    map_slot(target).map(|(_, index)| COMPONENTS[index])
}

/// Whether glMap can accept these orders and strides for `target`, so that the API edge knows
/// it may read the control points (`Some(components)`).
pub fn readable_map(target: GLenum, dimensions: usize, orders: [i32; 2], strides: [i32; 2]) -> Option<usize> {
    let (dims, index) = map_slot(target)?;
    let k = COMPONENTS[index];
    let valid = |order: i32, stride: i32| (1..=MAX_EVAL_ORDER as i32).contains(&order) && stride >= k as i32;
    (dims == dimensions && (0..dims).all(|d| valid(orders[d], strides[d]))).then_some(k)
}

/// The initial control point of each map (GL 2.1 table 5.1's defaults).
fn initial_point(index: usize) -> Point {
    match index {
        COLOR_4 => [1.0; 4],
        1 => [1.0, 0.0, 0.0, 0.0],
        NORMAL => [0.0, 0.0, 1.0, 0.0],
        TEXTURE_COORD_4 | VERTEX_4 => [0.0, 0.0, 0.0, 1.0],
        _ => [0.0; 4],
    }
}

/// `value`'s first `components` components, the rest (0, 0, 0, 1) as glVertex and glTexCoord
/// fill them.
fn with_defaults(value: Point, components: usize) -> Point {
    let mut out = [0.0, 0.0, 0.0, 1.0];
    out[..components].copy_from_slice(&value[..components]);
    out
}

/// One map: a curve (v order 1) or a surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// The orders along u and v.
    orders: [usize; 2],
    /// u1, u2, v1, v2.
    domain: [f32; 4],
    /// 1/(u2 − u1) and 1/(v2 − v1), kept as Mesa keeps them (parameters map to [0, 1] with
    /// one subtraction and one product).
    inverse_extent: [f32; 2],
    /// The control points, point (i, j) at `i · vorder + j`.
    points: Vec<Point>,
}

impl Map {
    fn initial(index: usize) -> Map {
        Map {
            orders: [1, 1],
            domain: [0.0, 1.0, 0.0, 1.0],
            inverse_extent: [1.0, 1.0],
            points: vec![initial_point(index)],
        }
    }

    fn parameters(&self, [u, v]: [f32; 2]) -> [f32; 2] {
        [(u - self.domain[0]) * self.inverse_extent[0], (v - self.domain[2]) * self.inverse_extent[1]]
    }

    fn point(&self, i: usize, j: usize) -> Point {
        self.points[i * self.orders[1] + j]
    }

    fn curve_at(&self, u: f32) -> Point {
        let [t, _] = self.parameters([u, self.domain[2]]);
        bezier::horner_curve(self.orders[0], |i| self.points[i], t)
    }

    fn surface_at(&self, uv: [f32; 2]) -> Point {
        bezier::horner_surface(self.orders, |i, j| self.point(i, j), self.parameters(uv))
    }
}

/// The eighteen maps of a context, in enum order.
#[derive(Clone, Debug, PartialEq)]
pub struct EvalMaps {
    map1: [Map; 9],
    map2: [Map; 9],
}

impl Default for EvalMaps {
    fn default() -> Self {
        EvalMaps { map1: std::array::from_fn(Map::initial), map2: std::array::from_fn(Map::initial) }
    }
}

/// Grid coordinate `i` of `segments` over [`start`, `end`] (glEvalMesh, glEvalPoint).
fn grid_coordinate(i: i64, segments: i32, [start, end]: [f32; 2]) -> f32 {
    if i == segments as i64 {
        return end;
    }
    let step = (end - start) / segments as f32;
    i as f32 * step + start
}

/// The first enabled map among `candidates` (listed from the most components down).
fn first_enabled(enables: &[bool; 9], candidates: &[usize]) -> Option<usize> {
    candidates.iter().copied().find(|&index| enables[index])
}

const VERTEX_MAPS: [usize; 2] = [VERTEX_4, VERTEX_3];
const TEXTURE_MAPS: [usize; 4] = [TEXTURE_COORD_4, TEXTURE_COORD_4 - 1, TEXTURE_COORD_4 - 2, TEXTURE_COORD_1];

impl Context {
    /// glMap1: `points` are the control points read with the stride (`None` for NULL or when
    /// the edge could not read them because the arguments are invalid).
    pub fn map1(&mut self, target: GLenum, [u1, u2]: [f32; 2], stride: i32, order: i32, points: Option<Vec<Point>>) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some((1, index)) = map_slot(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        if u1 == u2 || !(1..=MAX_EVAL_ORDER as i32).contains(&order) || stride < COMPONENTS[index] as i32 {
            return self.error(GL_INVALID_VALUE);
        }
        if self.state.texture.active_unit != 0 {
            return self.error(GL_INVALID_OPERATION);
        }
        let Some(points) = points.filter(|p| p.len() == order as usize) else {
            return self.error(GL_INVALID_VALUE);
        };
        self.evaluators.map1[index] = Map {
            orders: [order as usize, 1],
            domain: [u1, u2, 0.0, 1.0],
            inverse_extent: [1.0 / (u2 - u1), 1.0],
            points,
        };
    }

    /// glMap2: `points` as for [`Context::map1`], point (i, j) at `i · vorder + j`.
    pub fn map2(
        &mut self,
        target: GLenum,
        domain: [f32; 4],
        strides: [i32; 2],
        orders: [i32; 2],
        points: Option<Vec<Point>>,
    ) {
        if !self.check_outside_begin_end() {
            return;
        }
        let Some((2, index)) = map_slot(target) else {
            return self.error(GL_INVALID_ENUM);
        };
        let [u1, u2, v1, v2] = domain;
        let order_ok = |order: i32| (1..=MAX_EVAL_ORDER as i32).contains(&order);
        let k = COMPONENTS[index] as i32;
        if u1 == u2 || v1 == v2 || !orders.iter().all(|&o| order_ok(o)) || strides.iter().any(|&s| s < k) {
            return self.error(GL_INVALID_VALUE);
        }
        if self.state.texture.active_unit != 0 {
            return self.error(GL_INVALID_OPERATION);
        }
        let orders = orders.map(|o| o as usize);
        let Some(points) = points.filter(|p| p.len() == orders[0] * orders[1]) else {
            return self.error(GL_INVALID_VALUE);
        };
        self.evaluators.map2[index] =
            Map { orders, domain, inverse_extent: [1.0 / (u2 - u1), 1.0 / (v2 - v1)], points };
    }

    /// glGetMap: the control points (GL_COEFF, `k` components each), the order(s) (GL_ORDER)
    /// or the domain (GL_DOMAIN); `None` after an error.
    pub fn get_map(&mut self, target: GLenum, query: GLenum) -> Option<Vec<Value>> {
        if !self.check_outside_begin_end() {
            return None;
        }
        let Some((dimensions, index)) = map_slot(target) else {
            self.error(GL_INVALID_ENUM);
            return None;
        };
        let map = if dimensions == 1 { &self.evaluators.map1[index] } else { &self.evaluators.map2[index] };
        let k = COMPONENTS[index];
        Some(match query {
            GL_COEFF => map.points.iter().flat_map(|p| p[..k].iter().map(|&c| Value::Float(c))).collect(),
            GL_ORDER => map.orders[..dimensions].iter().map(|&o| Value::Int(o as i32)).collect(),
            GL_DOMAIN => map.domain[..2 * dimensions].iter().map(|&d| Value::Float(d)).collect(),
            _ => {
                self.error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// glMapGrid1.
    pub fn map_grid1(&mut self, segments: i32, domain: [f32; 2]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if segments < 1 {
            return self.error(GL_INVALID_VALUE);
        }
        (self.state.eval.grid1_segments, self.state.eval.grid1_domain) = (segments, domain);
    }

    /// glMapGrid2.
    pub fn map_grid2(&mut self, segments: [i32; 2], domain: [f32; 4]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if segments.iter().any(|&n| n < 1) {
            return self.error(GL_INVALID_VALUE);
        }
        (self.state.eval.grid2_segments, self.state.eval.grid2_domain) = (segments, domain);
    }

    /// glEvalCoord1.
    pub fn eval_coord1(&mut self, u: f32) {
        let enables = &self.state.eval.map1;
        let Some(vertex_map) = first_enabled(enables, &VERTEX_MAPS) else {
            return;
        };
        let maps = &self.evaluators.map1;
        let mut vertex = self.state.current.vertex_at([0.0, 0.0, 0.0, 1.0]);
        if enables[COLOR_4] {
            vertex.color = maps[COLOR_4].curve_at(u);
        }
        if enables[NORMAL] {
            let [x, y, z, _] = maps[NORMAL].curve_at(u);
            vertex.normal = [x, y, z];
        }
        if let Some(texture_map) = first_enabled(enables, &TEXTURE_MAPS) {
            vertex.tex_coords[0] = with_defaults(maps[texture_map].curve_at(u), COMPONENTS[texture_map]);
        }
        vertex.position = with_defaults(maps[vertex_map].curve_at(u), COMPONENTS[vertex_map]);
        self.push_open_vertex(vertex);
    }

    /// glEvalCoord2.
    pub fn eval_coord2(&mut self, uv: [f32; 2]) {
        let enables = &self.state.eval.map2;
        let Some(vertex_map) = first_enabled(enables, &VERTEX_MAPS) else {
            return;
        };
        let maps = &self.evaluators.map2;
        let mut vertex = self.state.current.vertex_at([0.0, 0.0, 0.0, 1.0]);
        if enables[COLOR_4] {
            vertex.color = maps[COLOR_4].surface_at(uv);
        }
        if enables[NORMAL] {
            let [x, y, z, _] = maps[NORMAL].surface_at(uv);
            vertex.normal = [x, y, z];
        }
        if let Some(texture_map) = first_enabled(enables, &TEXTURE_MAPS) {
            vertex.tex_coords[0] = with_defaults(maps[texture_map].surface_at(uv), COMPONENTS[texture_map]);
        }
        let map = &maps[vertex_map];
        let position = if self.state.eval.auto_normal {
            let (point, du, dv) = bezier::de_casteljau_surface(map.orders, |i, j| map.point(i, j), map.parameters(uv));
            vertex.normal = bezier::surface_normal(point, du, dv, vertex_map == VERTEX_4);
            point
        } else {
            map.surface_at(uv)
        };
        vertex.position = with_defaults(position, COMPONENTS[vertex_map]);
        self.push_open_vertex(vertex);
    }

    /// glEvalPoint1: glEvalCoord1 at grid coordinate `i`.
    pub fn eval_point1(&mut self, i: i32) {
        let eval = &self.state.eval;
        self.eval_coord1(grid_coordinate(i as i64, eval.grid1_segments, eval.grid1_domain));
    }

    /// glEvalPoint2: glEvalCoord2 at grid coordinates (`i`, `j`).
    pub fn eval_point2(&mut self, i: i32, j: i32) {
        let uv = self.grid2_coordinates(i as i64, j as i64);
        self.eval_coord2(uv);
    }

    fn grid2_coordinates(&self, i: i64, j: i64) -> [f32; 2] {
        let eval = &self.state.eval;
        let [u1, u2, v1, v2] = eval.grid2_domain;
        let [nu, nv] = eval.grid2_segments;
        [grid_coordinate(i, nu, [u1, u2]), grid_coordinate(j, nv, [v1, v2])]
    }

    /// glEvalMesh1: GL_POINT draws the grid points `i1..=i2` as points, GL_LINE as one strip.
    pub fn eval_mesh1(&mut self, mode: GLenum, i1: i32, i2: i32) {
        if !self.check_outside_begin_end() {
            return;
        }
        let primitive = match mode {
            GL_POINT => GL_POINTS,
            GL_LINE => GL_LINE_STRIP,
            _ => return self.error(GL_INVALID_ENUM),
        };
        if first_enabled(&self.state.eval.map1, &VERTEX_MAPS).is_none() {
            return;
        }
        let (segments, domain) = (self.state.eval.grid1_segments, self.state.eval.grid1_domain);
        self.begin(primitive);
        for i in i1 as i64..=i2 as i64 {
            self.eval_coord1(grid_coordinate(i, segments, domain));
        }
        self.end();
    }

    /// glEvalMesh2 over the grid rectangle [`i1`, `i2`] × [`j1`, `j2`]: points, the grid lines
    /// (rows, then columns) or the filled cells (one triangle strip per row of cells).
    pub fn eval_mesh2(&mut self, mode: GLenum, [i1, i2]: [i32; 2], [j1, j2]: [i32; 2]) {
        if !self.check_outside_begin_end() {
            return;
        }
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            return self.error(GL_INVALID_ENUM);
        }
        if first_enabled(&self.state.eval.map2, &VERTEX_MAPS).is_none() {
            return;
        }
        let (is, js) = (i1 as i64..=i2 as i64, j1 as i64..=j2 as i64);
        match mode {
            GL_POINT => {
                self.begin(GL_POINTS);
                for j in js {
                    for i in is.clone() {
                        self.eval_coord2(self.grid2_coordinates(i, j));
                    }
                }
                self.end();
            }
            GL_LINE => {
                for j in js.clone() {
                    self.begin(GL_LINE_STRIP);
                    for i in is.clone() {
                        self.eval_coord2(self.grid2_coordinates(i, j));
                    }
                    self.end();
                }
                for i in is {
                    self.begin(GL_LINE_STRIP);
                    for j in js.clone() {
                        self.eval_coord2(self.grid2_coordinates(i, j));
                    }
                    self.end();
                }
            }
            _ => {
                for j in j1 as i64..j2 as i64 {
                    self.begin(GL_TRIANGLE_STRIP);
                    for i in is.clone() {
                        self.eval_coord2(self.grid2_coordinates(i, j));
                        self.eval_coord2(self.grid2_coordinates(i, j + 1));
                    }
                    self.end();
                }
            }
        }
    }

    /// The glGet values of the evaluator state (the enables are capabilities); `None` for
    /// other pnames.
    pub(crate) fn evaluator_values(&self, pname: GLenum) -> Option<Vec<Value>> {
        let eval = &self.state.eval;
        Some(match pname {
            GL_MAP1_GRID_DOMAIN => eval.grid1_domain.map(Value::Float).to_vec(),
            GL_MAP1_GRID_SEGMENTS => vec![Value::Int(eval.grid1_segments)],
            GL_MAP2_GRID_DOMAIN => eval.grid2_domain.map(Value::Float).to_vec(),
            GL_MAP2_GRID_SEGMENTS => eval.grid2_segments.map(Value::Int).to_vec(),
            GL_MAX_EVAL_ORDER => vec![Value::Int(MAX_EVAL_ORDER as i32)],
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::vertex_input::test_support::context;

    fn floats(values: Option<Vec<Value>>) -> Vec<f32> {
        values.expect("a valid query").iter().map(|v| v.to_float()).collect()
    }

    #[test]
    fn maps_start_as_the_specification_says_and_queries_return_them() {
        let mut ctx = context();
        assert_eq!(floats(ctx.get_map(GL_MAP1_COLOR_4, GL_COEFF)), vec![1.0; 4]);
        assert_eq!(floats(ctx.get_map(GL_MAP2_NORMAL, GL_COEFF)), vec![0.0, 0.0, 1.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP1_VERTEX_4, GL_COEFF)), vec![0.0, 0.0, 0.0, 1.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP2_INDEX, GL_COEFF)), vec![1.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP2_TEXTURE_COORD_2, GL_ORDER)), vec![1.0, 1.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP2_VERTEX_3, GL_DOMAIN)), vec![0.0, 1.0, 0.0, 1.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP1_TEXTURE_COORD_3, GL_DOMAIN)), vec![0.0, 1.0]);
        let points = vec![[1.0, 2.0, 3.0, 0.0], [4.0, 5.0, 6.0, 0.0]];
        ctx.map1(GL_MAP1_VERTEX_3, [2.0, 4.0], 3, 2, Some(points));
        assert_eq!(floats(ctx.get_map(GL_MAP1_VERTEX_3, GL_COEFF)), vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP1_VERTEX_3, GL_ORDER)), vec![2.0]);
        assert_eq!(floats(ctx.get_map(GL_MAP1_VERTEX_3, GL_DOMAIN)), vec![2.0, 4.0]);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_map(GL_MAP1_VERTEX_3, GL_COEFF + 3), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_map(GL_MAP1_GRID_DOMAIN, GL_COEFF), None);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn invalid_maps_set_the_error_and_change_nothing() {
        let mut ctx = context();
        let two = || Some(vec![[0.0; 4]; 2]);
        let cases: [(GLenum, [f32; 2], i32, i32, GLenum); 6] = [
            (GL_MAP2_VERTEX_3, [0.0, 1.0], 3, 2, GL_INVALID_ENUM),
            (GL_MAP1_VERTEX_3, [1.0, 1.0], 3, 2, GL_INVALID_VALUE),
            (GL_MAP1_VERTEX_3, [0.0, 1.0], 2, 2, GL_INVALID_VALUE),
            (GL_MAP1_VERTEX_3, [0.0, 1.0], 3, 0, GL_INVALID_VALUE),
            (GL_MAP1_VERTEX_3, [0.0, 1.0], 3, MAX_EVAL_ORDER as i32 + 1, GL_INVALID_VALUE),
            (GL_TEXTURE_2D, [0.0, 1.0], 3, 2, GL_INVALID_ENUM),
        ];
        for (target, domain, stride, order, error) in cases {
            ctx.map1(target, domain, stride, order, two());
            assert_eq!(ctx.take_error(), error, "{target:#x} {domain:?} {stride} {order}");
        }
        ctx.map1(GL_MAP1_VERTEX_3, [0.0, 1.0], 3, 2, None);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE, "NULL points");
        ctx.map2(GL_MAP2_COLOR_4, [0.0, 1.0, 2.0, 2.0], [4, 8], [2, 1], two());
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE, "v1 == v2");
        ctx.map2(GL_MAP2_COLOR_4, [0.0, 1.0, 0.0, 1.0], [8, 3], [1, 2], two());
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE, "vstride < 4");
        ctx.state.texture.active_unit = 1;
        ctx.map1(GL_MAP1_VERTEX_3, [0.0, 1.0], 3, 2, two());
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION, "active texture unit 1");
        ctx.state.texture.active_unit = 0;
        ctx.begin(GL_POINTS);
        ctx.map1(GL_MAP1_VERTEX_3, [0.0, 1.0], 3, 2, two());
        ctx.map_grid1(2, [0.0, 1.0]);
        ctx.eval_mesh1(GL_POINT, 0, 1);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.evaluators, EvalMaps::default());
        ctx.map_grid2([1, 0], [0.0; 4]);
        assert_eq!(ctx.take_error(), GL_INVALID_VALUE);
        ctx.eval_mesh2(GL_POLYGON, [0, 1], [0, 1]);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        ctx.eval_mesh1(GL_FILL, 0, 1);
        assert_eq!(ctx.take_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.state.eval, Default::default());
        assert!(readable_map(GL_MAP2_VERTEX_4, 2, [30, 1], [4, 4]).is_some());
        assert!(readable_map(GL_MAP2_VERTEX_4, 1, [30, 1], [4, 4]).is_none());
        assert!(readable_map(GL_MAP1_INDEX, 1, [31, 0], [1, 0]).is_none());
    }

    #[test]
    fn eval_coord_replaces_the_mapped_attributes_and_keeps_the_current_ones() {
        let mut ctx = context();
        // A line from (0, 0, 0) to (8, 4, 0) over u in [2, 6]; a color ramp over [0, 1].
        ctx.map1(GL_MAP1_VERTEX_3, [2.0, 6.0], 3, 2, Some(vec![[0.0; 4], [8.0, 4.0, 0.0, 0.0]]));
        ctx.map1(GL_MAP1_COLOR_4, [0.0, 1.0], 4, 2, Some(vec![[0.0, 0.0, 0.0, 1.0], [1.0, 0.5, 0.0, 1.0]]));
        ctx.map1(GL_MAP1_TEXTURE_COORD_2, [0.0, 1.0], 2, 1, Some(vec![[0.25, 0.75, 0.0, 0.0]]));
        ctx.set_color([0.1, 0.2, 0.3, 0.4]);
        ctx.begin(GL_POINTS);
        ctx.eval_coord1(4.0);
        ctx.end();
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
        assert!(ctx.vertex_input.delivered.is_empty(), "no vertex map enabled: nothing happens");
        ctx.begin(GL_POINTS);
        ctx.state.eval.map1[VERTEX_3] = true;
        ctx.eval_coord1(4.0);
        ctx.state.eval.map1[COLOR_4] = true;
        ctx.state.eval.map1[TEXTURE_COORD_1 + 1] = true;
        ctx.eval_coord1(0.5);
        ctx.end();
        let (_, vertices) = &ctx.vertex_input.delivered[0];
        assert_eq!(vertices[0].position, [4.0, 2.0, 0.0, 1.0]);
        assert_eq!(vertices[0].color, [0.1, 0.2, 0.3, 0.4], "the current color");
        assert_eq!(vertices[1].position, [-3.0, -1.5, 0.0, 1.0], "extrapolated below u1");
        assert_eq!(vertices[1].color, [0.5, 0.25, 0.0, 1.0]);
        assert_eq!(vertices[1].tex_coords[0], [0.25, 0.75, 0.0, 1.0]);
        assert_eq!(ctx.state.current.color, [0.1, 0.2, 0.3, 0.4], "current values do not change");
        assert_eq!(ctx.state.current.tex_coords[0], [0.0, 0.0, 0.0, 1.0]);
        // MAP1_VERTEX_4 wins over MAP1_VERTEX_3.
        ctx.map1(GL_MAP1_VERTEX_4, [0.0, 1.0], 4, 1, Some(vec![[1.0, 2.0, 3.0, 2.0]]));
        ctx.state.eval.map1[VERTEX_4] = true;
        ctx.begin(GL_POINTS);
        ctx.eval_coord1(0.5);
        ctx.end();
        assert_eq!(ctx.vertex_input.delivered[1].1[0].position, [1.0, 2.0, 3.0, 2.0]);
    }

    #[test]
    fn meshes_walk_the_grid_and_auto_normal_replaces_the_normal() {
        let mut ctx = context();
        // The bilinear patch of the unit square tilted along z = x over [0, 1]².
        let corners = vec![[0.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 1.0, 0.0], [1.0, 1.0, 1.0, 0.0]];
        ctx.map2(GL_MAP2_VERTEX_3, [0.0, 1.0, 0.0, 1.0], [6, 3], [2, 2], Some(corners));
        ctx.state.eval.map2[VERTEX_3] = true;
        ctx.map_grid2([4, 2], [0.0, 1.0, 0.0, 1.0]);
        ctx.eval_mesh2(GL_FILL, [0, 4], [0, 2]);
        let delivered = std::mem::take(&mut ctx.vertex_input.delivered);
        assert_eq!(delivered.len(), 2, "one strip per row of cells");
        assert!(delivered.iter().all(|(mode, v)| *mode == GL_TRIANGLE_STRIP && v.len() == 10));
        assert_eq!(delivered[1].1[1].position, [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(delivered[1].1[9].position, [1.0, 1.0, 1.0, 1.0]);
        assert_eq!(delivered[0].1[2].position, [0.25, 0.0, 0.25, 1.0]);
        assert_eq!(delivered[0].1[0].normal, [0.0, 0.0, 1.0], "the current normal");
        ctx.state.eval.auto_normal = true;
        ctx.eval_mesh2(GL_LINE, [1, 2], [0, 1]);
        let delivered = std::mem::take(&mut ctx.vertex_input.delivered);
        // Rows along u (2 of 2 points), then columns along v (2 of 2 points).
        assert_eq!(delivered.len(), 4);
        assert_eq!(delivered[0].1[1].position, [0.5, 0.0, 0.5, 1.0]);
        assert_eq!(delivered[2].1[1].position, [0.25, 0.5, 0.25, 1.0]);
        let h = std::f32::consts::FRAC_1_SQRT_2;
        let n = delivered[0].1[0].normal;
        assert!((n[0] + h).abs() < 1e-6 && n[1] == 0.0 && (n[2] - h).abs() < 1e-6, "{n:?}");
        ctx.eval_mesh2(GL_POINT, [0, 1], [2, 2]);
        let (mode, points) = &ctx.vertex_input.delivered[0];
        assert_eq!((*mode, points.len()), (GL_POINTS, 2));
        assert_eq!(points[1].position, [0.25, 1.0, 0.25, 1.0]);
        // glEvalPoint: the same grid coordinates.
        ctx.begin(GL_POINTS);
        ctx.eval_point2(3, 1);
        ctx.end();
        assert_eq!(ctx.vertex_input.delivered[1].1[0].position, [0.75, 0.5, 0.75, 1.0]);
        assert_eq!(ctx.get_floats(GL_MAP2_GRID_DOMAIN), Some(vec![0.0, 1.0, 0.0, 1.0]));
        assert_eq!(ctx.get_integers(GL_MAP2_GRID_SEGMENTS), Some(vec![4, 2]));
        assert_eq!(ctx.get_integers(GL_MAX_EVAL_ORDER), Some(vec![30]));
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }

    #[test]
    fn grid_coordinates_end_exactly_at_the_domain_end() {
        // (0.7 − 0.1)/3 · 3 + 0.1 is not 0.7 in single precision; the last point is.
        assert_eq!(grid_coordinate(3, 3, [0.1, 0.7]), 0.7);
        assert_eq!(grid_coordinate(0, 3, [0.1, 0.7]), 0.1);
        assert_eq!(grid_coordinate(-1, 2, [0.0, 1.0]), -0.5);
        assert_eq!(grid_coordinate(4, 2, [1.0, 0.0]), -1.0);
    }

    #[test]
    fn eval_bit_saves_the_enables_and_grids() {
        let mut ctx = context();
        ctx.push_attrib(GL_EVAL_BIT);
        ctx.set_capability(GL_MAP2_VERTEX_4, true);
        ctx.set_capability(GL_AUTO_NORMAL, true);
        ctx.map_grid1(5, [1.0, 2.0]);
        ctx.map_grid2([3, 4], [1.0, 2.0, 3.0, 4.0]);
        ctx.map1(GL_MAP1_INDEX, [0.0, 1.0], 1, 1, Some(vec![[7.0, 0.0, 0.0, 0.0]]));
        assert_eq!(ctx.get_integers(GL_MAP1_GRID_SEGMENTS), Some(vec![5]));
        ctx.pop_attrib();
        assert_eq!(ctx.state.eval, Default::default());
        assert_eq!(floats(ctx.get_map(GL_MAP1_INDEX, GL_COEFF)), vec![7.0], "maps are not in the group");
        // GL_ENABLE_BIT restores the enables only.
        ctx.push_attrib(GL_ENABLE_BIT);
        ctx.set_capability(GL_MAP1_NORMAL, true);
        ctx.map_grid1(5, [1.0, 2.0]);
        ctx.pop_attrib();
        assert!(!ctx.state.eval.map1[NORMAL]);
        assert_eq!(ctx.state.eval.grid1_segments, 5);
        assert_eq!(ctx.take_error(), GL_NO_ERROR);
    }
}

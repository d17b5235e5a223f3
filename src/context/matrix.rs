//! The matrix stacks (modelview, projection, texture per unit, color) and the single-precision
//! matrix arithmetic of Mesa's `m_matrix.c`, reproduced operation for operation.
//!
//! Matrices are column-major `[f32; 16]` (element `(row, col)` at `col * 4 + row`), as GL
//! hands them over; glLoadMatrixd and the other double entry points convert to float first.
//! Bit-exact agreement with Mesa needs more than the same formulas: Mesa keeps, with each
//! matrix, a set of flags describing what was multiplied into it (rotation, translation,
//! perspective, ...), and those flags decide
//! - whether a product is computed with all 64 terms or with the 3×4 shortcut that assumes a
//!   bottom row of (0, 0, 0, 1) — the two differ in the sign of zeros and with infinities;
//! - which of six inversion algorithms computes the inverse (glClipPlane transforms its plane
//!   by the inverse of the modelview matrix, so the algorithm shows in glGetClipPlane).
//!
//! So [`Matrix`] carries Mesa's flags, type and cached inverse, and updates them at the same
//! points: every operation marks what it changed, and [`Matrix::analyse`] classifies the
//! matrix and recomputes the inverse when it is dirty. Mesa analyses at glPushMatrix, at
//! glClipPlane and when a draw validates state; the draw path calls
//! [`MatrixStacks::validate`] for the latter (see its doc). The inverse keeps Mesa's quirks:
//! the 3-D algorithms leave the bottom row of the previous inverse in place, and a singular
//! matrix has the identity as its inverse.
use crate::gl::limits::{
    MAX_COLOR_STACK_DEPTH, MAX_MODELVIEW_STACK_DEPTH, MAX_PROJECTION_STACK_DEPTH, MAX_TEXTURE_COORDS,
    MAX_TEXTURE_STACK_DEPTH,
};
use glam::Mat4;

/// Mesa's `MAT_FLAG_*` and `MAT_DIRTY_*` bits.
mod flag {
    pub const GENERAL: u32 = 0x1;
    pub const ROTATION: u32 = 0x2;
    pub const TRANSLATION: u32 = 0x4;
    pub const UNIFORM_SCALE: u32 = 0x8;
    pub const GENERAL_SCALE: u32 = 0x10;
    pub const GENERAL_3D: u32 = 0x20;
    pub const PERSPECTIVE: u32 = 0x40;
    pub const SINGULAR: u32 = 0x80;
    pub const DIRTY_TYPE: u32 = 0x100;
    pub const DIRTY_FLAGS: u32 = 0x200;
    pub const DIRTY_INVERSE: u32 = 0x400;

    pub const ANGLE_PRESERVING: u32 = ROTATION | TRANSLATION | UNIFORM_SCALE;
    pub const GEOMETRY: u32 =
        GENERAL | ROTATION | TRANSLATION | UNIFORM_SCALE | GENERAL_SCALE | GENERAL_3D | PERSPECTIVE | SINGULAR;
    pub const THREE_D: u32 = ROTATION | TRANSLATION | UNIFORM_SCALE | GENERAL_SCALE | GENERAL_3D;
    pub const DIRTY: u32 = DIRTY_TYPE | DIRTY_FLAGS | DIRTY_INVERSE;
}

/// Mesa's matrix classification, which picks the inversion algorithm.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MatrixType {
    General,
    Identity,
    NoRotation3d,
    Perspective,
    TwoD,
    NoRotation2d,
    ThreeD,
}

const IDENTITY: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

/// Index of element (row, col) of a column-major matrix.
const fn at(row: usize, col: usize) -> usize {
    col * 4 + row
}

/// The full product `a · b` (Mesa's `matmul4`).
fn matmul4(a: &[f32; 16], b: &[f32; 16]) -> [f32; 16] {
    let mut p = [0.0; 16];
    for i in 0..4 {
        let (ai0, ai1, ai2, ai3) = (a[at(i, 0)], a[at(i, 1)], a[at(i, 2)], a[at(i, 3)]);
        for j in 0..4 {
            p[at(i, j)] = ai0 * b[at(0, j)] + ai1 * b[at(1, j)] + ai2 * b[at(2, j)] + ai3 * b[at(3, j)];
        }
    }
    p
}

/// The product of two matrices whose bottom rows are (0, 0, 0, 1) (Mesa's `matmul34`).
fn matmul34(a: &[f32; 16], b: &[f32; 16]) -> [f32; 16] {
    let mut p = [0.0; 16];
    for i in 0..3 {
        let (ai0, ai1, ai2, ai3) = (a[at(i, 0)], a[at(i, 1)], a[at(i, 2)], a[at(i, 3)]);
        for j in 0..3 {
            p[at(i, j)] = ai0 * b[at(0, j)] + ai1 * b[at(1, j)] + ai2 * b[at(2, j)];
        }
        p[at(i, 3)] = ai0 * b[at(0, 3)] + ai1 * b[at(1, 3)] + ai2 * b[at(2, 3)] + ai3;
    }
    p[at(3, 3)] = 1.0;
    p
}

/// `m` transposed (glLoadTransposeMatrix and the TRANSPOSE queries).
pub fn transpose(m: &[f32; 16]) -> [f32; 16] {
    std::array::from_fn(|i| m[at(i / 4, i % 4)])
}

/// The row vector `v · m` (Mesa's `_mesa_transform_vector`, used for plane equations).
pub fn transform_row_vector(v: [f32; 4], m: &[f32; 16]) -> [f32; 4] {
    std::array::from_fn(|j| v[0] * m[at(0, j)] + v[1] * m[at(1, j)] + v[2] * m[at(2, j)] + v[3] * m[at(3, j)])
}

/// One matrix with Mesa's bookkeeping: what was multiplied into it, its type and its inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrix {
    m: [f32; 16],
    inv: [f32; 16],
    flags: u32,
    kind: MatrixType,
}

impl Default for Matrix {
    fn default() -> Self {
        Matrix { m: IDENTITY, inv: IDENTITY, flags: 0, kind: MatrixType::Identity }
    }
}

impl Matrix {
    /// The elements, column-major.
    pub fn elements(&self) -> &[f32; 16] {
        &self.m
    }

    pub fn to_mat4(&self) -> Mat4 {
        Mat4::from_cols_array(&self.m)
    }

    /// The inverse as of the last [`Matrix::analyse`] (the identity for a singular matrix).
    pub fn inverse(&self) -> &[f32; 16] {
        &self.inv
    }

    /// GL_RESCALE_NORMAL's factor (and GLSL's gl_NormalScale) for this matrix as the
    /// modelview: see [`MatrixStacks::normal_rescale`]. Call on an analysed matrix.
    pub fn normal_rescale(&self) -> f32 {
        if self.flags_within(flag::ROTATION | flag::TRANSLATION) {
            return 1.0;
        }
        let inv = self.inverse();
        let f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
        let f = if f < 1e-12 { 1.0 } else { f };
        1.0 / f.sqrt()
    }

    /// Whether every geometry flag of the matrix is among `allowed` (Mesa's `TEST_MAT_FLAGS`).
    fn flags_within(&self, allowed: u32) -> bool {
        flag::GEOMETRY & !allowed & self.flags == 0
    }

    pub fn is_dirty(&self) -> bool {
        self.flags & flag::DIRTY != 0
    }

    /// glLoadIdentity. The geometry flags survive, as in Mesa.
    pub fn set_identity(&mut self) {
        self.m = IDENTITY;
        self.inv = IDENTITY;
        self.kind = MatrixType::Identity;
        self.flags &= !flag::DIRTY;
    }

    /// glLoadMatrix: nothing changes when the elements are bitwise the same.
    pub fn load(&mut self, m: &[f32; 16]) {
        if self.m.iter().zip(m).any(|(a, b)| a.to_bits() != b.to_bits()) {
            self.m = *m;
            self.flags = flag::GENERAL | flag::DIRTY;
        }
    }

    /// glMultMatrix: always the full product; multiplying by the identity is skipped.
    pub fn multiply(&mut self, m: &[f32; 16]) {
        if m.iter().zip(&IDENTITY).all(|(a, b)| a == b) {
            return;
        }
        self.flags |= flag::GENERAL | flag::DIRTY;
        self.m = matmul4(&self.m, m);
    }

    /// Post-multiplies by a generated matrix whose kind is `flags` (Mesa's `matrix_multf`).
    fn multiply_generated(&mut self, m: &[f32; 16], flags: u32) {
        self.flags |= flags | flag::DIRTY_TYPE | flag::DIRTY_INVERSE;
        self.m = if self.flags_within(flag::THREE_D) { matmul34(&self.m, m) } else { matmul4(&self.m, m) };
    }

    /// glRotate (`angle` in degrees, non-zero). An axis along x, y or z uses only the sign of
    /// that coordinate; another axis is normalised, and one shorter than 1e-4 rotates nothing.
    pub fn rotate(&mut self, angle: f32, x: f32, y: f32, z: f32) {
        // Mesa computes the radians in double precision and takes sinf/cosf of the float.
        let radians = (angle as f64 * std::f64::consts::PI / 180.0) as f32;
        let (s, c) = (radians.sin(), radians.cos());
        let mut r = IDENTITY;
        let mut axis_aligned = true;
        if x == 0.0 && y == 0.0 && z != 0.0 {
            r[at(0, 0)] = c;
            r[at(1, 1)] = c;
            let s = if z < 0.0 { -s } else { s };
            r[at(0, 1)] = -s;
            r[at(1, 0)] = s;
        } else if x == 0.0 && y != 0.0 && z == 0.0 {
            r[at(0, 0)] = c;
            r[at(2, 2)] = c;
            let s = if y < 0.0 { -s } else { s };
            r[at(0, 2)] = s;
            r[at(2, 0)] = -s;
        } else if x != 0.0 && y == 0.0 && z == 0.0 {
            r[at(1, 1)] = c;
            r[at(2, 2)] = c;
            let s = if x < 0.0 { -s } else { s };
            r[at(1, 2)] = -s;
            r[at(2, 1)] = s;
        } else {
            axis_aligned = false;
        }
        if !axis_aligned {
            let mag = (x * x + y * y + z * z).sqrt();
            if mag <= 1.0e-4 {
                return;
            }
            let (x, y, z) = (x / mag, y / mag, z / mag);
            let (xx, yy, zz, xy, yz, zx) = (x * x, y * y, z * z, x * y, y * z, z * x);
            let (xs, ys, zs) = (x * s, y * s, z * s);
            let one_c = 1.0 - c;
            r[at(0, 0)] = (one_c * xx) + c;
            r[at(0, 1)] = (one_c * xy) - zs;
            r[at(0, 2)] = (one_c * zx) + ys;
            r[at(1, 0)] = (one_c * xy) + zs;
            r[at(1, 1)] = (one_c * yy) + c;
            r[at(1, 2)] = (one_c * yz) - xs;
            r[at(2, 0)] = (one_c * zx) - ys;
            r[at(2, 1)] = (one_c * yz) + xs;
            r[at(2, 2)] = (one_c * zz) + c;
        }
        self.multiply_generated(&r, flag::ROTATION);
    }

    /// glFrustum (arguments already validated).
    pub fn frustum(&mut self, left: f32, right: f32, bottom: f32, top: f32, near: f32, far: f32) {
        let x = (2.0 * near) / (right - left);
        let y = (2.0 * near) / (top - bottom);
        let a = (right + left) / (right - left);
        let b = (top + bottom) / (top - bottom);
        let c = -(far + near) / (far - near);
        let d = -(2.0 * far * near) / (far - near);
        let mut f = [0.0; 16];
        f[at(0, 0)] = x;
        f[at(0, 2)] = a;
        f[at(1, 1)] = y;
        f[at(1, 2)] = b;
        f[at(2, 2)] = c;
        f[at(2, 3)] = d;
        f[at(3, 2)] = -1.0;
        self.multiply_generated(&f, flag::PERSPECTIVE);
    }

    /// glOrtho (arguments already validated).
    pub fn ortho(&mut self, left: f32, right: f32, bottom: f32, top: f32, near: f32, far: f32) {
        let mut o = [0.0; 16];
        o[at(0, 0)] = 2.0 / (right - left);
        o[at(0, 3)] = -(right + left) / (right - left);
        o[at(1, 1)] = 2.0 / (top - bottom);
        o[at(1, 3)] = -(top + bottom) / (top - bottom);
        o[at(2, 2)] = -2.0 / (far - near);
        o[at(2, 3)] = -(far + near) / (far - near);
        o[at(3, 3)] = 1.0;
        self.multiply_generated(&o, flag::GENERAL_SCALE | flag::TRANSLATION);
    }

    /// glScale: scales the first three columns in place.
    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        for (col, factor) in [x, y, z].into_iter().enumerate() {
            for row in 0..4 {
                self.m[at(row, col)] *= factor;
            }
        }
        self.flags |=
            if (x - y).abs() < 1e-8 && (x - z).abs() < 1e-8 { flag::UNIFORM_SCALE } else { flag::GENERAL_SCALE };
        self.flags |= flag::DIRTY_TYPE | flag::DIRTY_INVERSE;
    }

    /// glTranslate: updates the last column in place.
    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        let m = &mut self.m;
        for row in 0..4 {
            m[at(row, 3)] = m[at(row, 0)] * x + m[at(row, 1)] * y + m[at(row, 2)] * z + m[at(row, 3)];
        }
        self.flags |= flag::TRANSLATION | flag::DIRTY_TYPE | flag::DIRTY_INVERSE;
    }

    /// Brings the type, flags and inverse up to date (Mesa's `_math_matrix_analyse`).
    pub fn analyse(&mut self) {
        if self.flags & flag::DIRTY_TYPE != 0 {
            if self.flags & flag::DIRTY_FLAGS != 0 {
                self.analyse_from_scratch();
            } else {
                self.analyse_from_flags();
            }
        }
        if self.flags & flag::DIRTY_INVERSE != 0 {
            if self.invert() {
                self.flags &= !flag::SINGULAR;
            } else {
                self.flags |= flag::SINGULAR;
                self.inv = IDENTITY;
            }
            self.flags &= !flag::DIRTY_INVERSE;
        }
        self.flags &= !(flag::DIRTY_FLAGS | flag::DIRTY_TYPE);
    }

    /// Classifies the matrix by its elements alone, after glLoadMatrix or glMultMatrix.
    fn analyse_from_scratch(&mut self) {
        const fn zero(i: u32) -> u32 {
            1 << i
        }
        const fn one(i: u32) -> u32 {
            1 << (i + 16)
        }
        const NO_TRANSLATION: u32 = zero(12) | zero(13) | zero(14);
        const NO_2D_SCALE: u32 = one(0) | one(5);
        const IDENTITY_MASK: u32 = one(0)
            | zero(4)
            | zero(8)
            | zero(12)
            | zero(1)
            | one(5)
            | zero(9)
            | zero(13)
            | zero(2)
            | zero(6)
            | one(10)
            | zero(14)
            | zero(3)
            | zero(7)
            | zero(11)
            | one(15);
        const NO_ROTATION_2D: u32 = zero(4)
            | zero(8)
            | zero(1)
            | zero(9)
            | zero(2)
            | zero(6)
            | one(10)
            | zero(14)
            | zero(3)
            | zero(7)
            | zero(11)
            | one(15);
        const TWO_D: u32 =
            zero(8) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) | zero(3) | zero(7) | zero(11) | one(15);
        const NO_ROTATION_3D: u32 =
            zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | zero(3) | zero(7) | zero(11) | one(15);
        const THREE_D: u32 = zero(3) | zero(7) | zero(11) | one(15);
        const PERSPECTIVE: u32 =
            zero(4) | zero(12) | zero(1) | zero(13) | zero(2) | zero(6) | zero(3) | zero(7) | zero(15);
        let sq = |x: f32| x * x;
        let dot2 = |a: &[f32], b: &[f32]| a[0] * b[0] + a[1] * b[1];
        let dot3 = |a: &[f32], b: &[f32]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let tolerance = sq(1e-6);

        let m = self.m;
        let mut mask = 0u32;
        for (i, &v) in m.iter().enumerate() {
            if v == 0.0 {
                mask |= 1 << i;
            }
        }
        for (i, bit) in [(0, 16), (5, 21), (10, 26), (15, 31)] {
            if m[i] == 1.0 {
                mask |= 1 << bit;
            }
        }
        self.flags &= !flag::GEOMETRY;
        if mask & NO_TRANSLATION != NO_TRANSLATION {
            self.flags |= flag::TRANSLATION;
        }
        if mask == IDENTITY_MASK {
            self.kind = MatrixType::Identity;
        } else if mask & NO_ROTATION_2D == NO_ROTATION_2D {
            self.kind = MatrixType::NoRotation2d;
            if mask & NO_2D_SCALE != NO_2D_SCALE {
                self.flags |= flag::GENERAL_SCALE;
            }
        } else if mask & TWO_D == TWO_D {
            let mm = dot2(&m[0..], &m[0..]);
            let m4m4 = dot2(&m[4..], &m[4..]);
            let mm4 = dot2(&m[0..], &m[4..]);
            self.kind = MatrixType::TwoD;
            if sq(mm - 1.0) > tolerance || sq(m4m4 - 1.0) > tolerance {
                self.flags |= flag::GENERAL_SCALE;
            }
            self.flags |= if sq(mm4) > tolerance { flag::GENERAL_3D } else { flag::ROTATION };
        } else if mask & NO_ROTATION_3D == NO_ROTATION_3D {
            self.kind = MatrixType::NoRotation3d;
            if sq(m[0] - m[5]) < tolerance && sq(m[0] - m[10]) < tolerance {
                if sq(m[0] - 1.0) > tolerance {
                    self.flags |= flag::UNIFORM_SCALE;
                }
            } else {
                self.flags |= flag::GENERAL_SCALE;
            }
        } else if mask & THREE_D == THREE_D {
            let c1 = dot3(&m[0..], &m[0..]);
            let c2 = dot3(&m[4..], &m[4..]);
            let c3 = dot3(&m[8..], &m[8..]);
            let d1 = dot3(&m[0..], &m[4..]);
            self.kind = MatrixType::ThreeD;
            if sq(c1 - c2) < tolerance && sq(c1 - c3) < tolerance {
                if sq(c1 - 1.0) > tolerance {
                    self.flags |= flag::UNIFORM_SCALE;
                }
            } else {
                self.flags |= flag::GENERAL_SCALE;
            }
            if sq(d1) < tolerance {
                // The third column of a rotation is the cross product of the first two.
                let cross = [
                    m[1] * m[6] - m[2] * m[5] - m[8],
                    m[2] * m[4] - m[0] * m[6] - m[9],
                    m[0] * m[5] - m[1] * m[4] - m[10],
                ];
                let len_sq = cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2];
                self.flags |= if len_sq < tolerance { flag::ROTATION } else { flag::GENERAL_3D };
            } else {
                self.flags |= flag::GENERAL_3D;
            }
        } else if mask & PERSPECTIVE == PERSPECTIVE && m[11] == -1.0 {
            self.kind = MatrixType::Perspective;
            self.flags |= flag::GENERAL;
        } else {
            self.kind = MatrixType::General;
            self.flags |= flag::GENERAL;
        }
    }

    /// Classifies the matrix from the flags its operations recorded.
    fn analyse_from_flags(&mut self) {
        let m = &self.m;
        self.kind = if self.flags_within(0) {
            MatrixType::Identity
        } else if self.flags_within(flag::TRANSLATION | flag::UNIFORM_SCALE | flag::GENERAL_SCALE) {
            if m[10] == 1.0 && m[14] == 0.0 {
                MatrixType::NoRotation2d
            } else {
                MatrixType::NoRotation3d
            }
        } else if self.flags_within(flag::THREE_D) {
            if m[8] == 0.0 && m[9] == 0.0 && m[2] == 0.0 && m[6] == 0.0 && m[10] == 1.0 && m[14] == 0.0 {
                MatrixType::TwoD
            } else {
                MatrixType::ThreeD
            }
        } else if m[4] == 0.0
            && m[12] == 0.0
            && m[1] == 0.0
            && m[13] == 0.0
            && m[2] == 0.0
            && m[6] == 0.0
            && m[3] == 0.0
            && m[7] == 0.0
            && m[11] == -1.0
            && m[15] == 0.0
        {
            MatrixType::Perspective
        } else {
            MatrixType::General
        };
    }

    /// Computes the inverse with the algorithm of the matrix's type; false when singular.
    fn invert(&mut self) -> bool {
        match self.kind {
            MatrixType::General | MatrixType::Perspective => self.invert_general(),
            MatrixType::Identity => {
                self.inv = IDENTITY;
                true
            }
            MatrixType::NoRotation3d => self.invert_no_rotation(3),
            MatrixType::NoRotation2d => self.invert_no_rotation(2),
            MatrixType::TwoD | MatrixType::ThreeD => self.invert_3d(),
        }
    }

    /// Gaussian elimination with partial pivoting (Mesa's `invert_matrix_general`). The loops
    /// index columns as Mesa's unrolled code does, so the operations are visibly the same.
    #[allow(clippy::needless_range_loop)]
    fn invert_general(&mut self) -> bool {
        let m = &self.m;
        let mut rows: [[f32; 8]; 4] = std::array::from_fn(|r| {
            let mut row = [0.0; 8];
            for c in 0..4 {
                row[c] = m[at(r, c)];
            }
            row[4 + r] = 1.0;
            row
        });
        // Row "pointers" into `rows`, swapped while pivoting.
        let mut p = [0usize, 1, 2, 3];

        if rows[p[3]][0].abs() > rows[p[2]][0].abs() {
            p.swap(3, 2);
        }
        if rows[p[2]][0].abs() > rows[p[1]][0].abs() {
            p.swap(2, 1);
        }
        if rows[p[1]][0].abs() > rows[p[0]][0].abs() {
            p.swap(1, 0);
        }
        if rows[p[0]][0] == 0.0 {
            return false;
        }
        // Eliminate the first variable.
        let r0 = rows[p[0]];
        let factors = [1, 2, 3].map(|k| rows[p[k]][0] / r0[0]);
        for c in 1..4 {
            let s = r0[c];
            for k in 1..4 {
                rows[p[k]][c] -= factors[k - 1] * s;
            }
        }
        for c in 4..8 {
            let s = r0[c];
            if s != 0.0 {
                for k in 1..4 {
                    rows[p[k]][c] -= factors[k - 1] * s;
                }
            }
        }

        if rows[p[3]][1].abs() > rows[p[2]][1].abs() {
            p.swap(3, 2);
        }
        if rows[p[2]][1].abs() > rows[p[1]][1].abs() {
            p.swap(2, 1);
        }
        if rows[p[1]][1] == 0.0 {
            return false;
        }
        // Eliminate the second variable.
        let r1 = rows[p[1]];
        let (m2, m3) = (rows[p[2]][1] / r1[1], rows[p[3]][1] / r1[1]);
        for c in 2..4 {
            rows[p[2]][c] -= m2 * r1[c];
            rows[p[3]][c] -= m3 * r1[c];
        }
        for c in 4..8 {
            let s = r1[c];
            if s != 0.0 {
                rows[p[2]][c] -= m2 * s;
                rows[p[3]][c] -= m3 * s;
            }
        }

        if rows[p[3]][2].abs() > rows[p[2]][2].abs() {
            p.swap(3, 2);
        }
        if rows[p[2]][2] == 0.0 {
            return false;
        }
        // Eliminate the third variable.
        let r2 = rows[p[2]];
        let m3 = rows[p[3]][2] / r2[2];
        for c in 3..8 {
            rows[p[3]][c] -= m3 * r2[c];
        }
        if rows[p[3]][3] == 0.0 {
            return false;
        }

        // Back substitution.
        let s = 1.0 / rows[p[3]][3];
        for c in 4..8 {
            rows[p[3]][c] *= s;
        }
        let r3 = rows[p[3]];
        let m2 = rows[p[2]][3];
        let s = 1.0 / rows[p[2]][2];
        for c in 4..8 {
            rows[p[2]][c] = s * (rows[p[2]][c] - r3[c] * m2);
        }
        let m1 = rows[p[1]][3];
        for c in 4..8 {
            rows[p[1]][c] -= r3[c] * m1;
        }
        let m0 = rows[p[0]][3];
        for c in 4..8 {
            rows[p[0]][c] -= r3[c] * m0;
        }

        let r2 = rows[p[2]];
        let m1 = rows[p[1]][2];
        let s = 1.0 / rows[p[1]][1];
        for c in 4..8 {
            rows[p[1]][c] = s * (rows[p[1]][c] - r2[c] * m1);
        }
        let m0 = rows[p[0]][2];
        for c in 4..8 {
            rows[p[0]][c] -= r2[c] * m0;
        }

        let r1 = rows[p[1]];
        let m0 = rows[p[0]][1];
        let s = 1.0 / rows[p[0]][0];
        for c in 4..8 {
            rows[p[0]][c] = s * (rows[p[0]][c] - r1[c] * m0);
        }

        for (r, &row) in p.iter().enumerate() {
            for c in 0..4 {
                self.inv[at(r, c)] = rows[row][4 + c];
            }
        }
        true
    }

    /// Inverse of an affine matrix by the adjugate of its 3×3 part (Mesa's
    /// `invert_matrix_3d_general`). The bottom row of the previous inverse is kept.
    fn invert_3d_general(&mut self) -> bool {
        let i = &self.m;
        let e = |r: usize, c: usize| i[at(r, c)];
        let (mut pos, mut neg) = (0.0f32, 0.0f32);
        let mut accumulate = |t: f32| {
            if t >= 0.0 {
                pos += t
            } else {
                neg += t
            }
        };
        accumulate(e(0, 0) * e(1, 1) * e(2, 2));
        accumulate(e(1, 0) * e(2, 1) * e(0, 2));
        accumulate(e(2, 0) * e(0, 1) * e(1, 2));
        accumulate(-e(2, 0) * e(1, 1) * e(0, 2));
        accumulate(-e(1, 0) * e(0, 1) * e(2, 2));
        accumulate(-e(0, 0) * e(2, 1) * e(1, 2));
        let det = pos + neg;
        if det.abs() < 1e-25 {
            return false;
        }
        let det = 1.0 / det;
        let o = &mut self.inv;
        o[at(0, 0)] = (e(1, 1) * e(2, 2) - e(2, 1) * e(1, 2)) * det;
        o[at(0, 1)] = -(e(0, 1) * e(2, 2) - e(2, 1) * e(0, 2)) * det;
        o[at(0, 2)] = (e(0, 1) * e(1, 2) - e(1, 1) * e(0, 2)) * det;
        o[at(1, 0)] = -(e(1, 0) * e(2, 2) - e(2, 0) * e(1, 2)) * det;
        o[at(1, 1)] = (e(0, 0) * e(2, 2) - e(2, 0) * e(0, 2)) * det;
        o[at(1, 2)] = -(e(0, 0) * e(1, 2) - e(1, 0) * e(0, 2)) * det;
        o[at(2, 0)] = (e(1, 0) * e(2, 1) - e(2, 0) * e(1, 1)) * det;
        o[at(2, 1)] = -(e(0, 0) * e(2, 1) - e(2, 0) * e(0, 1)) * det;
        o[at(2, 2)] = (e(0, 0) * e(1, 1) - e(1, 0) * e(0, 1)) * det;
        self.set_inverse_translation();
        true
    }

    /// The translation column of the inverse of an affine matrix whose 3×3 inverse is in place.
    fn set_inverse_translation(&mut self) {
        let (i, o) = (&self.m, &mut self.inv);
        for r in 0..3 {
            o[at(r, 3)] = -(i[at(0, 3)] * o[at(r, 0)] + i[at(1, 3)] * o[at(r, 1)] + i[at(2, 3)] * o[at(r, 2)]);
        }
    }

    /// Inverse of a 3-D (or 2-D) affine matrix (Mesa's `invert_matrix_3d`): by transposing
    /// when the flags say it preserves angles, else by [`Matrix::invert_3d_general`].
    fn invert_3d(&mut self) -> bool {
        if !self.flags_within(flag::ANGLE_PRESERVING) {
            return self.invert_3d_general();
        }
        let i = self.m;
        if self.flags & flag::UNIFORM_SCALE != 0 {
            let scale = i[at(0, 0)] * i[at(0, 0)] + i[at(0, 1)] * i[at(0, 1)] + i[at(0, 2)] * i[at(0, 2)];
            if scale == 0.0 {
                return false;
            }
            let scale = 1.0 / scale;
            for r in 0..3 {
                for c in 0..3 {
                    self.inv[at(c, r)] = scale * i[at(r, c)];
                }
            }
        } else if self.flags & flag::ROTATION != 0 {
            for r in 0..3 {
                for c in 0..3 {
                    self.inv[at(c, r)] = i[at(r, c)];
                }
            }
        } else {
            // A pure translation.
            self.inv = IDENTITY;
            for r in 0..3 {
                self.inv[at(r, 3)] = -i[at(r, 3)];
            }
            return true;
        }
        if self.flags & flag::TRANSLATION != 0 {
            self.set_inverse_translation();
        } else {
            for r in 0..3 {
                self.inv[at(r, 3)] = 0.0;
            }
        }
        true
    }

    /// Inverse of a scale and translation in the first `dims` axes (Mesa's
    /// `invert_matrix_3d_no_rot` and `invert_matrix_2d_no_rot`).
    fn invert_no_rotation(&mut self, dims: usize) -> bool {
        let i = &self.m;
        if (0..dims).any(|d| i[at(d, d)] == 0.0) {
            return false;
        }
        let mut o = IDENTITY;
        for d in 0..dims {
            o[at(d, d)] = 1.0 / i[at(d, d)];
        }
        if self.flags & flag::TRANSLATION != 0 {
            for d in 0..dims {
                o[at(d, 3)] = -(i[at(d, 3)] * o[at(d, d)]);
            }
        }
        self.inv = o;
        true
    }
}

/// Which stack glMatrixMode selected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StackId {
    Modelview,
    Projection,
    /// The texture stack of a unit.
    Texture(usize),
    Color,
}

/// The four kinds of matrix stack; each starts with the identity and is never empty.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStacks {
    modelview: Vec<Matrix>,
    projection: Vec<Matrix>,
    /// One per texture coordinate set (GL 2.0 section 2.11.2).
    texture: [Vec<Matrix>; MAX_TEXTURE_COORDS],
    color: Vec<Matrix>,
}

impl Default for MatrixStacks {
    fn default() -> Self {
        MatrixStacks {
            modelview: vec![Matrix::default()],
            projection: vec![Matrix::default()],
            texture: std::array::from_fn(|_| vec![Matrix::default()]),
            color: vec![Matrix::default()],
        }
    }
}

/// The top of a stack.
fn top(stack: &[Matrix]) -> Matrix {
    stack.last().copied().unwrap_or_default()
}

impl MatrixStacks {
    pub fn modelview(&self) -> Mat4 {
        top(&self.modelview).to_mat4()
    }

    pub fn projection(&self) -> Mat4 {
        top(&self.projection).to_mat4()
    }

    pub fn texture(&self, unit: usize) -> Mat4 {
        self.texture.get(unit).map_or(Mat4::IDENTITY, |s| top(s).to_mat4())
    }

    pub fn color(&self) -> Mat4 {
        top(&self.color).to_mat4()
    }

    /// The inverse of the modelview matrix as Mesa keeps it (for normals and eye planes);
    /// valid after [`MatrixStacks::validate`].
    pub fn modelview_inverse(&self) -> Mat4 {
        Mat4::from_cols_array(top(&self.modelview).inverse())
    }

    /// GL_RESCALE_NORMAL's factor as Mesa computes it: 1 for a length-preserving modelview
    /// (rotations and translations by its flags), else 1/√(f) with f the squared length of
    /// the inverse's third row (1 when f < 10⁻¹²). Call after [`MatrixStacks::validate`].
    pub fn normal_rescale(&self) -> f32 {
        top(&self.modelview).normal_rescale()
    }

    /// Projection × modelview as Mesa computes its combined matrix (`_ModelProjectMatrix`):
    /// the 3×4 product when both are affine by their flags. Call after
    /// [`MatrixStacks::validate`].
    pub fn model_project(&self) -> Mat4 {
        Mat4::from_cols_array(&self.model_project_matrix().m)
    }

    /// [`MatrixStacks::model_project`] as a matrix of its own with the flags Mesa gives the
    /// product (`_math_matrix_mul_matrix`: the union of both, type and inverse dirty), not yet
    /// analysed. Mesa's combined matrix keeps its previous inverse between products (which
    /// the 3-D inversions partly leave in place); this one starts from the identity.
    pub fn model_project_matrix(&self) -> Matrix {
        let (p, m) = (top(&self.projection), top(&self.modelview));
        let flags = p.flags | m.flags | flag::DIRTY_TYPE | flag::DIRTY_INVERSE;
        let combined = Matrix { flags, ..Matrix::default() };
        let product = if combined.flags_within(flag::THREE_D) { matmul34(&p.m, &m.m) } else { matmul4(&p.m, &m.m) };
        Matrix { m: product, ..combined }
    }

    /// What a draw (or any command that validates state in Mesa: glBegin, glDrawArrays,
    /// glRasterPos, glReadPixels, ...) does to the matrices before using them: analyses the
    /// modelview, projection and every texture matrix that changed. The analysis can change
    /// the flags that later products depend on, so it must happen where Mesa's does.
    pub fn validate(&mut self) {
        self.top_mut(StackId::Modelview).analyse();
        self.top_mut(StackId::Projection).analyse();
        for unit in 0..MAX_TEXTURE_COORDS {
            self.top_mut(StackId::Texture(unit)).analyse();
        }
    }

    /// The stack `id` names; `None` for a texture unit that does not exist.
    pub fn stack(&self, id: StackId) -> Option<&Vec<Matrix>> {
        match id {
            StackId::Modelview => Some(&self.modelview),
            StackId::Projection => Some(&self.projection),
            StackId::Texture(unit) => self.texture.get(unit),
            StackId::Color => Some(&self.color),
        }
    }

    fn stack_mut(&mut self, id: StackId) -> &mut Vec<Matrix> {
        match id {
            StackId::Modelview => &mut self.modelview,
            StackId::Projection => &mut self.projection,
            StackId::Texture(unit) => &mut self.texture[unit.min(MAX_TEXTURE_COORDS - 1)],
            StackId::Color => &mut self.color,
        }
    }

    /// The top matrix of stack `id`.
    pub fn top(&self, id: StackId) -> Matrix {
        self.stack(id).map_or_else(Matrix::default, |s| top(s))
    }

    /// The top matrix of stack `id`, to change.
    pub fn top_mut(&mut self, id: StackId) -> &mut Matrix {
        let stack = self.stack_mut(id);
        if stack.is_empty() {
            stack.push(Matrix::default());
        }
        let last = stack.len() - 1;
        &mut stack[last]
    }

    /// Number of matrices on stack `id` (GL_*_STACK_DEPTH).
    pub fn depth(&self, id: StackId) -> usize {
        self.stack(id).map_or(1, Vec::len)
    }

    /// The most matrices stack `id` holds (GL_MAX_*_STACK_DEPTH).
    pub fn max_depth(id: StackId) -> usize {
        match id {
            StackId::Modelview => MAX_MODELVIEW_STACK_DEPTH,
            StackId::Projection => MAX_PROJECTION_STACK_DEPTH,
            StackId::Texture(_) => MAX_TEXTURE_STACK_DEPTH,
            StackId::Color => MAX_COLOR_STACK_DEPTH,
        }
    }

    /// glPushMatrix: false when the stack is full. The top is analysed first, as in Mesa.
    pub fn push(&mut self, id: StackId) -> bool {
        if self.depth(id) >= Self::max_depth(id) {
            return false;
        }
        let top = self.top_mut(id);
        if top.is_dirty() {
            top.analyse();
        }
        let copy = *top;
        self.stack_mut(id).push(copy);
        true
    }

    /// glPopMatrix: false when only one matrix is left.
    pub fn pop(&mut self, id: StackId) -> bool {
        let stack = self.stack_mut(id);
        if stack.len() <= 1 {
            return false;
        }
        stack.pop();
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bits(m: &[f32; 16]) -> [u32; 16] {
        m.map(f32::to_bits)
    }

    fn matrix(m: [f32; 16]) -> Matrix {
        let mut matrix = Matrix::default();
        matrix.load(&m);
        matrix
    }

    #[test]
    fn translate_and_scale_update_columns_in_place() {
        let mut m = Matrix::default();
        m.scale(0.5, 2.5, -0.25);
        m.translate(1e10, 3.0, 4.0);
        let e = m.elements();
        assert_eq!(e[0], 0.5);
        assert_eq!(e[5], 2.5);
        assert_eq!(e[10], -0.25);
        // 0 · -0.25 keeps the sign of the factor: Mesa reads back -0 there.
        assert_eq!(e[8].to_bits(), (-0.0f32).to_bits());
        assert_eq!(e[12], 5e9);
        assert_eq!(e[13], 7.5);
        assert_eq!(e[14], -1.0);
        assert_eq!(e[15], 1.0);
    }

    #[test]
    fn axis_rotations_use_only_the_sign_of_the_axis() {
        let mut a = Matrix::default();
        a.rotate(30.0, 0.0, 0.0, 5.0);
        let mut b = Matrix::default();
        b.rotate(30.0, 0.0, 0.0, 1.0);
        assert_eq!(bits(a.elements()), bits(b.elements()));
        let mut c = Matrix::default();
        c.rotate(30.0, 0.0, 0.0, -2.0);
        let mut d = Matrix::default();
        d.rotate(-30.0, 0.0, 0.0, 1.0);
        assert_eq!(bits(c.elements()), bits(d.elements()));
        let (s, co) = ((30.0f64.to_radians() as f32).sin(), (30.0f64.to_radians() as f32).cos());
        assert_eq!(b.elements()[0], co);
        assert_eq!(b.elements()[1], s);
        assert_eq!(b.elements()[4], -s);
        // 90 degrees about x: cos is not exactly zero in single precision.
        let mut x = Matrix::default();
        x.rotate(90.0, 1.0, 0.0, 0.0);
        assert_eq!(x.elements()[5], -4.371139e-8);
        assert_eq!(x.elements()[6], 1.0);
        assert_eq!(x.elements()[9], -1.0);
    }

    #[test]
    fn rotation_about_an_arbitrary_axis_is_normalised() {
        let mut m = Matrix::default();
        m.rotate(120.0, 1.0, 1.0, 1.0);
        // 120 degrees about (1,1,1) permutes the axes: x → y → z.
        let e = m.elements();
        for (i, expected) in [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0].iter().enumerate() {
            assert!((e[i] - expected).abs() < 1e-6, "{i}: {}", e[i]);
        }
        assert_eq!(&e[12..], &[0.0, 0.0, 0.0, 1.0]);
        let mut tiny = Matrix::default();
        tiny.rotate(45.0, 1e-5, 1e-5, 1e-5);
        assert_eq!(tiny, Matrix::default());
        let mut zero = Matrix::default();
        zero.rotate(45.0, 0.0, 0.0, 0.0);
        assert_eq!(zero, Matrix::default());
    }

    #[test]
    fn frustum_and_ortho_build_the_standard_matrices() {
        let mut f = Matrix::default();
        f.frustum(-1.0, 1.0, -2.0, 2.0, 1.0, 3.0);
        let expected = [1.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, -2.0, -1.0, 0.0, 0.0, -3.0, 0.0];
        assert_eq!(f.elements(), &expected);
        let mut o = Matrix::default();
        o.ortho(0.0, 4.0, 0.0, 2.0, -1.0, 1.0);
        // -(far + near) is -0, but the 3×4 product adds the identity's +0 translation.
        let expected = [0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, -1.0, -1.0, 0.0, 1.0];
        assert_eq!(bits(o.elements()), bits(&expected));
    }

    #[test]
    fn the_3x4_product_differs_from_the_full_one_only_in_zero_signs() {
        // After glScale(-1, -1, -1), row 0 is (-1, -0, -0, 0). Rotating by 90 degrees about z,
        // element (0, 2) sums (-1)·0 + (-0)·0 + (-0)·1 = -0 in the 3×4 product; the full
        // product adds 0·0 = +0 and ends at +0.
        let mut affine = Matrix::default();
        affine.scale(-1.0, -1.0, -1.0);
        affine.rotate(90.0, 0.0, 0.0, 1.0);
        let mut general = Matrix::default();
        general.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0);
        general.set_identity(); // the perspective flag survives glLoadIdentity, as in Mesa
        general.scale(-1.0, -1.0, -1.0);
        general.rotate(90.0, 0.0, 0.0, 1.0);
        assert_eq!(affine.elements()[at(0, 2)].to_bits(), (-0.0f32).to_bits());
        assert_eq!(general.elements()[at(0, 2)].to_bits(), 0.0f32.to_bits());
        // The full product also computes the bottom row: (-0)·c + (-0)·s + ... = +0.
        assert_eq!(affine.elements()[at(3, 0)].to_bits(), 0.0f32.to_bits());
        for i in 0..16 {
            assert_eq!(affine.elements()[i], general.elements()[i], "{i}");
        }
    }

    #[test]
    fn load_of_the_same_bits_changes_nothing_and_mult_by_identity_is_skipped() {
        let mut m = Matrix::default();
        m.load(&IDENTITY);
        assert_eq!(m, Matrix::default());
        m.multiply(&IDENTITY);
        assert_eq!(m, Matrix::default());
        let mut negative_zero = IDENTITY;
        negative_zero[4] = -0.0;
        m.multiply(&negative_zero); // equal as floats: still skipped
        assert_eq!(m, Matrix::default());
        m.load(&negative_zero); // different bits: loaded, and marked general
        assert_eq!(m.elements()[4].to_bits(), (-0.0f32).to_bits());
        assert!(m.is_dirty());
    }

    #[test]
    fn analysis_classifies_and_inverts_each_kind() {
        let mut t = Matrix::default();
        t.translate(2.0, 3.0, 4.0);
        t.analyse();
        assert_eq!(t.kind, MatrixType::NoRotation3d);
        assert_eq!(&t.inverse()[12..], &[-2.0, -3.0, -4.0, 1.0]);

        let mut s = Matrix::default();
        s.scale(2.0, 4.0, 1.0);
        s.translate(1.0, 1.0, 0.0);
        s.analyse();
        assert_eq!(s.kind, MatrixType::NoRotation2d);
        assert_eq!(s.inverse(), &[0.5, 0.0, 0.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, -1.0, 0.0, 1.0]);

        let mut r = Matrix::default();
        r.rotate(90.0, 1.0, 0.0, 0.0);
        r.analyse();
        assert_eq!(r.kind, MatrixType::ThreeD);
        assert_eq!(bits(r.inverse()), bits(&transpose(r.elements())));

        let mut p = Matrix::default();
        p.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 3.0);
        p.analyse();
        assert_eq!(p.kind, MatrixType::Perspective);
        let product = matmul4(p.elements(), p.inverse());
        for (i, v) in product.iter().enumerate() {
            assert!((v - IDENTITY[i]).abs() < 1e-6, "{i}: {v}");
        }

        let mut singular = matrix([1.0, 2.0, 3.0, 4.0, 2.0, 4.0, 6.0, 8.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        singular.analyse();
        assert_eq!(singular.inverse(), &IDENTITY);
        assert_ne!(singular.flags & flag::SINGULAR, 0);
        // A singular matrix forces full products afterwards.
        singular.set_identity();
        assert!(!singular.flags_within(flag::THREE_D));
    }

    #[test]
    fn general_inversion_pivots() {
        // The first pivot must come from row 2.
        let mut m = matrix([0.0, 1.0, 4.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 1.0, 0.0, 1.0, 1.0, 1.0, 2.0]);
        m.analyse();
        assert_eq!(m.kind, MatrixType::General);
        let product = matmul4(m.elements(), m.inverse());
        for (i, v) in product.iter().enumerate() {
            assert!((v - IDENTITY[i]).abs() < 1e-6, "{i}: {v}");
        }
    }

    #[test]
    fn uniform_scale_rotation_inverts_by_scaled_transpose() {
        let mut m = Matrix::default();
        m.rotate(90.0, 0.0, 0.0, 1.0);
        m.scale(2.0, 2.0, 2.0);
        m.analyse();
        let inv = m.inverse();
        // (R·2)⁻¹ = Rᵀ/2, from 1/(row 0 · row 0) exactly.
        assert_eq!(inv[1], m.elements()[4] * 0.25);
        assert_eq!(inv[0], m.elements()[0] * 0.25);
    }

    #[test]
    fn row_vector_transform_and_transpose() {
        let m: [f32; 16] = std::array::from_fn(|i| i as f32);
        assert_eq!(transform_row_vector([1.0, 0.0, 0.0, 0.0], &m), [0.0, 4.0, 8.0, 12.0]);
        assert_eq!(transform_row_vector([0.0, 0.0, 0.0, 1.0], &m), [3.0, 7.0, 11.0, 15.0]);
        assert_eq!(transpose(&m)[1], 4.0);
        assert_eq!(transpose(&transpose(&m)), m);
    }

    #[test]
    fn stacks_push_copies_and_refuse_beyond_their_depth() {
        let mut stacks = MatrixStacks::default();
        stacks.top_mut(StackId::Modelview).translate(1.0, 2.0, 3.0);
        assert!(stacks.push(StackId::Modelview));
        // The pushed-from matrix was analysed.
        assert!(!stacks.modelview[0].is_dirty());
        assert_eq!(stacks.modelview[0], stacks.modelview[1]);
        for _ in 2..MAX_MODELVIEW_STACK_DEPTH {
            assert!(stacks.push(StackId::Modelview));
        }
        assert!(!stacks.push(StackId::Modelview));
        assert_eq!(stacks.depth(StackId::Modelview), MAX_MODELVIEW_STACK_DEPTH);
        while stacks.pop(StackId::Modelview) {}
        assert_eq!(stacks.depth(StackId::Modelview), 1);
        assert_eq!(stacks.modelview().w_axis.x, 1.0);
        assert!(!stacks.pop(StackId::Texture(3)));
        for _ in 1..MAX_TEXTURE_STACK_DEPTH {
            assert!(stacks.push(StackId::Texture(3)));
        }
        assert!(!stacks.push(StackId::Texture(3)));
        assert_eq!(stacks.depth(StackId::Texture(2)), 1);
    }

    #[test]
    fn model_project_uses_the_affine_product_for_affine_matrices() {
        let mut stacks = MatrixStacks::default();
        stacks.top_mut(StackId::Projection).scale(-1.0, -1.0, -1.0);
        stacks.top_mut(StackId::Modelview).rotate(90.0, 0.0, 0.0, 1.0);
        stacks.validate();
        let (p, m) = (*stacks.top(StackId::Projection).elements(), *stacks.top(StackId::Modelview).elements());
        assert_eq!(bits(&stacks.model_project().to_cols_array()), bits(&matmul34(&p, &m)));
        assert_eq!(stacks.model_project().to_cols_array()[at(0, 2)].to_bits(), (-0.0f32).to_bits());
        stacks.top_mut(StackId::Projection).set_identity();
        stacks.top_mut(StackId::Projection).frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0);
        stacks.validate();
        let p = *stacks.top(StackId::Projection).elements();
        assert_eq!(bits(&stacks.model_project().to_cols_array()), bits(&matmul4(&p, &m)));
    }
}

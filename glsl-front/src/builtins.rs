//! The built-ins of GLSL 1.10 and 1.20 (chapters 7 and 8 of the specifications): every
//! built-in function as a signature table, and the compatibility profile's built-in
//! variables, constants and uniform state with their types and the stage each belongs to.
//!
//! Signatures are written once as short lines (`G mix(G,G,float)`) and expanded over the
//! generic types, the way the specification itself writes them: `G` is genType (float,
//! vec2, vec3, vec4), `I` its integer form (int, ivec2, ivec3, ivec4), `v`/`iv`/`bv` are
//! the 2- to 4-component float/int/bool vectors of one size.
//!
//! Beyond the specifications, as Mesa 22: the integer `abs`, `sign`, `min`, `max` and
//! `clamp` of GLSL 1.30 are there in 1.10 and 1.20 too (Mesa compiles them there, and
//! shaders written against it call `min(int, int)`, e.g. piglit's
//! vs-loop-variable-iteration-limit-unroll); no other 1.30 built-in is, and there is still
//! no implicit int-to-float conversion in 1.10 (`min(int, float)` is an error, as in Mesa). A leading `v:` or `f:` limits a signature to vertex or fragment shaders (the `Lod`
//! texture lookups, `ftransform`; the bias forms, the derivatives). The table is built
//! once per process.

use super::hir::{Scalar, Stage, StructType, Type, Value, BOOL, FLOAT, INT};
use super::lex::Sampler;
use std::collections::HashMap;
use std::sync::Arc;
use std::sync::OnceLock;

/// One built-in function signature.
#[derive(Clone, Debug, PartialEq)]
pub struct Signature {
    pub name: &'static str,
    pub ret: Type,
    pub params: Vec<Type>,
    pub stage: Option<Stage>,
    /// The first GLSL version that has it (110 or 120).
    pub version: u32,
}

const FUNCTIONS: &str = "
G radians(G)
G degrees(G)
G sin(G)
G cos(G)
G tan(G)
G asin(G)
G acos(G)
G atan(G,G)
G atan(G)
G pow(G,G)
G exp(G)
G log(G)
G exp2(G)
G log2(G)
G sqrt(G)
G inversesqrt(G)
G abs(G)
G sign(G)
G floor(G)
G ceil(G)
G fract(G)
G mod(G,G)
G mod(G,float)
G min(G,G)
G min(G,float)
G max(G,G)
G max(G,float)
G clamp(G,G,G)
G clamp(G,float,float)
I abs(I)
I sign(I)
I min(I,I)
I min(I,int)
I max(I,I)
I max(I,int)
I clamp(I,I,I)
I clamp(I,int,int)
G mix(G,G,G)
G mix(G,G,float)
G step(G,G)
G step(float,G)
G smoothstep(G,G,G)
G smoothstep(float,float,G)
float length(G)
float distance(G,G)
float dot(G,G)
vec3 cross(vec3,vec3)
G normalize(G)
v:vec4 ftransform()
G faceforward(G,G,G)
G reflect(G,G)
G refract(G,G,float)
bv lessThan(v,v)
bv lessThan(iv,iv)
bv lessThanEqual(v,v)
bv lessThanEqual(iv,iv)
bv greaterThan(v,v)
bv greaterThan(iv,iv)
bv greaterThanEqual(v,v)
bv greaterThanEqual(iv,iv)
bv equal(v,v)
bv equal(iv,iv)
bv equal(bv,bv)
bv notEqual(v,v)
bv notEqual(iv,iv)
bv notEqual(bv,bv)
bool any(bv)
bool all(bv)
bv not(bv)
vec4 texture1D(sampler1D,float)
f:vec4 texture1D(sampler1D,float,float)
vec4 texture1DProj(sampler1D,vec2)
f:vec4 texture1DProj(sampler1D,vec2,float)
vec4 texture1DProj(sampler1D,vec4)
f:vec4 texture1DProj(sampler1D,vec4,float)
v:vec4 texture1DLod(sampler1D,float,float)
v:vec4 texture1DProjLod(sampler1D,vec2,float)
v:vec4 texture1DProjLod(sampler1D,vec4,float)
vec4 texture2D(sampler2D,vec2)
f:vec4 texture2D(sampler2D,vec2,float)
vec4 texture2DProj(sampler2D,vec3)
f:vec4 texture2DProj(sampler2D,vec3,float)
vec4 texture2DProj(sampler2D,vec4)
f:vec4 texture2DProj(sampler2D,vec4,float)
v:vec4 texture2DLod(sampler2D,vec2,float)
v:vec4 texture2DProjLod(sampler2D,vec3,float)
v:vec4 texture2DProjLod(sampler2D,vec4,float)
vec4 texture3D(sampler3D,vec3)
f:vec4 texture3D(sampler3D,vec3,float)
vec4 texture3DProj(sampler3D,vec4)
f:vec4 texture3DProj(sampler3D,vec4,float)
v:vec4 texture3DLod(sampler3D,vec3,float)
v:vec4 texture3DProjLod(sampler3D,vec4,float)
vec4 textureCube(samplerCube,vec3)
f:vec4 textureCube(samplerCube,vec3,float)
v:vec4 textureCubeLod(samplerCube,vec3,float)
vec4 shadow1D(sampler1DShadow,vec3)
f:vec4 shadow1D(sampler1DShadow,vec3,float)
vec4 shadow2D(sampler2DShadow,vec3)
f:vec4 shadow2D(sampler2DShadow,vec3,float)
vec4 shadow1DProj(sampler1DShadow,vec4)
f:vec4 shadow1DProj(sampler1DShadow,vec4,float)
vec4 shadow2DProj(sampler2DShadow,vec4)
f:vec4 shadow2DProj(sampler2DShadow,vec4,float)
v:vec4 shadow1DLod(sampler1DShadow,vec3,float)
v:vec4 shadow2DLod(sampler2DShadow,vec3,float)
v:vec4 shadow1DProjLod(sampler1DShadow,vec4,float)
v:vec4 shadow2DProjLod(sampler2DShadow,vec4,float)
f:G dFdx(G)
f:G dFdy(G)
f:G fwidth(G)
float noise1(G)
vec2 noise2(G)
vec3 noise3(G)
vec4 noise4(G)
";

/// A type name of the table, with `G`/`v`/`iv`/`bv` at component count `n`.
fn table_type(word: &str, n: u8) -> Type {
    match word {
        "G" => Type::vector(Scalar::Float, n),
        "I" => Type::vector(Scalar::Int, n),
        "v" => Type::Vector(Scalar::Float, n),
        "iv" => Type::Vector(Scalar::Int, n),
        "bv" => Type::Vector(Scalar::Bool, n),
        "float" => FLOAT,
        "bool" => BOOL,
        "int" => INT,
        "vec2" => Type::Vector(Scalar::Float, 2),
        "vec3" => Type::Vector(Scalar::Float, 3),
        "vec4" => Type::Vector(Scalar::Float, 4),
        "sampler1D" => Type::Sampler(Sampler::S1D),
        "sampler2D" => Type::Sampler(Sampler::S2D),
        "sampler3D" => Type::Sampler(Sampler::S3D),
        "samplerCube" => Type::Sampler(Sampler::Cube),
        "sampler1DShadow" => Type::Sampler(Sampler::S1DShadow),
        "sampler2DShadow" => Type::Sampler(Sampler::S2DShadow),
        other => unreachable!("built-in table type {other}"),
    }
}

fn build() -> HashMap<&'static str, Vec<Signature>> {
    let mut table: HashMap<&'static str, Vec<Signature>> = HashMap::new();
    for line in FUNCTIONS.lines().map(str::trim).filter(|l| !l.is_empty()) {
        let (stage, line) = match line.split_once(':') {
            Some(("v", rest)) => (Some(Stage::Vertex), rest),
            Some(("f", rest)) => (Some(Stage::Fragment), rest),
            _ => (None, line),
        };
        let (ret, rest) = line.split_once(' ').expect("return type");
        let (name, params) = rest.split_once('(').expect("parameters");
        let params: Vec<&str> = params.trim_end_matches(')').split(',').filter(|p| !p.is_empty()).collect();
        let words = || std::iter::once(ret).chain(params.iter().copied());
        let sizes: &[u8] = if words().any(|w| w == "G" || w == "I") {
            &[1, 2, 3, 4]
        } else if words().any(|w| matches!(w, "v" | "iv" | "bv")) {
            &[2, 3, 4]
        } else {
            &[1]
        };
        for &n in sizes {
            let sig = Signature {
                name: name_static(name),
                ret: table_type(ret, n),
                params: params.iter().map(|p| table_type(p, n)).collect(),
                stage,
                version: 110,
            };
            let list = table.entry(sig.name).or_default();
            // `G min(G,float)` at one component is `min(float,float)` again.
            if !list.iter().any(|s| s.params == sig.params) {
                list.push(sig);
            }
        }
    }
    // The matrix functions: matrixCompMult of every matrix type (the non-square ones are
    // 1.20's), 1.20's outerProduct and transpose.
    for c in 2..=4u8 {
        for r in 2..=4u8 {
            let m = Type::Matrix(c, r);
            let version = if c == r { 110 } else { 120 };
            let sigs = [
                ("matrixCompMult", m.clone(), vec![m.clone(), m.clone()], version),
                ("outerProduct", m.clone(), vec![Type::Vector(Scalar::Float, r), Type::Vector(Scalar::Float, c)], 120),
                ("transpose", Type::Matrix(r, c), vec![m.clone()], 120),
            ];
            for (name, ret, params, version) in sigs {
                table.entry(name).or_default().push(Signature { name, ret, params, stage: None, version });
            }
        }
    }
    table
}

/// The table's names as `'static` strings (the table lives for the process).
fn name_static(name: &str) -> &'static str {
    FUNCTIONS
        .match_indices(name)
        .find(|(i, _)| {
            let before = FUNCTIONS[..*i].chars().next_back();
            let after = FUNCTIONS[i + name.len()..].chars().next();
            before == Some(' ') && after == Some('(')
        })
        .map(|(i, _)| &FUNCTIONS[i..i + name.len()])
        .expect("name in the table")
}

/// The built-in function signatures by name (all versions and stages; callers filter).
pub fn functions() -> &'static HashMap<&'static str, Vec<Signature>> {
    static TABLE: OnceLock<HashMap<&'static str, Vec<Signature>>> = OnceLock::new();
    TABLE.get_or_init(build)
}

/// The implementation limits the built-in constants report (`gl_MaxLights`...).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    pub max_lights: i32,
    pub max_clip_planes: i32,
    pub max_texture_units: i32,
    pub max_texture_coords: i32,
    pub max_vertex_attribs: i32,
    pub max_vertex_uniform_components: i32,
    pub max_varying_floats: i32,
    pub max_vertex_texture_image_units: i32,
    pub max_combined_texture_image_units: i32,
    pub max_texture_image_units: i32,
    pub max_fragment_uniform_components: i32,
    pub max_draw_buffers: i32,
}

impl Limits {
    /// What tessera's GL reports (glGet answers the GL_MAX_* pnames of GL 2.0 from this;
    /// tessera's `glsl` module asserts at compile time that these are its `gl::limits` and
    /// varying budget, which this crate cannot see): 4 fixed-function texture units, 8 texture
    /// image units for fragment shaders (GL_MAX_TEXTURE_IMAGE_UNITS, the combined count too),
    /// 6 clip planes. No texture image units for vertex shaders (GL 2.0 allows 0: their
    /// lookups are not wired to textures). 8 texture coordinate sets (GL_MAX_TEXTURE_COORDS,
    /// as on Mesa; piglit's shaders index `gl_TexCoord[7]` without asking): sets 4..7 have
    /// current values, arrays, texture matrices and texgen state but no fixed-function
    /// texturing (GL 2.0 section 2.7; GLSL 1.20 section 7.4 wants gl_MaxTextureCoords equal
    /// to it). The uniform budget is Mesa's llvmpipe value, the one tessera's link checks;
    /// the varying budget what tessera's vertex record carries (16 vec4 slots; Mesa's is 128).
    pub const TESSERA: Limits = Limits {
        max_lights: 8,
        max_clip_planes: 6,
        max_texture_units: 4,
        max_texture_coords: 8,
        max_vertex_attribs: 16,
        max_vertex_uniform_components: 16384,
        max_varying_floats: 64,
        max_vertex_texture_image_units: 0,
        max_combined_texture_image_units: 8,
        max_texture_image_units: 8,
        max_fragment_uniform_components: 16384,
        max_draw_buffers: 8,
    };
}

impl Default for Limits {
    /// [`Limits::TESSERA`].
    fn default() -> Self {
        Limits::TESSERA
    }
}

/// How a built-in variable may be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// An input of the stage: read-only.
    In,
    /// An output: written and read.
    Out,
    /// Built-in uniform state: read-only.
    Uniform,
    /// A built-in constant.
    Const(i32),
    /// An attribute (vertex) or varying (both stages): storage as GL names it.
    Attribute,
    VaryingOut,
    VaryingIn,
}

/// One built-in variable.
#[derive(Clone, Debug)]
pub struct BuiltinVariable {
    pub name: &'static str,
    pub ty: Type,
    pub access: Access,
}

/// The built-in struct types of the uniform state (section 7.5), with their members.
pub fn builtin_structs(next_id: &mut u32) -> Vec<Arc<StructType>> {
    let v4 = Type::Vector(Scalar::Float, 4);
    let v3 = Type::Vector(Scalar::Float, 3);
    let list: [(&str, Vec<(&str, Type)>); 8] = [
        ("gl_DepthRangeParameters", vec![("near", FLOAT), ("far", FLOAT), ("diff", FLOAT)]),
        (
            "gl_PointParameters",
            vec![
                ("size", FLOAT),
                ("sizeMin", FLOAT),
                ("sizeMax", FLOAT),
                ("fadeThresholdSize", FLOAT),
                ("distanceConstantAttenuation", FLOAT),
                ("distanceLinearAttenuation", FLOAT),
                ("distanceQuadraticAttenuation", FLOAT),
            ],
        ),
        (
            "gl_MaterialParameters",
            vec![
                ("emission", v4.clone()),
                ("ambient", v4.clone()),
                ("diffuse", v4.clone()),
                ("specular", v4.clone()),
                ("shininess", FLOAT),
            ],
        ),
        (
            "gl_LightSourceParameters",
            vec![
                ("ambient", v4.clone()),
                ("diffuse", v4.clone()),
                ("specular", v4.clone()),
                ("position", v4.clone()),
                ("halfVector", v4.clone()),
                ("spotDirection", v3),
                ("spotExponent", FLOAT),
                ("spotCutoff", FLOAT),
                ("spotCosCutoff", FLOAT),
                ("constantAttenuation", FLOAT),
                ("linearAttenuation", FLOAT),
                ("quadraticAttenuation", FLOAT),
            ],
        ),
        ("gl_LightModelParameters", vec![("ambient", v4.clone())]),
        ("gl_LightModelProducts", vec![("sceneColor", v4.clone())]),
        ("gl_LightProducts", vec![("ambient", v4.clone()), ("diffuse", v4.clone()), ("specular", v4.clone())]),
        (
            "gl_FogParameters",
            vec![("color", v4), ("density", FLOAT), ("start", FLOAT), ("end", FLOAT), ("scale", FLOAT)],
        ),
    ];
    list.into_iter()
        .map(|(name, members)| {
            *next_id += 1;
            Arc::new(StructType {
                name: name.to_string(),
                members: members.into_iter().map(|(n, t)| (n.to_string(), t)).collect(),
                id: *next_id,
            })
        })
        .collect()
}

/// The built-in variables of `stage` in GLSL `version`, given the struct types from
/// [`builtin_structs`] (in its order).
pub fn variables(stage: Stage, version: u32, limits: &Limits, structs: &[Arc<StructType>]) -> Vec<BuiltinVariable> {
    let v = |n| Type::Vector(Scalar::Float, n);
    let arr = |t: Type, n: i32| Type::Array(Box::new(t), Some(n as u32));
    let st = |i: usize| Type::Struct(structs[i].clone());
    let mut out = Vec::new();
    let mut add = |name: &'static str, ty: Type, access: Access| out.push(BuiltinVariable { name, ty, access });
    let consts = [
        ("gl_MaxLights", limits.max_lights),
        ("gl_MaxClipPlanes", limits.max_clip_planes),
        ("gl_MaxTextureUnits", limits.max_texture_units),
        ("gl_MaxTextureCoords", limits.max_texture_coords),
        ("gl_MaxVertexAttribs", limits.max_vertex_attribs),
        ("gl_MaxVertexUniformComponents", limits.max_vertex_uniform_components),
        ("gl_MaxVaryingFloats", limits.max_varying_floats),
        ("gl_MaxVertexTextureImageUnits", limits.max_vertex_texture_image_units),
        ("gl_MaxCombinedTextureImageUnits", limits.max_combined_texture_image_units),
        ("gl_MaxTextureImageUnits", limits.max_texture_image_units),
        ("gl_MaxFragmentUniformComponents", limits.max_fragment_uniform_components),
        ("gl_MaxDrawBuffers", limits.max_draw_buffers),
    ];
    for (name, value) in consts {
        add(name, INT, Access::Const(value));
    }
    let m4 = Type::Matrix(4, 4);
    const MATRICES: [&str; 16] = [
        "gl_ModelViewMatrix",
        "gl_ModelViewMatrixInverse",
        "gl_ModelViewMatrixTranspose",
        "gl_ModelViewMatrixInverseTranspose",
        "gl_ProjectionMatrix",
        "gl_ProjectionMatrixInverse",
        "gl_ProjectionMatrixTranspose",
        "gl_ProjectionMatrixInverseTranspose",
        "gl_ModelViewProjectionMatrix",
        "gl_ModelViewProjectionMatrixInverse",
        "gl_ModelViewProjectionMatrixTranspose",
        "gl_ModelViewProjectionMatrixInverseTranspose",
        "gl_TextureMatrix",
        "gl_TextureMatrixInverse",
        "gl_TextureMatrixTranspose",
        "gl_TextureMatrixInverseTranspose",
    ];
    for name in MATRICES {
        let ty =
            if name.starts_with("gl_TextureMatrix") { arr(m4.clone(), limits.max_texture_coords) } else { m4.clone() };
        add(name, ty, Access::Uniform);
    }
    add("gl_NormalMatrix", Type::Matrix(3, 3), Access::Uniform);
    add("gl_NormalScale", FLOAT, Access::Uniform);
    add("gl_DepthRange", st(0), Access::Uniform);
    add("gl_ClipPlane", arr(v(4), limits.max_clip_planes), Access::Uniform);
    add("gl_Point", st(1), Access::Uniform);
    add("gl_FrontMaterial", st(2), Access::Uniform);
    add("gl_BackMaterial", st(2), Access::Uniform);
    add("gl_LightSource", arr(st(3), limits.max_lights), Access::Uniform);
    add("gl_LightModel", st(4), Access::Uniform);
    add("gl_FrontLightModelProduct", st(5), Access::Uniform);
    add("gl_BackLightModelProduct", st(5), Access::Uniform);
    add("gl_FrontLightProduct", arr(st(6), limits.max_lights), Access::Uniform);
    add("gl_BackLightProduct", arr(st(6), limits.max_lights), Access::Uniform);
    add("gl_TextureEnvColor", arr(v(4), limits.max_texture_units), Access::Uniform);
    for plane in ["gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR", "gl_EyePlaneQ"] {
        add(plane, arr(v(4), limits.max_texture_coords), Access::Uniform);
    }
    for plane in ["gl_ObjectPlaneS", "gl_ObjectPlaneT", "gl_ObjectPlaneR", "gl_ObjectPlaneQ"] {
        add(plane, arr(v(4), limits.max_texture_coords), Access::Uniform);
    }
    add("gl_Fog", st(7), Access::Uniform);
    let tex_coord = Type::Array(Box::new(v(4)), None);
    match stage {
        Stage::Vertex => {
            add("gl_Position", v(4), Access::Out);
            add("gl_PointSize", FLOAT, Access::Out);
            add("gl_ClipVertex", v(4), Access::Out);
            add("gl_Color", v(4), Access::Attribute);
            add("gl_SecondaryColor", v(4), Access::Attribute);
            add("gl_Normal", v(3), Access::Attribute);
            add("gl_Vertex", v(4), Access::Attribute);
            for name in [
                "gl_MultiTexCoord0",
                "gl_MultiTexCoord1",
                "gl_MultiTexCoord2",
                "gl_MultiTexCoord3",
                "gl_MultiTexCoord4",
                "gl_MultiTexCoord5",
                "gl_MultiTexCoord6",
                "gl_MultiTexCoord7",
            ] {
                add(name, v(4), Access::Attribute);
            }
            add("gl_FogCoord", FLOAT, Access::Attribute);
            add("gl_FrontColor", v(4), Access::VaryingOut);
            add("gl_BackColor", v(4), Access::VaryingOut);
            add("gl_FrontSecondaryColor", v(4), Access::VaryingOut);
            add("gl_BackSecondaryColor", v(4), Access::VaryingOut);
            add("gl_TexCoord", tex_coord, Access::VaryingOut);
            add("gl_FogFragCoord", FLOAT, Access::VaryingOut);
        }
        Stage::Fragment => {
            add("gl_FragCoord", v(4), Access::In);
            add("gl_FrontFacing", BOOL, Access::In);
            add("gl_FragColor", v(4), Access::Out);
            add("gl_FragData", arr(v(4), limits.max_draw_buffers), Access::Out);
            add("gl_FragDepth", FLOAT, Access::Out);
            if version >= 120 {
                add("gl_PointCoord", v(2), Access::In);
            }
            add("gl_Color", v(4), Access::VaryingIn);
            add("gl_SecondaryColor", v(4), Access::VaryingIn);
            add("gl_TexCoord", tex_coord, Access::VaryingIn);
            add("gl_FogFragCoord", FLOAT, Access::VaryingIn);
        }
    }
    out
}

/// A built-in constant's value as a constant component.
pub fn const_value(access: Access) -> Option<Value> {
    match access {
        Access::Const(v) => Some(Value::I(v)),
        _ => None,
    }
}

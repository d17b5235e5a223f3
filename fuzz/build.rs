//! Generates the fuzz decoder's table of entry points from tessera's generated header
//! (`include/GL/tessera.h`): an `extern "C"` declaration and a caller for every GL entry
//! point whose arguments the decoder can draw without knowing the function (scalars, and
//! pointers to small fixed-size arrays). Entry points whose pointer arguments are sized by
//! other arguments or by pixel-store state have hand-written decoders in `src/lib.rs` or
//! are listed in `SKIPPED` with the reason.
//!
//! It also writes `seed_shim.c` next to the table: an LD_PRELOAD library that wraps the same
//! entry points and writes every call a program makes as the bytes that make the decoder
//! repeat it (tools/fuzz-seeds.sh records the capi tests with it: the seed corpus).

use std::fmt::Write;
use std::path::PathBuf;

/// Entry points the generated table must not call: hand-written decoders cover them, or
/// they read or write caller memory whose size the decoder cannot know from the prototype.
const HAND_WRITTEN: &[&str] = &[
    // Read client arrays at draw time: indices are bounded by hand.
    "glArrayElement",
    "glArrayElementEXT",
    "glDrawArrays",
    "glDrawArraysEXT",
    // Pixel rectangles sized by pixel-store state.
    "glReadPixels",
    "glPolygonStipple",
    "glGetPolygonStipple",
    // Write an unknown amount (a texture image).
    "glGetTexImage",
    "glGetCompressedTexImage",
    "glGetCompressedTexImageARB",
    // Store the pointer for later writes.
    "glSelectBuffer",
    "glFeedbackBuffer",
    // Buffer mapping is exercised by hand (writes within the mapped size).
    "glMapBuffer",
    "glMapBufferARB",
    // Evaluator meshes cost their grid range times the map's order cubed: hand-written
    // decoders keep the ranges small (an arbitrary GLint range would run for hours).
    "glEvalMesh1",
    "glEvalMesh2",
];

/// Parameter names that size another (pointer) argument.
const SIZE_NAMES: &[&str] = &[
    "n",
    "count",
    "size",
    "width",
    "height",
    "depth",
    "bufSize",
    "mapsize",
    "len",
    "length",
    "stride",
    "drawcount",
    "primcount",
    "range",
    "_count",
    "imageSize",
    "order",
    "uorder",
    "vorder",
    "ustride",
    "vstride",
];

/// Sizing parameters the decoder can bound without knowing the function: an element count
/// drawn from `-1..=bound`, small enough that the arrays it sizes (elements of at most 8
/// bytes, strided at most 16 elements) fit in the scratch area.
const BOUNDED_SIZES: &[(&str, i32)] =
    &[("n", 64), ("mapsize", 1024), ("order", 40), ("uorder", 40), ("vorder", 40), ("ustride", 16), ("vstride", 16)];

struct Param {
    ty: String,
    name: String,
}

fn parse(line: &str) -> Option<(String, String, Vec<Param>)> {
    let line = line.trim();
    let open = line.find('(')?;
    if !line.ends_with(");") || line.starts_with('#') || line.starts_with("typedef") {
        return None;
    }
    let head = &line[..open];
    let name_start = head.rfind(|c: char| !(c.is_alphanumeric() || c == '_'))? + 1;
    let name = head[name_start..].to_string();
    let ret = head[..name_start].trim().to_string();
    let inner = &line[open + 1..line.len() - 2];
    let mut params = Vec::new();
    if inner.trim() != "void" && !inner.trim().is_empty() {
        for p in inner.split(',') {
            let p = p.trim();
            let (ty, pname) = if let Some(bracket) = p.find('[') {
                // `const GLfloat m[16]`: an array parameter is a pointer.
                let decl = &p[..bracket];
                let split = decl.rfind(' ')?;
                (format!("{} *", &decl[..split]), decl[split + 1..].to_string())
            } else {
                let split = p.rfind(|c: char| c == ' ' || c == '*')?;
                (p[..split + 1].trim().to_string(), p[split + 1..].to_string())
            };
            params.push(Param { ty, name: pname });
        }
    }
    Some((ret, name, params))
}

/// The Rust type and the decoder expression of a C parameter type.
fn scalar(ty: &str) -> Option<(&'static str, &'static str)> {
    Some(match ty {
        "GLenum" => ("u32", "z.glenum()"),
        "GLbitfield" => ("u32", "z.bitfield()"),
        "GLboolean" => ("u8", "z.boolean()"),
        "GLbyte" => ("i8", "z.int() as i8"),
        "GLshort" => ("i16", "z.int() as i16"),
        "GLint" | "GLsizei" => ("i32", "z.int()"),
        "GLubyte" => ("u8", "z.int() as u8"),
        "GLushort" => ("u16", "z.int() as u16"),
        "GLuint" => ("u32", "z.int() as u32"),
        "GLfloat" | "GLclampf" => ("f32", "z.float()"),
        "GLdouble" | "GLclampd" => ("f64", "z.double()"),
        "GLintptr" | "GLsizeiptr" => ("isize", "z.small_size()"),
        _ => return None,
    })
}

/// Whether the only unbounded sizing parameter of a glMap* prototype is its `stride`.
fn only_stride_unbounded(params: &[Param], bound_of: &impl Fn(&Param) -> Option<i32>) -> bool {
    params.iter().filter(|p| SIZE_NAMES.contains(&p.name.as_str()) && bound_of(p).is_none()).all(|p| p.name == "stride")
}

fn main() {
    let header = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap()).join("../include/GL/tessera.h");
    println!("cargo:rerun-if-changed={}", header.display());
    let text =
        std::fs::read_to_string(&header).expect("include/GL/tessera.h (run cargo build in the repository first)");
    let mut externs = String::new();
    let mut callers = String::new();
    let mut table = String::new();
    let mut shim = String::from(SHIM_PREAMBLE);
    let mut index = 0usize;
    let mut skipped = String::new();
    let mut seen = std::collections::BTreeSet::new();
    let mut enums = std::collections::BTreeSet::new();
    for line in text.lines() {
        if let Some(rest) = line.trim().strip_prefix("#define GL_") {
            if let Some(value) = rest.split_whitespace().nth(1).and_then(|v| v.parse::<u32>().ok()) {
                enums.insert(value);
            }
        }
        let Some((ret, name, params)) = parse(line) else { continue };
        if !name.starts_with("gl") || name.starts_with("glX") || !seen.insert(name.clone()) {
            continue;
        }
        let has_pointer = params.iter().any(|p| p.ty.contains('*'));
        let bound_of = |p: &Param| BOUNDED_SIZES.iter().find(|(n, _)| *n == p.name).map(|&(_, b)| b);
        let sized = params.iter().any(|p| SIZE_NAMES.contains(&p.name.as_str()) && bound_of(p).is_none());
        // glMap*'s plain `stride` is bounded like ustride/vstride.
        let map_stride = name.starts_with("glMap");
        let reason = if HAND_WRITTEN.contains(&name.as_str()) {
            Some("hand-written decoder or unknown size")
        } else if name.contains("Pointer") && name != "glGetPointerv" && name != "glGetPointervEXT" {
            Some("client array pointer: hand-written")
        } else if has_pointer && sized && !(map_stride && only_stride_unbounded(&params, &bound_of)) {
            Some("pointer sized by another argument")
        } else if params.iter().any(|p| p.ty.contains("char")) {
            Some("string argument")
        } else {
            None
        };
        if let Some(reason) = reason {
            let _ = writeln!(skipped, "    (\"{name}\", \"{reason}\"),");
            continue;
        }
        let mut decl = Vec::new();
        let mut args = Vec::new();
        let mut encoders = Vec::new();
        let mut ok = true;
        for (i, p) in params.iter().enumerate() {
            let bound = bound_of(p).or((has_pointer && map_stride && p.name == "stride").then_some(16));
            if p.ty.contains('*') {
                decl.push(format!("a{i}: *mut std::ffi::c_void"));
                args.push(format!("z.scratch_pointer({i})"));
                encoders.push(format!("seed_pointer((const void *)a{i});"));
            } else if let (Some(bound), Some((rust, _))) = (bound.filter(|_| has_pointer), scalar(&p.ty)) {
                decl.push(format!("a{i}: {rust}"));
                args.push(format!("z.count({bound}) as {rust}"));
                encoders.push(format!("seed_count((long long)a{i}, {bound});"));
            } else if let Some((rust, expr)) = scalar(&p.ty) {
                decl.push(format!("a{i}: {rust}"));
                args.push(expr.to_string());
                let encoder = match expr {
                    "z.glenum()" => "seed_enum",
                    "z.bitfield()" => "seed_bitfield",
                    "z.boolean()" => "seed_boolean",
                    "z.float()" => "seed_float",
                    "z.double()" => "seed_double",
                    "z.small_size()" => "seed_size",
                    _ => "seed_int",
                };
                encoders.push(format!("{encoder}(a{i});"));
            } else {
                ok = false;
            }
        }
        if !ok {
            let _ = writeln!(skipped, "    (\"{name}\", \"unknown parameter type\"),");
            continue;
        }
        let ret_rust = match ret.as_str() {
            "void" => "",
            r if r.contains('*') => " -> *const std::ffi::c_void",
            r => match scalar(r) {
                Some((rust, _)) => match rust {
                    "u32" => " -> u32",
                    "u8" => " -> u8",
                    "i32" => " -> i32",
                    _ => " -> u32",
                },
                None => " -> *const std::ffi::c_void",
            },
        };
        let _ = writeln!(externs, "    fn {name}({}){ret_rust};", decl.join(", "));
        let lets: String = args.iter().enumerate().map(|(i, a)| format!("let a{i} = {a}; ")).collect();
        let call_args: Vec<String> = (0..args.len()).map(|i| format!("a{i}")).collect();
        let _ = writeln!(
            callers,
            "#[allow(non_snake_case)]\nfn call_{name}(z: &mut Fuzzer) {{ {lets}z.note(\"{name}\"); \
             // SAFETY: arguments drawn by the decoder: scalars, and pointers into its scratch area\n    \
             // (64 KiB, larger than any fixed-size array a GL entry point reads or writes).\n    \
             let _ = unsafe {{ {name}({}) }}; }}",
            call_args.join(", ")
        );
        let _ = writeln!(table, "    (\"{name}\", call_{name}),");
        let c_params: Vec<String> = params.iter().enumerate().map(|(i, p)| format!("{} a{i}", p.ty)).collect();
        let c_types: Vec<&str> = params.iter().map(|p| p.ty.as_str()).collect();
        let c_args: Vec<String> = (0..params.len()).map(|i| format!("a{i}")).collect();
        let (c_params, c_types) = if params.is_empty() {
            ("void".to_string(), "void".to_string())
        } else {
            (c_params.join(", "), c_types.join(", "))
        };
        let call = if ret == "void" {
            format!("seed_depth++;\n    real({});\n    seed_depth--;", c_args.join(", "))
        } else {
            format!(
                "seed_depth++;\n    {ret} result = real({});\n    seed_depth--;\n    return result;",
                c_args.join(", ")
            )
        };
        let _ = writeln!(
            shim,
            "{ret} {name}({c_params})\n{{\n    static {ret} (*real)({c_types});\n    \
             if (!real)\n        real = ({ret} (*)({c_types}))dlsym(RTLD_NEXT, \"{name}\");\n    \
             if (seed_begin({index})) {{\n        {}\n    }}\n    {call}\n}}\n",
            encoders.join("\n        "),
        );
        index += 1;
    }
    let enum_list: Vec<String> = enums.iter().map(|v| v.to_string()).collect();
    let out = format!(
        "#[allow(clashing_extern_declarations)]\nextern \"C\" {{\n{externs}}}\n\n{callers}\n\
         /// Every entry point the decoder calls by prototype alone.\n\
         pub static GENERATED: &[(&str, fn(&mut Fuzzer))] = &[\n{table}];\n\n\
         /// Entry points left out of [`GENERATED`], with the reason.\n\
         pub static SKIPPED: &[(&str, &str)] = &[\n{skipped}];\n\n\
         /// Every GL_* value the header defines.\n\
         pub static ENUMS: &[u32] = &[{}];\n",
        enum_list.join(", ")
    );
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").unwrap());
    std::fs::write(out_dir.join("generated.rs"), out).unwrap();
    std::fs::write(out_dir.join("seed_shim.c"), shim).unwrap();
}

/// The start of `seed_shim.c`: the encoders of the decoder's argument kinds (see
/// `Fuzzer::glenum` and the others in src/lib.rs), each writing the bytes that make the
/// decoder draw exactly the recorded value (or the nearest it can draw).
const SHIM_PREAMBLE: &str = r#"/* Generated by fuzz/build.rs: records the GL calls of a program as a command stream for
 * the command_stream fuzz target. LD_PRELOAD this library and set TESSERA_FUZZ_SEED to the
 * output file; calls tessera makes inside a recorded call are not recorded. */
#define _GNU_SOURCE
#include <GL/tessera.h>
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/uio.h>
#include <unistd.h>

static FILE *seed_out;
static int seed_depth;

static void seed_bytes(const void *bytes, size_t n)
{
    fwrite(bytes, 1, n, seed_out);
}

static void seed_byte(unsigned b)
{
    unsigned char c = (unsigned char)b;
    seed_bytes(&c, 1);
}

static void seed_u16(unsigned v)
{
    seed_byte(v & 0xff);
    seed_byte(v >> 8 & 0xff);
}

static void seed_u32(uint32_t v)
{
    seed_u16(v & 0xffff);
    seed_u16(v >> 16);
}

/* A generated call: selector >= 48, then its index in GENERATED. */
static int seed_begin(unsigned index)
{
    static int opened;
    if (!opened) {
        const char *path = getenv("TESSERA_FUZZ_SEED");
        seed_out = path ? fopen(path, "ab") : NULL;
        opened = 1;
    }
    if (!seed_out || seed_depth)
        return 0;
    /* Where each call starts, for cutting the stream into seeds at call boundaries. */
    static FILE *calls;
    if (!calls) {
        char path[4096];
        snprintf(path, sizeof path, "%s.calls", getenv("TESSERA_FUZZ_SEED"));
        calls = fopen(path, "a");
    }
    if (calls)
        fprintf(calls, "%ld\n", ftell(seed_out));
    seed_byte(48);
    seed_u16(index);
    return 1;
}

static void seed_enum(uint32_t v) { seed_byte(230); seed_u32(v); }
static void seed_bitfield(uint32_t v) { seed_byte(3); seed_u32(v); }
static void seed_boolean(unsigned v) { seed_byte(v == 0 ? 128 : v == 1 || v < 251 ? 0 : v); }
static void seed_int(long long v) { seed_byte(224); seed_u32((uint32_t)v); }
static void seed_float(float v) { uint32_t bits; memcpy(&bits, &v, 4); seed_byte(240); seed_u32(bits); }
static void seed_double(double v)
{
    uint64_t bits;
    memcpy(&bits, &v, 8);
    seed_byte(0);
    seed_u32((uint32_t)(bits >> 32));
    seed_u32((uint32_t)bits);
}
static void seed_size(long long v)
{
    if (v >= 0 && v < 65536) {
        seed_byte(1);
        seed_u16((unsigned)v);
    } else {
        seed_byte(0);
        seed_byte(v < 0 ? 0 : 8);
    }
}
static void seed_count(long long v, int bound)
{
    if (v < -1)
        v = -1;
    if (v > bound)
        v = bound;
    seed_u16((unsigned)(v + 1));
}
/* A pointer: NULL, or the first 64 bytes it points to (read without faulting: a shorter
 * array at the end of a page gives zeros). */
static void seed_pointer(const void *p)
{
    unsigned char bytes[64] = {0};
    if (!p) {
        seed_byte(0);
        return;
    }
    for (size_t n = 64; n > 0; n /= 2) {
        struct iovec local = {bytes, n}, remote = {(void *)p, n};
        if (process_vm_readv(getpid(), &local, 1, &remote, 1, 0) == (ssize_t)n)
            break;
    }
    seed_byte(8);
    seed_bytes(bytes, 64);
}

"#;

#!/usr/bin/env python3
"""One-off generator for src/gl/enums.rs.

GL enum values are interface facts fixed by the Khronos registry; this script reads the
names and values of the GL 1.0-2.1 core sections (and the extension names listed in EXTRA)
from the system headers so that tessera's constants match the ABI bit for bit. The output is
committed; the ABI check in capi-tests proves it stays equal to the system headers.
"""
import re, sys

GL_H = "/usr/include/GL/gl.h"
GLEXT_H = "/usr/include/GL/glext.h"
SECTIONS = ["GL_VERSION_1_2", "GL_VERSION_1_3", "GL_VERSION_1_4", "GL_VERSION_1_5",
            "GL_VERSION_2_0", "GL_VERSION_2_1"]
# Enums of later versions/extensions that tessera implements (names only; values from glext.h).
EXTRA = sys.argv[1:]
FEATURE = re.compile(r"^GL_(VERSION_\d_\d|ARB_|EXT_|MESA_|ATI_|NV_|OES_|SGI|SUN|IBM|APPLE|INTEL|HP_|3DFX|KHR_|AMD_|GREMEDY|WIN_|PGI|REND|S3|OML|INGR)")
DEFINE = re.compile(r"^#define\s+(GL_[A-Za-z0-9_]+)\s+(0x[0-9A-Fa-f]+|\d+)u?l*\s*$")

def defines(lines):
    for line in lines:
        m = DEFINE.match(line.strip())
        if m and not (m.group(2) == "1" and FEATURE.match(m.group(1))):
            yield m.group(1), m.group(2)

out, seen = [], set()
def add(name, value, origin):
    if name in seen:
        return
    seen.add(name)
    out.append((name, value, origin))

gl = open(GL_H).read().splitlines()
for n, v in defines(gl):
    add(n, v, "gl.h")
ext = open(GLEXT_H).read().splitlines()
for sec in SECTIONS:
    start = ext.index("#ifndef %s" % sec)
    end = ext.index("#endif /* %s */" % sec)
    for n, v in defines(ext[start:end]):
        add(n, v, sec)
all_ext = dict(defines(ext))
for n in EXTRA:
    add(n, all_ext[n], "extension")

print("//! GL enum values: the constants of GL 1.0-2.1 and of the extensions tessera implements.")
print("//!")
print("//! Generated once by `tools/gen_enums.py` from the registry's values; cbindgen exports them")
print("//! into `include/GL/tessera.h`, and the ABI check proves every value equals the system's.")
print("#![allow(non_upper_case_globals)]")
print("use super::types::{GLboolean, GLenum};")
print()
for n, v, o in out:
    ty = "GLboolean" if n in ("GL_TRUE", "GL_FALSE") else "GLenum"
    print("pub const %s: %s = %s;" % (n, ty, v))

/* Links a GLSL program (a vertex and a fragment shader) and draws with it, for the
 * TESSERA_DEBUG=programs test in tests/capi.rs: both stages' IR must be printed. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdlib.h>

static GLuint shader(GLenum kind, const char *source)
{
    GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    return s;
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    void *buffer = calloc(16 * 16, 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16))
        return 2;
    GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, "void main() { gl_Position = ftransform(); }\n"));
    glAttachShader(program,
                   shader(GL_FRAGMENT_SHADER, "uniform float k;\n"
                                              "void main() { gl_FragColor = vec4(k * 0.5, 0.25, 0.0, 1.0); }\n"));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked)
        return 3;
    glUseProgram(program);
    glUniform1f(glGetUniformLocation(program, "k"), 1.0f);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    glFinish();
    OSMesaDestroyContext(ctx);
    free(buffer);
    return glGetError() == GL_NO_ERROR ? 0 : 1;
}

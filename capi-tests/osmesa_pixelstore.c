/* OSMesaPixelStore: OSMESA_Y_UP (1: row 0 of the buffer is the bottom row, the default;
 * 0: row 0 is the top row) and OSMESA_ROW_LENGTH (rows that many pixels apart; the padding
 * between rows is never written), read back through the caller's buffer and
 * OSMesaGetIntegerv.
 *
 * Mesa 22 writes the caller's buffer only when something was rendered since the last flush,
 * so every step renders again instead of only flushing.
 */
#include "common.h"

#define W 8
#define H 4
#define ROW 11 /* pixels per row in memory: 3 pixels of padding */
#define GUARD 32

static const unsigned char red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255}, blue[4] = {0, 0, 255, 255};
static const unsigned char pad[4] = {0xEE, 0xEE, 0xEE, 0xEE};

/* The picture: red everywhere, the bottom row green, the top-left 2x1 pixels blue. */
static void render(void)
{
    glDisable(GL_SCISSOR_TEST);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W, 1);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, H - 1, 2, 1);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
}

/* The expected bytes of window pixel (x, y) (y from the bottom). */
static const unsigned char *expected(int x, int y)
{
    if (y == H - 1 && x < 2)
        return blue;
    return y == 0 ? green : red;
}

/* Checks the buffer: `row` pixels per memory row, y_up as set; padding and guard untouched. */
static void check_buffer(const char *what, const unsigned char *buffer, int row, int y_up)
{
    int wrong = 0;
    for (int mem_row = 0; mem_row < H && !wrong; mem_row++) {
        int y = y_up ? mem_row : H - 1 - mem_row;
        for (int x = 0; x < row && !wrong; x++) {
            const unsigned char *got = buffer + ((size_t)mem_row * row + x) * 4;
            const unsigned char *want = x < W ? expected(x, y) : pad;
            if (memcmp(got, want, 4) != 0) {
                wrong = 1;
                capi_check(0, "%s: memory row %d pixel %d is %02x%02x%02x%02x, expected %02x%02x%02x%02x", what, mem_row,
                           x, got[0], got[1], got[2], got[3], want[0], want[1], want[2], want[3]);
            }
        }
    }
    for (size_t i = (size_t)row * H * 4; i < (size_t)ROW * H * 4 + GUARD; i++)
        if (buffer[i] != 0xEE) {
            capi_check(0, "%s: byte %zu after the image was written", what, i);
            break;
        }
}

static void query(const char *what)
{
    GLint row_length = -1, y_up = -1;
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &row_length);
    OSMesaGetIntegerv(OSMESA_Y_UP, &y_up);
    capi_value(what, "row_length=%d y_up=%d", row_length, y_up);
}

int main(void)
{
    size_t size = (size_t)ROW * H * 4 + GUARD;
    unsigned char *buffer = malloc(size);
    memset(buffer, 0xEE, size);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    capi_check(OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H), "MakeCurrent");
    query("defaults");

    render();
    check_buffer("y_up=1", buffer, W, 1);
    capi_save_image("y_up_1", W, H, 4, CAPI_U8, buffer);

    memset(buffer, 0xEE, size);
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    query("after_y_up_0");
    render();
    check_buffer("y_up=0", buffer, W, 0);
    capi_save_image("y_up_0", W, H, 4, CAPI_U8, buffer);

    memset(buffer, 0xEE, size);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, ROW);
    query("after_row_length");
    render();
    check_buffer("row_length=11 y_up=0", buffer, ROW, 0);
    capi_save_image("row_length_y_up_0", ROW, H, 4, CAPI_U8, buffer);

    memset(buffer, 0xEE, size);
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    query("after_y_up_1");
    render();
    check_buffer("row_length=11 y_up=1", buffer, ROW, 1);
    capi_save_image("row_length_y_up_1", ROW, H, 4, CAPI_U8, buffer);

    /* The settings belong to the context and survive binding the buffer again. */
    memset(buffer, 0xEE, size);
    capi_check(OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H), "MakeCurrent again");
    query("after_rebind");
    render();
    check_buffer("rebound", buffer, ROW, 1);

    /* Any nonzero OSMESA_Y_UP value means 1. */
    OSMesaPixelStore(OSMESA_Y_UP, 5);
    query("after_y_up_5");

    /* An unknown parameter or a negative row length changes nothing. Mesa 22 reports nothing
     * (its _mesa_error gets no context) and stores the negative row length as given;
     * tessera records GL_INVALID_ENUM / GL_INVALID_VALUE on the current context and keeps
     * the row length, so those parts are checked per implementation. */
    int tessera = capi_is_tessera();
    OSMesaPixelStore(0x99, 1);
    GLenum error = glGetError();
    capi_check(error == (tessera ? GL_INVALID_ENUM : GL_NO_ERROR), "unknown pname: error 0x%x", error);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, -1);
    error = glGetError();
    capi_check(error == (tessera ? GL_INVALID_VALUE : GL_NO_ERROR), "negative row length: error 0x%x", error);
    GLint row_length = 0, y_up = 0;
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &row_length);
    OSMesaGetIntegerv(OSMESA_Y_UP, &y_up);
    capi_check(row_length == (tessera ? ROW : -1), "row length after invalid calls: %d", row_length);
    capi_value("y_up_after_invalid", "%d", y_up);

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return capi_finish();
}

/* The raster position and pixel rectangles: glRasterPos (transformed, clipped: invalid
 * outside the view volume, its color and distance), glWindowPos, the GL_CURRENT_RASTER_*
 * queries; text drawn with glBitmap (advancing the raster position, through the scissor,
 * alpha, depth and blend stages); glDrawPixels of several formats and types, with positive,
 * fractional and negative zoom, through the depth test, and of depth values; glBitmap and
 * glDrawPixels compiled into a display list with the unpack modes of compile time. */
#include "common.h"

#define W 96
#define H 64

/* A 8x8 font of three glyphs, rows bottom-up. */
static const GLubyte glyphs[3][8] = {
    {0x18, 0x24, 0x42, 0x7e, 0x42, 0x42, 0x42, 0x00},
    {0x7c, 0x42, 0x42, 0x7c, 0x42, 0x42, 0x7c, 0x00},
    {0x3c, 0x42, 0x40, 0x40, 0x40, 0x42, 0x3c, 0x00},
};

static void raster_values(const char *stage)
{
    capi_value_query(stage, "raster_position", GL_CURRENT_RASTER_POSITION, 4);
    capi_value_query(stage, "raster_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
    capi_value_query(stage, "raster_color", GL_CURRENT_RASTER_COLOR, 4);
    capi_value_query(stage, "raster_distance", GL_CURRENT_RASTER_DISTANCE, 1);
}

int main(void)
{
    capi_make_context(OSMESA_RGBA, GL_UNSIGNED_BYTE, 24, 8, 0, W, H, NULL);
    raster_values("initial");
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* Raster positions and their attributes. */
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glRasterPos3f(10.25f, 20.5f, 0.5f);
    raster_values("rasterpos");
    /* GL 2.1 section 2.14.6 clamps the raster color (GL_CLAMP_VERTEX_COLOR); Mesa 22 keeps
     * it unclamped (manifest). */
    glColor3f(2, -1, 0.5f);
    glRasterPos2i(W + 1, 5);
    raster_values("outside");
    glRasterPos4f(10, 10, 0, 1);
    glPushMatrix();
    glTranslatef(0, 0, -0.5f);
    glRasterPos2f(3, 4);
    raster_values("clamped_color");
    glPopMatrix();
    glWindowPos2i(-5, 7);
    raster_values("windowpos");
    glWindowPos3f(5.5f, 6.5f, 0.25f);
    raster_values("windowpos3");

    /* Text with glBitmap: two lines, the second through the scissor and blending. */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1, 1, 0);
    glRasterPos2i(4, 50);
    for (int i = 0; i < 6; i++)
        glBitmap(8, 8, 0, 0, 9, 0, glyphs[i % 3]);
    raster_values("after_text");
    glBitmap(0, 0, 0, 0, -20, -12, NULL); /* a move only */
    raster_values("after_move");
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 40, H);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0, 1, 1, 0.5f);
    glRasterPos2f(4.5f, 40.0f);
    glBitmap(8, 8, 1.5f, 0.5f, 9, 0, glyphs[0]);
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[1]);
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[2]);
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[0]);
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[1]);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    /* Invalid raster position: nothing drawn, no move. */
    glRasterPos2i(-10, 5);
    glBitmap(8, 8, 0, 0, 9, 0, glyphs[0]);
    raster_values("invalid_bitmap");
    glBitmap(-1, 8, 0, 0, 0, 0, glyphs[0]);
    capi_expect_error(GL_INVALID_VALUE, "glBitmap negative width");

    /* glDrawPixels: RGBA bytes, RGB floats zoomed, luminance, packed 5-6-5, negative zoom. */
    GLubyte rgba[6 * 4 * 4];
    GLfloat rgbf[5 * 3 * 3];
    GLubyte lum[7 * 3];
    GLushort rgb565[4 * 4];
    for (int i = 0; i < 6 * 4; i++) {
        rgba[4 * i] = (GLubyte)(i * 10);
        rgba[4 * i + 1] = (GLubyte)(255 - i * 7);
        rgba[4 * i + 2] = (GLubyte)(i * 3);
        rgba[4 * i + 3] = 255;
    }
    for (int i = 0; i < 5 * 3 * 3; i++)
        rgbf[i] = (float)((i * 37) % 100) / 99.0f;
    for (int i = 0; i < 7 * 3; i++)
        lum[i] = (GLubyte)(i * 12);
    for (int i = 0; i < 16; i++)
        rgb565[i] = (GLushort)((i * 2) << 11 | (i * 4) << 5 | (31 - i * 2));
    glRasterPos2i(2, 2);
    glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glRasterPos2i(12, 2);
    glPixelZoom(2.0f, 3.0f);
    glDrawPixels(5, 3, GL_RGB, GL_FLOAT, rgbf);
    glPixelZoom(1.4f, 1.0f);
    glRasterPos2f(24.3f, 12.0f); /* rounded to 24; no pixel centre on a zoomed pixel's edge */
    glDrawPixels(7, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glPixelZoom(-1.0f, -2.0f);
    glRasterPos2i(50, 30);
    glDrawPixels(4, 4, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, rgb565);
    glPixelZoom(1, 1);
    capi_value_query("zoom", "zoom_x", GL_ZOOM_X, 1);
    /* Pixel transfer scale and bias (then clamped). */
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferi(GL_BLUE_SCALE, 3);
    capi_value_query("transfer", "green_bias", GL_GREEN_BIAS, 1);
    glRasterPos2i(2, 30);
    glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPushAttrib(GL_PIXEL_MODE_BIT);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPopAttrib();
    capi_value_query("popped", "red_scale", GL_RED_SCALE, 1);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_SCALE, 1);
    glPixelTransferf(GL_ZOOM_X, 1);
    capi_expect_error(GL_INVALID_ENUM, "glPixelTransfer bad pname");
    /* Pixel maps: red inverted, green through a 4-entry ramp, blue from GLushort values. */
    {
        static const GLfloat invert[2] = {1, 0};
        static const GLfloat ramp[4] = {0.1f, 0.9f, 0.3f, 0.6f};
        static const GLushort blue[3] = {65535, 0, 32768};
        GLfloat back[4];
        GLuint back_ui[4];
        GLushort back_us[3];
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
        glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, ramp);
        glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 3, blue);
        glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 3, ramp);
        capi_expect_error(GL_INVALID_VALUE, "index map size not a power of two");
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, invert);
        capi_expect_error(GL_INVALID_VALUE, "empty map");
        capi_value_query("maps", "g_to_g_size", GL_PIXEL_MAP_G_TO_G_SIZE, 1);
        capi_value_query("maps", "max_table", GL_MAX_PIXEL_MAP_TABLE, 1);
        glGetPixelMapfv(GL_PIXEL_MAP_G_TO_G, back);
        capi_value("maps.g_to_g", "%a %a %a %a", back[0], back[1], back[2], back[3]);
        glGetPixelMapuiv(GL_PIXEL_MAP_G_TO_G, back_ui);
        capi_value("maps.g_to_g_ui", "%u %u %u %u", back_ui[0], back_ui[1], back_ui[2], back_ui[3]);
        glGetPixelMapusv(GL_PIXEL_MAP_B_TO_B, back_us);
        capi_value("maps.b_to_b_us", "%u %u %u", back_us[0], back_us[1], back_us[2]);
        /* llvmpipe looks the maps up in a filtered texture (blue and alpha between entries);
         * tessera looks each component up in its table at round(c * (size - 1)), as GL 2.1
         * section 3.6.5 says. Checked on tessera only, then cleared. */
        glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
        glRasterPos2i(2, 36);
        glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
        GLubyte mapped[4];
        glReadPixels(2, 36, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, mapped);
        if (capi_is_tessera())
            capi_check(mapped[0] == 255 && mapped[1] == 153 && mapped[2] == 255 && mapped[3] == 0,
                       "mapped %u %u %u %u", mapped[0], mapped[1], mapped[2], mapped[3]);
        glEnable(GL_SCISSOR_TEST);
        glScissor(2, 36, 6, 4);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
    /* Through the depth test: a quad at z = 0, then pixels at raster z -0.5 (nearer) and
     * +0.5 (farther) with GL_LESS. */
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.5f, 0.5f, 0.5f);
    glBegin(GL_QUADS);
    glVertex2i(56, 2);
    glVertex2i(90, 2);
    glVertex2i(90, 20);
    glVertex2i(56, 20);
    glEnd();
    glRasterPos3f(58, 4, 0.5f); /* window z 0.25: nearer than the quad's 0.5 */
    glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glRasterPos3f(66, 4, -0.5f); /* window z 0.75: hidden */
    glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    /* Depth pixels: a ramp, drawn with the raster color where nearer than the quad. */
    GLfloat depths[16 * 8];
    for (int i = 0; i < 16 * 8; i++)
        depths[i] = (float)(i % 16) / 15.0f;
    glColor3f(1, 0, 0);
    glRasterPos2i(72, 8);
    glDrawPixels(16, 8, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    glDisable(GL_DEPTH_TEST);
    glDrawPixels(2, 2, GL_RGBA, GL_DOUBLE, rgba);
    capi_expect_error(GL_INVALID_ENUM, "glDrawPixels GL_DOUBLE");
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, rgba);
    capi_expect_error(GL_INVALID_OPERATION, "glDrawPixels packed type of the wrong size");

    /* Compiled: the unpack modes of compile time apply. */
    GLuint list = glGenLists(1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glNewList(list, GL_COMPILE);
    glRasterPos2i(40, 22);
    glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glColor3f(1, 0.5f, 0);
    glRasterPos2i(40, 30);
    glBitmap(8, 7, 0, 0, 0, 0, glyphs[2]);
    glEndList();
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    for (int i = 0; i < 6 * 4 * 4; i++)
        rgba[i] = 0;
    glCallList(list);
    capi_expect_error(GL_NO_ERROR, "no error");
    capi_save_framebuffer("pixel_rects", W, H);
    return capi_finish();
}

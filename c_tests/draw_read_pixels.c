/* ffl-test: differential */
/*
 * glDrawPixels and glReadPixels (§3.6.4, §4.3.1, §4.3.2). In feedback, glDrawPixels with
 * a valid raster position gives GL_DRAW_PIXEL_TOKEN and the raster position as a vertex
 * (§5.3), in every feedback type; with an invalid one nothing. No selection hit (§5.2
 * counts primitives and raster positions only). glReadPixels of a framebuffer nothing was
 * drawn into (the OSMesa build's buffer starts zeroed): every color 0 after pixel transfer
 * (a red bias shows), packed with the pack modes (row length, skipped rows and pixels,
 * alignment), the bytes between rows untouched. Errors: negative sizes, bad formats and
 * types, GL_BITMAP with a color format, packed types with the wrong format, color indices
 * read in RGBA mode, inside glBegin/glEnd.
 */
#include "ffl_test.h"

#define BUF_SIZE 256

static const GLubyte image[2 * 2 * 4] = {
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16,
};

static void feedback(GLenum type)
{
    static GLfloat buf[BUF_SIZE];
    static const char *names[] = { "2d", "3d", "3d_color", "3d_color_texture", "4d" };
    static const GLenum types[] = { GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE,
                                    GL_4D_COLOR_TEXTURE };
    char tag[32];
    int k;
    GLint n;
    for (k = 0; types[k] != type; k++)
        ;
    sprintf(tag, "draw_%s", names[k]);
    glFeedbackBuffer(BUF_SIZE, type, buf);
    glRenderMode(GL_FEEDBACK);
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glTexCoord4f(0.5f, 0.25f, 0.125f, 1.0f);
    glRasterPos3f(10.0f, 20.0f, 0.5f);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glPassThrough(1.0f);
    glRasterPos3f(1000.0f, 20.0f, 0.5f); /* outside: invalid */
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glPassThrough(2.0f);
    glRasterPos2f(3.0f, 4.0f);
    glDrawPixels(0, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_BITMAP, image);
    n = glRenderMode(GL_RENDER);
    printf("%s count %d\n", tag, (int)n);
    ffl_print_feedback(tag, buf, n, type);
    ffl_print_error(tag);
}

static void errors(void)
{
    glRasterPos2f(3.0f, 4.0f);
    glDrawPixels(-1, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    ffl_print_error("draw_negative_width");
    glDrawPixels(2, -1, GL_RGBA, GL_UNSIGNED_BYTE, image);
    ffl_print_error("draw_negative_height");
    glDrawPixels(2, 2, GL_LINEAR, GL_UNSIGNED_BYTE, image);
    ffl_print_error("draw_bad_format");
    glDrawPixels(2, 2, GL_RGBA, GL_LINEAR, image);
    ffl_print_error("draw_bad_type");
    glDrawPixels(2, 2, GL_RGBA, GL_BITMAP, image);
    ffl_print_error("draw_bitmap_rgba");
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, image);
    ffl_print_error("draw_565_rgba");
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, image);
    ffl_print_error("draw_4444_rgb");
    glBegin(GL_POINTS);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glEnd();
    ffl_print_error("draw_in_begin_end");
}

static void print_bytes(const char *what, const GLubyte *bytes, int n)
{
    int i;
    printf("%s bytes", what);
    for (i = 0; i < n; i++)
        printf(" %d", (int)bytes[i]);
    printf("\n");
}

static void read_back(void)
{
    GLubyte bytes[64];
    GLfloat floats[16];
    int i;

    memset(bytes, 0xab, sizeof bytes);
    glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    ffl_print_error("read_rgba");
    print_bytes("read_rgba", bytes, 20);

    /* Rows of 3 pixels' room, 1 row and 1 pixel skipped, 3-byte RGB pixels aligned to 4. */
    memset(bytes, 0xab, sizeof bytes);
    glPixelStorei(GL_PACK_ROW_LENGTH, 3);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, bytes);
    ffl_print_error("read_rgb_packed");
    print_bytes("read_rgb_packed", bytes, 40);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);

    /* Pixel transfer applies to what is read. */
    glPixelTransferf(GL_RED_BIAS, 0.5f);
    glPixelTransferf(GL_ALPHA_SCALE, 2.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.25f);
    for (i = 0; i < 16; i++)
        floats[i] = -7.0f;
    glReadPixels(0, 0, 2, 1, GL_RGBA, GL_FLOAT, floats);
    ffl_print_error("read_biased");
    ffl_pfv("read_biased", floats, 10);
    printf("\n");
    memset(bytes, 0xab, sizeof bytes);
    glReadPixels(0, 0, 3, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, bytes);
    ffl_print_error("read_packed_type");
    print_bytes("read_packed_type", bytes, 16);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);

    glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, bytes);
    ffl_print_error("read_color_index");
    glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    ffl_print_error("read_negative_width");
    glReadPixels(0, 0, 1, 1, GL_LINEAR, GL_UNSIGNED_BYTE, bytes);
    ffl_print_error("read_bad_format");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, bytes);
    ffl_print_error("read_bitmap_rgba");
    glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, bytes);
    ffl_print_error("read_4444_rgb");
    glBegin(GL_POINTS);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    glEnd();
    ffl_print_error("read_in_begin_end");
}

int main(void)
{
    GLuint records[16];
    GLint hits;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    feedback(GL_2D);
    feedback(GL_3D);
    feedback(GL_3D_COLOR);
    feedback(GL_3D_COLOR_TEXTURE);
    feedback(GL_4D_COLOR_TEXTURE);

    glSelectBuffer(16, records);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(3);
    glRasterPos2f(3.0f, 4.0f);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glLoadName(5);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
    hits = glRenderMode(GL_RENDER);
    printf("select hits %d\n", (int)hits);
    ffl_print_hits("select", records, hits, 16);
    ffl_print_error("select");

    errors();
    read_back();
    return 0;
}

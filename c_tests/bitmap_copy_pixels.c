/* ffl-test: differential */
/*
 * glBitmap and glCopyPixels in feedback (§5.3): with a valid raster position,
 * GL_BITMAP_TOKEN or GL_COPY_PIXEL_TOKEN and the raster position as a vertex
 * (window coordinates, raster color, raster texture coordinate) in every
 * feedback type; glBitmap then moves the raster position by (xmove, ymove),
 * a NULL zero-sized bitmap included (the usual way to move it). With an
 * invalid raster position nothing is fed back and nothing moves. Neither
 * makes a selection hit (§5.2 counts primitives and raster positions only).
 * Errors: negative sizes, a bad copy type, inside glBegin/glEnd.
 */
#include "ffl_test.h"

static void position(const char *what)
{
    GLfloat v[4];
    GLboolean valid;
    glGetFloatv(GL_CURRENT_RASTER_POSITION, v);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    printf("%s", what);
    ffl_pfv("xyzw", v, 4);
    printf(" valid %d error %s\n", (int)valid, ffl_error_name(glGetError()));
}

int main(void)
{
    static const GLenum types[5] = { GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE,
                                     GL_4D_COLOR_TEXTURE };
    static const GLubyte bits[8] = { 0xff, 0x81, 0x81, 0xff, 0, 0, 0, 0 };
    GLfloat buffer[512];
    GLuint records[16];
    GLint n, i, t;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glTexCoord4f(0.5f, 0.25f, 0.125f, 2.0f);

    for (t = 0; t < 5; t++) {
        glRasterPos4f(0.1f, 0.2f, -2.0f, 1.0f);
        glFeedbackBuffer(512, types[t], buffer);
        glRenderMode(GL_FEEDBACK);
        glBitmap(8, 4, 1.5f, 2.0f, 3.0f, -1.0f, bits);
        glCopyPixels(0, 0, 4, 4, GL_COLOR);
        glBitmap(0, 0, 0, 0, 10.0f, 10.0f, NULL);
        glCopyPixels(1, 1, 2, 2, GL_DEPTH);
        glRasterPos3f(0, 0, 5); /* behind the eye: invalid */
        glBitmap(8, 4, 0, 0, 1, 1, bits);
        glCopyPixels(0, 0, 1, 1, GL_STENCIL);
        n = glRenderMode(GL_RENDER);
        printf("type %d values %d:", t, (int)n);
        for (i = 0; i < n; i++) {
            printf(" %.9g", buffer[i]);
        }
        printf(" error %s\n", ffl_error_name(glGetError()));
        position("after");
    }

    /* Outside feedback the bitmap still moves the raster position. */
    glRasterPos2f(0.0f, 0.0f);
    glBitmap(0, 0, 0, 0, 2.5f, -3.5f, NULL);
    position("moved_in_render_mode");

    glSelectBuffer(16, records);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(4);
    glBitmap(8, 4, 0, 0, 1, 1, bits);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    n = glRenderMode(GL_RENDER);
    printf("select hits %d error %s\n", (int)n, ffl_error_name(glGetError()));
    position("moved_in_select_mode");

    glBitmap(-1, 4, 0, 0, 1, 1, bits);
    printf("bitmap_negative_width error %s\n", ffl_error_name(glGetError()));
    glBitmap(1, -4, 0, 0, 1, 1, bits);
    printf("bitmap_negative_height error %s\n", ffl_error_name(glGetError()));
    position("unmoved_by_errors");
    glCopyPixels(0, 0, -1, 1, GL_COLOR);
    printf("copy_negative_width error %s\n", ffl_error_name(glGetError()));
    glCopyPixels(0, 0, 1, 1, 0x1234);
    printf("copy_bad_type error %s\n", ffl_error_name(glGetError()));
    glBegin(GL_POINTS);
    glBitmap(0, 0, 0, 0, 1, 1, NULL);
    glEnd();
    printf("bitmap_inside error %s\n", ffl_error_name(glGetError()));
    glBegin(GL_POINTS);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    glEnd();
    printf("copy_inside error %s\n", ffl_error_name(glGetError()));
    return 0;
}

/* ffl-test: differential */
/*
 * Clipping against the view volume (§2.12) with a perspective projection
 * (glFrustum): points, segments, triangles, quads and polygons crossing each
 * of the six sides (left, right, bottom, top, near, far), crossing several
 * at once (a corner; a triangle larger than the view on every side; a
 * segment leaving on both ends), entirely outside, and with vertices behind
 * the eye (clip w < 0). New vertices interpolate color and texture
 * coordinates; a clipped triangle becomes a polygon fed back as a fan of
 * triangles. Filled, then as outlines (GL_LINE: clipping adds no edges along
 * the view volume's sides in Mesa's draw module, which fflight copies) and as
 * points (GL_POINT), in GL_3D_COLOR and GL_4D_COLOR_TEXTURE (clip w).
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"

#define BUF_SIZE 16384

typedef struct {
    GLenum mode;
    int n;
    float v[4][3];
} shape;

/* eye coordinates; the view volume at depth d = -z is |x| <= d, |y| <= d,
 * 1 <= d <= 10 */
static const shape shapes[] = {
    { GL_TRIANGLES, 3, { { -8, 0, -5 }, { 0, -1, -5 }, { 0, 1.5f, -5 } } },     /* left */
    { GL_TRIANGLES, 3, { { 8, 0.5f, -5 }, { 0, 1, -5 }, { 0.5f, -1.5f, -5 } } }, /* right */
    { GL_TRIANGLES, 3, { { 0.3f, -7, -5 }, { 1, 0, -5 }, { -1, 0.5f, -5 } } },   /* bottom */
    { GL_TRIANGLES, 3, { { -0.2f, 9, -6 }, { -1, 0, -4 }, { 1.5f, 0.5f, -5 } } }, /* top */
    { GL_TRIANGLES, 3, { { 0.1f, 0.2f, -0.5f }, { 1, 0, -3 }, { -1, 1, -3 } } },  /* near */
    { GL_TRIANGLES, 3, { { 0.2f, -0.1f, -14 }, { 1, 0, -6 }, { -1, 1, -6 } } },   /* far */
    { GL_TRIANGLES, 3, { { 0.3f, 0.1f, 2 }, { 1, 0, -4 }, { -1, 0.5f, -4 } } },   /* behind the eye */
    { GL_TRIANGLES, 3, { { -9, 9, -5 }, { 2, -1, -5 }, { 3, 2.5f, -5 } } },       /* a corner */
    { GL_TRIANGLES, 3, { { -20, -20, -5 }, { 20, -19, -5 }, { 0.5f, 30, -5 } } }, /* every side */
    { GL_TRIANGLES, 3, { { 10, 10, -5 }, { 12, 10, -5 }, { 11, 13, -5 } } },      /* outside */
    { GL_TRIANGLES, 3, { { -2, -2, 3 }, { 2, -2, 4 }, { 0, 2, 3.5f } } },         /* all behind */
    { GL_QUADS, 4, { { -1, -1, -0.5f }, { 1, -1.2f, -0.5f }, { 1.2f, 1, -12 }, { -1, 1, -12 } } },
    { GL_POLYGON, 4, { { -7, -1, -5 }, { 0, -8, -6 }, { 7, 1, -5 }, { 0.5f, 8, -4 } } },
    { GL_LINES, 2, { { -8, 0.2f, -5 }, { 8, -0.3f, -5 } } },                      /* both ends */
    { GL_LINES, 2, { { 0.2f, 0.1f, 3 }, { 0.5f, 0.5f, -5 } } },                   /* behind */
    { GL_LINES, 2, { { 0.1f, 0.3f, -0.2f }, { -0.4f, 0.2f, -15 } } },             /* near, far */
    { GL_LINES, 2, { { 9, 9, -5 }, { 12, 9, -5 } } },                             /* outside */
    { GL_LINE_STRIP, 4, { { 3, 0, -5 }, { 7, 1, -5 }, { 1, 1, -5 }, { -1, -7, -5 } } },
    /* a strip whose first segment is clipped away (clip_line_strip_reset.c) */
    { GL_LINE_STRIP, 4, { { 8, 0, -5 }, { 7, 1, -5 }, { 1, 1, -5 }, { -1, -7, -5 } } },
    { GL_LINE_LOOP, 3, { { -2, 0, 2 }, { 2, 1, -5 }, { 0, -2, -5 } } },
    { GL_POINTS, 4, { { 0.5f, 0.5f, -5 }, { -6, 0, -5 }, { 0, 0, 2 }, { 0, 0, -11 } } },
};

static void draw(ffl_fb *fb)
{
    int s, k, c = 0;
    for (s = 0; s < (int)(sizeof shapes / sizeof shapes[0]); s++) {
        ffl_fb_begin(fb, shapes[s].mode);
        for (k = 0; k < shapes[s].n; k++, c++) {
            glColor4f(0.05f * (float)(c % 20), 1.0f - 0.04f * (float)(c % 25),
                      (float)(c % 3) / 2.0f, 1.0f - 0.01f * (float)c);
            glTexCoord4f(0.1f * (float)k, -0.2f * (float)s, 0.5f, 1.0f + 0.25f * (float)k);
            glVertex3fv(shapes[s].v[k]);
        }
        glEnd();
    }
}

static int pass(const char *tag, GLenum type)
{
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, type);
    draw(&fb);
    return ffl_fb_finish(&fb, tag, NULL, NULL);
}

int main(void)
{
    int failed = 0;
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    failed |= pass("fill_3d_color", GL_3D_COLOR);
    failed |= pass("fill_4d_color_texture", GL_4D_COLOR_TEXTURE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    failed |= pass("line_3d_color", GL_3D_COLOR);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    failed |= pass("point_4d_color_texture", GL_4D_COLOR_TEXTURE);
    return failed;
}

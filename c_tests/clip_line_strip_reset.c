/* ffl-test: differential */
/*
 * The line stipple reset of a strip or loop whose first segment is clipped
 * away (§3.4.2, §5.3). The stipple counter is reset when glBegin starts a
 * strip or loop and advances only with the fragments a segment produces; a
 * segment clipped away entirely produces none, so the first segment fed back
 * still starts from a reset counter and is a GL_LINE_RESET_TOKEN
 * ("GL_LINE_RESET_TOKEN is returned whenever the line stipple pattern is
 * reset"). Strips and loops whose first one or two segments lie outside the
 * view volume or a user clip plane, and for contrast the same with the first
 * segment visible.
 *
 * osmesa-known: line-reset
 * (OSMesa feeds back GL_LINE_TOKEN for every segment of a strip or loop.)
 */
#include "ffl_test.h"

#define BUF_SIZE 2048

static void strip(ffl_fb *fb, GLenum mode, int n, const float (*v)[2])
{
    int k;
    ffl_fb_begin(fb, mode);
    for (k = 0; k < n; k++) {
        glColor3f(0.2f * (float)k, 0.5f, 1.0f - 0.2f * (float)k);
        glVertex2fv(v[k]);
    }
    glEnd();
}

int main(void)
{
    /* the view is [-10, 10] x [-10, 10] */
    static const float first_out[4][2] = { { 12, 0 }, { 15, 3 }, { 5, 3 }, { -5, -3 } };
    static const float two_out[4][2] = { { 12, 0 }, { 15, 3 }, { 11, -2 }, { -5, -3 } };
    static const float first_in[4][2] = { { 2, 0 }, { 5, 3 }, { 15, 3 }, { -5, -3 } };
    static const float plane_out[4][2] = { { -6, -1 }, { -7, 2 }, { 5, 3 }, { 4, -3 } };
    static const GLdouble plane[4] = { 1, 0, 0, 4 }; /* x >= -4 */
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    int failed = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    strip(&fb, GL_LINE_STRIP, 4, first_out);
    strip(&fb, GL_LINE_STRIP, 4, two_out);
    strip(&fb, GL_LINE_LOOP, 4, first_out);
    strip(&fb, GL_LINE_STRIP, 4, first_in);
    strip(&fb, GL_LINES, 4, first_out);
    failed |= ffl_fb_finish(&fb, "view_volume", NULL, NULL);

    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    strip(&fb, GL_LINE_STRIP, 4, plane_out);
    strip(&fb, GL_LINE_LOOP, 4, plane_out);
    failed |= ffl_fb_finish(&fb, "user_plane", NULL, NULL);
    return failed;
}

/* ffl-test: differential */
/*
 * Face culling (§2.14.1, §3.5.1): with GL_CULL_FACE enabled, glCullFace
 * GL_FRONT, GL_BACK or GL_FRONT_AND_BACK discards polygons of that facing
 * before they are fed back; glFrontFace GL_CCW or GL_CW says which window
 * orientation is the front. Points and segments are never culled. The same
 * shapes (triangles, strips, fans, quads, quad strips, polygons of both
 * orientations, points, lines) in every combination, culling disabled and
 * enabled, filled and as outlines (culling comes before the polygon mode).
 * The state is read back (glIsEnabled, GL_CULL_FACE_MODE, GL_FRONT_FACE).
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 16384

static vref_set vref;

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    static const GLenum modes[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                    GL_QUAD_STRIP, GL_POLYGON, GL_POINTS, GL_LINES,
                                    GL_LINE_STRIP };
    GLint v[2];
    ffl_fb fb;
    ffl_rng r;
    int m, k;
    glGetIntegerv(GL_CULL_FACE_MODE, v);
    glGetIntegerv(GL_FRONT_FACE, v + 1);
    printf("%s enabled %d cull_face_mode 0x%x front_face 0x%x\n", tag,
           glIsEnabled(GL_CULL_FACE) == GL_TRUE, (unsigned)v[0], (unsigned)v[1]);
    ffl_rng_seed(&r, 0x63756c6cu); /* the same shapes every pass */
    ffl_fb_init(&fb);
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (k = 0; k < 4; k++)
            vref_draw_shape(&vref, &fb, &r, modes[m], 4 + k, ffl_rng_float(&r, -4, 4),
                            ffl_rng_float(&r, -4, 4), 5, 3);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    static const GLenum culls[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    static const char *cull_names[3] = { "front", "back", "front_and_back" };
    static const GLenum fronts[2] = { GL_CCW, GL_CW };
    static const char *front_names[2] = { "ccw", "cw" };
    ref_state ref;
    char tag[64];
    int c, f, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    mirror_rotatef(&ref, 10, 0.5f, 0.2f, 1);

    failed |= pass("default", &ref);
    for (f = 0; f < 2; f++) {
        glFrontFace(fronts[f]);
        for (c = 0; c < 3; c++) {
            glCullFace(culls[c]);
            glDisable(GL_CULL_FACE);
            sprintf(tag, "off_%s_%s", cull_names[c], front_names[f]);
            failed |= pass(tag, &ref);
            glEnable(GL_CULL_FACE);
            sprintf(tag, "on_%s_%s", cull_names[c], front_names[f]);
            failed |= pass(tag, &ref);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            sprintf(tag, "on_%s_%s_line", cull_names[c], front_names[f]);
            failed |= pass(tag, &ref);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        }
    }
    vref_print_counts(&vref);
    return failed;
}

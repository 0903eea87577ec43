/* ffl-test: differential */
/*
 * Polygon modes (§3.5.4): glPolygonMode for the front and the back face
 * separately, every pair of GL_FILL, GL_LINE and GL_POINT, then
 * GL_FRONT_AND_BACK. A polygon is fed back in the mode of its facing: filled
 * (polygon tokens), as its boundary edges (line tokens; a split quad or
 * polygon draws no inner edges) or as the vertices that start boundary
 * edges (point tokens). No edge flags here (see osmesa_diff_edge_flags.c).
 * Every polygon primitive, both orientations, lit; GL_POLYGON_MODE is read
 * back. Points and segments are not polygons and ignore the mode.
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
                                    GL_QUAD_STRIP, GL_POLYGON, GL_POINTS, GL_LINE_LOOP };
    GLint v[2];
    ffl_fb fb;
    ffl_rng r;
    int m, k;
    glGetIntegerv(GL_POLYGON_MODE, v);
    printf("%s polygon_mode 0x%x 0x%x\n", tag, (unsigned)v[0], (unsigned)v[1]);
    ffl_rng_seed(&r, 0x6d6f6465u);
    ffl_fb_init(&fb);
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (k = 0; k < 4; k++)
            vref_draw_shape(&vref, &fb, &r, modes[m], 3 + 2 * k, ffl_rng_float(&r, -4, 4),
                            ffl_rng_float(&r, -4, 4), 5, 3);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    static const GLenum modes[3] = { GL_FILL, GL_LINE, GL_POINT };
    static const char *names[3] = { "fill", "line", "point" };
    ref_state ref;
    char tag[64];
    int f, b, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    mirror_rotatef(&ref, -20, 0.1f, 0.4f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, -0.4f, 0.3f, 1, 0);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (f = 0; f < 3; f++) {
        for (b = 0; b < 3; b++) {
            glPolygonMode(GL_FRONT, modes[f]);
            glPolygonMode(GL_BACK, modes[b]);
            sprintf(tag, "front_%s_back_%s", names[f], names[b]);
            failed |= pass(tag, &ref);
        }
    }
    for (f = 0; f < 3; f++) {
        glPolygonMode(GL_FRONT_AND_BACK, modes[f]);
        sprintf(tag, "front_and_back_%s", names[f]);
        failed |= pass(tag, &ref);
    }
    vref_print_counts(&vref);
    return failed;
}

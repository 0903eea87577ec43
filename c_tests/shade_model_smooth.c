/* ffl-test: differential */
/*
 * Smooth shading (§2.14.7): with glShadeModel(GL_SMOOTH) (set after
 * GL_FLAT, so the change is seen) every vertex keeps its own color in
 * feedback, and a vertex made by clipping gets the color interpolated
 * between the two ends of the clipped edge (§2.12), primary color and
 * alpha alike. Every primitive, a color per vertex, unlit and lit, with a
 * perspective projection and shapes crossing the view volume and a user
 * clip plane, filled and as outlines. GL_SHADE_MODEL is read back.
 * (glShadeModel(GL_FLAT) in feedback: osmesa_diff_flat_feedback.c.)
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 32768

static vref_set vref;

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    GLint model;
    ffl_fb fb;
    ffl_rng r;
    int m, k;
    glGetIntegerv(GL_SHADE_MODEL, &model);
    printf("%s shade_model 0x%x\n", tag, (unsigned)model);
    ffl_rng_seed(&r, 0x736d6fu);
    ffl_fb_init(&fb);
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (k = 0; k < 3; k++)
            vref_draw_shape(&vref, &fb, &r, modes[m], 4 + 2 * k, ffl_rng_float(&r, -6, 6),
                            ffl_rng_float(&r, -6, 6), 8, 6);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    static const GLdouble plane[4] = { 0.3, 1, 0, 3 };
    ref_state ref;
    int failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    mirror_translatef(&ref, 0, 0, -12);
    mirror_rotatef(&ref, 35, 1, 0.3f, 0.1f);
    glClipPlane(GL_CLIP_PLANE1, plane);
    glEnable(GL_CLIP_PLANE1);

    glShadeModel(GL_FLAT);
    glShadeModel(GL_SMOOTH);
    failed |= pass("unlit", &ref);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 1, 1, 2, 0);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
    mirror_materialf(&ref, GL_FRONT_AND_BACK, GL_SHININESS, 16);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);
    failed |= pass("lit", &ref);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    failed |= pass("lit_line", &ref);
    vref_print_counts(&vref);
    return failed;
}

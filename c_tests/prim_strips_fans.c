/* ffl-test: differential */
/*
 * Triangle strips and fans (§2.6.1): GL_TRIANGLE_STRIP and GL_TRIANGLE_FAN
 * with 0 to 10 vertices (fewer than three make nothing). A strip's odd
 * triangles keep the strip's orientation; a fan turns around its first
 * vertex (here sometimes by more than a full turn). Random shapes of both
 * orientations (no culling), a color and a normal per vertex, smooth
 * shading, unlit and lit. Each fed-back vertex that is a drawn vertex carries
 * the reference's window coordinates and color (reference/vertex_ref.h).
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 8192

static vref_set vref;

static void lights(ref_state *ref)
{
    mirror_light4f(ref, GL_LIGHT0, GL_POSITION, 1, 2, 3, 0);
    mirror_light4f(ref, GL_LIGHT1, GL_POSITION, -3, 1, 6, 1);
    mirror_light4f(ref, GL_LIGHT1, GL_DIFFUSE, 0.4f, 0.3f, 0.2f, 1);
    mirror_light4f(ref, GL_LIGHT1, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_lightf(ref, GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    mirror_material4f(ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
    mirror_materialf(ref, GL_FRONT_AND_BACK, GL_SHININESS, 20);
    mirror_enable(ref, GL_LIGHT0, 1);
    mirror_enable(ref, GL_LIGHT1, 1);
    mirror_enable(ref, GL_COLOR_MATERIAL, 1);
}

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    ffl_rng r;
    static const GLenum modes[] = { GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN };
    int m, count;
    ffl_rng_seed(&r, 0x737472u);
    ffl_fb_init(&fb);
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(ref));
    printf("\n");
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (count = 0; count <= 10; count++)
            vref_draw_shape(&vref, &fb, &r, modes[m], count, 0, 0, 9, 5);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    ref_state ref;
    int failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    mirror_rotatef(&ref, 25, 0.3f, 0.2f, 1);

    failed |= pass("unlit", &ref);
    lights(&ref);
    mirror_enable(&ref, GL_LIGHTING, 1);
    failed |= pass("lit", &ref);
    vref_print_counts(&vref);
    return failed;
}

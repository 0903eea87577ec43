/* ffl-test: differential */
/*
 * Quadrilaterals and polygons (§2.6.1): GL_QUADS with 0 to 13 vertices (an
 * incomplete last group of one to three vertices dropped), GL_QUAD_STRIP
 * (an odd last vertex dropped, fewer than four make nothing) and GL_POLYGON
 * (fewer than three make nothing). Convex shapes of both orientations (no
 * culling), a color and a normal per vertex, smooth shading, unlit and lit.
 * Feedback returns them as triangles; how a quad or polygon is split is the
 * implementation's choice (fflight splits as Mesa's draw module does, so the
 * streams compare one for one). Each fed-back vertex that is a drawn vertex
 * carries the reference's window coordinates and color.
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
    static const GLenum modes[] = { GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    int m, count;
    ffl_rng_seed(&r, 0x717561u);
    ffl_fb_init(&fb);
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(ref));
    printf("\n");
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (count = 0; count <= 13; count++)
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

/* ffl-test: differential */
/*
 * Two-sided lighting of polygons (§2.14.1): with GL_LIGHT_MODEL_TWO_SIDE a
 * back-facing polygon takes the back color, lit with the back material and
 * the negated normal; a front-facing one the front color; points and
 * segments always the front color. The back material differs from the front
 * in every property (ambient, diffuse with its alpha, specular, emission,
 * shininess). Without two-sided lighting back faces use the front colors.
 * Facing follows glFrontFace (CCW, then CW). Filled, where the fed-back
 * polygon's orientation gives the face; then as outlines and points with
 * only one facing left (the other culled), so the reference knows the face.
 * Two lights (a local spot light and a directional one), a local viewer.
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 16384

static vref_set vref;

static int pass(const char *tag, ref_state *ref, int face)
{
    static GLfloat buf[BUF_SIZE];
    static const GLenum modes[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                    GL_QUAD_STRIP, GL_POLYGON, GL_POINTS, GL_LINES };
    ffl_fb fb;
    ffl_rng r;
    int m, k;
    ffl_rng_seed(&r, 0x74776f73u);
    ffl_fb_init(&fb);
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(ref));
    printf("\n");
    vref_start(&vref, ref);
    vref.polygon_face = face;
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (k = 0; k < 4; k++)
            vref_draw_shape(&vref, &fb, &r, modes[m], 4 + k, ffl_rng_float(&r, -4, 4),
                            ffl_rng_float(&r, -4, 4), 5, 3);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

/* filled; then outlines and points of the back faces alone, then of the
 * front faces alone */
static int passes(const char *name, ref_state *ref)
{
    char tag[64];
    int failed = 0;
    sprintf(tag, "%s_fill", name);
    failed |= pass(tag, ref, -1);
    glEnable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glCullFace(GL_FRONT);
    sprintf(tag, "%s_back_line", name);
    failed |= pass(tag, ref, 1);
    glCullFace(GL_BACK);
    sprintf(tag, "%s_front_line", name);
    failed |= pass(tag, ref, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glCullFace(GL_FRONT);
    sprintf(tag, "%s_back_point", name);
    failed |= pass(tag, ref, 1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_CULL_FACE);
    return failed;
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
    glFrustum(-1, 1, -1, 1, 2, 40);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    mirror_translatef(&ref, 0, 0, -20);
    mirror_rotatef(&ref, 25, 0.3f, 1, 0.2f);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 2, 3, 10, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPOT_DIRECTION, -0.1f, -0.2f, -1, 0);
    mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_CUTOFF, 60);
    mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_EXPONENT, 4);
    mirror_lightf(&ref, GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.002f);
    mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, -1, 0.5f, -0.3f, 0);
    mirror_light4f(&ref, GL_LIGHT1, GL_DIFFUSE, 0.5f, 0.4f, 0.3f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_SPECULAR, 0.3f, 0.4f, 0.5f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_AMBIENT, 0.1f, 0.05f, 0.1f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_AMBIENT, 0.3f, 0.2f, 0.1f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_DIFFUSE, 0.7f, 0.5f, 0.2f, 0.9f);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_EMISSION, 0.05f, 0, 0, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 30);
    mirror_material4f(&ref, GL_BACK, GL_AMBIENT, 0.1f, 0.2f, 0.3f, 1);
    mirror_material4f(&ref, GL_BACK, GL_DIFFUSE, 0.2f, 0.4f, 0.8f, 0.35f);
    mirror_material4f(&ref, GL_BACK, GL_SPECULAR, 0.9f, 0.8f, 0.2f, 1);
    mirror_material4f(&ref, GL_BACK, GL_EMISSION, 0, 0.05f, 0.1f, 1);
    mirror_materialf(&ref, GL_BACK, GL_SHININESS, 7);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT1, 1);
    mirror_enable(&ref, GL_NORMALIZE, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 1);
    failed |= passes("two_side_ccw", &ref);
    glFrontFace(GL_CW);
    failed |= passes("two_side_cw", &ref);
    glFrontFace(GL_CCW);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 0);
    failed |= passes("one_side", &ref);
    vref_print_counts(&vref);
    return failed;
}

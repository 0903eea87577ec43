/* ffl-test: differential */
/*
 * User clip planes (§2.12): glClipPlane under a non-identity modelview (a
 * rotation, a translation and a non-uniform scale), so each plane is stored
 * in eye coordinates as (a b c d) M^-1; glGetClipPlane returns those (checked
 * against the reference's own inverse of the stored modelview). The drawing
 * modelview differs from the one the planes were given under: they stay
 * where they were put. Three of the six planes enabled (a fourth defined but
 * disabled), then all six; points, segments, strips, triangles, quads and
 * polygons crossing them, lit, filled, as outlines (GL_LINE: the edges that
 * clipping adds along a user plane are drawn, as in Mesa's draw module) and
 * as points.
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 32768

static vref_set vref;

/* "getclip <i> plane a b c d ref plane a' b' c' d'": the stored plane and
 * the reference's (a b c d) M^-1 for the modelview M stored when it was set */
static void print_plane(int i, const GLdouble *eqn, const ref_mat4 *m)
{
    GLdouble got[4] = { -9, -9, -9, -9 };
    double inv3[3][3], t[3], expect[4];
    int r, c;
    glGetClipPlane(GL_CLIP_PLANE0 + i, got);
    /* M = [A t; 0 1], M^-1 = [A^-1, -A^-1 t; 0 1]; the plane is a row vector */
    ref_mat3_inverse(m, inv3);
    for (r = 0; r < 3; r++)
        t[r] = m->m[12 + r];
    for (c = 0; c < 3; c++)
        expect[c] = eqn[0] * inv3[0][c] + eqn[1] * inv3[1][c] + eqn[2] * inv3[2][c];
    expect[3] = eqn[3];
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++)
            expect[3] -= eqn[r] * inv3[r][c] * t[c];
    printf("getclip %d", i);
    ffl_pdv("plane", got, 4);
    printf(" ref");
    ffl_pdv("plane", expect, 4);
    printf("\n");
}

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    ffl_fb fb;
    ffl_rng r;
    int m, k;
    ffl_rng_seed(&r, 0x636c6970u);
    ffl_fb_init(&fb);
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < (int)(sizeof modes / sizeof modes[0]); m++)
        for (k = 0; k < 3; k++)
            vref_draw_shape(&vref, &fb, &r, modes[m], 4 + 2 * k, ffl_rng_float(&r, -3, 3),
                            ffl_rng_float(&r, -3, 3), 6, 3);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    static const GLdouble planes[6][4] = {
        { 1, 0.2, 0, 2 }, { 0, 1, 0, 50 }, { -0.3, 1, 0.1, 1.5 },
        { 0.5, -0.5, 1, 4 }, { -1, -0.1, 0.2, 3 }, { 0.1, -1, -0.2, 2.5 },
    };
    ref_state ref;
    ref_mat4 at_plane[6];
    int i, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -20, 20);
    glMatrixMode(GL_MODELVIEW);

    /* the planes, each under the modelview of its moment */
    mirror_load_identity(&ref);
    mirror_rotatef(&ref, 30, 0.2f, 0.3f, 1);
    mirror_translatef(&ref, 0.5f, -1, 2);
    for (i = 0; i < 6; i++) {
        GLfloat f[16];
        int k;
        if (i == 3)
            mirror_scalef(&ref, 1.5f, 0.75f, 2);
        glClipPlane(GL_CLIP_PLANE0 + i, planes[i]);
        glGetFloatv(GL_MODELVIEW_MATRIX, f);
        for (k = 0; k < 16; k++)
            at_plane[i].m[k] = f[k];
    }
    for (i = 0; i < 6; i++)
        print_plane(i, planes[i], &at_plane[i]);

    /* the drawing modelview, and light */
    mirror_load_identity(&ref);
    mirror_rotatef(&ref, -15, 1, 0.5f, 0.2f);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1, 0);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_materialf(&ref, GL_FRONT_AND_BACK, GL_SHININESS, 12);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE2);
    glEnable(GL_CLIP_PLANE5);
    printf("enabled");
    for (i = 0; i < 6; i++)
        printf(" %d", glIsEnabled(GL_CLIP_PLANE0 + i) == GL_TRUE);
    printf("\n");
    failed |= pass("three_fill", &ref);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    failed |= pass("three_line", &ref);
    glPolygonMode(GL_FRONT, GL_POINT);
    failed |= pass("three_point_line", &ref);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    for (i = 0; i < 6; i++)
        glEnable(GL_CLIP_PLANE0 + i);
    failed |= pass("six_fill", &ref);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    failed |= pass("six_line", &ref);
    vref_print_counts(&vref);
    return failed;
}

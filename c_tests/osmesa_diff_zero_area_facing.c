/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: the facing of a polygon of zero area (§2.14.1, §3.5.1).
 * Two-sided lighting selects the back color when the signed window-space area a
 * satisfies a <= 0 under glFrontFace(GL_CCW) (-a <= 0 under GL_CW), so a triangle
 * of zero area takes the back colors under either winding; culling takes a polygon
 * as front facing only if the sign is positive, so GL_CULL_FACE with GL_BACK
 * discards it and GL_FRONT keeps it. OSMesa (the draw module's two-side stage takes the
 * back colors only when det * sign < 0) gives such triangles their front colors; its
 * culling is as the spec's.
 * gluSphere with texture coordinates makes such triangles at its poles
 * (glu_quadrics_tess.c). Triangles with two coincident corners and with three
 * collinear corners, under both windings, front material red and back material
 * blue; each vertex carries the reference's color for the face the spec selects.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 4096

static vref_set vref;

/* Corners of degenerate triangles (window y of a row is exactly equal), then one
 * counterclockwise and one clockwise triangle for contrast. */
static const float corners[4][3][2] = {
    { { -8, 6 }, { -8, 6 }, { -4, 2 } }, /* two coincident corners */
    { { -8, -2 }, { -4, -2 }, { 2, -2 } }, /* collinear */
    { { 2, 6 }, { 8, 6 }, { 5, 9 } },    /* counterclockwise */
    { { 2, -6 }, { 8, -6 }, { 5, -9 } }, /* clockwise */
};

static void draw(ref_state *ref)
{
    static const float normals[3][3] = { { 0.2f, 0.1f, 1 }, { -0.3f, 0.4f, 0.8f },
                                         { 0.5f, -0.2f, 0.6f } };
    int t, k;
    glBegin(GL_TRIANGLES);
    for (t = 0; t < 4; t++)
        for (k = 0; k < 3; k++) {
            /* coincident corners share their normal: they are one window position */
            int n = t == 0 && k == 1 ? 0 : k;
            mirror_normal3f(ref, normals[n][0], normals[n][1], normals[n][2]);
            vref_vertex3f(&vref, corners[t][k][0], corners[t][k][1], 0);
        }
    glEnd();
}

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    ffl_fb_mark(&fb, GL_TRIANGLES);
    draw(ref);
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

/* With culling: "<tag> polygons <n> ref polygons <spec's n>". */
static void cull_pass(const char *tag, GLenum mode, int expected, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    GLint n;
    glEnable(GL_CULL_FACE);
    glCullFace(mode);
    glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    draw(ref);
    n = glRenderMode(GL_RENDER);
    glDisable(GL_CULL_FACE);
    /* every polygon token is 2 + 3 * 7 values */
    printf("%s polygons %d ref polygons %d\n", tag, (int)(n / 23), expected);
}

int main(void)
{
    ref_state ref;
    int failed = 0;

    ffl_test_init();
    ref_init(&ref);
    mirror_box_view(&ref, 10);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.2f, 0.3f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, -0.2f, 0.1f, -1, 0);
    mirror_light4f(&ref, GL_LIGHT1, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_DIFFUSE, 0.9f, 0.2f, 0.1f, 1);
    mirror_material4f(&ref, GL_BACK, GL_DIFFUSE, 0.1f, 0.3f, 0.9f, 1);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT1, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    failed |= pass("ccw", &ref);
    /* culling: the two degenerate triangles are back facing, with one of the others */
    cull_pass("ccw_cull_back", GL_BACK, 1, &ref);
    cull_pass("ccw_cull_front", GL_FRONT, 3, &ref);
    glFrontFace(GL_CW);
    failed |= pass("cw", &ref);
    cull_pass("cw_cull_back", GL_BACK, 1, &ref);
    cull_pass("cw_cull_front", GL_FRONT, 3, &ref);
    ffl_print_error("zero_area");
    return failed;
}

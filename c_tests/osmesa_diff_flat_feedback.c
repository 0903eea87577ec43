/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: glShadeModel(GL_FLAT) in feedback (§2.14.7, §5.3).
 * With flat shading every vertex of a primitive takes the color of its
 * provoking vertex (table 2.8 in GL 1.5): the last vertex of a segment (for
 * the closing segment of a loop, the loop's first vertex), the last of each
 * separate triangle and of each triangle of a strip or fan, the last of each
 * quad, the last of each quad of a quad strip, the first vertex of a
 * polygon. Feedback returns the colors as rasterization would see them, so
 * the fed-back colors are the provoking vertex's. OSMesa returns each
 * vertex's own color for filled polygons and for segments of line
 * primitives; it does apply flat shading to polygon outlines (GL_LINE) and
 * points (GL_POINT), shown for contrast. Every vertex a distinct color; each
 * fed-back vertex carries the provoking vertex's color as its reference.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 8192

static vref_set vref;
/* the drawn vertices of the current glBegin: first index and count */
static int prim_first[FFL_MAX_PRIMS], prim_count[FFL_MAX_PRIMS];
static ffl_fb fb;

/* The provoking vertex of the primitive a fed-back token belongs to, from
 * the drawn vertices it shows (by window position): the primitive is known
 * from the smallest index (separate triangles, quads, polygons) or from all
 * of them (a strip's or fan's triangle, a segment). */
static int provoking(GLenum mode, int first, int count, const int *idx, int n)
{
    int lo = idx[0], hi = idx[0], k;
    for (k = 1; k < n; k++) {
        if (idx[k] < lo) lo = idx[k];
        if (idx[k] > hi) hi = idx[k];
    }
    lo -= first;
    hi -= first;
    switch (mode) {
    case GL_POLYGON: return first;
    case GL_TRIANGLES: return first + lo / 3 * 3 + 2;
    case GL_QUADS: return first + lo / 4 * 4 + 3;
    case GL_LINE_LOOP: return first + (lo == 0 && hi == count - 1 && count > 2 ? 0 : hi);
    default: return first + hi; /* segments, strips, fans, quad strips */
    }
}

static int current_prim = -1;

static void flat_note(void *user, GLenum mode, GLenum token, const GLfloat *vertices, int nverts,
                      int k, GLenum type)
{
    int idx[16], n, size = ffl_feedback_vertex_size(type), p;
    (void)user; (void)token;
    for (n = 0; n < nverts && n < 16; n++) {
        idx[n] = vref_index_of(&vref, vertices + n * size, vertices + n * size + 2);
        if (idx[n] < 0)
            return;
    }
    /* the primitive: the one whose drawn vertices include this token's */
    for (p = 0; p < fb.nprims; p++)
        if (idx[0] >= prim_first[p] && idx[0] < prim_first[p] + prim_count[p])
            break;
    if (p == fb.nprims || fb.modes[p] != mode)
        return;
    current_prim = p;
    printf(" ref");
    ffl_pdv("rgba", vref.v[provoking(mode, prim_first[p], prim_count[p], idx, nverts)].color[0], 4);
    (void)k;
}

static void draw(GLenum mode, int count, float cx, float cy, ffl_rng *r)
{
    float p[16][3];
    int k;
    prim_first[fb.nprims] = vref.n;
    prim_count[fb.nprims] = count;
    ffl_shape(r, mode, count, cx, cy, 1.6, 0, p);
    ffl_fb_begin(&fb, mode);
    for (k = 0; k < count; k++) {
        mirror_color4f(vref.ref, ffl_rng_float(r, 0, 1), ffl_rng_float(r, 0, 1),
                       ffl_rng_float(r, 0, 1), 1);
        vref_vertex3f(&vref, p[k][0], p[k][1], p[k][2]);
    }
    glEnd();
}

static int pass(const char *tag, ref_state *ref, int polygons_only)
{
    static GLfloat buf[BUF_SIZE];
    static const GLenum modes[] = { GL_TRIANGLES, GL_QUADS, GL_POLYGON, GL_TRIANGLE_STRIP,
                                    GL_TRIANGLE_FAN, GL_QUAD_STRIP, GL_LINES, GL_LINE_STRIP,
                                    GL_LINE_LOOP, GL_POINTS };
    ffl_rng r;
    int m, n = polygons_only ? 3 : 10;
    ffl_rng_seed(&r, 0x666c6174u);
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < n; m++)
        draw(modes[m], modes[m] == GL_POINTS ? 2 : 6, -6.0f + 4.0f * (float)(m % 4),
             -5.0f + 4.0f * (float)(m / 4), &r);
    return ffl_fb_finish(&fb, tag, flat_note, NULL);
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
    glShadeModel(GL_FLAT);

    failed |= pass("flat_fill", &ref, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    failed |= pass("flat_line", &ref, 1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    failed |= pass("flat_point", &ref, 1);
    return failed;
}

/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: edge flags in GL_LINE and GL_POINT polygon modes
 * (§2.6.2, §3.5.4). Each vertex of GL_TRIANGLES, GL_QUADS and GL_POLYGON
 * starts an edge flagged with the current edge flag (glEdgeFlag); in
 * GL_LINE mode only the boundary edges whose starting vertex is flagged
 * TRUE are drawn, in GL_POINT mode only the vertices flagged TRUE. (Strips
 * and fans ignore edge flags: all their edges are boundary edges; shown for
 * contrast.) OSMesa's feedback returns nothing at all for these draws once a
 * vertex is flagged FALSE. Each draw prints its feedback, then the edges (or
 * points) fed back against the spec's set: "edges <n> missing <m> extra <e>
 * ref edges <n'> missing 0 extra 0", edges identified by their drawn end
 * vertices (by window position) and direction.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 4096
#define MAX_V 16

static vref_set vref;
static GLboolean flags[MAX_V];
static int nverts_drawn;
static GLenum drawn_mode;
/* the edges and points fed back, by drawn vertex index */
static int got_edge[MAX_V][MAX_V], got_point[MAX_V], unknown;

static void collect(void *user, GLenum mode, GLenum token, const GLfloat *vertices, int nverts,
                    int k, GLenum type)
{
    int size = ffl_feedback_vertex_size(type), a, b;
    (void)user; (void)mode;
    if (k != 0)
        return;
    a = vref_index_of(&vref, vertices, NULL);
    if (token == GL_POINT_TOKEN) {
        if (a < 0) unknown++; else got_point[a]++;
    } else if (nverts == 2) {
        b = vref_index_of(&vref, vertices + size, NULL);
        if (a < 0 || b < 0) unknown++; else got_edge[a][b]++;
    }
}

/* The spec's boundary edges: i -> i+1 within each polygon of the primitive
 * (the last back to the first), drawn when flags[i] (always in strips and
 * fans: every edge of each triangle). */
static void expected(int edge[MAX_V][MAX_V], int point[MAX_V])
{
    int n = nverts_drawn, g, i, size = drawn_mode == GL_TRIANGLES ? 3 : drawn_mode == GL_QUADS ? 4 : n;
    memset(edge, 0, sizeof(int) * MAX_V * MAX_V);
    memset(point, 0, sizeof(int) * MAX_V);
    if (drawn_mode == GL_TRIANGLE_STRIP) {
        for (i = 0; i + 2 < n; i++) {
            int t[3];
            t[0] = i; t[1] = i + 1; t[2] = i + 2;
            if (i % 2) { t[0] = i + 1; t[1] = i; }
            edge[t[0]][t[1]]++; edge[t[1]][t[2]]++; edge[t[2]][t[0]]++;
        }
        return;
    }
    for (g = 0; g + size <= n; g += size)
        for (i = g; i < g + size; i++)
            if (flags[i]) {
                edge[i][i + 1 < g + size ? i + 1 : g]++;
                point[i]++;
            }
}

static int draw(const char *tag, GLenum pmode, GLenum mode, int n, const float (*p)[2],
                const GLboolean *f)
{
    static GLfloat buf[BUF_SIZE];
    static int want_edge[MAX_V][MAX_V], want_point[MAX_V];
    ffl_fb fb;
    int i, j, got = 0, want = 0, missing = 0, extra = 0, failed;
    glPolygonMode(GL_FRONT_AND_BACK, pmode);
    vref.n = 0;
    nverts_drawn = n;
    drawn_mode = mode;
    memset(got_edge, 0, sizeof got_edge);
    memset(got_point, 0, sizeof got_point);
    unknown = 0;
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D);
    ffl_fb_begin(&fb, mode);
    for (i = 0; i < n; i++) {
        flags[i] = f[i];
        glEdgeFlag(f[i]);
        vref_vertex3f(&vref, p[i][0], p[i][1], 0);
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
    failed = ffl_fb_finish(&fb, tag, collect, NULL);
    expected(want_edge, want_point);
    for (i = 0; i < n; i++) {
        if (pmode == GL_POINT) {
            got += got_point[i];
            want += want_point[i];
            missing += want_point[i] > got_point[i] ? want_point[i] - got_point[i] : 0;
            extra += got_point[i] > want_point[i] ? got_point[i] - want_point[i] : 0;
            continue;
        }
        for (j = 0; j < n; j++) {
            got += got_edge[i][j];
            want += want_edge[i][j];
            missing += want_edge[i][j] > got_edge[i][j] ? want_edge[i][j] - got_edge[i][j] : 0;
            extra += got_edge[i][j] > want_edge[i][j] ? got_edge[i][j] - want_edge[i][j] : 0;
        }
    }
    printf("%s %s %d missing %d extra %d ref %s %d missing 0 extra 0\n", tag,
           pmode == GL_POINT ? "points" : "edges", got, missing, extra + unknown,
           pmode == GL_POINT ? "points" : "edges", want);
    return failed;
}

int main(void)
{
    static const float tris[6][2] = { { -8, -6 }, { -2, -6 }, { -5, 0 },
                                      { 1, -6 }, { 8, -5 }, { 4, 0 } };
    static const GLboolean tri_flags[6] = { 1, 0, 1, 0, 0, 1 };
    static const float quads[8][2] = { { -8, 1 }, { -3, 1 }, { -3, 5 }, { -8, 5 },
                                       { 0, 1 }, { 6, 1 }, { 7, 6 }, { 1, 5 } };
    static const GLboolean quad_flags[8] = { 1, 0, 1, 1, 0, 1, 0, 1 };
    static const float polygon[6][2] = { { -4, -9 }, { 4, -9 }, { 8, -4 },
                                         { 3, 2 }, { -3, 2 }, { -8, -4 } };
    static const GLboolean polygon_flags[6] = { 1, 1, 0, 1, 0, 1 };
    static const GLboolean all_false[6] = { 0, 0, 0, 0, 0, 0 };
    ref_state ref;
    int m, failed = 0;
    char tag[64];

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    vref_start(&vref, &ref);

    for (m = 0; m < 2; m++) {
        GLenum pmode = m ? GL_POINT : GL_LINE;
        const char *name = m ? "point" : "line";
        sprintf(tag, "%s_triangles", name);
        failed |= draw(tag, pmode, GL_TRIANGLES, 6, tris, tri_flags);
        sprintf(tag, "%s_quads", name);
        failed |= draw(tag, pmode, GL_QUADS, 8, quads, quad_flags);
        sprintf(tag, "%s_polygon", name);
        failed |= draw(tag, pmode, GL_POLYGON, 6, polygon, polygon_flags);
        sprintf(tag, "%s_polygon_all_false", name);
        failed |= draw(tag, pmode, GL_POLYGON, 6, polygon, all_false);
    }
    /* strips ignore the flags: every edge is drawn, in both */
    failed |= draw("line_strip_ignores_flags", GL_LINE, GL_TRIANGLE_STRIP, 5, polygon, all_false);
    return failed;
}

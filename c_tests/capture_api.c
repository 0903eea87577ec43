/* ffl-test: fflight-only */
/*
 * The capture API: fflCaptureBegin / fflCaptureEnd collect the vertices of
 * every draw (glBegin/glEnd and vertex array draws) and the points, lines and
 * triangles primitive assembly makes of them, before clipping; feedback runs
 * as usual meanwhile. Checked here against the feedback of the same draws
 * (nothing is clipped or culled): the same primitives in the same order, the
 * window coordinates of the captured clip coordinates, the same colors and
 * texture coordinates; quadrilaterals and polygons as the triangles feedback
 * reports; edge flags. Then the read calls' ranges and errors.
 */
#include "ffl_test.h"
#include <string.h>

#define MAX_V 64
#define FEEDBACK 4096

static int failures = 0;

static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("FAILED %s\n", what);
        failures++;
    }
}

static double window_x(const GLfloat *clip) { return (clip[0] / clip[3] + 1.0) * 32.0; }
static double window_y(const GLfloat *clip) { return (clip[1] / clip[3] + 1.0) * 32.0; }
static double window_z(const GLfloat *clip) { return (clip[2] / clip[3] + 1.0) * 0.5; }

static void draw_scene(void)
{
    static const GLfloat ring[8][3] = {
        { 1, 0, 0 }, { 0.7f, 0.7f, 0.1f }, { 0, 1, 0 }, { -0.7f, 0.7f, -0.1f },
        { -1, 0, 0 }, { -0.7f, -0.7f, 0.1f }, { 0, -1, 0 }, { 0.7f, -0.7f, -0.1f },
    };
    static const GLubyte ring_colors[8][4] = {
        { 255, 0, 0, 255 }, { 200, 50, 0, 255 }, { 0, 255, 0, 128 }, { 0, 50, 200, 255 },
        { 0, 0, 255, 255 }, { 90, 90, 90, 255 }, { 255, 255, 0, 64 }, { 10, 200, 30, 255 },
    };
    static const GLushort fan[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
    int i;
    /* A quad whose third vertex has its edge flag off. */
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glTexCoord2f(0, 0);
    glVertex3f(-1.5f, -1.5f, 0);
    glColor3f(0, 1, 0);
    glTexCoord2f(1, 0);
    glVertex3f(-0.5f, -1.5f, 0);
    glEdgeFlag(GL_FALSE);
    glColor3f(0, 0, 1);
    glTexCoord2f(1, 1);
    glVertex3f(-0.5f, -0.5f, 0);
    glEdgeFlag(GL_TRUE);
    glColor3f(1, 1, 0);
    glTexCoord2f(0, 1);
    glVertex3f(-1.5f, -0.5f, 0);
    glEnd();
    /* Lines and points. */
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 4; i++) {
        glColor3f(0.2f * (float)i, 0.5f, 1.0f - 0.2f * (float)i);
        glVertex3f(0.5f + 0.3f * (float)i, 1.0f - 0.2f * (float)(i % 2), 0.2f);
    }
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(1.2f, -1.2f, 0.3f);
    glVertex3f(1.4f, -1.0f, 0.3f);
    glEnd();
    /* A polygon from vertex arrays. */
    glVertexPointer(3, GL_FLOAT, 0, ring);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, ring_colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawElements(GL_POLYGON, 8, GL_UNSIGNED_SHORT, fan);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

int main(void)
{
    static const GLfloat light[4] = { 0.2f, 0.3f, 1.0f, 0.0f };
    static GLfloat fb[FEEDBACK];
    static FflCapturedVertex v[MAX_V];
    static FflCapturedPrimitive p[2 * MAX_V];
    FflCapturedVertex one;
    GLuint nv, np, k, i;
    GLint n, at = 0;
    int triangles = 0, lines = 0, points = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 20);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -6);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);

    /* Nothing is captured before fflCaptureBegin. */
    draw_scene();
    expect(fflCaptureVertexCount() == 0 && fflCapturePrimitiveCount() == 0, "off by default");

    glFeedbackBuffer(FEEDBACK, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    fflCaptureBegin();
    draw_scene();
    fflCaptureEnd();
    n = glRenderMode(GL_RENDER);
    draw_scene(); /* not captured */
    nv = fflCaptureVertexCount();
    np = fflCapturePrimitiveCount();
    printf("captured vertices %u primitives %u feedback values %d error %s\n", nv, np, (int)n,
           ffl_error_name(glGetError()));
    expect(nv == 4 + 4 + 2 + 8, "vertex count");
    expect(np == 2 + 3 + 2 + 6, "primitive count");
    expect(fflCaptureReadVertices(0, MAX_V, v) == nv, "read every vertex");
    expect(fflCaptureReadPrimitives(0, MAX_V, p) == np, "read every primitive");
    expect(sizeof(FflCapturedVertex) == 116 && sizeof(FflCapturedPrimitive) == 32, "no padding");

    /* Primitive by primitive, against the feedback tokens. */
    for (k = 0; k < np && at < n; k++) {
        GLfloat token = fb[at++];
        GLuint count = p[k].vertex_count;
        char what[64];
        if (p[k].kind == GL_TRIANGLES) {
            triangles++;
            expect(token == GL_POLYGON_TOKEN && fb[at++] == 3.0f, "triangle token");
        } else if (p[k].kind == GL_LINES) {
            lines++;
            expect(token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN, "line token");
        } else {
            points++;
            expect(token == GL_POINT_TOKEN, "point token");
        }
        for (i = 0; i < count; i++) {
            const FflCapturedVertex *c = &v[p[k].vertices[i]];
            const GLfloat *f = fb + at;
            sprintf(what, "primitive %u vertex %u", k, i);
            expect(fabs(f[0] - window_x(c->clip)) < 1e-4 && fabs(f[1] - window_y(c->clip)) < 1e-4
                       && fabs(f[2] - window_z(c->clip)) < 1e-6 && f[3] == c->clip[3],
                   what);
            expect(memcmp(f + 4, c->front_primary, sizeof c->front_primary) == 0, what);
            expect(memcmp(f + 8, c->tex_coord, sizeof c->tex_coord) == 0, what);
            at += 12;
        }
    }
    expect(k == np && at == n, "every primitive fed back, in order");
    printf("triangles %d lines %d points %d\n", triangles, lines, points);

    /* The quad: two triangles, (v0, v1, v3) and (v1, v2, v3); the inner edge
     * and the edge leaving v2 (edge flag off) are not drawn as lines. */
    expect(p[0].mode == GL_QUADS && p[0].draw == 0 && p[1].draw == 0, "quad draw");
    expect(p[0].vertices[0] == 0 && p[0].vertices[1] == 1 && p[0].vertices[2] == 3, "quad split");
    expect(p[1].vertices[0] == 1 && p[1].vertices[1] == 2 && p[1].vertices[2] == 3, "quad split");
    expect(p[0].edges[0] && !p[0].edges[1] && p[0].edges[2], "first triangle edges");
    expect(p[1].edges[0] && !p[1].edges[1] && !p[1].edges[2], "second triangle edges");
    expect(v[2].edge_flag == GL_FALSE && v[3].edge_flag == GL_TRUE, "vertex edge flags");
    /* Draws are numbered; the polygon came from glDrawElements. */
    expect(p[np - 1].mode == GL_POLYGON && p[np - 1].draw == 3, "array draw numbered");
    /* Eye coordinates: the modelview only translates. */
    expect(v[0].eye[0] == -1.5f && v[0].eye[2] == -6.0f && v[0].eye[3] == 1.0f, "eye position");

    /* Reads: a range, the end, past the end, NULL. */
    memset(&one, 0, sizeof one);
    expect(fflCaptureReadVertices(nv - 1, 1, &one) == 1 && memcmp(&one, &v[nv - 1], sizeof one) == 0,
           "read at the end");
    expect(fflCaptureReadPrimitives(np - 2, 5, p + np) == 2
               && memcmp(p + np, p + np - 2, 2 * sizeof *p) == 0,
           "a range that runs past the end");
    expect(fflCaptureReadVertices(nv, 5, &one) == 0, "read past the end");
    expect(fflCaptureReadPrimitives(np + 100, 1, p) == 0, "read far past the end");
    expect(glGetError() == GL_NO_ERROR, "no error so far");
    expect(fflCaptureReadVertices(0, 1, NULL) == 0 && glGetError() == GL_INVALID_VALUE,
           "NULL destination");
    expect(fflCaptureReadVertices(0, 0, NULL) == 0 && glGetError() == GL_NO_ERROR,
           "nothing to copy");

    /* Between glBegin and glEnd both calls are refused and change nothing. */
    glBegin(GL_POINTS);
    fflCaptureBegin();
    glVertex3f(0, 0, 0);
    glEnd();
    expect(glGetError() == GL_INVALID_OPERATION, "fflCaptureBegin inside glBegin/glEnd");
    expect(fflCaptureVertexCount() == nv, "capture kept");

    /* A new capture drops the old one. */
    fflCaptureBegin();
    fflCaptureEnd();
    expect(fflCaptureVertexCount() == 0 && fflCapturePrimitiveCount() == 0, "begin clears");
    printf("failures %d\n", failures);
    return failures != 0;
}
